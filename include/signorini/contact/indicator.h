#pragma once

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/point.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <array>

namespace Signorini
{
  using namespace dealii;

  namespace Contact
  {
    /**
     * The smooth indicator function of a deformable body (formulation.md
     * section 3). For every face of body 2's potential contact surface,
     * in the current configuration, build modified simplices:
     *
     * - 2D: the face [B, C] is stretched along its own line to
     *   B' = B - s (C - B), C' = C + s (C - B) (s = 'stretch', 0.12 in the
     *   poster's figure), and the apex A is the midpoint of the cell's
     *   opposite face [D, E] (or, with an apex depth theta < 1, the point
     *   theta of the way from the face's midpoint to it). One triangle
     *   (A, B', C').
     * - 3D: the quad face Q0 Q1 Q2 Q3 is split along Q0-Q2 into two
     *   triangles, each scaled about its centroid by 1 + 2s, and the apex
     *   is the centroid of the opposite face. Two tetrahedra.
     *
     * F_T(x) = Fp(M_T^-1 (x - A)), M_T = [V1 - A | ... | Vd - A], with
     * Fp(xi) = c <xi_1>^3 ... <xi_d>^3 <1 - sum xi>^3, normalised by c
     * (3^9 in 2D, 4^12 in 3D) so that its maximum is 1. Fp is C^2 and
     * positive exactly inside the simplex, so F_T vanishes on the contact
     * surface (the base's plane) and outside the body, is positive just
     * inside it, and the stretched bases of neighbouring faces overlap, so
     * the sum over faces Phi = sum_T F_T has no zero line at shared
     * vertices.
     *
     * A second shape, 'partition' (not in the poster), is built so that
     * Phi is the same everywhere along a flat surface of equal faces, as
     * the contact patch test needs (doc/two_bodies.md): over each face a
     * prism normal to it (2D: a strip), with affine coordinates t along
     * the face (2D: t in [0, 1] from B to C; 3D: (t1, t2) in [0, 1]^2 in
     * the frame of the quad's midlines) and the depth d below the face,
     *
     *   F(x) = g(d / H) W(t),  g(eta) = 64 <eta>^3 <1 - eta>^3,
     *
     * H the apex's height over the face. W is a product of one C^2
     * smoothstep ramp per face end: at an end shared with a neighbour it
     * rises over [-s, s] (s from 'ramp' where set, else the common
     * stretch), so that the ramps of the two faces sum to 1; at
     * a free end (free_end) it rises over [-s_end, 0], so that Phi keeps
     * its full strength up to the end. F is C^2, vanishes outside the
     * body and on the surface, and the weights of the faces around a
     * point sum to 1 wherever the faces are flat and equal.
     *
     * The variables of one face term are the coordinates of the point x
     * and of the cell's vertices that define the simplices: x, the face
     * vertices, the opposite face's vertices (2D: 5 points, 10 variables;
     * 3D: 9 points, 27 variables), in this order.
     */
    /// Which indicator a face term is: the poster's simplices or the
    /// partition of unity over prisms (IndicatorFace).
    enum class IndicatorShape
    {
      simplex,
      partition
    };

    template <int dim>
    struct IndicatorFace
    {
      static constexpr std::array<double, (dim == 2 ? 2 : 4)>
      make_negative()
      {
        std::array<double, (dim == 2 ? 2 : 4)> a{};
        for (auto &x : a)
          x = -1.;
        return a;
      }

      static constexpr unsigned int n_face_vertices = (dim == 2 ? 2 : 4);
      static constexpr unsigned int n_points  = 1 + 2 * n_face_vertices;
      static constexpr unsigned int n_variables = dim * n_points;

      /// Face vertices in order (2D: B, C; 3D: cyclic Q0..Q3) and the
      /// opposite face's vertices, vertex i opposite face vertex i.
      std::array<Point<dim>, n_face_vertices> face;
      std::array<Point<dim>, n_face_vertices> opposite;

      /// Per face vertex: if >= 0, the stretch used at this vertex instead
      /// of the common one (for the free ends of a contact surface, e.g.
      /// on a symmetry plane, where no neighbouring face overlaps).
      std::array<double, n_face_vertices> end_stretch = make_negative();

      using Shape = IndicatorShape;
      Shape shape = Shape::simplex;

      /// For the partition shape: whether end v is a free end of the
      /// target surface (2D: vertex v; 3D: the edge from vertex v to
      /// vertex v + 1).
      std::array<bool, n_face_vertices> free_end{};

      /// For the partition shape: per end, if > 0, the half-width of the
      /// ramp at a shared end as a fraction of this face (instead of the
      /// common stretch): s times the smaller neighbour's size over this
      /// face's, so that the ramps of unequal faces still sum to 1.
      std::array<double, n_face_vertices> ramp{};

      /// Sum of the face's simplex terms F_T at x. The apex lies the
      /// fraction @p apex_depth of the way from the face's centroid to the
      /// opposite face's centroid (1: on the opposite face).
      double
      value(const Point<dim> &x,
            const double      stretch,
            const double      apex_depth = 1.) const;

      /**
       * Penetration depth of x: its smallest distance to the base plane
       * of a simplex that contains it (where the simplex's term is > 0),
       * or -1 if no simplex of the face contains x.
       */
      double
      depth(const Point<dim> &x,
            const double      stretch,
            const double      apex_depth = 1.) const;

      /**
       * Value, gradient and Hessian with respect to the n_variables
       * variables (x first, then face, then opposite vertices), by
       * forward-mode automatic differentiation (nested Sacado SFad, sized at
       * compile time: no heap allocation) in the few linear combinations
       * of the variables that the term depends on (2D 6, 3D 12 or 15).
       */
      double
      derivatives(const Point<dim>  &x,
                  const double        stretch,
                  Vector<double>     &gradient,
                  FullMatrix<double> &hessian,
                  const double        apex_depth = 1.) const;

      /// The gradient with respect to the point x alone (the first dim
      /// entries of derivatives()'s gradient, at a fraction of the cost).
      Tensor<1, dim>
      point_gradient(const Point<dim> &x,
                     const double      stretch,
                     const double      apex_depth = 1.) const;

      /**
       * Whether x lies strictly inside the cell spanned by the face and
       * the opposite face (sides taken as the planes through three of
       * their vertices: exact in 2D, for nearly flat faces in 3D).
       */
      bool
      in_cell(const Point<dim> &x) const;

      /// The stretch at each face vertex.
      std::array<double, n_face_vertices>
      stretches(const double stretch) const;

      /// A box containing the cell and every point where the face's
      /// terms are > 0.
      BoundingBox<dim>
      bounding_box(const double stretch, const double apex_depth = 1.) const;
    };
  } // namespace Contact
} // namespace Signorini
