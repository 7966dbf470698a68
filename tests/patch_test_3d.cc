// Contact patch test in 3D (prm/patch_test_3d.prm): the nodal form, the
// integral form as the poster has it (2 x 2 Gauss points per face,
// Stretch 0.12), and the integral form with Stretch 0.5; the largest
// deviation of the nodal pressure from the applied one against 2%
// (tests/patch_test.h).
#include "patch_test.h"

#include <fstream>

int
main()
{
  std::ofstream out("output");
  const std::string form = "subsection Contact\n  subsection Two bodies\n";
  patch_test(out, "nodal", "patch_test_3d.prm", "", 3, 0.02);
  patch_test(out, "integral", "patch_test_3d.prm",
             form + "    set Contact form = integral\n  end\nend\n", 3, 0.02);
  patch_test(out, "integral_stretch_0.5", "patch_test_3d.prm",
             form + "    set Contact form = integral\n    set Stretch = 0.5\n"
                    "  end\nend\n",
             3, 0.02);
}
