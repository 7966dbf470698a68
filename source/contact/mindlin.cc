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
    } // namespace Mindlin
  } // namespace Contact
} // namespace Signorini
