#pragma once

#include <deal.II/base/parameter_handler.h>

namespace Signorini
{
  using namespace dealii;

  /**
   * The "Checkpoint" subsection: when a run saves its state so that
   * `signorini --restart DIR` can continue it (doc/robustness.md).
   *
   * A checkpoint is the folder DIR/checkpoints/checkpoint-NNNNNN with the
   * mesh (p4est's save, mesh*) with, attached cell by cell, the solution,
   * the state the Hessian's pattern was built at and the state that lives
   * on nodes and cells (a MeshState: the contact model's nodal forces, the
   * interior point method's multipliers on the contact nodes and on the
   * incompressible cells); each rank's state file (state-R.bin: load-step
   * time and size, the report so far, the parts' state that is the same
   * on every rank (penalty, barrier, broad-phase counters, output series;
   * Ipopt's multipliers, Ipopt running on one rank), then this rank's
   * entries of the vectors and fields); and the parameters it ran with
   * (parameters.prm). `signorini --restart` continues it on any number of
   * ranks (Simulator::restore(), doc/robustness.md). It is written under
   * a temporary name and renamed when complete; the newest 'Keep'
   * checkpoints are kept. A checkpoint is always written when the run is
   * interrupted by SIGINT or SIGTERM, whatever these settings say.
   */
  struct CheckpointParameters
  {
    enum class Mode
    {
      automatic,
      on,
      off
    };
    Mode               mode            = Mode::automatic;
    unsigned int       every_steps     = 10;
    double             every_minutes   = 10.;
    unsigned int       automatic_steps = 50;
    unsigned long long automatic_dofs  = 200000;
    unsigned int       keep            = 2;

    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);

    /// Whether periodic checkpoints are written for a run of @p n_steps
    /// load steps and @p n_dofs DoFs.
    bool
    enabled(const unsigned int n_steps, const unsigned long long n_dofs) const;
  };
} // namespace Signorini
