#include <signorini/contact/indicator.h>

#include <deal.II/base/tensor.h>

#include <Sacado.hpp>

#include <cmath>
#include <vector>
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

      /// C^2 ramp: 0 for u <= 0, 1 for u >= 1, u^3 (10 - 15 u + 6 u^2)
      /// between (value, first and second derivatives match at both ends;
      /// ramp(u) + ramp(1 - u) = 1).
      template <typename Number>
      Number
      ramp(const Number &u)
      {
        if (u <= 0.)
          return Number(0.);
        if (u >= 1.)
          return Number(1.);
        return u * u * u * (10. + u * (-15. + 6. * u));
      }

      /**
       * The weight of one face end at the coordinate t along the face
       * (t = 0 at the end, t > 0 into the face): at a shared end it rises
       * over [-s, s] (the neighbour's weight falls over the same points,
       * and the two sum to 1); at a free end over [-s_end, 0].
       */
      template <typename Number>
      Number
      end_weight(const Number &t, const bool free_end, const double s)
      {
        return free_end ? ramp<Number>((t + s) / s) : ramp<Number>((t + s) / (2. * s));
      }

      /**
       * The 'partition' face term (indicator.h): g(d / H) W(t) over the
       * prism normal to the face.
       */
      template <int dim, typename Number>
      Number
      partition_term(const std::array<std::array<Number, dim>, IndicatorFace<dim>::n_points> &p,
                     const double                                                  stretch,
                     const std::array<double, IndicatorFace<dim>::n_face_vertices> &end_stretch,
                     const std::array<bool, IndicatorFace<dim>::n_face_vertices>   &free_end,
                     const std::array<double, IndicatorFace<dim>::n_face_vertices> &ramp,
                     const double apex_depth,
                     double      *depth = nullptr)
      {
        constexpr unsigned int nf = IndicatorFace<dim>::n_face_vertices;
        if (depth)
          *depth = -1.;
        std::array<Number, dim> G, apex;
        for (unsigned int d = 0; d < dim; ++d)
          {
            Number face_mean = 0., opposite_mean = 0.;
            for (unsigned int v = 0; v < nf; ++v)
              {
                face_mean += p[1 + v][d];
                opposite_mean += p[1 + nf + v][d];
              }
            G[d]    = face_mean / double(nf);
            apex[d] = G[d] + apex_depth * (opposite_mean - face_mean) / double(nf);
          }
        // In-plane axes (2D: B -> C; 3D: the quad's midlines, a1 from edge
        // 3-0 to edge 1-2, a2 from edge 0-1 to edge 2-3) and the unit
        // normal towards the apex.
        std::array<std::array<Number, dim>, dim - 1> a;
        std::array<Number, dim>                      n;
        if constexpr (dim == 2)
          {
            for (unsigned int d = 0; d < dim; ++d)
              a[0][d] = p[2][d] - p[1][d];
            n[0] = -a[0][1];
            n[1] = a[0][0];
          }
        else
          {
            for (unsigned int d = 0; d < dim; ++d)
              {
                a[0][d] = 0.5 * (p[2][d] + p[3][d] - p[1][d] - p[4][d]);
                a[1][d] = 0.5 * (p[3][d] + p[4][d] - p[1][d] - p[2][d]);
              }
            n[0] = a[0][1] * a[1][2] - a[0][2] * a[1][1];
            n[1] = a[0][2] * a[1][0] - a[0][0] * a[1][2];
            n[2] = a[0][0] * a[1][1] - a[0][1] * a[1][0];
          }
        Number n2 = 0., height = 0.;
        for (unsigned int d = 0; d < dim; ++d)
          {
            n2 += n[d] * n[d];
            height += n[d] * (apex[d] - G[d]);
          }
        const Number n_norm = std::sqrt(n2);
        Number       dist   = 0.;
        for (unsigned int d = 0; d < dim; ++d)
          dist += n[d] * (p[0][d] - G[d]);
        // Oriented so that the apex lies at positive height.
        const double sign = (height > 0. ? 1. : -1.);
        dist *= sign / n_norm;
        height *= sign / n_norm;
        const Number eta = dist / height;
        if (eta <= 0. || eta >= 1.)
          return Number(0.);

        // Coordinates along the face, t in [0, 1] over it.
        std::array<Number, dim - 1> t;
        if constexpr (dim == 2)
          {
            Number num = 0., den = 0.;
            for (unsigned int d = 0; d < dim; ++d)
              {
                num += (p[0][d] - p[1][d]) * a[0][d];
                den += a[0][d] * a[0][d];
              }
            t[0] = num / den;
          }
        else
          {
            Number g00 = 0., g01 = 0., g11 = 0., r0 = 0., r1 = 0.;
            for (unsigned int d = 0; d < dim; ++d)
              {
                g00 += a[0][d] * a[0][d];
                g01 += a[0][d] * a[1][d];
                g11 += a[1][d] * a[1][d];
                r0 += a[0][d] * (p[0][d] - G[d]);
                r1 += a[1][d] * (p[0][d] - G[d]);
              }
            const Number det = g00 * g11 - g01 * g01;
            t[0]             = 0.5 + (g11 * r0 - g01 * r1) / det;
            t[1]             = 0.5 + (g00 * r1 - g01 * r0) / det;
          }
        // The ends of each coordinate: 2D t = 0 at vertex 0, t = 1 at
        // vertex 1; 3D t1 = 0 at edge 3, t1 = 1 at edge 1, t2 = 0 at edge
        // 0, t2 = 1 at edge 2 (edge v from vertex v to v + 1).
        const unsigned int lower[2] = {dim == 2 ? 0u : 3u, 0u};
        const unsigned int upper[2] = {1u, 2u};
        Number             weight   = 1.;
        for (unsigned int k = 0; k + 1 < dim; ++k)
          {
            const unsigned int lo = lower[k], hi = upper[k];
            // A free end's width is the end stretch (3D: set at the
            // edge's first vertex), a shared end's the common stretch.
            const auto width = [&](const unsigned int e) {
              return free_end[e] ? end_stretch[e] : ramp[e] > 0. ? ramp[e] : stretch;
            };
            weight *= end_weight<Number>(t[k], free_end[lo], width(lo));
            weight *= end_weight<Number>(1. - t[k], free_end[hi], width(hi));
          }
        const Number one_minus = 1. - eta;
        const Number term      = 64. * eta * eta * eta * one_minus * one_minus * one_minus * weight;
        if constexpr (std::is_same_v<Number, double>)
          if (depth && term > 0.)
            *depth = dist;
        return term;
      }

      /// A quad face's centroid and midlines (cyclic vertices Q0..Q3): a1
      /// from edge 3-0 to edge 1-2, a2 from edge 0-1 to edge 2-3, the frame
      /// of the partition shape (partition_term() builds the same one in
      /// its AD numbers).
      std::array<Tensor<1, 3>, 3>
      centroid_and_midlines(const std::array<Point<3>, 4> &q)
      {
        return {{0.25 * (q[0] + q[1] + q[2] + q[3]),
                 0.5 * (q[1] + q[2] - q[0] - q[3]),
                 0.5 * (q[2] + q[3] - q[0] - q[1])}};
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

      /**
       * A face term depends on its n variables y (indicator.h) only
       * through m < n linear combinations z = L y: both shapes are
       * unchanged when x and all vertices move together, the opposite
       * face enters through its centroid only, and the partition shape
       * sees the face through its centroid and midlines alone. Nested
       * forward mode in z costs about (m / n)^2 of the same in y (3D
       * partition: 12 against 27 variables); the derivatives in y follow
       * as L^T g_z and L^T H_z L.
       */
      template <int dim, unsigned int m>
      struct LinearReduction
      {
        static constexpr unsigned int n = IndicatorFace<dim>::n_variables;
        /// z = L y (rows of L) and a right inverse P of L (L P = I): the
        /// point y0 + P (z - z0) has the reduced coordinates z.
        std::array<std::array<double, n>, m> L{};
        std::array<std::array<double, m>, n> P{};
        /// The nonzero columns of each row of L.
        std::array<std::vector<unsigned int>, m> nonzero;

        /// Row a of L gets coefficient c on coordinate d of point k.
        void
        add(const unsigned int a, const unsigned int k, const unsigned int d, const double c)
        {
          L[a][k * dim + d] += c;
        }

        /// P = L^T (L L^T)^-1, and the nonzero columns.
        void
        finish()
        {
          FullMatrix<double> LLt(m, m);
          for (unsigned int a = 0; a < m; ++a)
            for (unsigned int b = 0; b < m; ++b)
              for (unsigned int i = 0; i < n; ++i)
                LLt(a, b) += L[a][i] * L[b][i];
          LLt.gauss_jordan();
          for (unsigned int i = 0; i < n; ++i)
            for (unsigned int a = 0; a < m; ++a)
              for (unsigned int b = 0; b < m; ++b)
                P[i][a] += L[b][i] * LLt(b, a);
          for (unsigned int a = 0; a < m; ++a)
            for (unsigned int i = 0; i < n; ++i)
              if (L[a][i] != 0.)
                nonzero[a].push_back(i);
        }
      };

      /// Simplex shape: every face vertex and the opposite face's centroid
      /// relative to x (2D 6, 3D 15 variables).
      template <int dim>
      auto
      simplex_reduction()
      {
        constexpr unsigned int nf = IndicatorFace<dim>::n_face_vertices;
        LinearReduction<dim, dim *(nf + 1)> R;
        for (unsigned int d = 0; d < dim; ++d)
          {
            for (unsigned int v = 0; v < nf; ++v)
              {
                R.add(v * dim + d, 1 + v, d, 1.);
                R.add(v * dim + d, 0, d, -1.);
              }
            for (unsigned int v = 0; v < nf; ++v)
              R.add(nf * dim + d, 1 + nf + v, d, 1. / nf);
            R.add(nf * dim + d, 0, d, -1.);
          }
        R.finish();
        return R;
      }

      /// Partition shape: x relative to the face's centroid, the face's
      /// axes (2D C - B; 3D the midlines) and the opposite face's centroid
      /// relative to the face's (2D 6, 3D 12 variables).
      template <int dim>
      auto
      partition_reduction()
      {
        constexpr unsigned int nf = IndicatorFace<dim>::n_face_vertices;
        // Axis k = sum_v alpha[k][v] face vertex v (partition_term()).
        const std::array<std::array<double, 4>, 2> alpha =
          dim == 2 ? std::array<std::array<double, 4>, 2>{{{{-1., 1., 0., 0.}}, {}}} :
                     std::array<std::array<double, 4>, 2>{
                       {{{-.5, .5, .5, -.5}}, {{-.5, -.5, .5, .5}}}};
        LinearReduction<dim, dim *(dim + 1)> R;
        for (unsigned int d = 0; d < dim; ++d)
          {
            R.add(d, 0, d, 1.);
            for (unsigned int v = 0; v < nf; ++v)
              {
                R.add(d, 1 + v, d, -1. / nf);
                for (unsigned int k = 0; k + 1 < dim; ++k)
                  R.add((1 + k) * dim + d, 1 + v, d, alpha[k][v]);
                R.add(dim * dim + d, 1 + nf + v, d, 1. / nf);
                R.add(dim * dim + d, 1 + v, d, -1. / nf);
              }
          }
        R.finish();
        return R;
      }

      /**
       * Value, gradient and Hessian of term(p) in the variables y at
       * @p values, by nested forward mode (sized at compile time, on the
       * stack) in the m reduced variables of @p R.
       */
      template <int dim, unsigned int m, typename Term>
      double
      reduced_derivatives(
        const std::array<std::array<double, dim>, IndicatorFace<dim>::n_points> &values,
        const LinearReduction<dim, m>                                             &R,
        Vector<double>                                                            &gradient,
        FullMatrix<double>                                                        &hessian,
        const Term                                                                &term)
      {
        using Inner            = Sacado::Fad::SFad<double, m>;
        using Outer            = Sacado::Fad::SFad<Inner, m>;
        constexpr unsigned int n = IndicatorFace<dim>::n_variables;
        std::array<std::array<Outer, dim>, IndicatorFace<dim>::n_points> p;
        for (unsigned int k = 0; k < IndicatorFace<dim>::n_points; ++k)
          for (unsigned int d = 0; d < dim; ++d)
            {
              const unsigned int i = k * dim + d;
              Inner              inner(values[k][d]);
              for (unsigned int a = 0; a < m; ++a)
                inner.fastAccessDx(a) = R.P[i][a];
              p[k][d] = Outer(inner);
              for (unsigned int a = 0; a < m; ++a)
                p[k][d].fastAccessDx(a) = Inner(R.P[i][a]);
            }
        const Outer result = term(p);

        gradient.reinit(n);
        hessian.reinit(n, n);
        // H_z L, then L^T (H_z L), over L's nonzeros.
        std::array<std::array<double, n>, m> HL{};
        for (unsigned int a = 0; a < m; ++a)
          {
            const double ga = result.dx(a).val();
            for (const unsigned int i : R.nonzero[a])
              gradient(i) += R.L[a][i] * ga;
            for (unsigned int b = 0; b < m; ++b)
              {
                const double h = result.dx(a).dx(b);
                if (h != 0.)
                  for (const unsigned int i : R.nonzero[b])
                    HL[a][i] += h * R.L[b][i];
              }
          }
        for (unsigned int a = 0; a < m; ++a)
          for (const unsigned int i : R.nonzero[a])
            for (unsigned int j = 0; j < n; ++j)
              hessian(i, j) += R.L[a][i] * HL[a][j];
        return result.val().val();
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
      if (shape == Shape::partition)
        return partition_term<dim, double>(gather<dim, double>(*this, x),
                                           stretch, stretches(stretch), free_end, ramp, apex_depth);
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
      if (shape == Shape::partition)
        partition_term<dim, double>(gather<dim, double>(*this, x), stretch,
                                    stretches(stretch), free_end, ramp, apex_depth, &d);
      else
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
      const auto values = gather<dim, double>(*this, x);
      if (shape == Shape::partition)
        {
          static const auto reduction = partition_reduction<dim>();
          return reduced_derivatives<dim>(values, reduction, gradient, hessian, [&](const auto &p) {
            using Number = typename std::decay_t<decltype(p[0][0])>;
            return partition_term<dim, Number>(p, stretch, stretches(stretch), free_end, ramp,
                                               apex_depth);
          });
        }
      static const auto reduction = simplex_reduction<dim>();
      return reduced_derivatives<dim>(values, reduction, gradient, hessian, [&](const auto &p) {
        using Number = typename std::decay_t<decltype(p[0][0])>;
        return face_term<dim, Number>(p, stretches(stretch), apex_depth);
      });
    }

    template <int dim>
    Tensor<1, dim>
    IndicatorFace<dim>::point_gradient(const Point<dim> &x,
                                       const double      stretch,
                                       const double      apex_depth) const
    {
      using Number      = Sacado::Fad::SFad<double, dim>;
      const auto values = gather<dim, double>(*this, x);
      std::array<std::array<Number, dim>, n_points> p;
      for (unsigned int k = 0; k < n_points; ++k)
        for (unsigned int d = 0; d < dim; ++d)
          p[k][d] = (k == 0 ? Number(dim, d, values[k][d]) : Number(values[k][d]));
      const Number result =
        shape == Shape::partition ?
          partition_term<dim, Number>(p, stretch, stretches(stretch), free_end, ramp, apex_depth) :
          face_term<dim, Number>(p, stretches(stretch), apex_depth);
      Tensor<1, dim> g;
      for (unsigned int d = 0; d < dim; ++d)
        g[d] = result.dx(d);
      return g;
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
          // The base: the plane through three face vertices, or for the
          // partition shape its own plane (through the face's centroid,
          // normal to its midlines), so that a point of a warped face is
          // inside exactly where that shape sees it below the face.
          std::array<Point<dim>, 3> base = {{face[0], face[1], face[2]}};
          if (shape == Shape::partition)
            {
              const auto [G, a1, a2] = centroid_and_midlines(face);
              base = {{Point<dim>(G), Point<dim>(G + a1), Point<dim>(G + a2)}};
            }
          std::vector<std::array<Point<dim>, 3>> sides = {
            base, {{opposite[0], opposite[1], opposite[2]}}};
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
      if (shape == Shape::partition)
        {
          // The prism's far side: the face moved by the apex's height
          // along the face's normal.
          Point<dim>     G;
          Tensor<1, dim> n;
          if constexpr (dim == 2)
            {
              G = 0.5 * (face[0] + face[1]);
              n = Tensor<1, dim>({face[0][1] - face[1][1], face[1][0] - face[0][0]});
            }
          else
            {
              const auto [centroid, a1, a2] = centroid_and_midlines(face);
              G = Point<dim>(centroid);
              n = cross_product_3d(a1, a2);
            }
          n /= n.norm();
          const Tensor<1, dim> up = (n * (apex - G)) * n;
          for (const auto &q : face)
            for (unsigned int d = 0; d < dim; ++d)
              {
                lower[d] = std::min(lower[d], q[d] + up[d]);
                upper[d] = std::max(upper[d], q[d] + up[d]);
              }
        }
      for (unsigned int d = 0; d < dim; ++d)
        {
          double largest = 0.;
          for (const double s : stretches(stretch))
            largest = std::max(largest, s);
          const double grow = 2. * largest * (face_upper[d] - face_lower[d]);
          // (the partition shape's prism is grown as a whole)
          const double whole = (shape == Shape::partition ? grow : 0.);
          lower[d] = std::min(lower[d] - whole, face_lower[d] - grow);
          upper[d] = std::max(upper[d] + whole, face_upper[d] + grow);
        }
      return BoundingBox<dim>(std::make_pair(lower, upper));
    }

    template struct IndicatorFace<2>;
    template struct IndicatorFace<3>;
  } // namespace Contact
} // namespace Signorini
