// Every linear solver and ordering gives the same answer (issue "Fast
// linear algebra and assembly"): the Hertz scene (prm/default.prm with
// one global refinement less, 3770 DoFs, penalty continuation) and 3D
// SSNV187 (prm/ssnv187_3d_c20.prm refined once, 2187 DoFs) solved
// - on one rank with Amesos_Mumps and each deterministic ordering (pord,
//   the reference; amd, amf, qamd), with Amesos_Klu, PETSc_Mumps (LDL^T),
//   PETSc_Cholmod, and with CG + AMG (rigid motions as near null space,
//   Chebyshev and block Gauss-Seidel smoothers, the latter also with a
//   coarse level of at most 250 unknowns, CG to 1e-12, no fallback
//   to the direct solver), and with CG preconditioned by hypre's
//   BoomerAMG (a new hierarchy for every matrix: the kept one is in
//   tests/kept_amg.cc);
// - on two ranks with the direct solver (auto: PETSc_Mumps, distributed),
//   Amesos_Mumps (distributed), Amesos_Klu (gathered to one rank),
//   CG + AMG (ML) and CG preconditioned by PETSc's GAMG (both with the
//   kept hierarchy).
// Each run converges, takes as many load steps as the reference, and its
// quantities (contact force, Hertz a and p0, the largest penetration; the
// top displacement and the reaction) agree with the reference's to 1e-8
// relative. The direct solver keeps its symbolic analysis across Newton
// iterations (tests/direct_solver_reuse.cc), so this also checks that the
// kept analysis gives the answers a new one gives.

#include "run_output.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

using RunOutput::verdict;

namespace
{
  struct Variant
  {
    std::string name;
    std::string linear; // entries of Solver > Linear solver
    bool        two_ranks;
  };

  const std::string mpirun = "mpirun --allow-run-as-root --oversubscribe -np 2 ";

  std::string
  edits(const std::string &mesh, const std::string &linear)
  {
    return mesh + "subsection Solver\n  subsection Linear solver\n" + linear +
           "  end\nend\n";
  }
} // namespace

int
main()
{
  std::ofstream out("output");

  const std::string cg = "    set Type = cg-amg\n    set Relative tolerance = 1e-12\n"
                         "    set Fall back to direct = false\n";
  const std::vector<Variant> variants = {
    {"mumps_pord", "    set Direct solver = Amesos_Mumps\n    set MUMPS ordering = pord\n", false},
    {"mumps_amd", "    set Direct solver = Amesos_Mumps\n    set MUMPS ordering = amd\n", false},
    {"mumps_amf", "    set Direct solver = Amesos_Mumps\n    set MUMPS ordering = amf\n", false},
    {"mumps_qamd", "    set Direct solver = Amesos_Mumps\n    set MUMPS ordering = qamd\n", false},
    {"klu", "    set Direct solver = Amesos_Klu\n", false},
    {"petsc_mumps", "    set Direct solver = PETSc_Mumps\n", false},
    {"petsc_cholmod", "    set Direct solver = PETSc_Cholmod\n", false},
    {"cg_amg", cg, false},
    {"cg_amg_gauss_seidel", cg + "    set AMG smoother = symmetric block Gauss-Seidel\n", false},
    // A small coarse level: ML's block Gauss-Seidel on a 2D coarse level
    // with an odd number of aggregates (3 modes, 2 DoFs per node) ended the
    // process before the coarse levels were smoothed point by point.
    {"cg_amg_gauss_seidel_coarse_250",
     cg + "    set AMG smoother = symmetric block Gauss-Seidel\n    set AMG coarse size = 250\n",
     false},
    {"direct_2_ranks", "    set Direct solver = auto\n", true},
    {"amesos_mumps_2_ranks", "    set Direct solver = Amesos_Mumps\n", true},
    {"klu_2_ranks", "    set Direct solver = Amesos_Klu\n", true},
    {"cg_amg_2_ranks", cg, true},
    {"cg_gamg_2_ranks", cg + "    set AMG package = GAMG\n", true},
    {"cg_boomeramg", cg + "    set AMG package = BoomerAMG\n    set Keep preconditioner = false\n", false}};

  struct Scene
  {
    std::string              name, file, mesh;
    std::vector<std::string> quantities;
  };
  const std::vector<Scene> scenes = {
    {"hertz",
     "default.prm",
     "subsection Mesh\n  set Global refinements = 2\nend\n"
     "subsection Solver\n  set Method = newton-penalty\nend\n",
     {"contact_force_y", "hertz_a", "hertz_p0", "max_penetration_over_h"}},
    {"ssnv187_3d",
     "ssnv187_3d_c20.prm",
     "subsection Mesh\n  set Global refinements = 1\nend\n",
     {"top_uy", "reaction_y_boundary_2"}}};

  for (const auto &scene : scenes)
    {
      std::string reference;
      for (const auto &v : variants)
        {
          const std::string name = scene.name + "_" + v.name;
          const int         status =
            RunOutput::run_scene(name, scene.file, edits(scene.mesh, v.linear),
                                 v.two_ranks ? mpirun : "");
          if (reference.empty())
            reference = name;
          const auto numbers = RunOutput::summary_numbers(name + "/summary.json");
          const auto ref = RunOutput::summary_numbers(reference + "/summary.json");
          const bool same_steps =
            RunOutput::first_number(numbers, "load steps") ==
            RunOutput::first_number(ref, "load steps");
          const double worst =
            RunOutput::largest_relative_difference(reference, name, scene.quantities);
          out << scene.name << ", " << v.name
              << ": converges with the reference's load steps, quantities to "
                 "1e-8: "
              << verdict(status == 0 && same_steps && worst < 1e-8) << "\n";
          std::cerr << name << ": exit " << status << ", largest relative "
                    << "difference " << worst << "\n";
        }
    }
}
