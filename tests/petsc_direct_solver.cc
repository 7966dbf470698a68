// The PETSc direct solvers (PETSc_Mumps: MUMPS' LDL^T distributed over the
// ranks; PETSc_Cholmod: CHOLMOD's Cholesky, one rank) on a 1D Laplacian
// with a diagonal shift, n = 81 unknowns split into contiguous row ranges
// over the ranks:
// - the solution equals Amesos_Klu's (KLU gathers the matrix to one rank)
//   to 1e-12 relative, for a positive definite and an indefinite matrix;
// - new values on one pattern reuse the symbolic analysis; a second
//   right-hand side for the same values reuses the numeric factorisation;
//   a new pattern is analysed again;
// - MUMPS counts the negative eigenvalues of the indefinite matrix exactly
//   (the eigenvalues are known in closed form);
// - a singular matrix is a failed solve with a reason, and the solver
//   works again afterwards;
// - each MUMPS ordering asked for (amd, amf, pord, qamd) is the one MUMPS
//   reports it used (on one rank PETSc 3.18 once replaced it by MUMPS'
//   automatic choice), scotch (not in Debian's parallel MUMPS) reports the
//   one MUMPS took instead, with KLU's answers;
// - Amesos_Mumps gives KLU's answers too (also on 2 ranks);
// - with two unknowns per node of one pattern MUMPS orders the graph of the
//   nodes (ICNTL(15) = -2), with KLU's answers; not for the Laplacian;
// - CHOLMOD refuses the indefinite matrix as not positive definite (one
//   rank only: the 2-rank output has no CHOLMOD lines).

#include <signorini/solvers/linear_solver.h>

#include "shifted_laplacian.h"

#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

using namespace Signorini;

namespace
{
  constexpr unsigned int n = 81;

  IndexSet
  owned_rows()
  {
    const unsigned int ranks = Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
    const unsigned int rank  = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
    IndexSet           owned(n);
    owned.add_range(rank * n / ranks, (rank + 1) * n / ranks);
    return owned;
  }

  /// Negative eigenvalues of the width-1 matrix with @p shift.
  int
  exact_negative(const double shift)
  {
    int count = 0;
    for (unsigned int k = 1; k <= n; ++k)
      count += (2. + shift - 2. * std::cos(k * M_PI / (n + 1.)) < 0.);
    return count;
  }

  double
  difference(const VectorType &a, const VectorType &b)
  {
    VectorType d(a);
    d -= b;
    return d.l2_norm() / b.l2_norm();
  }

  /// One direct solver of LinearSolver by name, its solves of shifted
  /// Laplacians, and their largest difference from KLU's answers.
  struct Trial
  {
    explicit Trial(const std::string &name, const VectorType &b, const int ordering = 4)
      : solver(parameters(name, ordering))
      , b(b)
      , x(b)
    {}

    static LinearSolver::Parameters
    parameters(const std::string &name, const int ordering = 4)
    {
      LinearSolver::Parameters p;
      p.type           = LinearSolver::Parameters::Type::direct;
      p.direct_solver  = name;
      p.mumps_ordering = ordering;
      return p;
    }

    /// Solve with the matrix (@p width, @p shift); compare with KLU.
    bool
    solve(const unsigned int width, const double shift)
    {
      shifted_laplacian(A, owned_rows(), width, shift);
      return solve_current();
    }

    bool
    solve_current()
    {
      LinearSolver::Info info;
      const bool         solved = solver.solve(A, x, b, info, message);
      ok                        = ok && solved;
      if (solved)
        {
          LinearSolver klu(parameters("Amesos_Klu"));
          VectorType   reference(b);
          std::string  klu_message;
          AssertThrow(klu.solve(A, reference, b, info, klu_message),
                      ExcMessage(klu_message));
          worst = std::max(worst, difference(x, reference));
        }
      return solved;
    }

    LinearSolver      solver;
    const VectorType &b;
    VectorType        x;
    MatrixType        A;
    std::string       message;
    double            worst = 0.;
    bool              ok    = true;
  };
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool root = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  const bool one_rank = Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) == 1;
  std::ofstream out;
  if (root)
    out.open("output");
  const auto say = [&](const std::string &what, const bool ok) {
    if (root)
      out << what << ": " << (ok ? "yes" : "NO") << "\n";
  };

  VectorType b(owned_rows(), MPI_COMM_WORLD);
  for (const auto i : b.locally_owned_elements())
    b[i] = std::sin(0.1 * i) + 1.;
  b.compress(VectorOperation::insert);

  {
    Trial mumps("PETSc_Mumps", b);
    mumps.solve(1, 0.1); // positive definite
    const bool definite_inertia = mumps.solver.negative_pivots() == 0;
    mumps.solve(1, -0.6); // indefinite, same pattern
    const int negative = mumps.solver.negative_pivots();
    mumps.solve_current(); // the same values again
    const unsigned int symbolic = mumps.solver.n_symbolic_factorizations();
    const unsigned int numeric  = mumps.solver.n_numeric_factorizations();
    mumps.solve(2, 0.1); // a new pattern

    say("PETSc_Mumps: every solve succeeded", mumps.ok);
    say("PETSc_Mumps: solutions equal Amesos_Klu's to 1e-12", mumps.worst < 1e-12);
    say("PETSc_Mumps: one analysis, two factorisations for three solves of "
        "one pattern",
        symbolic == 1 && numeric == 2);
    say("PETSc_Mumps: analysed again for a new pattern",
        mumps.solver.n_symbolic_factorizations() == 2);
    say("PETSc_Mumps: no negative pivot on the definite matrix",
        definite_inertia);
    say("PETSc_Mumps: negative pivots of the indefinite matrix equal its "
        "negative eigenvalues (" +
          std::to_string(exact_negative(-0.6)) + ")",
        negative == exact_negative(-0.6));
    if (root)
      std::cerr << "PETSc_Mumps: " << (mumps.ok ? "" : mumps.message + "; ")
                << "largest difference " << mumps.worst << ", negative pivots "
                << negative << " (exact " << exact_negative(-0.6) << ")\n";

    // Singular: unknown 40 decoupled from the others with a zero diagonal
    // (its row and column zero), an exact zero pivot whatever the ordering.
    shifted_laplacian(mumps.A, owned_rows(), 1, 0.1);
    for (const auto i : owned_rows())
      if (i == 39 || i == 41)
        mumps.A.set(i, 40, 0.);
      else if (i == 40)
        for (const unsigned int j : {39, 40, 41})
          mumps.A.set(i, j, 0.);
    mumps.A.compress(VectorOperation::insert);
    const bool singular_failed = !mumps.solve_current();
    say("PETSc_Mumps: a singular matrix fails with a reason",
        singular_failed &&
          mumps.message.find("singular") != std::string::npos);
    if (root)
      std::cerr << "PETSc_Mumps singular: " << mumps.message << "\n";
    mumps.ok = true;
    say("PETSc_Mumps: and solves again afterwards",
        mumps.solve(1, 0.1) && mumps.worst < 1e-12);
  }

  {
    // MUMPS ICNTL(7) codes of the orderings (LinearSolver::Parameters).
    bool        used = true, solved = true;
    double      worst = 0.;
    std::string report;
    for (const auto &[name, code] : std::vector<std::pair<std::string, int>>{
           {"amd", 0}, {"amf", 2}, {"scotch", 3}, {"pord", 4}, {"qamd", 6}})
      {
        Trial trial("PETSc_Mumps", b, code);
        trial.solve(1, -0.6);
        // Debian's parallel MUMPS (the one PETSc links) is built without
        // SCOTCH: MUMPS takes one of its own instead and says which.
        used = used && (name == "scotch" ? !trial.solver.ordering_used().empty() :
                                           trial.solver.ordering_used() == name);
        solved = solved && trial.ok;
        worst  = std::max(worst, trial.worst);
        report += " " + name + ": " + trial.solver.ordering_used();
      }
    say("PETSc_Mumps: each ordering asked for is the one MUMPS used (amd, amf, "
        "pord, qamd; scotch names its stand-in), with Amesos_Klu's solutions "
        "to 1e-12",
        used && solved && worst < 1e-12);
    if (root)
      std::cerr << "PETSc_Mumps orderings used:" << report << "\n";
  }

  {
    // Amesos_Mumps on the same matrices: on 2 ranks it failed as
    // "singular" while the sequential MUMPS that Ipopt links stood in for
    // the parallel one (CMakeLists.txt).
    Trial amesos("Amesos_Mumps", b);
    for (const double shift : {0.1, -0.6})
      amesos.solve(1, shift);
    say("Amesos_Mumps: definite and indefinite solves equal Amesos_Klu's to "
        "1e-12",
        amesos.ok && amesos.worst < 1e-12);
    if (root)
      std::cerr << "Amesos_Mumps: " << amesos.message << " largest difference "
                << amesos.worst << "\n";
  }

  {
    // Two unknowns per node with one pattern (a 2D vector field): MUMPS
    // orders the graph of the 80 nodes (ICNTL(15) = -2), with KLU's answers.
    // The 1D Laplacian above has no such blocks (81 unknowns).
    constexpr unsigned int nodes = 80, m = 2 * nodes;
    const unsigned int     ranks = Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
    const unsigned int     rank  = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
    IndexSet               owned(m);
    owned.add_range(2 * (rank * nodes / ranks), 2 * ((rank + 1) * nodes / ranks));
    DynamicSparsityPattern pattern(m, m, owned);
    for (const auto i : owned)
      for (unsigned int node = (i / 2 > 0 ? i / 2 - 1 : 0);
           node <= std::min(nodes - 1, i / 2 + 1);
           ++node)
        for (unsigned int c = 0; c < 2; ++c)
          pattern.add(i, 2 * node + c);
    MatrixType A;
    A.reinit(owned, owned, pattern, MPI_COMM_WORLD);
    for (const auto i : owned)
      for (unsigned int node = (i / 2 > 0 ? i / 2 - 1 : 0);
           node <= std::min(nodes - 1, i / 2 + 1);
           ++node)
        for (unsigned int c = 0; c < 2; ++c)
          A.set(i, 2 * node + c,
                (node == i / 2 ? 2.1 : -1.) * (c == i % 2 ? 2. : 0.5));
    A.compress(VectorOperation::insert);
    VectorType rhs(owned, MPI_COMM_WORLD), x(rhs), reference(rhs);
    for (const auto i : owned)
      rhs[i] = std::cos(0.3 * i);
    rhs.compress(VectorOperation::insert);
    LinearSolver       mumps(Trial::parameters("PETSc_Mumps")),
      klu(Trial::parameters("Amesos_Klu"));
    LinearSolver::Info info;
    std::string        message;
    const bool solved = mumps.solve(A, x, rhs, info, message) &&
                        klu.solve(A, reference, rhs, info, message);
    Trial laplacian("PETSc_Mumps", b);
    laplacian.solve(1, 0.1);
    const double blocked_difference = difference(x, reference);
    say("PETSc_Mumps: the graph of the nodes is ordered for two unknowns per "
        "node (and not for the 1D Laplacian), with Amesos_Klu's solution to "
        "1e-12",
        solved && mumps.ordering_block() == 2 &&
          laplacian.solver.ordering_block() == 1 &&
          blocked_difference < 1e-12);
    if (root)
      std::cerr << "PETSc_Mumps node blocks: " << mumps.ordering_block() << " and "
                << laplacian.solver.ordering_block() << ", difference "
                << blocked_difference << "\n";
  }

  if (one_rank)
    {
      Trial cholmod("PETSc_Cholmod", b);
      cholmod.solve(1, 0.1);
      cholmod.solve(1, 0.5);
      const unsigned int symbolic = cholmod.solver.n_symbolic_factorizations();
      const bool         definite = cholmod.ok;
      const bool         refused  = !cholmod.solve(1, -0.6);
      const std::string  reason   = cholmod.message;
      cholmod.ok                  = true;
      cholmod.solve(1, 0.1);
      say("PETSc_Cholmod: every definite solve succeeded", definite && cholmod.ok);
      say("PETSc_Cholmod: solutions equal Amesos_Klu's to 1e-12",
          cholmod.worst < 1e-12);
      say("PETSc_Cholmod: one analysis for two matrices of one pattern",
          symbolic == 1);
      say("PETSc_Cholmod: the indefinite matrix is refused as not positive "
          "definite",
          refused && reason.find("not positive definite") != std::string::npos);
      std::cerr << "PETSc_Cholmod: largest difference " << cholmod.worst << "; "
                << reason << "\n";
    }
}
