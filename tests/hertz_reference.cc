// The Hertz quantities computed from sampled contact pressures
// (Contact::HertzReference::quantities), on synthetic profiles whose
// answers are known:
// - the exact Hertz profile, sampled at 201 points over [0, 2a] (half
//   model): a and p0 from the least-squares fit to 1e-12, and an L2
//   profile error of 0;
// - the same profile times 1.1: the L2 error is 0.1 to 1e-12 (the
//   trapezoidal rule integrates both sides with the same weights);
// - a profile with a 5% larger contact half-width, p0 kept: the L2 error
//   on 201 samples graded towards the axis (x_i = 2a (i/200)^2, as on a
//   mesh refined around the contact point) within 2% of the same integral
//   on 10^5 uniform intervals. The square-root edges limit the
//   trapezoidal rule on 201 samples to about 1.5%; an unweighted mean over
//   the graded samples would be 36% low.

#include <signorini/contact/hertz.h>

#include <cmath>
#include <fstream>
#include <iostream>
#include <map>
#include <string>
#include <vector>

using Signorini::Contact::HertzReference;

namespace
{
  std::map<std::string, double>
  quantities(const HertzReference &h, const std::vector<std::pair<double, double>> &s)
  {
    std::map<std::string, double> q;
    for (const auto &x : h.quantities(s))
      q[x.name] = x.value;
    return q;
  }

  const char *
  verdict(const bool ok)
  {
    return ok ? "yes" : "NO";
  }
} // namespace

int
main()
{
  std::ofstream  out("output");
  HertzReference h;
  h.line_load         = 35.;
  h.radius            = 50.;
  h.contact_modulus   = 76.9;
  h.modelled_fraction = 0.5;
  h.p0_from_fit       = true;
  const double a = h.half_width(), p0 = h.peak_pressure();

  auto sample = [&](const double scale, const double width, const unsigned int n,
                    const double grading = 1.) {
    std::vector<std::pair<double, double>> s;
    for (unsigned int i = 0; i <= n; ++i)
      {
        const double x = 2. * a * std::pow(double(i) / n, grading),
                     r = x / (width * a);
        s.emplace_back(x, r < 1. ? scale * p0 * std::sqrt(1. - r * r) : 0.);
      }
    return s;
  };

  const auto exact = quantities(h, sample(1., 1., 200));
  out << "exact profile: a from the fit to 1e-12: "
      << verdict(std::abs(exact.at("hertz_a") / a - 1.) < 1e-12) << "\n"
      << "exact profile: p0 from the fit to 1e-12: "
      << verdict(std::abs(exact.at("hertz_p0") / p0 - 1.) < 1e-12) << "\n"
      << "exact profile: L2 error 0: "
      << verdict(std::abs(exact.at("hertz_pressure_l2_error")) < 1e-14) << "\n";

  const auto scaled = quantities(h, sample(1.1, 1., 200));
  out << "1.1 x the profile: L2 error 0.1 to 1e-12: "
      << verdict(std::abs(scaled.at("hertz_pressure_l2_error") - 0.1) < 1e-12) << "\n";

  // The reference value of the wider profile's error: the same trapezoid
  // formula on 10^5 intervals.
  const auto wide   = sample(1., 1.05, 200, 2.);
  const auto fine   = sample(1., 1.05, 100000);
  double     e2 = 0., n2 = 0.;
  for (std::size_t i = 0; i + 1 < fine.size(); ++i)
    {
      const double dx = fine[i + 1].first - fine[i].first;
      const double e0 = fine[i].second - h.pressure(fine[i].first);
      const double e1 = fine[i + 1].second - h.pressure(fine[i + 1].first);
      const double q0 = h.pressure(fine[i].first), q1 = h.pressure(fine[i + 1].first);
      e2 += 0.5 * dx * (e0 * e0 + e1 * e1);
      n2 += 0.5 * dx * (q0 * q0 + q1 * q1);
    }
  const double reference = std::sqrt(e2 / n2);
  const double computed  = quantities(h, wide).at("hertz_pressure_l2_error");
  out << "5% wider profile: L2 error within 2% of the fine integral: "
      << verdict(std::abs(computed / reference - 1.) < 2e-2) << "\n";
  std::cerr << "wider profile: " << computed << " against " << reference << "\n";
}
