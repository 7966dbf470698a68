// 3D self-contact, prm/tube_crush_3d.prm (issue 51): a thin-walled tube
// (a quarter: x >= 0, half its length) crushed between two plates to a
// gap of 0.32, below twice its wall. Two runs:
// - the scene: it reaches the end with step cuts before at most 10% of
//   the steps and min J > 0 in every step; self-contact is active at the
//   end; the plate's reaction equals the foundation's (1e-6); and an
//   independent geometric test on the inner surface's nodes
//   (contact_profile_pair2.csv, current positions), layer by layer along
//   the axis (the nodes of one reference y): no node of the lower half
//   lies above the polyline of the upper half in the x-z plane (nor one
//   of the upper half below the lower's) by more than the penalty's
//   tolerance, 1e-2 of the inner faces' diameter (measured 5.6e-4 of
//   1.2e-3);
// - the same with the self-contact term acting nowhere (an exclusion
//   radius of 100, beyond the tube: every face is skipped): the inner
//   halves pass through each other by more than 0.05 (the walls, 0.4
//   thick, in a gap of 0.32): the check is real.
// Only verdicts are printed.

#include "run_output.h"
#include "surface_crossing.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <map>
#include <string>
#include <vector>

namespace
{
  using RunOutput::read_csv;
  using RunOutput::summary_quantity;
  using RunOutput::verdict;

  /// The inner surface's nodes by reference y (rounded to 1e-9): in each
  /// layer ordered by reference x, the halves told apart by reference z
  /// (above or below the axis, z = 1), checked in the x-z plane.
  std::map<long long, std::vector<SurfaceCrossing::Node>>
  layers(const std::string &folder)
  {
    std::map<long long, std::vector<SurfaceCrossing::Node>> nodes;
    for (const auto &row : read_csv(folder + "/contact_profile_pair2.csv"))
      nodes[std::llround(row.at("Xy") * 1e9)].push_back(
        {row.at("Xx"), row.at("Xz"), row.at("x"), row.at("z")});
    return nodes;
  }

  double
  largest_crossing(const std::map<long long, std::vector<SurfaceCrossing::Node>> &all)
  {
    double worst = -1e300;
    for (const auto &layer : all)
      worst = std::max(worst, SurfaceCrossing::largest_crossing(layer.second, 1.));
    return worst;
  }
} // namespace

int
main()
{
  std::ofstream out("output");
  // The inner faces' diameter, the size the penetration tolerance is
  // relative to: the half circumference over 30 faces, 0.5 over 6 along y.
  const double h = std::hypot(3.14159265358979 * 0.8 / 30., 0.5 / 6.);

  const int status = RunOutput::run_scene("run", "tube_crush_3d.prm", "");
  out << "tube exits 0: " << verdict(status == 0) << "\n";
  const auto steps = read_csv("run/load_steps.csv");
  double     cuts = 0., min_J = 1e300, last_t = 0.;
  for (const auto &s : steps)
    {
      cuts += s.at("cuts_before");
      min_J  = std::min(min_J, s.at("min_J"));
      last_t = s.at("time");
    }
  out << "reaches the plate gap 0.32: " << verdict(std::abs(last_t - 1.) < 1e-12) << "\n"
      << "step cuts before at most 10% of the steps: "
      << verdict(!steps.empty() && cuts <= 0.1 * steps.size()) << "\n"
      << "min J > 0 in every step: " << verdict(min_J > 0.) << "\n";
  std::cerr << "steps " << steps.size() << " cuts " << cuts << " min J " << min_J << "\n";

  const std::string summary    = "run/summary.json";
  const double      self_force = summary_quantity(summary, "pair2_self_contact_force");
  const double      active     = summary_quantity(summary, "pair2_active_contact_nodes");
  const double      reaction   = summary_quantity(summary, "reaction_z_boundary_15");
  const double      bottom     = summary_quantity(summary, "pair3_contact_force_z");
  out << "self-contact active at the end (force > 1% of the reaction, nodes > 0): "
      << verdict(self_force > 0.01 * std::abs(reaction) && active > 0) << "\n"
      << "the plate's reaction is the foundation's (1e-6): "
      << verdict(std::abs(std::abs(reaction) - bottom) <= 1e-6 * std::abs(bottom)) << "\n";
  std::cerr << "self force " << self_force << " active " << active << " reaction "
            << reaction << " bottom " << bottom << "\n";

  const double crossing = largest_crossing(layers("run"));
  out << "no inner node beyond the opposite half by more than 1e-2 h: "
      << verdict(crossing <= 1e-2 * h) << "\n";
  std::cerr << "largest crossing " << crossing << " (h " << h << ")\n";

  const int off = RunOutput::run_scene(
    "off", "tube_crush_3d.prm",
    "subsection Contact\n subsection Pairs\n  set Self-contact exclusion radius = 100\n"
    " end\nend\n");
  const double through = largest_crossing(layers("off"));
  out << "self-contact acting nowhere: exits 0: " << verdict(off == 0)
      << "; the inner halves pass through each other by more than 0.05: "
      << verdict(through > 0.05) << "\n";
  std::cerr << "acting nowhere: crossing " << through << "\n";
  return 0;
}
