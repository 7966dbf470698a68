// The slip length sweep of tests/cattaneo_mindlin_two_body_2d on the
// scene's own mesh (prm/cattaneo_mindlin_two_body_2d.prm, h/a = 0.031):
// c/a at Q/(mu P) = 0.25, 0.5, 0.75 moves by less than 0.02 (the issue's
// check) when the slip length goes from 1e-4 h (the default) to 1e-6 h,
// and stays within max(0.03, 1.5 h/a) of Mindlin's; the outer loop ends
// below 1e-6 within 10 iterations in every step. Measured: c/a the same to
// all printed digits (0.8732, 0.7050, 0.4907). Kept outside the default
// suite: the 1e-6 h run takes about 205 s of CPU (the pressing steps are cut
// ten times: the stick stiffness 2 mu lambda / eps is 100 times the
// default's), about 4 minutes in all. On a coarse mesh one node changing
// status moves c/a by more than 0.02 (tests/cattaneo_mindlin_two_body_2d).
// Only verdicts are printed.

#include "mindlin_steps.h"
#include "run_output.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

namespace
{
  using RunOutput::read_csv;
  using RunOutput::verdict;

  struct Run
  {
    bool                ok = false, settled = true;
    double              a = 0., h = 0.;
    std::vector<double> ratio, c_over_a;
  };

  Run
  run(const std::string &name, const std::string &edits)
  {
    Run r;
    r.ok = RunOutput::run_scene(name, "cattaneo_mindlin_two_body_2d.prm", edits) == 0;
    r.a  = RunOutput::summary_quantity(name + "/summary.json", "hertz_a", "reference");
    r.h              = MindlinSteps::node_spacing(name + "/contact_profile.csv", r.a);
    const auto steps = MindlinSteps::read(name + "/load_steps.csv", r.a, {2., 3., 4.});
    r.settled        = steps.settled;
    r.ratio          = steps.ratio;
    r.c_over_a       = steps.c_over_a;
    std::cerr << name << ": h/a " << r.h / r.a << "\n";
    for (unsigned int i = 0; i < r.ratio.size(); ++i)
      std::cerr << "  Q/(mu P) " << r.ratio[i] << " c/a " << r.c_over_a[i] << "\n";
    return r;
  }

  void
  check(std::ostream &out, const Run &r, const std::string &what)
  {
    out << what << ": exit code 0: " << verdict(r.ok) << "\n";
    const bool three = r.ratio.size() == 3;
    out << what << ": three tangential steps: " << verdict(three) << "\n";
    if (!three)
      return;
    bool close = true;
    for (unsigned int i = 0; i < 3; ++i)
      close = close && std::abs(r.c_over_a[i] - std::sqrt(1. - r.ratio[i])) <=
                         std::max(0.03, 1.5 * r.h / r.a);
    out << what << ": c/a within max(0.03, 1.5 h/a) of Mindlin's at the three ratios: "
        << verdict(close) << "\n"
        << what << ": outer loop below 1e-6 within 10 iterations each step: "
        << verdict(r.settled) << "\n";
  }
} // namespace

int
main()
{
  std::ofstream out("output");
  const Run normal = run("run_default", "");
  check(out, normal, "slip length 1e-4 h");
  const Run sharp = run("run_eps", "subsection Contact\n  subsection Friction\n"
                                   "    set Slip length = 1e-6\n  end\nend\n");
  check(out, sharp, "slip length 1e-6 h");
  if (normal.ratio.size() == 3 && sharp.ratio.size() == 3)
    {
      double change = 0.;
      for (unsigned int i = 0; i < 3; ++i)
        change = std::max(change, std::abs(normal.c_over_a[i] - sharp.c_over_a[i]));
      out << "c/a moves by less than 0.02 from slip length 1e-4 h to 1e-6 h: "
          << verdict(change < 0.02) << "\n";
    }
}
