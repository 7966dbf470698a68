#include <signorini/parameters/study_parameters.h>

#include <string>

namespace Signorini
{
  namespace Study
  {
    using namespace dealii;

    void
    declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Study");
      prm.declare_entry("Quantities",
                        "",
                        Patterns::List(Patterns::Anything()),
                        "The quantities of the scene (names in summary.json) "
                        "whose errors the study reports, e.g. hertz_a, "
                        "hertz_p0. Only read by signorini --study.");
      prm.declare_entry("Reported quantities",
                        "",
                        Patterns::List(Patterns::Anything()),
                        "Further quantities written to study.csv and the "
                        "tables as they are, outside the accuracy check: "
                        "e.g. hertz_pressure_l2_error, itself the error of "
                        "the pressure profile against Hertz's.");
      prm.declare_entry("Reference variant",
                        "",
                        Patterns::Anything(),
                        "The variant (its Name) whose finest runs give the "
                        "converged solution of the discrete model: Richardson "
                        "extrapolation of its three finest runs when they "
                        "converge monotonically, else its finest run.");
      prm.declare_entry("Accuracy",
                        "0.001",
                        Patterns::Double(0.),
                        "The relative error (against the converged model) at "
                        "which the study reports, per variant, the first run "
                        "reaching it for every quantity: its DoFs and wall "
                        "time [-].");
      prm.declare_entry("Write fields",
                        "false",
                        Patterns::Bool(),
                        "Write the VTU fields of every run (costs time that "
                        "the study then counts).");
      for (unsigned int v = 0; v < max_variants; ++v)
        {
          prm.enter_subsection("Variant " + std::to_string(v + 1));
          prm.declare_entry("Name", "", Patterns::Anything(),
                            "The variant's name; empty: not run.");
          prm.declare_entry("Settings",
                            "",
                            Patterns::Anything(),
                            "Overrides of the scene's entries for this "
                            "variant: 'Subsection/Entry = value; ...', e.g. "
                            "'Solver/Method = ipopt; Mesh refinement/Number "
                            "of cycles = 0'.");
          prm.declare_entry("Series entry",
                            "",
                            Patterns::Anything(),
                            "The entry whose values make the series, e.g. "
                            "'Mesh/Global refinements'; empty: one run (whose "
                            "refinement cycles, if any, make the series).");
          prm.declare_entry("Series values",
                            "",
                            Patterns::List(Patterns::Anything()),
                            "The values of the series entry, coarsest first.");
          prm.leave_subsection();
        }
      prm.leave_subsection();
    }
  } // namespace Study
} // namespace Signorini
