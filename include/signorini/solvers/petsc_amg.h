#pragma once

#include <mpi.h>

#include <memory>
#include <string>
#include <vector>

class Epetra_CrsMatrix;
class Epetra_Vector;

namespace Signorini
{
  /**
   * One V-cycle of a PETSc algebraic multigrid preconditioner, built from a
   * copy of a Trilinos matrix and applied to Trilinos vectors of its row
   * layout, for deal.II's CG in place of Trilinos ML (LinearSolver, 'AMG
   * package'):
   * - PETSc's GAMG (smoothed aggregation) with the given near null space
   *   (orthonormalised), the matrix's block size the DoFs per node;
   * - hypre's BoomerAMG (classical), which uses the block size only.
   * The options database (PETSC_OPTIONS, -pc_gamg_*, -pc_hypre_*) can
   * adjust either: the preconditioner reads it when built.
   */
  class PETScAMG
  {
  public:
    enum class Package
    {
      gamg,
      boomeramg
    };

    explicit PETScAMG(Package package);
    ~PETScAMG();

    /**
     * Build the hierarchy for @p A, whose locally owned rows must be one
     * contiguous range in rank order (deal.II's numbering). The first
     * @p n_modes of @p modes: the near null space on the owned rows, in
     * their order (GAMG; none: GAMG's default); @p dofs_per_node: the
     * block size (1: none).
     */
    void
    initialize(const Epetra_CrsMatrix                 &A,
               const std::vector<std::vector<double>> &modes,
               unsigned int                            n_modes,
               unsigned int                            dofs_per_node);

    /// dst = M^-1 src, one V-cycle.
    void
    vmult(Epetra_Vector &dst, const Epetra_Vector &src) const;

    static std::string
    name(Package package);

  private:
    struct State;
    Package                package;
    std::unique_ptr<State> state;
  };
} // namespace Signorini
