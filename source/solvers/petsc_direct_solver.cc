#include <signorini/input_error.h>
#include <signorini/pattern_hash.h>
#include <signorini/solvers/petsc_interop.h>
#include <signorini/solvers/petsc_direct_solver.h>

#include <deal.II/base/exceptions.h>

#include <Epetra_CrsGraph.h>
#include <Epetra_CrsMatrix.h>
#include <Epetra_MpiComm.h>
#include <Epetra_MultiVector.h>
#include <petscksp.h>

#include <algorithm>
#include <array>
#include <stdexcept>
#include <utility>

namespace Signorini
{
  namespace
  {
    /// Whether PETSc's options (PETSC_OPTIONS, the command line) chose
    /// MUMPS' ordering before this program set it: asked once, before the
    /// first analysis.
    bool
    ordering_from_command_line()
    {
      static const bool set = [] {
        PetscBool has = PETSC_FALSE;
        PetscOptionsHasName(nullptr, nullptr, "-mat_mumps_icntl_7", &has);
        return has == PETSC_TRUE;
      }();
      return set;
    }

    /// For k = 3 and 2: how many blocks of k consecutive local rows
    /// (starting at global multiples of k) there are, and how many of them
    /// have one column pattern in all their k rows. The vector components of
    /// a node in deal.II's numbering of an FESystem form such blocks, except
    /// at nodes with some components constrained (their rows and columns
    /// hold only the diagonal). @p columns: the global columns of the local
    /// rows, row r in [row_start[r], row_start[r+1]); @p first: the global
    /// index of local row 0.
    std::array<std::array<long long, 2>, 2>
    node_blocks(const std::vector<PetscInt> &columns,
                const std::vector<int>      &row_start,
                const long long              first)
    {
      std::array<std::array<long long, 2>, 2> counts{};
      const int                               n = static_cast<int>(row_start.size()) - 1;
      for (const int k : {3, 2})
        {
          auto &[blocks, uniform] = counts[3 - k];
          if (n % k != 0 || first % k != 0)
            continue;
          blocks = n / k;
          std::vector<PetscInt> head, row;
          for (int r = 0; r < n; r += k)
            {
              head.assign(columns.begin() + row_start[r],
                          columns.begin() + row_start[r + 1]);
              std::sort(head.begin(), head.end());
              bool same = true;
              for (int i = 1; i < k && same; ++i)
                {
                  row.assign(columns.begin() + row_start[r + i],
                             columns.begin() + row_start[r + i + 1]);
                  std::sort(row.begin(), row.end());
                  same = row == head;
                }
              uniform += same;
            }
        }
      return counts;
    }

    /// The size of the node blocks whose graph MUMPS is to order: 3 or 2
    /// where every rank's rows split into such blocks and half of all of
    /// them have one pattern, else 1 (collective).
    int
    node_block_size(const std::vector<PetscInt> &columns,
                    const std::vector<int>      &row_start,
                    const long long              first,
                    const int                    n,
                    const MPI_Comm               comm)
    {
      // MUMPS orders the graph of node blocks of k unknowns when half
      // of the blocks have one pattern (on every rank together). The
      // order of the blocks is then one order of the unknowns, so
      // the factorisation is that of the same matrix whatever the
      // other half; it only decides the fill.
      auto      counts   = node_blocks(columns, row_start, first);
      long long local[4] = {counts[0][0], counts[0][1], counts[1][0],
                            counts[1][1]},
                total[4] = {0, 0, 0, 0};
      MPI_Allreduce(local, total, 4, MPI_LONG_LONG, MPI_SUM, comm);
      // Every rank's rows must split into whole blocks.
      int ranks_blocked[2] = {0, 0};
      for (int i = 0; i < 2; ++i)
        {
          const int mine = n == 0 || counts[i][0] > 0;
          MPI_Allreduce(&mine, &ranks_blocked[i], 1, MPI_INT, MPI_MIN, comm);
        }
      int block = 1;
      for (int i = 0; i < 2 && block == 1; ++i)
        if (ranks_blocked[i] == 1 && total[2 * i] > 0 &&
            2 * total[2 * i + 1] >= total[2 * i])
          block = 3 - i;
      return block;
    }

    /// Create @p M, a symmetric PETSc matrix of @p n local rows (of
    /// @p n_global) with room for exactly the given entries per row in
    /// the diagonal and off-diagonal blocks.
    void
    create_matrix(const MPI_Comm               comm,
                  const int                    n,
                  const PetscInt               n_global,
                  const std::vector<PetscInt> &diagonal,
                  const std::vector<PetscInt> &off_diagonal,
                  Mat                         &M)
    {
      check_petsc(MatCreate(comm, &M), "MatCreate");
      check_petsc(MatSetSizes(M, n, n, n_global, n_global), "MatSetSizes");
      check_petsc(MatSetType(M, MATAIJ), "MatSetType");
      check_petsc(MatSeqAIJSetPreallocation(M, 0, diagonal.data()),
                  "MatSeqAIJSetPreallocation");
      check_petsc(MatMPIAIJSetPreallocation(M, 0, diagonal.data(), 0,
                                            off_diagonal.data()),
                  "MatMPIAIJSetPreallocation");
      // Only the upper triangle is factorised: the Hessians are
      // symmetric.
      check_petsc(MatSetOption(M, MAT_SYMMETRIC, PETSC_TRUE), "MatSetOption");
      check_petsc(MatSetOption(M, MAT_SYMMETRY_ETERNAL, PETSC_TRUE), "MatSetOption");
      check_petsc(MatSetOption(M, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_TRUE),
                  "MatSetOption");
    }

    /// Create @p ksp: no iteration, only the Cholesky factorisation of
    /// @p solver_type (MUMPS or CHOLMOD).
    void
    create_direct_solver(const MPI_Comm comm, const MatSolverType solver_type, KSP &ksp)
    {
      check_petsc(KSPCreate(comm, &ksp), "KSPCreate");
      check_petsc(KSPSetType(ksp, KSPPREONLY), "KSPSetType");
      PC pc = nullptr;
      check_petsc(KSPGetPC(ksp, &pc), "KSPGetPC");
      check_petsc(PCSetType(pc, PCCHOLESKY), "PCSetType");
      // The package's own fill-reducing ordering: PETSc's default for
      // a factorisation is the natural one, which CHOLMOD would take
      // as given (and fill the factor of a 34k-DoF 2D Hessian with
      // gigabytes).
      check_petsc(PCFactorSetMatOrderingType(pc, MATORDERINGEXTERNAL),
                  "PCFactorSetMatOrderingType");
      check_petsc(PCFactorSetMatSolverType(pc, solver_type), "PCFactorSetMatSolverType");
    }

    /// Create the MUMPS factor of @p pc and set its controls, which must
    /// be set before the analysis: the ordering @p mumps_ordering and,
    /// with @p block > 1, the node blocks to order.
    void
    set_mumps_controls(PC pc, const int mumps_ordering, const int block, const int memory_mb)
    {
      // The factor exists from here on; its MUMPS controls must be
      // set before the analysis. ICNTL(28) = 1: sequential
      // analysis with the ordering of ICNTL(7) (deterministic,
      // unlike MUMPS' parallel orderings); ICNTL(13) = 1: no
      // ScaLAPACK on the root front, so that INFOG(12) counts
      // every negative pivot; ICNTL(14): 50% more workspace than
      // the analysis estimates.
      check_petsc(PCFactorSetUpMatSolverType(pc), "PCFactorSetUpMatSolverType");
      Mat F = nullptr;
      check_petsc(PCFactorGetMatrix(pc, &F), "PCFactorGetMatrix");
      // The ordering goes through PETSc's options: on one rank
      // PETSc 3.18 sets ICNTL(7) = 7 (MUMPS' own choice) when it
      // initialises MUMPS at the analysis, after this call, so
      // MatMumpsSetIcntl(F, 7, ...) had no effect there (every
      // choice gave MUMPS' own pick: AMF for small matrices, PORD
      // for large ones); the options are read after that. One set
      // in PETSC_OPTIONS wins.
      if (!ordering_from_command_line())
        check_petsc(PetscOptionsSetValue(nullptr,
                                         "-mat_mumps_icntl_7",
                                         std::to_string(mumps_ordering).c_str()),
                    "PetscOptionsSetValue");
      check_petsc(MatMumpsSetIcntl(F, 28, 1), "MUMPS ICNTL(28)");
      check_petsc(MatMumpsSetIcntl(F, 13, 1), "MUMPS ICNTL(13)");
      check_petsc(MatMumpsSetIcntl(F, 14, 50), "MUMPS ICNTL(14)");
      // ICNTL(15) = -k: the analysis orders the graph of the node
      // blocks (half or a third of the unknowns, a quarter or a
      // ninth of the edges): on the 2D 2e5-DoF rigid Hertz Hessian
      // 10% fewer flops per factorisation and a shorter analysis
      // (doc/performance.md).
      if (block > 1)
        check_petsc(MatMumpsSetIcntl(F, 15, -block), "MUMPS ICNTL(15)");
      // ICNTL(23): the most working memory per rank, so that a matrix too
      // large for the machine ends in MUMPS' own error (INFOG(1) = -19)
      // instead of the kernel killing the process.
      if (memory_mb > 0)
        check_petsc(MatMumpsSetIcntl(F, 23, memory_mb), "MUMPS ICNTL(23)");
    }

    /// Why a factorisation failed, to follow the package's name.
    std::string
    factorization_failure(const bool not_definite, const MatFactorError error)
    {
      return not_definite ? ": the matrix is not positive definite" :
             error == MAT_FACTOR_NUMERIC_ZEROPIVOT ?
                            ": the matrix is singular (zero pivot)" :
             error == MAT_FACTOR_OUTMEMORY ?
                            ": out of memory in the factorisation" :
             error == MAT_FACTOR_NOERROR ?
                            ": the factorisation failed on another rank" :
                            ": the factorisation failed";
    }
  } // namespace

  /// The PETSc objects of one sparsity pattern.
  struct PETScDirectSolver::State
  {
    Mat                 matrix   = nullptr;
    KSP                 ksp      = nullptr;
    std::size_t         hash     = 0;
    PetscInt            first    = 0;
    PetscInt            n_global = 0;
    /// The values of the matrix last copied in, in Epetra's order, and
    /// whether PETSc holds their factorisation.
    std::vector<double> values;
    bool                factorized = false;
    /// The global column indices of the local rows, in Epetra's order, and
    /// where each row starts in them (found once per pattern).
    std::vector<PetscInt> columns;
    std::vector<int>      row_start;
    /// Unknowns in blocks of this size with one pattern, on every rank
    /// (node_blocks()); MUMPS then orders the graph of the blocks.
    int block = 1;

    ~State()
    {
      if (ksp)
        KSPDestroy(&ksp);
      if (matrix)
        MatDestroy(&matrix);
    }
  };

  PETScDirectSolver::PETScDirectSolver(const Package package,
                                       const int     mumps_ordering,
                                       const int     memory_limit)
    : package(package)
    , mumps_ordering(mumps_ordering)
    , memory_limit(memory_limit)
  {
    // CHOLMOD picks a simplicial LDL^T for small or very sparse matrices,
    // which factorises indefinite matrices without complaint; the
    // supernodal LL^T fails on them, which is what tells the Newton and
    // interior point iterations to shift the diagonal. Ask for it always
    // (unless the command line set it).
    if (package == Package::cholmod)
      {
        // CHOLMOD's own warning on stderr would repeat what the solve's
        // message says.
        for (const auto &[key, value] :
             {std::pair<const char *, const char *>{"-mat_cholmod_factor",
                                                    "SUPERNODAL"},
              {"-mat_cholmod_print", "0"}})
          {
            PetscBool set = PETSC_FALSE;
            PetscOptionsHasName(nullptr, nullptr, key, &set);
            if (!set)
              PetscOptionsSetValue(nullptr, key, value);
          }
      }
  }

  PETScDirectSolver::~PETScDirectSolver() = default;

  std::string
  PETScDirectSolver::name(const Package package)
  {
    return package == Package::mumps ? "PETSc_Mumps (distributed LDLT)" :
                                       "PETSc_Cholmod (supernodal Cholesky)";
  }

  void
  PETScDirectSolver::clear()
  {
    state.reset();
  }

  bool
  PETScDirectSolver::solve(const Epetra_CrsMatrix   &A,
                           Epetra_MultiVector       &x,
                           const Epetra_MultiVector &b,
                           std::string              &message)
  {
    const auto *mpi = dynamic_cast<const Epetra_MpiComm *>(&A.Comm());
    AssertThrow(mpi != nullptr,
                dealii::ExcMessage("The matrix has no MPI communicator."));
    const MPI_Comm comm = mpi->Comm();
    const int      n    = A.NumMyRows();
    AssertThrow(x.MyLength() == n && b.MyLength() == n &&
                  x.NumVectors() == 1 && b.NumVectors() == 1,
                dealii::ExcMessage("The vectors do not match the matrix rows."));

    try
      {
        const std::size_t hash = sparsity_pattern_hash(A);
        if (!on_all_ranks(comm, state && state->hash == hash))
          {
            state.reset();
            if (!analyse(A, hash, comm, message))
              return false;
          }
        // Copy the values in and factorise unless they are the ones
        // factorised last: then only solve again.
        if (!on_all_ranks(comm, same_values(A)) && !factorize(A, comm, message))
          return false;
        if (!solve_factorized(x, b, comm, message))
          return false;
      }
    catch (const SolveFailure &)
      {
        state.reset();
        throw;
      }
    catch (const std::exception &e)
      {
        state.reset();
        message = e.what();
        return false;
      }
    return true;
  }

  bool
  PETScDirectSolver::analyse(const Epetra_CrsMatrix &A,
                             const std::size_t       hash,
                             const MPI_Comm          comm,
                             std::string            &message)
  {
    const Epetra_BlockMap &cols = A.ColMap();
    const int              n    = A.NumMyRows();
    const long long n_before = first_owned_row(A, comm);
    if (n_before < 0)
      {
        message = name(package) +
                  ": the rows a rank owns are not one contiguous range "
                  "in rank order";
        return false;
      }
    if (package == Package::cholmod && A.Comm().NumProc() > 1)
      {
        message = name(package) + " runs on one MPI rank only";
        return false;
      }

    state           = std::make_unique<State>();
    state->hash     = hash;
    state->first    = n_before;
    state->n_global = A.NumGlobalRows64();

    std::vector<PetscInt> diagonal(n, 0), off_diagonal(n, 0);
    state->row_start.assign(1, 0);
    for (int r = 0; r < n; ++r)
      {
        int  m       = 0;
        int *indices = nullptr;
        A.Graph().ExtractMyRowView(r, m, indices);
        for (int k = 0; k < m; ++k)
          {
            const long long c = cols.GID64(indices[k]);
            state->columns.push_back(static_cast<PetscInt>(c));
            if (c >= state->first && c < state->first + n)
              ++diagonal[r];
            else
              ++off_diagonal[r];
          }
        state->row_start.push_back(state->columns.size());
      }
    state->block =
      node_block_size(state->columns, state->row_start, state->first, n, comm);
    create_matrix(comm, n, state->n_global, diagonal, off_diagonal, state->matrix);
    create_direct_solver(comm,
                         package == Package::mumps ? MATSOLVERMUMPS :
                                                     MATSOLVERCHOLMOD,
                         state->ksp);
    ++n_symbolic;
    return true;
  }

  bool
  PETScDirectSolver::same_values(const Epetra_CrsMatrix &A) const
  {
    const State &s    = *state;
    const int    n    = A.NumMyRows();
    bool         same = s.factorized;
    for (int r = 0, offset = 0; r < n && same; ++r)
      {
        int     m = 0;
        double *v = nullptr;
        A.ExtractMyRowView(r, m, v);
        same = std::equal(v, v + m, s.values.begin() + offset);
        offset += m;
      }
    return same;
  }

  bool
  PETScDirectSolver::factorize(const Epetra_CrsMatrix &A,
                               const MPI_Comm          comm,
                               std::string            &message)
  {
    State    &s = *state;
    const int n = A.NumMyRows();
    s.factorized = false;
    s.values.clear();
    for (int r = 0; r < n; ++r)
      {
        int     m = 0;
        double *v = nullptr;
        A.ExtractMyRowView(r, m, v);
        AssertThrow(m == s.row_start[r + 1] - s.row_start[r],
                    dealii::ExcInternalError());
        const PetscInt row = s.first + r;
        check_petsc(MatSetValues(s.matrix, 1, &row, m,
                                 s.columns.data() + s.row_start[r], v,
                                 INSERT_VALUES),
                    "MatSetValues");
        s.values.insert(s.values.end(), v, v + m);
      }
    check_petsc(MatAssemblyBegin(s.matrix, MAT_FINAL_ASSEMBLY), "MatAssemblyBegin");
    check_petsc(MatAssemblyEnd(s.matrix, MAT_FINAL_ASSEMBLY), "MatAssemblyEnd");
    check_petsc(KSPSetOperators(s.ksp, s.matrix, s.matrix), "KSPSetOperators");
    PC pc = nullptr;
    check_petsc(KSPGetPC(s.ksp, &pc), "KSPGetPC");
    if (package == Package::mumps)
      set_mumps_controls(pc, mumps_ordering, s.block, memory_limit);
    // CHOLMOD's supernodal Cholesky stops at the first pivot that
    // is not positive, as a PETSc error (PETSC_ERR_MAT_CH_ZRPVT),
    // not as the factor's error type; PETSc must not print it.
    PetscPushErrorHandler(PetscReturnErrorHandler, nullptr);
    const PetscErrorCode setup = KSPSetUp(s.ksp);
    PetscPopErrorHandler();
    ++n_numeric;
    const bool not_definite = setup == PETSC_ERR_MAT_CH_ZRPVT;
    if (!not_definite)
      check_petsc(setup, "KSPSetUp");

    Mat F = nullptr;
    check_petsc(PCFactorGetMatrix(pc, &F), "PCFactorGetMatrix");
    MatFactorError error = MAT_FACTOR_NOERROR;
    if (!not_definite)
      check_petsc(MatFactorGetError(F, &error), "MatFactorGetError");
    // MUMPS' status INFOG(1): its memory errors are -13 (an allocation
    // failed) and -19 (more than ICNTL(23) needed). (-8 and -9, a
    // workspace too small for the pivots of this matrix, stay ordinary
    // failures: a shifted diagonal may factorise.)
    PetscInt status = 0;
    if (package == Package::mumps && !not_definite)
      {
        PetscInt value = 0;
        check_petsc(MatMumpsGetInfog(F, 1, &status), "MUMPS INFOG(1)");
        check_petsc(MatMumpsGetInfog(F, 12, &value), "MUMPS INFOG(12)");
        negative = static_cast<int>(value);
        check_petsc(MatMumpsGetInfog(F, 7, &value), "MUMPS INFOG(7)");
        ordering = static_cast<int>(value);
        block    = s.block;
      }
    else
      negative = (not_definite || error != MAT_FACTOR_NOERROR) ? 1 : 0;
    const bool memory = status == -13 || status == -19;
    if (!on_all_ranks(comm, error == MAT_FACTOR_NOERROR && !not_definite))
      {
        state.reset();
        // Fatal: a smaller step or a shifted diagonal needs as much memory.
        if (!on_all_ranks(comm, !memory))
          throw SolveFailure(
            name(package) +
            (status == -19 ?
               ": the factorisation needs more memory than MUMPS may use (at most " +
                 std::to_string(memory_limit) +
                 " MB per rank, Solver > Linear solver > Direct solver memory limit)" :
               ": MUMPS could not allocate the memory of the factorisation (its "
               "error " + std::to_string(status) + ")") +
            ": use Solver > Linear solver > Type = cg-amg, or more memory per rank");
        message = name(package) + factorization_failure(not_definite, error);
        return false;
      }
    s.factorized = true;
    return true;
  }

  bool
  PETScDirectSolver::solve_factorized(Epetra_MultiVector       &x,
                                      const Epetra_MultiVector &b,
                                      const MPI_Comm            comm,
                                      std::string              &message)
  {
    const State &s = *state;
    const int    n = x.MyLength();
    Vec          pb = nullptr, px = nullptr;
    check_petsc(VecCreateMPIWithArray(comm, 1, n, s.n_global,
                                      const_cast<double *>(b[0]), &pb),
                "VecCreateMPIWithArray");
    check_petsc(VecCreateMPIWithArray(comm, 1, n, s.n_global, x[0], &px),
                "VecCreateMPIWithArray");
    const PetscErrorCode code = KSPSolve(s.ksp, pb, px);
    VecDestroy(&pb);
    VecDestroy(&px);
    check_petsc(code, "KSPSolve");
    KSPConvergedReason reason;
    check_petsc(KSPGetConvergedReason(s.ksp, &reason), "KSPGetConvergedReason");
    if (!on_all_ranks(comm, reason >= 0))
      {
        state.reset();
        message = name(package) + ": the solve failed (PETSc reason " +
                  std::to_string(static_cast<int>(reason)) + ")";
        return false;
      }
    return true;
  }
} // namespace Signorini
