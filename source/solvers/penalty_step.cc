#include <signorini/archive_io.h>
#include <signorini/solvers/penalty_step.h>

#include <algorithm>
#include <sstream>

namespace Signorini
{
  template <int dim>
  PenaltyStep<dim>::PenaltyStep(const Parameters::Scene &parameters,
                                Scene<dim>              &scene,
                                Problem<dim>            &problem,
                                TimerOutput             &timer,
                                ConditionalOStream      &progress,
                                const bool               ipopt_stages)
    : StepSolver<dim>(parameters, scene, problem, timer, progress)
    , ipopt_stages(ipopt_stages)
  {
    // From the carried state Ipopt's stages crawled: the exact contact
    // Hessian is indefinite there, Ipopt's inertia correction added
    // delta = 1e4..1e5 (lg(rg) 4.2-5.0 in ipopt.out) and its steps were
    // 1e-6 long, 500 iterations per sliding step on prm/hard/ironing_full.
    // Newton takes the convexified contact Hessian and needed 4.
    if (ipopt_stages)
      this->without_transport("Ipopt as the stage solver (Solver > Method = ipopt)");
  }

  template <int dim>
  void
  PenaltyStep<dim>::rebuild_pattern(const VectorType &u)
  {
    this->scene.build_matrix(u);
  }

  template <int dim>
  void
  PenaltyStep<dim>::setup()
  {
    StepSolver<dim>::setup();
    auto &scene   = this->scene;
    auto &problem = this->problem;
    // The penalty scale: the largest small-strain Young's modulus, in the
    // contact model's units.
    mu0 = problem.contact->initial_penalty(
      this->parameters.solver.penalty.initial_factor * scene.max_young_modulus());
    if (initial_mu0 == 0.)
      {
        initial_mu0 = mu0;
        last_mu     = mu0;
      }
    if (ipopt_stages)
      {
        // Without constraints: the penalty stages are unconstrained.
        ipopt = this->make_ipopt(nullptr, nullptr);
        ipopt->set_penalty(problem.contact.get(),
                           [this](const VectorType &u) { rebuild_pattern(u); });
      }
  }

  template <int dim>
  void
  PenaltyStep<dim>::start_path()
  {
    last_mu = mu0;
  }

  template <int dim>
  bool
  PenaltyStep<dim>::solve(const double                 time,
                          StepStatistics              &stats,
                          Report::Step                &record)
  {
    auto                         &scene  = this->scene;
    auto                         &energy = *this->problem.energy;
    auto                         &term   = *this->problem.contact;
    const Contact::FrictionTerm<dim> *friction = this->problem.friction.get();
    ContinuationParameters continuation = this->parameters.solver.penalty;
    // Ipopt solves each stage to its own tolerance: no loose stages.
    if (ipopt)
      continuation.stage_tolerance = 0.;
    NewtonMinimizer               newton = this->newton();
    // A re-solve of the friction loop starts at the penalty the last
    // solve ended with: from a lower one its first stage would leave the
    // converged state and could end in another of the penalised
    // problem's minima, so that the outer loop cycles between two states.
    const double mu_start =
      this->friction_resolve ?
        last_mu :
        (continuation.restart_each_step ?
           mu0 :
           std::max(mu0, last_mu / continuation.step_reduction));
    const typename Contact::PenaltyObjective<dim>::PatternBuilder rebuild =
      [this](const VectorType &u) {
        TimerOutput::Scope scope(this->timer, "sparsity pattern");
        rebuild_pattern(u);
      };
    // The predictor's objective: G_mu with the first stage's penalty (with
    // either stage minimiser), so that its step is checked against the
    // contact's admissibility too.
    {
      Contact::PenaltyObjective<dim> penalty(energy, term, time, mu_start, rebuild);
      penalty.timer = &this->timer;
      Contact::FrictionObjective<dim> objective(penalty, friction);
      if (!this->predict(newton, objective, time, stats))
        return false;
    }

    // Each stage: Newton on G_mu, or Ipopt as an unconstrained minimiser.
    StageSolver solve_stage = [&](const double mu, VectorType &u,
                                  const double loose_tolerance) {
      Contact::PenaltyObjective<dim> penalty(energy, term, time, mu, rebuild);
      penalty.timer = &this->timer;
      Contact::FrictionObjective<dim> stage(penalty, friction);
      NewtonMinimizer stage_newton = newton;
      stage_newton.loosen(loose_tolerance);
      return stage_newton.minimize(stage, scene.homogeneous_constraints, u,
                                   scene.solution_ghosted, scene.hessian,
                                   scene.rhs);
    };
    // du/dmu = -H^{-1} grad P at a converged stage, for the stage
    // predictor (Newton stages only: it uses their Hessian and solver).
    // The tangent solves' share of the step's linear solver statistics.
    NewtonMinimizer::Statistics tangent_solves;
    StageTangent stage_tangent = [&](const double mu, VectorType &u) {
      Contact::PenaltyObjective<dim> penalty(energy, term, time, mu, rebuild);
      penalty.timer = &this->timer;
      Contact::FrictionObjective<dim> stage(penalty, friction);
      scene.solution_ghosted = u;
      {
        TimerOutput::Scope scope(this->timer, "assembly");
        if (!stage.evaluate(scene.solution_ghosted,
                            scene.homogeneous_constraints, &scene.rhs,
                            &scene.hessian)
               .admissible)
          return false;
        scene.rhs = 0.;
        term.add_penalty(scene.solution_ghosted, 1.,
                         scene.homogeneous_constraints, &scene.rhs, nullptr);
      }
      TimerOutput::Scope scope(this->timer, "linear solve");
      LinearSolver::Info info;
      std::string        reason;
      u = 0.;
      if (!tangent_solves.count_linear_solve(
            this->linear_solver.solve(scene.hessian, u, scene.rhs, info, reason),
            info, reason))
        return false;
      scene.homogeneous_constraints.distribute(u);
      return true;
    };
    if (ipopt)
      {
        const AffineConstraints<double> target =
          scene.boundary_constraints(time, false);
        solve_stage = [&, target, newton_stage = solve_stage](
                        const double mu, VectorType &u, const double loose) {
          const VectorType start(u);
          scene.solution_ghosted = u;
          const auto result = ipopt->solve(time, target, scene.solution_ghosted, mu);
          record.solver_status = result.status;
          if (result.success)
            {
              u = scene.solution_ghosted;
              NewtonMinimizer::Statistics s;
              s.converged  = true;
              s.iterations = result.iterations;
              s.evaluation = energy.evaluate(scene.solution_ghosted, time,
                                             scene.homogeneous_constraints,
                                             nullptr, nullptr);
              return s;
            }
          // Ipopt has no safeguard against a Hessian that is singular but
          // factorises as positive definite by round-off: a body held only
          // by contact at zero penetration, whose cubic penalty has no
          // stiffness yet. Its step is then of the order 1e12 and every
          // trial point is rejected (tests/two_body_ipopt on a machine
          // whose BLAS rounds that pivot away from zero). Newton shifts
          // such a Hessian: the stage is minimised by Newton from the
          // same start, and counted.
          this->progress << "      Ipopt failed (" << result.failure()
                         << "): this stage is minimised by Newton" << std::endl;
          ++newton_stages;
          u = start;
          NewtonMinimizer::Statistics s = newton_stage(mu, u, loose);
          s.iterations += result.iterations;
          return s;
        };
      }
    const ContinuationResult result =
      penalty_continuation(continuation, solve_stage, stage_tangent, energy,
                           term, time,
                           mu_start, mu0, scene.homogeneous_constraints,
                           scene.solution, scene.solution_ghosted,
                           this->progress);
    stats                   = result.last;
    stats.iterations        = result.iterations;
    // Over all stages and the tangents between them.
    stats.linear_iterations =
      result.linear_iterations + tangent_solves.linear_iterations;
    stats.linear_solves = result.linear_solves + tangent_solves.linear_solves;
    stats.linear_fallbacks =
      result.linear_fallbacks + tangent_solves.linear_fallbacks;
    stats.converged         = result.converged;
    stats.reason            = result.reason;
    record.stages           = result.stages;
    if (!result.converged)
      return false;
    term.set_contact_forces(result.forces);
    last_mu = result.stages.back().mu;
    if (!result.tolerance_met)
      {
        tolerance_met = false;
        std::ostringstream status;
        if (result.capped)
          status << "penetration tolerance not met: mu capped at "
                 << result.stages.back().mu
                 << " (Solver > Penalty > Maximum penalty ratio)";
        else
          status << "penetration tolerance not met in "
                 << continuation.max_stages
                 << " stages (Solver > Penalty > Maximum stages)";
        record.solver_status = status.str();
      }
    return true;
  }

  template <int dim>
  void
  PenaltyStep<dim>::write_contact_summary(Json &c) const
  {
    c["initial penalty"]           = initial_mu0;
    c["final penalty"]             = last_mu;
    c["penetration tolerance"]     = this->parameters.solver.penalty.penetration_tolerance;
    c["penetration tolerance met"] = tolerance_met;
    if (ipopt)
      c["ipopt stages minimised by newton"] = newton_stages;
  }

  template <int dim>
  void
  PenaltyStep<dim>::save_state(OutputArchive &archive, MeshState &mesh) const
  {
    (void)mesh;
    archive << initial_mu0 << last_mu << tolerance_met << newton_stages;
    if (ipopt)
      ipopt->save_state(archive);
  }

  template <int dim>
  void
  PenaltyStep<dim>::load_state(InputArchive &archive, MeshState &mesh)
  {
    (void)mesh;
    archive >> initial_mu0 >> last_mu >> tolerance_met >> newton_stages;
    if (ipopt)
      ipopt->load_state(archive);
  }

  template class PenaltyStep<2>;
  template class PenaltyStep<3>;
} // namespace Signorini
