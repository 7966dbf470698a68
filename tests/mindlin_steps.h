// What the Cattaneo-Mindlin tests read from a run (issue 50): the load
// steps at the tangential loads and the spacing of the contact nodes.
#pragma once

#include "run_output.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

namespace MindlinSteps
{
  /// The rows of load_steps.csv at the given load times, with c/a.
  struct Steps
  {
    /// Every step's outer loop ended below 1e-6 within 10 iterations.
    bool settled = true;
    /// At each time asked for: tangential_load_ratio, stick_radius / a
    /// and stick_radius_reference / a, and the whole row.
    std::vector<double>                        ratio, c_over_a, reference_c_over_a;
    std::vector<std::map<std::string, double>> rows;
  };

  /// Read @p load_steps (a load_steps.csv) at @p times, with Hertz's @p a.
  inline Steps
  read(const std::string &load_steps, const double a, const std::vector<double> &times)
  {
    Steps r;
    for (const auto &s : RunOutput::read_csv(load_steps))
      {
        r.settled =
          r.settled && s.at("friction_iterations") <= 10 && s.at("friction_change") <= 1e-6;
        for (const double t : times)
          if (std::abs(s.at("time") - t) < 1e-9)
            {
              r.ratio.push_back(s.at("tangential_load_ratio"));
              r.c_over_a.push_back(s.at("stick_radius") / a);
              r.reference_c_over_a.push_back(s.at("stick_radius_reference") / a);
              r.rows.push_back(s);
            }
      }
    return r;
  }

  /// The largest spacing of the 2D contact nodes with |X| < a below the
  /// height 0.5, from @p profile (a contact_profile.csv): the half disk's
  /// nodes inside the contact zone.
  inline double
  node_spacing(const std::string &profile, const double a)
  {
    std::vector<double> x;
    for (const auto &p : RunOutput::read_csv(profile))
      if (std::abs(p.at("Xx")) < a && p.at("Xy") < 0.5)
        x.push_back(p.at("Xx"));
    std::sort(x.begin(), x.end());
    double h = 0.;
    for (unsigned int i = 1; i < x.size(); ++i)
      h = std::max(h, x[i] - x[i - 1]);
    return h;
  }
} // namespace MindlinSteps
