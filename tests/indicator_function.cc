// The smooth indicator function of a deformable body's contact surface:
// (1) gradient and Hessian of a face term (by automatic differentiation)
//     against central differences, in 2D and 3D, for random cells and for
//     nearly degenerate ones (flat, sheared); a corrupted Hessian must be
//     rejected;
// (2) sampling: Phi = sum of face terms is > 0 in a layer just inside the
//     surface, including under the shared vertices, and 0 on the surface
//     and outside.
// Both for the poster's simplices and for the 'partition' shape; for the
// latter also (3) the points near a face's ends, where the weights ramp,
// and (4) how much Phi varies along a flat surface at a fixed depth, with
// equal faces (where it must be constant, free ends included) and uneven
// ones.

#include <signorini/contact/indicator.h>

#include <deal.II/base/utilities.h>

#include <fstream>
#include <iomanip>
#include <map>
#include <random>

using namespace dealii;
using namespace Signorini;

constexpr double stretch = 0.12;

using Shape = Contact::IndicatorShape;

template <int dim>
Contact::IndicatorFace<dim>
unit_face(std::mt19937 &rng, const double jitter, const double depth, const double shear,
          const Shape shape)
{
  // Face on x_d = 0, cell below it down to x_d = -depth.
  std::uniform_real_distribution<double> u(-1., 1.);
  Contact::IndicatorFace<dim>            f;
  f.shape = shape;
  const std::array<std::array<double, 2>, 4> corners = {
    {{0., 0.}, {1., 0.}, {1., 1.}, {0., 1.}}};
  for (unsigned int v = 0; v < f.n_face_vertices; ++v)
    {
      Point<dim> q;
      q[0] = (dim == 2 ? double(v) : corners[v][0]);
      if (dim == 3)
        q[1] = corners[v][1];
      Point<dim> r = q;
      r[dim - 1]   = -depth;
      r[0] += shear;
      for (unsigned int d = 0; d < dim; ++d)
        {
          q[d] += jitter * u(rng);
          r[d] += jitter * u(rng);
        }
      f.face[v]     = q;
      f.opposite[v] = r;
    }
  return f;
}

template <int dim>
void
check_derivatives(const std::string &name, const double jitter, const double depth,
                  const double shear, std::ostream &out,
                  const Shape shape = Shape::simplex, const bool near_ends = false)
{
  std::mt19937                           rng(42 + dim);
  std::uniform_real_distribution<double> u(0., 1.);
  double worst_g = 0., worst_h = 0., worst_value = 0., worst_corrupted = 1e300;
  unsigned int positive = 0;
  for (unsigned int trial = 0; trial < 20; ++trial)
    {
      auto f = unit_face<dim>(rng, jitter, depth, shear, shape);
      // A point inside the cell near the face, where the terms are > 0.
      Point<dim>          x;
      std::vector<double> weights(f.n_face_vertices);
      double              sum = 0.;
      for (auto &wt : weights)
        sum += (wt = 0.2 + u(rng));
      for (unsigned int v = 0; v < f.n_face_vertices; ++v)
        x += weights[v] / sum * f.face[v];
      if (near_ends)
        {
          // Within 0.1 of vertex 0's end(s), on either side, and every
          // other trial with free ends.
          x = f.face[0];
          for (unsigned int d = 0; d + 1 < dim; ++d)
            x[d] += 0.2 * (u(rng) - 0.5);
          if (trial % 2 == 1)
            f.free_end.fill(true), f.end_stretch.fill(0.3);
        }
      x[dim - 1] -= 0.1 * depth * (0.2 + u(rng));

      Vector<double>     g;
      FullMatrix<double> H;
      const double       value = f.derivatives(x, stretch, g, H);
      worst_value = std::max(worst_value, std::abs(value - f.value(x, stretch)));
      positive += (value > 0.);
      const unsigned int n     = f.n_variables;
      const double       scale = g.l2_norm() + 1e-300;
      // Perturb variable i (point i / dim, coordinate i % dim).
      auto shifted = [&](const unsigned int i, const double h) {
        Contact::IndicatorFace<dim> s = f;
        Point<dim>                  y = x;
        const unsigned int          k = i / dim, d = i % dim;
        if (k == 0)
          y[d] += h;
        else if (k <= f.n_face_vertices)
          s.face[k - 1][d] += h;
        else
          s.opposite[k - 1 - f.n_face_vertices][d] += h;
        return std::make_pair(s, y);
      };
      const double h = 1e-6 * depth;
      FullMatrix<double> fd_H(n, n);
      for (unsigned int i = 0; i < n; ++i)
        {
          const auto p = shifted(i, h), m = shifted(i, -h);
          const double fd = (p.first.value(p.second, stretch) -
                             m.first.value(m.second, stretch)) / (2 * h);
          worst_g = std::max(worst_g, std::abs(fd - g(i)) / scale);
          Vector<double>     gp, gm;
          FullMatrix<double> Hp, Hm;
          p.first.derivatives(p.second, stretch, gp, Hp);
          m.first.derivatives(m.second, stretch, gm, Hm);
          for (unsigned int j = 0; j < n; ++j)
            fd_H(j, i) = (gp(j) - gm(j)) / (2 * h);
        }
      const double h_scale = H.frobenius_norm() + 1e-300;
      FullMatrix<double> diff(H);
      diff.add(-1., fd_H);
      worst_h = std::max(worst_h, diff.frobenius_norm() / h_scale);
      FullMatrix<double> corrupted(H);
      corrupted *= 1.001;
      corrupted.add(-1., fd_H);
      if (value > 0.)
        worst_corrupted = std::min(worst_corrupted, corrupted.frobenius_norm() / h_scale);
    }
  const bool ok = worst_g < 1e-6 && worst_h < 1e-5 && worst_value < 1e-14 && positive >= 15;
  out << dim << "D " << name << ": " << positive << "/20 points with Phi > 0, "
      << "gradient vs FD " << (worst_g < 1e-6 ? "ok" : "FAIL") << ", Hessian vs FD "
      << (worst_h < 1e-5 ? "ok" : "FAIL") << ", value() = derivatives() "
      << (worst_value < 1e-14 ? "ok" : "FAIL") << ", Hessian x 1.001 "
      << (worst_corrupted >= 1e-5 ? "rejected" : "NOT rejected") << "\n";
  if (!ok)
    std::cerr << name << ": " << worst_g << " " << worst_h << " " << worst_value << "\n";
}

// A strip of cells under x_d = 0 with uneven vertex spacing; sample Phi in
// a layer below the surface (also under every shared vertex), on it and
// above it.
template <int dim>
void
check_sampling(const double stretch, std::ostream &out, const Shape shape = Shape::simplex,
               const bool equal = false)
{
  const std::vector<double> xs = (equal ? std::vector<double>{0., 1., 2., 3., 4.} :
                                          std::vector<double>{0., 0.7, 1.5, 2.6, 4.});
  const std::vector<double> ys = (dim == 2 ? std::vector<double>{0., 1.} :
                                   equal    ? std::vector<double>{0., 1., 2.} :
                                              std::vector<double>{0., 0.9, 2.});
  const double depth = 1.;
  std::vector<Contact::IndicatorFace<dim>> faces;
  for (unsigned int i = 0; i + 1 < xs.size(); ++i)
    for (unsigned int j = 0; j + 1 < ys.size(); ++j)
      {
        Contact::IndicatorFace<dim> f;
        f.shape = shape;
        if (dim == 2)
          {
            f.face[0][0] = xs[i];
            f.face[1][0] = xs[i + 1];
          }
        else
          {
            const double cx[4] = {xs[i], xs[i + 1], xs[i + 1], xs[i]};
            const double cy[4] = {ys[j], ys[j], ys[j + 1], ys[j + 1]};
            for (unsigned int v = 0; v < 4; ++v)
              {
                f.face[v][0] = cx[v];
                f.face[v][1] = cy[v];
              }
          }
        for (unsigned int v = 0; v < f.n_face_vertices; ++v)
          {
            f.opposite[v]          = f.face[v];
            f.opposite[v][dim - 1] = -depth;
          }
        if (shape == Shape::partition)
          {
            // The strip's outer ends are free ends (as setup() finds them).
            const bool first_x = (i == 0), last_x = (i + 2 == xs.size());
            const bool first_y = (j == 0), last_y = (j + 2 == ys.size());
            const std::array<bool, 4> free =
              (dim == 2 ? std::array<bool, 4>{{first_x, last_x, false, false}} :
                          std::array<bool, 4>{{first_y, last_x, last_y, first_x}});
            for (unsigned int v = 0; v < f.n_face_vertices; ++v)
              if (free[v])
                {
                  f.free_end[v]                                = true;
                  f.end_stretch[v]                             = 0.5;
                  f.end_stretch[(v + 1) % f.n_face_vertices] = 0.5;
                }
          }
        faces.push_back(f);
        if (dim == 2)
          break;
      }
  if (shape == Shape::partition)
    {
      // The ramps at shared ends as setup() sets them: s times the smaller
      // neighbour's diameter over this face's.
      const unsigned int ny = (dim == 2 ? 1 : ys.size() - 1);
      auto diameter = [&](const Contact::IndicatorFace<dim> &f) {
        double d = 0.;
        for (const auto &a : f.face)
          for (const auto &b : f.face)
            d = std::max(d, a.distance(b));
        return d;
      };
      for (unsigned int k = 0; k < faces.size(); ++k)
        {
          const int i = k / ny, j = k % ny;
          const std::array<std::array<int, 2>, 4> next =
            (dim == 2 ? std::array<std::array<int, 2>, 4>{{{{i - 1, j}}, {{i + 1, j}}, {{0, 0}}, {{0, 0}}}} :
                        std::array<std::array<int, 2>, 4>{{{{i, j - 1}}, {{i + 1, j}}, {{i, j + 1}}, {{i - 1, j}}}});
          for (unsigned int v = 0; v < faces[k].n_face_vertices; ++v)
            {
              const int ni = next[v][0], nj = next[v][1];
              if (ni < 0 || nj < 0 || ni + 1 >= int(xs.size()) || nj >= int(ny))
                continue;
              faces[k].ramp[v] =
                stretch * std::min(1., diameter(faces[ni * ny + nj]) / diameter(faces[k]));
            }
        }
    }
  auto Phi = [&](const Point<dim> &x) {
    double s = 0.;
    for (const auto &f : faces)
      if (f.bounding_box(stretch).point_inside(x))
        s += f.value(x, stretch);
    return s;
  };
  auto Phi_all = [&](const Point<dim> &x) {
    double s = 0.;
    for (const auto &f : faces)
      s += f.value(x, stretch);
    return s;
  };
  // Sample positions: a fine grid plus every vertex coordinate.
  std::vector<double> sx, sy = {0.};
  for (unsigned int k = 1; k < 400; ++k)
    sx.push_back(0.01 * k);
  sx.insert(sx.end(), xs.begin() + 1, xs.end() - 1);
  if (dim == 3)
    {
      sy.clear();
      for (unsigned int k = 1; k < 40; ++k)
        sy.push_back(0.05 * k);
      sy.push_back(0.9);
    }
  if (shape == Shape::partition) // the free ends themselves
    {
      sx.push_back(xs.front());
      sx.push_back(xs.back());
      if (dim == 3)
        {
          sy.push_back(ys.front());
          sy.push_back(ys.back());
        }
    }
  // Largest relative variation of Phi along the surface at each depth.
  std::map<double, std::pair<double, double>> range;
  unsigned int inside = 0, inside_positive = 0, outside = 0, outside_zero = 0,
               box_misses = 0;
  double       on_surface = 0.;
  for (const double x : sx)
    for (const double y : sy)
      for (const double e : {1e-3, 1e-2, 0.05, 0.1, -1e-3, -0.1, 0.})
        {
          Point<dim> p;
          p[0]       = x;
          if (dim == 3)
            p[1] = y;
          p[dim - 1] = -e * depth;
          const double v = Phi(p);
          box_misses += (std::abs(v - Phi_all(p)) > 0.);
          if (e > 0.)
            {
              auto it = range.find(e);
              if (it == range.end())
                range[e] = {v, v};
              else
                it->second = {std::min(it->second.first, v), std::max(it->second.second, v)};
              ++inside;
              inside_positive += (v > 0.);
            }
          else if (e < 0.)
            {
              ++outside;
              outside_zero += (v == 0.);
            }
          else // on the surface: zero up to round-off in 1 - sum xi
            on_surface = std::max(on_surface, v);
        }
  out << dim << "D sampling, stretch " << stretch << ": Phi > 0 at " << inside_positive << " of " << inside
      << " points in the layer (depth 1e-3 .. 0.1 of the cell), Phi = 0 at "
      << outside_zero << " of " << outside
      << " points above the surface, max Phi on the surface < 1e-30: "
      << (on_surface < 1e-30 ? "yes" : "NO") << "; bounding boxes miss "
      << box_misses << " nonzero contributions\n";
  if (shape == Shape::partition)
    {
      double variation = 0.;
      for (const auto &r : range)
        variation = std::max(variation, (r.second.second - r.second.first) / r.second.second);
      out << "  partition, " << (equal ? "equal" : "uneven")
          << " faces: largest variation of Phi along the surface at a fixed depth ";
      // With the ramps of unequal faces spanning the same length on both
      // sides of an end, 2D is exact too; 3D only where the faces around
      // an edge have the same diameter.
      if (equal || dim == 2)
        out << "< 1e-12: " << (variation < 1e-12 ? "yes" : "NO") << "\n";
      else
        out << std::setprecision(2) << 100. * variation << "%\n";
    }
}

int
main()
{
  std::ofstream out("output");
  check_derivatives<2>("random cells", 0.1, 1., 0., out);
  check_derivatives<2>("flat cells (depth 1e-3)", 0., 1e-3, 0., out);
  check_derivatives<2>("sheared cells", 0.05, 0.3, 0.8, out);
  check_derivatives<3>("random cells", 0.1, 1., 0., out);
  check_derivatives<3>("flat cells (depth 1e-3)", 0., 1e-3, 0., out);
  check_derivatives<3>("sheared cells", 0.05, 0.3, 0.8, out);
  check_sampling<2>(stretch, out);
  check_sampling<3>(stretch, out);
  // Without the stretch, Phi vanishes under the shared vertices (and, in
  // 3D, under the diagonals): the sampling test sees it.
  check_sampling<2>(0., out);
  check_sampling<3>(0., out);

  const auto P = Shape::partition;
  check_derivatives<2>("partition, random cells", 0.1, 1., 0., out, P);
  check_derivatives<2>("partition, flat cells (depth 1e-3)", 0., 1e-3, 0., out, P);
  check_derivatives<2>("partition, sheared cells", 0.05, 0.3, 0.8, out, P);
  check_derivatives<2>("partition, near the ends", 0.1, 1., 0., out, P, true);
  check_derivatives<3>("partition, random cells", 0.1, 1., 0., out, P);
  check_derivatives<3>("partition, flat cells (depth 1e-3)", 0., 1e-3, 0., out, P);
  check_derivatives<3>("partition, sheared cells", 0.05, 0.3, 0.8, out, P);
  check_derivatives<3>("partition, near the ends", 0.1, 1., 0., out, P, true);
  for (const bool equal : {true, false})
    {
      check_sampling<2>(stretch, out, P, equal);
      check_sampling<3>(stretch, out, P, equal);
    }
}
