// Contact patch test in 2D (prm/patch_test_2d.prm): the scene's variant
// (integral form, 4 Gauss points per face, the 'partition' indicator) and
// the poster's forms (Indicator shape = simplex): the nodal form and the
// integral form with 2 Gauss points per face; the largest deviation of the
// nodal pressure from the applied one against 1% (tests/patch_test.h).
#include "patch_test.h"

#include <fstream>

int
main()
{
  std::ofstream     out("output");
  const std::string form = "subsection Contact\n  subsection Two bodies\n";
  const std::string poster = "    set Indicator shape = simplex\n";
  patch_test(out, "partition_integral_K4", "patch_test_2d.prm", "", 2, 0.01);
  patch_test(out, "partition_integral_K2", "patch_test_2d.prm",
             form + "    set Gauss points per face = 2\n  end\nend\n", 2, 0.01);
  patch_test(out, "poster_nodal", "patch_test_2d.prm",
             form + poster + "    set Contact form = nodal\n  end\nend\n", 2, 0.01);
  patch_test(out, "poster_integral_K2", "patch_test_2d.prm",
             form + poster + "    set Gauss points per face = 2\n  end\nend\n", 2, 0.01);
}
