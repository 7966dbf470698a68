// Checkpoint and restart (doc/robustness.md): a run restarted from any of
// its checkpoints ends with the same summary.json numbers (wall times and
// peak memory excepted) to 1e-10 relative, the same load steps and
// iterations, and the same load_steps.csv rows, as the run that was never
// stopped:
// - penalty continuation, two bodies (Hertz on a block), 1 rank and 2 ranks,
//   and in two passes (Passes = two-pass), and several pairs (the disk
//   stack, Type = pairs);
// - Ipopt with the rigid foundation's constraints (warm-started multipliers);
// - the interior point method (the same, on 1 and 2 ranks), also with
//   incompressible bodies (the augmented Lagrangian's multipliers);
// - adaptive refinement cycles, restarted in the load path and in a cycle;
// - the estimate from a coarser mesh (2 ranks), restarted on either mesh.
// Writing checkpoints does not change the run. A run checkpointed on 1
// rank continues on 2 (tests/restart_ranks: 2 ranks on 1 and 3). Bad
// restarts exit 2 with a message: a changed mesh entry, another scene's
// parameters, a checkpoint of the previous format, no checkpoint, a state
// file of rank 1 cut short (on 2 ranks, without a hang).

#include "run_output.h"

#include <signorini/archive_io.h>
#include <signorini/driver/checkpoint.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>

using RunOutput::verdict;

namespace
{
  const std::string mpirun = "mpirun --allow-run-as-root --oversubscribe -np 2 ";
  // Two ranks: KLU on the gathered matrix, whose answers are the same to
  // the last bit from run to run. MUMPS distributed over the ranks (the
  // default there) assembles its fronts in the order the messages arrive,
  // so two runs differ at round-off (measured: a final residual of 3.0e-10
  // against 3.7e-10), and an exact comparison would test the solver, not
  // the checkpoint.
  const std::string klu =
    "subsection Solver\n  subsection Linear solver\n"
    "    set Direct solver = Amesos_Klu\n  end\nend\n";

  bool
  same(const std::string &a, const std::string &b)
  {
    return RunOutput::same_results(a, b, 1e-10);
  }

  std::string
  checkpoint(const std::string &folder, const unsigned int n)
  {
    char name[32];
    std::snprintf(name, sizeof(name), "checkpoint-%06u", n);
    return folder + "/checkpoints/" + name;
  }

  int
  restart(const std::string &what, const std::string &launcher = "")
  {
    return RunOutput::execute(launcher + SIGNORINI_EXECUTABLE + " --restart " +
                              what + " > /dev/null 2>&1")
      .first;
  }

  /**
   * Run @p scene with @p edits without checkpoints, and again with one
   * after every converged step; restart a copy of the second run from
   * each of @p from (checkpoint numbers) and compare every run with the
   * first.
   */
  void
  check_scene(std::ostream                    &out,
              const std::string               &name,
              const std::string               &scene,
              const std::string               &edits,
              const std::vector<unsigned int> &from,
              const std::string               &launcher = "")
  {
    const std::string every =
      "subsection Checkpoint\n  set Write checkpoints = true\n"
      "  set Every load steps = 1\n  set Keep = 100\nend\n";
    const bool ran =
      RunOutput::run_scene(name + "_plain", scene, edits, launcher) == 0 &&
      RunOutput::run_scene(name, scene, edits + every, launcher) == 0;
    out << name << ": runs converged: " << verdict(ran)
        << "; checkpoints change nothing: "
        << verdict(ran && same(name + "_plain", name)) << "\n";
    for (const unsigned int n : from)
      {
        const std::string copy = name + "_from_" + std::to_string(n);
        std::filesystem::remove_all(copy);
        std::filesystem::copy(name, copy, std::filesystem::copy_options::recursive);
        const bool exists = std::filesystem::exists(checkpoint(copy, n));
        const int  code   = restart(checkpoint(copy, n), launcher);
        out << name << ": restarted from checkpoint " << n
            << ": exit code " << code << ", same numbers as without a stop: "
            << verdict(exists && code == 0 && same(name + "_plain", copy)) << "\n";
      }
  }
} // namespace

int
main()
{
  std::ofstream out("output");
  const std::string four_steps =
    "subsection Load stepping\n  set Number of steps = 4\nend\n";

  // Penalty continuation with two deformable bodies (checkpoint n: after
  // load step n + 1).
  check_scene(out, "block", "hertz_block.prm", four_steps, {0, 2});
  // The same in two passes (TwoPassContact: both passes' states).
  check_scene(out, "two_pass", "hertz_block.prm",
              four_steps + "subsection Contact\n  subsection Two bodies\n"
                           "    set Passes = two-pass\n  end\nend\n",
              {1});
  // Several contact pairs (Type = pairs, the disk stack): every part's
  // record and broad-phase counts, one field each.
  check_scene(out, "pairs", "disk_stack.prm", "", {0});
  // Ipopt with constraints, its multipliers warm-started across steps.
  check_scene(out, "ipopt", "default.prm",
              four_steps +
                "subsection Mesh\n  set Global refinements = 2\nend\n"
                "subsection Solver\n  set Method = ipopt\nend\n",
              {1, 3});
  // The program's interior point method: its multipliers warm-started
  // across steps, on 1 and 2 ranks.
  const std::string interior_point =
    four_steps + "subsection Mesh\n  set Global refinements = 2\nend\n"
                 "subsection Solver\n  set Method = interior-point\nend\n";
  check_scene(out, "interior_point", "default.prm", interior_point, {1, 3});
  check_scene(out, "interior_point_ranks", "default.prm", interior_point + klu,
              {2}, mpirun);
  // The same with incompressible bodies: the augmented Lagrangian's
  // multipliers carried across steps and through the checkpoint.
  check_scene(out, "incompressible", "ssnv187_incompressible.prm",
              four_steps + "subsection Solver\n  set Method = interior-point\nend\n",
              {1});
  // Coulomb friction (issue 50): the friction history of the last two
  // steps (the next step's extrapolation) is in the checkpoint; from step
  // 3 (pressing) and step 7 (sliding), on 1 and 2 ranks.
  check_scene(out, "friction", "sliding_block.prm", "", {2, 6});
  check_scene(out, "friction_ranks", "sliding_block.prm", klu, {6}, mpirun);
  // Refinement cycles: checkpoints in the load path (0: after step 1),
  // after cycle 0 is recorded (2), on cycle 1's mesh before its solve (3)
  // and after it (4).
  check_scene(out, "cycles", "hertz_adaptive.prm",
              "subsection Mesh\n  set Global refinements = 2\nend\n"
              "subsection Mesh refinement\n  set Number of cycles = 2\nend\n",
              {0, 2, 3, 4});
  // Two ranks.
  check_scene(out, "ranks", "hertz_block.prm", four_steps + klu, {2}, mpirun);
  // The estimate from a coarser mesh, on 2 ranks: restarted in the load
  // path on the coarsened mesh (1: the cells to refine back come from the
  // checkpoint) and on the scene's mesh before its solve (5).
  check_scene(out, "coarser", "hertz_block.prm",
              four_steps + klu +
                "subsection Mesh refinement\n"
                "  set Estimate from a coarser mesh = true\nend\n",
              {1, 5}, mpirun);

  // A restart that cannot be honoured.
  {
    std::ofstream("changed.prm")
      << "include " << SIGNORINI_SOURCE_DIR << "/prm/hertz_block.prm\n"
      << four_steps << "subsection Mesh\n  set Global refinements = 3\nend\n";
    const auto changed = RunOutput::execute(std::string(SIGNORINI_EXECUTABLE) +
                                            " --restart block changed.prm 2>&1");
    out << "changed mesh: exit code " << changed.first << ", names the entry: "
        << verdict(changed.second.find("Mesh > Global refinements: '2' -> '3'") !=
                   std::string::npos)
        << "\n";
    // Another number of ranks: the run on 1 rank continued on 2 from its
    // first checkpoint (the direct solver there is MUMPS, whose round-off
    // varies from run to run: the quantities to 1e-8).
    const std::string on_two = "block_on_2_ranks";
    std::filesystem::remove_all(on_two);
    std::filesystem::copy("block", on_two, std::filesystem::copy_options::recursive);
    const int ranks = restart(checkpoint(on_two, 0), mpirun);
    out << "other rank count: exit code " << ranks << ", same quantities as without a stop: "
        << verdict(ranks == 0 &&
                   RunOutput::largest_quantity_difference("block_plain", on_two) <= 1e-8)
        << "\n";
    // Another scene's parameters for this checkpoint.
    std::ofstream("other_scene.prm")
      << "include " << SIGNORINI_SOURCE_DIR << "/prm/default.prm\n"
      << "set Output directory = block\n";
    const auto other = RunOutput::execute(std::string(SIGNORINI_EXECUTABLE) +
                                          " --restart block other_scene.prm 2>&1");
    out << "another scene: exit code " << other.first << ", says so: "
        << verdict(other.second.find("cannot continue with changed entries") !=
                   std::string::npos)
        << "\n";
    // A checkpoint of the previous format (6: the state on nodes and cells
    // was this rank's lists, valid on as many ranks only): its header as
    // that format wrote it.
    const std::string old_format = "block_format_6";
    std::filesystem::remove_all(old_format);
    std::filesystem::copy("block", old_format, std::filesystem::copy_options::recursive);
    {
      Signorini::Checkpoint::Header header;
      header.format    = 6;
      header.dimension = 2;
      header.n_ranks   = 1;
      std::ofstream                   file(checkpoint(old_format, 0) + "/state-0.bin",
                             std::ios::binary);
      boost::archive::binary_oarchive archive(file);
      archive << header;
    }
    const auto old = RunOutput::execute(std::string(SIGNORINI_EXECUTABLE) +
                                        " --restart " + checkpoint(old_format, 0) +
                                        " 2>&1");
    out << "format 6: exit code " << old.first << ", names the format: "
        << verdict(old.second.find("checkpoint format 6, this program reads format " +
                                     std::to_string(Signorini::Checkpoint::format_version)) !=
                   std::string::npos)
        << "\n";
    std::filesystem::create_directories("empty");
    const auto none = RunOutput::execute(std::string(SIGNORINI_EXECUTABLE) +
                                         " --restart empty 2>&1");
    out << "no checkpoint: exit code " << none.first << ", says so: "
        << verdict(none.second.find("no checkpoint") != std::string::npos) << "\n";

    // Rank 1's state file cut short: every rank reports it and stops (rank
    // 1 alone failed before, and rank 0 waited for it in the first
    // collective operation for ever).
    const std::string damaged = "ranks_damaged";
    std::filesystem::remove_all(damaged);
    std::filesystem::copy("ranks", damaged, std::filesystem::copy_options::recursive);
    const std::string state = checkpoint(damaged, 2) + "/state-1.bin";
    const bool        cut   = std::filesystem::exists(state);
    if (cut)
      std::filesystem::resize_file(state, std::filesystem::file_size(state) / 2);
    const auto reply = RunOutput::execute("timeout 300 " + mpirun +
                                          SIGNORINI_EXECUTABLE + " --restart " +
                                          checkpoint(damaged, 2) + " 2>&1");
    out << "rank 1's state file cut short: exit code " << reply.first
        << ", names it: "
        << verdict(cut && reply.second.find("state-1.bin") != std::string::npos)
        << "\n";
  }
}
