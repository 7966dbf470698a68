#pragma once

// The regularised Coulomb law of one contact point as an incremental
// dissipation potential (doc/friction.md, "The dissipation potential"):
// self-contained, with exact first and second derivatives, so that a
// contact model can add mu lambda f0(|s|) to the energy that a load step
// minimises. Nothing here knows a mesh, a solver or a contact model.

#include <deal.II/base/tensor.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <array>
#include <vector>

namespace Signorini
{
  using namespace dealii;

  namespace Contact
  {
    /**
     * The smoothing f0 of |s| with slip length eps (y = |s| >= 0):
     *
     *   f0(y) = y^2/eps - y^3/(3 eps^2) + eps/3   for y < eps,
     *   f0(y) = y                                 for y >= eps,
     *
     * so that f1 = f0' = 2y/eps - y^2/eps^2 below eps and 1 above, and
     * f0'' = 2/eps - 2y/eps^2 below eps and 0 above. f0, f1 and f0'' are
     * continuous at eps (f0'' vanishes from both sides); f0''' jumps
     * there (-2/eps^2 to 0). f0(|s|) is therefore C^2 in s everywhere,
     * with a Lipschitz Hessian, including at s = 0, where its Hessian
     * tends to (2/eps) I: the smoothing of incremental potential contact
     * (Li et al. 2020), chosen C^2 so that Newton's Hessian is continuous.
     */
    namespace SlipSmoothing
    {
      /// f0(y).
      double
      f0(const double y, const double eps);

      /// f1(y) = f0'(y): the traction's magnitude over mu lambda.
      double
      f1(const double y, const double eps);

      /// f1(y) / y, finite at y = 0 (2/eps there).
      double
      f1_over_y(const double y, const double eps);

      /// f1'(y) = f0''(y).
      double
      df1(const double y, const double eps);
    } // namespace SlipSmoothing

    /// A contact point's state for output: no normal force (open), a
    /// slip below the slip length (stick) or at or beyond it (slip).
    enum class FrictionStatus
    {
      open,
      stick,
      slip
    };

    /**
     * The lagged tangent basis T = [t_1 ... t_{dim-1}] of a contact point:
     * orthonormal columns orthogonal to the unit normal n. The slip of a
     * displacement increment du is s = T^T du (in R^(dim-1)).
     */
    template <int dim>
    struct TangentBasis
    {
      std::array<Tensor<1, dim>, dim - 1> t;

      /// T^T v.
      Tensor<1, dim - 1>
      project(const Tensor<1, dim> &v) const;

      /// T g (a tangential vector of R^dim from its components).
      Tensor<1, dim>
      lift(const Tensor<1, dim - 1> &g) const;

      /// T K T^T.
      Tensor<2, dim>
      lift(const Tensor<2, dim - 1> &K) const;
    };

    /**
     * The tangent basis of the normal @p normal (normalised here; throws
     * std::invalid_argument for a zero or non-finite vector).
     * 2D: t = (n_y, -n_x), so that (t, n) is right-handed and the upward
     * normal (0, 1) of the foundation gives t = (1, 0).
     * 3D: the branch-free orthonormal pair of Duff et al. ("Building an
     * orthonormal basis, revisited", JCGT 2017), with the sign of n_z
     * picked so that it stays accurate for every n, n = (0, 0, -1)
     * included; t_1 x t_2 = n, and n = (0, 0, 1) gives t_1 = (1, 0, 0),
     * t_2 = (0, 1, 0).
     */
    template <int dim>
    TangentBasis<dim>
    tangent_basis(const Tensor<1, dim> &normal);

    /**
     * The incremental dissipation potential of one contact point for
     * quasi-static Coulomb friction with a lagged normal force lambda >= 0
     * and a lagged tangent basis:
     *
     *   D(s) = mu lambda f0(|s|),   s the tangential slip increment over
     *                               the load step (SlipSmoothing),
     *
     * its gradient, the tangential traction t_T = mu lambda f1(|s|) s/|s|
     * (|t_T| = mu lambda exactly once |s| >= eps), and its Hessian
     *
     *   mu lambda [ f1/|s| I + (f1' - f1/|s|) s s^T / |s|^2 ],
     *
     * evaluated in a form that stays finite at s = 0 (where it is
     * (2 mu lambda / eps) I, the stick stiffness). D is convex: the
     * Hessian's eigenvalues are mu lambda f1' >= 0 along s and
     * mu lambda f1/|s| > 0 across it.
     *
     * lambda is a force (the nodal contact force, or a quadrature point's
     * force), so D is an energy; eps is a length (the caller turns the
     * relative 'Slip length' into one per point, FrictionParameters).
     * With mu = 0 or lambda = 0 every result is exactly zero.
     */
    template <int dim>
    class FrictionLaw
    {
    public:
      static constexpr unsigned int n_tangential = dim - 1;
      using Slip = Tensor<1, dim - 1>;

      /// Throws std::invalid_argument unless mu >= 0 and eps > 0, both
      /// finite.
      FrictionLaw(const double coefficient, const double slip_length);

      double
      coefficient() const
      {
        return mu;
      }
      double
      slip_length() const
      {
        return eps;
      }

      /// Value, gradient (the tangential traction) and Hessian in s.
      struct Response
      {
        double                       value = 0.;
        Tensor<1, dim - 1>           traction;
        Tensor<2, dim - 1>           stiffness;
      };

      /// D, dD/ds and d2D/ds2 at the slip @p s for the lagged normal
      /// force @p normal_force (>= 0: std::invalid_argument otherwise).
      Response
      evaluate(const Slip &s, const double normal_force) const;

      /// D alone.
      double
      value(const Slip &s, const double normal_force) const;

      /// Stick (|s| < eps), slip (|s| >= eps), or open (normal force 0).
      FrictionStatus
      status(const Slip &s, const double normal_force) const;

      /// The dissipated energy of the increment, mu lambda |s|: exact
      /// Coulomb, not smoothed (for the energy balance in the output).
      double
      dissipated_energy(const Slip &s, const double normal_force) const;

      /**
       * The slip s = T^T sum_j c_j du_j of a combination of points (the
       * one point of a rigid foundation: c = {1}; a body 1 point against
       * the material point of body 2 it touches: c = {1, -N_1, ..., -N_m}
       * with body 2's shape function values N_i, or {1, -1} for two
       * points).
       */
      static Slip
      slip(const TangentBasis<dim>            &basis,
           const std::vector<double>          &coefficients,
           const std::vector<Tensor<1, dim>>  &increments);

      /**
       * D of the slip of the combination above and, if given, its
       * gradient (size n dim, point j's components at j dim + d) and
       * Hessian (n dim x n dim) with respect to the increments du_j (the
       * basis and the coefficients held fixed): gradient block j =
       * c_j T t_T, Hessian block (i, j) = c_i c_j T K T^T. The vectors are
       * resized. Returns D.
       */
      double
      evaluate_points(const TangentBasis<dim>           &basis,
                      const std::vector<double>         &coefficients,
                      const std::vector<Tensor<1, dim>> &increments,
                      const double                       normal_force,
                      Vector<double>                    *gradient,
                      FullMatrix<double>                *hessian) const;

      /// One point on the rigid foundation: s = T^T du.
      double
      evaluate_rigid(const TangentBasis<dim> &basis,
                     const Tensor<1, dim>    &increment,
                     const double             normal_force,
                     Vector<double>          *gradient,
                     FullMatrix<double>      *hessian) const;

      /// Two points: s = T^T (du_1 - du_2) (gradient and Hessian in
      /// (du_1, du_2)).
      double
      evaluate_pair(const TangentBasis<dim> &basis,
                    const Tensor<1, dim>    &increment_1,
                    const Tensor<1, dim>    &increment_2,
                    const double             normal_force,
                    Vector<double>          *gradient,
                    FullMatrix<double>      *hessian) const;

    private:
      double mu;
      double eps;
    };
  } // namespace Contact
} // namespace Signorini
