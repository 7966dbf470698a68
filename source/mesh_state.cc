#include <signorini/mesh_state.h>

#include <algorithm>
#include <stdexcept>
#include <string>

namespace Signorini
{
  void
  MeshState::save_dof_field(const std::vector<types::global_dof_index> &dofs,
                            const std::vector<double>                  &values)
  {
    if (dofs.size() != values.size())
      throw std::logic_error("MeshState: " + std::to_string(values.size()) +
                             " values for " + std::to_string(dofs.size()) + " DoFs");
    DofEntries entries(dofs.size());
    for (std::size_t i = 0; i < dofs.size(); ++i)
      entries[i] = {dofs[i], values[i]};
    // A DoF twice would keep only one of its values in the transferred
    // vector: the layouts that call this have one value per DoF.
    std::sort(entries.begin(), entries.end());
    for (std::size_t i = 1; i < entries.size(); ++i)
      if (entries[i].first == entries[i - 1].first)
        throw std::logic_error("MeshState: DoF " + std::to_string(entries[i].first) +
                               " twice in one field");
    dof_entries.push_back(std::move(entries));
  }

  void
  MeshState::save_cell_field(const std::vector<unsigned int> &cells,
                             const std::vector<double>       &values)
  {
    if (cells.size() != values.size())
      throw std::logic_error("MeshState: " + std::to_string(values.size()) +
                             " values for " + std::to_string(cells.size()) + " cells");
    CellEntries entries(cells.size());
    for (std::size_t i = 0; i < cells.size(); ++i)
      entries[i] = {cells[i], values[i]};
    cell_entries.push_back(std::move(entries));
  }

  std::vector<VectorType>
  MeshState::dof_vectors(const IndexSet &owned, const MPI_Comm comm) const
  {
    std::vector<VectorType> vectors(dof_entries.size());
    for (std::size_t f = 0; f < dof_entries.size(); ++f)
      {
        vectors[f].reinit(owned, comm);
        for (const auto &[dof, value] : dof_entries[f])
          vectors[f][dof] = value;
        vectors[f].compress(VectorOperation::insert);
      }
    return vectors;
  }

  std::vector<Vector<double>>
  MeshState::cell_vectors(const unsigned int n_active_cells) const
  {
    std::vector<Vector<double>> vectors(cell_entries.size(),
                                        Vector<double>(n_active_cells));
    for (std::size_t f = 0; f < cell_entries.size(); ++f)
      for (const auto &[cell, value] : cell_entries[f])
        vectors[f][cell] = value;
    return vectors;
  }

  std::vector<double>
  MeshState::load_dof_field(const std::vector<types::global_dof_index> &dofs)
  {
    if (next_dof_field >= dof_fields.size())
      throw std::runtime_error("the checkpoint holds " +
                               std::to_string(dof_fields.size()) +
                               " fields on DoFs, the restarted run reads more");
    const VectorType   &field = dof_fields[next_dof_field++];
    std::vector<double> values(dofs.size());
    for (std::size_t i = 0; i < dofs.size(); ++i)
      values[i] = field[dofs[i]];
    return values;
  }

  std::vector<double>
  MeshState::load_cell_field(const std::vector<unsigned int> &cells)
  {
    if (next_cell_field >= cell_fields.size())
      throw std::runtime_error("the checkpoint holds " +
                               std::to_string(cell_fields.size()) +
                               " fields on cells, the restarted run reads more");
    const Vector<double> &field = cell_fields[next_cell_field++];
    std::vector<double>   values(cells.size());
    for (std::size_t i = 0; i < cells.size(); ++i)
      values[i] = field[cells[i]];
    return values;
  }
} // namespace Signorini
