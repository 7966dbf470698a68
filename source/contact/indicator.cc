#include <signorini/contact/indicator.h>

#include <Sacado.hpp>

#include <cmath>

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
                const double stretch)
      {
        constexpr unsigned int nf = IndicatorFace<dim>::n_face_vertices;
        // Apex: mean of the opposite face's vertices.
        std::array<Number, dim> apex;
        for (unsigned int d = 0; d < dim; ++d)
          {
            apex[d] = 0.;
            for (unsigned int v = 0; v < nf; ++v)
              apex[d] += p[1 + nf + v][d];
            apex[d] /= double(nf);
          }

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
                base[v][d] = centroid[d] + (1. + 2. * stretch) *
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
    double
    IndicatorFace<dim>::value(const Point<dim> &x, const double stretch) const
    {
      return face_term<dim, double>(gather<dim, double>(*this, x), stretch);
    }

    template <int dim>
    double
    IndicatorFace<dim>::derivatives(const Point<dim>  &x,
                                    const double        stretch,
                                    Vector<double>     &gradient,
                                    FullMatrix<double> &hessian) const
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
      const Outer result = face_term<dim, Outer>(p, stretch);
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
    BoundingBox<dim>
    IndicatorFace<dim>::bounding_box(const double stretch) const
    {
      Point<dim> apex;
      for (const auto &q : opposite)
        apex += q / double(n_face_vertices);
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
      for (unsigned int d = 0; d < dim; ++d)
        {
          const double grow = 2. * stretch * (face_upper[d] - face_lower[d]);
          lower[d] = std::min(lower[d], face_lower[d] - grow);
          upper[d] = std::max(upper[d], face_upper[d] + grow);
        }
      return BoundingBox<dim>(std::make_pair(lower, upper));
    }

    template struct IndicatorFace<2>;
    template struct IndicatorFace<3>;
  } // namespace Contact
} // namespace Signorini
