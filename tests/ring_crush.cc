// Self-contact, prm/ring_crush.prm (issue 51): a ring crushed between two
// plates until its inner surface folds onto itself. Three runs:
// - the scene (the half ring, x >= 0): it reaches the plate gap 4.0 with
//   step cuts before at most 10% of the steps and min J > 0 in every
//   step; self-contact is active at the end (a force and active nodes);
//   the plate's reaction equals the foundation's and the ring is in
//   balance (1e-6 of the reaction); and an independent geometric test
//   on the inner surface's nodes (contact_profile_pair2.csv, current
//   positions): no node of the lower half lies above the polyline of
//   the upper half (nor one of the upper half below the lower half's)
//   by more than the penalty's tolerance, 1e-2 of the inner faces' size;
// - the same with the self-contact term acting nowhere (an exclusion
//   radius of 100, beyond the ring: every face is skipped): the inner
//   surfaces pass through each other, by more than 0.1 (the walls, 4.4
//   thick, in a gap of 4.0): the check above is real;
// - the same declared as 'Body 1 > Self contact' instead of the pairs'
//   list: the same reaction and self-contact force;
// - the full ring (plate x in [-8, 8], u_x held at the ring's lowest and
//   highest points, 'Fixed points'): its plate reaction is twice the half
//   model's within 0.5%.
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

  /// The inner surface's nodes: ordered along the surface by reference
  /// x, the halves told apart by reference y (above or below the centre).
  std::vector<SurfaceCrossing::Node>
  inner_nodes(const std::string &folder)
  {
    std::vector<SurfaceCrossing::Node> nodes;
    for (const auto &row : read_csv(folder + "/contact_profile_pair2.csv"))
      nodes.push_back({row.at("Xx"), row.at("Xy"), row.at("x"), row.at("y")});
    return nodes;
  }
} // namespace

int
main()
{
  std::ofstream out("output");
  const double  cy = 6.35, h = 3.14159265358979 * 4.15 / 64.; // inner faces

  const int status = RunOutput::run_scene("half", "ring_crush.prm", "");
  out << "half ring exits 0: " << verdict(status == 0) << "\n";
  const auto steps = read_csv("half/load_steps.csv");
  double     cuts = 0., min_J = 1e300, last_t = 0.;
  for (const auto &s : steps)
    {
      cuts += s.at("cuts_before");
      min_J  = std::min(min_J, s.at("min_J"));
      last_t = s.at("time");
    }
  out << "reaches the plate gap 4.0: " << verdict(std::abs(last_t - 1.) < 1e-12) << "\n"
      << "step cuts before at most 10% of " << steps.size() << " steps: "
      << verdict(!steps.empty() && cuts <= 0.1 * steps.size()) << "\n"
      << "min J > 0 in every step: " << verdict(min_J > 0.) << "\n";
  std::cerr << "steps " << steps.size() << " cuts " << cuts << " min J " << min_J << "\n";

  const std::string summary    = "half/summary.json";
  const double      self_force = summary_quantity(summary, "pair2_self_contact_force");
  const double      active     = summary_quantity(summary, "pair2_active_contact_nodes");
  const double      reaction   = summary_quantity(summary, "reaction_y_boundary_13");
  const double      plate      = summary_quantity(summary, "pair1_contact_force_y");
  const double      bottom     = summary_quantity(summary, "pair3_contact_force_y");
  const double      ring_y     = summary_quantity(summary, "body1_contact_force_y");
  out << "self-contact active at the end (force > 1% of the reaction, nodes > 0): "
      << verdict(self_force > 0.01 * std::abs(reaction) && active > 0) << "\n"
      << "plate and foundation carry the reaction (1e-6): "
      << verdict(std::abs(plate + bottom) <= 1e-6 * std::abs(bottom) &&
                 std::abs(std::abs(reaction) - bottom) <= 1e-6 * std::abs(bottom))
      << "\n"
      << "ring in balance (1e-6 of the reaction): "
      << verdict(std::abs(ring_y) <= 1e-6 * std::abs(bottom)) << "\n";
  std::cerr << "self force " << self_force << " active " << active << " reaction "
            << reaction << " plate " << plate << " bottom " << bottom << " ring "
            << ring_y << "\n";

  const double crossing = SurfaceCrossing::largest_crossing(inner_nodes("half"), cy);
  out << "no inner node beyond the opposite half by more than 1e-2 h: "
      << verdict(crossing <= 1e-2 * h) << "\n";
  std::cerr << "largest crossing " << crossing << " (h " << h << ")\n";

  // Without self-contact the halves pass through each other. The term is
  // switched off by an exclusion radius beyond the ring (every face is
  // skipped for every point: it acts nowhere), so that the inner
  // surface's nodes are still reported in pair 2's profile.
  const int off = RunOutput::run_scene(
    "off", "ring_crush.prm",
    "subsection Contact\n subsection Pairs\n  set Self-contact exclusion radius = 100\n"
    " end\nend\n");
  const double through = SurfaceCrossing::largest_crossing(inner_nodes("off"), cy);
  out << "without self-contact: exits 0: " << verdict(off == 0)
      << "; the inner surfaces pass through each other by more than 0.1: "
      << verdict(through > 0.1) << "\n";
  std::cerr << "without self-contact: crossing " << through << "\n";

  // The same self-contact declared on the body ('Body 1 > Self contact'):
  // the same pair, the same answer.
  const int    shorthand = RunOutput::run_scene(
    "body", "ring_crush.prm",
    "subsection Contact\n subsection Pairs\n  set Self-contact boundary ids =\n end\nend\n"
    "subsection Body 1\n set Self contact = true\n set Self contact boundary ids = 0\nend\n");
  const double body_reaction = summary_quantity("body/summary.json", "reaction_y_boundary_13");
  const double body_self = summary_quantity("body/summary.json", "pair2_self_contact_force");
  out << "Body 1 > Self contact instead of the pairs' list: exits 0: "
      << verdict(shorthand == 0) << "; the same reaction and self-contact force (1e-12): "
      << verdict(std::abs(body_reaction / reaction - 1.) <= 1e-12 &&
                 std::abs(body_self / self_force - 1.) <= 1e-12)
      << "\n";
  std::cerr << "body shorthand: reaction " << body_reaction << " self " << body_self << "\n";

  // The full ring: twice the half's reaction.
  const int full = RunOutput::run_scene(
    "full", "ring_crush.prm",
    "subsection Body 1\n subsection Geometry\n  set Shape = ring\n end\nend\n"
    "subsection Body 2\n subsection Geometry\n  set Lower corner = -8, 12.7\n"
    "  set Subdivisions = 16, 1\n end\nend\n"
    "subsection Boundary conditions\n set Fixed boundaries =\n"
    " set Fixed points = 0, 0: x; 0, 12.7: x\nend\n");
  const double full_reaction = summary_quantity("full/summary.json", "reaction_y_boundary_13");
  const double difference    = std::abs(full_reaction / (2. * reaction) - 1.);
  out << "full ring exits 0: " << verdict(full == 0)
      << "; its reaction twice the half's within 0.5%: " << verdict(difference <= 5e-3)
      << "\n";
  std::cerr << "full reaction " << full_reaction << " half x 2 " << 2. * reaction
            << " difference " << difference << "\n";
  return 0;
}
