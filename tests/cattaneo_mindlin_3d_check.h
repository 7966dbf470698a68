// The checks of the 3D Cattaneo-Mindlin scenes (issue 50), shared by
// tests/cattaneo_mindlin_3d (compressible, Q1) and
// tests/cattaneo_mindlin_3d_incompressible_long (J = 1 per cell, Q2): a
// half ball (x >= 0, symmetry plane x = 0) pressed onto the rigid plane,
// then loaded along y by Q = 0.25, 0.5, 0.75 mu P (t = 3, 4, 5), Q applied
// as a traction on the top. From load_steps.csv and summary.json:
// - the normal force within 1% of the Hertz reference's P/2 and the
//   friction force's y component equal to the applied -Q/2 within 0.5%;
// - Q/(mu P) along the load (the friction force's y component over mu
//   times the normal force) within 0.02 of 0.25, 0.5, 0.75;
// - c/a (stick_radius: the radius of the disk of the stick zone's area)
//   within max(0.03, 1.5 h/a) of (1 - Q/(mu P))^(1/3), computed here from
//   the measured ratio, and, tighter, within 0.05;
// - the program's stick_radius_reference equal to it (1e-6), c/a falling
//   with Q;
// - the outer loop below 1e-6 within 10 iterations in every step.
// Only verdicts are printed.
#pragma once

#include "run_output.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

/// Run prm/@p scene (whose load is mu P = @p mu_P_applied on the whole
/// sphere) and write the verdicts to "output".
inline void
check_cattaneo_mindlin_3d(const std::string &scene, const double mu_P_applied)
{
  using RunOutput::verdict;
  std::ofstream     out("output");
  const bool        ok = RunOutput::run_scene("run", scene, "") == 0;
  const std::string summary = "run/summary.json";
  out << "exit code 0: " << verdict(ok) << "\n";
  const double a     = RunOutput::summary_quantity(summary, "hertz_a", "reference");
  const double P_ref = RunOutput::summary_quantity(summary, "contact_force_z", "reference");
  double       h     = std::nan("");
  for (const auto &e : RunOutput::summary_numbers(summary))
    if (e.first == "min mesh size")
      {
        h = e.second;
        break;
      }
  // The scene's load: mu P = mu_P_applied on the whole sphere, Q/(mu P)
  // = 0.25 (t - 2) for t >= 2; the half carries Q/2.
  const double        mu = 0.3;
  std::vector<double> ratio, c_over_a, reference;
  bool                settled = true, force_ok = true;
  double              normal  = 0.;
  for (const auto &s : RunOutput::read_csv("run/load_steps.csv"))
    {
      const double t = s.at("time");
      settled = settled && s.at("friction_iterations") <= 10 && s.at("friction_change") <= 1e-6;
      const double half_Q = 0.5 * 0.25 * std::max(t - 2., 0.) * mu_P_applied;
      force_ok = force_ok && std::abs(s.at("friction_force_y") + half_Q) <=
                               0.005 * std::max(half_Q, 0.125 * mu_P_applied);
      for (const double target : {3., 4., 5.})
        if (std::abs(t - target) < 1e-9)
          {
            normal = s.at("contact_force_z");
            ratio.push_back(-s.at("friction_force_y") / (mu * normal));
            c_over_a.push_back(s.at("stick_radius") / a);
            reference.push_back(s.at("stick_radius_reference") / a);
          }
    }
  out << "three tangential steps: " << verdict(ratio.size() == 3) << "\n";
  if (ratio.size() != 3)
    return;
  std::cerr << "a " << a << " h " << h << " P/2 " << normal << " (Hertz " << P_ref << ")\n";
  out << "normal force within 1% of the Hertz reference's P/2: "
      << verdict(std::abs(normal - P_ref) <= 0.01 * P_ref) << "\n"
      << "friction force along y = -Q/2 within 0.5%, every step: " << verdict(force_ok)
      << "\n";
  const double allowed = std::max(0.03, 1.5 * h / a);
  const double targets[3] = {0.25, 0.5, 0.75};
  bool         falling = true;
  for (unsigned int i = 0; i < 3; ++i)
    {
      const double theory = std::cbrt(std::max(0., 1. - ratio[i]));
      std::cerr << "Q/(mu P) " << ratio[i] << " c/a " << c_over_a[i] << " Mindlin " << theory
                << " error " << c_over_a[i] - theory << " allowed " << allowed << "\n";
      out << "Q/(mu P) = " << targets[i]
          << " (within 0.02): " << verdict(std::abs(ratio[i] - targets[i]) <= 0.02)
          << ", c/a within max(0.03, 1.5 h/a) of Mindlin's: "
          << verdict(std::abs(c_over_a[i] - theory) <= allowed)
          << ", within 0.05: " << verdict(std::abs(c_over_a[i] - theory) <= 0.05)
          << ", the program's reference equals it: "
          << verdict(std::abs(reference[i] - theory) <= 1e-6) << "\n";
      if (i > 0)
        falling = falling && c_over_a[i] < c_over_a[i - 1];
    }
  out << "c/a falls with Q: " << verdict(falling) << "\n"
      << "outer loop below 1e-6 within 10 iterations each step: " << verdict(settled) << "\n";
}
