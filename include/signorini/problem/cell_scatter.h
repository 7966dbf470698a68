#pragma once

#include <signorini/types.h>

#include <deal.II/base/index_set.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace Signorini
{
  using namespace dealii;

  /**
   * Adds cells' local matrices and vectors straight into the locally owned
   * rows of a Trilinos matrix and vector, for the cells none of whose DoFs
   * is constrained and all of whose DoFs are locally owned (all but the
   * cells at Dirichlet boundaries, hanging nodes and partition
   * boundaries); add() returns false for any other cell, which then takes
   * AffineConstraints::distribute_local_to_global.
   *
   * The first time a cell is added, the position of each of its n x n
   * entries in the matrix's compressed row storage is found (the local
   * row, and the slot within the row, by one merge of the cell's sorted
   * column indices with the row's) and kept: every later assembly adds
   * the entries through those positions, without Epetra's global-to-local
   * lookups, binary searches or any sorting. The positions are kept while
   * the matrix's local structure stays the same (begin() compares a hash
   * of its row and column maps and of its column indices, one pass over
   * the pattern) and are forgotten when it changes (new sparsity pattern
   * for two-body contact couplings, refinement, repartitioning).
   *
   * Each entry receives the same values in the same cell order as through
   * distribute_local_to_global, so the sums are bitwise identical.
   * Memory: per cell n row indices (4 bytes) and n x n one-byte slots
   * (Q1: 96 bytes per cell in 2D, 672 in 3D); a cell with a row of more
   * than 255 entries takes the general path.
   */
  class CellScatter
  {
  public:
    /**
     * Prepares one assembly into @p matrix and @p vector over a mesh of
     * @p n_cells active cells (indexed by active_cell_index()) with
     * @p dofs_per_cell DoFs each. With either pointer null, or a matrix
     * whose storage is not compressed, add() returns false for every cell.
     */
    void
    begin(MatrixType                      *matrix,
          VectorType                      *vector,
          const AffineConstraints<double> &constraints,
          const IndexSet                  &owned,
          unsigned int                     n_cells,
          unsigned int                     dofs_per_cell);

    /**
     * Adds cell @p cell_index's local matrix and vector, whose DoFs are
     * @p dofs, and returns true; or returns false and adds nothing if the
     * cell must take the general path.
     */
    bool
    add(unsigned int                                cell_index,
        const std::vector<types::global_dof_index> &dofs,
        const FullMatrix<double>                   &cell_matrix,
        const Vector<double>                       &cell_vector);

    /// Cells whose positions are kept (for tests and memory reports).
    std::size_t
    n_cached_cells() const;

  private:
    /// Finds and keeps the positions of the cell's entries; false if the
    /// cell cannot take the direct path.
    bool
    find_positions(unsigned int                                cell_index,
                   const std::vector<types::global_dof_index> &dofs);

    enum State : std::uint8_t
    {
      unknown,
      cached,
      general
    };

    const AffineConstraints<double> *constraints = nullptr;
    const IndexSet                  *owned       = nullptr;
    bool                             enabled     = false;
    const Epetra_CrsMatrix          *matrix      = nullptr;
    double                          *vector_values = nullptr;
    bool                             linear_rows   = false;
    long long                        first_row     = 0;
    int                             *row_offsets   = nullptr;
    int                             *column_indices = nullptr;
    double                          *matrix_values  = nullptr;

    std::size_t               pattern_hash  = 0;
    unsigned int              dofs_per_cell = 0;
    std::vector<State>        states;
    std::vector<int>          rows;
    std::vector<std::uint8_t> slots;

    std::vector<int>          columns;
    std::vector<unsigned int> order;
  };
} // namespace Signorini
