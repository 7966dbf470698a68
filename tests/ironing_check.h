// The checks of a whole shallow ironing path (indent by 1 over t <= 1,
// slide 10 over 1 <= t <= 2, frictionless), shared by the 2D and 3D
// ironing tests; computed from the run's reactions.csv, load_steps.csv and
// summary.json in "run":
// - the run converges and reaches t = 2;
// - the force the die's support feels balances the contact force (the die
//   carries no other load) in every step, to 1e-6 of the vertical force;
// - the vertical force at t = 1 lies in [2.5e8, 4.5e8] (Code_Aster's
//   SSNP153 has 3.3e8 with Coulomb friction 0.3);
// - frictionless, the state at t = 2 is the mirror image of the state at
//   t = 1 (about x = 6): Rx(2) = -Rx(1) and R_vertical(2) = R_vertical(1)
//   within `mirror` (2% unless a test asks for less);
// - while sliding (1.2 <= t <= 1.8) the mean of |Rx| / |R_vertical| is at
//   most `mean_ratio` and its step-to-step jump at most `jump` of the
//   vertical force;
// - the penetration the continuation aims at (at the Gauss points, which
//   the penalty acts on) is met, and the die's nodes, which lie between
//   Gauss points, penetrate at most `node_penetration` h;
// - and it prints the number of load steps and step cuts and the
//   reactions at t = 1, 1.5 and 2 to 4 digits, which the .mpirun=2
//   variants expect to be the same as on one rank; with print_iterations
//   also the total of Newton iterations, which must not depend on the
//   rank count either (issue: robust sliding).
#pragma once

#include "run_output.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <ostream>
#include <sstream>
#include <string>

namespace IroningCheck
{
  /// @p vertical: the name of the vertical reaction and contact force
  /// component ("y" in 2D, "z" in 3D).
  inline void
  check(std::ostream     &out,
        const int         status,
        const std::string vertical,
        const double      mean_ratio,
        const double      jump,
        const double      node_penetration,
        const bool        print_iterations = false,
        const double      mirror           = 0.02)
  {
    using RunOutput::read_csv;
    using RunOutput::verdict;
    const std::string R_v = "R" + vertical + "_1", f_v = "contact_force_" + vertical;
    out << "exit code 0: " << verdict(status == 0) << "\n";

    const auto reactions = read_csv("run/reactions.csv");
    const auto steps     = read_csv("run/load_steps.csv");
    const bool complete  = !reactions.empty() && reactions.size() == steps.size() &&
                          std::abs(reactions.back().at("time") - 2.) < 1e-9;
    out << "reached t = 2: " << verdict(complete) << "\n";
    if (!complete)
      return;

    double worst_balance = 0., rx_1 = 0., rv_1 = 0., ratio_sum = 0., worst_jump = 0.,
           worst_penetration = 0.;
    unsigned int sliding = 0;
    for (unsigned int i = 0; i < steps.size(); ++i)
      {
        const auto  &r  = reactions[i];
        const auto  &s  = steps[i];
        const double t  = r.at("time");
        const double rv = std::abs(r.at(R_v));
        if (rv > 1e3)
          worst_balance =
            std::max({worst_balance,
                      std::abs(r.at("Rx_1") + s.at("contact_force_x")) / rv,
                      std::abs(r.at(R_v) + s.at(f_v)) / rv});
        if (std::abs(t - 1.) < 1e-9)
          {
            rx_1 = r.at("Rx_1");
            rv_1 = r.at(R_v);
          }
        if (t >= 1.2 - 1e-9 && t <= 1.8 + 1e-9)
          {
            ratio_sum += std::abs(r.at("Rx_1")) / rv;
            ++sliding;
            worst_jump = std::max(worst_jump,
                                  std::abs(r.at("Rx_1") - reactions[i - 1].at("Rx_1")) / rv);
          }
        worst_penetration = std::max(worst_penetration, s.at("max_penetration_over_h"));
      }
    const double rx_2 = reactions.back().at("Rx_1"), rv_2 = reactions.back().at(R_v);
    const double mirror_x = std::abs(rx_2 + rx_1) / std::abs(rx_1);
    const double mirror_v = std::abs(rv_2 - rv_1) / std::abs(rv_1);
    const double mean     = sliding > 0 ? ratio_sum / sliding : 1.;
    const auto   percent  = [](const double x) {
      std::ostringstream s; // 2%, 1.2%
      s << std::setprecision(3) << 100. * x << "%";
      return s.str();
    };
    out << "support force balances the contact force (1e-6): "
        << verdict(worst_balance < 1e-6) << "\n"
        << "vertical force at t = 1 in [2.5e8, 4.5e8]: "
        << verdict(std::abs(rv_1) > 2.5e8 && std::abs(rv_1) < 4.5e8) << "\n"
        << "mirror: Rx(2) = -Rx(1) within " << percent(mirror) << ": "
        << verdict(mirror_x < mirror) << "\n"
        << "mirror: R" << vertical << "(2) = R" << vertical << "(1) within "
        << percent(mirror) << ": " << verdict(mirror_v < mirror) << "\n"
        << "sliding (t in [1.2, 1.8], " << (sliding >= 20 ? "at least 20" : "FEWER THAN 20")
        << " steps): mean |Rx|/|R" << vertical << "| <= " << percent(mean_ratio) << ": "
        << verdict(mean <= mean_ratio) << "\n"
        << "sliding: step-to-step jump of Rx <= " << percent(jump) << " of |R" << vertical
        << "|: " << verdict(worst_jump <= jump) << "\n"
        << "penetration tolerance (at the Gauss points) met: "
        << verdict(RunOutput::summary_flag("run/summary.json", "penetration tolerance met"))
        << "\n"
        << "penetration / h at the die's nodes (between Gauss points) <= "
        << node_penetration << ": " << verdict(worst_penetration <= node_penetration)
        << "\n";
    // The path itself, to 4 digits: the same on 1 and 2 ranks (the
    // .mpirun=2 variants expect the same lines).
    unsigned int cuts = 0;
    for (const auto &s : steps)
      cuts += static_cast<unsigned int>(s.at("cuts_before"));
    out << "load steps: " << steps.size() << ", step cuts: " << cuts << "\n";
    if (print_iterations)
      out << "Newton iterations: " << RunOutput::newton_iterations("run") << "\n";
    const auto fixed4 = [](double x) {
      if (std::abs(x) < 5e-5) // no "-0.0000"
        x = 0.;
      std::ostringstream s;
      s << std::fixed << std::setprecision(4) << x;
      return s.str();
    };
    for (const auto &r : reactions)
      for (const double t : {1., 1.5, 2.})
        if (std::abs(r.at("time") - t) < 1e-9)
          out << "t = " << t << ": Rx/|R" << vertical
              << "| = " << fixed4(r.at("Rx_1") / std::abs(r.at(R_v))) << ", R" << vertical
              << " = " << std::setprecision(4) << r.at(R_v) << "\n";
    std::cerr << "balance " << worst_balance << " Rx(1) " << rx_1 << " R" << vertical
              << "(1) " << rv_1 << " Rx(2) " << rx_2 << " R" << vertical << "(2) " << rv_2
              << " mean ratio " << mean << " jump " << worst_jump << " penetration "
              << worst_penetration << "\n";
  }

  /// Run @p scene with the die's (body 1) and the block's (body 2) coarse
  /// cells set to @p die and @p block (`Subdivisions` entries) and the
  /// parameter text @p extra appended into "run", and write check()'s
  /// verdicts into "output".
  inline void
  run_and_check(const std::string &scene,
                const std::string &die,
                const std::string &block,
                const std::string &vertical,
                const double       mean_ratio,
                const double       jump,
                const double       node_penetration,
                const bool         print_iterations = false,
                const std::string &extra            = "",
                const double       mirror           = 0.02)
  {
    std::ofstream out("output");
    const auto    subdivisions = [](const unsigned int body, const std::string &cells) {
      return "subsection Body " + std::to_string(body) +
             "\n  subsection Geometry\n    set Subdivisions = " + cells + "\n  end\nend\n";
    };
    const int status =
      RunOutput::run_scene("run", scene, subdivisions(1, die) + subdivisions(2, block) + extra);
    check(out, status, vertical, mean_ratio, jump, node_penetration, print_iterations, mirror);
  }
} // namespace IroningCheck
