#pragma once

#include <signorini/types.h>

#include <deal.II/base/index_set.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/solver_control.h>

#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <vector>

class Amesos_BaseSolver;
class Epetra_CrsMatrix;
class Epetra_LinearProblem;
class Epetra_MultiVector;
namespace Teuchos
{
  class ParameterList;
}
namespace dealii
{
  namespace TrilinosWrappers
  {
    class PreconditionAMG;
  }
} // namespace dealii

namespace Signorini
{
  using namespace dealii;

  class PETScDirectSolver;
  class PETScAMG;

  /**
   * The near null space of an elasticity operator for algebraic multigrid:
   * the rigid motions evaluated at the DoF support points, for the locally
   * owned DoFs (in the order of the locally owned index set): first the
   * @p n_translations translations, then the rotations (1 in 2D, 3 in 3D).
   */
  struct NearNullSpace
  {
    IndexSet                         owned;
    std::vector<std::vector<double>> modes;
    unsigned int                     n_translations = 0;
    /// DoFs per node when they are numbered node by node (the DoFs of a
    /// node consecutive, component c at offset c); 1 otherwise.
    unsigned int                     dofs_per_node = 1;
    bool                             higher_order  = false;
  };

  /**
   * Solves the Newton systems H d = b. "direct" factorises H with Trilinos
   * Amesos (MUMPS on one rank, KLU on a matrix gathered to one rank) or
   * with PETSc (MUMPS' LDL^T distributed over the ranks, CHOLMOD's
   * Cholesky on one rank; PETScDirectSolver) and keeps the symbolic
   * analysis while the sparsity pattern of H is unchanged; "cg-amg" and
   * "minres-amg" use a Krylov method preconditioned by Trilinos ML
   * algebraic multigrid with the rigid motions as near null space. When a
   * Krylov solve does not converge the solver falls back to the direct one
   * if allowed.
   */
  class LinearSolver
  {
  public:
    struct Parameters
    {
      enum class Type
      {
        direct,
        cg_amg,
        minres_amg
      };
      /// The near null space given to AMG.
      enum class NullSpace
      {
        translations,
        rigid_motions
      };
      Type         type = Type::direct;
      std::string  direct_solver = "Amesos_Klu"; // "auto" is resolved when parsed
      /// MUMPS' fill-reducing ordering, as its ICNTL(7) code (also given
      /// to Ipopt's MUMPS as mumps_pivot_order).
      int          mumps_ordering = 4;
      /// The most working memory MUMPS may allocate per rank, in MB, as
      /// its ICNTL(23); 0: no limit.
      int          direct_memory_limit = 0;
      double       relative_tolerance = 1e-8;
      unsigned int max_iterations     = 1000;
      double       aggregation_threshold = 1e-4;
      unsigned int smoother_sweeps       = 2;
      /// ML's "coarse: max size": the largest level factorised directly;
      /// 0: 250 with the six rigid motions of 3D as near null space, 2000
      /// otherwise.
      unsigned int amg_coarse_size       = 0;
      /// ML's "smoother: type".
      std::string  smoother              = "Chebyshev";
      bool         fallback_to_direct    = true;
      /// CG + AMG: keep the hierarchy of the diagonally scaled matrix
      /// across solves (solve_kept_amg()).
      bool         keep_preconditioner   = true;
      NullSpace    null_space            = NullSpace::rigid_motions;
      /// Whose algebraic multigrid preconditions CG: Trilinos ML, or
      /// PETSc's GAMG or hypre's BoomerAMG (PETScAMG); each with the kept
      /// hierarchy of the scaled matrix unless keep_preconditioner is
      /// false.
      enum class AmgPackage
      {
        ml,
        gamg,
        boomeramg
      };
      AmgPackage   amg_package           = AmgPackage::ml;
      /// How Newton sets an iterative solve's tolerance: the fixed
      /// 'Relative tolerance', or the Eisenstat-Walker forcing term
      /// (forcing_term()).
      enum class Forcing
      {
        fixed,
        eisenstat_walker
      };
      Forcing      forcing     = Forcing::eisenstat_walker;
      double       max_forcing = 0.01;

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);
      std::string
      name() const;
    };

    /**
     * The relative tolerance of the next Newton solve of an inexact
     * Newton method (Eisenstat and Walker's choice 2 with the safeguards
     * of C. T. Kelley, Iterative Methods for Linear and Nonlinear
     * Equations, 1995, section 6.3): 'Maximum forcing term' at the first
     * iteration (@p previous_residual <= 0), then
     *   eta = min(eta_max, max(0.9 (|g| / |g_prev|)^2, 0.9 eta_prev^2))
     * (the second term only where 0.9 eta_prev^2 > 0.1: no sudden
     * tightening), and never below 0.5 @p tolerance / |g| (no solve more
     * accurate than the Newton tolerance can use) nor below 'Relative
     * tolerance'. With the 'fixed' forcing, or a direct solver:
     * 'Relative tolerance'.
     */
    double
    forcing_term(double residual,
                 double previous_residual,
                 double previous_forcing,
                 double tolerance) const;

    struct Info
    {
      unsigned int iterations   = 0;
      bool         used_fallback = false;
      /// The relative tolerance an iterative solve was asked for (0 for a
      /// direct solve).
      double       relative_tolerance = 0.;
      /// An iterative solve stopped at an iterate beyond max_solution.
      bool         singular = false;
    };

    explicit LinearSolver(const Parameters &parameters);
    ~LinearSolver();

    /// The near null space for AMG (see NearNullSpace).
    void
    set_near_null_space(NearNullSpace null_space);

    /**
     * Forget the direct solver's symbolic analysis and the AMG hierarchy.
     * Both are also redone whenever the matrix or its sparsity pattern
     * changes, which solve() detects itself; this only frees the memory.
     */
    void
    clear();

    /// How many symbolic analyses the direct solver has done so far.
    unsigned int
    n_symbolic_factorizations() const;

    /// How many numeric factorisations the direct solver has done so far
    /// (a second solve with the same matrix values reuses the last one).
    unsigned int
    n_numeric_factorizations() const;

    /// How many AMG hierarchies this solver built (ML, GAMG or BoomerAMG;
    /// kept across solves or, without 'Keep preconditioner', one for each
    /// new matrix).
    unsigned int
    n_preconditioner_builds() const
    {
      return amg.n_builds;
    }

    /**
     * The number of negative eigenvalues of the matrix of the last solve(),
     * where its factorisation tells it (PETSc_Mumps: MUMPS' negative
     * pivots; PETSc_Cholmod: 1 if it failed as not positive definite, else
     * 0); -1 otherwise (another solver, an iterative solve, or a failure
     * before the factorisation).
     */
    int
    negative_pivots() const
    {
      return last_negative_pivots;
    }

    /**
     * The fill-reducing ordering MUMPS used in the last analysis of the
     * PETSc_Mumps solver ("amd", "amf", "scotch", "pord", "qamd"), or ""
     * (another solver, or no analysis yet).
     */
    std::string
    ordering_used() const;

    /// The node block size of that analysis (PETScDirectSolver::
    /// ordering_block()), or -1.
    int
    ordering_block() const;

    /**
     * Solve @p H @p x = @p b. Returns false (x undefined) if the solve
     * failed; @p message says why. An iterative solve stops at
     * |H x - b| <= @p relative_tolerance |b| when that is given (> 0; an
     * inexact Newton method's forcing term), else at the parameter
     * file's 'Relative tolerance'; a direct solve ignores it. With
     * @p max_solution > 0 an iterative solve stops as soon as an iterate
     * has an entry larger than that (a singular or nearly singular H, e.g.
     * a body held only by contact before it touches: its CG iterates grow
     * without bound and the residual stalls) and fails with
     * Info::singular set and no fallback to the direct solver, whose
     * solution would be just as large.
     */
    bool
    solve(const MatrixType &H,
          VectorType       &x,
          const VectorType &b,
          Info             &info,
          std::string      &message,
          double            relative_tolerance = 0.,
          double            max_solution = 0.) const;

    /// Whether solve() is iterative (its accuracy set by a tolerance).
    bool
    is_iterative() const
    {
      return parameters.type != Parameters::Type::direct;
    }

    const Parameters &
    get_parameters() const
    {
      return parameters;
    }

  private:
    bool
    solve_petsc(const MatrixType &H,
                VectorType       &x,
                const VectorType &b,
                std::string      &message) const;

    bool
    solve_amesos(const MatrixType &H,
                 VectorType       &x,
                 const VectorType &b,
                 std::string      &message) const;

    bool
    solve_direct(const MatrixType &H,
                 VectorType       &x,
                 const VectorType &b,
                 std::string      &message) const;

    void
    forget_analysis() const;

    /// How many near null space vectors AMG gets: all the rigid motions,
    /// or the translations alone ('AMG near null space').
    unsigned int
    n_amg_modes() const;

    /// ML's parameters for @p H, with the near null space in @p modes
    /// (which must live until the preconditioner is built).
    void
    amg_parameters(const MatrixType                    &H,
                   Teuchos::ParameterList              &list,
                   std::unique_ptr<Epetra_MultiVector> &modes) const;

    /// The direct solver and its symbolic analysis, kept while the
    /// sparsity pattern stays the same (a cache: solve() is const), with
    /// its own copy of the matrix (Amesos uses the matrix until it is
    /// destroyed).
    struct DirectState
    {
      std::unique_ptr<Epetra_CrsMatrix>     matrix;
      std::size_t                           pattern_hash = 0;
      std::unique_ptr<Epetra_LinearProblem> problem;
      std::unique_ptr<Amesos_BaseSolver>    solver;
      unsigned int                          n_symbolic = 0;
      /// The solver holds the factorisation of the matrix copy's values.
      bool                                  factorized = false;
      unsigned int                          n_numeric  = 0;
      /// The PETSc direct solvers (PETSc_Mumps, PETSc_Cholmod) instead.
      std::unique_ptr<PETScDirectSolver>    petsc;
    };

    /// Build the AMG hierarchy for @p H (ML's, or PETSc's for CG with
    /// another 'AMG package') unless it is that of the last solve (the
    /// same matrix object, pattern and values).
    void
    prepare_amg(const MatrixType &H) const;

    /// Whether the hierarchy is ML's (MINRES, or CG with 'AMG package =
    /// ML'), not a PETSc package's.
    bool
    uses_ml() const;

    /**
     * A new hierarchy (ML's or the PETSc package's) for @p H, replacing
     * the one held, and counted. With @p s_inv (H scaled by S = diag^-1/2,
     * its inverse as a vector of H's rows) the near null space is S^-1
     * times the rigid motions, that of the scaled matrix. The caller sets
     * the rest of the AmgState.
     */
    void
    build_amg(const MatrixType &H, const Epetra_Vector *s_inv) const;

    /**
     * CG on @p H with an AMG hierarchy kept across solves. H = S^-1 H_s
     * S^-1 with S = diag(H)^-1/2 and H_s the scaled matrix, whose diagonal
     * is 1: the rows of the contact nodes, whose barrier or penalty terms
     * change by orders of magnitude from one iteration to the next, then
     * change no more than the others, and ML's smoother, which keeps the
     * diagonal of the matrix it was built for, stays right. H is scaled in
     * place for the solve (ML's finest level reads the matrix) and scaled
     * back; CG runs on H_s's iterates with S H_s S as the operator and S
     * AMG(H_s)^-1 S as the preconditioner, so that it stops on the
     * residual of the original system. The hierarchy is rebuilt when the
     * sparsity pattern changes, when a solve fails, and after a solve that
     * needed more than 1.5 times (plus 5) the CG iterations of the solve
     * right after the last build. A kept hierarchy gets 3 times (plus 20)
     * those iterations: a solve that needs more is started again with a
     * new hierarchy, and @p wasted gets the iterations of the first try
     * (0 otherwise), also when the second try throws. Throws what SolverCG
     * throws.
     */
    void
    solve_kept_amg(const MatrixType &H,
                   VectorType       &x,
                   const VectorType &b,
                   SolverControl    &control,
                   const std::function<SolverControl::State(const unsigned int,
                                                            const double,
                                                            const VectorType &)>
                                 &check,
                   unsigned int &wasted) const;

    /// The AMG hierarchy of the last iterative solve and the matrix it was
    /// built from: its address, pattern and values (a cache: solve() is
    /// const).
    struct AmgState
    {
      std::unique_ptr<TrilinosWrappers::PreconditionAMG> preconditioner;
      /// Or the PETSc package's hierarchy.
      std::unique_ptr<PETScAMG> petsc;
      const void  *matrix        = nullptr;
      std::size_t  pattern_hash  = 0;
      std::size_t  values_hash   = 0;
      /// Built by solve_kept_amg() for the scaled matrix.
      bool         scaled          = false;
      /// A kept hierarchy that the next solve must rebuild.
      bool         rebuild         = false;
      /// CG iterations of the solve right after the last build.
      unsigned int base_iterations = 0;
      unsigned int n_builds        = 0;
    };

    Parameters          parameters;
    NearNullSpace       null_space;
    mutable DirectState direct;
    mutable AmgState    amg;
    /// negative_pivots() of the last solve.
    mutable int         last_negative_pivots = -1;
  };
} // namespace Signorini
