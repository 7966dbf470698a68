// The penalty continuation when it meets its limits, on Hertz on a rigid
// plane (prm/default.prm with 3 local refinements):
// - the cap: a penetration tolerance of 1e-6 h that would need mu ~ 1e11
//   mu_0, with 'Maximum penalty ratio' = 1e4. No stage goes beyond
//   1e4 mu_0, every load step ends at the cap, the run is accepted with
//   "penetration tolerance met": false and a solver status that names the
//   cap, and the answer is still Hertz's (p0 within 2%, the penetration
//   the one of mu = 1e4 mu_0, not garbage);
// - a failed stage: jumps of 1e6 in mu (Minimum growth = Maximum growth =
//   1e6) with at most 10 Newton iterations per stage (Maximum iterations).
//   The big jump fails; the stage is tried again from the previous stage's
//   solution with a jump of 1e3, which converges; the run ends converged,
//   with the tolerance met and Hertz's p0 within 2%.

#include "run_output.h"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

using RunOutput::first_number;
using RunOutput::verdict;

namespace
{
  // The scene's penalty path (its default is the interior point method)
  // on a coarser mesh.
  const std::string coarse = "subsection Mesh\n  set Local refinements = 3\nend\n"
                             "subsection Solver\n  set Method = newton-penalty\nend\n";
} // namespace

int
main()
{
  std::ofstream out("output");

  // The cap.
  const int capped = RunOutput::run_scene(
    "capped", "default.prm",
    coarse + "subsection Solver\n  subsection Penalty\n"
             "    set Penetration tolerance = 1e-6\n"
             "    set Maximum penalty ratio = 1e4\n  end\nend\n");
  {
    const std::string text    = RunOutput::read_text("capped/summary.json");
    const auto        numbers = RunOutput::summary_numbers("capped/summary.json");
    const double      mu0     = first_number(numbers, "initial penalty");
    double            largest = 0.;
    unsigned int      at_cap  = 0, steps = 0;
    double            last_mu = 0.;
    for (const auto &[key, value] : numbers)
      {
        if (key == "mu")
          {
            largest = std::max(largest, value);
            last_mu = value;
          }
        // Each step's record ends with its contact force; its last stage
        // came before.
        if (key == "contact force")
          {
            ++steps;
            at_cap += std::abs(last_mu / (1e4 * mu0) - 1.) < 1e-12;
          }
      }
    const double p0  = RunOutput::summary_quantity("capped/summary.json", "hertz_p0");
    const double pen = RunOutput::summary_quantity("capped/summary.json",
                                                   "max_penetration_over_h");
    out << "cap: exit 0 and status converged: "
        << verdict(capped == 0 &&
                   text.find("\"status\": \"converged\"") != std::string::npos)
        << "\n"
        << "cap: no stage beyond 1e4 mu_0: "
        << verdict(mu0 > 0. && largest <= 1e4 * mu0 * (1. + 1e-12)) << "\n"
        << "cap: every load step ends at the cap: "
        << verdict(steps > 0 && at_cap == steps) << "\n"
        << "cap: penetration tolerance met false, status names the cap: "
        << verdict(text.find("\"penetration tolerance met\": false") != std::string::npos &&
                   text.find("mu capped at") != std::string::npos)
        << "\n"
        << "cap: p0 within 2% of Hertz: "
        << verdict(std::abs(p0 / 10.98917 - 1.) < 0.02) << "\n"
        << "cap: penetration / h in (1e-6, 1e-2): " << verdict(pen > 1e-6 && pen < 1e-2)
        << "\n";
    std::cerr << "cap: mu0 " << mu0 << ", largest " << largest << ", steps " << steps
              << ", p0 " << p0 << ", penetration / h " << pen << "\n";
  }

  // A failed stage, tried again with a smaller jump.
  const int retried = RunOutput::run_scene(
    "retried", "default.prm",
    coarse + "subsection Solver\n  subsection Newton\n"
             "    set Maximum iterations = 10\n  end\n"
             "  subsection Penalty\n    set Minimum growth = 1e6\n"
             "    set Maximum growth = 1e6\n  end\nend\n");
  {
    const std::string text    = RunOutput::read_text("retried/summary.json");
    const auto        numbers = RunOutput::summary_numbers("retried/summary.json");
    // Every stage in file order: its mu and whether it converged.
    std::vector<std::pair<double, bool>> stages;
    for (auto pos = text.find("\"mu\": "); pos != std::string::npos;
         pos      = text.find("\"mu\": ", pos + 1))
      {
        const auto close = text.find('}', pos);
        stages.emplace_back(std::strtod(text.c_str() + pos + 6, nullptr),
                            text.substr(pos, close - pos).find("\"converged\": false") ==
                              std::string::npos);
      }
    // After a failed stage, the next one jumps by the square root of the
    // failed jump from the last converged stage.
    unsigned int failures = 0, halved = 0;
    for (std::size_t i = 1; i + 1 < stages.size(); ++i)
      if (!stages[i].second)
        {
          ++failures;
          std::size_t j = i;
          while (j > 0 && !stages[j - 1].second)
            --j;
          if (j == 0)
            continue;
          const double base = stages[j - 1].first;
          halved += std::abs(stages[i + 1].first / base -
                             std::sqrt(stages[i].first / base)) <
                    1e-9 * stages[i + 1].first / base;
        }
    std::cerr << "retry: " << stages.size() << " stages, " << failures
              << " failed, " << halved << " followed by the square root of the jump\n";
    const double p0 = RunOutput::summary_quantity("retried/summary.json", "hertz_p0");
    out << "retry: exit 0 and status converged: "
        << verdict(retried == 0 &&
                   text.find("\"status\": \"converged\"") != std::string::npos)
        << "\n"
        << "retry: a stage failed and was tried again with the square root of its jump: "
        << verdict(failures > 0 && halved == failures) << "\n"
        << "retry: penetration tolerance met: "
        << verdict(text.find("\"penetration tolerance met\": true") != std::string::npos)
        << "\n"
        << "retry: p0 within 2% of Hertz: "
        << verdict(std::abs(p0 / 10.98917 - 1.) < 0.02) << "\n";
  }
}
