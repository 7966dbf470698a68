// A contact model from outside the library is one class and one
// register_model() call: "test plane", a rigid plane y = Height with its
// own subsection (Contact > Test plane), written here as a user would
// write a new model. The default scene (Hertz contact on a rigid plane) is
// run with it in this process and with the built-in 'rigid foundation'
// plane by the real executable; every quantity must agree to round-off,
// the summary must name the new model, the Type selection must list it,
// and the solvers must take its capabilities (interior-point accepts it
// because it declares node-wise constraints). A second registration of a
// name is refused.

#include "run_output.h"

#include <signorini/contact/foundation.h>
#include <signorini/contact/registry.h>
#include <signorini/contact/rigid_foundation.h>
#include <signorini/driver/run.h>
#include <signorini/output/report.h>

#include <cmath>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace
{
  using namespace dealii;
  using namespace Signorini;

  /// The new model: a rigid foundation whose plane comes from its own entry.
  template <int dim>
  class TestPlane : public Contact::RigidFoundation<dim>
  {
  public:
    using Contact::RigidFoundation<dim>::RigidFoundation;

    std::string
    type_name() const override
    {
      return "test plane";
    }
  };

  template <int dim>
  std::unique_ptr<Contact::Model<dim>>
  create_test_plane(const Contact::ModelParameters &parameters,
                    const types::boundary_id        boundary_id,
                    const DoFHandler<dim>          &dof_handler,
                    const Mapping<dim>             &mapping)
  {
    Contact::FoundationParameters plane;
    plane.shape  = Contact::FoundationParameters::Shape::plane;
    plane.height = Contact::parsed<double>(parameters);
    plane.slope.assign(dim - 1, 0.);
    plane.context = "Contact > Test plane";
    return std::make_unique<TestPlane<dim>>(Contact::Foundation<dim>::create(plane),
                                            boundary_id,
                                            dof_handler,
                                            mapping);
  }

  Contact::ModelEntry
  test_plane_model()
  {
    Contact::ModelEntry entry;
    entry.name = "test plane";
    entry.help = "test plane: a rigid plane y = Height (tests/contact_registration).";
    entry.capabilities.node_wise_constraints = true;
    entry.declare_parameters                 = [](ParameterHandler &prm) {
      prm.enter_subsection("Test plane");
      prm.declare_entry("Height", "0", Patterns::Double(), "The plane's height.");
      prm.leave_subsection();
    };
    entry.parse_parameters = [](ParameterHandler &prm, const unsigned int) {
      prm.enter_subsection("Test plane");
      const double height = prm.get_double("Height");
      prm.leave_subsection();
      return std::make_shared<const Contact::ParsedParameters<double>>(height);
    };
    entry.create_2d = create_test_plane<2>;
    entry.create_3d = create_test_plane<3>;
    return entry;
  }

  void
  write_scene(const std::string &file, const std::string &type, const std::string &output)
  {
    std::ofstream(file) << "include " << SIGNORINI_SOURCE_DIR << "/prm/default.prm\n"
                        << "set Output directory = " << output << "\n"
                        << "subsection Output\n  set Format = none\nend\n"
                        << "subsection Contact\n  set Type = " << type << "\n"
                        // Only this process knows the new model's entries.
                        << (type == "test plane" ?
                              "  subsection Test plane\n    set Height = 0\n  end\n" :
                              "")
                        << "end\n";
  }
} // namespace

int
main()
{
  std::ofstream out("output");

  // The one registration line.
  Contact::register_model(test_plane_model());

  try
    {
      Contact::register_model(test_plane_model());
      out << "second registration of 'test plane': accepted (NO)\n";
    }
  catch (const std::logic_error &)
    {
      out << "second registration of 'test plane': refused\n";
    }

  {
    ParameterHandler prm;
    declare_parameters(prm);
    prm.enter_subsection("Contact");
    bool listed = true;
    try
      {
        prm.set("Type", "test plane");
      }
    catch (const std::exception &)
      {
        listed = false;
      }
    prm.leave_subsection();
    out << "Contact > Type accepts 'test plane': " << (listed ? "yes" : "NO") << "\n";
  }

  // The built-in plane, by the real executable.
  write_scene("builtin.prm", "rigid foundation", "builtin");
  const auto [code, text] =
    RunOutput::execute(std::string(SIGNORINI_EXECUTABLE) + " builtin.prm 2>&1");
  out << "built-in rigid foundation: exit code " << code << "\n";
  if (code != 0)
    out << text << "\n";

  // The registered model, in this process.
  write_scene("registered.prm", "test plane", "registered");
  std::vector<Quantity> registered;
  std::string           status;
  char                  program[] = "signorini";
  char                  scene[]   = "registered.prm";
  char                 *arguments[] = {program, scene, nullptr};
  const int exit_code = run_program(2, arguments, /*quiet=*/true, [&](const Report &report) {
    registered = report.quantities;
    status     = report.status;
  });
  out << "test plane: exit code " << exit_code << ", status " << status << "\n";

  const std::string summary = RunOutput::read_text("registered/summary.json");
  out << "summary names the model: "
      << (summary.find("\"type\": \"test plane\"") != std::string::npos ? "yes" : "NO") << "\n";

  unsigned int compared = 0, differ = 0;
  for (const auto &q : registered)
    {
      const double builtin = RunOutput::summary_quantity("builtin/summary.json", q.name);
      const double scale   = std::max({std::abs(builtin), std::abs(q.value), 1e-300});
      ++compared;
      if (!(std::abs(builtin - q.value) <= 1e-12 * scale))
        {
          ++differ;
          out << "  " << q.name << ": test plane " << q.value << ", built-in " << builtin
              << "\n";
        }
    }
  out << "quantities compared: " << (compared >= 8 ? "at least 8" : "too few")
      << ", differing by more than 1e-12: " << differ << "\n";
  return 0;
}
