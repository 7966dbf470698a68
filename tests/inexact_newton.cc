// Inexact Newton (Solver > Linear solver > Forcing term = Eisenstat-Walker):
// - LinearSolver::forcing_term() follows its documented rule: the maximum
//   at a minimisation's first iteration, 0.9 (|g| / |g_prev|)^2 after it,
//   Kelley's safeguard against sudden tightening, the bound 0.5 tol / |g|,
//   the floor 'Relative tolerance'; the fixed forcing and a direct solver
//   give 'Relative tolerance';
// - 3D SSNV187 (14 739 DoFs, CG + AMG, nu = 0.499) and the rigid Hertz
//   scene with the penalty path (3770 DoFs, CG + AMG) solved with the
//   fixed tolerance and with the forcing term give the same answers to
//   1e-8 relative, on one rank and (SSNV187) on two, and the forcing term
//   needs at most half the CG iterations of the fixed tolerance.

#include <signorini/solvers/linear_solver.h>

#include "run_output.h"

#include <cmath>
#include <fstream>
#include <iostream>
#include <string>

using RunOutput::verdict;

namespace
{
  bool
  close(const double a, const double b)
  {
    return std::abs(a - b) <= 1e-14 * std::abs(b);
  }

  const std::string mpirun = "mpirun --allow-run-as-root --oversubscribe -np 2 ";
} // namespace

int
main()
{
  std::ofstream out("output");
  using Signorini::LinearSolver;

  {
    LinearSolver::Parameters p;
    p.type               = LinearSolver::Parameters::Type::cg_amg;
    p.relative_tolerance = 1e-8;
    p.forcing            = LinearSolver::Parameters::Forcing::eisenstat_walker;
    p.max_forcing        = 0.5;
    const LinearSolver s(p);
    const double       tol = 1e-10;
    // First iteration, far from the tolerance: the maximum.
    const bool first = close(s.forcing_term(1., 0., 0., tol), 0.5);
    // 0.9 (0.1)^2 = 0.009; the last forcing 0.01 keeps no floor
    // (0.9 * 1e-4 < 0.1).
    const bool quadratic = close(s.forcing_term(0.1, 1., 0.01, tol), 0.009);
    // After a forcing of 0.4, 0.9 * 0.16 = 0.144 > 0.1: no sudden drop.
    const bool safeguard = close(s.forcing_term(0.1, 1., 0.4, tol), 0.144);
    // Capped at the maximum when |g| grows.
    const bool capped = close(s.forcing_term(2., 1., 0.01, tol), 0.5);
    // Near convergence: no tighter than 0.5 tol / |g|.
    const bool bound = close(s.forcing_term(1e-9, 1e-3, 0.01, tol), 0.05);
    // Never below 'Relative tolerance'.
    const bool floor = close(s.forcing_term(1e-6, 1., 0.01, 1e-20), 1e-8);
    out << "forcing term: first " << verdict(first) << ", quadratic "
        << verdict(quadratic) << ", safeguard " << verdict(safeguard)
        << ", capped " << verdict(capped) << ", bound " << verdict(bound)
        << ", floor " << verdict(floor) << "\n";

    LinearSolver::Parameters fixed = p;
    fixed.forcing                  = LinearSolver::Parameters::Forcing::fixed;
    LinearSolver::Parameters direct = p;
    direct.type                     = LinearSolver::Parameters::Type::direct;
    out << "fixed forcing and direct solver use the relative tolerance: "
        << verdict(close(LinearSolver(fixed).forcing_term(0.1, 1., 0.01, tol), 1e-8) &&
                   close(LinearSolver(direct).forcing_term(0.1, 1., 0.01, tol), 1e-8))
        << "\n";
  }

  struct Scene
  {
    std::string              name, file, edits;
    std::vector<std::string> quantities;
    bool                     two_ranks;
  };
  const std::string cg = "subsection Solver\n  subsection Linear solver\n"
                         "    set Type = cg-amg\n    set Fall back to direct = false\n";
  const std::vector<Scene> scenes = {
    {"ssnv187_3d",
     "ssnv187_3d_neo_hookean.prm",
     "subsection Mesh\n  set Global refinements = 2\nend\n" + cg,
     {"top_uy", "reaction_y_boundary_2"},
     true},
    {"hertz",
     "default.prm",
     "subsection Mesh\n  set Global refinements = 2\nend\n" + cg +
       "  end\n  set Method = newton-penalty\n  subsection Linear solver\n",
     {"contact_force_y", "hertz_a", "hertz_p0"},
     false}};
  for (const auto &scene : scenes)
    {
      const std::string fixed = scene.name + "_fixed", ew = scene.name + "_ew";
      const int         s_fixed = RunOutput::run_scene(
        fixed, scene.file, scene.edits + "    set Forcing term = fixed\n  end\nend\n");
      const int s_ew = RunOutput::run_scene(
        ew, scene.file, scene.edits + "    set Forcing term = Eisenstat-Walker\n  end\nend\n");
      const double worst =
        RunOutput::largest_relative_difference(fixed, ew, scene.quantities);
      const double cg_fixed = RunOutput::summary_sum(fixed, "linear iterations");
      const double cg_ew    = RunOutput::summary_sum(ew, "linear iterations");
      std::cerr << scene.name << ": exit " << s_fixed << ", " << s_ew
                << "; largest relative difference " << worst << "; CG iterations "
                << cg_fixed << " fixed, " << cg_ew << " Eisenstat-Walker\n";
      out << scene.name << ": both converge, same answers to 1e-8: "
          << verdict(s_fixed == 0 && s_ew == 0 && worst < 1e-8)
          << "; at most half the CG iterations: "
          << verdict(cg_ew > 0 && cg_ew <= 0.5 * cg_fixed) << "\n";
      if (scene.two_ranks)
        {
          const std::string ew2    = scene.name + "_ew_2_ranks";
          const int         status = RunOutput::run_scene(
            ew2,
            scene.file,
            scene.edits + "    set Forcing term = Eisenstat-Walker\n  end\nend\n",
            mpirun);
          const double d =
            RunOutput::largest_relative_difference(ew, ew2, scene.quantities);
          std::cerr << scene.name << " on 2 ranks: exit " << status
                    << "; largest relative difference " << d << "\n";
          out << scene.name << ", 2 ranks: converges, same answers to 1e-8: "
              << verdict(status == 0 && d < 1e-8) << "\n";
        }
    }
}
