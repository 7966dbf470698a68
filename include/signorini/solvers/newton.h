#pragma once

#include <signorini/solvers/newton_parameters.h>

#include <signorini/solvers/linear_solver.h>
#include <signorini/problem/objective.h>
#include <signorini/types.h>

#include <algorithm>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>
#include <deal.II/lac/affine_constraints.h>

#include <limits>
#include <string>

namespace Signorini
{
  using namespace dealii;

  /**
   * Newton's method for min E(u), with
   * - a backtracking Armijo line search on E that rejects inadmissible
   *   states (J <= 0 or non-finite values at a quadrature point);
   * - descent directions only: if the Newton direction d does not satisfy
   *   g.d < -eps |g| |d| (indefinite Hessian) or the linear solve fails,
   *   the Hessian is shifted, H + tau diag(|H_ii|), with tau = 'Initial
   *   shift' multiplied by 10 per retry, and as a last resort the scaled
   *   steepest descent direction is used;
   * - convergence when |minus gradient|_2 <= max(rtol * force scale,
   *   atol) and, after the first iteration, either the last energy
   *   decrease |dE| <= etol * (|strain energy| + |external work|) or
   *   |minus gradient|_2 <= atol;
   * - a first trial step no longer than 'Maximum increment' times the
   *   scene size in any DoF (a body held only by contact has a singular
   *   Hessian until it touches: its Newton step is huge).
   */
  class NewtonMinimizer
  {
  public:
    using Parameters = NewtonParameters;


    struct Statistics
    {
      bool         converged            = false;
      unsigned int iterations           = 0;
      unsigned int backtracks           = 0;
      unsigned int regularized_steps    = 0;
      unsigned int convexified_steps    = 0; // projected contact Hessian used
      unsigned int linear_iterations    = 0;
      unsigned int linear_solves        = 0; // solves tried, failed ones too
      unsigned int linear_fallbacks     = 0;
      unsigned int linear_failures      = 0; // solves that gave no direction
      std::string  linear_message;            // why the last one failed
      double       residual             = 0.;
      double       force_scale          = 0.;
      Evaluation   evaluation;
      std::string  reason;

      /// Count one linear solve that returned @p ok with @p info (and,
      /// if it failed, @p message); returns @p ok.
      bool
      count_linear_solve(const bool                ok,
                         const LinearSolver::Info &info,
                         const std::string        &message)
      {
        linear_iterations += info.iterations;
        ++linear_solves;
        linear_fallbacks += info.used_fallback;
        if (!ok)
          {
            ++linear_failures;
            linear_message = message;
          }
        return ok;
      }
    };

    NewtonMinimizer(const Parameters   &parameters,
                    const LinearSolver &linear_solver,
                    ConditionalOStream &progress,
                    TimerOutput        &timer);

    /**
     * Minimise from @p u (locally owned entries; must satisfy
     * @p constraints). @p ghosted is a ghosted work vector of the same
     * layout; @p hessian and @p rhs are work objects with the sparsity
     * and layout of the problem. On return @p u holds the last accepted
     * iterate, whether or not it converged.
     */
    Statistics
    minimize(Objective                       &objective,
             const AffineConstraints<double> &constraints,
             VectorType                      &u,
             VectorType                      &ghosted,
             MatrixType                      &hessian,
             VectorType                      &rhs);

    /**
     * The scene's size (diameter of its bounding box): no trial step
     * moves a DoF by more than 'Maximum increment' times this.
     */
    void
    set_length_scale(const double length)
    {
      length_scale = length;
    }

    /**
     * Take at least one Newton step even from a start that already meets
     * the tolerance: the re-solves of the friction loop, whose normal
     * forces (stiff functions of the state) the outer loop compares to
     * 1e-6, start from a state that met the tolerance for the last lag;
     * one more quadratic step resolves them far below it.
     */
    void
    iterate_at_least_once()
    {
      at_least_once = true;
    }

    /**
     * Stop at the relative residual tolerance @p tolerance and at an
     * energy decrease of @p tolerance times the energy scale, where these
     * are looser than the parameter file's (a penalty stage that only
     * starts the next one).
     */
    void
    loosen(const double tolerance)
    {
      parameters.residual_tolerance =
        std::max(parameters.residual_tolerance, tolerance);
      parameters.energy_tolerance = std::max(parameters.energy_tolerance, tolerance);
    }

    /**
     * A tangent predictor for changed Dirichlet data: one linear step
     * d from H d = -g with the inhomogeneous @p constraints (which move
     * the Dirichlet values to their new targets). Taken in full if the
     * new state is admissible; else its free part is halved until it is
     * (down to the Dirichlet increment alone: d_D + s (d - d_D), s = 1,
     * 1/2, ..., 1/64, 0), so that a linear step that overshoots (through
     * the contact layer, or to J <= 0) does not cost a load step cut.
     * Returns false (u unchanged) if even the Dirichlet increment alone
     * is inadmissible. A step with some of its free part is kept only if
     * its energy is below that of the Dirichlet increment alone: from a
     * start that is already close (TransportPredictor) the exact Hessian
     * can be indefinite and the step climb, and a step whose linear model
     * misses a contact that starts in it (the first touch: no contact
     * term in H) pushes one body into the other.
     */
    bool
    predictor(Objective                       &objective,
              const AffineConstraints<double> &constraints,
              VectorType                      &u,
              VectorType                      &ghosted,
              MatrixType                      &hessian,
              VectorType                      &rhs,
              std::string                     &reason);

  private:
    bool
    descent_direction(Objective                       &objective,
                      const VectorType                &u,
                      VectorType                      &ghosted,
                      const AffineConstraints<double> &constraints,
                      MatrixType                      &hessian,
                      const VectorType                &rhs,
                      VectorType                      &direction,
                      double                           forcing,
                      Statistics                      &statistics);

    Parameters          parameters;
    double              length_scale  = 0.;
    bool                at_least_once = false;
    const LinearSolver &linear_solver;
    ConditionalOStream &progress;
    TimerOutput        &timer;
  };
} // namespace Signorini
