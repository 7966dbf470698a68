// The active-set polish under CG + AMG with the kept, diagonally scaled
// hierarchy, on the committed 3D scene prm/hertz_sphere.prm (27 882 DoFs,
// interior point method, 2 load steps instead of its 1, CG to 1e-6).
// Measured when written, one rank: polish off 22 interior point iterations
// and 558 CG iterations; polish without active-set updates 13 and 403;
// with the default (6 updates per attempt under CG) 11 and 278 (with CG to
// 1e-8: 16 and 547, 13 and 517, 11 and 369). Checked, with margins for other BLAS
// kernels:
// - the default polish gives the answers of the plain interior point
//   method (p0, a, the contact force) to 1e-6, with at least 3 fewer
//   interior point iterations and at most 0.8 times its CG iterations;
// - its answer has exact complementarity: no node penetrates by more than
//   1e-12 h;
// - updating the active set inside an attempt takes at most 0.85 times
//   the CG iterations of ending the attempt at the first wrong node
//   ('Active-set polish updates = 0');
// - summary.json's 'linear solves' counts the predictor's and the
//   corrector's solve of each interior point iteration (2 per iteration,
//   more with inertia corrections; at most 4 checked) in the run without
//   the polish;
// - two ranks give the one-rank answers to 1e-7;
// - with hypre's BoomerAMG and a new hierarchy for every matrix ('AMG
//   package = BoomerAMG', 'Keep preconditioner = false') the polish runs
//   too: at least 3 fewer interior point iterations than without it (it
//   was off in that setting until 2026-11-27), the answers of the default
//   to 1e-6;
// - summary.json's 'AMG builds' (per load step, and their total in
//   "solver"): the kept hierarchy is built at most once per 4 solves; the
//   new hierarchies of BoomerAMG are built once per interior point
//   iteration at least (a new matrix each) but fewer times than there are
//   solves (the corrector reuses the predictor's).

#include "run_output.h"

#include <fstream>
#include <iostream>
#include <string>

using RunOutput::verdict;

int
main()
{
  std::ofstream     out("output");
  const std::string mpirun = "mpirun --allow-run-as-root --oversubscribe -np 2 ";
  // Two load steps (the scene has one): two warm-started polish attempts.
  const std::string two_steps = "subsection Load stepping\n  set Number of steps = 2\nend\n";
  const auto        polish    = [&](const std::string &entry) {
    return two_steps + "subsection Solver\n  subsection Interior point\n    set " + entry +
           "\n  end\nend\n";
  };
  const int on  = RunOutput::run_scene("default", "hertz_sphere.prm", two_steps);
  const int off = RunOutput::run_scene("off", "hertz_sphere.prm",
                                       polish("Active-set polish = false"));
  const int no_updates = RunOutput::run_scene(
    "no_updates", "hertz_sphere.prm", polish("Active-set polish updates = 0"));
  const int two = RunOutput::run_scene("two_ranks", "hertz_sphere.prm", two_steps, mpirun);
  const std::string boomeramg =
    "subsection Solver\n  subsection Linear solver\n    set AMG package = BoomerAMG\n"
    "    set Keep preconditioner = false\n  end\nend\n";
  const int boomer = RunOutput::run_scene("boomeramg", "hertz_sphere.prm", two_steps + boomeramg);
  const int boomer_off = RunOutput::run_scene(
    "boomeramg_off", "hertz_sphere.prm", polish("Active-set polish = false") + boomeramg);

  const auto iterations = [](const std::string &run) {
    return RunOutput::first_number(RunOutput::summary_numbers(run + "/summary.json"),
                                   "interior_point iterations");
  };
  const auto cg = [](const std::string &run) {
    return RunOutput::summary_sum(run, "linear iterations");
  };
  const auto solves = [](const std::string &run) {
    return RunOutput::summary_sum(run, "linear solves");
  };
  // The total in "solver" comes first, then one entry per load step.
  const auto total_builds = [](const std::string &run) {
    const auto numbers = RunOutput::summary_numbers(run + "/summary.json");
    return RunOutput::first_number(numbers, "AMG builds");
  };
  const auto builds = [&](const std::string &run) {
    return RunOutput::summary_sum(run, "AMG builds") - total_builds(run);
  };
  const std::vector<std::string> answers = {"hertz_p0", "hertz_a", "contact_force_z"};
  const double against_off = RunOutput::largest_relative_difference("default", "off", answers);
  const double against_two =
    RunOutput::largest_relative_difference("two_ranks", "default", answers);
  const double against_boomer =
    RunOutput::largest_relative_difference("boomeramg", "default", answers);
  const double penetration =
    RunOutput::summary_quantity("default/summary.json", "max_penetration_over_h");
  std::cerr << "exit codes " << on << " " << off << " " << no_updates << " " << two
            << "; interior point iterations default " << iterations("default")
            << ", off " << iterations("off") << ", no updates "
            << iterations("no_updates") << "; CG iterations " << cg("default") << ", "
            << cg("off") << ", " << cg("no_updates") << "; linear solves "
            << solves("default") << ", " << solves("off") << ", " << solves("no_updates")
            << "; against off "
            << against_off << ", two ranks " << against_two << ", penetration / h "
            << penetration << "; BoomerAMG exit codes " << boomer << " " << boomer_off
            << ", interior point iterations " << iterations("boomeramg") << " and "
            << iterations("boomeramg_off") << " without the polish, against the default "
            << against_boomer << "; AMG builds " << builds("default") << " (total "
            << total_builds("default") << "), BoomerAMG " << builds("boomeramg") << " in "
            << solves("boomeramg") << " solves\n";
  const bool ran = on == 0 && off == 0 && no_updates == 0 && two == 0;
  out << "all runs converged: " << verdict(ran) << "\n"
      << "the polished answers equal the plain method's to 1e-6: "
      << verdict(ran && against_off < 1e-6) << "\n"
      << "at least 3 fewer interior point iterations: "
      << verdict(ran && iterations("default") + 3 <= iterations("off")) << "\n"
      << "at most 0.8 times the CG iterations: "
      << verdict(ran && cg("default") <= 0.8 * cg("off")) << "\n"
      << "no node penetrates by more than 1e-12 h: "
      << verdict(ran && penetration <= 1e-12) << "\n"
      << "active-set updates take at most 0.85 times the CG iterations of none: "
      << verdict(ran && cg("default") <= 0.85 * cg("no_updates")) << "\n"
      << "the summary counts at least the predictor's and the corrector's solve "
         "per interior point iteration, at most 4: "
      << verdict(ran && solves("off") >= 2 * iterations("off") &&
                 solves("off") <= 4 * iterations("off"))
      << "\n"
      << "two ranks give the same answers to 1e-7: "
      << verdict(ran && against_two < 1e-7) << "\n"
      << "BoomerAMG with new hierarchies polishes: at least 3 fewer interior "
         "point iterations, the default's answers to 1e-6: "
      << verdict(boomer == 0 && boomer_off == 0 &&
                 iterations("boomeramg") + 3 <= iterations("boomeramg_off") &&
                 against_boomer < 1e-6)
      << "\n"
      << "summary.json counts the AMG builds: kept at most once per 4 solves, "
         "BoomerAMG's new ones once per matrix: "
      << verdict(ran && boomer == 0 && builds("default") >= 1 &&
                 4 * builds("default") <= solves("default") &&
                 total_builds("default") == builds("default") &&
                 builds("boomeramg") >= iterations("boomeramg") &&
                 builds("boomeramg") < solves("boomeramg"))
      << "\n";
}
