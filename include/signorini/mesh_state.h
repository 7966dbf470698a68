#pragma once

#include <signorini/types.h>

#include <deal.II/base/index_set.h>
#include <deal.II/base/types.h>
#include <deal.II/lac/vector.h>

#include <utility>
#include <vector>

namespace Signorini
{
  using namespace dealii;

  /**
   * The part of a run's state that lives on the mesh rather than on every
   * rank alike: values on displacement DoFs (the contact model's nodal
   * forces, the interior point method's multipliers, each at its node's
   * DoFs) and values on active cells (the multipliers of the
   * incompressibility constraints). Each rank holds only its own nodes and
   * cells, in an order that depends on the partition, so a checkpoint
   * cannot keep them as plain per-rank lists if it is to be restarted on
   * another number of ranks. Here they become fields: one vector on the
   * scene's DoFs or one value per active cell, which the checkpoint keeps
   * with the mesh and transfers cell by cell, like the solution
   * (Scene::save(), Scene::load_fields()).
   *
   * Saving (Simulator::snapshot()): each part adds its fields in a fixed
   * order with save_dof_field() and save_cell_field(). Loading
   * (Simulator::restore()): each part reads them back in the same order
   * with load_dof_field() and load_cell_field(), at its DoFs and cells of
   * the restarted run's mesh.
   */
  class MeshState
  {
  public:
    /// One field on DoFs: (DoF, value) of this rank's entries.
    using DofEntries = std::vector<std::pair<types::global_dof_index, double>>;
    /// One field on cells: (active cell index, value) of this rank's
    /// locally owned cells.
    using CellEntries = std::vector<std::pair<unsigned int, double>>;

    /// Add a field with @p values[i] at DoF @p dofs[i] (each DoF once, owned
    /// by this rank).
    void
    save_dof_field(const std::vector<types::global_dof_index> &dofs,
                   const std::vector<double>                  &values);

    /// Add a field with @p values[i] on the locally owned active cell with
    /// index @p cells[i].
    void
    save_cell_field(const std::vector<unsigned int> &cells,
                    const std::vector<double>       &values);

    /// The next field on DoFs, read at @p dofs (locally owned).
    std::vector<double>
    load_dof_field(const std::vector<types::global_dof_index> &dofs);

    /// The next field on cells, read on the active cells @p cells.
    std::vector<double>
    load_cell_field(const std::vector<unsigned int> &cells);

    /// The saved fields on DoFs as locally owned vectors with @p owned
    /// (this rank's entries set, the rest zero).
    std::vector<VectorType>
    dof_vectors(const IndexSet &owned, const MPI_Comm comm) const;

    /// The saved fields on cells as vectors of @p n_active_cells values.
    std::vector<Vector<double>>
    cell_vectors(const unsigned int n_active_cells) const;

    /// The fields saved, this rank's entries.
    std::vector<DofEntries>  dof_entries;
    std::vector<CellEntries> cell_entries;

    /// The fields to load from, on the restarted run's mesh: locally owned
    /// DoF vectors, and cell vectors indexed by active cell index.
    std::vector<VectorType>     dof_fields;
    std::vector<Vector<double>> cell_fields;

  private:
    unsigned int next_dof_field  = 0;
    unsigned int next_cell_field = 0;
  };
} // namespace Signorini
