// Cattaneo-Mindlin in 3D, prm/cattaneo_mindlin_3d.prm (issue 50): the
// compressible neo-Hookean half ball (nu = 0.45, Q1), mu P = 0.09696. The
// checks are in cattaneo_mindlin_3d_check.h. Measured: c/a - Mindlin =
// -0.004, -0.012, -0.027 with the allowance 0.27 at h/a = 0.18.

#include "cattaneo_mindlin_3d_check.h"

int
main()
{
  check_cattaneo_mindlin_3d("cattaneo_mindlin_3d.prm", 0.09696);
}
