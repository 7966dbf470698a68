// A load step that fails is cut in half, and the steps after it still land
// on the requested times (the multiples of End time / Number of steps):
// prm/hertz_block.prm in 3 steps with at most 6 Newton iterations per
// penalty stage, so that the first steps fail and are cut (measured: 23
// cuts, 22 steps). Checks: the run converges, cuts happen, every requested
// time (1/3, 2/3, 1) is a step's end, and the force at the end is the run
// without cuts' within 1e-6. Until the step after a cut was clipped to the
// next requested time, the same run ended its steps at 0.34375 and
// 0.677083 (28 steps): the reactions at 1/3 and 2/3 were never computed.

#include "run_output.h"

#include <cmath>
#include <fstream>

int
main()
{
  using RunOutput::verdict;
  std::ofstream out("output");
  const int     cut = RunOutput::run_scene(
    "cut", "hertz_block.prm",
    "subsection Load stepping\n  set Number of steps = 3\nend\n"
    "subsection Solver\n  subsection Newton\n    set Maximum iterations = 6\n  end\nend\n");
  const int plain = RunOutput::run_scene(
    "plain", "hertz_block.prm", "subsection Load stepping\n  set Number of steps = 3\nend\n");
  out << "both runs exit 0: " << verdict(cut == 0 && plain == 0) << "\n";
  const auto   steps = RunOutput::read_csv("cut/load_steps.csv");
  unsigned int cuts  = 0;
  for (const auto &s : steps)
    cuts += static_cast<unsigned int>(s.at("cuts_before"));
  out << "steps were cut: " << verdict(cuts > 0) << "\n";
  for (const double t : {1. / 3., 2. / 3., 1.})
    {
      bool found = false;
      for (const auto &s : steps)
        found = found || std::abs(s.at("time") - t) < 1e-9;
      out << "a step ends at t = " << t << ": " << verdict(found) << "\n";
    }
  const auto   last  = RunOutput::read_csv("plain/load_steps.csv");
  const double f_cut = steps.empty() ? 0. : steps.back().at("contact_force");
  const double f     = last.empty() ? 1. : last.back().at("contact_force");
  out << "final contact force as without cuts (1e-6): "
      << verdict(std::abs(f_cut - f) <= 1e-6 * std::abs(f)) << "\n";
}
