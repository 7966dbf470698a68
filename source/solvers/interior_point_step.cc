#include <signorini/solvers/interior_point_step.h>

namespace Signorini
{
  template <int dim>
  InteriorPointStep<dim>::InteriorPointStep(const Parameters::Scene &parameters,
                                            Scene<dim>              &scene,
                                            Problem<dim>            &problem,
                                            TimerOutput             &timer,
                                            ConditionalOStream      &progress)
    : StepSolver<dim>(parameters, scene, problem, timer, progress)
    , minimizer(parameters.solver.interior_point, this->linear_solver, progress, timer)
  {}

  template <int dim>
  void
  InteriorPointStep<dim>::setup()
  {
    StepSolver<dim>::setup();
    AssertThrow(this->problem.contact && this->problem.contact->has_constraints(),
                ExcMessage("the interior point method needs node-wise constraints"));
    minimizer.setup(*this->problem.contact,
                    this->scene.homogeneous_constraints,
                    this->scene.dof_handler.get_communicator());
    minimizer.set_step_limits(this->parameters.solver.newton.max_increment *
                                this->scene.size,
                              this->parameters.solver.newton.increment_tolerance *
                                this->scene.size);
  }

  template <int dim>
  bool
  InteriorPointStep<dim>::solve(const double    time,
                                StepStatistics &stats,
                                Report::Step   &record)
  {
    auto &scene = this->scene;
    // The Dirichlet values of this load time; the slacks absorb any
    // penetration this causes, the iteration removes it.
    const AffineConstraints<double> target = scene.boundary_constraints(time, false);
    target.distribute(scene.solution);
    EnergyObjective<dim> objective(*this->problem.energy, time);
    stats = minimizer.minimize(objective, scene.homogeneous_constraints,
                               scene.solution, scene.solution_ghosted,
                               scene.hessian, scene.rhs);
    scene.solution_ghosted = scene.solution;
    record.solver_status   = stats.converged ? "converged" : stats.reason;
    if (!stats.converged)
      return false;
    this->problem.contact->forces() = minimizer.multipliers();
    return true;
  }

  template <int dim>
  void
  InteriorPointStep<dim>::save_state(OutputArchive &archive) const
  {
    minimizer.save_state(archive);
  }

  template <int dim>
  void
  InteriorPointStep<dim>::load_state(InputArchive &archive)
  {
    minimizer.load_state(archive);
  }

  template class InteriorPointStep<2>;
  template class InteriorPointStep<3>;
} // namespace Signorini
