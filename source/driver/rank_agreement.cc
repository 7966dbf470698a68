#include <signorini/driver/rank_agreement.h>

#include <chrono>
#include <thread>

namespace Signorini
{
  namespace RankAgreement
  {
    namespace
    {
      MPI_Comm agreement = MPI_COMM_NULL;
    }

    void
    initialize()
    {
      if (agreement == MPI_COMM_NULL)
        MPI_Comm_dup(MPI_COMM_WORLD, &agreement);
    }

    bool
    all_ranks_failed(const double seconds)
    {
      int n_ranks = 1;
      MPI_Comm_size(MPI_COMM_WORLD, &n_ranks);
      if (n_ranks == 1 || agreement == MPI_COMM_NULL)
        return true;
      MPI_Request request = MPI_REQUEST_NULL;
      MPI_Ibarrier(agreement, &request);
      const auto end = std::chrono::steady_clock::now() +
                       std::chrono::duration<double>(seconds);
      int done = 0;
      while (true)
        {
          MPI_Test(&request, &done, MPI_STATUS_IGNORE);
          if (done)
            return true;
          if (std::chrono::steady_clock::now() >= end)
            return false; // the request stays open: the caller aborts
          std::this_thread::sleep_for(std::chrono::milliseconds(5));
        }
    }
  } // namespace RankAgreement
} // namespace Signorini
