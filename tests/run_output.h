// Reading what a run of the signorini executable wrote, for tests that run
// whole scenes and check numbers computed from the output files.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>

extern char **environ;

namespace RunOutput
{
  /// The whole text of a file (empty if it cannot be read).
  inline std::string
  read_text(const std::string &file)
  {
    std::ifstream     in(file);
    std::stringstream buffer;
    buffer << in.rdbuf();
    return buffer.str();
  }

  /// The rows of a CSV file with a header line, as name -> value maps.
  inline std::vector<std::map<std::string, double>>
  read_csv(const std::string &file)
  {
    std::ifstream                              in(file);
    std::string                                line;
    std::vector<std::string>                   names;
    std::vector<std::map<std::string, double>> rows;
    if (!std::getline(in, line))
      return rows;
    std::stringstream header(line);
    for (std::string name; std::getline(header, name, ',');)
      names.push_back(name);
    while (std::getline(in, line))
      {
        std::stringstream             row(line);
        std::map<std::string, double> values;
        std::string                   cell;
        for (unsigned int i = 0; i < names.size() && std::getline(row, cell, ','); ++i)
          values[names[i]] = std::atof(cell.c_str());
        rows.push_back(values);
      }
    return rows;
  }

  /**
   * The "value" (or another numeric @p field, e.g. "relative error") of
   * quantity @p name in the "quantities" block of a summary.json (NaN if
   * the file or the quantity is missing).
   */
  inline double
  summary_quantity(const std::string &summary_file,
                   const std::string &name,
                   const std::string &field = "value")
  {
    std::ifstream     in(summary_file);
    std::stringstream buffer;
    buffer << in.rdbuf();
    const std::string text = buffer.str();
    // The run's own block, the last: each refinement cycle's record before
    // it has a "quantities" block of its own.
    const auto block = text.rfind("\"quantities\"");
    const auto        key   = text.find("\"" + name + "\"", block);
    if (block == std::string::npos || key == std::string::npos)
      return std::numeric_limits<double>::quiet_NaN();
    const std::string tag   = "\"" + field + "\":";
    const auto        value = text.find(tag, key);
    if (value == std::string::npos)
      return std::numeric_limits<double>::quiet_NaN();
    return std::strtod(text.c_str() + value + tag.size(), nullptr);
  }

  /**
   * Every number of a summary.json with the key it stands under, in file
   * order, except the wall times (the "wall time [s]" object) and the
   * peak memory, which differ from run to run by nature.
   */
  inline std::vector<std::pair<std::string, double>>
  summary_numbers(const std::string &summary_file)
  {
    std::ifstream     in(summary_file);
    std::stringstream buffer;
    buffer << in.rdbuf();
    std::string text = buffer.str();
    const auto  wall = text.find("\"wall time [s]\"");
    if (wall != std::string::npos)
      text.erase(wall, text.find('}', wall) - wall);
    std::vector<std::pair<std::string, double>> numbers;
    std::string                                 key;
    for (std::size_t i = 0; i < text.size(); ++i)
      if (text[i] == '"')
        {
          const auto end = text.find('"', i + 1);
          key            = text.substr(i + 1, end - i - 1);
          i              = end;
        }
      else if (text[i] == '-' || (text[i] >= '0' && text[i] <= '9'))
        {
          char        *end   = nullptr;
          const double value = std::strtod(text.c_str() + i, &end);
          // Timings and memory differ from run to run (also a contact
          // pair's "search wall time [s]" inside the contact block).
          if (key != "peak memory MB" && key.find("wall time") == std::string::npos)
            numbers.emplace_back(key, value);
          i = end - text.c_str() - 1;
        }
    return numbers;
  }

  /// summary_numbers() without any wall time (also those of the
  /// refinement cycles): what two runs of one scene must agree on.
  inline std::vector<std::pair<std::string, double>>
  result_numbers(const std::string &folder)
  {
    auto all = summary_numbers(folder + "/summary.json");
    std::vector<std::pair<std::string, double>> kept;
    for (const auto &e : all)
      if (e.first.find("wall time") == std::string::npos)
        kept.push_back(e);
    return kept;
  }

  /**
   * Whether the runs in folders @p a and @p b wrote the same numbers (to
   * @p tolerance relative) to summary.json (result_numbers()) and
   * load_steps.csv; the first difference goes to stderr.
   */
  inline bool
  same_results(const std::string &a, const std::string &b, const double tolerance)
  {
    auto differ = [tolerance](const double x, const double y) {
      return std::abs(x - y) > tolerance * std::max(std::abs(x), std::abs(y));
    };
    const auto x = result_numbers(a), y = result_numbers(b);
    if (x.size() < 20 || x.size() != y.size())
      {
        std::cerr << a << " vs " << b << ": " << x.size() << " and " << y.size()
                  << " numbers in summary.json\n";
        return false;
      }
    for (std::size_t i = 0; i < x.size(); ++i)
      if (x[i].first != y[i].first || differ(x[i].second, y[i].second))
        {
          std::cerr << a << " vs " << b << ": " << x[i].first << " "
                    << x[i].second << " vs " << y[i].second << "\n";
          return false;
        }
    const auto r = read_csv(a + "/load_steps.csv");
    const auto s = read_csv(b + "/load_steps.csv");
    if (r.empty() || r.size() != s.size())
      {
        std::cerr << a << " vs " << b << ": load_steps.csv has " << r.size()
                  << " and " << s.size() << " rows\n";
        return false;
      }
    for (std::size_t i = 0; i < r.size(); ++i)
      for (const auto &[key, value] : r[i])
        if (s[i].count(key) == 0 || differ(value, s[i].at(key)))
          {
            std::cerr << a << " vs " << b << ": load_steps.csv row " << i + 1
                      << " " << key << "\n";
            return false;
          }
    return true;
  }

  /**
   * Whether two refinement_cycles.csv tables (read_csv()) hold the same
   * cycles with the same numbers to @p tolerance relative, wall times
   * aside. An estimated error ("NAME_estimated_error") is compared
   * relative to its quantity NAME: the estimate of a quantity that the
   * load fixes (a resultant) is round-off.
   */
  inline bool
  same_cycles(const std::vector<std::map<std::string, double>> &a,
              const std::vector<std::map<std::string, double>> &b,
              const double                                      tolerance)
  {
    bool same = a.size() == b.size();
    for (std::size_t c = 0; same && c < a.size(); ++c)
      for (const auto &[column, value] : a[c])
        if (column.find("wall_time") == std::string::npos)
          {
            const auto   suffix = column.find("_estimated_error");
            const double scale  = suffix == std::string::npos ?
                                    std::abs(value) :
                                    std::abs(a[c].at(column.substr(0, suffix)));
            same &= b[c].count(column) > 0 &&
                    std::abs(b[c].at(column) - value) <= tolerance * scale + 1e-14;
          }
    return same;
  }

  /// Whether summary.json @p file holds the entry `"key": true`.
  inline bool
  summary_flag(const std::string &file, const std::string &key)
  {
    return read_text(file).find("\"" + key + "\": true") != std::string::npos;
  }

  /// The first number stored under @p key in @p numbers (from
  /// summary_numbers()), NaN if there is none.
  inline double
  first_number(const std::vector<std::pair<std::string, double>> &numbers,
               const std::string                                 &key)
  {
    for (const auto &e : numbers)
      if (e.first == key)
        return e.second;
    return std::numeric_limits<double>::quiet_NaN();
  }

  /// The total Newton iterations of the run in @p folder (NaN if its
  /// summary.json has none).
  inline double
  newton_iterations(const std::string &folder)
  {
    return first_number(summary_numbers(folder + "/summary.json"), "newton iterations");
  }

  /**
   * Every quantity's "value" in the run's own "quantities" block of a
   * summary.json (the last one: each refinement cycle's record before it
   * has a block of its own), in file order.
   */
  inline std::vector<std::pair<std::string, double>>
  quantity_values(const std::string &summary_file)
  {
    const std::string text  = read_text(summary_file);
    std::vector<std::pair<std::string, double>> values;
    const auto block = text.rfind("\"quantities\"");
    if (block == std::string::npos)
      return values;
    std::size_t i     = text.find('{', block);
    int         depth = 0;
    std::string name;
    for (; i < text.size(); ++i)
      if (text[i] == '{')
        ++depth;
      else if (text[i] == '}')
        {
          if (--depth == 0)
            break;
        }
      else if (text[i] == '"')
        {
          const auto        end = text.find('"', i + 1);
          const std::string key = text.substr(i + 1, end - i - 1);
          i                     = end;
          if (depth == 1)
            name = key;
          else if (depth == 2 && key == "value")
            values.emplace_back(name,
                                std::strtod(text.c_str() + text.find(':', end) + 1,
                                            nullptr));
        }
    return values;
  }

  /**
   * The largest difference between the quantities of the runs in folders
   * @p a and @p b (quantity_values()), each relative to the larger of the
   * two values, and for a component of a vector (a name with _x, _y or _z
   * as a word: contact_force_x, reaction_x_boundary_2) relative to that
   * vector's magnitude, so that a component that vanishes by symmetry
   * counts as the round-off it is. 1 if the two runs do not have the same
   * quantities; @p worst_name gets the quantity.
   */
  inline double
  largest_quantity_difference(const std::string &a,
                              const std::string &b,
                              std::string       *worst_name = nullptr)
  {
    const auto x = quantity_values(a + "/summary.json");
    const auto y = quantity_values(b + "/summary.json");
    if (x.empty() || x.size() != y.size())
      return 1.;
    // The vector a component belongs to: its name with the component
    // replaced.
    auto vector_of = [](std::string name) {
      for (const std::string c : {"_x", "_y", "_z"})
        {
          const auto at = name.find(c);
          if (at != std::string::npos &&
              (at + 2 == name.size() || name[at + 2] == '_'))
            return name.replace(at, 2, "_?");
        }
      return std::string();
    };
    std::map<std::string, double> magnitude;
    for (const auto &[name, value] : x)
      {
        const auto v = vector_of(name);
        if (!v.empty())
          magnitude[v] += value * value;
      }
    double worst = 0.;
    for (std::size_t i = 0; i < x.size(); ++i)
      {
        if (x[i].first != y[i].first || !std::isfinite(x[i].second) ||
            !std::isfinite(y[i].second))
          return 1.;
        double     scale = std::max(std::abs(x[i].second), std::abs(y[i].second));
        const auto v     = vector_of(x[i].first);
        if (!v.empty())
          scale = std::max(scale, std::sqrt(magnitude[v]));
        const double d = x[i].second == y[i].second ?
                           0. :
                           std::abs(x[i].second - y[i].second) / scale;
        if (d > worst)
          {
            worst = d;
            if (worst_name)
              *worst_name = x[i].first;
          }
      }
    return worst;
  }

  /// Whether the runs in @p a and @p b report the same contact force
  /// (y), Hertz half-width a and peak pressure p0, to @p tolerance
  /// relative.
  inline bool
  same_hertz_answer(const std::string &a, const std::string &b, const double tolerance)
  {
    bool same = true;
    for (const char *q : {"contact_force_y", "hertz_a", "hertz_p0"})
      {
        const double x = summary_quantity(a + "/summary.json", q);
        const double y = summary_quantity(b + "/summary.json", q);
        same &= std::isfinite(x) && std::abs(x - y) <= tolerance * std::abs(x);
      }
    return same;
  }

  /**
   * The largest relative difference |x_a - x_b| / |x_a| of the quantities
   * @p names between the runs in folders @p a and @p b (1 if one is
   * missing or not finite on either side; 0 for a quantity that is exactly
   * 0 in both, such as a force component that vanishes by symmetry).
   */
  inline double
  largest_relative_difference(const std::string              &a,
                              const std::string              &b,
                              const std::vector<std::string> &names)
  {
    double worst = 0.;
    for (const auto &q : names)
      {
        const double x = summary_quantity(a + "/summary.json", q);
        const double y = summary_quantity(b + "/summary.json", q);
        const double d = std::abs(x - y) / std::max(std::abs(x), 1e-300);
        worst          = std::isnan(d) ? 1. : std::max(worst, d);
      }
    return worst;
  }

  /// The sum of every number stored under @p key in the summary.json of
  /// the run in @p folder (e.g. the load steps' "linear iterations").
  inline double
  summary_sum(const std::string &folder, const std::string &key)
  {
    double sum = 0.;
    for (const auto &e : summary_numbers(folder + "/summary.json"))
      if (e.first == key)
        sum += e.second;
    return sum;
  }

#if defined(SIGNORINI_EXECUTABLE) && defined(SIGNORINI_SOURCE_DIR)
  /**
   * Run the committed scene prm/@p scene with @p edits appended (entries
   * that override the scene's), writing to the folder @p name, without
   * fields and quietly; @p launcher (e.g. "mpirun -np 2 ") goes before the
   * executable. Returns std::system's status (0: exit code 0).
   */
  inline int
  run_scene(const std::string &name,
            const std::string &scene,
            const std::string &edits,
            const std::string &launcher = "")
  {
    std::ofstream(name + ".prm")
      << "include " << SIGNORINI_SOURCE_DIR << "/prm/" << scene << "\n"
      << "set Output directory = " << name << "\n"
      << edits
      << "subsection Output\n  set Format = none\n  set Verbosity = quiet\nend\n";
    return std::system(
      (launcher + SIGNORINI_EXECUTABLE + " " + name + ".prm").c_str());
  }
#endif

  inline const char *
  verdict(const bool ok)
  {
    return ok ? "yes" : "NO";
  }
  /// Exit code (-1 if it did not exit normally) and standard output of
  /// the shell command @p command.
  inline std::pair<int, std::string>
  execute(const std::string &command)
  {
    FILE       *pipe = popen(command.c_str(), "r");
    std::string text;
    char        buffer[512];
    while (pipe && fgets(buffer, sizeof(buffer), pipe))
      text += buffer;
    const int status = pipe ? pclose(pipe) : -1;
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, text};
  }
  /// Start the command @p args (searched in PATH) with its output
  /// discarded, without waiting for it; returns its pid.
  inline pid_t
  start_quietly(const std::vector<std::string> &args)
  {
    std::vector<char *> argv;
    for (const auto &a : args)
      argv.push_back(const_cast<char *>(a.c_str()));
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
    pid_t pid = -1;
    posix_spawnp(&pid, argv[0], &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    return pid;
  }
} // namespace RunOutput
