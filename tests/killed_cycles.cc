// A run killed from outside during its refinement cycles (SIGKILL: the
// kernel's answer to a lack of memory, which the program cannot catch)
// keeps the cycles it finished: summary.json (status "running") and
// refinement_cycles.csv are rewritten after every cycle, with the cycles'
// quantities and estimated errors. The scene is the rigid Hertz of
// prm/hertz_adaptive.prm with 9 cycles (the last ones take seconds); the
// test kills it as soon as refinement_cycles.csv holds cycles 0 to 2.
// Until the files were written per cycle, they were written at the end
// only, and the killed run left neither its cycles nor the CSV.

#include "run_output.h"

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

#include <sys/wait.h>

using RunOutput::verdict;

int
main()
{
  std::ofstream out("output");
  std::filesystem::remove_all("run");
  std::ofstream("run.prm") << "include " << SIGNORINI_SOURCE_DIR
                           << "/prm/hertz_adaptive.prm\n"
                              "set Output directory = run\n"
                              "subsection Mesh refinement\n"
                              "  set Number of cycles = 9\n"
                              "  set Maximum level    = 20\n"
                              "end\n"
                              "subsection Output\n  set Format = none\nend\n";
  const pid_t pid = RunOutput::start_quietly({SIGNORINI_EXECUTABLE, "run.prm"});

  // Wait (at most 120 s) for cycles 0 to 2 in the CSV, or for the end.
  bool seen = false, ended = false;
  int  status = 0;
  for (int k = 0; k < 12000 && !seen && !ended; ++k)
    {
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
      seen  = RunOutput::read_csv("run/refinement_cycles.csv").size() >= 3;
      ended = waitpid(pid, &status, WNOHANG) == pid;
    }
  if (!ended)
    {
      kill(pid, SIGKILL);
      waitpid(pid, &status, 0);
    }
  out << "killed during the cycles: " << verdict(seen && !ended) << "\n";

  const auto cycles = RunOutput::read_csv("run/refinement_cycles.csv");
  out << "refinement_cycles.csv has cycles 0 to 2: " << verdict(cycles.size() >= 3) << "\n";
  bool estimated = false;
  for (const auto &row : cycles)
    if (row.count("hertz_p0_estimated_error") && row.at("cycle") >= 2)
      estimated = estimated || row.at("hertz_p0_estimated_error") > 0.;
  out << "p0's estimated error from cycle 2 on: " << verdict(estimated) << "\n";
  const std::string summary = RunOutput::read_text("run/summary.json");
  const auto        status_at = summary.find("\"status\": \"running\"");
  out << "summary.json says running: " << verdict(status_at != std::string::npos) << "\n";
  const auto n = RunOutput::execute(
    "python3 -c \"import json; s=json.load(open('run/summary.json')); "
    "print(len(s['mesh refinement']['cycles']))\"");
  out << "summary.json holds at least 3 cycles: "
      << verdict(n.first == 0 && std::stoi("0" + n.second) >= 3) << "\n";
}
