#pragma once

#include <mpi.h>

#include <stdexcept>
#include <string>

namespace Signorini
{
  /**
   * A clean stop on SIGINT and SIGTERM (a Ctrl-C, a batch system's time
   * limit). The first signal only sets a flag; the run stops at the next
   * safe point (a Newton or Ipopt iteration, a load step, a refinement
   * cycle), goes back to its last converged step, writes a checkpoint and
   * summary.json with "status": "interrupted", and exits with 128 + the
   * signal number (130 for SIGINT, 143 for SIGTERM). A second signal ends
   * the process at once with the same code; the files on disk are then
   * those of the last completed write (every file is renamed into place
   * or appended by whole rows), and summary.json says "running".
   *
   * The safe points are collective: every rank of the run stops at the
   * same one, whichever rank received the signal.
   */
  namespace Interruption
  {
    /// Thrown at a safe point after a signal: unwinds to the driver.
    class Interrupted : public std::runtime_error
    {
    public:
      explicit Interrupted(const int signal_number);

      /// SIGINT or SIGTERM.
      int signal_number;
    };

    /// Install the handlers for SIGINT and SIGTERM (idempotent).
    void
    install();

    /// The signal this process received (0: none). Not collective.
    int
    received();

    /**
     * The signal any rank of @p comm received (0: none). Collective: all
     * ranks must call it at the same point.
     */
    int
    check(MPI_Comm comm);

    /// check(), and throw Interrupted if a signal was received.
    void
    throw_if_requested(MPI_Comm comm);

    /// Act as if @p signal_number had been received (for tests).
    void
    request(const int signal_number);

    /// The signal's name: "SIGINT", "SIGTERM" or "signal N".
    std::string
    signal_name(const int signal_number);
  } // namespace Interruption
} // namespace Signorini
