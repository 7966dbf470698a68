// Solver > Linear solver > Direct solver memory limit (MUMPS' ICNTL(23)
// through PETSc_Mumps): a factorisation that needs more than the limit
// ends the run at once with status "failed", exit code 3 and a reason that
// names the limit and the way out (CG + AMG), instead of the system
// killing the process for lack of memory (the sphere on the block at
// 1.1e6 DoFs: 12.7 GB on one rank, doc/performance.md). Before the failure
// was fatal the same run cut its first load step 12 times, 500 failed
// solves in all. Also: 0 (no limit, the default) solves as before, a
// value that is not a whole number is bad input (exit 2, the key named),
// and the 1 MB case ends the same way on 2 ranks.

#include "run_output.h"

#include <fstream>
#include <string>

int
main()
{
  using RunOutput::verdict;
  std::ofstream out("output");
  const auto    limit = [](const std::string &value) {
    return "subsection Solver\n  subsection Linear solver\n"
           "    set Direct solver memory limit = " + value + "\n  end\nend\n";
  };
  const int tiny = RunOutput::run_scene("tiny", "hertz_block.prm", limit("1"));
  out << "1 MB: exit code 3: " << verdict(tiny == 3 * 256) << "\n";
  const std::string summary = RunOutput::read_text("tiny/summary.json");
  out << "1 MB: status failed: "
      << verdict(summary.find("\"status\": \"failed\"") != std::string::npos) << "\n"
      << "1 MB: the reason names the limit and CG + AMG: "
      << verdict(summary.find("more memory than MUMPS may use (at most 1 MB per rank") !=
                   std::string::npos &&
                 summary.find("Type = cg-amg") != std::string::npos)
      << "\n";
  const auto steps = RunOutput::read_csv("tiny/load_steps.csv");
  out << "1 MB: no load step converged, none retried: "
      << verdict(steps.empty() && summary.find("\"step cuts\": 0") != std::string::npos)
      << "\n";
  const int none = RunOutput::run_scene("none", "hertz_block.prm", limit("0"));
  out << "0 (no limit): converges: " << verdict(none == 0) << "\n";
  std::ofstream("bad.prm") << "include " << SIGNORINI_SOURCE_DIR << "/prm/hertz_block.prm\n"
                           << limit("lots");
  const auto bad = RunOutput::execute(std::string(SIGNORINI_EXECUTABLE) +
                                      " --check bad.prm 2>&1");
  out << "'lots': exit code 2, names the key: "
      << verdict(bad.first == 2 &&
                 bad.second.find("Direct solver memory limit") != std::string::npos)
      << "\n";
  const int two = RunOutput::run_scene("two_ranks", "hertz_block.prm", limit("1"),
                                       "mpirun -np 2 --oversubscribe --allow-run-as-root ");
  out << "1 MB on 2 ranks: exit code 3, status failed: "
      << verdict(two == 3 * 256 && RunOutput::read_text("two_ranks/summary.json")
                                       .find("more memory than MUMPS may use") !=
                                     std::string::npos)
      << "\n";
}
