// The 3D ironing scene (prm/ironing_3d.prm: the die and block of
// prm/ironing.prm as a slab one cell thick along y with u_y = 0 on its
// faces) on the scene's own mesh (block 48 x 1 x 16 cells, faces of 1/4,
// die 8 x 1 x 8; 5484 DoFs), the whole path in 80 load steps, integral
// form; the checks are those of ironing_check.h with the vertical along z.
// With the scene's transport predictor (the die moves one block face per
// step) the path takes 416 Newton iterations on 1 and 2 ranks, printed
// (533 before the tangent predictor's energy check at every step, 528
// before Newton lengthened the convexified steps of a crawling iteration),
// about 23 s (2580 and 97 s without it; the test ran on a mesh of block faces of 1/3 before, where
// the die moves 3/4 of a face per step and the predictor's interpolation
// of the bulge gains less: 1392 iterations against 1631, with one step
// cut). Measured: no step cut; Rz(1) = -3.295e8; the mirror equal to 1e-9;
// Rx mid-slide 0; checked as before: mean |Rx|/|Rz| while sliding to 2%,
// the step-to-step jump of Rx to 8% of |Rz|, the die's nodes' penetration
// to 3e-2 h. With block faces of 1/2 (24 x 1 x 8) the mirror failed
// (Rx(2) = -0.48 Rx(1)) and the sliding ratio was 3.7%.

#include "ironing_check.h"

int
main()
{
  IroningCheck::run_and_check("ironing_3d.prm", "8, 1, 8", "48, 1, 16", "z", 0.02, 0.08, 3e-2, true);
}
