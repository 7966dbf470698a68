#include <signorini/contact/indicator.h>

#include <deal.II/base/tensor.h>

#include <Sacado.hpp>

#include <cmath>
#include <type_traits>

namespace Signorini
{
  namespace Contact
  {
    namespace
    {
      template <typename Number>
      Number
      cube_positive(const Number &s)
      {
        return s > 0. ? s * s * s : Number(0.);
      }

      /// 3^9 (2D) and 4^12 (3D): Fp's maximum becomes 1.
      template <int dim>
      constexpr double
      normalisation()
      {
        return dim == 2 ? 19683. : 16777216.;
      }

      /**
       * The face term at the variables p (x, face vertices, opposite
       * vertices; p[k][d] is coordinate d of point k).
       */
      template <int dim, typename Number>
      Number
      face_term(const std::array<std::array<Number, dim>, IndicatorFace<dim>::n_points> &p,
                const std::array<double, IndicatorFace<dim>::n_face_vertices> &stretch,
                const double apex_depth,
                double      *depth = nullptr)
      {
        constexpr unsigned int nf = IndicatorFace<dim>::n_face_vertices;
        // Apex: from the face's centroid towards the opposite face's
        // centroid, the fraction apex_depth of the way.
        std::array<Number, dim> apex;
        for (unsigned int d = 0; d < dim; ++d)
          {
            Number face_mean = 0., opposite_mean = 0.;
            for (unsigned int v = 0; v < nf; ++v)
              {
                face_mean += p[1 + v][d];
                opposite_mean += p[1 + nf + v][d];
              }
            apex[d] = (face_mean + apex_depth * (opposite_mean - face_mean)) / double(nf);
          }
        if (depth)
          *depth = -1.;

        // The simplices' bases: 2D one segment, 3D two triangles.
        constexpr unsigned int n_simplices = (dim == 2 ? 1 : 2);
        const unsigned int     corners[2][3] = {{0, 1, 2}, {0, 2, 3}};
        Number                 total         = 0.;
        for (unsigned int t = 0; t < n_simplices; ++t)
          {
            // Base vertices scaled about their centroid by 1 + 2 s.
            std::array<std::array<Number, dim>, dim> base;
            std::array<Number, dim>                  centroid;
            for (unsigned int d = 0; d < dim; ++d)
              {
                centroid[d] = 0.;
                for (unsigned int v = 0; v < dim; ++v)
                  centroid[d] += p[1 + corners[t][v]][d];
                centroid[d] /= double(dim);
              }
            for (unsigned int v = 0; v < dim; ++v)
              for (unsigned int d = 0; d < dim; ++d)
                base[v][d] = centroid[d] + (1. + 2. * stretch[corners[t][v]]) *
                                             (p[1 + corners[t][v]][d] - centroid[d]);

            // xi = M^-1 (x - A), M = [base_v - A].
            std::array<std::array<Number, dim>, dim> M;
            std::array<Number, dim>                  r;
            for (unsigned int i = 0; i < dim; ++i)
              {
                r[i] = p[0][i] - apex[i];
                for (unsigned int v = 0; v < dim; ++v)
                  M[i][v] = base[v][i] - apex[i];
              }
            std::array<Number, dim> xi;
            if (dim == 2)
              {
                const Number det = M[0][0] * M[1][1] - M[0][1] * M[1][0];
                xi[0] = (M[1][1] * r[0] - M[0][1] * r[1]) / det;
                xi[1] = (-M[1][0] * r[0] + M[0][0] * r[1]) / det;
              }
            else
              {
                // Cramer's rule with cofactors.
                const auto &m   = M;
                const Number c00 = m[1][1] * m[2][2] - m[1][2] * m[2][1];
                const Number c01 = m[1][2] * m[2][0] - m[1][0] * m[2][2];
                const Number c02 = m[1][0] * m[2][1] - m[1][1] * m[2][0];
                const Number det = m[0][0] * c00 + m[0][1] * c01 + m[0][2] * c02;
                const Number c10 = m[0][2] * m[2][1] - m[0][1] * m[2][2];
                const Number c11 = m[0][0] * m[2][2] - m[0][2] * m[2][0];
                const Number c12 = m[0][1] * m[2][0] - m[0][0] * m[2][1];
                const Number c20 = m[0][1] * m[1][2] - m[0][2] * m[1][1];
                const Number c21 = m[0][2] * m[1][0] - m[0][0] * m[1][2];
                const Number c22 = m[0][0] * m[1][1] - m[0][1] * m[1][0];
                // inverse = adjugate / det, adjugate = cofactor^T
                xi[0] = (c00 * r[0] + c10 * r[1] + c20 * r[2]) / det;
                xi[1] = (c01 * r[0] + c11 * r[1] + c21 * r[2]) / det;
                xi[2] = (c02 * r[0] + c12 * r[1] + c22 * r[2]) / det;
              }
            Number last = 1.;
            Number term = normalisation<dim>();
            for (unsigned int d = 0; d < dim; ++d)
              {
                last -= xi[d];
                term *= cube_positive(xi[d]);
              }
            term *= cube_positive(last);
            total += term;
            if constexpr (std::is_same_v<Number, double>)
              if (depth && term > 0.)
                {
                  // Distance to the base plane: the apex's barycentric
                  // coordinate times the apex's height over the base,
                  // |det M| / measure of the base (2D: its length, 3D:
                  // twice its area).
                  Tensor<1, dim> e1, e2;
                  for (unsigned int d = 0; d < dim; ++d)
                    {
                      e1[d] = base[1][d] - base[0][d];
                      if (dim == 3)
                        e2[d] = base[dim - 1][d] - base[0][d];
                    }
                  double det = 0., measure = 0.;
                  if constexpr (dim == 2)
                    {
                      det     = M[0][0] * M[1][1] - M[0][1] * M[1][0];
                      measure = e1.norm();
                    }
                  else
                    {
                      Tensor<2, dim> m;
                      for (unsigned int i = 0; i < dim; ++i)
                        for (unsigned int j = 0; j < dim; ++j)
                          m[i][j] = M[i][j];
                      det     = determinant(m);
                      measure = cross_product_3d(e1, e2).norm();
                    }
                  const double d_t = last * std::abs(det) / measure;
                  *depth = (*depth < 0. ? d_t : std::min(*depth, d_t));
                }
          }
        return total;
      }

      template <int dim, typename Number>
      std::array<std::array<Number, dim>, IndicatorFace<dim>::n_points>
      gather(const IndicatorFace<dim> &f, const Point<dim> &x)
      {
        constexpr unsigned int nf = IndicatorFace<dim>::n_face_vertices;
        std::array<std::array<Number, dim>, IndicatorFace<dim>::n_points> p;
        for (unsigned int d = 0; d < dim; ++d)
          {
            p[0][d] = x[d];
            for (unsigned int v = 0; v < nf; ++v)
              {
                p[1 + v][d]      = f.face[v][d];
                p[1 + nf + v][d] = f.opposite[v][d];
              }
          }
        return p;
      }
    } // namespace

    template <int dim>
    std::array<double, IndicatorFace<dim>::n_face_vertices>
    IndicatorFace<dim>::stretches(const double stretch) const
    {
      std::array<double, n_face_vertices> s;
      for (unsigned int v = 0; v < n_face_vertices; ++v)
        s[v] = (end_stretch[v] >= 0. ? end_stretch[v] : stretch);
      return s;
    }

    template <int dim>
    double
    IndicatorFace<dim>::value(const Point<dim> &x,
                              const double      stretch,
                              const double      apex_depth) const
    {
      return face_term<dim, double>(gather<dim, double>(*this, x),
                                    stretches(stretch),
                                    apex_depth);
    }

    template <int dim>
    double
    IndicatorFace<dim>::depth(const Point<dim> &x,
                              const double      stretch,
                              const double      apex_depth) const
    {
      double d = -1.;
      face_term<dim, double>(gather<dim, double>(*this, x), stretches(stretch),
                             apex_depth, &d);
      return d;
    }

    template <int dim>
    double
    IndicatorFace<dim>::derivatives(const Point<dim>  &x,
                                    const double        stretch,
                                    Vector<double>     &gradient,
                                    FullMatrix<double> &hessian,
                                    const double        apex_depth) const
    {
      using Inner = Sacado::Fad::DFad<double>;
      using Outer = Sacado::Fad::DFad<Inner>;
      const auto values = gather<dim, double>(*this, x);
      std::array<std::array<Outer, dim>, n_points> p;
      for (unsigned int k = 0; k < n_points; ++k)
        for (unsigned int d = 0; d < dim; ++d)
          {
            const unsigned int i = k * dim + d;
            Inner              inner(n_variables, i, values[k][d]);
            p[k][d] = Outer(n_variables, i, inner);
          }
      const Outer result = face_term<dim, Outer>(p, stretches(stretch), apex_depth);
      gradient.reinit(n_variables);
      hessian.reinit(n_variables, n_variables);
      if (result.size() == 0) // a constant zero: no variable entered
        return result.val().val();
      for (unsigned int i = 0; i < n_variables; ++i)
        {
          gradient(i) = result.dx(i).val();
          if (result.dx(i).size() > 0)
            for (unsigned int j = 0; j < n_variables; ++j)
              hessian(i, j) = result.dx(i).dx(j);
        }
      return result.val().val();
    }

    template <int dim>
    bool
    IndicatorFace<dim>::in_cell(const Point<dim> &x) const
    {
      constexpr unsigned int nf = n_face_vertices;
      Point<dim>             centroid;
      double                 size = 0.;
      for (unsigned int v = 0; v < nf; ++v)
        {
          centroid += (face[v] + opposite[v]) / (2. * nf);
          size = std::max(size, face[v].distance(opposite[v]));
        }
      // Each side as (point, normal), the normal oriented away from the
      // centroid.
      // The face itself is outside (a point on the contact surface has
      // not penetrated); the other sides belong to the cell (a point on
      // a symmetry plane through the cell's side is inside).
      auto outside = [&](const Point<dim> &p, Tensor<1, dim> n, const bool base) {
        n /= n.norm();
        if ((centroid - p) * n > 0.)
          n = -n;
        return base ? (x - p) * n > -1e-10 * size : (x - p) * n > 1e-10 * size;
      };
      if constexpr (dim == 2)
        {
          const std::array<Point<dim>, 4> polygon = {
            {face[0], face[1], opposite[1], opposite[0]}};
          for (unsigned int i = 0; i < 4; ++i)
            {
              const Tensor<1, dim> e = polygon[(i + 1) % 4] - polygon[i];
              if (outside(polygon[i], Tensor<1, dim>({-e[1], e[0]}), i == 0))
                return false;
            }
          return true;
        }
      else
        {
          std::vector<std::array<Point<dim>, 3>> sides = {
            {{face[0], face[1], face[2]}}, {{opposite[0], opposite[1], opposite[2]}}};
          for (unsigned int v = 0; v < nf; ++v)
            sides.push_back({{face[v], face[(v + 1) % nf], opposite[v]}});
          for (unsigned int i = 0; i < sides.size(); ++i)
            if (outside(sides[i][0],
                        cross_product_3d(sides[i][1] - sides[i][0],
                                         sides[i][2] - sides[i][0]),
                        i == 0))
              return false;
          return true;
        }
    }

    template <int dim>
    BoundingBox<dim>
    IndicatorFace<dim>::bounding_box(const double stretch,
                                     const double apex_depth) const
    {
      Point<dim> apex;
      for (unsigned int v = 0; v < n_face_vertices; ++v)
        apex += ((1. - apex_depth) * face[v] + apex_depth * opposite[v]) /
                double(n_face_vertices);
      // A stretched base vertex V + 2s (V - G_t) (G_t a centroid of face
      // vertices) moves by at most 2s times the faces' extent in each
      // coordinate.
      Point<dim> face_lower = face[0], face_upper = face[0];
      for (const auto &q : face)
        for (unsigned int d = 0; d < dim; ++d)
          {
            face_lower[d] = std::min(face_lower[d], q[d]);
            face_upper[d] = std::max(face_upper[d], q[d]);
          }
      Point<dim> lower = apex, upper = apex;
      // The cell's opposite vertices too, for in_cell() queries.
      for (const auto &q : opposite)
        for (unsigned int d = 0; d < dim; ++d)
          {
            lower[d] = std::min(lower[d], q[d]);
            upper[d] = std::max(upper[d], q[d]);
          }
      for (unsigned int d = 0; d < dim; ++d)
        {
          double largest = 0.;
          for (const double s : stretches(stretch))
            largest = std::max(largest, s);
          const double grow = 2. * largest * (face_upper[d] - face_lower[d]);
          lower[d] = std::min(lower[d], face_lower[d] - grow);
          upper[d] = std::max(upper[d], face_upper[d] + grow);
        }
      return BoundingBox<dim>(std::make_pair(lower, upper));
    }

    template struct IndicatorFace<2>;
    template struct IndicatorFace<3>;
  } // namespace Contact
} // namespace Signorini
