#pragma once

#include <signorini/solvers/ipopt_solver.h>
#include <signorini/solvers/step_solver.h>

#include <memory>

namespace Signorini
{
  /**
   * Ipopt on E with the contact model's node-wise constraints and the
   * incompressibility equalities (formulation.md (11)); one MPI rank.
   */
  template <int dim>
  class IpoptStep : public StepSolver<dim>
  {
  public:
    using StepSolver<dim>::StepSolver;

    void
    setup() override;

    bool
    solve(const double                 time,
          StepStatistics              &stats,
          Report::Step                &record) override;

    std::string
    iteration_name() const override
    {
      return "ipopt";
    }

    /// "ipopt derivative test errors" when the test ran.
    void
    write_summary(Json &summary) const override;

    /// ipopt_derivative_test_errors when the test ran.
    void
    add_quantities(std::vector<Quantity> &quantities) const override;

    /// Ipopt's warm-start data and the derivative test's result (Ipopt
    /// runs on one rank only: the archive holds its node-wise
    /// multipliers).
    void
    save_state(OutputArchive &archive, MeshState &mesh) const override;
    void
    load_state(InputArchive &archive, MeshState &mesh) override;

  private:
    std::unique_ptr<IpoptSolver<dim>> ipopt;
    int                               derivative_test_errors = -1;
  };
} // namespace Signorini
