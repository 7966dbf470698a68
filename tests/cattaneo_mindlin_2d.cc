// Cattaneo-Mindlin in 2D, prm/cattaneo_mindlin_2d.prm (issue 50): an
// incompressible cylinder pressed onto the rigid plane, then dragged
// sideways; at t = 2, 3 and 4 the load ratio Q/(mu P) is about 0.25, 0.5
// and 0.75. From load_steps.csv (tangential_load_ratio, stick_radius and
// Mindlin's stick_radius_reference a sqrt(1 - Q/(mu P)) per step) and
// summary.json:
// - on the scene's mesh (Local refinements 5, h = 0.0123 at the contact)
//   and once refined (6): c/a within max(0.03, 1.5 h/a) of Mindlin's at
//   the three ratios (measured on 5: +0.050, +0.075, +0.039 with the
//   allowance 0.20; on 6: +0.033, +0.041, +0.022 with 0.10);
// - the c/a error is smaller on the finer mesh; the tangential traction's
//   L2 error against Mindlin's (at t = 4) is at most 0.15 on both
//   (measured 0.105 and 0.112: it does not fall with h, and the issue's
//   0.05 is not met; doc/friction.md says why);
// - c/a moves by less than 0.02 when the slip length goes from 1e-4 h
//   (the default) to 1e-6 h (measured: 0 at the three ratios; 1e-3 h
//   gives c/a larger by 0.034, 0.034 and 0.067);
// - the outer loop ends below 1e-6 within 10 iterations in every step.
// Only verdicts are printed.

#include "mindlin_steps.h"
#include "run_output.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <map>
#include <string>
#include <vector>

namespace
{
  using RunOutput::read_csv;
  using RunOutput::verdict;

  struct Run
  {
    bool                ok = false;
    double              a = 0., h = 0., l2 = 0.;
    std::vector<double> ratio, c_over_a, reference_c_over_a;
    bool                settled = true;
  };

  double
  summary_number(const std::string &file, const std::string &key)
  {
    for (const auto &e : RunOutput::summary_numbers(file))
      if (e.first == key)
        return e.second;
    return std::nan("");
  }

  Run
  run(const std::string &name, const std::string &edits)
  {
    Run r;
    r.ok = RunOutput::run_scene(name, "cattaneo_mindlin_2d.prm", edits) == 0;
    const std::string summary = name + "/summary.json";
    r.a  = RunOutput::summary_quantity(summary, "hertz_a", "reference");
    r.h  = summary_number(summary, "min mesh size");
    r.l2 = RunOutput::summary_quantity(summary, "friction_traction_l2_error");
    const auto steps = MindlinSteps::read(name + "/load_steps.csv", r.a, {2., 3., 4.});
    r.settled            = steps.settled;
    r.ratio              = steps.ratio;
    r.c_over_a           = steps.c_over_a;
    r.reference_c_over_a = steps.reference_c_over_a;
    std::cerr << name << ": a " << r.a << " h " << r.h << " L2 " << r.l2 << "\n";
    for (unsigned int i = 0; i < r.ratio.size(); ++i)
      std::cerr << "  Q/(mu P) " << r.ratio[i] << " c/a " << r.c_over_a[i] << " Mindlin "
                << r.reference_c_over_a[i] << "\n";
    return r;
  }

  double
  error(const Run &r, const unsigned int i)
  {
    return std::abs(r.c_over_a[i] - r.reference_c_over_a[i]);
  }

  void
  check(std::ostream &out, const Run &r, const std::string &what)
  {
    out << what << ": exit code 0: " << verdict(r.ok) << "\n";
    const bool three = r.ratio.size() == 3;
    out << what << ": three tangential steps: " << verdict(three) << "\n";
    if (!three)
      return;
    const double targets[3] = {0.25, 0.5, 0.75};
    for (unsigned int i = 0; i < 3; ++i)
      {
        const double allowed = std::max(0.03, 1.5 * r.h / r.a);
        out << what << ": Q/(mu P) = " << targets[i] << " (within 0.05): "
            << verdict(std::abs(r.ratio[i] - targets[i]) <= 0.05) << ", c/a within max(0.03, "
            << "1.5 h/a) of Mindlin's: " << verdict(error(r, i) <= allowed) << "\n";
      }
    out << what << ": outer loop below 1e-6 within 10 iterations each step: "
        << verdict(r.settled) << "\n";
  }
} // namespace

int
main()
{
  std::ofstream out("output");
  const Run coarse = run("run_5", "");
  check(out, coarse, "scene's mesh");
  const Run fine = run("run_6", "subsection Mesh\n  set Local refinements = 6\nend\n");
  check(out, fine, "refined once");
  if (coarse.ratio.size() == 3 && fine.ratio.size() == 3)
    {
      double e_coarse = 0., e_fine = 0.;
      for (unsigned int i = 0; i < 3; ++i)
        {
          e_coarse += error(coarse, i);
          e_fine += error(fine, i);
        }
      out << "c/a error smaller on the finer mesh: " << verdict(e_fine < e_coarse) << "\n"
          << "traction L2 error at most 0.15 on both meshes (a guard: the issue's 0.05 "
             "is not met, doc/friction.md): "
          << verdict(fine.l2 <= 0.15 && coarse.l2 <= 0.15) << "\n";
    }
  const Run sharp = run("run_eps", "subsection Contact\n  subsection Friction\n"
                                   "    set Slip length = 1e-6\n  end\nend\n");
  check(out, sharp, "slip length 1e-6 h");
  if (coarse.ratio.size() == 3 && sharp.ratio.size() == 3)
    {
      double change = 0.;
      for (unsigned int i = 0; i < 3; ++i)
        change = std::max(change, std::abs(coarse.c_over_a[i] - sharp.c_over_a[i]));
      out << "c/a moves by less than 0.02 from slip length 1e-4 h to 1e-6 h: "
          << verdict(change < 0.02) << "\n";
    }
}
