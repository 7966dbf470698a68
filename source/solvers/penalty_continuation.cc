#include <signorini/input_error.h>
#include <signorini/solvers/penalty_continuation.h>

#include <cmath>
#include <iomanip>
#include <sstream>

namespace Signorini
{
  void
  ContinuationParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Initial penalty factor",
                      "1",
                      Patterns::Double(0.),
                      "c_0 in mu_0 = c_0 E / h^2 (rigid foundation) or "
                      "mu_0 = c_0 E h (two bodies; 2D and 3D) (E: the "
                      "largest small-strain Young's modulus of the bodies, "
                      "h: the smallest mesh size h_k on the contact "
                      "boundary, for two bodies the smallest target face) "
                      "[-]; > 0. "
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
                      "1e3",
                      Patterns::Double(1.),
                      "Largest factor between two stages' penalties (a "
                      "larger jump makes the next Newton solve start "
                      "further from its solution). prm/default.prm with "
                      "the other defaults: 25 Newton iterations with 1e3, "
                      "27 with 1e2, 25 with 1e4 (doc/performance.md).");
    prm.declare_entry("Maximum stages",
                      "20",
                      Patterns::Integer(1, 200),
                      "Stages per load step; if the tolerance is still not "
                      "met the step is accepted with a warning, and "
                      "summary.json says so.");
    prm.declare_entry("Maximum penalty ratio",
                      "1e14",
                      Patterns::Double(1.),
                      "Largest mu / mu_0 [-]; >= 1. Beyond it the penalty "
                      "Hessian drowns the elastic one in round-off. If "
                      "the penetration tolerance is not met at this mu "
                      "the step is accepted with a warning, and "
                      "summary.json says so (solver status of the step, "
                      "'penetration tolerance met' false).");
    prm.declare_entry("Stage iteration target",
                      "20",
                      Patterns::Integer(1),
                      "A stage that needs more solver iterations than "
                      "this is hard: the logarithm of the next stage's "
                      "largest jump in mu shrinks in proportion (target "
                      "/ iterations). A stage that needs at most half "
                      "lets the largest jump grow back (squared), up to "
                      "'Maximum growth'.");
    prm.declare_entry("Maximum stage retries",
                      "3",
                      Patterns::Integer(0, 20),
                      "A stage (after the first of a load step) whose "
                      "solver fails is tried again from the previous "
                      "stage's solution with the square root of its "
                      "jump in mu, at most this many times per load step; "
                      "then the load step fails (and is cut).");
    prm.declare_entry("Stage tolerance",
                      "1e-6",
                      Patterns::Double(0.),
                      "Relative residual tolerance (|gradient| over the "
                      "force scale, as Newton > Residual tolerance) at "
                      "which a stage stops while it may not be the last; "
                      "once a stage meets the penetration tolerance it is "
                      "finished to the Newton tolerance. An intermediate "
                      "stage's solution only starts the next one, so "
                      "solving it to round-off is wasted. 0: every stage "
                      "to the Newton tolerance.");
    prm.declare_entry("Stage predictor",
                      "tangent",
                      Patterns::Selection("tangent|extrapolation|none"),
                      "How a stage after the first starts. tangent: from "
                      "the last stage's solution moved along du/dmu (one "
                      "linear solve with the Hessian there), to first "
                      "order in mu^(-1/2), in which a node's penetration "
                      "is linear. extrapolation: from the last two "
                      "stages' solutions, linearly in mu^(-1/2) (no "
                      "solve; the second stage starts from the first's "
                      "solution). none: from the last stage's solution. "
                      "A predicted start that is inadmissible or has a "
                      "larger G_mu than the last solution is not used.");
    prm.declare_entry("Restart each load step",
                      "false",
                      Patterns::Bool(),
                      "true: every load step starts again from mu_0. "
                      "false: a load step starts from the previous step's "
                      "final penalty divided by 'Load step reduction' (at "
                      "least mu_0).");
    prm.declare_entry("Load step reduction",
                      "1",
                      Patterns::Double(1.),
                      "A load step starts from the previous step's final "
                      "penalty divided by this [-]; >= 1. A large value "
                      "eases Newton's first iterations; a small one keeps "
                      "the penetration small throughout, which two-body "
                      "contact needs (its penalty acts only in a thin "
                      "layer). On a rigid foundation, whose nodes coming "
                      "into contact Newton's line search lifts (Newton > "
                      "Limit trials), 1 took the fewest iterations "
                      "(prm/default.prm: 25 against 28 with 10); the "
                      "two-body scenes in prm/ set 10.");
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
    max_penalty_ratio     = prm.get_double("Maximum penalty ratio");
    stage_iteration_target = prm.get_integer("Stage iteration target");
    max_stage_retries      = prm.get_integer("Maximum stage retries");
    stage_tolerance        = prm.get_double("Stage tolerance");
    {
      const std::string predictor = prm.get("Stage predictor");
      stage_predictor = predictor == "tangent" ?
                          StagePredictor::tangent :
                          predictor == "extrapolation" ?
                          StagePredictor::extrapolation :
                          StagePredictor::none;
    }
    if (!(max_penalty_ratio >= 1.) || !std::isfinite(max_penalty_ratio))
      throw InputError("Solver > Penalty > Maximum penalty ratio",
                       "must be a finite number >= 1, got " +
                         prm.get("Maximum penalty ratio"));
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

  namespace
  {
    /// The largest jump in mu allowed after a converged stage reached by
    /// a jump @p jump in @p iterations Newton iterations: smaller if the
    /// stage took more than the target, larger if it took at most half.
    double
    next_max_jump(const ContinuationParameters &parameters,
                  const double                  max_jump,
                  const double                  jump,
                  const double                  iterations)
    {
      const double target = parameters.stage_iteration_target;
      if (iterations > target)
        return std::min(max_jump,
                        std::max(std::min(parameters.min_growth, max_jump),
                                 std::pow(jump, target / iterations)));
      if (2. * iterations <= target)
        return std::min(parameters.max_growth, max_jump * max_jump);
      return max_jump;
    }

    /// The next stage's penalty: the growth that the penetration ratio
    /// predicts for the target (penetration falls like mu^(-1/2)), within
    /// [Minimum growth, max_jump] and below the cap. After a failed stage
    /// max_jump may lie below Minimum growth: the failure wins.
    double
    next_penalty(const ContinuationParameters &parameters,
                 const double                  mu,
                 const double                  mu_cap,
                 const double                  max_jump,
                 const double                  penetration_ratio)
    {
      const double predicted =
        std::pow(penetration_ratio /
                   (parameters.target_fraction * parameters.penetration_tolerance),
                 2.);
      return std::min(mu_cap,
                      mu * std::max(std::min(parameters.min_growth, max_jump),
                                    std::min(max_jump, predicted)));
    }

    /// Why the continuation stopped at the failed stage at @p mu.
    std::string
    stage_failure(const ContinuationResult &result, const double mu)
    {
      std::ostringstream msg;
      msg << "penalty stage " << result.stages.size() << " (mu = " << mu
          << "): " << result.last.reason;
      if (result.retries > 0)
        msg << " (after " << result.retries
            << " retries with smaller jumps in mu)";
      return msg.str();
    }
  } // namespace

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
                       ConditionalOStream              &progress)
  {
    ContinuationResult result;
    const double       mu_cap = parameters.max_penalty_ratio * mu_reference;
    double             mu     = std::min(mu_start, mu_cap);
    double             max_jump = parameters.max_growth;
    // The solutions of the last two converged stages: stage solutions
    // behave like u(mu) = u_inf + c mu^(-1/2) (the penetration of a node
    // with a given force falls like mu^(-1/2)), so two of them
    // extrapolate the start of the next stage.
    VectorType   last(u), before_last(u);
    double       last_mu = 0., last_r = 0., before_last_r = 0.;
    unsigned int n_converged = 0;
    // The tangent du/dmu at the last converged stage (kept for a retry
    // from the same stage).
    VectorType tangent;
    double     tangent_mu = 0.;
    using Predictor       = ContinuationParameters::StagePredictor;
    // Moves u (the last stage's solution) to a predicted start for the
    // stage at mu, if that start is admissible and lowers G_mu.
    const auto predict_stage = [&](VectorType &u, const double mu) {
      VectorType start;
      if (parameters.stage_predictor == Predictor::tangent && stage_tangent)
        {
          if (tangent_mu != last_mu)
            {
              tangent = last;
              if (!stage_tangent(last_mu, tangent))
                return;
              tangent_mu = last_mu;
            }
          // First order in r = mu^(-1/2): du = du/dmu dmu/dr (r - r_k)
          // = 2 mu_k (1 - sqrt(mu_k / mu)) du/dmu.
          start = last;
          start.add(2. * last_mu * (1. - std::sqrt(last_mu / mu)), tangent);
        }
      else if (parameters.stage_predictor != Predictor::none &&
               n_converged >= 2)
        {
          const double factor =
            (1. / std::sqrt(mu) - last_r) / (last_r - before_last_r);
          start = last;
          start.add(factor, last);
          start.add(-factor, before_last);
        }
      else
        return;
      Contact::PenaltyObjective<dim> check(energy, contact, time, mu);
      ghosted                = start;
      const Evaluation trial = check.evaluate(ghosted, constraints, nullptr, nullptr);
      if (!trial.admissible)
        return;
      ghosted                = u;
      const Evaluation here  = check.evaluate(ghosted, constraints, nullptr, nullptr);
      if (trial.value < here.value)
        {
          u = start;
          progress << "    start predicted ("
                   << (parameters.stage_predictor == Predictor::tangent ?
                         "tangent" :
                         "extrapolation")
                   << ")" << std::endl;
        }
    };
    // Solve the stage at mu from u, adding its solver counts to the
    // result's.
    const auto run_stage = [&](const double loose_tolerance) {
      result.last = solve_stage(mu, u, loose_tolerance);
      result.iterations += result.last.iterations;
      result.linear_iterations += result.last.linear_iterations;
      result.linear_solves += result.last.linear_solves;
      result.linear_fallbacks += result.last.linear_fallbacks;
    };
    // The penalty forces at u (into result.forces) and their measure.
    const auto measure_stage = [&]() {
      ghosted = u;
      contact.add_penalty(ghosted, mu, constraints, nullptr, nullptr,
                          &result.forces);
      return contact.measure(ghosted, result.forces);
    };
    while (n_converged < parameters.max_stages)
      {
        if (n_converged >= 1)
          {
            u = last;
            predict_stage(u, mu);
          }
        progress << "  stage " << result.stages.size() + 1
                 << ": mu = " << std::scientific << std::setprecision(3)
                 << mu << std::defaultfloat << std::endl;
        run_stage(parameters.stage_tolerance);
        if (!result.last.converged)
          {
            result.stages.push_back({mu, result.last.iterations, 0., false});
            const double jump = n_converged >= 1 ? mu / last_mu : 1.;
            if (n_converged >= 1 &&
                result.retries < parameters.max_stage_retries &&
                jump > 1. + 1e-3)
              {
                // Go back to the last converged stage, half the jump in
                // log mu, and limit the jumps that follow to it.
                ++result.retries;
                max_jump = std::sqrt(jump);
                mu       = last_mu * max_jump;
                progress << "    stage failed (" << result.last.reason
                         << "); again with a jump of " << std::setprecision(3)
                         << max_jump << " in mu" << std::endl;
                continue;
              }
            result.reason = stage_failure(result, mu);
            return result;
          }
        auto summary = measure_stage();
        // The last stage (tolerance met, or the cap reached): finish it to
        // the Newton tolerance from where the loose solve stopped.
        if (parameters.stage_tolerance > 0. &&
            (summary.max_penetration_ratio <= parameters.penetration_tolerance ||
             mu >= mu_cap * (1. - 1e-12)))
          {
            const unsigned int loose_iterations = result.last.iterations;
            run_stage(0.);
            result.last.iterations += loose_iterations;
            if (!result.last.converged)
              {
                result.stages.push_back({mu, result.last.iterations, 0., false});
                result.reason = "penalty stage " +
                                std::to_string(result.stages.size()) +
                                ", finished to the Newton tolerance: " +
                                result.last.reason;
                return result;
              }
            summary = measure_stage();
          }
        result.stages.push_back(
          {mu, result.last.iterations, summary.max_penetration_ratio, true});
        progress << "    penetration / h = " << std::scientific
                 << std::setprecision(3) << summary.max_penetration_ratio
                 << std::defaultfloat << ", " << summary.n_active
                 << " active node(s)" << std::endl;
        // How hard was this stage? (The first stage of a load step also
        // carries the load increment: it does not say how hard a jump in
        // mu is.)
        if (n_converged >= 1)
          max_jump = next_max_jump(parameters, max_jump, mu / last_mu,
                                   result.last.iterations);
        before_last   = last;
        before_last_r = last_r;
        last          = u;
        last_mu       = mu;
        last_r        = 1. / std::sqrt(mu);
        ++n_converged;
        if (summary.max_penetration_ratio <= parameters.penetration_tolerance)
          {
            result.converged     = true;
            result.tolerance_met = true;
            return result;
          }
        if (mu >= mu_cap * (1. - 1e-12))
          {
            result.converged = true;
            result.capped    = true;
            progress << "  warning: the penalty reached its cap mu = "
                     << std::scientific << std::setprecision(3) << mu
                     << " (Maximum penalty ratio " << parameters.max_penalty_ratio
                     << " x mu_0) with penetration / h = "
                     << summary.max_penetration_ratio << " > "
                     << parameters.penetration_tolerance << std::defaultfloat
                     << "; the step is accepted" << std::endl;
            return result;
          }
        mu = next_penalty(parameters, mu, mu_cap, max_jump,
                          summary.max_penetration_ratio);
      }
    result.converged = true;
    progress << "  warning: the penetration tolerance was not met in "
             << parameters.max_stages << " penalty stages" << std::endl;
    return result;
  }

  template ContinuationResult
  penalty_continuation<2>(const ContinuationParameters &, const StageSolver &,
                          const StageTangent &,
                          const EnergyFunctional<2> &, Contact::PenaltyTerm<2> &,
                          const double, const double, const double,
                          const AffineConstraints<double> &, VectorType &,
                          VectorType &, ConditionalOStream &);
  template ContinuationResult
  penalty_continuation<3>(const ContinuationParameters &, const StageSolver &,
                          const StageTangent &,
                          const EnergyFunctional<3> &, Contact::PenaltyTerm<3> &,
                          const double, const double, const double,
                          const AffineConstraints<double> &, VectorType &,
                          VectorType &, ConditionalOStream &);
} // namespace Signorini
