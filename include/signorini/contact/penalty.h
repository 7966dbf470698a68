#pragma once

#include <signorini/contact/boundary_nodes.h>
#include <signorini/energy_functional.h>
#include <signorini/newton.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>

#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace Signorini
{
  namespace Contact
  {
    /**
     * A contact model that enters the energy as a penalty term mu P(U)
     * (C^2 in U): the rigid foundation's mu/3 sum_k w_k <-g_k>^3 or the
     * two-body indicator term mu sum_i w_i Phi(x_i). This is all the
     * penalty continuation needs to know of it.
     */
    template <int dim>
    class PenaltyTerm
    {
    public:
      virtual ~PenaltyTerm() = default;

      /**
       * Add mu P(u) and, if given, minus its gradient to @p rhs and its
       * Hessian to @p hessian (condensed with @p constraints, then
       * compressed: collective). Returns mu P summed over all ranks. If
       * @p forces is given it receives the model's nodal contact forces
       * (the record that measure() and the output read).
       */
      virtual double
      add_penalty(const VectorType                &u,
                  const double                     mu,
                  const AffineConstraints<double> &constraints,
                  VectorType                      *rhs,
                  MatrixType                      *hessian,
                  std::vector<double>             *forces = nullptr) const = 0;

      struct Measure
      {
        double       max_penetration_ratio = 0.; // penetration over h
        unsigned int n_active              = 0;
      };

      /// Largest penetration over the local mesh size, and the number of
      /// active contact nodes, of the state @p u with nodal @p forces.
      virtual Measure
      measure(const VectorType &u, const std::vector<double> &forces) const = 0;

      /**
       * Called before an evaluation with a Hessian at the ghosted @p u:
       * true if the couplings the term needs at @p u are not all in the
       * pairs the matrix's sparsity pattern was built for (collective).
       */
      virtual bool
      needs_new_pattern(const VectorType &u)
      {
        (void)u;
        return false;
      }

      /// The boundary id of Gamma_C.
      virtual types::boundary_id
      contact_boundary_id() const = 0;

      /// The nodes of the contact boundary Gamma_C (this rank's).
      virtual const BoundaryNodes<dim> &
      contact_nodes_on_boundary() const = 0;

      /// The contact pressure at each node of contact_nodes_on_boundary()
      /// for the state @p u with nodal @p forces (local).
      virtual std::vector<double>
      nodal_pressures(const VectorType &u, const std::vector<double> &forces) const = 0;

      /// Whether the state @p u is one the model can represent (collective).
      virtual bool
      admissible(const VectorType &u) const
      {
        (void)u;
        return true;
      }

      /**
       * Make add_penalty() assemble a positive semidefinite approximation
       * of the Hessian (on) or the exact one (off); returns whether the
       * model has such an approximation and uses it. Default: none.
       */
      virtual bool
      set_convexified(const bool on)
      {
        (void)on;
        return false;
      }

      /// Largest step length along the direction @p d (locally owned)
      /// from the ghosted @p u that the model allows (collective).
      virtual double
      max_step(const VectorType &u, const VectorType &d) const
      {
        (void)u;
        (void)d;
        return std::numeric_limits<double>::infinity();
      }
    };

    /**
     * The penalised energy G_mu(U) = E(U) + mu P(U) of formulation.md
     * sections 2 and 4, as a Newton objective. If the contact term asks
     * for a new sparsity pattern before a Hessian is assembled,
     * @p rebuild_pattern is called with the state first (it must
     * re-initialise the matrix that evaluate() receives).
     */
    template <int dim>
    class PenaltyObjective : public Objective
    {
    public:
      using PatternBuilder = std::function<void(const VectorType &)>;

      PenaltyObjective(const EnergyFunctional<dim> &energy,
                       PenaltyTerm<dim>            &contact,
                       const double                 time,
                       const double                 mu,
                       const PatternBuilder        &rebuild_pattern = {})
        : energy(energy)
        , contact(contact)
        , time(time)
        , mu(mu)
        , rebuild_pattern(rebuild_pattern)
      {}

      Evaluation
      evaluate(const VectorType                &u,
               const AffineConstraints<double> &constraints,
               VectorType                      *rhs,
               MatrixType                      *hessian) override;

      /// If set, the contact term's share of evaluate() is timed in its
      /// section "contact" (inside the caller's "assembly").
      TimerOutput *timer = nullptr;

      double
      max_step(const VectorType &u, const VectorType &d) override
      {
        return contact.max_step(u, d);
      }

      bool
      set_convexified(const bool on) override
      {
        return contact.set_convexified(on);
      }

    private:
      const EnergyFunctional<dim> &energy;
      PenaltyTerm<dim>            &contact;
      const double                 time;
      const double                 mu;
      PatternBuilder               rebuild_pattern;
    };

    /**
     * Penalty continuation (formulation.md section 4): minimise G_mu_k
     * for mu_0 < mu_1 < ... with Newton, each stage warm-started from the
     * last, until the largest penetration over the local mesh size (the
     * contact model's measure()) is at most the tolerance.
     *
     * Scale-free choices: mu_0 = c_0 E / h^2 (E the largest small-strain
     * Young's modulus of the bodies, h the smallest contact mesh size), for
     * which a node carrying a pressure p penetrates by about
     * h sqrt(p / (c_0 E)). Because the penetration of a node with a
     * given force falls like mu^(-1/2), the next factor is predicted from
     * the measured penetration: mu_{k+1} = mu_k (ratio / (f tol))^2 with
     * f the target fraction, bounded by the minimum and maximum growth.
     */
    struct ContinuationParameters
    {
      double       initial_factor        = 1.;
      double       penetration_tolerance = 1e-3;
      double       target_fraction       = 0.5;
      double       min_growth            = 4.;
      double       max_growth            = 1e4;
      unsigned int max_stages            = 20;
      bool         restart_each_step     = false;
      double       step_reduction        = 1e4;
      double       max_penalty_ratio     = 1e14; // cap of mu / mu_0
      unsigned int stage_iteration_target = 20;
      unsigned int max_stage_retries      = 3;

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);
    };

    struct Stage
    {
      double       mu                = 0.;
      unsigned int newton_iterations = 0;
      double       penetration_ratio = 0.;
      // false: the stage's solver failed and the stage was tried again
      // from the previous stage's solution with a smaller jump in mu.
      bool converged = true;
    };

    struct ContinuationResult
    {
      bool               converged     = false; // every stage converged
      bool               tolerance_met = false; // penetration below tolerance
      bool               capped        = false; // stopped at the largest mu
      unsigned int       retries       = 0;     // failed stages tried again
      unsigned int       linear_iterations = 0; // over all stages
      unsigned int       linear_fallbacks  = 0; // over all stages
      std::vector<Stage> stages;
      unsigned int       newton_iterations = 0;
      NewtonMinimizer::Statistics last;
      std::vector<double>         forces; // nodal forces at the end
      std::string                 reason;
    };

    /**
     * Minimises G_mu from @p u (locally owned entries, satisfying the
     * homogeneous constraints) and leaves the last accepted iterate in
     * @p u: Newton with a line search, or Ipopt as an unconstrained
     * minimiser (the poster's choice).
     */
    using StageSolver =
      std::function<NewtonMinimizer::Statistics(const double mu, VectorType &u)>;

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
                         const EnergyFunctional<dim>     &energy,
                         PenaltyTerm<dim>                &contact,
                         const double                     time,
                         const double                     mu_start,
                         const double                     mu_reference,
                         const AffineConstraints<double> &constraints,
                         VectorType                      &u,
                         VectorType                      &ghosted,
                         ConditionalOStream              &progress);
  } // namespace Contact
} // namespace Signorini
