// One-rank runs started without mpirun do without Open MPI's supporting
// daemon (driver/mpi_environment.h). Its session directory is then not
// there, and MPI-IO's shared-memory shared-file-pointer component, which
// keeps a file in that directory for every file opened, printed errors
// ("mca_sharedfp_sm_component_file_query: Error, unable to open file for
// mmap") when several such runs wrote HDF5 output at once, as ctest -j2
// does: 2 of 3 concurrent runs did on the development machine. The
// program therefore leaves that component out of one-rank runs. Here:
// three concurrent runs of the SSNV187 block with HDF5 output must
// converge and print nothing about MPI-IO.

#include "run_output.h"

#include <filesystem>
#include <fstream>
#include <string>

int
main()
{
  namespace fs = std::filesystem;
  const std::string scene =
    std::string(SIGNORINI_SOURCE_DIR) + "/prm/ssnv187_mooney_rivlin.prm";
  std::string command = "";
  for (unsigned int i = 0; i < 3; ++i)
    {
      const std::string name = "run" + std::to_string(i);
      fs::remove_all(name);
      std::ofstream(name + ".prm")
        << "include " << scene << "\n"
        << "set Output directory = " << name << "\n"
        << "subsection Output\n  set Format = hdf5\n  set Verbosity = quiet\nend\n";
      // The variables a user might have set would change what is tested.
      command += "env -u OMPI_MCA_sharedfp -u OMPI_MCA_ess_singleton_isolated " +
                 std::string(SIGNORINI_EXECUTABLE) + " " + name + ".prm > " +
                 name + ".log 2>&1 & ";
    }
  command += "wait";
  RunOutput::execute(command);

  for (unsigned int i = 0; i < 3; ++i)
    {
      const std::string name = "run" + std::to_string(i);
      const std::string log  = RunOutput::read_text(name + ".log");
      const std::string summary = RunOutput::read_text(name + "/summary.json");
      std::cout << name << ": converged "
                << (summary.find("\"status\": \"converged\"") != std::string::npos)
                << ", HDF5 written " << fs::exists(name + "/solution-0001.h5")
                << ", MPI-IO messages "
                << (log.find("sharedfp") != std::string::npos ||
                    log.find("mmap") != std::string::npos)
                << '\n';
    }
}
