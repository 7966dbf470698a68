// Every hard case of prm/hard/ (benchmarks.md section 5) at a coarse size,
// with every solver that applies (benchmarks/hard_cases.py runs them at
// full size). Each scene is run from this test's folder (its include of
// ../SCENE.prm is relative to prm/hard/, where the scene file is) with a
// coarser mesh where the scene is not already coarse; the mesh
// mismatch keeps its 1:7.8 ratio and the grazing ironing its 0.005
// indentation (on its coarse mesh the penalty path needed 15 step cuts
// there, Ipopt as the stage solver none; since the scenes' transport
// predictor, Load stepping > Sliding direction, neither needs any). For
// each run:
// - it converges (exit 0, status converged, no step-cut floor reached);
// - summary.json holds no non-finite number (they are written as null);
// - no inverted element: min J > 0 in every load step;
// - the penetration is reported and within the scene's penalty tolerance
//   (Ipopt on a rigid foundation: within 1e-4 h, its constraint tolerance
//   being absolute; the interior point method: within 1e-8 h);
// - every quantity with a reference is within its tolerance;
// - the iterations (Newton, Ipopt or interior point) are at most 1.5 x the
//   most measured across OpenBLAS's kernels (printed to stderr), so that a
//   change that makes a hard case much harder shows. Measured 2026-11-28
//   under OPENBLAS_CORETYPE = Nehalem, Sandybridge, Haswell, Zen, SkylakeX
//   and Cooperlake (scripts/check_kernels.sh): every Newton and interior
//   point count is the same under all six; Ipopt's on the two-body
//   penalty stages is not, its path changing with the last bits of BLAS
//   (mesh mismatch 30-61, stiff on soft block 28-46, grazing ironing
//   535-611, full ironing 1174-1210). A pinned count within [1/1.5, 1.5]
//   failed there on another CPU (issue 52); a lower bound guarded nothing
//   that the convergence checks do not. Before, these were the counts of
//   one machine at a time: the two-body cases
//   were measured again with the 'partition' indicator (the default since
//   2026-11-24: mesh mismatch 34 -> 28 and 71 -> 40, full ironing 1253 ->
//   1047 and 1500 -> 989), and again with the transport predictor of the
//   ironing scenes, which Newton's stages use and Ipopt's do not (2026-11-25:
//   grazing 140 -> 33, full ironing 1047 -> 244). SSNV187's corner with the interior point method
//   measured again when the MUMPS ordering asked for (pord) took effect on
//   one rank (2026-11-24; before, MUMPS chose AMF for this small matrix):
//   15 -> 8 iterations, 118 -> 11 factorisations. With AMF its first full
//   step stalled at |r_d|/F = 1.9e-8 and was cut, until the merit
//   function's nu followed each iteration's multipliers instead of only
//   growing: the same case with AMF (label _amf) now takes 8 too. Since
//   the barrier is capped at the previous iteration's (2026-11-27,
//   'Barrier update'), 9 with either ordering: its rise after the first
//   step re-centred this iterate (6 with 'Mehrotra').

#include "run_output.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

using RunOutput::first_number;
using RunOutput::verdict;

namespace
{
  struct Case
  {
    std::string  scene;
    std::string  method;
    std::string  edits;      // the coarse size
    double       iterations; // the most measured across BLAS kernels
    std::string  label = "";  // told apart from the same scene and method
  };

  const std::string local3 = "subsection Mesh\n  set Local refinements = 3\nend\n";
  // At 3 levels the Hertz fit has too few nodes inside a (NaN); at 4 its
  // a and p0 lie 3-4% from the half-space values: no tolerance at this size.
  const std::string stiff =
    "subsection Mesh\n  set Local refinements = 4\nend\n"
    "subsection Contact\n  subsection Hertz reference\n"
    "    set Tolerance a = 0\n    set Tolerance p0 = 0\n  end\nend\n";
  const std::string mismatch =
    "subsection Mesh\n  set Local refinements = 2\nend\n"
    "subsection Body 2\n  subsection Geometry\n    set Subdivisions = 5, 10\n"
    "  end\nend\n";
  // The interior point method's trap on SSNV187's corner: with AMF the
  // first full step stalled at 1.9e-8 F and was cut (15 iterations) while
  // the merit function's nu only grew (doc/robustness.md).
  const std::string amf = "subsection Solver\n  subsection Linear solver\n"
                          "    set MUMPS ordering = amf\n  end\nend\n";
  const std::string ironing = "subsection Mesh\n  set Global refinements = 0\nend\n"
                              "subsection Load stepping\n  set Number of steps = 40\nend\n";
} // namespace

int
main()
{
  std::vector<Case> cases = {
    {"ssnv187_nu4999", "newton", "", 7},
    {"ssnv187_20x_load", "newton", "", 88},
    {"ssnv187_corner", "newton-penalty", "", 21},
    {"ssnv187_corner", "ipopt", "", 10},
    {"ssnv187_corner", "interior-point", "", 9},
    {"ssnv187_corner", "interior-point", amf, 9, "_amf"},
    {"hertz_nu4999", "newton-penalty", local3, 21},
    {"hertz_nu4999", "ipopt", local3, 17},
    {"hertz_nu4999", "interior-point", local3, 8},
    {"hertz_tight_penetration", "newton-penalty", local3, 27},
    {"hertz_tight_penetration", "ipopt", local3, 17},
    {"hertz_tight_penetration", "interior-point", local3, 8},
    {"hertz_initial_gap", "newton-penalty", local3, 24},
    {"hertz_initial_gap", "ipopt", local3, 17},
    {"hertz_initial_gap", "interior-point", local3, 9},
    {"hertz_initial_penetration", "newton-penalty", local3, 24},
    {"hertz_initial_penetration", "ipopt", local3, 19},
    {"hertz_initial_penetration", "interior-point", local3, 10},
    {"stiff_on_soft_block", "newton-penalty", stiff, 26},
    {"stiff_on_soft_block", "ipopt", stiff, 46},
    {"mesh_mismatch", "newton-penalty", mismatch, 26},
    {"mesh_mismatch", "ipopt", mismatch, 61},
    {"ironing_grazing", "newton-penalty", ironing, 33},
    {"ironing_grazing", "ipopt", ironing, 611},
    {"ironing_full", "newton-penalty", ironing, 213},
    {"ironing_full", "ipopt", ironing, 1210},
    // Coulomb friction (issue 50), measured 2026-11-28 under this machine's
    // kernel only (Haswell); rigid-foundation interior point and Newton
    // counts were the same under all six kernels before.
    {"friction_mu1", "interior-point", "", 196},
    {"friction_mu1", "newton-penalty", "", 171},
    {"friction_mu001", "interior-point", "", 64},
    {"friction_mu001", "newton-penalty", "", 64},
    {"friction_reversal", "interior-point", "", 384},
    {"friction_reversal", "newton-penalty", "", 376},
    {"ssnv128_mu001", "interior-point", "", 35},
    {"ssnv128_mu001", "newton-penalty", "", 38},
  };

  std::ofstream     out("output");
  const std::string cwd  = std::filesystem::current_path().string();
  const std::string hard = std::string(SIGNORINI_SOURCE_DIR) + "/prm/hard";
  for (const auto &c : cases)
    {
      const std::string name   = c.scene + "_" + c.method + c.label;
      const std::string folder = cwd + "/" + name;
      std::ofstream(name + ".prm")
        << "include " << hard << "/" << c.scene << ".prm\n"
        << "set Output directory = " << folder << "\n"
        << "subsection Solver\n  set Method = " << c.method << "\nend\n"
        << c.edits
        << "subsection Output\n  set Format = none\n  set Verbosity = quiet\nend\n";
      const int status = std::system((std::string(SIGNORINI_EXECUTABLE) + " " +
                                      name + ".prm > " + name + ".log 2>&1")
                                       .c_str());
      const std::string summary_file = folder + "/summary.json";
      const std::string text         = RunOutput::read_text(summary_file);
      const auto        numbers      = RunOutput::summary_numbers(summary_file);

      out << name << ":\n"
          << "  exit 0 and status converged: "
          << verdict(status == 0 &&
                     text.find("\"status\": \"converged\"") != std::string::npos)
          << "\n"
          << "  no non-finite number in summary.json: "
          << verdict(!text.empty() && text.find("null") == std::string::npos)
          << "\n";

      double min_J = std::numeric_limits<double>::infinity();
      for (const auto &[key, value] : numbers)
        if (key == "min J")
          min_J = std::min(min_J, value);
      out << "  min J > 0 in every load step: "
          << verdict(std::isfinite(min_J) && min_J > 0.) << "\n";

      const bool   rigid_ipopt = c.method == "ipopt" &&
                               text.find("\"rigid foundation\"") != std::string::npos;
      const bool   interior_point = c.method == "interior-point";
      const double tolerance   = first_number(numbers, "penetration tolerance");
      const double penetration = first_number(numbers, "max penetration over h");
      if (text.find("\"contact\"") != std::string::npos)
        {
          const double bound = interior_point                    ? 1e-8 :
                               rigid_ipopt || std::isnan(tolerance) ? 1e-4 :
                                                                      tolerance;
          out << "  penetration / h reported and within "
              << (interior_point ? "1e-8" :
                  rigid_ipopt    ? "1e-4" :
                                   "the penalty tolerance")
              << ": "
              << verdict(std::isfinite(penetration) &&
                         penetration <= bound * (1. + 1e-9) &&
                         text.find("\"penetration tolerance met\": false") ==
                           std::string::npos)
              << "\n";
        }
      out << "  every quantity with a reference within its tolerance: "
          << verdict(!text.empty() &&
                     text.find("\"within tolerance\": false") == std::string::npos)
          << "\n";

      double iterations = first_number(numbers, "ipopt iterations");
      if (std::isnan(iterations))
        iterations = first_number(numbers, "interior_point iterations");
      if (std::isnan(iterations))
        iterations = first_number(numbers, "newton iterations");
      out << "  iterations at most 1.5x the most measured across BLAS kernels ("
          << c.iterations << "): " << verdict(iterations <= 1.5 * c.iterations)
          << "\n";
      std::cerr << name << ": exit " << status << ", "
                << first_number(numbers, "dofs") << " DoFs, "
                << first_number(numbers, "load steps") << " load steps ("
                << first_number(numbers, "step cuts") << " cuts), " << iterations
                << " iterations, min J " << min_J << ", penetration / h "
                << penetration << "\n";
    }
}
