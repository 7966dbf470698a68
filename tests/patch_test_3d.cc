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
  std::ofstream     out("output");
  const std::string form = "subsection Contact\n  subsection Two bodies\n";
  const std::string poster = "    set Indicator shape = simplex\n";
  patch_test(out, "partition_integral_K4", "patch_test_3d.prm", "", 3, 0.02);
  patch_test(out, "partition_integral_K2", "patch_test_3d.prm",
             form + "    set Gauss points per face = 2\n  end\nend\n", 3, 0.02);
  patch_test(out, "poster_nodal", "patch_test_3d.prm",
             form + poster + "    set Contact form = nodal\n  end\nend\n", 3, 0.02);
  patch_test(out, "poster_integral_K2", "patch_test_3d.prm",
             form + poster + "    set Gauss points per face = 2\n  end\nend\n", 3, 0.02);
}
