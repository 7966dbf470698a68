// A clean stop (doc/robustness.md): SIGTERM at a random moment of a run
// (fixed seeds; the moment is a fraction of an uninterrupted run's time
// after its summary.json appeared, so it falls into solves, output or
// checkpoint writing alike, whatever the machine's load) always
// leaves a valid summary.json whose status is "interrupted" (exit code
// 143) or "converged" (the run ended first; exit code 0), a load_steps.csv
// with one whole row per converged step, and for an interrupted run a
// checkpoint from which --restart ends with the numbers of the run that
// was never stopped (every summary.json number and load_steps.csv row to
// 1e-10 relative). Also on 2 ranks (the signal goes to both ranks), and
// with a second signal, which ends the process at once and still leaves
// well-formed files.

#include "run_output.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <random>
#include <sstream>
#include <string>
#include <thread>

#include <sys/wait.h>

using RunOutput::verdict;

namespace
{
  const std::string scene_edits =
    "subsection Load stepping\n  set Number of steps = 4\nend\n";
  // Two ranks: KLU on the gathered matrix, whose answers are the same to
  // the last bit from run to run. MUMPS distributed over the ranks (the
  // default there) assembles its fronts in the order the messages arrive,
  // so two runs differ at round-off (measured: 1e-10 in the reactions),
  // and an exact comparison would test the solver, not the checkpoint.
  const std::string two_rank_edits =
    "subsection Solver\n  subsection Linear solver\n"
    "    set Direct solver = Amesos_Klu\n  end\nend\n";

  bool
  same(const std::string &a, const std::string &b)
  {
    return RunOutput::same_results(a, b, 1e-10);
  }

  /// Status of a summary.json read by Python's JSON parser ("" if the
  /// file is not valid JSON).
  std::string
  json_status(const std::string &file)
  {
    const auto r = RunOutput::execute(
      "python3 -c \"import json,sys; print(json.load(open(sys.argv[1]))['status'])\" " +
      file + " 2>/dev/null");
    std::string status = r.second;
    while (!status.empty() && status.back() == '\n')
      status.pop_back();
    return r.first == 0 ? status : "";
  }

  /// Whether every row of load_steps.csv has as many fields as its
  /// header, and the number of rows.
  std::pair<bool, std::size_t>
  whole_rows(const std::string &file)
  {
    std::ifstream in(file);
    std::string   line;
    if (!std::getline(in, line))
      return {false, 0};
    const auto  fields = std::count(line.begin(), line.end(), ',');
    std::size_t rows   = 0;
    bool        whole  = true;
    while (std::getline(in, line))
      {
        whole = whole && std::count(line.begin(), line.end(), ',') == fields;
        ++rows;
      }
    return {whole, rows};
  }

  int
  wait_for(const pid_t pid)
  {
    int status = 0;
    waitpid(pid, &status, 0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  }

  std::vector<std::string>
  command(const std::string &name, const bool two_ranks)
  {
    std::vector<std::string> c;
    if (two_ranks)
      c = {"mpirun", "--allow-run-as-root", "--oversubscribe", "-np", "2"};
    c.push_back(SIGNORINI_EXECUTABLE);
    c.push_back(name + ".prm");
    return c;
  }

  /// A started run of the scene: the process, the processes a batch
  /// system would signal (the ranks on 2 ranks, else the process itself),
  /// and when its summary.json first appeared.
  struct Launched
  {
    pid_t                                 pid;
    std::vector<pid_t>                    targets;
    std::chrono::steady_clock::time_point running;
  };

  /// Write NAME.prm and start it. Returns once summary.json exists (and,
  /// on 2 ranks, both ranks do): from then on the program has installed
  /// its signal handlers and has a record to keep. A signal before that
  /// (MPI's start-up and the setup: 1.1 s of a 2.5 s run here, longer on
  /// a loaded machine) ends it with nothing written, as doc/robustness.md
  /// says, so every delay below counts from this moment.
  Launched
  launch(const std::string &name, const bool two_ranks)
  {
    std::filesystem::remove_all(name);
    std::ofstream(name + ".prm")
      << "include " << SIGNORINI_SOURCE_DIR << "/prm/hertz_block.prm\n"
      << "set Output directory = " << name << "\n"
      << scene_edits << (two_ranks ? two_rank_edits : "")
      << "subsection Output\n  set Format = none\n  set Verbosity = quiet\nend\n";
    Launched run{RunOutput::start_quietly(command(name, two_ranks)), {}, {}};
    // On 2 ranks the signal goes to the ranks themselves (mpirun's
    // children), as a batch system delivers it: Open MPI's own handling of
    // a signal to mpirun kills the ranks 1 s later, or ignores a signal
    // that comes before they run (doc/robustness.md).
    for (int attempt = 0; attempt < 12000; ++attempt)
      {
        run.targets = {run.pid};
        if (two_ranks)
          {
            run.targets.clear();
            std::istringstream children(
              RunOutput::execute("pgrep -P " + std::to_string(run.pid)).second);
            for (pid_t child; children >> child;)
              run.targets.push_back(child);
          }
        if ((!two_ranks || run.targets.size() == 2) &&
            std::filesystem::exists(name + "/summary.json"))
          break;
        // A run that ended before it wrote anything is reported below
        // (looked at, not reaped: wait_for() gets its exit code).
        siginfo_t ended = {};
        if (waitid(P_PID, run.pid, &ended, WEXITED | WNOHANG | WNOWAIT) == 0 &&
            ended.si_pid == run.pid)
          break;
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
      }
    run.running = std::chrono::steady_clock::now();
    return run;
  }

  /// Run the scene without a stop; returns whether it converged and how
  /// long it ran after its summary.json appeared.
  std::pair<bool, double>
  reference(const std::string &name, const bool two_ranks)
  {
    const Launched run  = launch(name, two_ranks);
    const int      code = wait_for(run.pid);
    return {code == 0 && json_status(name + "/summary.json") == "converged",
            std::chrono::duration<double>(std::chrono::steady_clock::now() -
                                          run.running)
              .count()};
  }

  /// Run a copy of the scene, interrupt it @p delay seconds after its
  /// summary.json appeared and check what it left.
  void
  interrupt(std::ostream      &out,
            const std::string &name,
            const double       delay,
            const bool         two_ranks,
            const bool         second_signal = false)
  {
    const Launched run = launch(name, two_ranks);
    const pid_t    pid = run.pid;
    std::this_thread::sleep_for(std::chrono::duration<double>(delay));
    for (const pid_t target : run.targets)
      kill(target, SIGTERM);
    if (second_signal)
      {
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
        kill(pid, SIGTERM);
      }
    const int  code   = wait_for(pid);
    const auto status = json_status(name + "/summary.json");
    const auto rows   = whole_rows(name + "/load_steps.csv");
    const auto steps =
      RunOutput::first_number(RunOutput::result_numbers(name), "load steps");

    if (second_signal)
      {
        // Ended at once: the files are those of the last complete write.
        out << name << ": second signal: valid summary.json: "
            << verdict(!status.empty()) << ", whole load_steps.csv rows: "
            << verdict(rows.first) << "\n";
        return;
      }
    // mpirun reports its own exit code; a single process gives 143.
    const bool interrupted = status == "interrupted";
    const bool code_ok =
      two_ranks ? true : (interrupted ? code == 143 : code == 0);
    const bool files_ok = (interrupted || status == "converged") && rows.first &&
                          static_cast<double>(rows.second) == steps;
    bool restarted = true;
    if (interrupted)
      {
        std::vector<std::string> again = command(name, two_ranks);
        again.pop_back();
        again.push_back("--restart");
        again.push_back(name);
        restarted = wait_for(RunOutput::start_quietly(again)) == 0 &&
                    json_status(name + "/summary.json") == "converged";
      }
    out << name << ": exit code as its status says: " << verdict(code_ok)
        << "; valid summary.json and load_steps.csv: " << verdict(files_ok)
        << "; ends with the numbers of the run without a stop: "
        << verdict(restarted &&
                   same(name, two_ranks ? "reference_two_ranks" : "reference"))
        << "\n";
  }
} // namespace

int
main()
{
  std::ofstream out("output");
  const auto [ran, length]                     = reference("reference", false);
  const auto [ran_two_ranks, length_two_ranks] = reference("reference_two_ranks", true);
  out << "uninterrupted runs (1 and 2 ranks) converged: "
      << verdict(ran && ran_two_ranks) << "\n";

  std::mt19937                           random(2026);
  std::uniform_real_distribution<double> fraction(0.05, 0.95);
  for (unsigned int seed = 1; seed <= 4; ++seed)
    interrupt(out, "seed" + std::to_string(seed), fraction(random) * length, false);
  interrupt(out, "two_ranks", fraction(random) * length_two_ranks, true);
  interrupt(out, "twice", 0.5 * length, false, true);
}
