// Coulomb friction on the rigid foundation, prm/sliding_block.prm (issue
// 50): a block pressed onto the plane, then dragged sideways by its top
// until every contact node slides. Checked from reactions.csv,
// load_steps.csv, contact_profile.csv and summary.json:
// - with the interior point method, newton-penalty and Ipopt: while any
//   contact node sticks, |Rx| < mu |Ry|; once all slide, |Rx| = mu |Ry|
//   within 0.1% (measured: 5.5e-8 and 5.4e-8); the top's reaction balances
//   the friction and the normal contact force (1e-6 of |Ry|); every
//   step's outer loop ends below the 1e-6 tolerance in at most 10
//   iterations;
// - on each sliding node |t_T| = mu p within 1%, on each sticking node
//   |t_T| <= mu p, at the end of the path (all slide) and at t = 1.2
//   (partial slip);
// - over a cycle (press, drag by +0.05, drag back, lift the top back to
//   its start, where the contact force vanishes) the work of the top's
//   reaction (trapezoidal rule over 20 steps per leg) equals the stored
//   energy at the end plus the dissipated energy, within 1% (measured:
//   5.2111e-4 against 3.7e-19 + 5.2005e-4, 0.20%); the last step's contact
//   force is below 1e-6 of the largest (measured 4.7e-10 against 2.5e-2),
//   and every step's outer loop ends within 10 iterations.
// Only verdicts are printed: iteration counts depend on the BLAS kernel.

#include "run_output.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <string>

namespace
{
  using RunOutput::read_csv;
  using RunOutput::verdict;
  const double mu = 0.3;

  /// The checks of a run whose path ends in gross slip.
  void
  check_path(std::ostream &out, const std::string &run, const std::string &what)
  {
    const auto reactions = read_csv(run + "/reactions.csv");
    const auto steps     = read_csv(run + "/load_steps.csv");
    out << what << ": " << steps.size() << " load steps, reactions of each: "
        << verdict(!steps.empty() && reactions.size() == steps.size()) << "\n";
    if (steps.empty() || reactions.size() != steps.size())
      return;
    bool   stick_below = true, slid = false, settled = true;
    double worst_slip = 0., worst_balance = 0.;
    for (unsigned int i = 0; i < steps.size(); ++i)
      {
        const double rx = reactions[i].at("Rx_3"), ry = reactions[i].at("Ry_3");
        const auto  &s  = steps[i];
        const double active = s.at("active_contact_nodes");
        worst_balance =
          std::max({worst_balance, std::abs(rx + s.at("friction_force_x")) / std::abs(ry),
                    std::abs(ry + s.at("contact_force_y")) / std::abs(ry)});
        settled = settled && s.at("friction_iterations") <= 10 &&
                  s.at("friction_change") <= 1e-6;
        if (s.at("stick_points") > 0)
          stick_below = stick_below && std::abs(rx) < mu * std::abs(ry);
        else if (s.at("slip_points") == active && active > 0)
          {
            slid       = true;
            worst_slip = std::max(worst_slip, std::abs(std::abs(rx) / (mu * std::abs(ry)) - 1.));
          }
      }
    std::cerr << what << ": gross slip |Rx|/(mu|Ry|) - 1 up to " << worst_slip
              << ", balance " << worst_balance << "\n";
    out << what << ": |Rx| < mu |Ry| while a node sticks: " << verdict(stick_below) << "\n"
        << what << ": gross slip reached: " << verdict(slid) << "\n"
        << what << ": |Rx| = mu |Ry| within 0.1% in gross slip: "
        << verdict(slid && worst_slip <= 1e-3) << "\n"
        << what << ": the top balances friction and contact force (1e-6): "
        << verdict(worst_balance <= 1e-6) << "\n"
        << what << ": outer loop below 1e-6 within 10 iterations each step: "
        << verdict(settled) << "\n";
  }

  /// Coulomb's law node by node in the last profile of @p run.
  void
  check_nodes(std::ostream &out, const std::string &run, const std::string &what)
  {
    const auto nodes = read_csv(run + "/contact_profile.csv");
    double     largest = 0.;
    for (const auto &n : nodes)
      largest = std::max(largest, n.at("pressure"));
    unsigned int n_stick = 0, n_slip = 0;
    bool         slip_ok = true, stick_ok = true;
    for (const auto &n : nodes)
      {
        const double p = n.at("pressure"), t = std::abs(n.at("friction_traction_x"));
        if (p <= 1e-6 * largest)
          continue;
        if (n.at("friction_status") == 2.)
          {
            ++n_slip;
            slip_ok = slip_ok && std::abs(t / (mu * p) - 1.) <= 1e-2;
          }
        else if (n.at("friction_status") == 1.)
          {
            ++n_stick;
            stick_ok = stick_ok && t <= mu * p * (1. + 1e-12);
          }
      }
    out << what << ": " << (n_slip > 0 ? "sliding nodes" : "NO SLIDING NODE")
        << ", |t_T| = mu p within 1%: " << verdict(n_slip > 0 && slip_ok) << "\n";
    if (n_stick > 0)
      out << what << ": sticking nodes, |t_T| <= mu p: " << verdict(stick_ok) << "\n";
  }
} // namespace

int
main()
{
  std::ofstream out("output");
  out << "interior point: exit code 0: "
      << verdict(RunOutput::run_scene("run_ip", "sliding_block.prm", "") == 0) << "\n";
  check_path(out, "run_ip", "interior point");
  check_nodes(out, "run_ip", "interior point, t = 2");

  out << "newton-penalty: exit code 0: "
      << verdict(RunOutput::run_scene("run_penalty", "sliding_block.prm",
                                      "subsection Solver\n  set Method = newton-penalty\nend\n") ==
                 0)
      << "\n";
  check_path(out, "run_penalty", "newton-penalty");
  check_nodes(out, "run_penalty", "newton-penalty, t = 2");

  out << "ipopt: exit code 0: "
      << verdict(RunOutput::run_scene("run_ipopt", "sliding_block.prm",
                                      "subsection Solver\n  set Method = ipopt\nend\n") == 0)
      << "\n";
  check_path(out, "run_ipopt", "ipopt");
  check_nodes(out, "run_ipopt", "ipopt, t = 2");

  // Partial slip: the path stopped at t = 1.2.
  out << "partial slip: exit code 0: "
      << verdict(RunOutput::run_scene("run_partial", "sliding_block.prm",
                                      "subsection Load stepping\n  set End time = 1.2\n"
                                      "  set Number of steps = 6\nend\n") == 0)
      << "\n";
  check_nodes(out, "run_partial", "partial slip, t = 1.2");

  // Energy over a cycle: press (t <= 1), drag by +0.05 (1..2), drag back
  // (2..3), lift the top back to its start (3..4): the contact force
  // vanishes at t = 4.
  const std::string ux = "0.05*(min(max(t - 1, 0), 1) - min(max(t - 2, 0), 1))";
  const std::string uy = "-0.01*min(t, 1) + 0.01*min(max(t - 3, 0), 1)";
  out << "cycle: exit code 0: "
      << verdict(RunOutput::run_scene(
                   "run_cycle", "sliding_block.prm",
                   "subsection Boundary conditions\n  set Prescribed displacement = " + ux +
                     "; " + uy +
                     "\nend\nsubsection Load stepping\n  set End time = 4\n"
                     "  set Number of steps = 80\nend\n") == 0)
      << "\n";
  const auto reactions = read_csv("run_cycle/reactions.csv");
  const auto top       = [](const double t) {
    const auto clamp01 = [](const double x) { return std::min(std::max(x, 0.), 1.); };
    return std::make_pair(0.05 * (clamp01(t - 1) - clamp01(t - 2)),
                          -0.01 * std::min(t, 1.) + 0.01 * clamp01(t - 3));
  };
  double work = 0., t_old = 0., rx_old = 0., ry_old = 0.;
  for (const auto &r : reactions)
    {
      const double t = r.at("time");
      const auto   a = top(t_old), b = top(t);
      work += 0.5 * (rx_old + r.at("Rx_3")) * (b.first - a.first) +
              0.5 * (ry_old + r.at("Ry_3")) * (b.second - a.second);
      t_old  = t;
      rx_old = r.at("Rx_3");
      ry_old = r.at("Ry_3");
    }
  const double stored =
    RunOutput::summary_quantity("run_cycle/summary.json", "potential_energy");
  const double dissipated =
    RunOutput::summary_quantity("run_cycle/summary.json", "dissipated_energy");
  std::cerr << "cycle: work " << work << " stored " << stored << " dissipated " << dissipated
            << "\n";
  out << "cycle: reaches t = 4: "
      << verdict(!reactions.empty() && std::abs(reactions.back().at("time") - 4.) < 1e-9)
      << "\n"
      << "cycle: external work = stored + dissipated energy within 1%: "
      << verdict(dissipated > 0. && std::abs(work - stored - dissipated) <= 1e-2 * work)
      << "\n";
  const auto   cycle_steps = read_csv("run_cycle/load_steps.csv");
  double       largest     = 0.;
  unsigned int outer       = 0;
  for (const auto &s : cycle_steps)
    {
      largest = std::max(largest, std::abs(s.at("contact_force_y")));
      outer   = std::max(outer, static_cast<unsigned int>(s.at("friction_iterations")));
    }
  const double last = cycle_steps.empty() ? 1. : std::abs(cycle_steps.back().at("contact_force_y"));
  std::cerr << "cycle: last contact force " << last << " of largest " << largest
            << ", outer iterations at most " << outer << "\n";
  out << "cycle: the contact force vanishes at the end (below 1e-6 of the largest): "
      << verdict(largest > 0. && last <= 1e-6 * largest) << "\n"
      << "cycle: every step's outer loop ends within 10 iterations: "
      << verdict(!cycle_steps.empty() && outer <= 10) << "\n";
}
