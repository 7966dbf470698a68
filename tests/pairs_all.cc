// 'Two-body pairs = all' (issue 51): every body against every other with
// one search, on prm/disk_stack.prm (three disks on the rigid plane, the
// top one loaded) with 'Contact boundaries = 0, 10, 20' (the arcs)
// instead of the list of the two neighbour pairs. From the run's
// summary.json and pair 1's profile (the all-bodies part):
// - every body balanced to 1e-8 of the load (bodyB_contact_force_y), the
//   all-bodies part's own resultant zero (its actions and reactions), the
//   foundation carrying the load;
// - at each disk-disk contact (y = 4 and y = 2) the largest nodal
//   pressure within 2% of Hertz's p0 with that contact's R* and E*
//   (measured -0.1% and -0.13%);
// - the search follows the contact zones: the (point, face) pairs
//   evaluated at the last step are at most 2.5 times those of the scene's
//   two listed pairs (both sides of each contact are points now: about 2),
//   though every body is tested against every other.
// - the default ('Two-body pairs = all' without 'Contact boundaries':
//   the free surfaces, here the three arcs) gives the same forces.
// Only verdicts are printed.

#include "run_output.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

namespace
{
  using RunOutput::read_csv;
  using RunOutput::summary_quantity;
  using RunOutput::verdict;

  const std::string no_hertz =
    "    subsection Pair 1\n      subsection Hertz reference\n        set Line load = 0\n"
    "      end\n    end\n"
    "    subsection Pair 2\n      subsection Hertz reference\n        set Line load = 0\n"
    "      end\n    end\n"
    "    subsection Pair 3\n      subsection Hertz reference\n        set Line load = 0\n"
    "      end\n    end\n";

  double
  last_evaluated_pairs(const std::string &folder)
  {
    const auto rows = read_csv(folder + "/load_steps.csv");
    return rows.empty() ? -1. : rows.back().at("evaluated_pairs");
  }
} // namespace

int
main()
{
  std::ofstream out("output");
  const int     status = RunOutput::run_scene(
    "all", "disk_stack.prm",
    "subsection Contact\n  subsection Pairs\n    set Two-body pairs = all\n"
    "    set Contact boundaries = 0, 10, 20\n" +
      no_hertz + "  end\nend\n");
  out << "all bodies: exits 0: " << verdict(status == 0) << "\n";
  const std::string s    = "all/summary.json";
  const double      half = 0.2; // P/2 on the half model
  const double      b1 = summary_quantity(s, "body1_contact_force_y"),
               b2 = summary_quantity(s, "body2_contact_force_y"),
               b3 = summary_quantity(s, "body3_contact_force_y");
  const double own = std::hypot(summary_quantity(s, "pair1_contact_force_x"),
                                summary_quantity(s, "pair1_contact_force_y"));
  const double ground = summary_quantity(s, "pair2_contact_force_y");
  out << "bodies balanced to 1e-8 of the load: "
      << verdict(std::abs(b1 - half) <= 1e-8 * half && std::abs(b2) <= 1e-8 * half &&
                 std::abs(b3) <= 1e-8 * half)
      << "; the part's resultant zero: " << verdict(own <= 1e-12)
      << "; the foundation carries the load: "
      << verdict(std::abs(ground - half) <= 1e-8 * half) << "\n";
  std::cerr << "bodies " << b1 << " " << b2 << " " << b3 << " own " << own << " ground "
            << ground << "\n";

  // Hertz's p0 of each disk-disk contact: R* = 1/2, 1/E* = sum (1 - nu^2)/E.
  const auto rows = read_csv("all/contact_profile_pair1.csv");
  const double P = 0.4, nu = 0.3;
  const struct
  {
    double y, E1, E2;
  } contacts[] = {{4., 200., 300.}, {2., 300., 400.}};
  for (const auto &c : contacts)
    {
      const double Estar = 1. / ((1. - nu * nu) / c.E1 + (1. - nu * nu) / c.E2);
      const double p0    = std::sqrt(P * Estar / (3.14159265358979 * 0.5));
      double       peak  = 0.;
      for (const auto &r : rows)
        if (std::abs(r.at("y") - c.y) < 0.2)
          peak = std::max(peak, r.at("pressure"));
      out << "contact at y = " << c.y << ": peak pressure within 2% of Hertz's p0: "
          << verdict(std::abs(peak / p0 - 1.) <= 0.02) << "\n";
      std::cerr << "y " << c.y << " peak " << peak << " p0 " << p0 << "\n";
    }

  // The default: 'all' over the free surfaces (the three arcs, the ids no
  // boundary condition names) gives the same part and the same numbers.
  const int automatic = RunOutput::run_scene(
    "automatic", "disk_stack.prm",
    "subsection Contact\n  subsection Pairs\n    set Two-body pairs = all\n" + no_hertz +
      "  end\nend\n");
  const std::string a    = "automatic/summary.json";
  double            diff = 0.;
  for (const char *q : {"body1_contact_force_y", "body2_contact_force_y", "body3_contact_force_y",
                        "pair2_contact_force_y"})
    diff = std::max(diff, std::abs(summary_quantity(a, q) - summary_quantity(s, q)));
  out << "the default (free surfaces): exits 0: " << verdict(automatic == 0)
      << "; the same forces as the named surfaces (1e-12 of the load): "
      << verdict(diff <= 1e-12 * half) << "\n";
  std::cerr << "default against named: " << diff << "\n";

  const int listed = RunOutput::run_scene("listed", "disk_stack.prm", "");
  const double all_pairs = last_evaluated_pairs("all");
  const double list_pairs = last_evaluated_pairs("listed");
  out << "listed pairs: exits 0: " << verdict(listed == 0)
      << "; evaluated (point, face) pairs with all bodies at most 2.5 times the "
         "listed pairs': "
      << verdict(all_pairs > 0. && list_pairs > 0. && all_pairs <= 2.5 * list_pairs) << "\n";
  std::cerr << "evaluated pairs: all " << all_pairs << " listed " << list_pairs << "\n";
  return 0;
}
