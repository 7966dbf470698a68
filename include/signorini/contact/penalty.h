#pragma once

#include <signorini/contact/rigid_foundation.h>
#include <signorini/energy_functional.h>
#include <signorini/newton.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace Signorini
{
  namespace Contact
  {
    /**
     * The penalised energy G_mu(U) = E(U) + mu/3 sum_k w_k <-g_k(U)>^3 of
     * formulation.md section 2, as a Newton objective (C^2 in U).
     */
    template <int dim>
    class PenaltyObjective : public Objective
    {
    public:
      PenaltyObjective(const EnergyFunctional<dim> &energy,
                       const RigidFoundation<dim>  &contact,
                       const double                 time,
                       const double                 mu)
        : energy(energy)
        , contact(contact)
        , time(time)
        , mu(mu)
      {}

      Evaluation
      evaluate(const VectorType                &u,
               const AffineConstraints<double> &constraints,
               VectorType                      *rhs,
               MatrixType                      *hessian) override;

    private:
      const EnergyFunctional<dim> &energy;
      const RigidFoundation<dim>  &contact;
      const double                 time;
      const double                 mu;
    };

    /**
     * Penalty continuation (formulation.md section 4): minimise G_mu_k
     * for mu_0 < mu_1 < ... with Newton, each stage warm-started from the
     * last, until the largest penetration over the local mesh size,
     * max_k <-g_k>/|grad g_k| / h_k, is at most the tolerance.
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
    };

    struct ContinuationResult
    {
      bool               converged     = false; // every stage converged
      bool               tolerance_met = false; // penetration below tolerance
      std::vector<Stage> stages;
      unsigned int       newton_iterations = 0;
      NewtonMinimizer::Statistics last;
      std::vector<double>         forces; // nodal forces at the end
      std::string                 reason;
    };

    /**
     * Run the continuation for one load step at @p time from @p u, the
     * first stage with @p mu_start. On return @p u holds the last
     * converged stage (or the last iterate if a stage failed).
     */
    template <int dim>
    ContinuationResult
    penalty_continuation(const ContinuationParameters    &parameters,
                         NewtonMinimizer                 &newton,
                         const EnergyFunctional<dim>     &energy,
                         const RigidFoundation<dim>      &contact,
                         const double                     time,
                         const double                     mu_start,
                         const AffineConstraints<double> &constraints,
                         VectorType                      &u,
                         VectorType                      &ghosted,
                         MatrixType                      &hessian,
                         VectorType                      &rhs,
                         ConditionalOStream              &progress);
  } // namespace Contact
} // namespace Signorini
