#include <signorini/archive_io.h>
#include <signorini/contact/contact_state.h>

namespace Signorini
{
  namespace Contact
  {
    void
    ContactState::save_state(OutputArchive &archive, MeshState &mesh) const
    {
      (void)archive;
      mesh.save_dof_field(force_dofs(), nodal_forces);
    }

    void
    ContactState::load_state(InputArchive &archive, MeshState &mesh)
    {
      (void)archive;
      const auto dofs = force_dofs();
      AssertThrow(dofs.size() == nodal_forces.size(),
                  ExcMessage("the contact model's forces and their DoFs differ in size"));
      nodal_forces = mesh.load_dof_field(dofs);
    }
  } // namespace Contact
} // namespace Signorini
