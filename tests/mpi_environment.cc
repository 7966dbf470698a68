// The Open MPI settings the program makes before MPI_Init
// (driver/mpi_environment.h): which it makes for which facts, that a
// user's choice wins, that an exclusion list (Debian's own `mtl = ^ofi`)
// is widened and a chosen component kept, and that the facts are read
// from the environment and from a parameter file.

#include <signorini/driver/mpi_environment.h>

#include "run_output.h"

#include <cstdlib>
#include <fstream>
#include <iostream>

using namespace Signorini;

namespace
{
  void
  print(const std::string &label, const MpiEnvironment::Facts &facts)
  {
    std::cout << label << ":";
    const auto settings = MpiEnvironment::settings(facts);
    if (settings.empty())
      std::cout << " (nothing)";
    for (const auto &[name, value] : settings)
      std::cout << ' ' << name << '=' << value;
    std::cout << '\n';
  }

  MpiEnvironment::Facts
  facts(const bool                                launched,
        const bool                                rdma,
        std::map<std::string, std::string> values = {})
  {
    MpiEnvironment::Facts f;
    f.launched    = launched;
    f.rdma_device = rdma;
    f.values      = std::move(values);
    return f;
  }
} // namespace

int
main()
{
  // Many one-rank runs starting and ending at once (as ctest -j2 with
  // tests/prm_mutation's parallel runs does): each must get through
  // MPI_Init. With a session directory shared by all isolated processes,
  // about 1 start in 160 failed; 360 starts then fail at least once with
  // a probability of 0.9.
  {
    const std::string command =
      std::string("for i in $(seq 60); do for j in 1 2 3 4 5 6; do (") +
      SIGNORINI_EXECUTABLE +
      " --help > /dev/null 2>&1 || echo failed) & done; wait; done";
    const auto [code, text] = RunOutput::execute(command);
    std::size_t failed = 0;
    for (std::size_t at = text.find("failed"); at != std::string::npos;
         at = text.find("failed", at + 1))
      ++failed;
    std::cout << "360 concurrent one-rank starts, failed: " << failed << '\n';
  }

  print("plain machine, no mpirun", facts(false, false));
  print("plain machine, mpirun", facts(true, false));
  print("RDMA adapter, no mpirun", facts(false, true));
  print("Debian's mtl = ^ofi", facts(true, false, {{"mtl", "^ofi"}}));
  print("all three excluded already",
        facts(true, false, {{"mtl", "^ofi,psm2,psm"}}));
  print("user chose mtl = psm2", facts(true, false, {{"mtl", "psm2"}}));
  print("user chose pml = cm", facts(true, false, {{"pml", "cm"}}));
  print("pml = ^ucx", facts(true, false, {{"pml", "^ucx"}}));
  print("user set ess_singleton_isolated = 0",
        facts(false, false, {{"ess_singleton_isolated", "0"}}));
  print("sharedfp = ^lockedfile, no mpirun",
        facts(false, false, {{"sharedfp", "^lockedfile"}}));
  print("user chose sharedfp = sm, no mpirun",
        facts(false, false, {{"sharedfp", "sm"}}));
  print("user chose orte_create_session_dirs = 1, no mpirun",
        facts(false, false, {{"orte_create_session_dirs", "1"}}));

  // The facts of this process: an environment variable, and a parameter
  // file named by OMPI_MCA_mca_base_param_files (comments and blanks as
  // Open MPI allows them).
  const std::string file = "mca-params.conf";
  std::ofstream(file) << "# a comment\n  pml = cm   # trailing comment\n"
                         "mtl=^ofi\n";
  setenv("OMPI_MCA_mca_base_param_files", file.c_str(), 1);
  setenv("OMPI_MCA_mtl", "psm2", 1);
  unsetenv("OMPI_MCA_pml");
  unsetenv("OMPI_MCA_ess_singleton_isolated");
  unsetenv("OMPI_MCA_sharedfp");
  unsetenv("OMPI_MCA_orte_create_session_dirs");
  const auto here = MpiEnvironment::facts_of_this_process();
  for (const auto &[name, value] : here.values)
    std::cout << "read " << name << " = " << value << '\n';
  print("this process", here);

  // prepare() puts the settings into the environment and remembers them.
  unsetenv("OMPI_MCA_mtl");
  std::ofstream(file) << "";
  unsetenv("OMPI_COMM_WORLD_SIZE");
  unsetenv("PMIX_RANK");
  unsetenv("PMI_RANK");
  const std::string applied = MpiEnvironment::prepare();
  std::cout << "prepare() == applied(): " << (applied == MpiEnvironment::applied())
            << '\n';
  const char *isolated = std::getenv("OMPI_MCA_ess_singleton_isolated");
  const char *sharedfp = std::getenv("OMPI_MCA_sharedfp");
  std::cout << "ess_singleton_isolated in the environment: "
            << (isolated ? isolated : "(unset)") << '\n'
            << "sharedfp in the environment: " << (sharedfp ? sharedfp : "(unset)")
            << '\n';
}
