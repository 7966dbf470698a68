// An independent geometric check for self-contact tests: the two halves of
// a surface (nodes split by a reference coordinate) must not cross each
// other. Each half is a polyline through its nodes' current positions in
// a plane, ordered by a reference coordinate along it; a node of one half
// is compared with the other half's polyline at its own abscissa.
#pragma once

#include <algorithm>
#include <vector>

namespace SurfaceCrossing
{
  struct Node
  {
    double order; // reference coordinate along the surface (the polyline's order)
    double side;  // reference coordinate that tells the halves apart
    double x, y;  // current position in the plane of the check (y across)
  };

  /**
   * The largest distance of a node of one half beyond the other half's
   * polyline (> 0: the halves cross there), the upper half (side above
   * @p split) lying above the lower one. Nodes outside the other half's
   * x range are not compared.
   */
  inline double
  largest_crossing(const std::vector<Node> &nodes, const double split)
  {
    std::vector<Node> upper, lower;
    for (const auto &n : nodes)
      (n.side > split ? upper : lower).push_back(n);
    const auto by_order = [](const Node &a, const Node &b) { return a.order < b.order; };
    std::sort(upper.begin(), upper.end(), by_order);
    std::sort(lower.begin(), lower.end(), by_order);
    double     worst = -1e300;
    const auto check = [&worst](const std::vector<Node> &line,
                                const std::vector<Node> &others,
                                const double             sign) {
      for (const auto &n : others)
        for (std::size_t k = 0; k + 1 < line.size(); ++k)
          {
            const Node &a = line[k], &b = line[k + 1];
            if (!(b.x > a.x) || n.x < a.x || n.x > b.x)
              continue;
            const double y = a.y + (b.y - a.y) * (n.x - a.x) / (b.x - a.x);
            // sign +1: the line is the upper half, n must stay below it.
            worst = std::max(worst, sign * (n.y - y));
          }
    };
    check(upper, lower, 1.);
    check(lower, upper, -1.);
    return worst;
  }
} // namespace SurfaceCrossing
