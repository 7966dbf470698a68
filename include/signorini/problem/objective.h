#pragma once

#include <signorini/types.h>

#include <deal.II/lac/affine_constraints.h>

#include <limits>

namespace Signorini
{
  using namespace dealii;

  /**
   * What one evaluation of an objective returns besides the vectors:
   * the value and its parts, whether the state is admissible (every
   * quadrature point has J > 0 and finite values), the smallest J, and a
   * force scale sqrt(sum over cells of |f_int,K|^2 + |f_ext,K|^2) that
   * makes residual tolerances relative and unit-free.
   */
  struct Evaluation
  {
    double value         = 0.;
    double strain_energy = 0.;
    double external_work = 0.;
    double min_J         = std::numeric_limits<double>::max();
    double force_scale   = 0.;
    /**
     * The round-off of value, estimated as machine epsilon times the sum
     * over the quadrature points of the shear modulus times JxW: an
     * energy density is a difference of O(mu) terms, so its error is
     * about eps mu whatever the strain (a stiff body moved rigidly has an
     * energy of pure round-off).
     */
    double round_off     = 0.;
    bool   admissible    = true;
  };

  /**
   * Something a Newton method can minimise: value, minus gradient and
   * Hessian at a (ghosted) state, condensed with the given constraints.
   * The energy functional is one; contact penalty terms add to it.
   */
  class Objective
  {
  public:
    virtual ~Objective() = default;

    virtual Evaluation
    evaluate(const VectorType                &u,
             const AffineConstraints<double> &constraints,
             VectorType                      *rhs,
             MatrixType                      *hessian) = 0;

    /**
     * The largest step length alpha for which u + alpha d is worth
     * trying from the ghosted state @p u along the (locally owned)
     * direction @p d; the line search starts from min(1, this). Default:
     * no limit.
     */
    virtual double
    max_step(const VectorType &u, const VectorType &d)
    {
      (void)u;
      (void)d;
      return std::numeric_limits<double>::infinity();
    }

    /**
     * Move the trial state @p trial of a line search from the ghosted
     * state @p u back towards states the objective's model makes
     * plausible (a contact node that was free at @p u and would sink
     * deeper than the deepest node in contact is lifted to that depth).
     * Returns whether anything moved (collective). Default: nothing.
     */
    virtual bool
    limit_trial(const VectorType &u, VectorType &trial)
    {
      (void)u;
      (void)trial;
      return false;
    }

    /**
     * Switch the Hessians of the following evaluations to a positive
     * semidefinite approximation of the objective's non-convex parts (on)
     * or back to the exact ones (off). Returns whether the objective has
     * such an approximation; Newton uses it for a step where the exact
     * Hessian gives no descent direction, before shifting the diagonal.
     */
    virtual bool
    set_convexified(const bool on)
    {
      (void)on;
      return false;
    }
  };

} // namespace Signorini
