#pragma once

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace Signorini
{
  /**
   * Open MPI settings the program makes for itself before MPI_Init, where
   * they only save time and the user has not chosen otherwise
   * (doc/performance.md, "Process start-up").
   *
   * - `mtl = ^psm,psm2,ofi` on a machine without an RDMA device (nothing
   *   under /sys/class/infiniband, where InfiniBand, Omni-Path, RoCE and
   *   EFA adapters appear). Those matching-transport components drive
   *   such adapters only, yet Open MPI opens each of them at every start,
   *   and their libraries calibrate timers and probe for hardware: about
   *   0.1 s each, 0.3 s of a 0.58 s start on the development machine.
   *   Shared memory and TCP (the components Open MPI picks when no adapter
   *   is there) are not touched.
   * - `ess_singleton_isolated = 1` when the program was started without
   *   mpirun: Open MPI then does not fork its supporting daemon (orted),
   *   which a process needs only to spawn others; the program never does.
   *   Then also `sharedfp = ^sm`: that MPI-IO component keeps its files in
   *   the daemon's session directory and printed an error for every file
   *   HDF5 output or a checkpoint opened; one process does not need it.
   *   And `orte_create_session_dirs = 0`: every isolated process is job
   *   family 0 and used the same session directory, which one process
   *   removed at its end while another was creating it (a failed
   *   MPI_Init when several runs start at once).
   *
   * The user's choices win. Open MPI reads a parameter from the
   * environment (OMPI_MCA_<name>) before its parameter files
   * ($HOME/.openmpi/mca-params.conf, then /etc/openmpi/openmpi-mca-params.conf,
   * or the files OMPI_MCA_mca_base_param_files names); the first value
   * found there is the one kept, except that an exclusion list (Debian's
   * own file says `mtl = ^ofi`) is widened by the components above, never
   * narrowed. A chosen list of transports (mtl = psm2,
   * or pml = cm, ...) is left as it is. Other MPI implementations ignore
   * OMPI_MCA_ variables.
   */
  namespace MpiEnvironment
  {
    /// What the decision depends on.
    struct Facts
    {
      /// Started by mpirun (or another launcher that sets PMIX_RANK).
      bool launched = false;
      /// The machine shows an RDMA device.
      bool rdma_device = false;
      /// The values of mtl, pml, ess_singleton_isolated and sharedfp that
      /// the environment or the parameter files set (name without
      /// OMPI_MCA_).
      std::map<std::string, std::string> values;
    };

    /// The facts of this process and machine.
    Facts
    facts_of_this_process();

    /// The settings (name without OMPI_MCA_, value) for @p facts.
    std::vector<std::pair<std::string, std::string>>
    settings(const Facts &facts);

    /**
     * Put settings(facts_of_this_process()) into the environment. Call
     * before MPI_Init; returns what was set, as applied() does.
     */
    std::string
    prepare();

    /// What prepare() set, "name=value" separated by spaces ("" if none).
    const std::string &
    applied();
  } // namespace MpiEnvironment
} // namespace Signorini
