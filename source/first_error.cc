#include <signorini/first_error.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/numbers.h>

namespace Signorini
{
  std::string
  first_error(const MPI_Comm comm, const std::string &error)
  {
    using namespace dealii;
    const unsigned int failed = Utilities::MPI::min(
      error.empty() ? numbers::invalid_unsigned_int :
                      Utilities::MPI::this_mpi_process(comm),
      comm);
    if (failed == numbers::invalid_unsigned_int)
      return "";
    return Utilities::MPI::broadcast(comm, error, failed);
  }
} // namespace Signorini
