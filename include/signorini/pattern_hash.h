#pragma once

#include <cstddef>

class Epetra_CrsMatrix;

namespace Signorini
{
  /**
   * A hash of the local structure of @p A: the global indices of its row
   * and column maps, its row lengths and the local column indices of every
   * locally stored row. Two matrices with equal hashes have (with
   * overwhelming probability) the same pattern on this rank, so a symbolic
   * factorisation, an AMG hierarchy or kept entry positions still apply.
   * Local: compare it on every rank. Costs one pass over the column
   * indices (eight independent lanes) and one over the maps' elements.
   */
  std::size_t
  sparsity_pattern_hash(const Epetra_CrsMatrix &A);
} // namespace Signorini
