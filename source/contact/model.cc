#include <signorini/archive_io.h>
#include <signorini/contact/model.h>

namespace Signorini
{
  namespace Contact
  {
    template <int dim>
    void
    Model<dim>::save_state(OutputArchive &archive) const
    {
      archive << nodal_forces;
    }

    template <int dim>
    void
    Model<dim>::load_state(InputArchive &archive)
    {
      std::vector<double> forces;
      archive >> forces;
      // The checkpoint's mesh, the same ranks: the same contact nodes.
      AssertThrow(forces.size() == nodal_forces.size() || nodal_forces.empty(),
                  ExcMessage("the checkpoint has " + std::to_string(forces.size()) +
                             " contact nodes on this rank, the restarted run " +
                             std::to_string(nodal_forces.size())));
      nodal_forces = std::move(forces);
    }

    template class Model<2>;
    template class Model<3>;
  } // namespace Contact
} // namespace Signorini
