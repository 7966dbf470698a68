#pragma once

#include <Epetra_CrsMatrix.h>
#include <mpi.h>
#include <petscsys.h>

#include <stdexcept>
#include <string>

namespace Signorini
{
  /// A PETSc call that failed (not a failed factorisation, which PETSc
  /// reports as the factor's error type): throw with PETSc's message.
  inline void
  check_petsc(const PetscErrorCode code, const char *what)
  {
    if (code == 0)
      return;
    const char *text = nullptr;
    PetscErrorMessage(code, &text, nullptr);
    throw std::runtime_error(std::string("PETSc ") + what + " failed: " +
                             (text ? text : "error " + std::to_string(code)));
  }

  /// Whether @p v holds on every rank of @p comm (collective).
  inline bool
  on_all_ranks(const MPI_Comm comm, const bool v)
  {
    int local = v ? 1 : 0, global = 0;
    MPI_Allreduce(&local, &global, 1, MPI_INT, MPI_MIN, comm);
    return global == 1;
  }

  /**
   * The global index of this rank's first row of @p A if the rows every
   * rank owns are one contiguous range in rank order, as PETSc's parallel
   * matrices need (deal.II's DoF numbering on a distributed mesh gives
   * that; it is checked rather than assumed); -1 on every rank otherwise.
   * Collective.
   */
  inline long long
  first_owned_row(const Epetra_CrsMatrix &A, const MPI_Comm comm)
  {
    const int n     = A.NumMyRows();
    long long first = 0, mine = n;
    MPI_Exscan(&mine, &first, 1, MPI_LONG_LONG, MPI_SUM, comm);
    int rank = 0;
    MPI_Comm_rank(comm, &rank);
    if (rank == 0)
      first = 0;
    bool contiguous = true;
    for (int r = 0; r < n && contiguous; ++r)
      contiguous = A.RowMap().GID64(r) == first + r;
    return on_all_ranks(comm, contiguous) ? first : -1;
  }
} // namespace Signorini
