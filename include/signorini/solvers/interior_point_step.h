#pragma once

#include <signorini/solvers/interior_point.h>
#include <signorini/solvers/step_solver.h>

#include <vector>

namespace Signorini
{
  /**
   * The primal-dual interior point method (InteriorPointMinimizer) on E
   * with the contact model's node-wise constraints g_k >= 0: the rigid
   * foundation. It runs on the project's distributed vectors and matrices
   * with the configured LinearSolver, on any number of MPI ranks. Its
   * multipliers are the nodal contact forces.
   */
  template <int dim>
  class InteriorPointStep : public StepSolver<dim>
  {
  public:
    InteriorPointStep(const Parameters::Scene &parameters,
                      Scene<dim>              &scene,
                      Problem<dim>            &problem,
                      TimerOutput             &timer,
                      ConditionalOStream      &progress);

    void
    setup() override;

    bool
    solve(const double    time,
          StepStatistics &stats,
          Report::Step   &record) override;

    std::string
    iteration_name() const override
    {
      return "interior_point";
    }

    /// The multipliers for the warm start: the contact constraints' on
    /// their nodes, the incompressibility constraints' on their cells.
    void
    save_state(OutputArchive &archive, MeshState &mesh) const override;
    void
    load_state(InputArchive &archive, MeshState &mesh) override;

  private:
    /// The active cell indices of the cells of y (and rho, volume).
    std::vector<unsigned int>
    incompressible_cells() const;

    InteriorPointMinimizer<dim> minimizer;
    // Incompressible bodies: one multiplier, weight and volume per
    // constrained cell of this rank (Incompressibility::cells() order).
    std::vector<double> y, rho, volume;
  };
} // namespace Signorini
