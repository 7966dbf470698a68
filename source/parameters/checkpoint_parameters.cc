#include <signorini/parameters/checkpoint_parameters.h>

namespace Signorini
{
  void
  CheckpointParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Checkpoint");
    prm.declare_entry("Write checkpoints",
                      "auto",
                      Patterns::Selection("auto|true|false"),
                      "Save the state of the run every 'Every load steps' "
                      "converged load steps or refinement cycles, or every "
                      "'Every minutes' of wall time, whichever comes first, "
                      "so that 'signorini --restart DIR' continues it. auto: "
                      "only for runs that declare at least 'Automatic from "
                      "load steps' load steps or have at least 'Automatic "
                      "from DoFs' DoFs. A SIGINT or SIGTERM always writes a "
                      "checkpoint of the last converged step.");
    prm.declare_entry("Every load steps",
                      "10",
                      Patterns::Integer(1),
                      "Converged load steps (or refinement cycles) between "
                      "two checkpoints.");
    prm.declare_entry("Every minutes",
                      "10",
                      Patterns::Double(0.),
                      "Wall time [min] after which the next converged step "
                      "writes a checkpoint; 0: by load steps only.");
    prm.declare_entry("Automatic from load steps",
                      "50",
                      Patterns::Integer(1),
                      "With 'Write checkpoints = auto': the declared number "
                      "of load steps from which checkpoints are written.");
    prm.declare_entry("Automatic from DoFs",
                      "200000",
                      Patterns::Integer(1),
                      "With 'Write checkpoints = auto': the number of DoFs "
                      "from which checkpoints are written.");
    prm.declare_entry("Keep",
                      "2",
                      Patterns::Integer(1, 100),
                      "How many of the newest checkpoints are kept.");
    prm.leave_subsection();
  }

  void
  CheckpointParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Checkpoint");
    const std::string m = prm.get("Write checkpoints");
    mode            = (m == "true" ? Mode::on : m == "false" ? Mode::off : Mode::automatic);
    every_steps     = prm.get_integer("Every load steps");
    every_minutes   = prm.get_double("Every minutes");
    automatic_steps = prm.get_integer("Automatic from load steps");
    automatic_dofs  = prm.get_integer("Automatic from DoFs");
    keep            = prm.get_integer("Keep");
    prm.leave_subsection();
  }

  bool
  CheckpointParameters::enabled(const unsigned int       n_steps,
                                const unsigned long long n_dofs) const
  {
    switch (mode)
      {
        case Mode::on:
          return true;
        case Mode::off:
          return false;
        default:
          return n_steps >= automatic_steps || n_dofs >= automatic_dofs;
      }
  }
} // namespace Signorini
