#include <signorini/interruption.h>

#include <deal.II/base/mpi.h>

#include <csignal>
#include <unistd.h>

namespace Signorini
{
  namespace Interruption
  {
    namespace
    {
      volatile std::sig_atomic_t signal_received = 0;

      extern "C" void
      handle_signal(int signal_number)
      {
        // A second signal: the user insists. Only async-signal-safe calls.
        if (signal_received != 0)
          _exit(128 + signal_number);
        signal_received = signal_number;
      }
    } // namespace

    Interrupted::Interrupted(const int signal_number)
      : std::runtime_error(signal_name(signal_number) + " received")
      , signal_number(signal_number)
    {}

    void
    install()
    {
      struct sigaction action = {};
      action.sa_handler       = handle_signal;
      sigemptyset(&action.sa_mask);
      // Restart interrupted system calls (writes, MPI's polling): the
      // run itself decides where to stop.
      action.sa_flags = SA_RESTART;
      sigaction(SIGINT, &action, nullptr);
      sigaction(SIGTERM, &action, nullptr);
    }

    int
    received()
    {
      return signal_received;
    }

    int
    check(MPI_Comm comm)
    {
      return dealii::Utilities::MPI::max(static_cast<int>(signal_received), comm);
    }

    void
    throw_if_requested(MPI_Comm comm)
    {
      if (const int s = check(comm); s != 0)
        throw Interrupted(s);
    }

    void
    request(const int signal_number)
    {
      signal_received = signal_number;
    }

    std::string
    signal_name(const int signal_number)
    {
      switch (signal_number)
        {
          case SIGINT:
            return "SIGINT";
          case SIGTERM:
            return "SIGTERM";
          default:
            return "signal " + std::to_string(signal_number);
        }
    }
  } // namespace Interruption
} // namespace Signorini
