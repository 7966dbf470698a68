#include <signorini/contact/factory.h>
#include <signorini/problem/problem.h>

namespace Signorini
{
  template <int dim>
  Problem<dim>::Problem(const Parameters::Scene &parameters, Scene<dim> &scene)
    : scene(scene)
    , energy(std::make_unique<EnergyFunctional<dim>>(scene.dof_handler,
                                                    *scene.mapping,
                                                    scene.materials,
                                                    scene.bc))
    , contact(Contact::create_model<dim>(parameters.contact,
                                         scene.dof_handler,
                                         *scene.mapping))
    , friction_parameters(parameters.contact.friction)
    , incompressible_ids(parameters.incompressible_ids())
  {}

  template <int dim>
  void
  Problem<dim>::setup_constraints()
  {
    if (!incompressible_ids.empty())
      incompressibility = std::make_unique<Incompressibility<dim>>(
        scene.dof_handler, *scene.mapping, incompressible_ids);
    if (contact && friction_parameters.active() && !friction)
      friction = Contact::create_friction_term<dim>(friction_parameters, *contact);
  }

  template struct Problem<2>;
  template struct Problem<3>;
} // namespace Signorini
