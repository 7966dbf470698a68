#pragma once

#include <signorini/types.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/numerics/data_out.h>

#include <array>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace Signorini
{
  using namespace dealii;

  namespace Contact
  {
    /**
     * A degree-of-freedom support point on a contact boundary: its dim
     * displacement DoFs, reference position, tributary weight
     * w = int_Gamma phi ds (reference configuration), local mesh size h
     * (mean diameter of the boundary faces at the node) and its DoF in
     * the scalar output space.
     */
    template <int dim>
    struct BoundaryNode
    {
      std::array<types::global_dof_index, dim> dofs;
      Point<dim>                               X;
      double                                   weight;
      double                                   h;
      types::global_dof_index                  scalar_dof;
    };

    /**
     * The support points of the boundary faces with the given ids, and
     * nodal output fields on them. Each MPI rank holds the nodes whose
     * DoFs it owns; nodes whose DoFs are hanging are left out (they follow
     * their parents). Used by both contact models for their nodes, their
     * VTU fields and their CSV profiles.
     */
    template <int dim>
    class BoundaryNodes
    {
    public:
      BoundaryNodes(const DoFHandler<dim> &dof_handler, const Mapping<dim> &mapping);

      /// Collect the nodes (call after the DoFs are distributed).
      void
      setup(const std::set<types::boundary_id> &boundary_ids,
            const AffineConstraints<double>    &hanging_constraints);

      const std::vector<BoundaryNode<dim>> &
      nodes() const
      {
        return node_list;
      }
      /// The boundary ids of the last setup(): the faces the nodes lie on.
      const std::set<types::boundary_id> &
      boundary_ids() const
      {
        return ids;
      }
      unsigned int
      n_global() const
      {
        return n_global_nodes;
      }
      /// Hanging nodes on the boundary (left out), on all ranks.
      unsigned int
      n_hanging() const
      {
        return n_hanging_nodes;
      }
      double
      mean_mesh_size() const
      {
        return mean_h;
      }
      double
      min_mesh_size() const
      {
        return min_h;
      }

      /**
       * Add nodal scalar fields (one value per owned node for each name)
       * to @p data_out; the vectors live in this object, one per name, until
       * a later call with the same name (so that the contact's and the
       * friction's fields can be added by separate calls to one DataOut).
       */
      void
      add_fields(DataOut<dim>                           &data_out,
                 const std::vector<std::string>          &names,
                 const std::vector<std::vector<double>> &values) const;

      /// The communicator of the mesh the nodes live on.
      MPI_Comm
      get_communicator() const
      {
        return dof_handler.get_communicator();
      }

      /**
       * A nodal field (one value per owned node) as a ghosted vector on
       * scalar_dofs(), with the values of hanging nodes interpolated from
       * the nodes they follow and zero away from the boundary (collective).
       */
      VectorType
      nodal_field(const std::vector<double> &values) const;

      /// The scalar Q_p DoFs the nodal fields live on.
      const DoFHandler<dim> &
      scalar_dofs() const
      {
        return scalar_dof_handler;
      }

      /**
       * Gather @p rows (one per owned node) on rank 0, sort them and
       * write them as CSV under @p header (collective).
       */
      void
      write_csv(const std::string                      &file,
                const std::string                      &header,
                const std::vector<std::vector<double>> &rows) const;

      /**
       * The header of a contact profile: X.., x.., then @p middle, then
       * force_x.., weight and, if @p reference, reference_pressure.
       */
      static std::string
      profile_header(const std::string &middle, const bool reference);

      /// (position, value) samples of every rank, on every rank, sorted by
      /// position.
      std::vector<std::pair<Point<dim>, double>>
      gather_sorted(const std::vector<std::pair<Point<dim>, double>> &local) const;

    private:
      const DoFHandler<dim>         &dof_handler;
      const Mapping<dim>            &mapping;
      std::vector<BoundaryNode<dim>> node_list;
      std::set<types::boundary_id>   ids;
      unsigned int                   n_global_nodes = 0;
      unsigned int                   n_hanging_nodes  = 0;
      double                         mean_h         = 0.;
      double                         min_h          = 0.;

      std::unique_ptr<FE_Q<dim>> scalar_fe;
      DoFHandler<dim>            scalar_dof_handler;
      AffineConstraints<double>  scalar_hanging;
      /// The vectors of the fields added last under each name, which
      /// DataOut reads when it builds patches (a map: its elements stay in
      /// place as others are added): a cache of the output, not state.
      mutable std::map<std::string, VectorType> fields;
    };
  } // namespace Contact
} // namespace Signorini
