// Restart on another number of MPI ranks (doc/robustness.md, "Checkpoints
// and restart"): a run checkpointed on 2 ranks continues on 1 and on 3
// ranks and ends with every quantity of its summary.json within 1e-8
// relative of the run that was never stopped (a component of a vector
// relative to the vector's magnitude), and with the same load steps, step
// cuts and iterations (a warm start lost in the transfer costs
// iterations):
// (a) the interior point method on the rigid foundation (its multipliers
//     and the contact forces on the contact nodes);
// (b) penalty continuation with two bodies (both bodies' nodal forces);
// (c) adaptive refinement cycles: a checkpoint on cycle 1's new mesh,
//     before its solve (the mesh loaded from p4est on the new number of
//     ranks), and one after it (cycle 2 then refines on the new ranks);
// (d) incompressible bodies with the interior point method (the
//     multipliers of the J = 1 constraints, one per cell).
// The uninterrupted run is the one that wrote the checkpoints (writing
// them changes nothing: tests/restart). The direct solver is KLU, whose
// answers on a given number of ranks are the same from run to run.

#include "run_output.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

using RunOutput::verdict;

namespace
{
  std::string
  mpirun(const unsigned int n)
  {
    return "mpirun --allow-run-as-root --oversubscribe -np " + std::to_string(n) + " ";
  }

  const std::string klu = "subsection Solver\n  subsection Linear solver\n"
                          "    set Direct solver = Amesos_Klu\n  end\nend\n";
  const std::string every_step =
    "subsection Checkpoint\n  set Write checkpoints = true\n"
    "  set Every load steps = 1\n  set Keep = 100\nend\n";
  const std::string four_steps =
    "subsection Load stepping\n  set Number of steps = 4\nend\n";

  std::string
  checkpoint(const std::string &folder, const unsigned int n)
  {
    char name[32];
    std::snprintf(name, sizeof(name), "checkpoint-%06u", n);
    return folder + "/checkpoints/" + name;
  }

  /// The counts that must not change: load steps, step cuts, iterations.
  std::vector<double>
  counts(const std::string &folder)
  {
    const auto numbers = RunOutput::summary_numbers(folder + "/summary.json");
    std::vector<double> c;
    for (const char *key : {"load steps", "step cuts", "newton iterations",
                            "interior_point iterations"})
      c.push_back(RunOutput::first_number(numbers, key));
    return c;
  }

  bool
  same_counts(const std::vector<double> &a, const std::vector<double> &b)
  {
    for (std::size_t i = 0; i < a.size(); ++i)
      if (!(a[i] == b[i] || (std::isnan(a[i]) && std::isnan(b[i]))))
        return false;
    return true;
  }

  /**
   * Run @p scene with @p edits on 2 ranks with a checkpoint after every
   * converged step, restart a copy of it from each of @p from (checkpoint
   * numbers) on 1 and on 3 ranks and compare each with it.
   */
  void
  check_scene(std::ostream                    &out,
              const std::string               &name,
              const std::string               &scene,
              const std::string               &edits,
              const std::vector<unsigned int> &from)
  {
    const bool ran =
      RunOutput::run_scene(name, scene, edits + klu + every_step, mpirun(2)) == 0;
    out << name << ": the run on 2 ranks converged: " << verdict(ran) << "\n";
    const auto reference = counts(name);
    for (const unsigned int n : from)
      for (const unsigned int ranks : {1u, 3u})
        {
          const std::string copy =
            name + "_from_" + std::to_string(n) + "_on_" + std::to_string(ranks);
          std::filesystem::remove_all(copy);
          if (ran)
            std::filesystem::copy(name, copy,
                                  std::filesystem::copy_options::recursive);
          const bool exists = std::filesystem::exists(checkpoint(copy, n));
          const int  code   = RunOutput::execute(mpirun(ranks) + SIGNORINI_EXECUTABLE +
                                              " --restart " + checkpoint(copy, n) +
                                              " > /dev/null 2>&1")
                             .first;
          std::string  quantity;
          const double difference =
            RunOutput::largest_quantity_difference(name, copy, &quantity);
          const bool same_counts_ = same_counts(reference, counts(copy));
          // The measured difference, for doc/robustness.md (not compared:
          // round-off).
          std::cerr << copy << ": largest relative difference " << difference
                    << " (" << quantity << ")\n";
          out << name << ": checkpoint " << n << " restarted on " << ranks
              << " rank(s): exit code " << code
              << ", quantities within 1e-8: "
              << verdict(exists && code == 0 && difference <= 1e-8)
              << ", same steps and iterations: "
              << verdict(exists && code == 0 && same_counts_) << "\n";
        }
  }
} // namespace

int
main()
{
  std::ofstream out("output");
  const std::string coarse = "subsection Mesh\n  set Global refinements = 2\nend\n";

  // (a) The program's interior point method on the rigid foundation
  // (checkpoint n: after load step n + 1).
  check_scene(out, "interior_point", "default.prm",
              four_steps + coarse +
                "subsection Solver\n  set Method = interior-point\nend\n",
              {1});
  // (b) Penalty continuation with two deformable bodies.
  check_scene(out, "block", "hertz_block.prm", four_steps, {1});
  // (c) Refinement cycles: 3 is on cycle 1's mesh before its solve, 4
  // after it.
  check_scene(out, "cycles", "hertz_adaptive.prm",
              coarse + "subsection Mesh refinement\n  set Number of cycles = 2\nend\n",
              {3, 4});
  // (d) Incompressible bodies: the augmented Lagrangian's multipliers.
  check_scene(out, "incompressible", "ssnv187_incompressible.prm",
              four_steps + "subsection Solver\n  set Method = interior-point\nend\n",
              {1});
}
