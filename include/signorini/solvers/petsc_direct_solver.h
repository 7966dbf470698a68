#pragma once

#include <mpi.h>

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

class Epetra_CrsMatrix;
class Epetra_MultiVector;

namespace Signorini
{
  /**
   * A sparse direct solver of PETSc's for the program's Trilinos (Epetra)
   * matrices: the locally owned rows are copied into a PETSc matrix of the
   * same parallel layout (no gathering to one rank), factorised and
   * solved; the vectors are handed over without a copy.
   *
   * - mumps: MUMPS through PETSc, distributed over every rank, as a
   *   symmetric LDL^T factorisation (MUMPS SYM = 2: the Hessians are
   *   symmetric, possibly indefinite), with MUMPS' sequential analysis and
   *   a deterministic ordering (ICNTL(7)); it reports the inertia of the
   *   matrix (the negative pivots, MUMPS INFOG(12)).
   * - cholmod: CHOLMOD's supernodal Cholesky (SuiteSparse, one rank), with
   *   its own choice between AMD and METIS nested dissection; it fails on a
   *   matrix that is not positive definite, which is how it reports the
   *   inertia (negative_pivots() is then 1, else 0).
   *
   * The symbolic analysis is kept while the sparsity pattern of the matrix
   * is unchanged on every rank; the numeric factorisation is redone only
   * when the values change (a second right-hand side for one matrix reuses
   * it).
   */
  class PETScDirectSolver
  {
  public:
    enum class Package
    {
      mumps,
      cholmod
    };

    /// @p memory_limit: MUMPS' ICNTL(23) in MB per rank, 0 for none.
    PETScDirectSolver(Package package, int mumps_ordering, int memory_limit = 0);
    ~PETScDirectSolver();

    /**
     * Solve A x = b. Returns false if the factorisation or the solve
     * failed (@p message says why; for a matrix that is singular or, with
     * CHOLMOD, not positive definite, the reason says so). Collective.
     */
    bool
    solve(const Epetra_CrsMatrix   &A,
          Epetra_MultiVector       &x,
          const Epetra_MultiVector &b,
          std::string              &message);

    /// Forget the analysis and the factorisation.
    void
    clear();

    unsigned int
    n_symbolic_factorizations() const
    {
      return n_symbolic;
    }

    unsigned int
    n_numeric_factorizations() const
    {
      return n_numeric;
    }

    /**
     * The number of negative eigenvalues of the last matrix factorised, or
     * -1 if unknown (no factorisation yet). CHOLMOD only tells whether
     * there is one: 1 when its factorisation failed for that reason.
     */
    int
    negative_pivots() const
    {
      return negative;
    }

    /**
     * The fill-reducing ordering MUMPS used in its last analysis (its
     * INFOG(7): 0 AMD, 2 AMF, 3 SCOTCH, 4 PORD, 6 QAMD), or -1 (CHOLMOD, or
     * no analysis yet).
     */
    int
    ordering_used() const
    {
      return ordering;
    }

    /**
     * The size of the node blocks (2 or 3 unknowns of one pattern) whose
     * graph MUMPS ordered in its last analysis (ICNTL(15)), 1 if it ordered
     * the unknowns' graph, or -1 (CHOLMOD, or no analysis yet).
     */
    int
    ordering_block() const
    {
      return block;
    }

    /// The name of the package and its factorisation, for summaries.
    static std::string
    name(Package package);

  private:
    struct State;

    /// A new state for the sparsity pattern of @p A (whose hash is
    /// @p hash): its columns, node blocks, PETSc matrix and solver. False
    /// (@p message says why) if PETSc cannot take the matrix's rows.
    /// Collective.
    bool
    analyse(const Epetra_CrsMatrix &A,
            std::size_t             hash,
            MPI_Comm                comm,
            std::string            &message);

    /// Whether this rank's values of @p A are the ones factorised last.
    bool
    same_values(const Epetra_CrsMatrix &A) const;

    /// Copy the values of @p A in and factorise. False (@p message says
    /// why, and the state is forgotten) if that failed on any rank.
    /// Collective.
    bool
    factorize(const Epetra_CrsMatrix &A, MPI_Comm comm, std::string &message);

    /// Solve with the factorisation. False (@p message says why, and
    /// the state is forgotten) if that failed on any rank. Collective.
    bool
    solve_factorized(Epetra_MultiVector       &x,
                     const Epetra_MultiVector &b,
                     MPI_Comm                  comm,
                     std::string              &message);

    Package                package;
    int                    mumps_ordering;
    int                    memory_limit;
    std::unique_ptr<State> state;
    unsigned int           n_symbolic = 0;
    unsigned int           n_numeric  = 0;
    int                    negative   = -1;
    int                    ordering   = -1;
    int                    block      = -1;
  };
} // namespace Signorini
