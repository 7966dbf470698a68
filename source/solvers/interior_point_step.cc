#include <signorini/archive_io.h>
#include <signorini/problem/incompressibility_lagrangian.h>
#include <signorini/solvers/interior_point_step.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

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
  {
    this->without_transport("Solver > Method = interior-point (not tried with sliding)");
  }

  template <int dim>
  void
  InteriorPointStep<dim>::setup()
  {
    StepSolver<dim>::setup();
    const auto &problem = this->problem;
    const auto &scene   = this->scene;
    if (const auto *constraints =
          problem.contact ? problem.contact->node_wise_constraints() : nullptr)
      minimizer.setup(*constraints, scene.homogeneous_constraints,
                      scene.dof_handler.get_communicator());
    else
      {
        AssertThrow(problem.incompressibility,
                    ExcMessage("the interior point method needs node-wise "
                               "constraints or incompressible bodies"));
        minimizer.setup_without_constraints(scene.h_min);
      }
    y.clear();
    rho.clear();
    volume.clear();
    if (problem.incompressibility)
      for (const auto &cell : problem.incompressibility->cells())
        {
          const auto material = scene.materials.find(cell->material_id());
          AssertThrow(material != scene.materials.end(),
                      ExcMessage("no material for an incompressible cell"));
          volume.push_back(cell->measure());
          rho.push_back(this->parameters.solver.interior_point.incompressibility_weight *
                        material->second->small_strain_lame().first / volume.back());
          y.push_back(0.);
        }
    minimizer.set_step_limits(this->parameters.solver.interior_point.max_increment *
                                this->scene.size,
                              this->parameters.solver.interior_point.increment_tolerance *
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
    EnergyObjective<dim> energy(*this->problem.energy, time);
    // With friction: E + sum D_p, the lagged dissipation potential.
    Contact::FrictionObjective<dim> objective(energy, this->problem.friction.get());
    const auto *incompressibility = this->problem.incompressibility.get();
    if (!incompressibility)
      stats = minimizer.minimize(objective, scene.homogeneous_constraints,
                                 scene.solution, scene.solution_ghosted,
                                 scene.hessian, scene.rhs);
    else
      {
        // The augmented Lagrangian of the J = 1 constraints, its
        // multipliers updated after each converged solve (warm: the last
        // load step's multipliers are the first guess). With friction the
        // same loop re-lags the normal forces (lags_friction()): one
        // fixed-point loop for both, not one inside the other.
        const auto &p     = this->parameters.solver.interior_point;
        const auto &cells = incompressibility->cells();
        const MPI_Comm comm = scene.dof_handler.get_communicator();
        Contact::FrictionTerm<dim> *friction = this->problem.friction.get();
        const unsigned int max_updates =
          friction ? std::max(p.max_multiplier_updates,
                              friction->friction_parameters().max_outer_iterations) :
                     p.max_multiplier_updates;
        // The state a re-solve after a large change of the lag starts
        // from (friction only).
        const VectorType start = friction ? scene.solution : VectorType();
        unsigned int   iterations = 0;
        std::vector<double> c(cells.size(), 0.);
        double change = 1.;
        for (unsigned int update = 0;; ++update)
          {
            if (update > 0 && friction && change <= small_friction_change)
              minimizer.restart_barrier(friction_restart_barrier);
            if (update > 0 && friction && change > this->friction_restart_change)
              scene.solution = start;
            IncompressibilityLagrangian<dim> lagrangian(objective, *incompressibility, y, rho);
            stats = minimizer.minimize(lagrangian, scene.homogeneous_constraints,
                                       scene.solution, scene.solution_ghosted,
                                       scene.hessian, scene.rhs);
            iterations += stats.iterations;
            if (!stats.converged)
              break;
            scene.solution_ghosted = scene.solution;
            double worst = 0.;
            for (unsigned int k = 0; k < cells.size(); ++k)
              {
                c[k]  = incompressibility->evaluate(cells[k], scene.solution_ghosted,
                                                    nullptr, nullptr);
                worst = std::max(worst, std::abs(c[k]) / volume[k]);
              }
            worst = Utilities::MPI::max(worst, comm);
            this->progress << "    multiplier update " << update
                           << ": max |c_K|/|K| = " << std::scientific
                           << std::setprecision(3) << worst << std::endl;
            this->progress << std::defaultfloat;
            change = 0.;
            if (friction)
              {
                this->problem.contact->set_contact_forces(minimizer.multipliers());
                change = this->update_friction(update, record);
              }
            if (worst <= p.incompressibility_tolerance &&
                (!friction || change <= friction->friction_parameters().outer_tolerance))
              break;
            if (update + 1 >= max_updates)
              {
                stats.converged = false;
                std::ostringstream reason;
                if (worst > p.incompressibility_tolerance)
                  reason << "the J = 1 constraints are not met after " << max_updates
                         << " multiplier updates (max |c_K|/|K| = " << worst << ")";
                else
                  reason << this->friction_failure(change, max_updates);
                stats.reason = reason.str();
                break;
              }
            for (unsigned int k = 0; k < cells.size(); ++k)
              y[k] += rho[k] * c[k];
          }
        stats.iterations = iterations;
      }
    scene.solution_ghosted = scene.solution;
    // A converged solve's reason is a note (the acceptable tolerance).
    record.solver_status =
      stats.converged && stats.reason.empty() ? "converged" : stats.reason;
    if (!stats.converged)
      return false;
    if (this->problem.contact)
      this->problem.contact->set_contact_forces(minimizer.multipliers());
    return true;
  }

  template <int dim>
  void
  InteriorPointStep<dim>::save_state(OutputArchive &archive, MeshState &mesh) const
  {
    minimizer.save_state(archive, mesh);
    // The incompressibility multipliers start the next load step.
    mesh.save_cell_field(incompressible_cells(), y);
  }

  template <int dim>
  void
  InteriorPointStep<dim>::load_state(InputArchive &archive, MeshState &mesh)
  {
    minimizer.load_state(archive, mesh);
    y = mesh.load_cell_field(incompressible_cells());
  }

  template <int dim>
  std::vector<unsigned int>
  InteriorPointStep<dim>::incompressible_cells() const
  {
    std::vector<unsigned int> cells;
    if (this->problem.incompressibility)
      for (const auto &cell : this->problem.incompressibility->cells())
        cells.push_back(cell->active_cell_index());
    return cells;
  }

  template class InteriorPointStep<2>;
  template class InteriorPointStep<3>;
} // namespace Signorini
