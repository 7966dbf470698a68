// CG + AMG with 'Keep preconditioner' (LinearSolver::solve_kept_amg): the
// AMG hierarchy of the matrix scaled to a unit diagonal is kept across
// solves, on a 1D Laplacian plus a diagonal shift (4000 unknowns, one
// rank and two), CG to 1e-12:
// - new values on the same pattern, a mild change (the shift up 10%): the
//   hierarchy is kept and CG takes no more than 1.5 times (+5) the
//   iterations of a hierarchy built for that matrix;
// - the "contact rows" (every 50th) 1000 times stiffer: this nearly
//   singular 1D matrix then changes its lowest modes, which a kept
//   hierarchy cannot follow (in the interior point method's 3D matrices,
//   where a contact node is one of many in its aggregates, it does,
//   doc/performance.md): CG with the kept hierarchy stops at 3x (+20) the
//   iterations after its build and the solve starts again with a new one,
//   which the next solve keeps;
// - the stiff rows back to the others: that solve keeps the hierarchy for
//   itself and takes more than 1.5x (+5) but not 3x (+20), and the next
//   one builds anew and is back within;
// - every solution equals the direct solver's to 1e-9;
// - the matrix handed to the solver is the same after the solve to the
//   last bits but round-off (the scaling is undone: 1e-15 relative);
// - a new sparsity pattern builds a new hierarchy;
// - without the entry (Keep preconditioner = false) every new matrix
//   builds its own, and a solve with the same matrix values as the one
//   before (the interior point method's predictor and corrector) reuses
//   it: 4 builds in the 6 solves above, 2 of which repeat their values.
// The same entry with PETSc's GAMG and hypre's BoomerAMG ('AMG package'):
// the mild change keeps their hierarchy too, CG within 1.5x (+5) of a new
// one's, the solutions equal the direct solver's to 1e-9, the matrix is
// restored, and a new pattern builds again; without the entry a second
// solve with the same values reuses the hierarchy (2 builds in 3 solves).

#include <signorini/solvers/linear_solver.h>

#include "shifted_laplacian.h"

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <string>

using namespace Signorini;

namespace
{
  constexpr unsigned int n = 4000;

  /// New values in the Laplacian @p A (with @p shift): every 50th row's
  /// diagonal times @p stiff, the matrix object and pattern kept (as the
  /// assembly of a new iteration does).
  void
  set_stiff_rows(MatrixType &A, const IndexSet &owned, const double shift,
                 const double stiff)
  {
    for (const auto i : owned)
      A.set(i, i, (2. + shift) * (i % 50 == 0 ? stiff : 1.));
    A.compress(VectorOperation::insert);
  }

  double
  difference(const VectorType &a, const VectorType &b)
  {
    VectorType d(a);
    d -= b;
    return d.l2_norm() / b.l2_norm();
  }

  /// The largest relative change of an entry from @p before to @p after.
  double
  changed(const MatrixType &before, const MatrixType &after)
  {
    double worst = 0.;
    for (auto e = before.begin(); e != before.end(); ++e)
      {
        const double a = after.el(e->row(), e->column());
        worst = std::max(worst, std::abs(a - e->value()) / std::abs(e->value()));
      }
    return Utilities::MPI::max(worst, MPI_COMM_WORLD);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool    root = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  std::ofstream out(root ? "output" : "/dev/null");
  const IndexSet owned = Utilities::create_evenly_distributed_partitioning(
    Utilities::MPI::this_mpi_process(MPI_COMM_WORLD),
    Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD),
    n);

  LinearSolver::Parameters parameters;
  parameters.type               = LinearSolver::Parameters::Type::cg_amg;
  parameters.relative_tolerance = 1e-12;
  parameters.fallback_to_direct = false;
  LinearSolver::Parameters fresh_parameters = parameters;
  fresh_parameters.keep_preconditioner      = false;
  LinearSolver::Parameters direct_parameters;
  direct_parameters.type = LinearSolver::Parameters::Type::direct;

  LinearSolver kept(parameters), fresh(fresh_parameters);
  VectorType   b(owned, MPI_COMM_WORLD);
  for (const auto i : owned)
    b[i] = std::sin(0.01 * i) + 1.;
  b.compress(VectorOperation::insert);
  VectorType x(b), y(b), z(b);

  // Whether every solve succeeded, the largest difference from the direct
  // solver's solution and the largest change of the matrix by a solve.
  struct Record
  {
    bool   ok       = true;
    double worst    = 0.;
    double restored = 0.;
  };
  MatrixType A, copy;
  shifted_laplacian(A, owned, 1, 1e-3);
  shifted_laplacian(copy, owned, 1, 1e-3);
  std::string message;
  // One solve with each solver on A's values now (the shift, the stiff
  // rows' factor); the kept solver's CG iterations and those of a
  // hierarchy built for this matrix.
  const auto solve_with = [&](LinearSolver &with_kept, LinearSolver &with_fresh,
                              Record &r, const double shift, const double stiff) {
    set_stiff_rows(A, owned, shift, stiff);
    set_stiff_rows(copy, owned, shift, stiff);
    LinearSolver::Info info_kept, info_fresh, info_direct;
    r.ok       = r.ok && with_kept.solve(A, x, b, info_kept, message);
    r.restored = std::max(r.restored, changed(copy, A));
    r.ok       = r.ok && with_fresh.solve(A, y, b, info_fresh, message);
    LinearSolver direct(direct_parameters);
    r.ok    = r.ok && direct.solve(A, z, b, info_direct, message);
    r.worst = std::max(r.worst, difference(x, z));
    return std::make_pair(info_kept.iterations, info_fresh.iterations);
  };
  Record     ml;
  const auto solve = [&](const double shift, const double stiff) {
    const auto its = solve_with(kept, fresh, ml, shift, stiff);
    if (root)
      std::cerr << "shift " << shift << ", stiff rows x " << stiff
                << ": CG iterations kept " << its.first << ", new hierarchy "
                << its.second << ", builds " << kept.n_preconditioner_builds() << " (without the entry "
                << fresh.n_preconditioner_builds() << ")\n";
    return its;
  };
  const auto within = [](const std::pair<unsigned int, unsigned int> &its) {
    return its.first <= 1.5 * its.second + 5;
  };

  const auto first = solve(1e-3, 1.);
  const auto mild  = solve(1.1e-3, 1.); // new values, a mild change
  const unsigned int after_mild = kept.n_preconditioner_builds();
  const auto stiff = solve(1.1e-3, 1e3); // the stiff rows 1000 times stiffer
  const unsigned int after_stiff = kept.n_preconditioner_builds();
  const auto stiff_again = solve(1.1e-3, 1e3);
  const unsigned int after_stiff_again = kept.n_preconditioner_builds();
  const auto back = solve(1.1e-3, 1.); // the stiff rows back
  const unsigned int after_back = kept.n_preconditioner_builds();
  const auto back_again = solve(1.1e-3, 1.);
  const unsigned int after_back_again = kept.n_preconditioner_builds();
  shifted_laplacian(A, owned, 2, 1e-3); // a wider stencil: a new pattern
  LinearSolver::Info info;
  ml.ok = ml.ok && kept.solve(A, x, b, info, message);

  out << "every solve succeeded: " << (ml.ok ? "yes" : "NO") << "\n"
      << "a mild change keeps the hierarchy, CG within 1.5x (+5) of a new "
         "one's: "
      << (after_mild == 1 && within(mild) ? "yes" : "NO") << "\n"
      << "a solve beyond 3x (+20) with it starts again with a new one: "
      << (after_stiff == 2 && stiff.first > 3 * first.first + 20 ? "yes" : "NO")
      << "\n"
      << "... which the next solve keeps, within 1.5x (+5): "
      << (after_stiff_again == 2 && within(stiff_again) ? "yes" : "NO") << "\n"
      << "a solve beyond 1.5x (+5) but within 3x (+20) keeps it for itself: "
      << (after_back == 2 && !within(back) ? "yes" : "NO") << "\n"
      << "... and makes the next solve build a new one, within 1.5x (+5): "
      << (after_back_again == 3 && within(back_again) ? "yes" : "NO") << "\n"
      << "solutions equal the direct solver's to 1e-9: "
      << (ml.worst < 1e-9 ? "yes" : "NO") << "\n"
      << "the matrix is the same after the solve to 1e-15: "
      << (ml.restored < 1e-15 ? "yes" : "NO") << "\n"
      << "a new pattern builds again: "
      << (kept.n_preconditioner_builds() == 4 ? "yes" : "NO") << "\n"
      << "without the entry: a new hierarchy for new values, the same for the same: "
      << (fresh.n_preconditioner_builds() == 4 ? "yes" : "NO") << "\n";
  if (root)
    std::cerr << "largest difference " << ml.worst << "; matrix change "
              << ml.restored << " " << message << "\n";

  for (const auto package : {LinearSolver::Parameters::AmgPackage::gamg,
                             LinearSolver::Parameters::AmgPackage::boomeramg})
    {
      LinearSolver::Parameters p = parameters, q = fresh_parameters;
      p.amg_package = q.amg_package = package;
      LinearSolver petsc_kept(p), petsc_fresh(q);
      Record                                r;
      std::pair<unsigned int, unsigned int> its[2];
      shifted_laplacian(A, owned, 1, 1e-3);
      its[0] = solve_with(petsc_kept, petsc_fresh, r, 1e-3, 1.);
      its[1] = solve_with(petsc_kept, petsc_fresh, r, 1.1e-3, 1.); // a mild change
      const unsigned int after_mild = petsc_kept.n_preconditioner_builds();
      solve_with(petsc_kept, petsc_fresh, r, 1.1e-3, 1.); // the same values again
      const unsigned int fresh_builds = petsc_fresh.n_preconditioner_builds();
      shifted_laplacian(A, owned, 2, 1e-3);
      LinearSolver::Info info_wide;
      r.ok = r.ok && petsc_kept.solve(A, x, b, info_wide, message);
      const std::string name =
        package == LinearSolver::Parameters::AmgPackage::gamg ? "GAMG" : "BoomerAMG";
      out << name << ": every solve succeeded: " << (r.ok ? "yes" : "NO") << "\n"
          << name << ": a mild change keeps the hierarchy, CG within 1.5x (+5): "
          << (after_mild == 1 && within(its[1]) ? "yes" : "NO") << "\n"
          << name << ": solutions equal the direct solver's to 1e-9: "
          << (r.worst < 1e-9 ? "yes" : "NO") << "\n"
          << name << ": the matrix is the same after the solve to 1e-15: "
          << (r.restored < 1e-15 ? "yes" : "NO") << "\n"
          << name << ": a new pattern builds again: "
          << (petsc_kept.n_preconditioner_builds() == 2 ? "yes" : "NO") << "\n"
          << name << ": without the entry, the same values reuse the hierarchy: "
          << (fresh_builds == 2 ? "yes" : "NO") << "\n";
      if (root)
        std::cerr << name << ": CG iterations kept / new " << its[0].first << " / "
                  << its[0].second << ", " << its[1].first << " / " << its[1].second
                  << "; largest difference " << r.worst << "\n";
    }
}
