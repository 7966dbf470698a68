// signorini --study on a small Hertz study (uniform Global refinements 2, 3,
// 4; adaptive with 3 cycles):
// - study.csv has one row per run (3) and per refinement cycle (4), with
//   DoFs growing along each series and positive wall times;
// - the converged model value of p0 is the Richardson extrapolation of the
//   three uniform runs, recomputed here from their rows, and every row's
//   error against it is |value - converged| / |converged|;
// - the analytic error is measured against Hertz's p0 = 10.98917;
// - a reported quantity (the L2 error of the pressure profile) is written
//   to every row as the run's summary.json has it;
// - a Settings entry the scene does not have is a clear input error (exit 2)
//   naming the variant.

#include "run_output.h"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>

using RunOutput::read_csv;
using RunOutput::verdict;

namespace
{
  void
  write_study(const std::string &file, const std::string &adaptive_settings)
  {
    std::ofstream(file)
      << "include " << SIGNORINI_SOURCE_DIR << "/prm/hertz_adaptive.prm\n"
      << "set Output directory = " << file.substr(0, file.size() - 4) << "\n"
      << "subsection Study\n"
      << "  set Quantities = hertz_a, hertz_p0\n"
      << "  set Reported quantities = hertz_pressure_l2_error\n"
      << "  set Reference variant = uniform\n"
      << "  subsection Variant 1\n"
      << "    set Name = uniform\n"
      << "    set Settings = Mesh refinement/Number of cycles = 0\n"
      << "    set Series entry = Mesh/Global refinements\n"
      << "    set Series values = 2, 3, 4\n"
      << "  end\n"
      << "  subsection Variant 2\n"
      << "    set Name = adaptive\n"
      << "    set Settings = " << adaptive_settings << "\n"
      << "  end\n"
      << "end\n";
  }
} // namespace

int
main()
{
  std::ofstream out("output");
  write_study("small.prm", "Mesh refinement/Number of cycles = 3");
  const int status = std::system((std::string(SIGNORINI_EXECUTABLE) +
                                  " --study small.prm > small.log 2>&1")
                                   .c_str());
  out << "study ran: " << verdict(status == 0) << "\n";
  const auto rows = read_csv("small/study/study.csv");
  out << "rows: " << rows.size() << "\n";
  bool growing = rows.size() == 7, timed = growing;
  for (std::size_t i = 1; i < rows.size(); ++i)
    if (i != 3) // the first adaptive row starts a new series
      growing &= rows[i].at("dofs") > rows[i - 1].at("dofs");
  for (const auto &r : rows)
    timed &= r.at("wall_time") > 0. && r.at("peak_memory_mb") > 0.;
  out << "DoFs grow along each series: " << verdict(growing) << "\n"
      << "wall time and peak memory recorded: " << verdict(timed) << "\n";
  if (rows.size() == 7)
    {
      const double q1 = rows[0].at("hertz_p0"), q2 = rows[1].at("hertz_p0"),
                   q3 = rows[2].at("hertz_p0");
      const double ratio     = (q2 - q1) / (q3 - q2);
      const double converged = q3 + (q3 - q2) / (ratio - 1.);
      bool         errors    = true;
      for (const auto &r : rows)
        {
          errors &= std::abs(r.at("hertz_p0_error_converged") -
                             std::abs(r.at("hertz_p0") - converged) / converged) <
                    1e-8;
          errors &= std::abs(r.at("hertz_p0_error_analytic") -
                             std::abs(r.at("hertz_p0") - 10.98917075) / 10.98917075) <
                    1e-7;
        }
      out << "errors against the Richardson value and against Hertz: "
          << verdict(errors) << "\n";
      // A reported quantity: the run's own value, in every row.
      const double l2 = RunOutput::summary_quantity("small/study/uniform-4/summary.json",
                                                    "hertz_pressure_l2_error");
      const std::string key = "hertz_pressure_l2_error";
      bool reported = rows[2].count(key) && std::abs(rows[2].at(key) / l2 - 1.) < 1e-8;
      // Every row but the coarsest (one node in contact: no profile).
      for (std::size_t i = 1; i < rows.size(); ++i)
        reported &= rows[i].count(key) && rows[i].at(key) > 0. && rows[i].at(key) < 1.;
      out << "reported quantity (pressure profile L2 error) in the rows, as in "
             "summary.json: "
          << verdict(reported) << "\n";
    }

  write_study("bad.prm", "Mesh refinement/Number of cycle = 3");
  const int bad = std::system(
    (std::string(SIGNORINI_EXECUTABLE) + " --study bad.prm > bad.log 2>&1").c_str());
  std::ifstream log("bad.log");
  const std::string text((std::istreambuf_iterator<char>(log)),
                         std::istreambuf_iterator<char>());
  out << "unknown entry in Settings: exit 2: "
      << verdict(WIFEXITED(bad) && WEXITSTATUS(bad) == 2) << "\n"
      << "message names the variant and the entry: "
      << verdict(text.find("Study > Variant 2 > Settings") != std::string::npos &&
                 text.find("Number of cycle") != std::string::npos)
      << "\n";
  std::cerr << text;

  // The study's folder cannot be made (a file stands where the output
  // directory should be): exit 2 with a message, on every rank (rank 0
  // alone threw before, and on several ranks the others waited for it).
  std::ofstream("blocked") << "a file, not a folder\n";
  write_study("blocked_study.prm", "Mesh refinement/Number of cycles = 1");
  std::ofstream("blocked_study.prm", std::ios::app)
    << "set Output directory = blocked/run\n";
  const auto blocked = RunOutput::execute(std::string(SIGNORINI_EXECUTABLE) +
                                          " --study blocked_study.prm 2>&1");
  out << "study folder that cannot be made: exit 2: "
      << verdict(blocked.first == 2) << ", message names it: "
      << verdict(blocked.second.find("cannot create 'blocked/run/study'") !=
                 std::string::npos)
      << "\n";
}
