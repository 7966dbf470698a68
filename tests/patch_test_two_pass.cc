// The contact patch test (tests/patch_test.h) with the nodal form evaluated
// in two passes (Contact > Two bodies > Passes = two-pass): body 2's target
// nodes are kept out of body 1 as body 1's nodes are kept out of body 2.
// Non-matching meshes of several ratios, coarser over finer and finer over
// coarser, with unequal (E2 = 2, nu2 = 0.2) and equal moduli (body 2 as
// body 1), at the penetration tolerance where the penalty's own error is
// below the goal (2D 1e-5, 3D 1e-4): the largest deviation of body 1's
// nodal pressure from p within 1% (2D) and 2% (3D), with the resultant,
// area and moment checks of patch_test(). The one-pass nodal form on the
// same meshes deviates by 2.6% to 15% (2D) and 7% to 24% (3D) whatever the
// tolerance (doc/two_bodies.md). One 2D and one 3D case also run on 2
// ranks.
#include "patch_test.h"

#include <fstream>
#include <string>

namespace
{
  /// Body 1 with n1 cells across, body 2 with n2, body 2's moduli equal to
  /// body 1's or not, nodal form in two passes at penetration tolerance tol.
  std::string
  edits(const unsigned int dim,
        const unsigned int n1,
        const unsigned int n2,
        const bool         equal_moduli,
        const std::string &tol)
  {
    const auto cells = [dim](const unsigned int n) {
      const std::string s = std::to_string(n);
      return dim == 2 ? s + ", " + s : s + ", " + s + ", 3";
    };
    return "subsection Body 1\n  subsection Geometry\n    set Subdivisions = " + cells(n1) +
           "\n  end\nend\n"
           "subsection Body 2\n  subsection Geometry\n    set Subdivisions = " + cells(n2) +
           "\n  end\n  subsection Material\n    set Young's modulus = " +
           (equal_moduli ? "1" : "2") + "\n    set Poisson's ratio = " +
           (equal_moduli ? "0.3" : "0.2") +
           "\n  end\nend\n"
           "subsection Contact\n  subsection Two bodies\n    set Contact form = nodal\n"
           "    set Passes = two-pass\n  end\nend\n"
           "subsection Solver\n  subsection Penalty\n    set Penetration tolerance = " +
           tol + "\n  end\nend\n";
  }
} // namespace

int
main()
{
  std::ofstream out("output");
  struct Case
  {
    unsigned int n1, n2;
    bool         equal;
  };
  for (const Case &c : {Case{5, 7, false}, Case{5, 7, true}, Case{9, 4, false},
                        Case{9, 4, true}, Case{4, 9, true}, Case{6, 11, false}})
    patch_test(out,
               "2d_" + std::to_string(c.n1) + "_over_" + std::to_string(c.n2) +
                 (c.equal ? "_equal" : "_unequal"),
               "patch_test_2d.prm", edits(2, c.n1, c.n2, c.equal, "1e-5"), 2, 0.01);
  for (const Case &c : {Case{5, 7, false}, Case{7, 5, true}, Case{5, 3, false},
                        Case{3, 5, true}})
    patch_test(out,
               "3d_" + std::to_string(c.n1) + "_over_" + std::to_string(c.n2) +
                 (c.equal ? "_equal" : "_unequal"),
               "patch_test_3d.prm", edits(3, c.n1, c.n2, c.equal, "1e-4"), 3, 0.02);
  const std::string two_ranks = "mpirun --allow-run-as-root --oversubscribe -np 2 ";
  patch_test(out, "2d_5_over_7_unequal_2_ranks", "patch_test_2d.prm",
             edits(2, 5, 7, false, "1e-5"), 2, 0.01, two_ranks);
  patch_test(out, "3d_5_over_7_unequal_2_ranks", "patch_test_3d.prm",
             edits(3, 5, 7, false, "1e-4"), 3, 0.02, two_ranks);
}
