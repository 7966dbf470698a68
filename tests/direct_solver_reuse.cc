// The direct solver keeps its symbolic analysis while the sparsity pattern
// of the matrix is unchanged, and redoes it when the pattern changes: on a
// 1D Laplacian plus a diagonal (80 unknowns), for Amesos_Mumps and
// Amesos_Klu,
// - new values on the same pattern (a shifted diagonal, as Newton's
//   regularisation does) reuse the analysis: one analysis for three solves;
// - a matrix with another pattern (a longer stencil) is analysed again;
// - every solution equals the one a freshly made solver computes, to 1e-12
//   relative;
// - clear() forgets the analysis.

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
  constexpr unsigned int n = 80;

  void
  make_matrix(MatrixType &A, const unsigned int width, const double shift)
  {
    shifted_laplacian(A, complete_index_set(n), width, shift);
  }

  double
  difference(const VectorType &a, const VectorType &b)
  {
    VectorType d(a);
    d -= b;
    return d.l2_norm() / b.l2_norm();
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream                    out("output");

  for (const std::string name : {"Amesos_Mumps", "Amesos_Klu"})
    {
      LinearSolver::Parameters parameters;
      parameters.type          = LinearSolver::Parameters::Type::direct;
      parameters.direct_solver = name;
      LinearSolver solver(parameters);

      VectorType b(complete_index_set(n), MPI_COMM_WORLD);
      for (unsigned int i = 0; i < n; ++i)
        b[i] = std::sin(0.1 * i) + 1.;
      b.compress(VectorOperation::insert);
      VectorType x(b), fresh(b);

      double worst = 0.;
      bool   ok    = true;
      // The answer of a solver made for this one solve.
      const auto compare = [&](const MatrixType &A) {
        LinearSolver       once(parameters);
        LinearSolver::Info info;
        std::string        message;
        ok    = ok && once.solve(A, fresh, b, info, message);
        worst = std::max(worst, difference(x, fresh));
      };

      MatrixType         A;
      LinearSolver::Info info;
      std::string        message;
      make_matrix(A, 1, 0.1);
      ok = ok && solver.solve(A, x, b, info, message);
      compare(A);
      make_matrix(A, 1, 0.5); // the same pattern, new values
      ok = ok && solver.solve(A, x, b, info, message);
      compare(A);
      for (unsigned int i = 0; i < n; ++i) // Newton's shift: set the diagonal
        A.set(i, i, 5.);
      A.compress(VectorOperation::insert);
      ok = ok && solver.solve(A, x, b, info, message);
      compare(A);
      const unsigned int same_pattern = solver.n_symbolic_factorizations();

      MatrixType B; // another pattern
      make_matrix(B, 2, 0.1);
      ok = ok && solver.solve(B, x, b, info, message);
      compare(B);
      make_matrix(A, 3, 0.1); // the first matrix with a new pattern
      ok = ok && solver.solve(A, x, b, info, message);
      compare(A);
      const unsigned int new_patterns = solver.n_symbolic_factorizations();

      solver.clear();
      ok = ok && solver.solve(A, x, b, info, message);
      compare(A);

      out << name << ": every solve succeeded: " << (ok ? "yes" : "NO") << "\n"
          << name << ": one symbolic analysis for three matrices of one pattern: "
          << (same_pattern == 1 ? "yes" : "NO") << "\n"
          << name << ": analysed again for each new pattern: "
          << (new_patterns == 3 ? "yes" : "NO") << "\n"
          << name << ": and after clear(): "
          << (solver.n_symbolic_factorizations() == 4 ? "yes" : "NO") << "\n"
          << name << ": solutions equal a fresh solver's to 1e-12: "
          << (worst < 1e-12 ? "yes" : "NO") << "\n";
      std::cerr << name << ": analyses " << same_pattern << ", " << new_patterns
                << "; largest difference " << worst << " " << message << "\n";
    }
}
