#include <signorini/interruption.h>
#include <signorini/solvers/newton.h>

#include <iomanip>
#include <sstream>

namespace Signorini
{
  void
  NewtonMinimizer::Parameters::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Maximum iterations",
                      "50",
                      Patterns::Integer(1),
                      "Newton iterations per load step before the step is "
                      "cut.");
    prm.declare_entry("Residual tolerance",
                      "1e-10",
                      Patterns::Double(0.),
                      "Converged when |gradient|_2 <= this * force scale, "
                      "the force scale being sqrt(sum over cells of "
                      "|f_int,K|^2 + |f_ext,K|^2) (unit free).");
    prm.declare_entry("Absolute tolerance",
                      "1e-14",
                      Patterns::Double(0.),
                      "Converged also when |gradient|_2 <= this [force] "
                      "(for unloaded states).");
    prm.declare_entry("Energy tolerance",
                      "1e-12",
                      Patterns::Double(0.),
                      "And when the last energy decrease is <= this * "
                      "(|strain energy| + |external work|).");
    prm.declare_entry("Armijo parameter",
                      "1e-4",
                      Patterns::Double(0., 0.5),
                      "Sufficient decrease: E(u + a d) <= E(u) + c1 a g.d.");
    prm.declare_entry("Backtracking factor",
                      "0.5",
                      Patterns::Double(0.05, 0.95),
                      "Step length reduction per rejected trial.");
    prm.declare_entry("Maximum backtracks",
                      "30",
                      Patterns::Integer(1, 200),
                      "Trials per line search before the step is cut.");
    prm.declare_entry("Initial shift",
                      "1e-6",
                      Patterns::Double(0.),
                      "First relative diagonal shift tau of an indefinite "
                      "Hessian (H + tau diag|H|), multiplied by 10 per "
                      "retry.");
    prm.declare_entry("Maximum shifts",
                      "8",
                      Patterns::Integer(0, 30),
                      "Shift retries before steepest descent is used.");
    prm.declare_entry("Inertia test",
                      "true",
                      Patterns::Bool(),
                      "With a direct solver that reports the inertia of "
                      "its LDL^T factorisation (PETSc_Mumps), a Hessian "
                      "with negative pivots gets the objective's "
                      "convexified contact Hessian (Two bodies > Hessian) "
                      "even when its own Newton direction passes the "
                      "descent test; if that direction does not descend, "
                      "the exact one is kept. Without contact (nothing to "
                      "convexify) the exact direction is kept. The "
                      "ironing scene's sliding steps took 40% fewer "
                      "iterations and the same path on 1 and 2 ranks. "
                      "Solvers without the inertia (CG, Amesos) use the "
                      "descent test alone.");
    prm.declare_entry("Limit trials",
                      "true",
                      Patterns::Bool(),
                      "Each line-search trial is first offered to the contact "
                      "model, which may move it back (the rigid foundation "
                      "lifts a node that was free and would sink deeper than "
                      "the deepest node in contact to that depth); the "
                      "limited trial is accepted on the Armijo test with the "
                      "slope of the move it makes, otherwise the plain trial "
                      "is tested. A load step that widens the contact zone "
                      "then needs no short steps for the nodes that come "
                      "into contact (doc/performance.md). Two-body contact "
                      "limits nothing.");
    prm.declare_entry("Maximum increment",
                      "0.1",
                      Patterns::Double(0.),
                      "The line search starts from a step that moves no DoF "
                      "by more than this fraction of the scene's size "
                      "(bounding-box diameter); 0: no limit.");
    prm.declare_entry("Increment tolerance",
                      "1e-14",
                      Patterns::Double(0.),
                      "Converged also when the Newton correction moves no "
                      "DoF by more than this fraction of the scene's size: "
                      "the gradient is then at its round-off level (a state "
                      "that is already in equilibrium, or a large penalty "
                      "whose gradient cannot get smaller). Keep it near "
                      "round-off (1e-14 is 50 machine epsilons): with a "
                      "steep penalty a displacement of 1e-12 of the scene "
                      "can still change the contact force by 1e-5; 0: "
                      "off.");
  }

  void
  NewtonMinimizer::Parameters::parse_parameters(ParameterHandler &prm)
  {
    max_iterations      = prm.get_integer("Maximum iterations");
    increment_tolerance = prm.get_double("Increment tolerance");
    residual_tolerance = prm.get_double("Residual tolerance");
    absolute_tolerance = prm.get_double("Absolute tolerance");
    energy_tolerance   = prm.get_double("Energy tolerance");
    armijo_c1          = prm.get_double("Armijo parameter");
    backtrack_factor   = prm.get_double("Backtracking factor");
    max_backtracks     = prm.get_integer("Maximum backtracks");
    initial_shift      = prm.get_double("Initial shift");
    max_shifts         = prm.get_integer("Maximum shifts");
    inertia_test       = prm.get_bool("Inertia test");
    limit_trials       = prm.get_bool("Limit trials");
    max_increment      = prm.get_double("Maximum increment");
  }

  NewtonMinimizer::NewtonMinimizer(const Parameters   &parameters,
                                   const LinearSolver &linear_solver,
                                   ConditionalOStream &progress,
                                   TimerOutput        &timer)
    : parameters(parameters)
    , linear_solver(linear_solver)
    , progress(progress)
    , timer(timer)
  {}

  bool
  NewtonMinimizer::descent_direction(Objective                       &objective,
                                     const VectorType                &u,
                                     VectorType                      &ghosted,
                                     const AffineConstraints<double> &constraints,
                                     MatrixType                      &hessian,
                                     const VectorType                &rhs,
                                     VectorType                      &d,
                                     const double                     forcing,
                                     Statistics                      &statistics)
  {
    TimerOutput::Scope scope(timer, "linear solve");
    const double       rhs_norm = rhs.l2_norm();

    // Is d a descent direction for E? (g = -rhs, so g.d = -rhs.d.)
    auto is_descent = [&](const VectorType &dir) {
      const double slope = rhs * dir;
      return std::isfinite(slope) && slope > 1e-12 * rhs_norm * dir.l2_norm();
    };

    LinearSolver::Info info;
    std::string        message;
    bool               indefinite = false;
    // A direction that moves a DoF by more than 1000 scene sizes comes
    // from a (nearly) singular Hessian, e.g. a body held only by contact
    // before it touches (an iterative solve stops as soon as an iterate
    // exceeds it); whether such a solve also passes the slope test is
    // chance (it depended on the units of the scene), so it is treated
    // like one that fails it: the Hessian gets shifted.
    const double largest_step = 1e3 * length_scale;
    // Solve H d = -g with the current matrix: is d a descent direction?
    auto solve_for_descent = [&]() {
      if (!statistics.count_linear_solve(
            linear_solver.solve(hessian, d, rhs, info, message, forcing, largest_step),
            info,
            message))
        return false;
      constraints.distribute(d);
      if (length_scale > 0. && d.linfty_norm() > largest_step)
        return false;
      // A factorisation with negative pivots: H is indefinite, and d may
      // lead towards a saddle of the quadratic model even when it passes
      // the slope test.
      indefinite =
        parameters.inertia_test && linear_solver.negative_pivots() > 0;
      return is_descent(d);
    };
    const bool exact_descent = solve_for_descent();
    if (exact_descent && !indefinite)
      return true;

    // The objective's convex approximation of its non-convex parts (the
    // projected contact Hessian), if it has one: for a direction that is
    // no descent direction, and for an indefinite factorisation. Without
    // one, an indefinite Hessian's descent direction is taken as it is
    // (a material's own loss of convexity, e.g. near a limit load, is not
    // the contact term's).
    if (objective.set_convexified(true))
      {
        // Kept in case the convexified direction does not descend.
        VectorType exact_direction;
        if (exact_descent)
          exact_direction = d;
        ++statistics.convexified_steps;
        progress << "      Hessian not positive definite: convexified contact "
                    "Hessian"
                 << std::endl;
        {
          TimerOutput::Scope assembly(timer, "assembly");
          VectorType         rhs_copy(rhs);
          ghosted = u;
          objective.evaluate(ghosted, constraints, &rhs_copy, &hessian);
        }
        objective.set_convexified(false);
        if (solve_for_descent())
          return true;
        if (exact_descent)
          {
            d = exact_direction;
            return true;
          }
      }
    else if (exact_descent)
      return true;

    // Regularise: shift the diagonal by tau |H_ii|.
    ++statistics.regularized_steps;
    const IndexSet      owned = rhs.locally_owned_elements();
    std::vector<double> diagonal;
    double              max_diagonal = 0.;
    for (const auto i : owned)
      {
        diagonal.push_back(hessian.diag_element(i));
        max_diagonal = std::max(max_diagonal, std::abs(diagonal.back()));
      }
    max_diagonal =
      Utilities::MPI::max(max_diagonal, rhs.get_mpi_communicator());
    double tau = parameters.initial_shift;
    for (unsigned int s = 0; s < parameters.max_shifts; ++s, tau *= 10.)
      {
        unsigned int k = 0;
        for (const auto i : owned)
          {
            const double h = std::max(std::abs(diagonal[k]), 1e-12 * max_diagonal);
            hessian.set(i, i, diagonal[k] + tau * h);
            ++k;
          }
        hessian.compress(VectorOperation::insert);
        progress << "      Hessian not positive definite: shift tau = "
                 << tau << std::endl;
        if (solve_for_descent())
          return true;
      }

    // Steepest descent, scaled by the largest diagonal entry.
    progress << "      using the steepest descent direction" << std::endl;
    d = rhs;
    if (max_diagonal > 0.)
      d /= max_diagonal;
    constraints.distribute(d);
    return is_descent(d);
  }

  namespace
  {
    /// A linear solver that fails (e.g. CG without the fallback to the
    /// direct solver) is the likely cause of a Newton failure: what to
    /// add to the reason to say so ("" if none failed).
    std::string
    linear_cause(const NewtonMinimizer::Statistics &statistics)
    {
      if (statistics.linear_failures == 0)
        return "";
      return "; " + std::to_string(statistics.linear_failures) +
             " linear solve(s) failed, the last: " + statistics.linear_message;
    }

    /// One line of progress per iteration.
    void
    print_iteration(ConditionalOStream &progress,
                    const unsigned int  it,
                    const double        residual,
                    const Evaluation   &e)
    {
      std::ostringstream line;
      line << "    it " << std::setw(2) << it << "  |g| "
           << std::scientific << std::setprecision(3) << residual
           << "  |g|/scale " << residual / std::max(e.force_scale, 1e-300)
           << "  E " << std::setprecision(10) << e.value
           << "  min J " << std::setprecision(4) << e.min_J;
      progress << line.str() << std::endl;
    }

    /// Whether the iteration ends at iterate @p it: converged (then
    /// statistics.converged is set) or failed (statistics.reason says
    /// why).
    bool
    iteration_ends(const NewtonMinimizer::Parameters &parameters,
                   const unsigned int                 it,
                   const double                       residual,
                   const double                       tolerance,
                   const double                       energy_scale,
                   const double                       last_decrease,
                   const bool                         at_least_once,
                   NewtonMinimizer::Statistics       &statistics)
    {
      if (!std::isfinite(residual))
        {
          statistics.reason = "the gradient is not finite";
          return true;
        }
      const bool energy_converged =
        (it > 0 &&
         std::abs(last_decrease) <= parameters.energy_tolerance * energy_scale);
      if (residual <= tolerance && ((it == 0 && !at_least_once) || energy_converged ||
                                    residual <= parameters.absolute_tolerance))
        {
          statistics.converged = true;
          return true;
        }
      if (it == parameters.max_iterations)
        {
          std::ostringstream msg;
          msg << "no convergence in " << it << " Newton iterations (|g| = "
              << residual << ", tolerance " << tolerance << ")";
          statistics.reason = msg.str() + linear_cause(statistics);
          return true;
        }
      return false;
    }

    /**
     * What the energy at @p e resolves: 1e3 eps (|strain energy| +
     * |external work| + |E|), or the evaluation's own estimate of its
     * round-off if that is larger (a barely strained stiff body).
     */
    double
    energy_noise(const Evaluation &e, const double energy_scale)
    {
      return std::max(1e3 * std::numeric_limits<double>::epsilon() *
                        (energy_scale + std::abs(e.value)),
                      e.round_off);
    }

    /**
     * The backtracking line search of one Newton iteration: along the
     * direction d from the iterate u, whose energy is e and minus
     * gradient rhs. The ghosted vector holds u (ghosted) on entry and is
     * the work vector of the trials.
     */
    class LineSearch
    {
    public:
      LineSearch(const NewtonMinimizer::Parameters &parameters,
                 const double                       length_scale,
                 ConditionalOStream                &progress,
                 Objective                         &objective,
                 const AffineConstraints<double>   &constraints,
                 const VectorType                  &u,
                 VectorType                        &ghosted,
                 const VectorType                  &rhs,
                 const VectorType                  &d)
        : parameters(parameters)
        , length_scale(length_scale)
        , progress(progress)
        , objective(objective)
        , constraints(constraints)
        , u(u)
        , ghosted(ghosted)
        , rhs(rhs)
        , d(d)
      {}

      /**
       * Search for a step: true if one is accepted, which is then in
       * @p trial, with its length in alpha and its evaluation in trial_e.
       * @p residual is |g| at u, @p energy_scale |strain energy| +
       * |external work|.
       */
      bool
      search(const Evaluation            &e,
             const double                 residual,
             const double                 energy_scale,
             VectorType                  &trial,
             NewtonMinimizer::Statistics &statistics,
             const bool                   may_expand = false)
      {
        const double slope = -(rhs * d); // g.d < 0
        const double noise = energy_noise(e, energy_scale);
        alpha = first_step_length();
        // The state u (ghosted) and g.u, for trials the objective limits
        // (taken before any trial overwrites the ghosted vector).
        VectorType u_ghosted;
        double     rhs_u = 0.;
        if (parameters.limit_trials)
          {
            u_ghosted = ghosted;
            rhs_u     = rhs * u;
          }
        // The energy resolves a decrease only down to its round-off, and
        // that is far above eps |E| where a stiff body is barely strained
        // (psi is a difference of O(1) invariants: its error is about
        // eps mu per unit volume whatever the strain). When the decrease a
        // Newton step promises is within 1e3 x the estimated noise, an
        // Armijo test on E is blind: a tiny step passes it by round-off
        // alone, the iterate does not move and the load step is cut by
        // chance (seen with another BLAS). There the step the limits allow
        // is judged by the gradient norm first; backtracking on E is the
        // fallback.
        if (-slope <= 1e3 * noise && lowers_gradient_norm(residual, trial))
          return true;
        if (!backtrack(e, slope, noise, u_ghosted, rhs_u, trial, statistics))
          return false;
        // A direction of the convexified (or shifted) Hessian, whose full
        // step was accepted as it is, when the caller allows it (the
        // iteration crawls): the exact Hessian has negative curvature there, the
        // convexified one overestimates it, and the full step may be far
        // short of the minimum along d (one pass on the ironing scene's
        // mesh at 160 steps crawled 2e-2 of energy per iteration for 100
        // iterations, four times). The step is doubled while the energy
        // keeps falling (Armijo) and the limits allow, 32 times at most.
        if (may_expand && plain && alpha == 1.)
          expand(e, slope, trial);
        return true;
      }

      /// The accepted step's length and its evaluation.
      double     alpha = 1.;
      Evaluation trial_e;

    private:
      /// The longest step the limits allow (first_step_length() without
      /// the cap at 1), and whether the accepted trial is u + alpha d.
      double max_alpha = 1.;
      bool   plain     = false;

      /// Double the accepted full step while the energy keeps falling.
      void
      expand(const Evaluation &e, const double slope, VectorType &trial)
      {
        VectorType candidate(u);
        for (unsigned int k = 0; k < 5 && 2. * alpha <= max_alpha; ++k)
          {
            const double next = 2. * alpha;
            candidate         = u;
            candidate.add(next, d);
            ghosted = candidate;
            const Evaluation next_e =
              objective.evaluate(ghosted, constraints, nullptr, nullptr);
            if (!next_e.admissible || !(next_e.value < trial_e.value) ||
                next_e.value > e.value + parameters.armijo_c1 * next * slope)
              break;
            trial   = candidate;
            trial_e = next_e;
            alpha   = next;
          }
        if (alpha > 1.)
          progress << "      step expanded to " << alpha << " times the Newton step"
                   << std::endl;
      }

      /// The first trial step length: 1, or less where the largest
      /// increment or the contact model (max_step) allows less.
      double
      first_step_length()
      {
        double step = 1.;
        max_alpha   = std::numeric_limits<double>::infinity();
        if (parameters.max_increment > 0. && length_scale > 0.)
          {
            const double largest = d.linfty_norm();
            max_alpha = parameters.max_increment * length_scale / std::max(largest, 1e-300);
            if (largest > parameters.max_increment * length_scale)
              {
                step = parameters.max_increment * length_scale / largest;
                progress << "      step limited to " << step
                         << " of the Newton step" << std::endl;
              }
          }
        const double limit = objective.max_step(ghosted, d);
        max_alpha          = std::min(max_alpha, limit);
        if (limit < step)
          {
            step = limit;
            progress << "      step limited to " << step
                     << " of the Newton step by the contact model" << std::endl;
          }
        return step;
      }

      /// Whether the step alpha leads to an admissible state with a
      /// smaller gradient norm than @p residual (then in @p trial).
      bool
      lowers_gradient_norm(const double residual, VectorType &trial)
      {
        trial = u;
        trial.add(alpha, d);
        ghosted = trial;
        VectorType trial_rhs(rhs);
        trial_e = objective.evaluate(ghosted, constraints, &trial_rhs, nullptr);
        if (trial_e.admissible && trial_rhs.l2_norm() < residual)
          {
            progress << "      energy decrease below round-off: step "
                        "accepted on the gradient norm"
                     << std::endl;
            return true;
          }
        return false;
      }

      /// Backtracking on the energy (Armijo test with @p slope = g.d),
      /// each trial first offered to the objective to limit.
      bool
      backtrack(const Evaluation            &e,
                const double                 slope,
                const double                 noise,
                const VectorType            &u_ghosted,
                const double                 rhs_u,
                VectorType                  &trial,
                NewtonMinimizer::Statistics &statistics)
      {
        for (unsigned int k = 0; k <= parameters.max_backtracks; ++k)
          {
            trial = u;
            trial.add(alpha, d);
            if (parameters.limit_trials && objective.limit_trial(u_ghosted, trial))
              {
                constraints.distribute(trial);
                const double limited_slope = rhs_u - rhs * trial;
                ghosted = trial;
                trial_e = objective.evaluate(ghosted, constraints, nullptr, nullptr);
                if (limited_slope < 0. && trial_e.admissible &&
                    trial_e.value <= e.value + parameters.armijo_c1 * limited_slope)
                  {
                    progress << "      trial limited by the contact model" << std::endl;
                    plain = false;
                    return true;
                  }
                trial = u;
                trial.add(alpha, d);
              }
            ghosted = trial;
            trial_e = objective.evaluate(ghosted, constraints, nullptr, nullptr);
            if (trial_e.admissible &&
                (trial_e.value <= e.value + parameters.armijo_c1 * alpha * slope ||
                 // near convergence the decrease drowns in round-off:
                 // accept a full step that does not increase E beyond it
                 (alpha == 1. && -slope <= noise && trial_e.value <= e.value + noise)))
              {
                plain = true;
                return true;
              }
            ++statistics.backtracks;
            alpha *= parameters.backtrack_factor;
          }
        return false;
      }

      const NewtonMinimizer::Parameters &parameters;
      const double                       length_scale;
      ConditionalOStream                &progress;
      Objective                         &objective;
      const AffineConstraints<double>   &constraints;
      const VectorType                  &u;
      VectorType                        &ghosted;
      const VectorType                  &rhs;
      const VectorType                  &d;
    };
  } // namespace

  NewtonMinimizer::Statistics
  NewtonMinimizer::minimize(Objective                       &objective,
                            const AffineConstraints<double> &constraints,
                            VectorType                      &u,
                            VectorType                      &ghosted,
                            MatrixType                      &hessian,
                            VectorType                      &rhs)
  {
    Statistics statistics;
    VectorType d(u), trial(u);

    auto full_evaluation = [&]() {
      TimerOutput::Scope scope(timer, "assembly");
      ghosted = u;
      return objective.evaluate(ghosted, constraints, &rhs, &hessian);
    };

    Evaluation e = full_evaluation();
    if (!e.admissible)
      {
        statistics.reason = "the initial state is inadmissible (min J = " +
                            std::to_string(e.min_J) + ")";
        statistics.evaluation = e;
        return statistics;
      }

    double last_decrease = std::numeric_limits<double>::infinity();
    // Consecutive iterations whose convexified (or shifted) direction was
    // taken in full: the iteration crawls along a direction of negative
    // curvature, and from the fifth on the line search may lengthen the
    // step (LineSearch::expand). Not sooner: on the nodal form's
    // non-convex energy a longer step can land in another of its
    // equilibria (the two-pass ironing's end state then missed the
    // mirror of its start by 28% instead of 3e-8).
    unsigned int crawling = 0;
    // The inexact Newton forcing term (iterative solvers only) and the
    // gradient norm it was chosen for.
    double forcing = 0., forcing_residual = 0.;
    for (unsigned int it = 0;; ++it)
      {
        // A safe point for a clean stop (collective, like the iteration).
        Interruption::throw_if_requested(u.get_mpi_communicator());
        const double residual = rhs.l2_norm();
        const double tolerance =
          std::max(parameters.residual_tolerance * e.force_scale,
                   parameters.absolute_tolerance);
        const double energy_scale =
          std::abs(e.strain_energy) + std::abs(e.external_work);
        statistics.iterations  = it;
        statistics.residual    = residual;
        statistics.force_scale = e.force_scale;
        statistics.evaluation  = e;
        print_iteration(progress, it, residual, e);
        if (iteration_ends(parameters, it, residual, tolerance, energy_scale,
                           last_decrease, at_least_once, statistics))
          return statistics;

        const unsigned int regularized_before =
          statistics.regularized_steps + statistics.convexified_steps;
        forcing = linear_solver.forcing_term(residual, forcing_residual, forcing,
                                             tolerance);
        forcing_residual = residual;
        unsigned int linear_before    = statistics.linear_iterations;
        unsigned int fallbacks_before = statistics.linear_fallbacks;
        if (!descent_direction(objective, u, ghosted, constraints, hessian, rhs, d,
                               forcing, statistics))
          {
            statistics.reason = "no descent direction found" + linear_cause(statistics);
            return statistics;
          }

        auto print_linear_solve = [&]() {
          if (linear_solver.is_iterative())
            progress << "      linear solve: "
                     << statistics.linear_iterations - linear_before
                     << " iterations to " << std::scientific << std::setprecision(1)
                     << forcing << " |g|" << std::endl;
        };
        print_linear_solve();

        // An inexact direction (an iterative solve stopped at the forcing
        // term) cannot be judged in the round-off regime: the energy does
        // not resolve the decrease it promises, and the correction is only
        // as small as its solve is accurate. The regime: a gradient as large
        // as the forces themselves (the force scale, itself round-off in an
        // unstrained body) whose promised decrease the energy cannot see.
        // There, and after a line search that failed on an inexact
        // direction, the Newton step is solved again to the fixed tolerance
        // (a true Newton step only: a shifted or convexified Hessian's is
        // not one), and the increment test below may end the iteration.
        // Without it, a step whose answer is a rigid motion (the ironing
        // die before it touches, under CG) wandered in round-off until the
        // line search gave up. A converging loaded state (gradient far
        // below the force scale) keeps its inexact directions.
        const double fixed_tolerance = linear_solver.get_parameters().relative_tolerance;
        auto true_newton_step = [&]() {
          return statistics.regularized_steps + statistics.convexified_steps ==
                 regularized_before;
        };
        // A solve that fell back to the direct solver is exact already.
        auto solved_exactly = [&]() {
          return forcing <= fixed_tolerance ||
                 statistics.linear_fallbacks > fallbacks_before;
        };
        auto can_solve_again = [&]() {
          return linear_solver.is_iterative() && !solved_exactly() &&
                 true_newton_step();
        };
        auto solve_again = [&]() {
          forcing = fixed_tolerance;
          progress << "      solved again to the fixed tolerance" << std::endl;
          linear_before    = statistics.linear_iterations;
          fallbacks_before = statistics.linear_fallbacks;
          const bool found = descent_direction(objective, u, ghosted, constraints,
                                               hessian, rhs, d, forcing, statistics);
          print_linear_solve();
          return found;
        };
        if (can_solve_again() && residual >= 0.1 * e.force_scale &&
            rhs * d <= 1e3 * energy_noise(e, energy_scale) && !solve_again())
          {
            statistics.reason = "no descent direction found" + linear_cause(statistics);
            return statistics;
          }

        // A correction below round-off of the geometry: nothing is left
        // to gain (the gradient is round-off, whatever its units). Only a
        // true Newton step says so (and only one solved to the fixed
        // tolerance: an inexact one may just be short).
        auto below_increment_tolerance = [&]() {
          if (true_newton_step() && solved_exactly() &&
              parameters.increment_tolerance > 0. && length_scale > 0. &&
              d.linfty_norm() <= parameters.increment_tolerance * length_scale)
            {
              progress << "      Newton correction " << std::scientific
                       << std::setprecision(2) << d.linfty_norm()
                       << " is below the increment tolerance" << std::endl;
              statistics.converged = true;
              return true;
            }
          return false;
        };
        if (below_increment_tolerance())
          return statistics;

        // Backtracking line search on the energy.
        LineSearch line_search(parameters, length_scale, progress, objective,
                               constraints, u, ghosted, rhs, d);
        auto       search = [&]() {
          TimerOutput::Scope scope(timer, "line search");
          return line_search.search(e, residual, energy_scale, trial, statistics,
                                    !true_newton_step() && crawling >= 5);
        };
        bool found = search();
        if (!found && can_solve_again())
          {
            if (!solve_again())
              {
                statistics.reason = "no descent direction found" + linear_cause(statistics);
                return statistics;
              }
            if (below_increment_tolerance())
              return statistics;
            found = search();
          }
        if (!found)
          {
            statistics.reason =
              "the line search found no admissible decrease of the energy "
              "after " + std::to_string(parameters.max_backtracks) +
              " backtracks";
            return statistics;
          }
        if (line_search.alpha < 1.)
          progress << "      line search: step length " << line_search.alpha
                   << std::endl;
        crawling = (!true_newton_step() && line_search.alpha >= 1.) ? crawling + 1 : 0;
        last_decrease = e.value - line_search.trial_e.value;
        u             = trial;
        e             = full_evaluation();
        if (!e.admissible)
          {
            statistics.reason = "inadmissible state after the line search";
            return statistics;
          }
      }
  }

  bool
  NewtonMinimizer::predictor(Objective                       &objective,
                             const AffineConstraints<double> &constraints,
                             VectorType                      &u,
                             VectorType                      &ghosted,
                             MatrixType                      &hessian,
                             VectorType                      &rhs,
                             std::string                     &reason)
  {
    Evaluation e;
    {
      TimerOutput::Scope scope(timer, "assembly");
      ghosted = u;
      e       = objective.evaluate(ghosted, constraints, &rhs, &hessian);
    }
    if (!e.admissible)
      {
        reason = "inadmissible state before the predictor";
        return false;
      }
    VectorType         d(u);
    LinearSolver::Info info;
    {
      TimerOutput::Scope scope(timer, "linear solve");
      if (!linear_solver.solve(hessian, d, rhs, info, reason))
        return false;
    }
    constraints.distribute(d);
    // The Dirichlet increment alone: zero but on the constrained DoFs.
    VectorType dirichlet(u);
    dirichlet = 0.;
    constraints.distribute(dirichlet);
    VectorType trial(u);
    double     scale = 1.;
    for (;;)
      {
        trial = u;
        trial.add(1. - scale, dirichlet, scale, d);
        {
          TimerOutput::Scope scope(timer, "line search");
          ghosted = trial;
          e       = objective.evaluate(ghosted, constraints, nullptr, nullptr);
        }
        if (e.admissible)
          break;
        if (scale == 0.)
          {
            reason =
              "the predictor step leads to an inadmissible state (min J = " +
              std::to_string(e.min_J) +
              (e.min_J > 0. ? "; the contact model rejects it" : "") +
              "), and so does the Dirichlet increment alone";
            return false;
          }
        scale = scale > 1. / 64. ? scale / 2. : 0.;
      }
    if (scale > 0.)
      {
        // The Dirichlet increment alone, if it is lower (a Newton step from
        // a start near the solution can climb where the Hessian is
        // indefinite; a linear step towards a first touch goes through the
        // other body, whose contact term H does not have yet).
        VectorType alone(u);
        alone.add(1., dirichlet);
        Evaluation a;
        {
          TimerOutput::Scope scope(timer, "line search");
          ghosted = alone;
          a       = objective.evaluate(ghosted, constraints, nullptr, nullptr);
        }
        if (a.admissible && a.value <= e.value)
          {
            progress << "      predictor: the linear step raises the energy ("
                     << e.value << " against " << a.value
                     << "); the Dirichlet increment alone" << std::endl;
            u = alone;
            return true;
          }
      }
    if (scale < 1.)
      {
        progress << "      predictor: the linear step is inadmissible; ";
        if (scale > 0.)
          progress << "its free part scaled by " << scale << std::endl;
        else
          progress << "the Dirichlet increment alone" << std::endl;
      }
    u = trial;
    return true;
  }
} // namespace Signorini
