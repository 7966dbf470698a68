#include <signorini/solvers/petsc_amg.h>
#include <signorini/solvers/petsc_interop.h>

#include <Epetra_CrsMatrix.h>
#include <Epetra_MpiComm.h>
#include <Epetra_Vector.h>
#include <petscksp.h>

#include <algorithm>
#include <stdexcept>

namespace Signorini
{

  struct PETScAMG::State
  {
    Mat matrix = nullptr;
    PC  pc     = nullptr;
    Vec x = nullptr, y = nullptr;
    ~State()
    {
      VecDestroy(&x);
      VecDestroy(&y);
      PCDestroy(&pc);
      MatDestroy(&matrix);
    }
  };

  PETScAMG::PETScAMG(const Package package)
    : package(package)
  {}

  PETScAMG::~PETScAMG() = default;

  std::string
  PETScAMG::name(const Package package)
  {
    return package == Package::gamg ? "PETSc GAMG" : "hypre BoomerAMG";
  }

  void
  PETScAMG::initialize(const Epetra_CrsMatrix                 &A,
                       const std::vector<std::vector<double>> &modes,
                       const unsigned int                      n_modes,
                       const unsigned int                      dofs_per_node)
  {
    state.reset();
    const auto *mpi = dynamic_cast<const Epetra_MpiComm *>(&A.Comm());
    if (mpi == nullptr)
      throw std::runtime_error("PETScAMG: the matrix has no MPI communicator");
    const MPI_Comm  comm = mpi->Comm();
    const int       n    = A.NumMyRows();
    const PetscInt  N    = static_cast<PetscInt>(A.NumGlobalRows64());
    if (first_owned_row(A, comm) < 0)
      throw std::runtime_error(name(package) + ": the rows a rank owns are not "
                                               "one contiguous range in rank order");

    // The rows in CSR form with global column indices.
    std::vector<PetscInt>    row_start(1, 0), columns;
    std::vector<PetscScalar> values;
    for (int r = 0; r < n; ++r)
      {
        int     m = 0;
        double *v = nullptr;
        int    *c = nullptr;
        A.ExtractMyRowView(r, m, v, c);
        for (int k = 0; k < m; ++k)
          {
            columns.push_back(static_cast<PetscInt>(A.ColMap().GID64(c[k])));
            values.push_back(v[k]);
          }
        row_start.push_back(static_cast<PetscInt>(columns.size()));
      }
    // PETSc wants the columns of each row sorted.
    for (int r = 0; r < n; ++r)
      {
        std::vector<std::pair<PetscInt, PetscScalar>> row;
        for (PetscInt k = row_start[r]; k < row_start[r + 1]; ++k)
          row.emplace_back(columns[k], values[k]);
        std::sort(row.begin(), row.end(),
                  [](const auto &a, const auto &b) { return a.first < b.first; });
        for (PetscInt k = row_start[r]; k < row_start[r + 1]; ++k)
          {
            columns[k] = row[k - row_start[r]].first;
            values[k]  = row[k - row_start[r]].second;
          }
      }

    auto s = std::make_unique<State>();
    check_petsc(MatCreate(comm, &s->matrix), "MatCreate");
    check_petsc(MatSetSizes(s->matrix, n, n, N, N), "MatSetSizes");
    const unsigned int block_size = dofs_per_node;
    if (on_all_ranks(comm, block_size > 1 && n % block_size == 0))
      check_petsc(MatSetBlockSize(s->matrix, static_cast<PetscInt>(block_size)),
                  "MatSetBlockSize");
    check_petsc(MatSetType(s->matrix, MATAIJ), "MatSetType");
    check_petsc(MatSeqAIJSetPreallocationCSR(s->matrix, row_start.data(),
                                             columns.data(), values.data()),
                "MatSeqAIJSetPreallocationCSR");
    check_petsc(MatMPIAIJSetPreallocationCSR(s->matrix, row_start.data(),
                                             columns.data(), values.data()),
                "MatMPIAIJSetPreallocationCSR");
    check_petsc(MatSetOption(s->matrix, MAT_SYMMETRIC, PETSC_TRUE), "MatSetOption");

    if (package == Package::gamg && n_modes > 0)
      {
        // GAMG asks for orthonormal vectors: modified Gram-Schmidt. The
        // vectors are destroyed also when a PETSc call throws.
        struct Vectors
        {
          std::vector<Vec> v;
          ~Vectors()
          {
            for (auto &x : v)
              VecDestroy(&x);
          }
        } owned{std::vector<Vec>(n_modes, nullptr)};
        std::vector<Vec> &vectors = owned.v;
        for (std::size_t m = 0; m < n_modes; ++m)
          {
            check_petsc(VecCreateMPI(comm, n, N, &vectors[m]), "VecCreateMPI");
            PetscScalar *a = nullptr;
            check_petsc(VecGetArray(vectors[m], &a), "VecGetArray");
            for (int r = 0; r < n; ++r)
              a[r] = modes[m][r];
            check_petsc(VecRestoreArray(vectors[m], &a), "VecRestoreArray");
            for (std::size_t k = 0; k < m; ++k)
              {
                PetscScalar dot = 0.;
                check_petsc(VecDot(vectors[m], vectors[k], &dot), "VecDot");
                check_petsc(VecAXPY(vectors[m], -dot, vectors[k]), "VecAXPY");
              }
            check_petsc(VecNormalize(vectors[m], nullptr), "VecNormalize");
          }
        MatNullSpace space = nullptr;
        check_petsc(MatNullSpaceCreate(comm, PETSC_FALSE, static_cast<PetscInt>(vectors.size()),
                                       vectors.data(), &space),
                    "MatNullSpaceCreate");
        const PetscErrorCode code = MatSetNearNullSpace(s->matrix, space);
        MatNullSpaceDestroy(&space);
        check_petsc(code, "MatSetNearNullSpace");
      }

    check_petsc(PCCreate(comm, &s->pc), "PCCreate");
    check_petsc(PCSetOperators(s->pc, s->matrix, s->matrix), "PCSetOperators");
    if (package == Package::gamg)
      check_petsc(PCSetType(s->pc, PCGAMG), "PCSetType");
    else
      {
        check_petsc(PCSetType(s->pc, PCHYPRE), "PCSetType");
        check_petsc(PCHYPRESetType(s->pc, "boomeramg"), "PCHYPRESetType");
        // For 3D elasticity, where PETSc's defaults (strength threshold
        // 0.25, Falgout coarsening, classical interpolation) build dense
        // coarse operators: 137.5 s against 25.2 s for the sphere at
        // 168 597 DoFs (doc/performance.md). Options given by the user
        // (PETSC_OPTIONS) take precedence.
        const std::pair<const char *, const char *> defaults[] = {
          {"-pc_hypre_boomeramg_strong_threshold", "0.5"},
          {"-pc_hypre_boomeramg_coarsen_type", "HMIS"},
          {"-pc_hypre_boomeramg_interp_type", "ext+i"},
          {"-pc_hypre_boomeramg_P_max", "4"},
          {"-pc_hypre_boomeramg_agg_nl", "1"}};
        for (const auto &[option, value] : defaults)
          {
            PetscBool set = PETSC_FALSE;
            check_petsc(PetscOptionsHasName(nullptr, nullptr, option, &set),
                        "PetscOptionsHasName");
            if (!set)
              check_petsc(PetscOptionsSetValue(nullptr, option, value),
                          "PetscOptionsSetValue");
          }
      }
    check_petsc(PCSetFromOptions(s->pc), "PCSetFromOptions");
    check_petsc(PCSetUp(s->pc), "PCSetUp");
    check_petsc(VecCreateMPIWithArray(comm, 1, n, N, nullptr, &s->x), "VecCreateMPIWithArray");
    check_petsc(VecCreateMPIWithArray(comm, 1, n, N, nullptr, &s->y), "VecCreateMPIWithArray");
    state = std::move(s);
  }

  void
  PETScAMG::vmult(Epetra_Vector &dst, const Epetra_Vector &src) const
  {
    double *in = nullptr, *out = nullptr;
    src.ExtractView(&in);
    dst.ExtractView(&out);
    check_petsc(VecPlaceArray(state->x, in), "VecPlaceArray");
    check_petsc(VecPlaceArray(state->y, out), "VecPlaceArray");
    const PetscErrorCode code = PCApply(state->pc, state->x, state->y);
    VecResetArray(state->x);
    VecResetArray(state->y);
    check_petsc(code, "PCApply");
  }
} // namespace Signorini
