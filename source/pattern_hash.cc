#include <signorini/pattern_hash.h>

#include <Epetra_CrsMatrix.h>

#include <cstdint>

namespace Signorini
{
  std::size_t
  sparsity_pattern_hash(const Epetra_CrsMatrix &A)
  {
    // Eight FNV-style lanes, so that the pass over the column indices
    // (the bulk) is not one chain of dependent multiplications.
    constexpr std::uint64_t prime = 1099511628211ull;
    std::uint64_t           h[8];
    for (unsigned int j = 0; j < 8; ++j)
      h[j] = 1469598103934665603ull + j;
    std::uint64_t lane = 0;
    const auto    mix  = [&](const long long v) {
      std::uint64_t &x = h[lane++ & 7];
      x = (x ^ static_cast<std::uint64_t>(v)) * prime;
    };
    const Epetra_BlockMap &rows = A.RowMap();
    const Epetra_BlockMap &cols = A.ColMap();
    mix(A.NumGlobalRows64());
    mix(rows.NumMyElements());
    for (int r = 0; r < rows.NumMyElements(); ++r)
      mix(rows.GID64(r));
    mix(cols.NumMyElements());
    for (int c = 0; c < cols.NumMyElements(); ++c)
      mix(cols.GID64(c));
    const Epetra_CrsGraph &graph = A.Graph();
    for (int r = 0; r < graph.NumMyRows(); ++r)
      {
        int  n       = 0;
        int *indices = nullptr;
        graph.ExtractMyRowView(r, n, indices);
        mix(n);
        int k = 0;
        for (; k + 8 <= n; k += 8)
          for (unsigned int j = 0; j < 8; ++j)
            h[j] = (h[j] ^ static_cast<std::uint64_t>(indices[k + j])) * prime;
        for (; k < n; ++k)
          mix(indices[k]);
      }
    std::uint64_t result = 0;
    for (unsigned int j = 0; j < 8; ++j)
      result = (result ^ h[j]) * prime + j;
    return static_cast<std::size_t>(result);
  }
} // namespace Signorini
