// A full disk (doc/robustness.md). Field output that does not fit ends the
// run with exit status 3 and a summary.json reason that names the file and
// the system's reason (deal.II's own message said only that some I/O
// failed), keeping the frames written before; an HDF5 frame that does not
// fit is removed (summary.json said "running" before: deal.II left the
// file open, holding the space). A checkpoint: p4est aborts the whole
// process when it cannot write the mesh (MPI-IO), so the program checks the
// free space before it writes a checkpoint. The run then ends as a failed
// output (exit status 3, summary.json's status "failed" with a reason that
// names the checkpoint and the space), keeps the checkpoints written
// before, and leaves no half-written checkpoint folder. The disk is a
// tmpfs of a fixed size mounted for the test (it needs root, as CI has;
// without it the test prints that the mount failed and fails): 400 kB
// hold no checkpoint of the default scene (1.2 MB each), 2 MB hold the
// first one only. Before the check, both runs ended in SIGABRT (exit
// status 134) with summary.json left "running".

#include "run_output.h"

#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>

using RunOutput::verdict;

namespace
{
  /// What fills the disk: VTU or HDF5 frames (no checkpoints), or
  /// checkpoints (no fields).
  enum class Writes
  {
    vtu,
    hdf5,
    checkpoints
  };

  /// A tmpfs of @p size mounted at @p folder while this object lives.
  struct Mount
  {
    Mount(const std::string &folder, const std::string &size)
      : folder(folder)
    {
      std::filesystem::create_directories(folder);
      mounted = std::system(("mount -t tmpfs -o size=" + size + " tmpfs " +
                             folder + " > /dev/null 2>&1")
                              .c_str()) == 0;
    }
    ~Mount()
    {
      if (mounted)
        std::system(("umount " + folder + " > /dev/null 2>&1").c_str());
    }
    std::string folder;
    bool        mounted = false;
  };

  /// A run of the default scene on a tmpfs of @p size; with checkpoints,
  /// @p kept of them fit.
  void
  check(const std::string &name,
        const std::string &size,
        const Writes       writes,
        const unsigned int kept = 0)
  {
    const std::string folder = std::filesystem::absolute(name).string();
    Mount             disk(folder, size);
    if (!disk.mounted)
      {
        std::cout << name << ": mounting a tmpfs failed" << std::endl;
        return;
      }
    const std::string out = folder + "/out";
    std::ofstream(name + ".prm")
      << "include " << SIGNORINI_SOURCE_DIR << "/prm/default.prm\n"
      << "set Output directory = " << out << "\n"
      << "subsection Output\n  set Format = "
      << (writes == Writes::vtu ? "vtu" : writes == Writes::hdf5 ? "hdf5" : "none")
      << "\n  set Verbosity = quiet\nend\n"
      << "subsection Checkpoint\n  set Write checkpoints = "
      << (writes == Writes::checkpoints ? "true" : "false") << "\n"
      << "  set Every load steps = 1\nend\n";
    const auto run = RunOutput::execute(std::string(SIGNORINI_EXECUTABLE) + " " +
                                        name + ".prm > /dev/null 2>&1; echo $?");
    const std::string code = run.second.substr(0, run.second.find('\n'));
    const auto        summary = RunOutput::execute(
      "python3 -c \"import json,sys; s=json.load(open(sys.argv[1])); "
      "print(s['status']); print(s.get('reason', ''))\" " +
      out + "/summary.json 2>/dev/null");
    const std::string status = summary.second.substr(0, summary.second.find('\n'));
    const std::string reason = summary.second.substr(summary.second.find('\n') + 1);
    const auto        names  = [&reason](const std::string &text) {
      return reason.find(text) != std::string::npos;
    };

    std::cout << name << " (" << size << "): exit status 3: " << verdict(code == "3")
              << "; status failed: " << verdict(status == "failed");
    if (writes == Writes::vtu)
      std::cout << "; reason names the file and 'No space left on device': "
                << verdict(names("field output: cannot write " + out + "/solution_") &&
                           names(".vtu: No space left on device"));
    else if (writes == Writes::hdf5)
      // The .h5 that did not fit is removed (deal.II left it open and half
      // written, holding the space summary.json needs).
      std::cout << "; reason names the file: "
                << verdict(names("field output: cannot write " + out +
                                 "/solution-0000.h5"))
                << "; .h5 left: "
                << (std::filesystem::exists(out + "/solution-0000.h5") ? "yes" : "no");
    else
      {
        const std::string failed_folder =
          "checkpoint-" + std::string(6 - std::to_string(kept).size(), '0') +
          std::to_string(kept);
        unsigned int complete = 0, other = 0;
        if (std::filesystem::is_directory(out + "/checkpoints"))
          for (const auto &entry :
               std::filesystem::directory_iterator(out + "/checkpoints"))
            {
              const auto p = entry.path();
              if (p.filename().string().rfind("checkpoint-", 0) == 0 &&
                  std::filesystem::exists(p / "state-0.bin") &&
                  std::filesystem::exists(p / "mesh") &&
                  std::filesystem::exists(p / "parameters.prm"))
                ++complete;
              else
                ++other;
            }
        std::cout << "; reason names the checkpoint and the space: "
                  << verdict(names("cannot create the checkpoint") &&
                             names(failed_folder) && names("MB free"))
                  << "; complete checkpoints kept: " << complete
                  << "; other entries: " << other;
      }
    std::cout << std::endl;
  }
} // namespace

int
main()
{
  check("no_room_for_fields", "200k", Writes::vtu);
  check("no_room_for_hdf5", "2000k", Writes::hdf5);
  check("no_room", "400k", Writes::checkpoints, 0);
  check("room_for_one", "2000k", Writes::checkpoints, 1);
}
