#include <signorini/input_error.h>
#include <signorini/pattern_hash.h>
#include <signorini/solvers/linear_solver.h>
#include <signorini/solvers/petsc_amg.h>
#include <signorini/solvers/petsc_direct_solver.h>

#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_minres.h>
#include <deal.II/lac/trilinos_precondition.h>

#include <Amesos.h>
#include <Amesos_BaseSolver.h>
#include <Epetra_CrsGraph.h>
#include <Epetra_CrsMatrix.h>
#include <Epetra_LinearProblem.h>
#include <Epetra_MultiVector.h>
#include <Epetra_Vector.h>
#include <Teuchos_ParameterList.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <memory>
#include <utility>

namespace Signorini
{
  namespace
  {
    /// The MUMPS orderings by name ('MUMPS ordering') and ICNTL(7) /
    /// INFOG(7) code.
    constexpr std::pair<const char *, int> mumps_orderings[] = {
      {"amd", 0}, {"amf", 2}, {"scotch", 3}, {"pord", 4}, {"qamd", 6}};
  } // namespace

  void
  LinearSolver::Parameters::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Type",
                      "direct",
                      Patterns::Selection("direct|cg-amg|minres-amg"),
                      "direct: sparse LU (Trilinos Amesos). cg-amg: conjugate "
                      "gradients with algebraic multigrid (Trilinos ML), for "
                      "large problems with a positive definite Hessian. "
                      "minres-amg: MINRES (symmetric indefinite systems) with "
                      "the same preconditioner, which itself assumes a "
                      "definite matrix.");
    prm.declare_entry(
      "Direct solver",
      "auto",
      Patterns::Selection("auto|Amesos_Klu|Amesos_Mumps|PETSc_Mumps|PETSc_Cholmod"),
      "The sparse direct solver. Every one keeps its symbolic analysis "
      "(ordering) while the sparsity pattern of the Hessian is unchanged "
      "and redoes only the numeric factorisation. "
      "Amesos_Mumps: MUMPS' LU through Trilinos, distributed over the "
      "ranks. Amesos_Klu: KLU on the matrix gathered to one rank, any "
      "number of ranks, about 2.3x slower than MUMPS on the 51k-DoF Hertz "
      "mesh. PETSc_Mumps: MUMPS' symmetric LDL^T through PETSc, "
      "distributed over all ranks (no gathering), with the sequential "
      "analysis and the 'MUMPS ordering'; it also counts the negative "
      "eigenvalues of the matrix. PETSc_Cholmod: CHOLMOD's supernodal "
      "Cholesky (SuiteSparse, METIS or AMD ordering), one MPI rank only; "
      "it fails on a matrix that is not positive definite, which the "
      "Newton and interior point iterations answer with a diagonal shift "
      "(the interior point method failed the peer's rigid Hertz scene with "
      "it: doc/performance.md). "
      "auto: PETSc_Mumps, the fastest measured on 1 and 2 ranks from 1e4 "
      "to 5e5 DoFs (doc/performance.md, 'Linear solvers').");
    prm.declare_entry("Direct solver memory limit",
                      "0",
                      Patterns::Integer(0, 100000000),
                      "The most working memory MUMPS may allocate per MPI "
                      "rank (PETSc_Mumps, the default direct solver), in "
                      "MB, as its ICNTL(23); 0: no limit. A factorisation "
                      "that needs more ends the run at once with status "
                      "failed and a reason that says so, instead of the "
                      "system killing the process for lack of memory. "
                      "MUMPS reserves (without touching) its whole working "
                      "array of that size at each factorisation, so the "
                      "limit must fit in the process's address space "
                      "(ulimit -v). An allocation that fails inside MUMPS "
                      "ends the run the same way, limit or not.");
    prm.declare_entry("MUMPS ordering",
                      "pord",
                      Patterns::Selection("pord|amf|amd|qamd|scotch|auto"),
                      "Fill-reducing ordering of MUMPS (PETSc_Mumps, "
                      "Amesos_Mumps and Ipopt's linear solver; MUMPS "
                      "ICNTL(7), with the sequential analysis on several "
                      "ranks). Debian's MUMPS has no METIS; its parallel "
                      "build (PETSc_Mumps, Amesos_Mumps) has no SCOTCH "
                      "either and takes AMF or PORD for scotch, while the "
                      "sequential one Ipopt links has it. MUMPS' automatic "
                      "choice (auto) takes SCOTCH where it has it, whose "
                      "orderings differ from run to run: two runs of one "
                      "scene then drift apart at round-off level and may "
                      "even take different load steps. pord (nested "
                      "dissection), amf, amd and qamd are deterministic; on "
                      "the 7330-DoF Hertz-on-block matrix pord gives 713k "
                      "entries in the factors, amf 726k, amd and qamd 751k, "
                      "scotch 780k; on the 129 514-DoF rigid Hertz Hessian "
                      "pord 3.5 GFlop per factorisation, amf 4.1, amd 6.1. "
                      "PETSc_Mumps orders the graph of the mesh nodes (2 or "
                      "3 unknowns each, MUMPS ICNTL(15)) when at least half "
                      "of them have one pattern: on the 202 692-DoF rigid "
                      "Hertz Hessian 6.9 instead of 7.6 GFlop per "
                      "factorisation on one rank. summary.json's solver "
                      "block names the ordering MUMPS used (PETSc_Mumps), "
                      "e.g. 'pord on node blocks of 2'.");
    prm.declare_entry("Relative tolerance",
                      "1e-8",
                      Patterns::Double(0., 1.),
                      "Iterative solvers: stop when |H d - b| <= this * |b|.");
    prm.declare_entry("Maximum iterations",
                      "1000",
                      Patterns::Integer(1),
                      "Iterative solvers: iteration limit.");
    prm.declare_entry("Forcing term",
                      "Eisenstat-Walker",
                      Patterns::Selection("fixed|Eisenstat-Walker"),
                      "Iterative solvers under Newton's method (the "
                      "penalty path, a scene without contact): the "
                      "tolerance of each Newton solve. fixed: 'Relative "
                      "tolerance'. Eisenstat-Walker: an inexact Newton "
                      "method; the first solve of a minimisation stops at "
                      "'Maximum forcing term', the next ones at 0.9 "
                      "(|g_k| / |g_k-1|)^2, tightening as the gradient "
                      "falls and never below 'Relative tolerance', so that "
                      "the linear solves far from the solution are cheap "
                      "(Kelley's safeguards, doc/performance.md). The "
                      "interior point method, the predictors and the "
                      "direct solver keep 'Relative tolerance'.");
    prm.declare_entry("Maximum forcing term",
                      "0.01",
                      Patterns::Double(0., 1.),
                      "Eisenstat-Walker: the largest relative tolerance of a "
                      "Newton solve (that of the first one).");
    prm.declare_entry("AMG aggregation threshold",
                      "1e-4",
                      Patterns::Double(0., 1.),
                      "Trilinos ML aggregation threshold.");
    prm.declare_entry("AMG smoother sweeps",
                      "2",
                      Patterns::Integer(1, 20),
                      "Trilinos ML smoother sweeps (the degree of the "
                      "Chebyshev polynomial).");
    prm.declare_entry("AMG coarse size",
                      "0",
                      Patterns::Integer(0),
                      "Trilinos ML coarsens until a level has at most this "
                      "many unknowns, and factorises that level with KLU. 0: "
                      "250 where the near null space has the six rigid "
                      "motions of 3D, 2000 (deal.II's default) otherwise. A "
                      "3D coarse level with six rigid motions per aggregate "
                      "has a nearly dense factor: at 2000 its two "
                      "triangular solves per V-cycle "
                      "took a quarter of the sphere's run at 27 882 DoFs. "
                      "Measured on prm/hertz_sphere.prm, 2 ranks, whole "
                      "process: 1.84 s with 2000, 1.42 s with 250 (27 882 "
                      "DoFs); 10.7 s and 9.2 s (168 597); the same CG "
                      "iterations. In 2D 250 took 5% (2e5 DoFs) and 17% "
                      "(8e5) more CG iterations for no gain in time "
                      "(doc/performance.md).");
    prm.declare_entry("AMG smoother",
                      "Chebyshev",
                      Patterns::Selection(
                        "Chebyshev|symmetric block Gauss-Seidel"),
                      "Trilinos ML smoother on every level but the "
                      "coarsest. Measured on 3D SSNV187 (nu = 0.499, Q1, "
                      "rigid motions), CG iterations per Newton solve: "
                      "14 739 DoFs: Chebyshev 97 (2 sweeps), 67 (4), 57 "
                      "(6); symmetric block Gauss-Seidel (node blocks) 63 "
                      "(2), 54 (3), 47 (4). 107 811 DoFs: Chebyshev 155 "
                      "(2), symmetric block Gauss-Seidel 77 (4). A "
                      "Gauss-Seidel sweep costs more than a Chebyshev "
                      "one.");
    prm.declare_entry("AMG package",
                      "ML",
                      Patterns::Selection("ML|GAMG|BoomerAMG"),
                      "Whose algebraic multigrid preconditions CG (Type = "
                      "cg-amg). ML: Trilinos ML's smoothed aggregation with "
                      "the entries above and the kept hierarchy. GAMG: "
                      "PETSc's smoothed aggregation with the same near null "
                      "space and the DoFs per node as block size. "
                      "BoomerAMG: hypre's classical AMG with that block "
                      "size. GAMG and BoomerAMG copy the matrix into PETSc; "
                      "'Keep preconditioner' applies to all three. PETSc's "
                      "options (PETSC_OPTIONS: -pc_gamg_..., "
                      "-pc_hypre_boomeramg_...) adjust GAMG and BoomerAMG.");
    prm.declare_entry("AMG near null space",
                      "rigid motions",
                      Patterns::Selection("rigid motions|translations"),
                      "The near null space ML's smoothed aggregation "
                      "preserves on every level. rigid motions: the dim "
                      "translations and the rotations (1 in 2D, 3 in 3D) "
                      "about the centre of the mesh, evaluated at the DoF "
                      "support points of the reference configuration. "
                      "translations: the translations only.");
    prm.declare_entry("Keep preconditioner",
                      "true",
                      Patterns::Bool(),
                      "CG + AMG: scale the matrix to a unit diagonal and "
                      "keep the AMG hierarchy of the scaled matrix from one "
                      "solve to the next (Newton or interior point "
                      "iterations, load steps), rebuilding it when the "
                      "sparsity pattern changes, when a solve fails, or "
                      "after a solve that took more than 1.5 times (plus 5) "
                      "the CG iterations of the one right after the last "
                      "build. Scaled, the rows of the contact nodes, whose "
                      "barrier or penalty terms change by orders of "
                      "magnitude between iterations, change no more than "
                      "the others. Measured on prm/hertz_sphere.prm "
                      "(interior point method): one build for the whole "
                      "run at 28 071 DoFs, two per rank at 169 773; "
                      "doc/performance.md has the times. Applies to every "
                      "'AMG package'; hypre's BoomerAMG does worse on the "
                      "scaled matrix (false: 24.2 s against 42.2 s at 1.7e5 "
                      "DoFs). false: a new hierarchy for every new matrix "
                      "(with ML the interior point method then skips its "
                      "active-set polish).");
    prm.declare_entry("Fall back to direct",
                      "true",
                      Patterns::Bool(),
                      "If an iterative solve does not converge, solve the "
                      "same system with the direct solver.");
  }

  void
  LinearSolver::Parameters::parse_parameters(ParameterHandler &prm)
  {
    const std::string t = prm.get("Type");
    type = (t == "direct" ? Type::direct :
            t == "cg-amg" ? Type::cg_amg :
                            Type::minres_amg);
    direct_solver         = prm.get("Direct solver");
    const unsigned int ranks = Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
    if (direct_solver == "auto")
      direct_solver = "PETSc_Mumps";
    else if (direct_solver == "PETSc_Cholmod" && ranks > 1)
      throw InputError("Solver > Linear solver > Direct solver",
                       "PETSc_Cholmod runs on one MPI rank only; this run "
                       "has " + std::to_string(ranks) +
                         " ranks: use PETSc_Mumps, Amesos_Mumps, Amesos_Klu "
                         "or auto");
    direct_memory_limit = prm.get_integer("Direct solver memory limit");
    const std::string ordering = prm.get("MUMPS ordering");
    mumps_ordering             = 7; // auto: MUMPS' own choice
    for (const auto &[name, code] : mumps_orderings)
      if (ordering == name)
        mumps_ordering = code;
    relative_tolerance    = prm.get_double("Relative tolerance");
    max_iterations        = prm.get_integer("Maximum iterations");
    forcing     = prm.get("Forcing term") == "Eisenstat-Walker" ?
                    Forcing::eisenstat_walker :
                    Forcing::fixed;
    max_forcing = prm.get_double("Maximum forcing term");
    if (forcing == Forcing::eisenstat_walker && max_forcing < relative_tolerance)
      throw InputError("Solver > Linear solver > Maximum forcing term",
                       "must be at least 'Relative tolerance' (" +
                         prm.get("Relative tolerance") + ")");
    aggregation_threshold = prm.get_double("AMG aggregation threshold");
    smoother_sweeps       = prm.get_integer("AMG smoother sweeps");
    amg_coarse_size       = prm.get_integer("AMG coarse size");
    smoother              = prm.get("AMG smoother");
    fallback_to_direct    = prm.get_bool("Fall back to direct");
    keep_preconditioner   = prm.get_bool("Keep preconditioner");
    {
      const std::string package = prm.get("AMG package");
      amg_package = package == "GAMG"      ? AmgPackage::gamg :
                    package == "BoomerAMG" ? AmgPackage::boomeramg :
                                             AmgPackage::ml;
      if (amg_package != AmgPackage::ml && type != Type::cg_amg)
        throw InputError("Solver > Linear solver > AMG package",
                         package + " preconditions CG only: set Type = cg-amg");
    }
    null_space = (prm.get("AMG near null space") == "translations" ?
                    NullSpace::translations :
                    NullSpace::rigid_motions);
  }

  std::string
  LinearSolver::Parameters::name() const
  {
    if (type == Type::direct)
      return "direct (" + direct_solver + ")";
    return std::string(type == Type::cg_amg ? "CG" : "MINRES") + " + AMG (" +
           (amg_package == AmgPackage::gamg      ? "PETSc GAMG" :
            amg_package == AmgPackage::boomeramg ? "hypre BoomerAMG" :
                                                   "Trilinos ML") +
           ")" +
           (forcing == Forcing::eisenstat_walker ? ", Eisenstat-Walker forcing" : "");
  }

  double
  LinearSolver::forcing_term(const double residual,
                             const double previous_residual,
                             const double previous_forcing,
                             const double tolerance) const
  {
    const double floor = parameters.relative_tolerance;
    if (!is_iterative() ||
        parameters.forcing != Parameters::Forcing::eisenstat_walker)
      return floor;
    const double eta_max = parameters.max_forcing;
    constexpr double gamma = 0.9;
    double eta = eta_max;
    if (previous_residual > 0.)
      {
        const double ratio = residual / previous_residual;
        eta = gamma * ratio * ratio;
        const double kept = gamma * previous_forcing * previous_forcing;
        if (kept > 0.1)
          eta = std::max(eta, kept);
        eta = std::min(eta, eta_max);
      }
    if (residual > 0.)
      eta = std::min(eta_max, std::max(eta, 0.5 * tolerance / residual));
    if (!std::isfinite(eta))
      eta = eta_max;
    return std::max(eta, floor);
  }

  LinearSolver::LinearSolver(const Parameters &parameters)
    : parameters(parameters)
  {}

  LinearSolver::~LinearSolver() = default;

  void
  LinearSolver::set_near_null_space(NearNullSpace modes)
  {
    null_space = std::move(modes);
  }

  void
  LinearSolver::clear()
  {
    forget_analysis();
    amg.preconditioner.reset();
    amg.petsc.reset();
    amg.matrix = nullptr;
  }

  unsigned int
  LinearSolver::n_symbolic_factorizations() const
  {
    return direct.n_symbolic +
           (direct.petsc ? direct.petsc->n_symbolic_factorizations() : 0);
  }

  std::string
  LinearSolver::ordering_used() const
  {
    const int used = direct.petsc ? direct.petsc->ordering_used() : -1;
    for (const auto &[name, code] : mumps_orderings)
      if (used == code)
        return name;
    return "";
  }

  int
  LinearSolver::ordering_block() const
  {
    return direct.petsc ? direct.petsc->ordering_block() : -1;
  }

  unsigned int
  LinearSolver::n_numeric_factorizations() const
  {
    return direct.n_numeric +
           (direct.petsc ? direct.petsc->n_numeric_factorizations() : 0);
  }

  void
  LinearSolver::forget_analysis() const
  {
    if (direct.petsc)
      direct.petsc->clear();
    direct.solver.reset();
    direct.problem.reset();
    direct.matrix.reset();
    direct.pattern_hash = 0;
    direct.factorized   = false;
  }

  bool
  LinearSolver::solve_petsc(const MatrixType &H,
                            VectorType       &x,
                            const VectorType &b,
                            std::string      &message) const
  {
    if (!direct.petsc)
      direct.petsc = std::make_unique<PETScDirectSolver>(
        parameters.direct_solver == "PETSc_Cholmod" ?
          PETScDirectSolver::Package::cholmod :
          PETScDirectSolver::Package::mumps,
        parameters.mumps_ordering,
        parameters.direct_memory_limit);
    const bool solved = direct.petsc->solve(
      H.trilinos_matrix(),
      x.trilinos_vector(),
      static_cast<const Epetra_MultiVector &>(b.trilinos_vector()),
      message);
    last_negative_pivots = direct.petsc->negative_pivots();
    return solved;
  }

  bool
  LinearSolver::solve_direct(const MatrixType &H,
                             VectorType       &x,
                             const VectorType &b,
                             std::string      &message) const
  {
    if (parameters.direct_solver.rfind("PETSc_", 0) == 0)
      {
        if (!solve_petsc(H, x, b, message))
          return false;
      }
    else if (!solve_amesos(H, x, b, message))
      return false;
    // Every rank must take the same decision: the callers branch into
    // collective operations on it.
    bool finite = true;
    for (const auto i : x.locally_owned_elements())
      finite = finite && std::isfinite(x[i]);
    if (Utilities::MPI::min(finite ? 1 : 0, x.get_mpi_communicator()) == 0)
      {
        message = "direct solver returned non-finite values (singular "
                  "Hessian: is the body held against rigid motion?)";
        return false;
      }
    return true;
  }

  bool
  LinearSolver::solve_amesos(const MatrixType &H,
                             VectorType       &x,
                             const VectorType &b,
                             std::string      &message) const
  {
    // Amesos directly rather than through TrilinosWrappers::SolverDirect,
    // which passes no parameters to the solver and redoes the symbolic
    // analysis at every solve. MUMPS' automatic ordering (ICNTL(7) = 7)
    // picks SCOTCH for larger matrices, whose choices differ from run to
    // run, so that two runs of one scene drift apart at round-off level
    // (7330 DoFs: from the 5th Newton iteration) and may take different
    // load steps ('MUMPS ordering').
    const MPI_Comm          comm = H.get_mpi_communicator();
    const Epetra_CrsMatrix &A    = H.trilinos_matrix();
    try
      {
        // The symbolic analysis (ordering, elimination tree) depends on the
        // pattern only: keep it while the pattern is the same on every
        // rank. Newton's diagonal shifts and new values need only a new
        // numeric factorisation. Amesos keeps a pointer to the matrix (and
        // uses it even in its destructor), so it gets a copy owned here:
        // the caller's matrix may be rebuilt or freed at any time.
        const std::size_t hash  = sparsity_pattern_hash(A);
        const bool        same  = direct.solver && direct.pattern_hash == hash;
        const bool        reuse = Utilities::MPI::min(same ? 1 : 0, comm) == 1;
        bool              same_values = reuse && direct.factorized;
        if (!reuse)
          {
            forget_analysis();
            direct.matrix  = std::make_unique<Epetra_CrsMatrix>(A);
            direct.problem = std::make_unique<Epetra_LinearProblem>(
              direct.matrix.get(),
              &x.trilinos_vector(),
              const_cast<Epetra_MultiVector *>(
                static_cast<const Epetra_MultiVector *>(&b.trilinos_vector())));
            Amesos factory;
            direct.solver.reset(
              factory.Create(parameters.direct_solver.c_str(), *direct.problem));
            if (!direct.solver)
              {
                forget_analysis();
                message = "direct solver " + parameters.direct_solver +
                          " is not available in this Trilinos";
                return false;
              }
            Teuchos::ParameterList list;
            list.sublist("mumps").set("ICNTL(7)", parameters.mumps_ordering);
            direct.solver->SetParameters(list);
            const int error = direct.solver->SymbolicFactorization();
            if (error != 0)
              {
                forget_analysis();
                message = "direct solver " + parameters.direct_solver +
                          ": symbolic analysis failed with Amesos error " +
                          std::to_string(error);
                return false;
              }
            direct.pattern_hash = hash;
            ++direct.n_symbolic;
          }
        else
          {
            // The same pattern, entry by entry (the hash runs over the
            // entries in their stored order): copy the values.
            for (int r = 0; r < A.NumMyRows(); ++r)
              {
                int     n = 0, n_copy = 0;
                double *values = nullptr, *copy = nullptr;
                A.ExtractMyRowView(r, n, values);
                direct.matrix->ExtractMyRowView(r, n_copy, copy);
                AssertThrow(n == n_copy, ExcInternalError());
                if (same_values && !std::equal(values, values + n, copy))
                  same_values = false;
                std::copy(values, values + n, copy);
              }
            direct.problem->SetLHS(&x.trilinos_vector());
            direct.problem->SetRHS(const_cast<Epetra_MultiVector *>(
              static_cast<const Epetra_MultiVector *>(&b.trilinos_vector())));
          }
        // The same values as the last factorisation (a second right-hand
        // side for one matrix, as the interior point method's corrector):
        // solve with it again.
        int error = 0;
        if (Utilities::MPI::min(same_values ? 1 : 0, comm) == 0)
          {
            direct.factorized = false;
            error             = direct.solver->NumericFactorization();
            ++direct.n_numeric;
            direct.factorized = (error == 0);
          }
        if (error == 0)
          error = direct.solver->Solve();
        if (error != 0)
          {
            // A failed factorisation may leave the solver in any state:
            // analyse again next time.
            forget_analysis();
            message = "direct solver " + parameters.direct_solver +
                      " failed with Amesos error " + std::to_string(error);
            return false;
          }
      }
    catch (const std::exception &e)
      {
        forget_analysis();
        message = std::string("direct solver failed: ") + e.what();
        return false;
      }
    return true;
  }

  unsigned int
  LinearSolver::n_amg_modes() const
  {
    return parameters.null_space == Parameters::NullSpace::rigid_motions ?
             null_space.modes.size() :
             std::min<std::size_t>(null_space.n_translations, null_space.modes.size());
  }

  void
  LinearSolver::amg_parameters(const MatrixType                    &H,
                               Teuchos::ParameterList              &list,
                               std::unique_ptr<Epetra_MultiVector> &modes) const
  {
    TrilinosWrappers::PreconditionAMG::AdditionalData data;
    data.elliptic              = true;
    data.higher_order_elements = null_space.higher_order;
    data.smoother_sweeps       = parameters.smoother_sweeps;
    data.aggregation_threshold = parameters.aggregation_threshold;
    data.smoother_type         = parameters.smoother.c_str();
    // deal.II's defaults for smoothed aggregation, without a null space:
    // it takes boolean masks only, which cannot express rotations.
    data.set_parameters(list, modes, H);
    // 0: a small coarse level where each aggregate carries the six rigid
    // motions of 3D (a nearly dense factor), deal.II's default otherwise.
    const unsigned int coarse_size = parameters.amg_coarse_size > 0 ? parameters.amg_coarse_size :
                                     n_amg_modes() >= 6             ? 250 :
                                                                      2000;
    list.set("coarse: max size", static_cast<int>(coarse_size));
    // ML's default, Uncoupled-MIS, aggregates across the ranks (MIS) once
    // a level has few rows per rank, and its check of the node blocks then
    // failed on the two-body couplings' ghost columns and ended the process
    // (tests/two_body_cg_amg). Uncoupled on every level: the same CG
    // iterations and times on the sphere at 27 882 and 168 597 DoFs.
    list.set("aggregation: type", std::string("Uncoupled"));

    const Epetra_Map  &map = H.trilinos_matrix().OperatorDomainMap();
    const unsigned int n_modes = n_amg_modes();
    if (n_modes == 0)
      return;
    AssertThrow(null_space.owned.n_elements() ==
                  static_cast<types::global_dof_index>(map.NumMyElements()),
                ExcMessage("The near null space does not match the matrix."));
    modes = std::make_unique<Epetra_MultiVector>(map, n_modes);
    for (int row = 0; row < map.NumMyElements(); ++row)
      {
        const auto k = null_space.owned.index_within_set(map.GID64(row));
        for (unsigned int m = 0; m < n_modes; ++m)
          (*modes)[m][row] = null_space.modes[m][k];
      }
    list.set("null space: type", "pre-computed");
    list.set("null space: dimension", static_cast<int>(n_modes));
    list.set("null space: vectors", modes->Values());
    // Aggregate whole nodes: the rotations are then resolved on every
    // aggregate (ML needs at least as many DoFs per aggregate as modes).
    if (null_space.dofs_per_node > 1)
      list.set("PDE equations", static_cast<int>(null_space.dofs_per_node));
    // ML's block Gauss-Seidel takes the finest level's block size (the
    // DoFs per node) on every level, but a coarse level has one block of
    // n_modes unknowns per aggregate: in 2D 3 modes against 2 DoFs per
    // node, and a level with an odd number of aggregates stops ML ("BGS
    // requires an integer no. of blocks"). The coarse levels then smooth
    // point by point.
    if (parameters.smoother == "symmetric block Gauss-Seidel" &&
        null_space.dofs_per_node > 1 && n_modes % null_space.dofs_per_node != 0)
      for (int level = 1; level < 10; ++level)
        list.set("smoother: type (level " + std::to_string(level) + ")",
                 std::string("symmetric Gauss-Seidel"));
  }

  namespace
  {
    /// One V-cycle of a PETScAMG on deal.II's Trilinos vectors.
    struct PETScVCycle
    {
      const PETScAMG &amg;
      void
      vmult(VectorType &dst, const VectorType &src) const
      {
        amg.vmult(*dst.trilinos_vector()(0), *src.trilinos_vector()(0));
      }
    };

    PETScAMG::Package
    petsc_package(const LinearSolver::Parameters::AmgPackage package)
    {
      return package == LinearSolver::Parameters::AmgPackage::gamg ?
               PETScAMG::Package::gamg :
               PETScAMG::Package::boomeramg;
    }

    /// A hash of the bits of the locally owned rows' values of @p A, the
    /// same on every rank.
    std::size_t
    values_hash(const Epetra_CrsMatrix &A, const MPI_Comm comm)
    {
      std::uint64_t h = 1469598103934665603ull;
      for (int r = 0; r < A.NumMyRows(); ++r)
        {
          int     n      = 0;
          double *values = nullptr;
          A.ExtractMyRowView(r, n, values);
          for (int k = 0; k < n; ++k)
            {
              std::uint64_t bits;
              std::memcpy(&bits, values + k, sizeof(bits));
              h = (h ^ bits) * 1099511628211ull;
            }
        }
      // Different on any rank: different everywhere.
      const std::uint64_t lo = Utilities::MPI::min(h, comm);
      const std::uint64_t hi = Utilities::MPI::max(h, comm);
      return static_cast<std::size_t>(lo * 31 + hi);
    }
  } // namespace

  bool
  LinearSolver::uses_ml() const
  {
    return parameters.type != Parameters::Type::cg_amg ||
           parameters.amg_package == Parameters::AmgPackage::ml;
  }

  void
  LinearSolver::build_amg(const MatrixType &H, const Epetra_Vector *s_inv) const
  {
    amg.preconditioner.reset();
    amg.petsc.reset();
    if (uses_ml())
      {
        Teuchos::ParameterList              list;
        std::unique_ptr<Epetra_MultiVector> modes;
        amg_parameters(H, list, modes);
        if (modes && s_inv)
          for (int m = 0; m < modes->NumVectors(); ++m)
            for (int i = 0; i < s_inv->MyLength(); ++i)
              (*modes)[m][i] *= (*s_inv)[i];
        amg.preconditioner = std::make_unique<TrilinosWrappers::PreconditionAMG>();
        amg.preconditioner->initialize(H, list);
      }
    else
      {
        // PETSc's copy of H reads the modes in the order of H's rows (GAMG
        // uses them; BoomerAMG takes the block size only).
        const unsigned int               n_modes = n_amg_modes();
        std::vector<std::vector<double>> scaled;
        if (s_inv)
          {
            scaled.resize(n_modes);
            for (unsigned int m = 0; m < n_modes; ++m)
              {
                scaled[m].resize(s_inv->MyLength());
                for (int i = 0; i < s_inv->MyLength(); ++i)
                  scaled[m][i] =
                    null_space.modes[m][null_space.owned.index_within_set(s_inv->Map().GID64(i))] *
                    (*s_inv)[i];
              }
          }
        amg.petsc = std::make_unique<PETScAMG>(petsc_package(parameters.amg_package));
        amg.petsc->initialize(H.trilinos_matrix(), s_inv ? scaled : null_space.modes, n_modes,
                              null_space.dofs_per_node);
      }
    ++amg.n_builds;
  }

  void
  LinearSolver::prepare_amg(const MatrixType &H) const
  {
    const Epetra_CrsMatrix &A       = H.trilinos_matrix();
    const MPI_Comm          comm    = H.get_mpi_communicator();
    const std::size_t       pattern = sparsity_pattern_hash(A);
    const std::size_t       values  = values_hash(A, comm);
    // The hierarchy refers to the matrix object it was built from.
    const bool same_here = (uses_ml() ? !!amg.preconditioner : !!amg.petsc) && !amg.scaled &&
                           amg.matrix == &A && amg.pattern_hash == pattern;
    const bool same_pattern = Utilities::MPI::min(same_here ? 1 : 0, comm) == 1;
    // Only for the very matrix it was built from: a hierarchy kept for
    // the next Newton matrices (new values) made CG take 20 to 40 times
    // the iterations on the interior point method's matrices, whose
    // contact rows change by orders of magnitude (ML's Chebyshev smoother
    // keeps the old largest eigenvalue).
    // The interior point method's predictor and corrector share one.
    if (same_pattern && amg.values_hash == values)
      return;

    build_amg(H, nullptr);
    amg.matrix       = &A;
    amg.pattern_hash = pattern;
    amg.values_hash  = values;
    amg.scaled       = false;
  }

  namespace
  {
    /// The operator w o A o w (w a diagonal, as a vector): vmult(dst, src)
    /// is w .* (A (w .* src)).
    template <class Operator>
    struct Sandwiched
    {
      const Operator    &A;
      const VectorType  &w;
      mutable VectorType tmp;
      void
      vmult(VectorType &dst, const VectorType &src) const
      {
        tmp = src;
        tmp.scale(w);
        A.vmult(dst, tmp);
        dst.scale(w);
      }
    };
  } // namespace

  void
  LinearSolver::solve_kept_amg(
    const MatrixType &H,
    VectorType       &x,
    const VectorType &b,
    SolverControl    &control,
    const std::function<SolverControl::State(const unsigned int,
                                             const double,
                                             const VectorType &)> &check,
    unsigned int &wasted) const
  {
    // The scaling S = diag(H)^-1/2 and its inverse, as vectors of b's
    // layout (the matrix's locally owned rows): CG scales with them, and
    // the matrix with their Epetra vectors.
    Epetra_CrsMatrix &A = const_cast<Epetra_CrsMatrix &>(H.trilinos_matrix());
    VectorType         w(b), w_inv(b);
    Epetra_Vector     &s     = *w.trilinos_vector()(0);
    Epetra_Vector     &s_inv = *w_inv.trilinos_vector()(0);
    A.ExtractDiagonalCopy(s);
    for (int i = 0; i < s.MyLength(); ++i)
      {
        const double d = std::abs(s[i]);
        s[i]           = d > 0. ? 1. / std::sqrt(d) : 1.;
        s_inv[i]       = 1. / s[i];
      }
    // H is H_s = S H S while this object lives, and H again after (also
    // when CG throws).
    struct Scaled
    {
      Epetra_CrsMatrix   &A;
      const Epetra_Vector &s_inv;
      Scaled(Epetra_CrsMatrix &A, const Epetra_Vector &s, const Epetra_Vector &s_inv)
        : A(A)
        , s_inv(s_inv)
      {
        A.LeftScale(s);
        A.RightScale(s);
      }
      ~Scaled()
      {
        A.LeftScale(s_inv);
        A.RightScale(s_inv);
      }
    } scaled(A, s, s_inv);

    const std::size_t pattern = sparsity_pattern_hash(A);
    const bool        ml      = uses_ml();
    const bool same_here = (ml ? !!amg.preconditioner : !!amg.petsc) && amg.scaled &&
                           amg.matrix == &A && amg.pattern_hash == pattern && !amg.rebuild;
    bool keep = Utilities::MPI::min(same_here ? 1 : 0, H.get_mpi_communicator()) == 1;
    const auto build = [&]() {
      // The near null space of H_s is S^-1 times that of H.
      build_amg(H, &s_inv);
      amg.matrix       = &A;
      amg.pattern_hash = pattern;
      amg.values_hash  = 0;
      amg.scaled       = true;
      amg.rebuild      = false;
    };
    if (!keep)
      build();

    // H = S^-1 H_s S^-1 and the preconditioner S AMG(H_s)^-1 S: CG's
    // iterates are S^-1 times those of CG on H_s, its residuals H's own.
    const Sandwiched<MatrixType> op{H, w_inv, VectorType(b)};
    // A failure of the caller's check (not of the hierarchy) is rethrown.
    bool       check_failed = false;
    const auto checked      = [&](const unsigned int i, const double r, const VectorType &v) {
      const SolverControl::State state = check(i, r, v);
      check_failed = check_failed || state == SolverControl::failure;
      return state;
    };
    const auto run_cg = [&]() {
      SolverCG<VectorType> cg(control);
      cg.connect(checked);
      if (ml)
        {
          const Sandwiched<TrilinosWrappers::PreconditionAMG> preconditioner{
            *amg.preconditioner, w, VectorType(b)};
          cg.solve(op, x, b, preconditioner);
        }
      else
        {
          const Sandwiched<PETScVCycle> preconditioner{PETScVCycle{*amg.petsc}, w,
                                                       VectorType(b)};
          cg.solve(op, x, b, preconditioner);
        }
    };
    wasted = 0;
    if (keep)
      {
        // A kept hierarchy that no longer fits the matrix (the active-set
        // polish's pinned nodes, a new contact zone) would let CG run to
        // the iteration limit: it gets 3 times (plus 20) the iterations
        // of the solve after its build, and is rebuilt for a second try.
        const unsigned int limit = control.max_steps();
        const unsigned int cap   = std::min(limit, 3 * amg.base_iterations + 20);
        control.set_max_steps(cap);
        try
          {
            run_cg();
          }
        catch (...)
          {
            control.set_max_steps(limit);
            if (check_failed || cap == limit || control.last_step() < cap)
              {
                amg.rebuild = true;
                throw;
              }
            wasted = control.last_step();
            keep   = false;
            x      = 0.;
          }
        control.set_max_steps(limit);
        if (keep)
          {
            if (control.last_step() > 1.5 * amg.base_iterations + 5)
              amg.rebuild = true;
            return;
          }
        build();
      }

    try
      {
        run_cg();
      }
    catch (...)
      {
        amg.rebuild = true;
        throw;
      }
    amg.base_iterations = control.last_step();
  }

  bool
  LinearSolver::solve(const MatrixType &H,
                      VectorType       &x,
                      const VectorType &b,
                      Info             &info,
                      std::string      &message,
                      const double      relative_tolerance,
                      const double      max_solution) const
  {
    info                 = Info();
    x                    = 0.;
    last_negative_pivots = -1;
    if (parameters.type == Parameters::Type::direct)
      return solve_direct(H, x, b, message);

    info.relative_tolerance = relative_tolerance > 0. ?
                                relative_tolerance :
                                parameters.relative_tolerance;
    SolverControl control(parameters.max_iterations,
                          info.relative_tolerance * b.l2_norm());
    unsigned int  wasted = 0; // CG iterations with a kept hierarchy that failed
    try
      {
        // Stops the solver at an iterate beyond max_solution (the same
        // decision on every rank: the norm is global).
        const auto bounded = [&](const unsigned int, const double, const VectorType &iterate) {
          if (max_solution > 0. && iterate.linfty_norm() > max_solution)
            {
              info.singular = true;
              return SolverControl::failure;
            }
          return SolverControl::success;
        };
        if (parameters.type == Parameters::Type::cg_amg &&
            parameters.keep_preconditioner)
          solve_kept_amg(H, x, b, control, bounded, wasted);
        else if (parameters.type == Parameters::Type::cg_amg &&
                 parameters.amg_package != Parameters::AmgPackage::ml)
          {
            prepare_amg(H);
            SolverCG<VectorType> cg(control);
            cg.connect(bounded);
            cg.solve(H, x, b, PETScVCycle{*amg.petsc});
          }
        else if (parameters.type == Parameters::Type::cg_amg)
          {
            prepare_amg(H);
            SolverCG<VectorType> cg(control);
            cg.connect(bounded);
            cg.solve(H, x, b, *amg.preconditioner);
          }
        else
          {
            prepare_amg(H);
            SolverMinRes<VectorType> minres(control);
            minres.connect(bounded);
            minres.solve(H, x, b, *amg.preconditioner);
          }
        info.iterations = wasted + control.last_step();
        return true;
      }
    catch (const std::exception &e)
      {
        info.iterations = wasted + control.last_step();
        if (info.singular)
          {
            message = parameters.name() + " stopped after " +
                      std::to_string(info.iterations) +
                      " iterations at an iterate larger than " +
                      std::to_string(max_solution) +
                      ": the matrix is (nearly) singular";
            return false;
          }
        message = parameters.name() + " did not converge in " +
                  std::to_string(info.iterations) + " iterations";
        if (!parameters.fallback_to_direct)
          return false;
        info.used_fallback = true;
        x                  = 0.;
        std::string direct_message;
        if (solve_direct(H, x, b, direct_message))
          return true;
        message += "; " + direct_message;
        return false;
      }
  }
} // namespace Signorini
