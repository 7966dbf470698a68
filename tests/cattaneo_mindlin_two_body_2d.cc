// Cattaneo-Mindlin between two deformable bodies of the same material,
// prm/cattaneo_mindlin_two_body_2d.prm (issue 50): a compressible
// neo-Hookean half disk (E = 200, nu = 0.3) pressed onto a block of the
// same material (two-body contact, integral form, newton-penalty, mu = 0.3),
// then pushed sideways by a dead traction Q = 0.25, 0.5, 0.75 mu P_Hertz at
// t = 2, 3, 4. Identical materials uncouple the normal and the tangential
// problems (Dundurs' beta = 0), so c/a = sqrt(1 - Q/(mu P)) with
// E* = E/(2(1 - nu^2)). From load_steps.csv, contact_profile.csv and
// summary.json:
// - the normal force within 1% of the Hertz reference's P (measured
//   -0.07%); Q/(mu P), the friction force over mu times the normal force,
//   within 0.02 of 0.25, 0.5, 0.75 (measured 0.2523, 0.5050, 0.7583);
// - c/a within max(0.03, 1.5 h/a) of Mindlin's at the three ratios, h the
//   largest spacing of the half disk's contact nodes within |x| < a (the
//   friction acts at those nodes; h/a = 0.031, allowance 0.046; measured
//   +0.0085, +0.0015, -0.0010), and the program's reference equal to
//   a sqrt(1 - Q/(mu P)) with its own Q/(mu P) (1e-9);
// - Sigma F_t = Q: the contact's whole force along x on the half disk
//   (friction plus the normal force's x component) equal to -Q within 0.5%
//   (measured 1e-7). The friction force alone is larger than Q by 0.87%,
//   0.96%, 1.03%: the 0.5% for it is not met, and is checked at
//   1.5% as a guard. Why: each body's surface under the tangential traction
//   q tilts by du_y/dx = (1 - 2 nu)(1 + nu) q / E (half-space; the two
//   bodies tilt alike, so the gap is unchanged), and the normal force on the
//   tilted interface carries about (1 - 2 nu)(1 + nu)/E * integral p q dx
//   of the load (the estimate is 0.00227 at Q = 0.75 mu P; measured
//   0.00200, 1.03% of Q; at nu = 0.45 the excess falls to 0.20%);
// - the outer loop below 1e-6 within 10 iterations in every step (at most
//   5 measured);
// - the slip length swept over two decades, 1e-4 h (the default) to
//   1e-6 h: the issue asks c/a to move by less than 0.02. c/a is quantised
//   by the node spacing: a node near the stick zone's edge that slips by
//   less than 1e-4 h in the step counts as sticking at the default and as
//   slipping at 1e-6 h, which moves one edge by a node and c/a by h/(2a).
//   On the scene's mesh h/(2a) = 0.015 and 1e-6 h gives the same c/a to all
//   digits (1e-5 h too; 1e-3 h moves it by 0.015 at 0.75, 1e-2 h by
//   0.031-0.046), but the run takes 205 s of CPU (ten cuts while pressing,
//   where the stick stiffness grows as 1/eps): that check is
//   tests/cattaneo_mindlin_two_body_2d_long. Here, on a coarse mesh
//   (Local refinements 5, h/a = 0.12, h/(2a) = 0.061), the 0.02 cannot be
//   met when a node sits near an edge: measured 0, 0.061, 0 at the three
//   ratios (one node, at Q = 0.5 mu P, the 1e-6 h value 0.674 being the
//   closer to Mindlin's 0.702). The test checks that c/a moves by at most
//   one node at one edge, 0.55 h/a (a guard at the measured level), and
//   that the coarse mesh's c/a is within max(0.03, 1.5 h/a) of Mindlin's
//   at both slip lengths.
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

  constexpr double mu = 0.3;

  struct Run
  {
    bool                ok = false;
    double              a = 0., h = 0., P_reference = 0.;
    std::vector<double> ratio, c_over_a, reference_c_over_a, applied_Q, friction_x,
      contact_x, normal_force;
    bool settled = true;
  };

  Run
  run(const std::string &name, const std::string &edits)
  {
    Run r;
    r.ok = RunOutput::run_scene(name, "cattaneo_mindlin_two_body_2d.prm", edits) == 0;
    const std::string summary = name + "/summary.json";
    r.a           = RunOutput::summary_quantity(summary, "hertz_a", "reference");
    r.P_reference = RunOutput::summary_quantity(summary, "contact_force_y", "reference");
    // The half disk's contact node spacing inside the contact zone.
    r.h              = MindlinSteps::node_spacing(name + "/contact_profile.csv", r.a);
    const auto steps = MindlinSteps::read(name + "/load_steps.csv", r.a, {2., 3., 4.});
    r.settled            = steps.settled;
    r.ratio              = steps.ratio;
    r.c_over_a           = steps.c_over_a;
    r.reference_c_over_a = steps.reference_c_over_a;
    for (const auto &s : steps.rows)
      {
        // The scene's dead traction on the 2-wide top: (t - 1)/4 mu P.
        r.applied_Q.push_back(0.25 * (s.at("time") - 1.) * mu * r.P_reference);
        r.friction_x.push_back(s.at("friction_force_x"));
        r.contact_x.push_back(s.at("contact_force_x"));
        r.normal_force.push_back(s.at("contact_force_y"));
      }
    std::cerr << name << ": a " << r.a << " h " << r.h << "\n";
    for (unsigned int i = 0; i < r.ratio.size(); ++i)
      std::cerr << "  Q/(mu P) " << r.ratio[i] << " c/a " << r.c_over_a[i] << " Mindlin "
                << r.reference_c_over_a[i] << " friction/Q - 1 "
                << -r.friction_x[i] / r.applied_Q[i] - 1. << " (friction + normal)/Q - 1 "
                << -(r.friction_x[i] + r.contact_x[i]) / r.applied_Q[i] - 1. << "\n";
    return r;
  }

  void
  check(std::ostream &out, const Run &r, const std::string &what, const bool forces)
  {
    out << what << ": exit code 0: " << verdict(r.ok) << "\n";
    const bool three = r.ratio.size() == 3;
    out << what << ": three tangential steps: " << verdict(three) << "\n";
    if (!three)
      return;
    const double targets[3] = {0.25, 0.5, 0.75};
    const double allowed    = std::max(0.03, 1.5 * r.h / r.a);
    for (unsigned int i = 0; i < 3; ++i)
      {
        const double mindlin = std::sqrt(1. - r.ratio[i]);
        out << what << ": Q/(mu P) = " << targets[i] << " (within 0.02): "
            << verdict(std::abs(r.ratio[i] - targets[i]) <= 0.02)
            << ", c/a within max(0.03, 1.5 h/a) of Mindlin's: "
            << verdict(std::abs(r.c_over_a[i] - mindlin) <= allowed)
            << ", reference = sqrt(1 - Q/(mu P)) (1e-9): "
            << verdict(std::abs(r.reference_c_over_a[i] - mindlin) <= 1e-9) << "\n";
        if (!forces)
          continue;
        const double Q = r.applied_Q[i];
        out << what << ": Q/(mu P) = " << targets[i]
            << ": normal force within 1% of Hertz's P: "
            << verdict(std::abs(r.normal_force[i] / r.P_reference - 1.) <= 0.01)
            << ", friction plus normal force along x = -Q (0.5%): "
            << verdict(std::abs((r.friction_x[i] + r.contact_x[i]) / Q + 1.) <= 0.005)
            << ", friction force alone = -Q within 1.5% (a guard: 1.03% measured, the "
               "interface tilts): "
            << verdict(std::abs(r.friction_x[i] / Q + 1.) <= 0.015) << "\n";
      }
    out << what << ": outer loop below 1e-6 within 10 iterations each step: "
        << verdict(r.settled) << "\n";
  }
} // namespace

int
main()
{
  std::ofstream out("output");
  const Run scene = run("run_scene", "");
  check(out, scene, "scene's mesh", true);

  const std::string coarse_mesh = "subsection Mesh\n  set Local refinements = 5\nend\n";
  const Run coarse = run("run_coarse", coarse_mesh);
  check(out, coarse, "coarse mesh", false);
  const Run sharp = run("run_eps", coarse_mesh + "subsection Contact\n  subsection Friction\n"
                                                 "    set Slip length = 1e-6\n  end\nend\n");
  check(out, sharp, "coarse mesh, slip length 1e-6 h", false);
  if (coarse.ratio.size() == 3 && sharp.ratio.size() == 3)
    {
      double change = 0.;
      for (unsigned int i = 0; i < 3; ++i)
        change = std::max(change, std::abs(coarse.c_over_a[i] - sharp.c_over_a[i]));
      out << "coarse mesh: c/a moves by at most one node at one edge (0.55 h/a) from slip "
             "length 1e-4 h to 1e-6 h (a guard: the issue's 0.02 is below this mesh's "
             "h/(2a); tests/cattaneo_mindlin_two_body_2d_long checks it on the scene's "
             "mesh): "
          << verdict(change <= 0.55 * coarse.h / coarse.a) << "\n";
    }
}
