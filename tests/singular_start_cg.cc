// A body held only by contact has a singular Hessian until it touches:
// the peer's rigid Hertz scene (prm/hertz_peer.prm, 9618 DoFs, the load
// in one step, u_x = 0 on the top edge only) starts the penalty path from
// a state where the vertical rigid motion costs no energy. CG + AMG on
// that Hessian used to run to its iteration limit and then fall back to
// the direct solver (whose solution is just as large, and rejected); now
// CG stops as soon as an iterate exceeds 1e3 scene sizes and Newton
// shifts the Hessian at once. Checked, on 1 and 2 ranks:
// - the run converges with no fallback to the direct solver and at most
//   300 CG iterations in all;
// - its contact force, Hertz a and p0 equal the direct solver's to 1e-8.

#include "run_output.h"

#include <cmath>
#include <fstream>
#include <iostream>
#include <string>

using RunOutput::verdict;

int
main()
{
  std::ofstream     out("output");
  const std::string mpirun = "mpirun --allow-run-as-root --oversubscribe -np 2 ";
  const std::string penalty =
    "subsection Solver\n  set Method = newton-penalty\n  subsection Linear solver\n";
  const int direct = RunOutput::run_scene(
    "direct", "hertz_peer.prm", penalty + "    set Type = direct\n  end\nend\n");
  for (const bool two : {false, true})
    {
      const std::string name = two ? "cg_amg_2_ranks" : "cg_amg";
      const int         status =
        RunOutput::run_scene(name,
                             "hertz_peer.prm",
                             penalty + "    set Type = cg-amg\n  end\nend\n",
                             two ? mpirun : "");
      const double fallbacks = RunOutput::summary_sum(name, "linear fallbacks");
      const double cg        = RunOutput::summary_sum(name, "linear iterations");
      const double worst     = RunOutput::largest_relative_difference(
        "direct", name, {"contact_force_y", "hertz_a", "hertz_p0"});
      std::cerr << name << ": exit " << status << " (direct " << direct << "), "
                << fallbacks << " fallbacks, " << cg
                << " CG iterations, largest relative difference " << worst << "\n";
      out << name << ": converges without the direct fallback in at most 300 CG "
          << "iterations: " << verdict(status == 0 && fallbacks == 0 && cg <= 300)
          << "; the direct solver's answers to 1e-8: "
          << verdict(direct == 0 && worst < 1e-8) << "\n";
    }
}
