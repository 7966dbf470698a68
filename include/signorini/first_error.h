#pragma once

#include <mpi.h>

#include <string>

namespace Signorini
{
  /**
   * The error of the lowest rank of @p comm whose @p error is not empty,
   * on every rank; empty if no rank has one. Collective. For work that each
   * rank does on its own (its own file) and that may fail on some ranks
   * only: every rank then stops with the same message instead of the
   * others going on into a collective operation the failed ones skip.
   */
  std::string
  first_error(const MPI_Comm comm, const std::string &error);
} // namespace Signorini
