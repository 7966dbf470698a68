#pragma once

#include <signorini/contact/model.h>
#include <signorini/parameters/scene_parameters.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>

#include <memory>

namespace Signorini
{
  namespace Contact
  {
    /**
     * The contact model that @p parameters declare (Contact > Type, a
     * registered model: contact/registry.h), on the DoFs of
     * @p dof_handler; null for Type = none. InputError if a boundary id
     * it names is not in the mesh.
     */
    template <int dim>
    std::unique_ptr<Model<dim>>
    create_model(const Parameters::ContactSection &parameters,
                 const DoFHandler<dim>            &dof_handler,
                 const Mapping<dim>               &mapping);
  } // namespace Contact
} // namespace Signorini
