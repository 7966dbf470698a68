#include <signorini/output/error_estimate.h>

#include <cmath>
#include <limits>

namespace Signorini
{
  namespace ErrorEstimate
  {
    namespace
    {
      /// Q + C h^p fitted to the points, p fixed: the limit Q and the
      /// root mean square residual.
      std::pair<double, double>
      fit(const std::vector<double> &h, const std::vector<double> &q, const double p)
      {
        const std::size_t   n = h.size();
        std::vector<double> x(n);
        double              mx = 0., mq = 0.;
        for (std::size_t i = 0; i < n; ++i)
          {
            x[i] = std::pow(h[i], p);
            mx += x[i] / n;
            mq += q[i] / n;
          }
        double sxx = 0., sxq = 0.;
        for (std::size_t i = 0; i < n; ++i)
          {
            sxx += (x[i] - mx) * (x[i] - mx);
            sxq += (x[i] - mx) * (q[i] - mq);
          }
        const double c     = sxx > 0. ? sxq / sxx : 0.;
        const double limit = mq - c * mx;
        double       rss   = 0.;
        for (std::size_t i = 0; i < n; ++i)
          rss += (q[i] - limit - c * x[i]) * (q[i] - limit - c * x[i]);
        return {limit, std::sqrt(rss / n)};
      }
    } // namespace

    Estimate
    estimate(const std::vector<double> &h_all, const std::vector<double> &q_all)
    {
      // One value per distinct mesh size, the latest.
      std::vector<double> h, q;
      for (std::size_t i = 0; i < h_all.size() && i < q_all.size(); ++i)
        {
          if (!std::isfinite(q_all[i]) || !(h_all[i] > 0.))
            continue;
          if (!h.empty() && h_all[i] >= h.back())
            {
              h.back() = h_all[i];
              q.back() = q_all[i];
            }
          else
            {
              h.push_back(h_all[i]);
              q.push_back(q_all[i]);
            }
        }
      Estimate e;
      const std::size_t n = h.size();
      if (n < 2)
        return e;
      e.valid = true;
      e.limit = q.back();
      // Richardson's estimate from the last two or three meshes, order 1.
      const auto richardson = [&](const std::size_t meshes) {
        const double r = h[n - 2] / h[n - 1];
        double       d = std::abs(q[n - 1] - q[n - 2]);
        // The previous difference, reduced as an order 2 sequence would
        // reduce it, bounds the estimate from below.
        if (meshes == 3)
          d = std::max(d, std::abs(q[n - 2] - q[n - 3]) / (r * r));
        e.error  = d / (r - 1.);
        e.order  = 1.;
        e.limit  = q.back();
        e.meshes = meshes;
        return e;
      };
      if (n < 4)
        return richardson(n);
      const std::vector<double> h4(h.end() - 4, h.end()), q4(q.end() - 4, q.end());
      double                    best = std::numeric_limits<double>::max();
      for (unsigned int k = 0; k <= 50; ++k)
        {
          const double p              = 0.5 + 0.05 * k;
          const auto [limit, residual] = fit(h4, q4, p);
          if (residual < best)
            {
              best    = residual;
              e.order = p;
              e.limit = limit;
            }
        }
      // The oldest of the four meshes does not belong to the sequence when
      // its change is one no order up to 3 explains (more than 8 times the
      // next: a mesh too coarse to resolve the contact zone), or when the
      // last three converge monotonically (each change smaller than the
      // one before, of the same sign) and the fit misses them by more than
      // their last change: the last three meshes then give the estimate.
      const double d0 = q[n - 3] - q[n - 4], d1 = q[n - 2] - q[n - 3],
                   d2 = q[n - 1] - q[n - 2];
      if (std::abs(d0) > 8. * std::abs(d1) ||
          (d1 * d2 > 0. && std::abs(d2) < std::abs(d1) && best > std::abs(d2)))
        return richardson(3);
      e.error  = std::max(std::abs(q.back() - e.limit), best);
      e.meshes = 4;
      return e;
    }

    void
    add_estimates(const std::vector<double>                &h,
                  const std::vector<std::vector<Quantity>> &per_mesh,
                  std::vector<Quantity>                    &latest)
    {
      for (auto &quantity : latest)
        {
          quantity.has_estimate = false;
          if (!quantity.estimable)
            continue;
          std::vector<double> hs, values;
          for (std::size_t i = 0; i < per_mesh.size() && i < h.size(); ++i)
            for (const auto &q : per_mesh[i])
              if (q.name == quantity.name)
                {
                  hs.push_back(h[i]);
                  values.push_back(q.value);
                }
          const Estimate e = estimate(hs, values);
          if (e.valid)
            {
              quantity.has_estimate    = true;
              quantity.estimated_error = e.error;
              quantity.observed_order  = e.order;
              quantity.estimate_meshes = e.meshes;
            }
        }
    }
  } // namespace ErrorEstimate
} // namespace Signorini
