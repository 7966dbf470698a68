// RankAgreement (driver/rank_agreement.h): the driver's check, after an
// error, that every rank failed with it. On 1 rank it holds at once. On 2
// ranks: both ranks asking agree at once; rank 1 asking alone sees, after
// the time limit, that rank 0 did not fail, and rank 0, which asks later,
// completes the same check (the two requests pair on the agreement's own
// communicator, never with the computation's collectives: a barrier on
// MPI_COMM_WORLD in between is not mistaken for it).

#include <signorini/driver/rank_agreement.h>

#include <deal.II/base/mpi.h>

#include <chrono>
#include <fstream>
#include <string>

using namespace dealii;
using namespace Signorini;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  RankAgreement::initialize();
  const MPI_Comm     comm    = MPI_COMM_WORLD;
  const unsigned int rank    = Utilities::MPI::this_mpi_process(comm);
  const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(comm);
  std::ofstream      out;
  if (rank == 0)
    out.open("output");
  auto yes = [](const bool b) { return b ? "yes" : "no"; };

  // Every rank failed.
  const bool all = RankAgreement::all_ranks_failed(30.);
  const bool all_everywhere = Utilities::MPI::min(all ? 1u : 0u, comm) == 1;
  if (rank == 0)
    out << "every rank failed: every rank sees it: " << yes(all_everywhere)
        << "\n";

  if (n_ranks > 1)
    {
      // Rank 1 alone, with a limit of 0.5 s.
      bool   alone   = true;
      double waited  = 0.;
      if (rank == 1)
        {
          const auto start = std::chrono::steady_clock::now();
          alone            = RankAgreement::all_ranks_failed(0.5);
          waited = std::chrono::duration<double>(std::chrono::steady_clock::now() -
                                                 start)
                     .count();
        }
      MPI_Barrier(comm);
      // Rank 0 now asks too: it pairs with rank 1's open request.
      bool late = true;
      if (rank == 0)
        late = RankAgreement::all_ranks_failed(30.);
      const bool rank1_alone = Utilities::MPI::broadcast(comm, alone, 1);
      const double rank1_waited = Utilities::MPI::broadcast(comm, waited, 1);
      if (rank == 0)
        out << "rank 1 alone: it sees that rank 0 did not fail: "
            << yes(!rank1_alone) << ", after the time limit: "
            << yes(rank1_waited >= 0.5 && rank1_waited < 10.)
            << "; rank 0 asking later completes the check: " << yes(late)
            << "\n";
    }
}
