// Units do not matter: the same scene with its lengths multiplied by 1000
// and its moduli by 1e6 (so stresses scale by 1e6 and forces per unit
// thickness by 1e9) must take the same load steps, about the same Newton
// iterations, and give the same answer in relative terms. Two scenes:
// - the rigid-foundation Hertz scene (prm/default.prm), penalty
//   continuation: mu_0 = c_0 E / h^2 and every Newton tolerance are
//   relative (measured: the same 45 iterations, answers to 1e-13; the
//   iterations must be equal: before a Newton direction from a singular
//   Hessian was treated as such, it was 45 against 47);
// - Hertz on an elastic block (prm/hertz_block.prm, one local refinement
//   less), two-body indicator function: mu_0 = c_0 E h (measured: 65 and
//   64 iterations, answers to 4e-11).
// Iterations may differ by round-off: 1000 and 1e6 are not powers of two,
// so the iterates differ in the last digits, and a convergence test on
// the energy decrease can flip at the last iteration. Hence: iterations
// within 5%, answers within 1e-8.

#include "run_output.h"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>

using RunOutput::summary_numbers;
using RunOutput::summary_quantity;
using RunOutput::verdict;

namespace
{
  double
  number(const std::string &summary, const std::string &key)
  {
    return RunOutput::first_number(summary_numbers(summary), key);
  }

  void
  compare(const std::string &label, const std::string &scene,
          const std::string &common, const std::string &scaled_edits,
          const double iteration_tolerance, std::ostream &out)
  {
    const std::string base = label + "_base", scaled = label + "_scaled";
    const bool ok = RunOutput::run_scene(base, scene, common) == 0 &&
                     RunOutput::run_scene(scaled, scene, common + scaled_edits) == 0;
    out << label << ": both runs exit 0: " << verdict(ok) << "\n";
    const std::string a = base + "/summary.json", b = scaled + "/summary.json";
    out << label << ": same load steps: "
        << verdict(number(a, "load steps") == number(b, "load steps")) << "\n";
    const double ia = number(a, "newton iterations"), ib = number(b, "newton iterations");
    out << label << ": Newton iterations within " << 100 * iteration_tolerance
        << "%: " << verdict(std::abs(ia - ib) <= iteration_tolerance * ia) << "\n";
    double worst = 0.;
    for (const auto &[q, factor] :
         std::initializer_list<std::pair<const char *, double>>{
           {"hertz_a", 1e3}, {"hertz_p0", 1e6}, {"contact_force_y", 1e9},
           {"max_penetration_over_h", 1.}, {"active_contact_nodes", 1.}})
      {
        const double x = summary_quantity(a, q), y = summary_quantity(b, q) / factor;
        const double d = std::abs(x - y) / std::abs(x);
        worst          = std::isnan(d) ? 1. : std::max(worst, d);
      }
    out << label << ": a, p0, force, penetration / h, active nodes agree to 1e-8: "
        << verdict(worst < 1e-8) << "\n";
    std::cerr << label << ": iterations " << ia << " / " << ib
              << ", largest relative difference " << worst << "\n";
  }
} // namespace

int
main()
{
  std::ofstream out("output");
  compare("rigid", "default.prm",
          "subsection Solver\n  set Method = newton-penalty\nend\n",
          "subsection Mesh\n  set Local refinement radius = 200\nend\n"
          "subsection Body 1\n  subsection Geometry\n    set Center = 0, 1000\n"
          "    set Radius = 1000\n  end\n  subsection Material\n"
          "    set Young's modulus = 2e8\n  end\nend\n"
          "subsection Boundary conditions\n  set Traction = 0; -863100*t\nend\n"
          "subsection Contact\n  subsection Hertz reference\n"
          "    set Line load = 1.7262e9\n    set Radius = 1000\n  end\nend\n",
          0., out);
  compare("two_bodies", "hertz_block.prm",
          "subsection Mesh\n  set Local refinements = 4\nend\n",
          "subsection Mesh\n  set Local refinement center = 0, 100000\n"
          "  set Local refinement radius = 12000\nend\n"
          "subsection Body 1\n  subsection Geometry\n    set Center = 0, 150000\n"
          "    set Radius = 50000\n  end\n  subsection Material\n"
          "    set Young's modulus = 210e6\n  end\nend\n"
          "subsection Body 2\n  subsection Geometry\n"
          "    set Upper corner = 50000, 100000\n  end\n  subsection Material\n"
          "    set Young's modulus = 70e6\n  end\nend\n"
          "subsection Boundary conditions\n  set Traction = 0; -0.35e6*t\nend\n"
          "subsection Contact\n  subsection Hertz reference\n"
          "    set Line load = 35e9\n    set Radius = 50000\n  end\nend\n",
          0.05, out);
}
