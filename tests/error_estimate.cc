// The discretisation error estimate of a quantity from a sequence of
// meshes (output/error_estimate.h), on sequences whose limit is known:
// - Q = 1 + 0.3 h^1.5 on halved meshes: four meshes find the order 1.5 and
//   the error of the finest to 1e-6 (the form is exact);
// - three meshes (Richardson with the assumed order 1): exact for an order
//   1 sequence, at most r + 1 = 3 times the error for order 2 (r = 2);
// - a sequence that oscillates about its limit (Q = 1 + (-1)^k 0.1 h): a
//   difference that is small by chance does not make the estimate small
//   (the previous difference, reduced by r^2, takes over); six meshes come
//   within a factor 3;
// - a sequence with scatter about its trend (0.1% of the first error) is
//   not estimated below its scatter;
// - the oldest of four meshes off the sequence (a jump 34 times the next
//   change, or on the other side of the limit while the last three
//   converge monotonically): the last three meshes give the estimate;
// - a repeated mesh size (a cycle that refined no cell below the smallest)
//   counts once, with its later value; non-finite values are skipped; one
//   mesh gives no estimate;
// - add_estimates() estimates only the estimable quantities, relative to
//   a vector's length where a scale is set, and tells how many meshes it
//   used.

#include <signorini/output/error_estimate.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <vector>

using namespace Signorini;

namespace
{
  const char *
  verdict(const bool ok)
  {
    return ok ? "yes" : "NO";
  }

  std::vector<double>
  halved(const unsigned int n)
  {
    std::vector<double> h;
    for (unsigned int k = 0; k < n; ++k)
      h.push_back(std::pow(0.5, k));
    return h;
  }
} // namespace

int
main()
{
  std::ofstream out("output");
  {
    const auto          h = halved(6);
    std::vector<double> q;
    for (const double x : h)
      q.push_back(1. + 0.3 * std::pow(x, 1.5));
    const auto   e    = ErrorEstimate::estimate(h, q);
    const double true_error = q.back() - 1.;
    out << "smooth sequence, 6 meshes: uses " << e.meshes << ", order "
        << e.order << "\n"
        << "  order found to 0.05: " << verdict(std::abs(e.order - 1.5) < 0.051)
        << "\n"
        << "  error of the finest to 1e-6 relative: "
        << verdict(std::abs(e.error - true_error) < 1e-6 * true_error) << "\n"
        << "  limit to 1e-9: " << verdict(std::abs(e.limit - 1.) < 1e-9) << "\n";
  }
  {
    const auto          h = halved(3);
    std::vector<double> q1, q2;
    for (const double x : h)
      {
        q1.push_back(2. - 0.5 * x);
        q2.push_back(2. - 0.5 * x * x);
      }
    const auto e1 = ErrorEstimate::estimate(h, q1);
    const auto e2 = ErrorEstimate::estimate(h, q2);
    out << "three meshes, order 1: uses " << e1.meshes << ", effectivity "
        << e1.error / (0.5 * h.back()) << "\n"
        << "three meshes, order 2: effectivity " << e2.error / (0.5 * 0.25 * 0.25)
        << "\n"
        << "  within 1e-12 of 1 and of 3: "
        << verdict(std::abs(e1.error / (0.5 * h.back()) - 1.) < 1e-12 &&
                   std::abs(e2.error / (0.5 * 0.25 * 0.25) - 3.) < 1e-12)
        << "\n";
  }
  {
    // Differences 0.15, 0.075, ...: with three meshes the last one is
    // 0.075 / 1 = 0.075 against a true 0.025 (effectivity 3).
    const auto          h = halved(3);
    std::vector<double> q;
    for (unsigned int k = 0; k < h.size(); ++k)
      q.push_back(1. + (k % 2 ? -0.1 : 0.1) * h[k]);
    const auto e = ErrorEstimate::estimate(h, q);
    out << "oscillating, three meshes: effectivity "
        << e.error / std::abs(q.back() - 1.) << "\n";
    // The middle value moved onto the trend of the other two: the last
    // difference is then small by chance.
    q[1]          = 0.5 * (q[0] + q[2]) + 1e-6;
    const auto e2 = ErrorEstimate::estimate(h, q);
    out << "  a small last difference keeps the estimate at least a quarter "
           "of the previous one: "
        << verdict(e2.error >= 0.25 * std::abs(q[1] - q[0]) * (1. - 1e-12)) << "\n";
    const auto          h6 = halved(6);
    std::vector<double> q6;
    for (unsigned int k = 0; k < h6.size(); ++k)
      q6.push_back(1. + (k % 2 ? -0.1 : 0.1) * h6[k]);
    const auto e6 = ErrorEstimate::estimate(h6, q6);
    const double effectivity = e6.error / std::abs(q6.back() - 1.);
    out << "oscillating, six meshes: effectivity " << effectivity
        << ", within a factor 3: "
        << verdict(effectivity >= 1. / 3. && effectivity <= 3.) << "\n";
  }
  {
    const auto          h = halved(6);
    std::vector<double> q;
    const double        scatter[] = {0., 1e-4, -1e-4, 1e-4, -1e-4, 1e-4};
    for (unsigned int k = 0; k < h.size(); ++k)
      q.push_back(1. + 0.1 * h[k] * h[k] + scatter[k]);
    const auto e = ErrorEstimate::estimate(h, q);
    out << "scatter of 1e-4 about an order 2 trend: estimate not below 5e-5: "
        << verdict(e.error >= 5e-5) << "\n";
  }
  {
    const std::vector<double> h = {1., 0.5, 0.5, 0.25};
    const std::vector<double> q = {2., 7., 1.5, 1.25};
    const auto e = ErrorEstimate::estimate(h, q);
    out << "a repeated mesh size counts once with its later value: "
        << verdict(e.meshes == 3 && std::abs(e.error - 0.25) < 1e-12) << "\n";
    const std::vector<double> q_nan = {2., std::numeric_limits<double>::quiet_NaN(), 1.5, 1.25};
    const auto e_nan = ErrorEstimate::estimate({1., 0.75, 0.5, 0.25}, q_nan);
    out << "a NaN value is skipped: " << verdict(e_nan.meshes == 3) << "\n";
    out << "one mesh, no estimate: "
        << verdict(!ErrorEstimate::estimate({1.}, {2.}).valid) << "\n";
  }
  // The oldest of four meshes off the sequence: by a jump no order up to
  // 3 explains (a mesh too coarse for the contact zone), or on the other
  // side of the limit while the last three converge monotonically; the
  // last three give the estimate (order 1 here: exact).
  for (const auto &[name, first] :
       {std::pair<const char *, double>{"a jump 34x the next change", 1.9},
        {"the other side of the limit", 0.98}})
    {
      const auto                h = halved(4);
      const std::vector<double> q = {first, 1.05, 1.025, 1.0125};
      const auto                e = ErrorEstimate::estimate(h, q);
      const double              effectivity = e.error / 0.0125;
      out << "oldest of four meshes off, " << name << ": uses " << e.meshes
          << ", effectivity " << effectivity << "\n"
          << "  the last three's estimate: "
          << verdict(e.meshes == 3 && std::abs(effectivity - 1.) < 1e-12) << "\n";
    }

  {
    std::vector<std::vector<Quantity>> per_mesh(3);
    const std::vector<double>          h = {1., 0.5, 0.25};
    for (unsigned int i = 0; i < 3; ++i)
      {
        Quantity fx, fy, count;
        fx.name = "contact_force_x";
        fx.value = 1e-14 * (i + 1); // round-off about 0
        fx.estimable = true;
        fx.scale = 2.;
        fy.name = "contact_force_y";
        fy.value = 2. + h[i];
        fy.estimable = true;
        fy.scale = 2. + h[i];
        count.name = "active_contact_nodes";
        count.value = 10 * (i + 1);
        per_mesh[i] = {fx, fy, count};
      }
    std::vector<Quantity> latest = per_mesh.back();
    ErrorEstimate::add_estimates(h, per_mesh, latest);
    out << "add_estimates: force components estimated, the count not: "
        << verdict(latest[0].has_estimate && latest[1].has_estimate &&
                   !latest[2].has_estimate)
        << "\n"
        << "  the vanishing component relative to the force: "
        << verdict(latest[0].estimated_relative_error() < 1e-13) << "\n"
        << "  the other: " << latest[1].estimated_relative_error()
        << ", from " << latest[1].estimate_meshes << " meshes\n";
  }
}
