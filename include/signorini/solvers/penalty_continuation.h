#pragma once

#include <signorini/solvers/continuation_parameters.h>

#include <signorini/contact/penalty.h>
#include <signorini/output/penalty_stage.h>
#include <signorini/problem/energy_functional.h>
#include <signorini/solvers/newton.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>

#include <functional>
#include <string>
#include <vector>

namespace Signorini
{

  struct ContinuationResult
  {
    bool               converged     = false; // every stage converged
    bool               tolerance_met = false; // penetration below tolerance
    bool               capped        = false; // stopped at the largest mu
    unsigned int       retries       = 0;     // failed stages tried again
    unsigned int       linear_iterations = 0; // over all stages
    unsigned int       linear_solves     = 0; // over all stages
    unsigned int       linear_fallbacks  = 0; // over all stages
    std::vector<PenaltyStage> stages;
    unsigned int       iterations        = 0; // over all stages
    NewtonMinimizer::Statistics last;
    std::vector<double>         forces; // nodal forces at the end
    std::string                 reason;
  };

  /**
   * Minimises G_mu from @p u (locally owned entries, satisfying the
   * homogeneous constraints) and leaves the last accepted iterate in
   * @p u: Newton with a line search, or Ipopt as an unconstrained
   * minimiser (the poster's choice). A positive @p loose_tolerance is
   * the relative residual and energy-decrease tolerance to stop at
   * instead of the Newton ones, where larger (a stage that may not be
   * the last; NewtonMinimizer::loosen()). Ipopt stages ignore it.
   */
  using StageSolver = std::function<NewtonMinimizer::Statistics(
    const double mu, VectorType &u, const double loose_tolerance)>;

  /**
   * The tangent of the stage solutions: replaces @p u (the converged
   * minimiser of G_mu, locally owned) by du/dmu = -H^{-1} grad P, H the
   * Hessian of G_mu at @p u. Returns false if the linear solve fails
   * (@p u is then undefined). Empty: no tangent predictor.
   */
  using StageTangent = std::function<bool(const double mu, VectorType &u)>;

  /**
   * Run the continuation for one load step at @p time from @p u, the
   * first stage with @p mu_start, each stage solved by @p solve_stage.
   * @p mu_reference is the scene's mu_0: no stage goes beyond
   * 'Maximum penalty ratio' times it.
   *
   * The jump from one stage to the next is predicted from the measured
   * penetration and clamped to [Minimum growth, g_max]. g_max starts at
   * 'Maximum growth' and follows how hard the stages are: a stage that
   * needs more than 'Stage iteration target' iterations shrinks the
   * logarithm of the next jump in proportion (g_max = g^(target / n)); an
   * easy one (at most half the target) lets it grow back (g_max^2). A
   * stage whose solver fails is tried again from the previous stage's
   * solution with the square root of the jump, up to 'Maximum stage
   * retries' times; only a failed first stage (nothing to go back to) or
   * too many retries fail the load step.
   *
   * On return @p u holds the last converged stage (or the last iterate
   * if a stage failed). @p ghosted is a ghosted work vector.
   */
  template <int dim>
  ContinuationResult
  penalty_continuation(const ContinuationParameters    &parameters,
                       const StageSolver               &solve_stage,
                       const StageTangent              &stage_tangent,
                       const EnergyFunctional<dim>     &energy,
                       Contact::PenaltyTerm<dim>       &contact,
                       const double                     time,
                       const double                     mu_start,
                       const double                     mu_reference,
                       const AffineConstraints<double> &constraints,
                       VectorType                      &u,
                       VectorType                      &ghosted,
                       ConditionalOStream              &progress);
} // namespace Signorini
