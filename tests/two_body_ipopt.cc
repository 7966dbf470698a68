// Two-body contact with Ipopt as the unconstrained minimiser of each penalty
// stage G_mu (the poster's solver) against Newton on the same stages: the
// Hertz cylinder on an elastic block (prm/hertz_block.prm, one local
// refinement less: 2302 DoFs), nodal and integral forms. For each form:
// - both runs converge and meet the scene's Hertz tolerances (exit 0);
// - a, p0 and the total contact force of the two solvers agree to 1e-5
//   (both minimise the same G_mu to their tolerances; measured: 6e-8);
// - the Ipopt run ends with the penetration the continuation asks for
//   (summary.json: "penetration tolerance met");
// - Ipopt minimises every stage but at most the first of each load step:
//   one that starts with the cylinder held only by contact at zero
//   penetration has a singular Hessian, which Ipopt may take for a
//   definite one (depending on the BLAS's round-off), and is then
//   minimised by Newton (summary.json counts such stages).

#include "run_output.h"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>

using RunOutput::summary_quantity;
using RunOutput::verdict;

namespace
{
  int
  run(const std::string &name, const std::string &method, const std::string &form)
  {
    return RunOutput::run_scene(
      name, "hertz_block.prm",
      "subsection Mesh\n  set Local refinements = 4\nend\n"
      "subsection Contact\n  subsection Two bodies\n    set Contact form = " +
        form + "\n  end\nend\nsubsection Solver\n  set Method = " + method +
        "\nend\n");
  }
} // namespace

int
main()
{
  std::ofstream out("output");
  for (const std::string form : {"nodal", "integral"})
    {
      const std::string newton = "newton_" + form, ipopt = "ipopt_" + form;
      const int         newton_status = run(newton, "newton-penalty", form);
      const int         ipopt_status  = run(ipopt, "ipopt", form);
      out << form << ": both runs exit 0 (converged, Hertz tolerances met): "
          << verdict(newton_status == 0 && ipopt_status == 0) << "\n";
      for (const std::string q : {"hertz_a", "hertz_p0", "contact_force_y"})
        {
          const double a = summary_quantity(newton + "/summary.json", q);
          const double b = summary_quantity(ipopt + "/summary.json", q);
          const double difference = std::abs(a - b) / std::abs(a);
          out << form << ": " << q << " of Ipopt and Newton agree to 1e-5: "
              << verdict(difference < 1e-5) << "\n";
          std::cerr << form << " " << q << " newton " << a << " ipopt " << b
                    << " relative difference " << difference << "\n";
        }
      // The points the penalty acts on (the integral form's Gauss points;
      // its nodes between them are reported but not penalised).
      out << form << ": Ipopt run meets the penetration tolerance 1e-3 h: "
          << verdict(RunOutput::summary_flag(ipopt + "/summary.json",
                                             "penetration tolerance met"))
          << "\n";
      const auto   numbers = RunOutput::summary_numbers(ipopt + "/summary.json");
      const double by_newton =
        RunOutput::first_number(numbers, "ipopt stages minimised by newton");
      const double steps = RunOutput::first_number(numbers, "load steps");
      out << form << ": Ipopt minimised all stages but at most one per load "
          << "step: " << verdict(by_newton <= steps) << "\n";
      std::cerr << form << ": stages minimised by Newton " << by_newton
                << " in " << steps << " load steps\n";
    }
}
