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
    int contiguous = 1;
    for (int r = 0; r < n && contiguous; ++r)
      contiguous = A.RowMap().GID64(r) == first + r;
    MPI_Allreduce(MPI_IN_PLACE, &contiguous, 1, MPI_INT, MPI_MIN, comm);
    return contiguous ? first : -1;
  }
} // namespace Signorini
