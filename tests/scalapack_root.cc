// MUMPS factorises the root front of the elimination tree with ScaLAPACK
// when it is large and the matrix is distributed over several ranks
// (Amesos_Mumps keeps MUMPS' default, ICNTL(13) = 0). The sequential MUMPS
// that Debian's Ipopt links defines dummy BLACS routines; loaded before
// ScaLAPACK, they aborted such a run with "BLACS_GRIDINIT should not be
// called" (Amesos_Mumps on 2 ranks, 3D block of 1e5 DoFs). CMakeLists.txt
// names ScaLAPACK before Ipopt. Here: a banded matrix (n = 2000 unknowns,
// half-width 500, so that the root front has about 500 rows, which MUMPS
// hands to ScaLAPACK on 2 ranks) solved by Amesos_Mumps and by PETSc_Mumps,
// both equal to Amesos_Klu's solution to 1e-10.

#include <signorini/solvers/linear_solver.h>

#include "shifted_laplacian.h"

#include <algorithm>
#include <fstream>
#include <iostream>
#include <string>

using namespace Signorini;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const unsigned int n     = 2000;
  const unsigned int ranks = Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
  const unsigned int rank  = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
  IndexSet           owned(n);
  owned.add_range(rank * n / ranks, (rank + 1) * n / ranks);

  MatrixType A;
  shifted_laplacian(A, owned, 500, 0.1);
  VectorType b(owned, MPI_COMM_WORLD);
  for (const auto i : owned)
    b[i] = 1. + 0.001 * i;
  b.compress(VectorOperation::insert);

  const auto solve = [&](const std::string &name, VectorType &x) {
    LinearSolver::Parameters p;
    p.type          = LinearSolver::Parameters::Type::direct;
    p.direct_solver = name;
    LinearSolver       solver(p);
    LinearSolver::Info info;
    std::string        message;
    x = b;
    const bool solved = solver.solve(A, x, b, info, message);
    if (!solved)
      std::cerr << name << ": " << message << "\n";
    return solved;
  };

  VectorType reference(b), x(b);
  AssertThrow(solve("Amesos_Klu", reference), ExcMessage("KLU failed"));
  std::ofstream out;
  if (rank == 0)
    out.open("output");
  for (const std::string name : {"Amesos_Mumps", "PETSc_Mumps"})
    {
      const bool solved = solve(name, x);
      x -= reference;
      const double difference = x.l2_norm() / reference.l2_norm();
      if (rank == 0)
        {
          out << name << ": solved, equal to Amesos_Klu's to 1e-10: "
              << (solved && difference < 1e-10 ? "yes" : "NO") << "\n";
          std::cerr << name << ": relative difference " << difference << "\n";
        }
    }
}
