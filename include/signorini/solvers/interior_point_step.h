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

    /// With incompressible bodies the multiplier loop of solve() also
    /// re-lags the friction.
    bool
    lags_friction() const override
    {
      return this->problem.incompressibility != nullptr;
    }

    bool
    restarts_friction() const override
    {
      return true;
    }

  protected:
    /// The friction loop's re-solve starts from a converged state: the
    /// barrier starts small (InteriorPointMinimizer::restart_barrier()).
    void
    prepare_friction_resolve(const double change) override
    {
      if (change <= small_friction_change)
        minimizer.restart_barrier(friction_restart_barrier);
    }

  private:
    /// The restart barrier of the friction loop's re-solves, relative
    /// to force scale x h, once the normal forces change by at most
    /// small_friction_change (relative): from a larger change (the first
    /// re-solve of a step whose normal forces grew, or the step after a
    /// frictionless first solve) 'Warm start barrier' is faster
    /// (cattaneo_mindlin_2d's first step: 60 iterations from 1e-8, 12 from
    /// 1e-3).
    static constexpr double friction_restart_barrier = 1e-8;
    static constexpr double small_friction_change    = 1e-2;

    /// The active cell indices of the cells of y (and rho, volume).
    std::vector<unsigned int>
    incompressible_cells() const;

    InteriorPointMinimizer<dim> minimizer;
    // Incompressible bodies: one multiplier, weight and volume per
    // constrained cell of this rank (Incompressibility::cells() order).
    std::vector<double> y, rho, volume;
  };
} // namespace Signorini
