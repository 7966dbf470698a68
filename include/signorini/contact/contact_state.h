#pragma once

#include <signorini/archive.h>
#include <signorini/mesh_state.h>
#include <signorini/types.h>

#include <deal.II/base/exceptions.h>

#include <string>
#include <utility>
#include <vector>

namespace Signorini
{
  namespace Contact
  {
    /**
     * The state role of a contact model: what it carries from one load
     * step to the next and a checkpoint keeps. That is the nodal contact
     * forces of the last converged solve (their layout is the model's:
     * one number per node for a rigid foundation, dim for two bodies),
     * and whatever a model adds in save_state()/load_state(). Solvers
     * hand forces over with set_contact_forces(), never by writing into
     * forces().
     */
    class ContactState
    {
    public:
      virtual ~ContactState() = default;

      /// The nodal contact forces of the last converged solve (read only:
      /// they change through set_contact_forces()).
      const std::vector<double> &
      forces() const
      {
        return nodal_forces;
      }

      /**
       * Take the nodal contact forces of a converged solve, in the layout
       * of forces(): the interior point method's multipliers, Ipopt's
       * (max(-lambda_k, 0)), the penalty continuation's record, or the
       * record from before a load step that is cut. This is the one way
       * forces enter a model from outside (a model's setup() resets them
       * and load_state() reads them from a checkpoint), and where a term
       * that lags the normal force (friction) will take it.
       */
      void
      set_contact_forces(std::vector<double> forces)
      {
        AssertThrow(forces.size() == nodal_forces.size(),
                    dealii::ExcMessage("contact forces of " + std::to_string(forces.size()) +
                                       " entries for a model whose record has " +
                                       std::to_string(nodal_forces.size())));
        nodal_forces = std::move(forces);
      }

      /// The DoF each entry of the nodal forces belongs to (this rank's
      /// nodes): the force's component on that node.
      virtual std::vector<types::global_dof_index>
      force_dofs() const = 0;

      /**
       * Save the state into a checkpoint: the nodal forces as a field on
       * their DoFs into @p mesh (force_dofs()), and what a model adds (into
       * @p archive only what is the same on every rank). load_state()
       * reads it back after the DoFs of the restarted run's mesh are set
       * up, on any number of ranks.
       */
      virtual void
      save_state(OutputArchive &archive, MeshState &mesh) const;
      virtual void
      load_state(InputArchive &archive, MeshState &mesh);

    protected:
      std::vector<double> nodal_forces;
    };
  } // namespace Contact
} // namespace Signorini
