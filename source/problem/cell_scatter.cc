#include <signorini/pattern_hash.h>
#include <signorini/problem/cell_scatter.h>

#include <Epetra_CrsMatrix.h>
#include <Epetra_FEVector.h>

#include <algorithm>
#include <string>

namespace Signorini
{
  void
  CellScatter::begin(MatrixType                      *matrix_,
                     VectorType                      *vector_,
                     const AffineConstraints<double> &constraints_,
                     const IndexSet                  &owned_,
                     const unsigned int               n_cells,
                     const unsigned int               dofs_per_cell_)
  {
    constraints = &constraints_;
    owned       = &owned_;
    enabled     = false;
    if (matrix_ == nullptr || vector_ == nullptr ||
        !matrix_->trilinos_matrix().Filled())
      return;
    matrix = &matrix_->trilinos_matrix();
    if (matrix->ExtractCrsDataPointers(row_offsets, column_indices,
                                       matrix_values) != 0)
      return;
    // The vector's entries are addressed by the matrix's local row index:
    // both are laid out over the same locally owned DoFs.
    const Epetra_BlockMap &vector_map = vector_->trilinos_vector().Map();
    if (!vector_map.SameAs(matrix->RowMap()))
      return;
    vector_values = vector_->trilinos_vector()[0];
    linear_rows   = matrix->RowMap().LinearMap();
    first_row     = matrix->RowMap().MinMyGID64();

    const std::size_t hash = sparsity_pattern_hash(*matrix);
    if (hash != pattern_hash || dofs_per_cell_ != dofs_per_cell ||
        states.size() != n_cells)
      {
        pattern_hash  = hash;
        dofs_per_cell = dofs_per_cell_;
        states.assign(n_cells, unknown);
        rows.assign(std::size_t(n_cells) * dofs_per_cell, -1);
        slots.assign(std::size_t(n_cells) * dofs_per_cell * dofs_per_cell,
                     0);
      }
    enabled = true;
  }

  bool
  CellScatter::find_positions(
    const unsigned int                          cell_index,
    const std::vector<types::global_dof_index> &dofs)
  {
    const unsigned int n = dofs_per_cell;
    columns.resize(n);
    order.resize(n);
    for (unsigned int k = 0; k < n; ++k)
      {
        if (!owned->is_element(dofs[k]))
          return false;
        columns[k] = matrix->LCID(
          static_cast<TrilinosWrappers::types::int_type>(dofs[k]));
        if (columns[k] < 0)
          return false;
        order[k] = k;
      }
    std::sort(order.begin(), order.end(),
              [this](const unsigned int a, const unsigned int b) {
                return columns[a] < columns[b];
              });
    int          *cell_rows  = &rows[std::size_t(cell_index) * n];
    std::uint8_t *cell_slots = &slots[std::size_t(cell_index) * n * n];
    for (unsigned int i = 0; i < n; ++i)
      {
        const int row = matrix->LRID(
          static_cast<TrilinosWrappers::types::int_type>(dofs[i]));
        AssertThrow(row >= 0,
                    ExcMessage("Hessian row of DoF " + std::to_string(dofs[i]) +
                               " is not locally stored"));
        const int  begin     = row_offsets[row];
        const int  n_entries = row_offsets[row + 1] - begin;
        const int *row_columns = column_indices + begin;
        if (n_entries > 255)
          return false;
        int p = 0;
        for (unsigned int kk = 0; kk < n; ++kk)
          {
            const unsigned int k = order[kk];
            while (p < n_entries && row_columns[p] < columns[k])
              ++p;
            AssertThrow(p < n_entries && row_columns[p] == columns[k],
                        ExcMessage("the Hessian's sparsity pattern has no "
                                   "entry (" +
                                   std::to_string(dofs[i]) + ", " +
                                   std::to_string(dofs[k]) + ")"));
            cell_slots[i * n + k] = static_cast<std::uint8_t>(p);
          }
        cell_rows[i] = row;
      }
    return true;
  }

  bool
  CellScatter::add(const unsigned int                          cell_index,
                   const std::vector<types::global_dof_index> &dofs,
                   const FullMatrix<double>                   &cell_matrix,
                   const Vector<double>                       &cell_vector)
  {
    if (!enabled || states[cell_index] == general)
      return false;
    const unsigned int n = dofs_per_cell;
    AssertDimension(dofs.size(), n);
    // Constraints may change between assemblies on the same pattern.
    for (const types::global_dof_index dof : dofs)
      if (constraints->is_constrained(dof))
        return false;
    const auto same_rows = [&]() {
      // The same DoFs as when the positions were found (a renumbering on
      // an unchanged pattern would show here). deal.II's owned DoFs are one
      // contiguous range, so the local row is a subtraction.
      const int *cell_rows = &rows[std::size_t(cell_index) * n];
      for (unsigned int i = 0; i < n; ++i)
        if ((linear_rows ?
               static_cast<long long>(dofs[i]) - first_row :
               static_cast<long long>(matrix->LRID(
                 static_cast<TrilinosWrappers::types::int_type>(dofs[i])))) !=
            cell_rows[i])
          return false;
      return true;
    };
    if (states[cell_index] == unknown || !same_rows())
      {
        states[cell_index] =
          find_positions(cell_index, dofs) ? cached : general;
        if (states[cell_index] == general)
          return false;
      }
    const int          *cell_rows  = &rows[std::size_t(cell_index) * n];
    const std::uint8_t *cell_slots = &slots[std::size_t(cell_index) * n * n];
    for (unsigned int i = 0; i < n; ++i)
      {
        double *const row_values = matrix_values + row_offsets[cell_rows[i]];
        const std::uint8_t *const row_slots = cell_slots + i * n;
        for (unsigned int k = 0; k < n; ++k)
          row_values[row_slots[k]] += cell_matrix(i, k);
        vector_values[cell_rows[i]] += cell_vector(i);
      }
    return true;
  }

  std::size_t
  CellScatter::n_cached_cells() const
  {
    return std::count(states.begin(), states.end(), cached);
  }
} // namespace Signorini
