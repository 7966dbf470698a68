// Cattaneo-Mindlin in 3D with the uncoupled body,
// prm/cattaneo_mindlin_3d_incompressible.prm (issue 50): the half ball of
// cattaneo_mindlin_3d with J = 1 per cell and Q2 (E* = 4 G), mu P =
// 0.10668. The checks are in cattaneo_mindlin_3d_check.h. Measured: c/a -
// Mindlin = +0.008, +0.040, +0.044 (node spacing 0.18 a; allowance 0.54
// with the cell size 0.36 a), about 2.5 minutes on one rank.

#include "cattaneo_mindlin_3d_check.h"

int
main()
{
  check_cattaneo_mindlin_3d("cattaneo_mindlin_3d_incompressible.prm", 0.10668);
}
