// Shallow ironing (prm/ironing.prm), shortened to 0 <= t <= 1.2: the die
// indents the block by 1 and slides 2 (eight block faces). Checks computed
// from the run's CSV files:
// - the run converges and reaches t = 1.2;
// - the force the die's support feels balances the contact force (the die
//   carries no other load) in every step, to 1e-6 of the vertical force;
// - the vertical force at t = 1 lies in [2.5e8, 4.5e8] (Code_Aster's
//   SSNP153 has 3.3e8 with Coulomb friction 0.3; this run, frictionless,
//   3.31e8 in the full run);
// - while sliding, the horizontal force stays below 10% of the vertical
//   and its largest step-to-step jump below 10% of the vertical
//   (full run: 2.9% on average, largest jump 5.2%);
// - the penetration the continuation aims at (1e-2 of h) is met.

#include "run_output.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>

using RunOutput::read_csv;
using RunOutput::verdict;

int
main()
{
  std::ofstream out("output");
  const int status = RunOutput::run_scene(
    "run", "ironing.prm",
    "subsection Load stepping\n  set End time = 1.2\n  set Number of steps = 48\nend\n");
  out << "exit code 0: " << verdict(status == 0) << "\n";

  const auto reactions = read_csv("run/reactions.csv");
  const auto steps     = read_csv("run/load_steps.csv");
  const bool complete  = !reactions.empty() && reactions.size() == steps.size() &&
                        std::abs(reactions.back().at("time") - 1.2) < 1e-9;
  out << "reached t = 1.2: " << verdict(complete) << "\n";
  if (!complete)
    return 0;

  double worst_balance = 0., ry_at_1 = 0., worst_ratio = 0., worst_jump = 0.,
         worst_penetration = 0.;
  for (unsigned int i = 0; i < steps.size(); ++i)
    {
      const auto  &r  = reactions[i];
      const auto  &s  = steps[i];
      const double ry = std::abs(r.at("Ry_1"));
      if (ry > 1e3)
        worst_balance =
          std::max({worst_balance,
                    std::abs(r.at("Rx_1") + s.at("contact_force_x")) / ry,
                    std::abs(r.at("Ry_1") + s.at("contact_force_y")) / ry});
      if (r.at("time") <= 1. + 1e-9)
        ry_at_1 = ry;
      else
        {
          worst_ratio = std::max(worst_ratio, std::abs(r.at("Rx_1")) / ry);
          worst_jump  = std::max(worst_jump,
                                std::abs(r.at("Rx_1") - reactions[i - 1].at("Rx_1")) / ry);
        }
      worst_penetration = std::max(worst_penetration, s.at("max_penetration_over_h"));
    }
  out << "support force balances the contact force (1e-6): "
      << verdict(worst_balance < 1e-6) << "\n"
      << "vertical force at t = 1 in [2.5e8, 4.5e8]: "
      << verdict(ry_at_1 > 2.5e8 && ry_at_1 < 4.5e8) << "\n"
      << "sliding: |horizontal| < 0.1 vertical: " << verdict(worst_ratio < 0.1) << "\n"
      << "sliding: step-to-step jump of the horizontal < 0.1 vertical: "
      << verdict(worst_jump < 0.1) << "\n"
      << "penetration / h <= 1e-2 in every step: "
      << verdict(worst_penetration <= 1e-2 * (1. + 1e-9)) << "\n";
  std::cerr << "balance " << worst_balance << " Ry(1) " << ry_at_1 << " ratio "
            << worst_ratio << " jump " << worst_jump << " penetration "
            << worst_penetration << "\n";
}
