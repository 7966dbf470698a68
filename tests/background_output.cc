// Field output written by a background thread while the next load step is
// solved (output/postprocess.h, Postprocessor::flush): on 1 and 2 ranks,
// every frame solution.pvd names has its .pvtu and every piece that names,
// each a complete VTU file, with no temporary file left; and a piece that
// cannot be written (a folder stands in its place) ends the run with exit
// status 3 and summary.json's status "failed" with a reason naming the
// file, on every rank (a failure on rank 1 alone must not hang rank 0),
// while solution.pvd names only the frames written before it. Every frame's
// pieces hold the mesh's cells together; a rank with 2 threads writes 2
// pieces (the default scene has 6630 cells, at least 2000 for each), 2
// ranks with 1 thread each one piece each. On 1 rank,
// the frame of the first load step (built and written while the second is
// solved) is byte for byte the last frame of a run that stops after that
// step (written once the run is over). That run ends with exit status 4:
// its Hertz reference is the full load's, so a and p0 are outside the
// tolerances at half the load.

#include "run_output.h"

#include <filesystem>
#include <fstream>
#include <iostream>
#include <regex>
#include <string>
#include <vector>

using RunOutput::verdict;

namespace
{
  const std::string mpirun = "mpirun --allow-run-as-root --oversubscribe -np 2 ";

  int
  run(const std::string &folder,
      const std::string &launcher,
      const std::string &extra = "")
  {
    std::ofstream(folder + ".prm")
      << "include " << SIGNORINI_SOURCE_DIR << "/prm/default.prm\n"
      << "set Output directory = " << folder << "\n"
      << "subsection Output\n  set Verbosity = quiet\nend\n"
      << extra;
    const int status = std::system(
      (launcher + SIGNORINI_EXECUTABLE + " " + folder + ".prm > /dev/null 2>&1")
        .c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }

  /// The file="..." names of a .pvd or the Source="..." names of a .pvtu.
  std::vector<std::string>
  names_in(const std::string &file, const std::string &attribute)
  {
    const std::string        text = RunOutput::read_text(file);
    const std::regex         pattern(attribute + "=\"([^\"]+)\"");
    std::vector<std::string> names;
    for (std::sregex_iterator it(text.begin(), text.end(), pattern), end;
         it != end;
         ++it)
      names.push_back((*it)[1]);
    return names;
  }

  struct Frames
  {
    int  complete    = 0;    // -1 if a piece is missing or cut short
    bool all_cells   = true; // each frame's pieces hold the mesh's cells
    int  last_pieces = 0;
    int  threads     = 0;    // per rank, from summary.json
  };

  /// The frames named in the folder's solution.pvd whose pieces are all
  /// there and complete, and the cells in them.
  Frames
  frames_in(const std::string &folder)
  {
    Frames      frames;
    const auto  numbers = RunOutput::summary_numbers(folder + "/summary.json");
    const auto  cells   = RunOutput::first_number(numbers, "cells");
    frames.threads = RunOutput::first_number(numbers, "threads per rank");
    for (const auto &pvtu : names_in(folder + "/solution.pvd", "file"))
      {
        const auto pieces = names_in(folder + "/" + pvtu, "Source");
        if (pieces.empty())
          return Frames{-1, false, 0};
        double in_pieces = 0.;
        for (const auto &piece : pieces)
          {
            const std::string text = RunOutput::read_text(folder + "/" + piece);
            if (text.size() < 20 ||
                text.find("</VTKFile>") == std::string::npos)
              return Frames{-1, false, 0};
            std::smatch n;
            if (std::regex_search(text, n, std::regex("NumberOfCells=\"([0-9]+)\"")))
              in_pieces += std::stod(n[1]);
          }
        frames.all_cells = frames.all_cells && in_pieces == cells;
        frames.last_pieces = pieces.size();
        ++frames.complete;
      }
    return frames;
  }

  int
  complete_frames(const std::string &folder)
  {
    return frames_in(folder).complete;
  }

  /// A VTU file without its comment (it carries the date and time).
  std::string
  without_comment(const std::string &file)
  {
    const std::string text  = RunOutput::read_text(file);
    const auto        start = text.find("<!--");
    const auto        end   = text.find("-->");
    if (start == std::string::npos || end == std::string::npos || end < start)
      return text;
    return text.substr(0, start) + text.substr(end + 3);
  }

  bool
  temporaries_left(const std::string &folder)
  {
    for (const auto &entry : std::filesystem::directory_iterator(folder))
      if (entry.path().filename().string().find(".tmp.") != std::string::npos)
        return true;
    return false;
  }

  std::string
  status_and_reason(const std::string &folder)
  {
    const std::string text = RunOutput::read_text(folder + "/summary.json");
    std::smatch       status, reason;
    std::regex_search(text, status, std::regex("\"status\": \"([a-z]+)\""));
    std::regex_search(text, reason, std::regex("\"reason\": \"([^\"]*)\""));
    return (status.empty() ? std::string("?") : status[1].str()) + " / " +
           (reason.empty() ? std::string("") : reason[1].str());
  }
} // namespace

int
main()
{
  std::ofstream out("output");
  for (const bool two : {false, true})
    {
      const std::string ranks = two ? "2 ranks" : "1 rank";
      const std::string good  = two ? "good_2" : "good_1";
      std::filesystem::remove_all(good);
      // 2 threads for the one rank, 1 for each of 2.
      const int code =
        run(good, two ? mpirun + "-x DEAL_II_NUM_THREADS=1 " :
                        "DEAL_II_NUM_THREADS=2 ");
      const Frames frames = frames_in(good);
      out << ranks << ": exit status " << code << ", complete frames "
          << frames.complete << ", pieces per frame = "
          << (two ? "ranks" : "threads") << " "
          << verdict(frames.last_pieces == (two ? 2 : frames.threads) &&
                     frames.threads == (two ? 1 : 2))
          << ", the pieces hold every cell " << verdict(frames.all_cells)
          << ", no temporary file left " << verdict(!temporaries_left(good))
          << "\n";
      if (!two)
        {
          // The same first load step (t = 0.5, dt = 0.5), as the last one.
          std::filesystem::remove_all("half");
          const int half_code =
            run("half", "DEAL_II_NUM_THREADS=2 ",
                "subsection Load stepping\n  set End time = 0.5\n"
                "  set Number of steps = 1\nend\n");
          const std::string a = without_comment(good + "/solution_0001.0.vtu");
          const std::string b = without_comment("half/solution_0001.0.vtu");
          out << ranks << ": frame of step 1 equals the last frame of a run "
              << "ending there (exit status " << half_code << ") "
              << verdict(a.size() > 1000 && a == b) << "\n";
        }

      // Of the first load step's frame: on 1 rank (2 threads) each of its
      // two pieces (the second is written by a thread of its own), on 2
      // ranks rank 1's.
      const std::vector<std::string> unwritable =
        two ? std::vector<std::string>{"solution_0001.1.vtu"} :
              std::vector<std::string>{"solution_0001.0.vtu", "solution_0001.1.vtu"};
      for (const auto &piece : unwritable)
        {
          const std::string bad = std::string(two ? "bad_2_" : "bad_1_") + piece;
          std::filesystem::remove_all(bad);
          std::filesystem::create_directories(bad + "/" + piece);
          const int failed_code =
            run(bad, two ? mpirun + "-x DEAL_II_NUM_THREADS=1 " :
                           "DEAL_II_NUM_THREADS=2 ");
          const auto summary = status_and_reason(bad);
          out << ranks << ", " << piece << " unwritable: exit status "
              << failed_code << ", status "
              << summary.substr(0, summary.find(" / "))
              << ", reason names the file "
              << verdict(summary.find(piece) != std::string::npos)
              << ", frames in solution.pvd " << complete_frames(bad) << "\n";
        }
    }
}
