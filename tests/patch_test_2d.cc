// Contact patch test in 2D (prm/patch_test_2d.prm): the scene's variant
// (integral form, 4 Gauss points per face, the 'partition' indicator), the
// same with 2 points, and the poster's forms (Indicator shape = simplex):
// the nodal form and the integral form with 2 Gauss points per face; the
// largest deviation of the nodal pressure from the applied one against 1%
// (tests/patch_test.h).
#include "patch_test.h"

#include <fstream>

int
main()
{
  std::ofstream out("output");
  patch_test_variants(out, "patch_test_2d.prm", 2, 0.01);
}
