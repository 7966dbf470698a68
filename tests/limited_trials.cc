// Newton's limited line-search trials (Solver > Newton > Limit trials,
// with Load step reduction = 1) against the former settings (no limit,
// reduction 10), whole program, on the rigid Hertz scenes with the penalty
// path (their default is the interior point method):
// - prm/default.prm: the same answer (contact force, a and p0 to 1e-4
//   relative: the last stage ends at another penalty), at most 25 Newton
//   iterations with the limit (the goal of issue 17; measured 25, 30
//   without) and fewer than without;
// - prm/hard/hertz_tight_penetration.prm (penetration down to 1e-6 h):
//   the same answer, and fewer iterations with the limit (measured 27
//   against 65).
// The lift itself is checked node by node in tests/limit_trial.

#include "run_output.h"

#include <fstream>
#include <string>

using RunOutput::verdict;

int
main()
{
  std::ofstream     out("output");
  const std::string penalty =
    "subsection Solver\n  set Method = newton-penalty\nend\n";
  const std::string former = penalty + "subsection Solver\n"
                             "  subsection Newton\n"
                             "    set Limit trials = false\n"
                             "  end\n"
                             "  subsection Penalty\n"
                             "    set Load step reduction = 10\n"
                             "  end\n"
                             "end\n";
  for (const std::string scene : {"default", "hard/hertz_tight_penetration"})
    {
      const std::string name = scene == "default" ? "default" : "tight";
      const bool        ran =
        RunOutput::run_scene(name + "_limited", scene + ".prm", penalty) == 0 &&
        RunOutput::run_scene(name + "_former", scene + ".prm", former) == 0;
      out << scene << ": both runs converged: " << verdict(ran) << "\n";
      if (!ran)
        continue;
      const double limited = RunOutput::newton_iterations(name + "_limited");
      const double plain   = RunOutput::newton_iterations(name + "_former");
      out << scene << ": same answer with and without the limit (1e-4): "
          << verdict(RunOutput::same_hertz_answer(name + "_limited",
                                                  name + "_former", 1e-4))
          << "\n"
          << scene << ": fewer Newton iterations with the limit: "
          << verdict(limited > 0. && limited < plain) << "\n";
      if (scene == "default")
        out << scene << ": at most 25 Newton iterations with the limit: "
            << verdict(limited > 0. && limited <= 25.) << "\n";
    }
}
