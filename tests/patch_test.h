// The contact patch test (prm/patch_test_2d.prm, prm/patch_test_3d.prm;
// benchmarks.md 7), shared by tests/patch_test_2d.cc and patch_test_3d.cc:
// run one contact form and print, from the run's CSV files,
// - the largest deviation of the nodal pressure on Gamma_C from the
//   applied pressure p = 0.01, rounded to 0.1%, and whether it is within
//   the goal (1% in 2D, 2% in 3D; the nodal form is not: see
//   doc/two_bodies.md, "Contact patch test");
// - the resultant contact force against the applied load p (to 1e-6; the
//   lateral components below 1e-3 p: the penalty slip leaves about 2e-4),
//   the contact area against the interface's (1, every node active, to
//   1e-9) and the moment about the origin against p's (the interface's
//   centroid at x = y = 0.5 in the current configuration, to 2%);
// - body 2's largest nodal pressure deviation, to 1% (reported only).
#pragma once

#include "run_output.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ostream>
#include <string>

inline void
patch_test(std::ostream      &out,
           const std::string &name,
           const std::string &scene,
           const std::string &edits,
           const unsigned int dim,
           const double       goal,
           const std::string &launcher = "")
{
  const double p      = 0.01;
  const int    status = RunOutput::run_scene(name, scene, edits, launcher);
  out << name << ": exit code 0: " << RunOutput::verdict(status == 0) << "\n";
  const auto profile = RunOutput::read_csv(name + "/contact_profile.csv");
  const auto steps   = RunOutput::read_csv(name + "/load_steps.csv");
  if (profile.empty() || steps.empty())
    return;
  double deviation = 0.;
  for (const auto &row : profile)
    deviation = std::max(deviation, std::abs(row.at("pressure") - p) / p);
  char percent[32];
  std::snprintf(percent, sizeof(percent), "%.1f%%", 100. * deviation);
  out << name << ": nodal pressure nodes " << profile.size()
      << ", largest deviation from p " << percent << ", within "
      << 100. * goal << "%: " << RunOutput::verdict(deviation <= goal) << "\n";
  // Body 2's side (the reaction of the penalty term on its target nodes):
  // reported, no goal.
  double target = 0.;
  for (const auto &row : RunOutput::read_csv(name + "/contact_profile_target.csv"))
    target = std::max(target, std::abs(row.at("pressure") - p) / p);
  std::snprintf(percent, sizeof(percent), "%.0f%%", 100. * target);
  out << name << ": body 2's nodal pressure, largest deviation from p " << percent
      << "\n";
  const auto &last  = steps.back();
  const char *axis  = dim == 2 ? "contact_force_y" : "contact_force_z";
  const bool  force = std::abs(last.at(axis) - p) < 1e-6 * p;
  bool        lateral = true;
  for (unsigned int d = 0; d + 1 < dim; ++d)
    lateral = lateral &&
              std::abs(last.at(std::string("contact_force_") + "xyz"[d])) < 1e-3 * p;
  out << name << ": resultant = applied load (1e-6, lateral 1e-3): "
      << RunOutput::verdict(force && lateral) << "\n";
  out << name << ": contact area = 1 (1e-9): "
      << RunOutput::verdict(std::abs(last.at("contact_area") - 1.) < 1e-9) << "\n";
  // The force on body 1, (0, p) (2D) or (0, 0, p) (3D), through the centroid of the
  // interface, about x = y = 0.5 (the lateral expansion moves it by
  // less than 1%).
  bool moment = std::abs(last.at("contact_moment_z") - (dim == 2 ? 0.5 * p : 0.)) <
                0.02 * 0.5 * p;
  if (dim == 3)
    moment = moment &&
             std::abs(last.at("contact_moment_x") - 0.5 * p) < 0.02 * 0.5 * p &&
             std::abs(last.at("contact_moment_y") + 0.5 * p) < 0.02 * 0.5 * p;
  out << name << ": moment about the origin = p's (2%): "
      << RunOutput::verdict(moment) << "\n";
}

/// The variants both tests run: the scene's (integral form, K = 4,
/// partition indicator), K = 2, and the poster's nodal and integral (K = 2)
/// forms with the simplex indicator.
inline void
patch_test_variants(std::ostream      &out,
                    const std::string &scene,
                    const unsigned int dim,
                    const double       goal)
{
  const std::string form   = "subsection Contact\n  subsection Two bodies\n";
  const std::string poster = "    set Indicator shape = simplex\n";
  const std::string k2     = "    set Gauss points per face = 2\n  end\nend\n";
  patch_test(out, "partition_integral_K4", scene, "", dim, goal);
  patch_test(out, "partition_integral_K2", scene, form + k2, dim, goal);
  patch_test(out, "poster_nodal", scene,
             form + poster + "    set Contact form = nodal\n  end\nend\n", dim, goal);
  patch_test(out, "poster_integral_K2", scene, form + poster + k2, dim, goal);
}
