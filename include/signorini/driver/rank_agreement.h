#pragma once

#include <mpi.h>

namespace Signorini
{
  /**
   * Whether an error that ended one rank's run ended every rank's.
   *
   * An exception thrown on some ranks only (a file one rank cannot read,
   * a failed allocation) leaves the other ranks waiting in a collective
   * operation that the failed ones will never join: without a check, the
   * run hangs until the batch system kills it, often without a word
   * (only rank 0 prints). The driver asks this after catching an error:
   * if every rank caught one, the ranks report and exit as usual; if not,
   * the failed rank prints its error and aborts the whole MPI job.
   *
   * The check is an MPI_Ibarrier on a communicator of its own (so that it
   * never pairs with the collectives of the computation), polled until
   * the time limit.
   */
  namespace RankAgreement
  {
    /// Collective on MPI_COMM_WORLD, once, right after MPI_Init.
    void
    initialize();

    /**
     * Called by a rank that failed: whether every rank of MPI_COMM_WORLD
     * called it too within @p seconds. true at once on one rank (and
     * before initialize()).
     */
    bool
    all_ranks_failed(const double seconds);

    /// The time the driver gives the other ranks to fail too [s].
    constexpr double default_wait = 10.;
  } // namespace RankAgreement
} // namespace Signorini
