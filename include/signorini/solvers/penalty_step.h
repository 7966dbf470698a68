#pragma once

#include <signorini/solvers/ipopt_solver.h>
#include <signorini/solvers/penalty_continuation.h>
#include <signorini/solvers/step_solver.h>

#include <memory>

namespace Signorini
{
  /**
   * Penalty continuation on G_mu = E + mu P (formulation.md section 4):
   * a predictor on G_mu_0 for moving boundaries, then stages with growing
   * mu, each minimised by the stage minimiser: Newton, or Ipopt without
   * constraints (two-body contact with Method = ipopt, as in the poster).
   * The penalty is scaled by the contact model (mu_0) and each load step
   * starts from the last step's final penalty over 'Load step reduction'.
   */
  template <int dim>
  class PenaltyStep : public StepSolver<dim>
  {
  public:
    /// @p ipopt_stages: minimise each stage with Ipopt instead of Newton.
    PenaltyStep(const Parameters::Scene &parameters,
                Scene<dim>              &scene,
                Problem<dim>            &problem,
                TimerOutput             &timer,
                ConditionalOStream      &progress,
                const bool               ipopt_stages);

    void
    setup() override;

    /// The first stage of the next step at the mesh's initial penalty.
    void
    start_path() override;

    bool
    solve(const double                 time,
          StepStatistics              &stats,
          Report::Step                &record) override;

    std::string
    iteration_name() const override
    {
      return ipopt ? "ipopt" : "newton";
    }

    /// Initial and final penalty, the tolerance and whether it was met.
    void
    write_contact_summary(Json &block) const override;

    /// The first mesh's and the last step's penalty, whether the
    /// tolerance was met, and Ipopt's warm-start data (Ipopt runs on one
    /// rank only).
    void
    save_state(OutputArchive &archive, MeshState &mesh) const override;
    void
    load_state(InputArchive &archive, MeshState &mesh) override;

  private:
    /// Re-initialise the Hessian with the contact couplings at @p u.
    void
    rebuild_pattern(const VectorType &u);

    const bool                        ipopt_stages;
    std::unique_ptr<IpoptSolver<dim>> ipopt; // with ipopt_stages
    double                            mu0     = 0.; // of the current mesh
    double                            initial_mu0 = 0.; // of the first mesh
    double                            last_mu = 0.; // of the last step
    bool                              tolerance_met = true;
    /// Ipopt stages that failed and were minimised by Newton instead.
    unsigned int                      newton_stages = 0;
  };
} // namespace Signorini
