// Mindlin-Deresiewicz hysteresis in 2D, prm/mindlin_hysteresis_2d.prm
// (issue 50): the incompressible cylinder of cattaneo_mindlin_2d pressed
// by P, then loaded tangentially by Q = 0.2, 0.4, 0.6 mu P (t = 3, 4, 5),
// unloaded to -0.6 mu P (t = 6..11) and reloaded to +0.6 mu P (t =
// 12..17), on the scene's mesh and on a finer one (Local refinements 6 in a
// ball of radius 0.12). From load_steps.csv and summary.json, each run:
// - the friction force equals the applied -Q(t) within 0.5% of Q*;
// - c/a (the stick zone of each step's slip increment) within max(0.03,
//   1.5 h/a) of the theory at every tangential step, the theory computed
//   here from the measured load ratios rho = Q/(mu P): sqrt(1 - |rho|)
//   on loading, sqrt(1 - |rho - rho_r|/2) after the reversal at rho_r
//   (measured: at most 0.074 on the scene's mesh, allowed 0.20; 0.034 on
//   the finer, allowed 0.10); the program's stick_radius_reference equals
//   it (to 1e-6: Contact::Mindlin::LoadPath);
// - on the finer mesh the two steps at Q = 0 after a reversal (t = 8, 14)
//   are further than the allowance from the monotonic reference c = a
//   (the hysteresis is seen, not only allowed);
// - the dissipated energy of the unloading (t = 6..11) and the reloading
//   (t = 12..17) half cycles positive, equal within 3%, and each within 5%
//   of mu^2 P^2/(pi E*) (1 - k^4 + 4 k^2 ln k), k^2 = 1 - Q*/(mu P)
//   (doc/friction.md §6), with E* = 4 P R/(pi a^2) from the Hertz
//   reference; the first loading (t = 3..5) within 5% of half of it;
// - the outer loop below 1e-6 within 10 iterations in every step.
// Only verdicts are printed.

#include "run_output.h"

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
  using RunOutput::verdict;

  // The scene's load: Q(t)/(mu P) in steps of 0.2 per unit of t, and the
  // mu P its traction uses (Function constants).
  const double mu_P_applied = 0.51786;

  double
  applied_ratio(const double t)
  {
    const double g = t < 5. ? std::max(t - 2., 0.) : (t < 11. ? 8. - t : t - 14.);
    return 0.2 * g;
  }

  // Mindlin-Deresiewicz's c/a at step k of the path of load ratios rho
  // (signed), with the reversals at t = 5 and 11 of this scene.
  double
  theory(const std::vector<double> &time, const std::vector<double> &rho, const unsigned int k)
  {
    const auto at = [&](const double t) {
      for (unsigned int i = 0; i < time.size(); ++i)
        if (std::abs(time[i] - t) < 1e-9)
          return rho[i];
      return std::nan("");
    };
    const double t = time[k];
    double       left;
    if (t <= 5. + 1e-9)
      left = 1. - std::abs(rho[k]);
    else if (t <= 11. + 1e-9)
      left = 1. - std::abs(rho[k] - at(5.)) / 2.;
    else
      left = 1. - std::abs(rho[k] - at(11.)) / 2.;
    return std::sqrt(std::max(0., left));
  }

  void
  check(std::ostream &out, const std::string &name, const std::string &edits,
        const std::string &what, const bool expect_distinct)
  {
    const bool ok = RunOutput::run_scene(name, "mindlin_hysteresis_2d.prm", edits) == 0;
    out << what << ": exit code 0: " << verdict(ok) << "\n";
    const std::string summary = name + "/summary.json";
    const double      a       = RunOutput::summary_quantity(summary, "hertz_a", "reference");
    const double      P_ref =
      RunOutput::summary_quantity(summary, "contact_force_y", "reference");
    double h = std::nan("");
    for (const auto &e : RunOutput::summary_numbers(summary))
      if (e.first == "min mesh size")
        h = e.second;
    // The steps at t = 1, ..., 17 (a cut step adds steps between them).
    const auto all_steps = read_csv(name + "/load_steps.csv");
    std::vector<std::map<std::string, double>> steps;
    const double mu = 0.3, R = 1.;
    bool         force_ok = true, settled = true;
    // Dissipation: t in (2, 5] (first loading), (5, 11] (unloading),
    // (11, 17] (reloading).
    double W_load = 0., W_unload = 0., W_reload = 0.;
    for (const auto &s : all_steps)
      {
        const double t = s.at("time");
        if (std::abs(t - std::round(t)) < 1e-9)
          steps.push_back(s);
        const double Q = applied_ratio(t) * mu_P_applied;
        force_ok = force_ok && std::abs(s.at("friction_force_x") + Q) <= 0.005 * 0.6 * mu_P_applied;
        settled  = settled && s.at("friction_iterations") <= 10 && s.at("friction_change") <= 1e-6;
        if (t > 2. + 1e-9)
          (t < 5. + 1e-9 ? W_load : t < 11. + 1e-9 ? W_unload : W_reload) +=
            s.at("dissipated_energy");
      }
    out << what << ": the steps at t = 1, 2, ..., 17: " << verdict(steps.size() == 17)
        << "\n";
    if (steps.size() != 17)
      return;
    std::vector<double> time, rho, c_over_a, reference;
    double              P_sum = 0.;
    for (const auto &s : steps)
      {
        const double t = s.at("time"), P = s.at("contact_force_y");
        time.push_back(t);
        rho.push_back(-s.at("friction_force_x") / (mu * P));
        c_over_a.push_back(s.at("stick_radius") / a);
        reference.push_back(s.at("stick_radius_reference") / a);
        if (t > 2.5)
          P_sum += P;
      }
    const double P = P_sum / 15.;
    std::cerr << what << ": a " << a << " h " << h << " P " << P << "\n";
    out << what << ": friction force = -Q(t) within 0.5% of Q*, every step: "
        << verdict(force_ok) << "\n";
    const double allowed = std::max(0.03, 1.5 * h / a);
    double       worst = 0., worst_reference = 0.;
    for (unsigned int k = 2; k < 17; ++k)
      {
        const double c = theory(time, rho, k);
        std::cerr << "  t " << time[k] << " Q/(mu P) " << rho[k] << " c/a " << c_over_a[k]
                  << " theory " << c << " program's " << reference[k] << "\n";
        worst           = std::max(worst, std::abs(c_over_a[k] - c));
        worst_reference = std::max(worst_reference, std::abs(reference[k] - c));
      }
    std::cerr << what << ": largest c/a error " << worst << ", allowed " << allowed << "\n";
    out << what << ": Q*/(mu P) = 0.6 within 0.02 at both reversals: "
        << verdict(std::abs(rho[4] - 0.6) <= 0.02 && std::abs(rho[10] + 0.6) <= 0.02) << "\n"
        << what << ": c/a within max(0.03, 1.5 h/a) of Mindlin-Deresiewicz's at all 15 "
        << "tangential steps: " << verdict(worst <= allowed) << "\n"
        << what << ": the program's reference equals the theory (1e-6): "
        << verdict(worst_reference <= 1e-6) << "\n";
    if (expect_distinct)
      out << what << ": at Q = 0 after each reversal, c/a further than the allowance from "
          << "the monotonic reference 1: "
          << verdict(1. - c_over_a[7] > allowed && 1. - c_over_a[13] > allowed) << "\n";

    const double E_star  = 4. * P_ref * R / (M_PI * a * a);
    const double rho_max = (std::abs(rho[4]) + std::abs(rho[10]) + std::abs(rho[16])) / 3.;
    const double k2      = 1. - rho_max;
    const double W_half =
      mu * mu * P * P / (M_PI * E_star) * (1. - k2 * k2 + 2. * k2 * std::log(k2));
    std::cerr << what << ": W load " << W_load << " unload " << W_unload << " reload "
              << W_reload << " closed form (half cycle) " << W_half << " E* " << E_star
              << "\n";
    const double mean = 0.5 * (W_unload + W_reload);
    out << what << ": dissipated energy of both half cycles positive: "
        << verdict(W_unload > 0. && W_reload > 0.) << ", equal within 3%: "
        << verdict(std::abs(W_unload - W_reload) <= 0.03 * mean) << ", each within 5% of "
        << "the closed form: "
        << verdict(std::abs(W_unload - W_half) <= 0.05 * W_half &&
                   std::abs(W_reload - W_half) <= 0.05 * W_half)
        << "\n"
        << what << ": first loading within 5% of half the closed form: "
        << verdict(std::abs(W_load - 0.5 * W_half) <= 0.025 * W_half) << "\n"
        << what << ": outer loop below 1e-6 within 10 iterations each step: "
        << verdict(settled) << "\n";
  }
} // namespace

int
main()
{
  std::ofstream out("output");
  check(out, "run_scene", "", "scene's mesh", false);
  check(out, "run_fine",
        "subsection Mesh\n  set Local refinements = 6\n"
        "  set Local refinement radius = 0.12\nend\n",
        "finer mesh", true);
}
