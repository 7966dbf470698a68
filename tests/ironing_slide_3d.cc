// The 3D ironing scene (prm/ironing_3d.prm: the die and block of
// prm/ironing.prm as a slab one cell thick along y with u_y = 0 on its
// faces) on a mesh 3/4 as fine as the scene's (block 36 x 1 x 12 cells,
// faces of 1/3, die 6 x 1 x 6; 3180 DoFs), the whole path in 80 load
// steps, integral form; the checks are those of ironing_check.h with the
// vertical along z. Measured on this mesh: no step cut, 1626 Newton
// iterations (2121 before Newton's inertia test), about 60 s; Rz(1) =
// -3.33e8; the mirror equal to 1e-9; mean |Rx|/|Rz| while sliding 1.50%
// (the scene's mesh: 0.52%; 2D at the scene's face size: 0.72%), checked
// to 2%; the largest step-to-step jump
// of Rx 5.7% of |Rz|, checked to 8% (2D: 2%); the die's nodes penetrate
// at most 8.7e-3 h. With block faces of 1/2 (24 x 1 x 8) the mirror
// failed (Rx(2) = -0.48 Rx(1)) and the sliding ratio was 3.7%.

#include "ironing_check.h"

int
main()
{
  IroningCheck::run_and_check("ironing_3d.prm", "6, 1, 6", "36, 1, 12", "z", 0.02, 0.08, 3e-2);
}
