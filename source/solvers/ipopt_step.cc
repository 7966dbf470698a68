#include <signorini/archive_io.h>
#include <signorini/solvers/ipopt_step.h>

#include <algorithm>

namespace Signorini
{
  template <int dim>
  void
  IpoptStep<dim>::setup()
  {
    StepSolver<dim>::setup();
    this->without_transport("Solver > Method = ipopt (not tried with sliding)");
    const auto *contact = this->problem.contact.get();
    ipopt = this->make_ipopt(contact ? contact->node_wise_constraints() : nullptr,
                             this->problem.incompressibility.get());
    ipopt->set_friction(this->problem.friction.get());
  }

  template <int dim>
  bool
  IpoptStep<dim>::solve(const double                 time,
                        StepStatistics              &stats,
                        Report::Step                &record)
  {
    auto &scene            = this->scene;
    scene.solution_ghosted = scene.solution;
    const AffineConstraints<double> target = scene.boundary_constraints(time, false);
    const auto result      = ipopt->solve(time, target, scene.solution_ghosted);
    scene.solution         = scene.solution_ghosted;
    stats.iterations       = result.iterations;
    stats.converged        = result.success;
    record.solver_status   = result.status;
    derivative_test_errors =
      std::max(derivative_test_errors, result.derivative_test_errors);
    if (!result.success)
      {
        stats.reason = result.failure();
        return false;
      }
    if (this->problem.contact)
      this->problem.contact->set_contact_forces(result.contact_forces);
    TimerOutput::Scope scope(this->timer, "assembly");
    stats.evaluation = this->problem.energy->evaluate(scene.solution_ghosted,
                                                      time,
                                                      scene.homogeneous_constraints,
                                                      nullptr,
                                                      nullptr);
    stats.residual = 0.;
    return true;
  }

  template <int dim>
  void
  IpoptStep<dim>::write_summary(Json &summary) const
  {
    StepSolver<dim>::write_summary(summary);
    if (derivative_test_errors >= 0)
      summary["ipopt derivative test errors"] = derivative_test_errors;
  }

  template <int dim>
  void
  IpoptStep<dim>::add_quantities(std::vector<Quantity> &quantities) const
  {
    if (derivative_test_errors >= 0)
      {
        Quantity q;
        q.name  = "ipopt_derivative_test_errors";
        q.value = derivative_test_errors;
        quantities.push_back(q);
      }
  }

  template <int dim>
  void
  IpoptStep<dim>::save_state(OutputArchive &archive, MeshState &mesh) const
  {
    (void)mesh;
    archive << derivative_test_errors;
    ipopt->save_state(archive);
  }

  template <int dim>
  void
  IpoptStep<dim>::load_state(InputArchive &archive, MeshState &mesh)
  {
    (void)mesh;
    archive >> derivative_test_errors;
    ipopt->load_state(archive);
  }

  template class IpoptStep<2>;
  template class IpoptStep<3>;
} // namespace Signorini
