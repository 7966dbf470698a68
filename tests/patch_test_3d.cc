// Contact patch test in 3D (prm/patch_test_3d.prm): the scene's variant
// (integral form, 4 x 4 Gauss points per face, the 'partition' indicator),
// the same with 2 x 2 points, and the poster's forms (Indicator shape =
// simplex): the nodal form and the integral form with 2 x 2 points; the
// largest deviation of the nodal pressure from the applied one against 2%
// (tests/patch_test.h).
#include "patch_test.h"

#include <fstream>

int
main()
{
  std::ofstream out("output");
  patch_test_variants(out, "patch_test_3d.prm", 3, 0.02);
}
