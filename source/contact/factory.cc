#include <signorini/contact/factory.h>
#include <signorini/contact/registry.h>
#include <signorini/input_error.h>

#include <algorithm>

namespace Signorini
{
  namespace Contact
  {
    template <int dim>
    std::unique_ptr<Model<dim>>
    create_model(const Parameters::ContactSection &parameters,
                 const DoFHandler<dim>            &dof_handler,
                 const Mapping<dim>               &mapping)
    {
      const ModelEntry *entry = parameters.model;
      if (!entry)
        return nullptr;
      // The boundaries the model acts on must exist (collective).
      std::vector<NamedBoundaryId> ids;
      if (entry->capabilities.contact_boundary_id)
        ids.push_back({"Contact boundary id", parameters.boundary_id});
      if (entry->boundary_ids)
        for (const auto &id : entry->boundary_ids(*parameters.model_parameters))
          ids.push_back(id);
      const auto mesh_ids = dof_handler.get_triangulation().get_boundary_ids();
      for (const auto &[key, id] : ids)
        if (std::find(mesh_ids.begin(), mesh_ids.end(), id) == mesh_ids.end())
          throw InputError("Contact > " + key,
                           "boundary id " + std::to_string(id) +
                             " does not exist in the mesh");
      std::unique_ptr<Model<dim>> model;
      if constexpr (dim == 2)
        model = entry->create_2d(*parameters.model_parameters, parameters.boundary_id,
                                 dof_handler, mapping);
      else
        model = entry->create_3d(*parameters.model_parameters, parameters.boundary_id,
                                 dof_handler, mapping);
      // The solver table reads the capability before any model exists: the
      // model must keep the entry's promise.
      AssertThrow(bool(model->node_wise_constraints()) ==
                    entry->capabilities.node_wise_constraints,
                  ExcMessage("contact model '" + entry->name +
                             "': its registry entry and its node_wise_constraints() "
                             "disagree on whether it has node-wise constraints"));
      return model;
    }

    template std::unique_ptr<Model<2>>
    create_model<2>(const Parameters::ContactSection &, const DoFHandler<2> &,
                    const Mapping<2> &);
    template std::unique_ptr<Model<3>>
    create_model<3>(const Parameters::ContactSection &, const DoFHandler<3> &,
                    const Mapping<3> &);
  } // namespace Contact
} // namespace Signorini
