#include <signorini/contact/mindlin.h>

#include <algorithm>
#include <cmath>

namespace Signorini
{
  namespace Contact
  {
    namespace Mindlin
    {
      double
      stick_ratio(const double load_ratio, const bool point_contact)
      {
        const double left = std::clamp(1. - load_ratio, 0., 1.);
        return point_contact ? std::cbrt(left) : std::sqrt(left);
      }

      double
      traction(const double r, const double a, const double c, const double mu_p0)
      {
        const auto root = [](const double x) { return std::sqrt(std::max(0., 1. - x * x)); };
        double q = root(r / a);
        if (c > 0.)
          q -= (c / a) * root(r / c);
        return mu_p0 * q;
      }

      void
      LoadPath::add(const double ratio)
      {
        const double change = ratio - last;
        if (std::abs(change) <= 1e-9)
          return;
        const int sense = change > 0. ? 1 : -1;
        if (direction != 0 && sense != direction)
          reversal_points.push_back(last);
        direction = sense;
        last      = ratio;
        // Close the loops that this branch has passed through (Masing).
        for (;;)
          {
            const std::size_t n = reversal_points.size();
            if (n >= 2 && sense * (ratio - reversal_points[n - 2]) >= 0.)
              reversal_points.resize(n - 2);
            else if (n == 1 && sense * (ratio + reversal_points[0]) >= 0.)
              reversal_points.clear();
            else
              break;
          }
      }

      double
      LoadPath::stick_ratio(const bool point_contact) const
      {
        if (reversal_points.empty())
          return Mindlin::stick_ratio(std::abs(last), point_contact);
        return Mindlin::stick_ratio(0.5 * std::abs(last - reversal_points.back()),
                                    point_contact);
      }

      double
      LoadPath::traction(const double r,
                         const double a,
                         const double mu_p0,
                         const bool   point_contact) const
      {
        // The virgin branch up to the first reversal (or the last load),
        // then each branch: twice the virgin traction of half its change.
        const auto branch = [&](const double from, const double to, const double factor) {
          const double change = std::abs(to - from) / factor;
          const double c      = a * Mindlin::stick_ratio(change, point_contact);
          const double sign   = to >= from ? 1. : -1.;
          return sign * factor * Mindlin::traction(r, a, c, mu_p0);
        };
        double      q    = 0.;
        double      from = 0.;
        double      factor = 1.;
        for (const double reversal : reversal_points)
          {
            q += branch(from, reversal, factor);
            from   = reversal;
            factor = 2.;
          }
        return q + branch(from, last, factor);
      }
    } // namespace Mindlin
  } // namespace Contact
} // namespace Signorini
