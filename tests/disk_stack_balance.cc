// Three disks stacked on the rigid plane, prm/disk_stack.prm (issue 51),
// checked from its summary.json by numbers this test computes itself:
// - the force balance of every body to 1e-8 of the load: body 1 carries
//   the traction -P/2 on its flat top, so its contact forces must sum to
//   +P/2; bodies 2 and 3 carry no load, so theirs must sum to 0 (the
//   vertical component: the horizontal one is balanced by the symmetry
//   plane's reaction); the body resultants are the code's
//   bodyB_contact_force_y, and the same sums are formed here from the
//   pairs' resultants on their contact and target bodies (pair 1: body 1
//   on body 2; pair 2: body 2 on body 3; pair 3: body 3 on the plane);
// - each two-body pair's action and reaction cancel (1e-8 of the load);
// - each pair's Hertz reference is the one this test computes from the
//   scene's radii and moduli (a = sqrt(4 P R* / (pi E*)), 1/E* = sum
//   (1 - nu^2)/E, the plane rigid), to 1e-6: the E* of a pair comes from
//   its own two bodies;
// - a and p0 within 2% of that reference.
// Only verdicts are printed; the measured numbers go to stderr.

#include "run_output.h"

#include <cmath>
#include <fstream>
#include <iostream>
#include <string>

namespace
{
  using RunOutput::summary_quantity;
  using RunOutput::verdict;

  const std::string summary = "run/summary.json";

  double
  q(const std::string &name, const std::string &field = "value")
  {
    return summary_quantity(summary, name, field);
  }
} // namespace

int
main()
{
  std::ofstream out("output");
  const int     status = RunOutput::run_scene("run", "disk_stack.prm", "");
  out << "run exits 0: " << verdict(status == 0) << "\n";

  const double P = 0.4, half = P / 2., nu = 0.3;
  const double E[3] = {200., 300., 400.};
  const auto   compliance = [nu](const double e) { return (1. - nu * nu) / e; };

  // Body balance, from the code's body resultants and from the pairs'.
  const double body[3] = {q("body1_contact_force_y"), q("body2_contact_force_y"),
                          q("body3_contact_force_y")};
  const double load[3] = {-half, 0., 0.};
  const double from_pairs[3] = {q("pair1_contact_force_y"),
                                q("pair1_target_force_y") + q("pair2_contact_force_y"),
                                q("pair2_target_force_y") + q("pair3_contact_force_y")};
  for (unsigned int b = 0; b < 3; ++b)
    {
      const double balance       = std::abs(body[b] + load[b]) / half;
      const double pairs_balance = std::abs(from_pairs[b] + load[b]) / half;
      out << "body " << b + 1 << ": contact forces + load = 0 within 1e-8 of the load: "
          << verdict(balance <= 1e-8) << "; from the pairs' resultants: "
          << verdict(pairs_balance <= 1e-8) << "\n";
      std::cerr << "body " << b + 1 << " " << body[b] << " balance " << balance
                << " from pairs " << pairs_balance << "\n";
    }
  for (const std::string pair : {"pair1", "pair2"})
    {
      const double sum =
        std::abs(q(pair + "_contact_force_y") + q(pair + "_target_force_y")) / half;
      const double sum_x =
        std::abs(q(pair + "_contact_force_x") + q(pair + "_target_force_x")) / half;
      out << pair << ": action + reaction = 0 within 1e-8 of the load: "
          << verdict(sum <= 1e-8 && sum_x <= 1e-8) << "\n";
      std::cerr << pair << " action + reaction " << sum << " " << sum_x << "\n";
    }

  // Hertz per pair: R* and E* of the pair.
  const double r_star[3] = {0.5, 0.5, 1.};
  const double e_star[3] = {1. / (compliance(E[0]) + compliance(E[1])),
                            1. / (compliance(E[1]) + compliance(E[2])),
                            1. / compliance(E[2])};
  for (unsigned int k = 0; k < 3; ++k)
    {
      const std::string pair = "pair" + std::to_string(k + 1);
      const double      a    = std::sqrt(4. * P * r_star[k] / (M_PI * e_star[k]));
      const double      p0   = 2. * P / (M_PI * a);
      const double      ref_a = q(pair + "_hertz_a", "reference");
      const double      ref_p = q(pair + "_hertz_p0", "reference");
      const double      err_a = std::abs(q(pair + "_hertz_a") - a) / a;
      const double      err_p = std::abs(q(pair + "_hertz_p0") - p0) / p0;
      out << pair << ": Hertz reference a, p0 as computed here (1e-6): "
          << verdict(std::abs(ref_a - a) <= 1e-6 * a && std::abs(ref_p - p0) <= 1e-6 * p0)
          << "; a within 2%: " << verdict(err_a <= 0.02)
          << "; p0 within 2%: " << verdict(err_p <= 0.02) << "\n";
      std::cerr << pair << " a " << q(pair + "_hertz_a") << " (" << a << ", " << err_a
                << ") p0 " << q(pair + "_hertz_p0") << " (" << p0 << ", " << err_p << ")\n";
    }
}
