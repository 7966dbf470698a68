#include <signorini/contact/penalty.h>
#include <signorini/input_error.h>

#include <cmath>
#include <iomanip>
#include <sstream>

namespace Signorini
{
  namespace Contact
  {
    template <int dim>
    Evaluation
    PenaltyObjective<dim>::evaluate(const VectorType                &u,
                                    const AffineConstraints<double> &constraints,
                                    VectorType                      *rhs,
                                    MatrixType                      *hessian)
    {
      if (hessian && contact.needs_new_pattern(u))
        {
          AssertThrow(rebuild_pattern,
                      ExcMessage("the contact couplings changed and no "
                                 "sparsity pattern builder was given"));
          rebuild_pattern(u);
        }
      Evaluation e = energy.evaluate(u, time, constraints, rhs, hessian);
      if (!e.admissible)
        return e;
      std::unique_ptr<TimerOutput::Scope> scope;
      if (timer)
        scope = std::make_unique<TimerOutput::Scope>(*timer, "contact");
      if (!contact.admissible(u))
        {
          e.admissible = false;
          return e;
        }
      const double penalty = contact.add_penalty(u, mu, constraints, rhs, hessian);
      e.value += penalty;
      if (!std::isfinite(e.value))
        e.admissible = false;
      return e;
    }

    void
    ContinuationParameters::declare_parameters(ParameterHandler &prm)
    {
      prm.declare_entry("Initial penalty factor",
                        "1",
                        Patterns::Double(0.),
                        "c_0 in mu_0 = c_0 E / h^2 (E: the largest "
                        "small-strain Young's modulus of the bodies, h: the "
                        "smallest mesh size h_k on the contact boundary) [-]; "
                        "> 0. "
                        "With c_0 = 1 a node carrying the pressure p "
                        "penetrates by about h sqrt(p / E) in the first "
                        "stage.");
      prm.declare_entry("Penetration tolerance",
                        "1e-3",
                        Patterns::Double(0.),
                        "Stop the continuation when the largest penetration "
                        "depth <-g_k>/|grad g_k| of a contact node, divided "
                        "by the node's local mesh size h_k, is at most this "
                        "[-]; > 0.");
      prm.declare_entry("Target fraction",
                        "0.5",
                        Patterns::Double(0., 1.),
                        "The next penalty factor aims at this fraction of "
                        "the tolerance: mu_{k+1} = mu_k (ratio / (f tol))^2.");
      prm.declare_entry("Minimum growth",
                        "4",
                        Patterns::Double(1.),
                        "Smallest factor between two stages' penalties.");
      prm.declare_entry("Maximum growth",
                        "1e4",
                        Patterns::Double(1.),
                        "Largest factor between two stages' penalties (a "
                        "larger jump makes the next Newton solve start "
                        "further from its solution).");
      prm.declare_entry("Maximum stages",
                        "20",
                        Patterns::Integer(1, 200),
                        "Stages per load step; if the tolerance is still not "
                        "met the step is accepted with a warning, and "
                        "summary.json says so.");
      prm.declare_entry("Restart each load step",
                        "false",
                        Patterns::Bool(),
                        "true: every load step starts again from mu_0. "
                        "false: a load step starts from the previous step's "
                        "final penalty divided by 'Load step reduction' (at "
                        "least mu_0).");
      prm.declare_entry("Load step reduction",
                        "1e4",
                        Patterns::Double(1.),
                        "A load step starts from the previous step's final "
                        "penalty divided by this [-]; >= 1. A large value "
                        "eases Newton's first iterations; a small one keeps "
                        "the penetration small throughout, which two-body "
                        "contact needs (its penalty acts only in a thin "
                        "layer).");
    }

    void
    ContinuationParameters::parse_parameters(ParameterHandler &prm)
    {
      initial_factor        = prm.get_double("Initial penalty factor");
      penetration_tolerance = prm.get_double("Penetration tolerance");
      target_fraction       = prm.get_double("Target fraction");
      min_growth            = prm.get_double("Minimum growth");
      max_growth            = prm.get_double("Maximum growth");
      max_stages            = prm.get_integer("Maximum stages");
      restart_each_step     = prm.get_bool("Restart each load step");
      step_reduction        = prm.get_double("Load step reduction");
      if (!(initial_factor > 0.))
        throw InputError("Solver > Penalty > Initial penalty factor",
                         "must be > 0, got " + prm.get("Initial penalty factor"));
      if (!(penetration_tolerance > 0.))
        throw InputError("Solver > Penalty > Penetration tolerance",
                         "must be > 0, got " + prm.get("Penetration tolerance"));
      if (!(target_fraction > 0.))
        throw InputError("Solver > Penalty > Target fraction", "must be > 0");
      if (max_growth < min_growth)
        throw InputError("Solver > Penalty > Maximum growth",
                         "must be >= Minimum growth");
    }

    template <int dim>
    ContinuationResult
    penalty_continuation(const ContinuationParameters    &parameters,
                         const StageSolver               &solve_stage,
                         const EnergyFunctional<dim>     &energy,
                         PenaltyTerm<dim>                &contact,
                         const double                     time,
                         const double                     mu_start,
                         const AffineConstraints<double> &constraints,
                         VectorType                      &u,
                         VectorType                      &ghosted,
                         ConditionalOStream              &progress)
    {
      ContinuationResult result;
      double             mu = mu_start;
      // Stage solutions behave like u(mu) = u_inf + c mu^(-1/2) (the
      // penetration of a node with a given force falls like mu^(-1/2)):
      // from two stages, extrapolate the start of the next one.
      VectorType previous(u);
      double     previous_r = 0.;
      for (unsigned int s = 0; s < parameters.max_stages; ++s)
        {
          if (s >= 1)
            {
              // u holds stage s-1's solution, previous stage s-2's.
              const double last_r = 1. / std::sqrt(result.stages.back().mu);
              VectorType   start(u);
              if (s >= 2)
                {
                  const double factor =
                    (1. / std::sqrt(mu) - last_r) / (last_r - previous_r);
                  start.add(factor, u);
                  start.add(-factor, previous);
                  ghosted = start;
                  PenaltyObjective<dim> check(energy, contact, time, mu);
                  if (!check.evaluate(ghosted, constraints, nullptr, nullptr)
                         .admissible)
                    start = u;
                }
              previous   = u;
              previous_r = last_r;
              u          = start;
            }
          progress << "  stage " << s + 1 << ": mu = " << std::scientific
                   << std::setprecision(3) << mu << std::defaultfloat
                   << std::endl;
          result.last = solve_stage(mu, u);
          result.newton_iterations += result.last.iterations;
          ghosted = u;
          contact.add_penalty(ghosted, mu, constraints, nullptr, nullptr,
                              &result.forces);
          const auto summary = contact.measure(ghosted, result.forces);
          result.stages.push_back(
            {mu, result.last.iterations, summary.max_penetration_ratio});
          progress << "    penetration / h = " << std::scientific
                   << std::setprecision(3) << summary.max_penetration_ratio
                   << std::defaultfloat << ", " << summary.n_active
                   << " active node(s)" << std::endl;
          if (!result.last.converged)
            {
              std::ostringstream msg;
              msg << "penalty stage " << s + 1 << " (mu = " << mu
                  << "): " << result.last.reason;
              result.reason = msg.str();
              return result;
            }
          if (summary.max_penetration_ratio <= parameters.penetration_tolerance)
            {
              result.converged     = true;
              result.tolerance_met = true;
              return result;
            }
          const double predicted =
            std::pow(summary.max_penetration_ratio /
                       (parameters.target_fraction * parameters.penetration_tolerance),
                     2.);
          mu *= std::max(parameters.min_growth,
                         std::min(parameters.max_growth, predicted));
        }
      result.converged = true;
      progress << "  warning: the penetration tolerance was not met in "
               << parameters.max_stages << " penalty stages" << std::endl;
      return result;
    }

    template class PenaltyObjective<2>;
    template class PenaltyObjective<3>;
    template ContinuationResult
    penalty_continuation<2>(const ContinuationParameters &, const StageSolver &,
                            const EnergyFunctional<2> &, PenaltyTerm<2> &,
                            const double, const double,
                            const AffineConstraints<double> &, VectorType &,
                            VectorType &, ConditionalOStream &);
    template ContinuationResult
    penalty_continuation<3>(const ContinuationParameters &, const StageSolver &,
                            const EnergyFunctional<3> &, PenaltyTerm<3> &,
                            const double, const double,
                            const AffineConstraints<double> &, VectorType &,
                            VectorType &, ConditionalOStream &);
  } // namespace Contact
} // namespace Signorini
