// Contact::Mindlin::LoadPath (issue 50): the Mindlin-Deresiewicz stick
// zone and tangential traction of a tangential load that turns back, with
// Masing's memory. Checked against the formulas written out here:
// - monotonic loading gives stick_ratio() and traction() of |rho|, for a
//   cylinder and a sphere;
// - unloading from rho* = 0.6 to rho: c'/a = sqrt(1 - (rho* - rho)/2)
//   (sphere: the cube root), at -rho* the loading's c*/a again;
// - the traction on the unloading branch is the one at rho* minus twice
//   the virgin traction of (rho* - rho)/2 (the superposition), at -rho*
//   minus the traction at rho*, and at +rho* after a full cycle the
//   traction at rho* again (to 1e-14 of mu p0);
// - an inner loop (0.6 -> 0.2 -> 0.6) is closed when the load passes 0.6,
//   after which the virgin branch continues (0.7: sqrt(0.3));
// - a branch from the first reversal that passes -rho* joins the virgin
//   branch; changes of 1e-12 (round-off) are not reversals.
// Only verdicts are printed.

#include <signorini/contact/mindlin.h>

#include <cmath>
#include <fstream>
#include <iostream>
#include <vector>

using namespace Signorini::Contact;

namespace
{
  const char *
  verdict(const bool ok)
  {
    return ok ? "yes" : "NO";
  }

  Mindlin::LoadPath
  path(const std::vector<double> &ratios)
  {
    Mindlin::LoadPath p;
    for (const double r : ratios)
      p.add(r);
    return p;
  }

  // The largest difference of two tractions over 0 <= r <= 1.2 a.
  template <class F, class G>
  double
  traction_difference(const F &f, const G &g)
  {
    double worst = 0.;
    for (int i = 0; i <= 240; ++i)
      worst = std::max(worst, std::abs(f(0.005 * i) - g(0.005 * i)));
    return worst;
  }
} // namespace

int
main()
{
  std::ofstream out("output");
  const double  a = 1., mu_p0 = 1.;
  for (const bool sphere : {false, true})
    {
      const std::string what = sphere ? "sphere" : "cylinder";
      const auto root = [sphere](const double x) { return sphere ? std::cbrt(x) : std::sqrt(x); };
      double     worst = 0.;
      for (const double rho : {0.25, 0.5, 0.75})
        {
          const auto p = path({0., rho});
          worst = std::max(worst, std::abs(p.stick_ratio(sphere) - root(1. - rho)));
          worst = std::max(worst, traction_difference(
                                    [&](double r) { return p.traction(r, a, mu_p0, sphere); },
                                    [&](double r) {
                                      return Mindlin::traction(r, a, a * root(1. - rho), mu_p0);
                                    }));
        }
      out << what << ": monotonic loading as stick_ratio() and traction(): "
          << verdict(worst < 1e-14) << "\n";

      worst = 0.;
      for (const double rho : {0.4, 0.2, 0., -0.2, -0.4, -0.6})
        {
          const auto p = path({0.2, 0.4, 0.6, rho});
          worst = std::max(worst, std::abs(p.stick_ratio(sphere) - root(1. - (0.6 - rho) / 2.)));
          const double c_star = a * root(1. - 0.6), c_prime = a * root(1. - (0.6 - rho) / 2.);
          worst = std::max(worst, traction_difference(
                                    [&](double r) { return p.traction(r, a, mu_p0, sphere); },
                                    [&](double r) {
                                      return Mindlin::traction(r, a, c_star, mu_p0) -
                                             2. * Mindlin::traction(r, a, c_prime, mu_p0);
                                    }));
        }
      out << what << ": unloading from 0.6: c'/a and the superposed traction: "
          << verdict(worst < 1e-14) << "\n";

      const auto at_star  = path({0.6});
      const auto at_minus = path({0.6, 0., -0.6});
      const auto cycled   = path({0.6, -0.6, 0.6});
      const double d1 = traction_difference(
        [&](double r) { return at_minus.traction(r, a, mu_p0, sphere); },
        [&](double r) { return -at_star.traction(r, a, mu_p0, sphere); });
      const double d2 = traction_difference(
        [&](double r) { return cycled.traction(r, a, mu_p0, sphere); },
        [&](double r) { return at_star.traction(r, a, mu_p0, sphere); });
      out << what << ": at -Q* the stick zone of +Q*: "
          << verdict(std::abs(at_minus.stick_ratio(sphere) - root(0.4)) < 1e-14)
          << ", the traction of +Q* reversed: " << verdict(d1 < 1e-14)
          << "; after a full cycle the traction of +Q*: " << verdict(d2 < 1e-14) << "\n";

      const auto inner = path({0.6, 0.2, 0.4});
      const auto outer = path({0.6, 0.2, 0.4, 0.7});
      out << what << ": inner loop 0.6 -> 0.2 -> 0.4: c/a of the branch from 0.2: "
          << verdict(std::abs(inner.stick_ratio(sphere) - root(1. - 0.1)) < 1e-14)
          << ", passing 0.6 closes it (0.7 on the virgin branch): "
          << verdict(std::abs(outer.stick_ratio(sphere) - root(0.3)) < 1e-14 &&
                     outer.reversals().empty())
          << "\n";

      const auto beyond = path({0.3, -0.5});
      const auto noisy  = path({1e-12, -1e-12, 0.3, 0.3 + 1e-12, -0.5});
      out << what << ": from 0.3 to -0.5 on the virgin branch again: "
          << verdict(std::abs(beyond.stick_ratio(sphere) - root(0.5)) < 1e-14 &&
                     beyond.reversals().empty())
          << ", round-off changes are not reversals: "
          << verdict(noisy.reversals() == beyond.reversals() &&
                     noisy.stick_ratio(sphere) == beyond.stick_ratio(sphere))
          << "\n";
    }
}
