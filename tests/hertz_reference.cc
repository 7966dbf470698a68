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
// Point contact (a sphere, 3D): a and p0 from the formulas against the
// values of benchmarks.md 6 (P = 0.29304, R = 1, E* = 219.78: a = 0.1000,
// p0 = 13.992), and the same three profiles sampled as on a surface mesh:
// 9 points per ring at angles 0..90 degrees, the ring radii graded and
// each point's radius perturbed by up to 1% of the ring spacing (the nodes
// of one ring are not at one r); the L2 error of the wider profile is
// compared with the integral with the area weight r on 10^5 intervals.
// Two curved bodies: 'Second radius' combined into R* by parse_parameters,
// the two-sphere and two-cylinder scenes' a and p0, a concave second
// surface, and one narrower than the body refused.

#include <signorini/contact/hertz.h>
#include <signorini/input_error.h>

#include <deal.II/base/parameter_handler.h>

#include <deal.II/base/point.h>

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

  // Point contact.
  HertzReference sphere;
  sphere.point_load      = 0.29304;
  sphere.radius          = 1.;
  sphere.contact_modulus = 200. / (1. - 0.09);
  sphere.p0_from_fit     = true;
  const double as = sphere.half_width(), ps = sphere.peak_pressure();
  out << "sphere: a = 0.1000 and p0 = 13.992 to 5e-5: "
      << verdict(std::abs(as / 0.1 - 1.) < 5e-5 && std::abs(ps / 13.992 - 1.) < 5e-5) << "\n";
  dealii::Point<3> node(0.03, 0.04, 0.);
  out << "sphere: s is the distance from the vertical centre line: "
      << verdict(std::abs(sphere.distance(node) - 0.05) < 1e-15) << "\n";

  auto surface = [&](const double scale, const double width) {
    std::vector<std::pair<double, double>> s;
    const unsigned int rings = 120;
    for (unsigned int i = 0; i <= rings; ++i)
      for (unsigned int k = 0; k < 9; ++k)
        {
          const double spacing = 2. * as / rings;
          const double r = 2. * as * std::pow(double(i) / rings, 1.5) +
                           (i > 0 ? 0.01 * spacing * std::sin(7. * k + i) : 0.);
          const double q = r / (width * as);
          s.emplace_back(r, q < 1. ? scale * ps * std::sqrt(1. - q * q) : 0.);
        }
    return s;
  };
  const auto exact_3d = quantities(sphere, surface(1., 1.));
  out << "sphere, exact profile: a and p0 from the fit to 1e-12: "
      << verdict(std::abs(exact_3d.at("hertz_a") / as - 1.) < 1e-12 &&
                 std::abs(exact_3d.at("hertz_p0") / ps - 1.) < 1e-12)
      << "\n"
      << "sphere, exact profile: L2 error 0: "
      << verdict(std::abs(exact_3d.at("hertz_pressure_l2_error")) < 1e-14) << "\n";
  const auto scaled_3d = quantities(sphere, surface(1.1, 1.));
  out << "sphere, 1.1 x the profile: L2 error 0.1 to 1e-12: "
      << verdict(std::abs(scaled_3d.at("hertz_pressure_l2_error") - 0.1) < 1e-12) << "\n";
  double e2r = 0., n2r = 0.;
  for (unsigned int i = 0; i < 100000; ++i)
    {
      const double r = 2. * as * (i + 0.5) / 100000, dr = 2. * as / 100000;
      const double q = r / (1.05 * as);
      const double wide_p = q < 1. ? ps * std::sqrt(1. - q * q) : 0.;
      const double e = wide_p - sphere.pressure(r);
      e2r += e * e * r * dr;
      n2r += sphere.pressure(r) * sphere.pressure(r) * r * dr;
    }
  const double reference_3d = std::sqrt(e2r / n2r);
  const double computed_3d =
    quantities(sphere, surface(1., 1.05)).at("hertz_pressure_l2_error");
  out << "sphere, 5% wider profile: L2 error within 3% of the integral with weight r: "
      << verdict(std::abs(computed_3d / reference_3d - 1.) < 3e-2) << "\n";
  std::cerr << "sphere, wider profile: " << computed_3d << " against " << reference_3d << "\n";

  // Two curved bodies (issue 51): 'Radius' R1 and 'Second radius' R2 give
  // R* = R1 R2 / (R1 + R2); prm/hertz_two_spheres.prm's numbers (R1 = 1,
  // R2 = 2, E* = 146.52, P = 0.03663) give a = 0.0500 and p0 = 6.9958, and
  // prm/hertz_two_cylinders.prm's (P = 0.43155 per unit thickness)
  // a = 0.0500, p0 = 5.4946. A concave R2 narrower than the body is
  // refused, R2 = 0 leaves 'Radius' as it is.
  const auto parse = [](const std::string &entries) {
    dealii::ParameterHandler prm;
    HertzReference::declare_parameters(prm);
    prm.parse_input_from_string(entries);
    HertzReference h;
    h.parse_parameters(prm);
    return h;
  };
  const double e_star = 1. / (0.91 / 200. + 0.91 / 400.);
  HertzReference spheres =
    parse("set Point load = 0.03663\nset Radius = 1\nset Second radius = 2\n");
  spheres.contact_modulus = e_star;
  out << "two spheres: R* = 2/3 to 1e-15, a = 0.0500 and p0 = 6.9958 to 5e-5: "
      << verdict(std::abs(spheres.radius - 2. / 3.) < 1e-15 &&
                 std::abs(spheres.half_width() / 0.05 - 1.) < 5e-5 &&
                 std::abs(spheres.peak_pressure() / 6.9958 - 1.) < 5e-5)
      << "\n";
  HertzReference cylinders =
    parse("set Line load = 0.43155\nset Radius = 1\nset Second radius = 2\n");
  cylinders.contact_modulus = e_star;
  out << "two cylinders: a = 0.0500 and p0 = 5.4946 to 5e-5: "
      << verdict(std::abs(cylinders.half_width() / 0.05 - 1.) < 5e-5 &&
                 std::abs(cylinders.peak_pressure() / 5.4946 - 1.) < 5e-5)
      << "\n";
  out << "a concave second surface: R2 = -3 gives R* = 1.5, R2 = 0 leaves R = 1: "
      << verdict(std::abs(parse("set Line load = 1\nset Second radius = -3\n").radius - 1.5) <
                   1e-15 &&
                 parse("set Line load = 1\nset Second radius = 0\n").radius == 1.)
      << "\n";
  bool refused = false;
  try
    {
      parse("set Line load = 1\nset Second radius = -0.5\n");
    }
  catch (const Signorini::InputError &e)
    {
      refused = std::string(e.what()).find("Second radius") != std::string::npos;
    }
  out << "a concave second surface narrower than the body (R2 = -0.5, R1 = 1) "
         "refused naming the entry: "
      << verdict(refused) << "\n";
}
