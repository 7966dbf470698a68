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
// - Amesos_Mumps gives KLU's answers too (also on 2 ranks);
// - CHOLMOD refuses the indefinite matrix as not positive definite (one
//   rank only: the 2-rank output has no CHOLMOD lines).

#include <signorini/solvers/linear_solver.h>

#include <deal.II/base/mpi.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <string>

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

  /// -u'' (stencil half-width @p width) plus @p shift on the diagonal.
  void
  make_matrix(MatrixType &A, const unsigned int width, const double shift)
  {
    const IndexSet         owned = owned_rows();
    DynamicSparsityPattern pattern(n, n, owned);
    for (const auto i : owned)
      for (unsigned int j = (i >= width ? i - width : 0);
           j <= std::min<unsigned int>(n - 1, i + width);
           ++j)
        pattern.add(i, j);
    A.reinit(owned, owned, pattern, MPI_COMM_WORLD);
    for (const auto i : owned)
      {
        A.set(i, i, 2. * width + shift);
        for (unsigned int k = 1; k <= width; ++k)
          {
            if (i >= k)
              A.set(i, i - k, -1.);
            if (i + k < n)
              A.set(i, i + k, -1.);
          }
      }
    A.compress(VectorOperation::insert);
  }

  /// Negative eigenvalues of the width-1 matrix: 2 + shift - 2 cos(k pi /
  /// (n + 1)), k = 1..n.
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

  LinearSolver::Parameters
  direct(const std::string &name)
  {
    LinearSolver::Parameters parameters;
    parameters.type          = LinearSolver::Parameters::Type::direct;
    parameters.direct_solver = name;
    return parameters;
  }
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

  // KLU's answer (the matrix gathered to one rank).
  const auto reference = [&](const MatrixType &A) {
    LinearSolver       klu(direct("Amesos_Klu"));
    VectorType         x(b);
    LinearSolver::Info info;
    std::string        message;
    AssertThrow(klu.solve(A, x, b, info, message), ExcMessage(message));
    return x;
  };

  {
    LinearSolver       solver(direct("PETSc_Mumps"));
    LinearSolver::Info info;
    std::string        message;
    VectorType         x(b);
    MatrixType         A;
    double             worst = 0.;
    bool               ok    = true;

    make_matrix(A, 1, 0.1); // positive definite
    ok    = ok && solver.solve(A, x, b, info, message);
    worst = std::max(worst, difference(x, reference(A)));
    const bool definite_inertia = solver.negative_pivots() == 0;
    make_matrix(A, 1, -0.6); // indefinite, same pattern
    ok    = ok && solver.solve(A, x, b, info, message);
    worst = std::max(worst, difference(x, reference(A)));
    const int negative = solver.negative_pivots();
    ok    = ok && solver.solve(A, x, b, info, message); // the same values
    const unsigned int symbolic = solver.n_symbolic_factorizations();
    const unsigned int numeric  = solver.n_numeric_factorizations();
    make_matrix(A, 2, 0.1); // a new pattern
    ok    = ok && solver.solve(A, x, b, info, message);
    worst = std::max(worst, difference(x, reference(A)));

    say("PETSc_Mumps: every solve succeeded", ok);
    say("PETSc_Mumps: solutions equal Amesos_Klu's to 1e-12", worst < 1e-12);
    say("PETSc_Mumps: one analysis, two factorisations for three solves of "
        "one pattern",
        symbolic == 1 && numeric == 2);
    say("PETSc_Mumps: analysed again for a new pattern",
        solver.n_symbolic_factorizations() == 2);
    say("PETSc_Mumps: no negative pivot on the definite matrix",
        definite_inertia);
    say("PETSc_Mumps: negative pivots of the indefinite matrix equal its "
        "negative eigenvalues (" +
          std::to_string(exact_negative(-0.6)) + ")",
        negative == exact_negative(-0.6));
    if (root)
      std::cerr << "PETSc_Mumps: " << (ok ? "" : message + "; ")
                << "largest difference " << worst
                << ", negative pivots " << negative << " (exact "
                << exact_negative(-0.6) << ")\n";

    // Singular: unknown 40 decoupled from the others with a zero diagonal
    // (its row and column zero), an exact zero pivot whatever the ordering.
    MatrixType S;
    make_matrix(S, 1, 0.1);
    for (const auto i : owned_rows())
      if (i == 39 || i == 41)
        S.set(i, 40, 0.);
      else if (i == 40)
        {
          S.set(i, 39, 0.);
          S.set(i, 40, 0.);
          S.set(i, 41, 0.);
        }
    S.compress(VectorOperation::insert);
    std::string singular_message;
    const bool  singular_failed = !solver.solve(S, x, b, info, singular_message);
    say("PETSc_Mumps: a singular matrix fails with a reason",
        singular_failed && singular_message.find("singular") != std::string::npos);
    if (root)
      std::cerr << "PETSc_Mumps singular: " << singular_message << "\n";
    make_matrix(A, 1, 0.1);
    const bool again = solver.solve(A, x, b, info, message);
    say("PETSc_Mumps: and solves again afterwards",
        again && difference(x, reference(A)) < 1e-12);
  }

  {
    // Amesos_Mumps on the same matrices: on 2 ranks it failed as
    // "singular" while the sequential MUMPS that Ipopt links stood in for
    // the parallel one (CMakeLists.txt).
    LinearSolver       solver(direct("Amesos_Mumps"));
    LinearSolver::Info info;
    std::string        message;
    VectorType         x(b);
    MatrixType         A;
    double             worst = 0.;
    bool               ok    = true;
    for (const double shift : {0.1, -0.6})
      {
        make_matrix(A, 1, shift);
        ok    = ok && solver.solve(A, x, b, info, message);
        worst = std::max(worst, difference(x, reference(A)));
      }
    say("Amesos_Mumps: definite and indefinite solves equal Amesos_Klu's to "
        "1e-12",
        ok && worst < 1e-12);
    if (root)
      std::cerr << "Amesos_Mumps: " << message << " largest difference "
                << worst << "\n";
  }

  if (one_rank)
    {
      LinearSolver       solver(direct("PETSc_Cholmod"));
      LinearSolver::Info info;
      std::string        message;
      VectorType         x(b);
      MatrixType         A;
      make_matrix(A, 1, 0.1);
      bool         ok    = solver.solve(A, x, b, info, message);
      double       worst = difference(x, reference(A));
      make_matrix(A, 1, 0.5);
      ok    = ok && solver.solve(A, x, b, info, message);
      worst = std::max(worst, difference(x, reference(A)));
      const unsigned int symbolic = solver.n_symbolic_factorizations();
      make_matrix(A, 1, -0.6);
      std::string indefinite;
      const bool  refused = !solver.solve(A, x, b, info, indefinite);
      make_matrix(A, 1, 0.1);
      ok = ok && solver.solve(A, x, b, info, message);
      out << "PETSc_Cholmod: every definite solve succeeded: "
          << (ok ? "yes" : "NO") << "\n"
          << "PETSc_Cholmod: solutions equal Amesos_Klu's to 1e-12: "
          << (worst < 1e-12 ? "yes" : "NO") << "\n"
          << "PETSc_Cholmod: one analysis for two matrices of one pattern: "
          << (symbolic == 1 ? "yes" : "NO") << "\n"
          << "PETSc_Cholmod: the indefinite matrix is refused as not positive "
             "definite: "
          << (refused &&
                  indefinite.find("not positive definite") != std::string::npos ?
                "yes" :
                "NO")
          << "\n";
      std::cerr << "PETSc_Cholmod: largest difference " << worst << "; "
                << indefinite << "\n";
    }
}
