// CellScatter (the cached positions of cells' local matrix entries in the
// Hessian's compressed rows) against AffineConstraints::
// distribute_local_to_global on a 2D Q1 mesh with hanging nodes and a
// Dirichlet side: the matrix and vector must be bitwise equal on the pass
// that finds the positions, on the passes that reuse them, after the
// sparsity pattern changes under the same matrix object (the positions
// must be found again, not reused: the rows of unconstrained DoFs gain
// the columns of constrained ones, which shifts the slots), and on a
// pattern with rows of more
// than 255 entries (cells touching them take the general path). Run on 1
// and 2 ranks (partition boundary cells take the general path); both
// print the same.

#include <signorini/problem/cell_scatter.h>

#include <deal.II/base/mpi.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <deal.II/numerics/vector_tools.h>

#include <Epetra_CrsMatrix.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <string>

using namespace dealii;
using namespace Signorini;

namespace
{
  /// Deterministic cell values, the same on any number of ranks.
  double
  entry(const Point<2> &centre, const unsigned int i, const unsigned int j)
  {
    return std::sin(13.1 * centre[0] + 7.3 * centre[1] + 0.37 * i +
                    0.11 * j) +
           (i == j ? 3. : 0.);
  }

  /// Assembles every owned cell's matrix and vector, through @p scatter
  /// (null: distribute_local_to_global only); returns the number of cells
  /// the scatter took (all ranks).
  unsigned int
  assemble(const DoFHandler<2>             &dof_handler,
           const AffineConstraints<double> &constraints,
           MatrixType                      &matrix,
           VectorType                      &vector,
           CellScatter                     *scatter)
  {
    matrix = 0.;
    vector = 0.;
    const unsigned int n = dof_handler.get_fe().n_dofs_per_cell();
    if (scatter)
      scatter->begin(&matrix, &vector, constraints,
                     dof_handler.locally_owned_dofs(),
                     dof_handler.get_triangulation().n_active_cells(), n);
    FullMatrix<double>                   cell_matrix(n, n);
    Vector<double>                       cell_vector(n);
    std::vector<types::global_dof_index> dofs(n);
    unsigned int                         direct = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(dofs);
          for (unsigned int i = 0; i < n; ++i)
            {
              cell_vector(i) = entry(cell->center(), i, n);
              for (unsigned int j = 0; j < n; ++j)
                cell_matrix(i, j) = entry(cell->center(), i, j);
            }
          if (scatter &&
              scatter->add(cell->active_cell_index(), dofs, cell_matrix,
                           cell_vector))
            ++direct;
          else
            constraints.distribute_local_to_global(cell_matrix, cell_vector,
                                                   dofs, matrix, vector);
        }
    matrix.compress(VectorOperation::add);
    vector.compress(VectorOperation::add);
    return Utilities::MPI::sum(direct, dof_handler.get_communicator());
  }

  /// Whether @p a and @p b have bitwise equal entries (all ranks).
  bool
  equal(const MatrixType &a, const MatrixType &b, const VectorType &u,
        const VectorType &v, const MPI_Comm comm)
  {
    bool same = true;
    const Epetra_CrsMatrix &A = a.trilinos_matrix();
    const Epetra_CrsMatrix &B = b.trilinos_matrix();
    for (int r = 0; r < A.NumMyRows(); ++r)
      {
        int     na, nb;
        double *va, *vb;
        int    *ca, *cb;
        A.ExtractMyRowView(r, na, va, ca);
        B.ExtractMyRowView(r, nb, vb, cb);
        same = same && na == nb;
        for (int k = 0; same && k < na; ++k)
          same = A.ColMap().GID64(ca[k]) == B.ColMap().GID64(cb[k]) &&
                 va[k] == vb[k];
      }
    for (const auto i : u.locally_owned_elements())
      same = same && u[i] == v[i];
    return Utilities::MPI::min(same ? 1 : 0, comm) == 1;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                   comm = MPI_COMM_WORLD;
  std::ofstream                    out;
  if (Utilities::MPI::this_mpi_process(comm) == 0)
    out.open("output");

  parallel::distributed::Triangulation<2> tria(comm);
  GridGenerator::subdivided_hyper_cube(tria, 4, 0., 1., true);
  tria.refine_global(2);
  for (const auto &cell : tria.active_cell_iterators())
    if (cell->is_locally_owned() && cell->center().distance(Point<2>(0.3, 0.6)) < 0.2)
      cell->set_refine_flag();
  tria.execute_coarsening_and_refinement();

  const FESystem<2> fe(FE_Q<2>(1), 2);
  DoFHandler<2>     dof_handler(tria);
  dof_handler.distribute_dofs(fe);
  const IndexSet owned    = dof_handler.locally_owned_dofs();
  const IndexSet relevant = DoFTools::extract_locally_relevant_dofs(dof_handler);

  AffineConstraints<double> constraints(relevant);
  DoFTools::make_hanging_node_constraints(dof_handler, constraints);
  VectorTools::interpolate_boundary_values(dof_handler, 0,
                                           Functions::ZeroFunction<2>(2),
                                           constraints);
  constraints.close();

  // Three patterns, one after the other under the same matrix objects:
  // the constrained one, the same with the constrained rows kept, and
  // that with long rows (columns 0..299 in every 97th DoF's row).
  const auto make_pattern = [&](const unsigned int kind) {
    TrilinosWrappers::SparsityPattern sp(owned, owned, relevant, comm);
    DoFTools::make_sparsity_pattern(dof_handler, sp, constraints,
                                    /*keep_constrained_dofs=*/kind > 0);
    if (kind == 2)
      for (const auto row : owned)
        if (row % 97 == 5)
          for (types::global_dof_index col = 0;
               col < std::min<types::global_dof_index>(300, dof_handler.n_dofs());
               ++col)
            sp.add(row, col);
    sp.compress();
    return sp;
  };

  out << "DoFs: " << dof_handler.n_dofs() << ", constrained DoFs: "
      << Utilities::MPI::sum(
           static_cast<unsigned int>(std::count_if(
             owned.begin(), owned.end(),
             [&](const auto i) { return constraints.is_constrained(i); })),
           comm)
      << "\n";
  MatrixType  matrix, reference;
  VectorType  vector(owned, comm), reference_vector(owned, comm);
  CellScatter scatter;
  const char *names[] = {"constrained pattern", "constrained rows kept",
                         "long rows"};
  unsigned int direct_before = 0;
  for (unsigned int kind = 0; kind < 3; ++kind)
    {
      const auto sp = make_pattern(kind);
      matrix.reinit(sp);
      reference.reinit(sp);
      assemble(dof_handler, constraints, reference, reference_vector,
               nullptr);
      unsigned int first = 0;
      bool         same  = true, same_count = true;
      for (unsigned int pass = 0; pass < 3; ++pass)
        {
          const unsigned int direct =
            assemble(dof_handler, constraints, matrix, vector, &scatter);
          if (pass == 0)
            first = direct;
          same_count = same_count && direct == first;
          same = same && equal(matrix, reference, vector, reference_vector,
                               comm);
        }
      const unsigned int cached = Utilities::MPI::sum(
        static_cast<unsigned int>(scatter.n_cached_cells()), comm);
      out << names[kind] << ": bitwise equal on 3 passes: "
          << (same ? "yes" : "NO")
          << ", cells on the direct path: " << (first > 0 ? "some" : "NONE")
          << ", the same on every pass: " << (same_count ? "yes" : "NO")
          << ", positions kept for them: " << (cached == first ? "yes" : "NO");
      if (kind == 1)
        out << ", as many as with the constrained pattern: "
            << (first == direct_before ? "yes" : "NO");
      if (kind == 2)
        out << ", fewer than without long rows: "
            << (first < direct_before ? "yes" : "NO");
      out << "\n";
      direct_before = first;
    }
}
