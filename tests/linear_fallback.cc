// The fallback from CG + AMG to the direct solver when CG stalls, and its
// count in summary.json: SSNV187 (Mooney-Rivlin, prm/ssnv187_mooney_rivlin.prm)
// with CG limited to 2 iterations, which cannot reach its tolerance.
// - with 'Fall back to direct': the run converges, every Newton step's
//   linear solve was redone by the direct solver (linear fallbacks equal
//   to the Newton iterations, per load step and in load_steps.csv), and the
//   answer equals the direct solver's to 1e-8;
// - without it: the run fails (exit 3), and the reason says that the CG
//   solves failed (the Newton iterations alone would hide the cause).

#include "run_output.h"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>
#include <sys/wait.h>

using RunOutput::first_number;
using RunOutput::verdict;

int
main()
{
  std::ofstream     out("output");
  // 2 global refinements (2.9k DoFs): on the 9 x 9 mesh AMG's coarse level
  // is the whole problem and CG converges at once.
  const std::string mesh    = "subsection Mesh\n  set Global refinements = 2\nend\n";
  const std::string stalled = "subsection Solver\n  subsection Linear solver\n"
                              "    set Type = cg-amg\n    set Maximum iterations = 2\n"
                              "    set Fall back to direct = @FALLBACK@\n  end\nend\n";
  auto with = [&](const std::string &fallback) {
    std::string text = stalled;
    text.replace(text.find("@FALLBACK@"), 10, fallback);
    return mesh + text;
  };
  const int direct   = RunOutput::run_scene("direct", "ssnv187_mooney_rivlin.prm", mesh);
  const int fallback = RunOutput::run_scene("fallback", "ssnv187_mooney_rivlin.prm",
                                            with("true"));
  const auto numbers = RunOutput::summary_numbers("fallback/summary.json");
  // Each step's "newton iterations" comes before its "linear fallbacks".
  double fallbacks = 0., iterations = 0., step_iterations = 0.;
  bool   every_step = true;
  for (const auto &[key, value] : numbers)
    if (key == "newton iterations")
      step_iterations = value;
    else if (key == "linear fallbacks")
      {
        fallbacks += value;
        every_step &= value == step_iterations && value > 0.;
      }
  iterations = first_number(numbers, "newton iterations");
  const auto steps = RunOutput::read_csv("fallback/load_steps.csv");
  double     csv_fallbacks = 0.;
  for (const auto &row : steps)
    csv_fallbacks += row.at("linear_fallbacks");
  const double u_direct = RunOutput::summary_quantity("direct/summary.json", "top_uy");
  const double u_fallback = RunOutput::summary_quantity("fallback/summary.json", "top_uy");
  out << "direct and fallback runs converge: " << verdict(direct == 0 && fallback == 0)
      << "\n"
      << "every Newton step fell back (fallbacks = Newton iterations, per step): "
      << verdict(fallbacks > 0. && fallbacks == iterations && every_step) << "\n"
      << "load_steps.csv counts the same fallbacks: "
      << verdict(csv_fallbacks == fallbacks) << "\n"
      << "top u_y equals the direct solver's to 1e-8: "
      << verdict(std::abs(u_fallback / u_direct - 1.) < 1e-8) << "\n";
  std::cerr << "fallbacks " << fallbacks << ", Newton iterations " << iterations
            << ", top u_y " << u_fallback << " against " << u_direct << "\n";

  // Fail fast: 10 Newton iterations, and no cut below half the step.
  const int failed = RunOutput::run_scene(
    "no_fallback", "ssnv187_mooney_rivlin.prm",
    with("false") + "subsection Solver\n  subsection Newton\n"
                    "    set Maximum iterations = 10\n  end\nend\n"
                    "subsection Load stepping\n  set Minimum step fraction = 0.5\nend\n");
  const std::string text = RunOutput::read_text("no_fallback/summary.json");
  out << "without the fallback: exit 3, status failed, the reason names the "
         "failed CG solves: "
      << verdict(WIFEXITED(failed) && WEXITSTATUS(failed) == 3 &&
                 text.find("\"status\": \"failed\"") != std::string::npos &&
                 text.find("linear solve(s) failed, the last: CG") !=
                   std::string::npos)
      << "\n";
}
