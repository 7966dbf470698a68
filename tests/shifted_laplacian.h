// The matrix of the direct solver tests: the 1D Laplacian -u'' with a
// stencil of half-width @p width, plus @p shift on the diagonal; n unknowns,
// the rows @p owned on this rank (all of them on one rank). With width 1
// its eigenvalues are 2 + shift - 2 cos(k pi / (n + 1)), k = 1..n.
#pragma once

#include <signorini/types.h>

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <algorithm>

inline void
shifted_laplacian(Signorini::MatrixType   &A,
                  const dealii::IndexSet &owned,
                  const unsigned int      width,
                  const double            shift)
{
  const unsigned int             n = owned.size();
  dealii::DynamicSparsityPattern pattern(n, n, owned);
  for (const auto i : owned)
    for (unsigned int j = (i >= width ? i - width : 0);
         j <= std::min<unsigned int>(n - 1, i + width);
         ++j)
      pattern.add(i, j);
  A.reinit(owned, owned, pattern, MPI_COMM_WORLD);
  for (const auto i : owned)
    {
      A.set(i, i, 2. * width + shift);
      for (unsigned int k = 1; k <= width; ++k)
        {
          if (i >= k)
            A.set(i, i - k, -1.);
          if (i + k < n)
            A.set(i, i + k, -1.);
        }
    }
  A.compress(dealii::VectorOperation::insert);
}
