#include <signorini/problem/energy_functional.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/grid/filtered_iterator.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>
#include <deal.II/meshworker/mesh_loop.h>

#include <Epetra_FEVector.h>

#include <algorithm>

namespace Signorini
{
  namespace
  {
    template <int dim>
    struct Scratch
    {
      Scratch(const Mapping<dim>       &mapping,
              const FiniteElement<dim> &fe,
              const bool                with_faces,
              const bool                with_body_force)
        : system_fe(fe)
        , fe_values(mapping,
                    fe.base_element(0),
                    QGauss<dim>(fe.degree + 1),
                    update_values | update_gradients | update_JxW_values |
                      (with_body_force ? update_quadrature_points :
                                         update_default))
        , fe_face_values(mapping,
                         fe,
                         QGauss<dim - 1>(fe.degree + 1),
                         with_faces ? (update_values | update_quadrature_points |
                                       update_JxW_values) :
                                      update_default)
        , with_faces(with_faces)
        , with_body_force(with_body_force)
      {
        // The element is FE_Q(p)^dim: shape function i is the scalar shape
        // function of node shape_node[i] in component shape_component[i].
        // The cell values are those of the scalar element (fe_values), whose
        // shape function a is node a's: the mapping transforms n/dim
        // gradients instead of n, and nothing is copied into the vector
        // element's shape functions.
        AssertThrow(fe.n_base_elements() == 1 &&
                      fe.element_multiplicity(0) == dim,
                    ExcMessage("the energy assembly needs a vector element "
                               "FE_Q(p)^dim"));
        const unsigned int n = fe.n_dofs_per_cell();
        shape_component.resize(n);
        shape_node.resize(n);
        for (unsigned int i = 0; i < n; ++i)
          {
            const auto ci      = fe.system_to_component_index(i);
            shape_component[i] = ci.first;
            shape_node[i]      = ci.second;
          }
        // Where entry (i, j) of the local Hessian is in the node blocks
        // Kt[p(c,d)][a][b] of the component pairs c <= d (see
        // hessian_kernel), mirrored for c > d and, in the diagonal pairs
        // c = d, for a > b.
        const unsigned int n_nodes = n / dim;
        const auto pair_index = [](const unsigned int c, const unsigned int d) {
          return c * dim - c * (c - 1) / 2 + (d - c);
        };
        block_entry.resize(n * n);
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = 0; j < n; ++j)
            {
              const unsigned int ci = shape_component[i];
              const unsigned int cj = shape_component[j];
              const unsigned int a  = shape_node[i];
              const unsigned int b  = shape_node[j];
              // the upper triangle (in the node pair) of a diagonal pair
              // block, else the block of c <= d
              const bool upper = ci < cj || (ci == cj && a <= b);
              block_entry[i * n + j] =
                upper ? (pair_index(ci, cj) * n_nodes + a) * n_nodes + b :
                        (pair_index(cj, ci) * n_nodes + b) * n_nodes + a;
            }
      }

      Scratch(const Scratch &other)
        : Scratch(other.fe_values.get_mapping(),
                  other.system_fe,
                  other.with_faces,
                  other.with_body_force)
      {}

      const FiniteElement<dim>         &system_fe;
      /// Values of the scalar base element on the cell.
      FEValues<dim>                     fe_values;
      FEFaceValues<dim>                 fe_face_values;
      bool                              with_faces;
      bool                              with_body_force;
      std::vector<Tensor<1, dim>>       values;
      std::vector<Vector<double>>       loads;
      std::vector<Tensor<1, dim>>       node_grads;
      std::vector<unsigned int>         shape_component;
      std::vector<unsigned int>         shape_node;
      std::vector<unsigned int>         block_entry;
      std::vector<double>               local_u;
      std::vector<double>               gT;
      std::vector<double>               AGt;
      std::vector<double>               Kt;
      std::vector<double>               f_int;
      std::vector<double>               f_ext;
    };

    struct Copy
    {
      Copy() = default;
      Copy(const Copy &) = default;

      /**
       * mesh_loop assigns its empty sample to the copy object before each
       * cell. The worker sizes and fills every buffer itself, so this
       * assignment resets the scalars only and keeps the buffers' storage
       * (no allocation per cell).
       */
      Copy &
      operator=(const Copy &)
      {
        reset();
        return *this;
      }

      FullMatrix<double>                   matrix;
      Vector<double>                       rhs;
      std::vector<types::global_dof_index> dofs;
      unsigned int                         cell_index    = 0;
      double                               strain_energy = 0.;
      double                               external_work = 0.;
      double                               force_sq      = 0.;
      double                               modulus_volume = 0.;
      double                               min_J = std::numeric_limits<double>::max();
      bool                                 admissible = true;
      bool                                 active     = false;

      void
      reset()
      {
        strain_energy = external_work = force_sq = modulus_volume = 0.;
        min_J      = std::numeric_limits<double>::max();
        admissible = true;
        active     = false;
      }
    };
    /**
     * Add JxW grad phi_i : A : grad phi_j to the node blocks s.Kt of the
     * component pairs c <= d: Kt[p(c,d)][a][b] += JxW sum_JL A[c][J][d][L]
     * g_a[J] g_b[L], with the scalar gradients g in s.gT[L][a]. N is the
     * number of nodes if known at compile time (Q1: 2^dim, so that the
     * loops unroll), else 0.
     */
    template <int dim, unsigned int N>
    inline __attribute__((always_inline)) void
    hessian_kernel(const Tensor<4, dim> &A,
                   const double          JxW,
                   const unsigned int    n_nodes,
                   const double *__restrict gT,
                   double *__restrict AGt,
                   double *__restrict Kt)
    {
      const unsigned int n    = (N > 0 ? N : n_nodes);
      unsigned int       pair = 0;
      for (unsigned int cc = 0; cc < dim; ++cc)
        for (unsigned int dd = cc; dd < dim; ++dd, ++pair)
          {
            double *const K = Kt + pair * n * n;
            // AG[L][a] = JxW sum_J A[c][J][d][L] g_a[J]
            for (unsigned int L = 0; L < dim; ++L)
              {
                double *const AGL = AGt + L * n;
                for (unsigned int a = 0; a < n; ++a)
                  AGL[a] = 0.;
                for (unsigned int JJ = 0; JJ < dim; ++JJ)
                  {
                    const double  w  = A[cc][JJ][dd][L] * JxW;
                    const double *gJ = gT + JJ * n;
                    for (unsigned int a = 0; a < n; ++a)
                      AGL[a] += w * gJ[a];
                  }
              }
            // K[a][b] += AG[L][a] g_b[L], L = 0, 1, (2) in turn: each entry
            // is loaded and stored once per quadrature point. A diagonal
            // pair (c = d) is symmetric in (a, b) (A[c][J][c][L] is
            // symmetric in J, L): its lower triangle is formed too (whole
            // rows vectorise; skipping it was measured slower) but not
            // used: Scratch::block_entry reads the upper one for both, so
            // that the local matrix is exactly symmetric.
            for (unsigned int a = 0; a < n; ++a)
              {
                double *Ka = K + a * n;
                for (unsigned int b = 0; b < n; ++b)
                  {
                    double k = Ka[b];
                    for (unsigned int L = 0; L < dim; ++L)
                      k += AGt[L * n + a] * gT[L * n + b];
                    Ka[b] = k;
                  }
              }
          }
    }

    // The same loops compiled for AVX (4 doubles per instruction; no FMA,
    // so every product and sum is rounded as in the default build and the
    // results are identical), chosen at run time where the processor has
    // it.
#if defined(__GNUC__) && defined(__x86_64__)
#  define SIGNORINI_AVX_KERNEL 1
    template <int dim, unsigned int N>
    __attribute__((target("avx"))) void
    hessian_kernel_avx(const Tensor<4, dim> &A,
                       const double          JxW,
                       const unsigned int    n_nodes,
                       const double         *gT,
                       double               *AGt,
                       double               *Kt)
    {
      hessian_kernel<dim, N>(A, JxW, n_nodes, gT, AGt, Kt);
    }
#endif

    template <int dim, unsigned int N>
    void
    accumulate_hessian(const Tensor<4, dim> &A,
                       const double          JxW,
                       Scratch<dim>         &s)
    {
      const unsigned int n_nodes = s.gT.size() / dim;
#ifdef SIGNORINI_AVX_KERNEL
      static const bool avx = __builtin_cpu_supports("avx");
      if (avx)
        {
          hessian_kernel_avx<dim, N>(A, JxW, n_nodes, s.gT.data(),
                                     s.AGt.data(), s.Kt.data());
          return;
        }
#endif
      hessian_kernel<dim, N>(A, JxW, n_nodes, s.gT.data(), s.AGt.data(),
                             s.Kt.data());
    }

    /**
     * Reads a cell's nodal values of the ghosted vector u. Locally owned
     * DoFs come straight from the vector's storage: deal.II's owned DoFs
     * are one contiguous range, stored contiguously (the vector's map is
     * sorted by global index), which the constructor checks; ghosts go
     * through the map.
     */
    class NodalValueReader
    {
    public:
      NodalValueReader(const VectorType &u, const IndexSet &owned)
        : u(u)
        , u_values(u.trilinos_vector()[0])
        , first_owned(owned.n_elements() > 0 ? *owned.begin() : 0)
        , n_owned(owned.n_elements())
      {
        const Epetra_BlockMap &u_map = u.trilinos_vector().Map();
        owned_offset =
          n_owned > 0 ? u_map.LID(static_cast<TrilinosWrappers::types::int_type>(
                          first_owned)) :
                        0;
        direct_read =
          n_owned > 0 && owned.is_contiguous() && owned_offset >= 0 &&
          u_map.LID(static_cast<TrilinosWrappers::types::int_type>(
            first_owned + n_owned - 1)) ==
            owned_offset + static_cast<int>(n_owned) - 1;
      }

      /// values[k] = u(dofs[k]).
      void
      read(const std::vector<types::global_dof_index> &dofs,
           std::vector<double>                        &values) const
      {
        for (unsigned int k = 0; k < dofs.size(); ++k)
          values[k] = direct_read && dofs[k] - first_owned < n_owned ?
                        u_values[owned_offset + (dofs[k] - first_owned)] :
                        u(dofs[k]);
      }

    private:
      const VectorType             &u;
      const double                 *u_values;
      const types::global_dof_index first_owned;
      const types::global_dof_index n_owned;
      int                           owned_offset;
      bool                          direct_read;
    };

    /**
     * The per-cell work of one evaluation: a cell's energy and its local
     * right-hand side and Hessian, and the work of the traction on its
     * boundary faces. Shared by mesh_loop's threads (it only reads its
     * members); its functions are defined here, in the energy's
     * translation unit, so that the compiler sees the whole cell loop.
     */
    template <int dim>
    struct CellAssembler
    {
      const std::map<types::material_id, const Material::Interface *> &materials;
      const BoundaryConditions<dim>                                    &bc;
      const VectorType                                                 &u;
      const NodalValueReader                                           &nodal_values;
      const FiniteElement<dim>                                         &fe;
      /// The traction and the body force (null if the scene has none).
      Function<dim>     *traction;
      Function<dim>     *body_force;
      const unsigned int dofs_per_cell;
      const bool         want_gradient;
      const bool         want_hessian;

      /// Evaluate the cell into @p c (c.admissible false if F is not
      /// admissible at one of its quadrature points).
      template <class CellIterator>
      void
      cell(const CellIterator &cell, Scratch<dim> &s, Copy &c) const
      {
        s.fe_values.reinit(
          static_cast<typename Triangulation<dim>::cell_iterator>(cell));
        c.reset(); // mesh_loop reuses one copy object per thread
        c.dofs.resize(dofs_per_cell);
        cell->get_dof_indices(c.dofs);
        c.cell_index = cell->active_cell_index();
        c.active     = true;
        if (want_gradient)
          c.rhs.reinit(dofs_per_cell);
        if (want_hessian)
          c.matrix.reinit(dofs_per_cell, dofs_per_cell);

        const auto material_it = materials.find(cell->material_id());
        AssertThrow(material_it != materials.end(),
                    ExcMessage("no material for material id " +
                               std::to_string(cell->material_id())));
        const Material::Interface &material = *material_it->second;

        prepare(s, c);
        if (!integrate(material, s, c))
          return;
        write_local_system(s, c);
      }

      /// Read the cell's nodal values, interpolate them and evaluate the
      /// body force at the quadrature points (if there is one), and size
      /// the buffers of the integration.
      void
      prepare(Scratch<dim> &s, const Copy &c) const
      {
        const unsigned int n_q     = s.fe_values.n_quadrature_points;
        const unsigned int n_nodes = dofs_per_cell / dim;
        s.node_grads.resize(n_nodes);
        s.local_u.resize(dofs_per_cell);
        nodal_values.read(c.dofs, s.local_u);
        if (bc.has_body_force())
          {
            s.values.assign(n_q, Tensor<1, dim>());
            for (unsigned int q = 0; q < n_q; ++q)
              for (unsigned int i = 0; i < dofs_per_cell; ++i)
                s.values[q][s.shape_component[i]] +=
                  s.local_u[i] * s.fe_values.shape_value(s.shape_node[i], q);
            s.loads.resize(n_q, Vector<double>(dim));
            body_force->vector_value_list(s.fe_values.get_quadrature_points(),
                                         s.loads);
          }
        // The Hessian is accumulated node block by node block over the
        // quadrature points, for the component pairs c <= d only (it is
        // symmetric): Kt[p(c,d)][a][b] = sum_q JxW sum_JL A[c][J][d][L]
        // g_a[J] g_b[L], with the scalar gradients g stored as gT[L][a] so
        // that the innermost loops run over contiguous nodes.
        constexpr unsigned int n_pairs = dim * (dim + 1) / 2;
        if (want_hessian)
          {
            s.gT.resize(dim * n_nodes);
            s.AGt.resize(dim * n_nodes);
            s.Kt.assign(n_pairs * n_nodes * n_nodes, 0.);
          }
      }

      /// The loop over the quadrature points: strain energy, work of the
      /// body force, internal and external forces (in s.f_int, s.f_ext)
      /// and the Hessian's node blocks (in s.Kt). False, with
      /// c.admissible false, at the first point where F is inadmissible.
      bool
      integrate(const Material::Interface &material, Scratch<dim> &s, Copy &c) const
      {
        const unsigned int      n_q     = s.fe_values.n_quadrature_points;
        const unsigned int      n_nodes = dofs_per_cell / dim;
        Material::Response<dim> response;
        std::vector<double>    &f_int = s.f_int;
        std::vector<double>    &f_ext = s.f_ext;
        f_int.assign(want_gradient ? dofs_per_cell : 0, 0.);
        f_ext.assign(want_gradient ? dofs_per_cell : 0, 0.);
        const double shear_modulus = std::abs(material.small_strain_lame().first);
        for (unsigned int q = 0; q < n_q; ++q)
          {
            // The scalar gradients once per node (not per shape function).
            for (unsigned int a = 0; a < n_nodes; ++a)
              s.node_grads[a] = s.fe_values.shape_grad(a, q);
            Tensor<2, dim> F = unit_symmetric_tensor<dim>();
            for (unsigned int i = 0; i < dofs_per_cell; ++i)
              F[s.shape_component[i]] += s.local_u[i] * s.node_grads[s.shape_node[i]];
            const double J = determinant(F);
            c.min_J        = std::min(c.min_J, J);
            if (!Material::evaluate(material, F, response, want_gradient) ||
                !(J > 0.))
              {
                c.admissible = false;
                return false;
              }
            const double JxW = s.fe_values.JxW(q);
            c.strain_energy += response.psi * JxW;
            c.modulus_volume += shear_modulus * JxW;

            if (bc.has_body_force())
              for (unsigned int d = 0; d < dim; ++d)
                c.external_work += s.loads[q][d] * s.values[q][d] * JxW;

            if (!want_gradient)
              continue;

            for (unsigned int i = 0; i < dofs_per_cell; ++i)
              {
                const unsigned int ci = s.shape_component[i];
                f_int[i] += (response.P[ci] * s.node_grads[s.shape_node[i]]) * JxW;
                if (bc.has_body_force())
                  f_ext[i] += s.loads[q][ci] *
                              s.fe_values.shape_value(s.shape_node[i], q) * JxW;
              }

            if (!want_hessian)
              continue;
            for (unsigned int a = 0; a < n_nodes; ++a)
              for (unsigned int L = 0; L < dim; ++L)
                s.gT[L * n_nodes + a] = s.node_grads[a][L];
            if (n_nodes == (1u << dim))
              accumulate_hessian<dim, (1u << dim)>(response.A, JxW, s);
            else
              accumulate_hessian<dim, 0>(response.A, JxW, s);
          }
        return true;
      }

      /// The local Hessian from its node blocks, the local right-hand
      /// side f_ext - f_int and the cell's share of the force scale.
      void
      write_local_system(const Scratch<dim> &s, Copy &c) const
      {
        if (want_hessian)
          for (unsigned int i = 0; i < dofs_per_cell; ++i)
            for (unsigned int j = 0; j < dofs_per_cell; ++j)
              c.matrix(i, j) = s.Kt[s.block_entry[i * dofs_per_cell + j]];

        if (want_gradient)
          for (unsigned int i = 0; i < dofs_per_cell; ++i)
            {
              c.rhs(i) = s.f_ext[i] - s.f_int[i];
              c.force_sq += s.f_int[i] * s.f_int[i] + s.f_ext[i] * s.f_ext[i];
            }
      }

      /// Add the work of the traction on the face @p face_no of the cell
      /// (if it is on a traction boundary) and its forces to @p c.
      template <class CellIterator>
      void
      traction_face(const CellIterator &cell,
                    const unsigned int  face_no,
                    Scratch<dim>       &s,
                    Copy               &c) const
      {
        if (!c.admissible ||
            !bc.is_traction_boundary(cell->face(face_no)->boundary_id()))
          return;
        const FEValuesExtractors::Vector displacement(0);
        s.fe_face_values.reinit(cell, face_no);
        const unsigned int n_q = s.fe_face_values.n_quadrature_points;
        s.values.resize(n_q);
        s.fe_face_values[displacement].get_function_values(u, s.values);
        s.loads.resize(n_q, Vector<double>(dim));
        traction->vector_value_list(s.fe_face_values.get_quadrature_points(),
                                   s.loads);
        std::vector<double> f_ext(dofs_per_cell, 0.);
        for (unsigned int q = 0; q < n_q; ++q)
          {
            const double JxW = s.fe_face_values.JxW(q);
            for (unsigned int d = 0; d < dim; ++d)
              c.external_work += s.loads[q][d] * s.values[q][d] * JxW;
            if (want_gradient)
              for (unsigned int i = 0; i < dofs_per_cell; ++i)
                {
                  const unsigned int ci = fe.system_to_component_index(i).first;
                  f_ext[i] += s.loads[q][ci] *
                              s.fe_face_values.shape_value(i, q) * JxW;
                }
          }
        if (want_gradient)
          for (unsigned int i = 0; i < dofs_per_cell; ++i)
            {
              c.rhs(i) += f_ext[i];
              c.force_sq += f_ext[i] * f_ext[i];
            }
      }
    };

    /// Sum the cells' contributions of all ranks into @p result (and the
    /// force scale from the ranks' @p force_sq); the state is inadmissible
    /// if it is on any rank or if the energy is not finite (collective).
    void
    sum_over_ranks(Evaluation &result, const double force_sq, const MPI_Comm comm)
    {
      result.strain_energy = Utilities::MPI::sum(result.strain_energy, comm);
      result.external_work = Utilities::MPI::sum(result.external_work, comm);
      result.min_J         = Utilities::MPI::min(result.min_J, comm);
      result.force_scale   = std::sqrt(Utilities::MPI::sum(force_sq, comm));
      result.round_off     = std::numeric_limits<double>::epsilon() *
                         Utilities::MPI::sum(result.round_off, comm);
      result.admissible =
        Utilities::MPI::min(result.admissible ? 1 : 0, comm) == 1;
      result.value = result.strain_energy - result.external_work;
      if (!std::isfinite(result.value))
        result.admissible = false;
    }

  } // namespace

  template <int dim>
  EnergyFunctional<dim>::EnergyFunctional(
    const DoFHandler<dim>                                           &dof_handler,
    const Mapping<dim>                                              &mapping,
    const std::map<types::material_id, const Material::Interface *> &materials,
    const BoundaryConditions<dim>                                    &bc)
    : dof_handler(dof_handler)
    , mapping(mapping)
    , materials(materials)
    , bc(bc)
  {}

  template <int dim>
  Evaluation
  EnergyFunctional<dim>::evaluate(const VectorType                &u,
                                  const double                     time,
                                  const AffineConstraints<double> &constraints,
                                  VectorType                      *rhs,
                                  MatrixType                      *hessian) const
  {
    const bool want_gradient = (rhs != nullptr);
    const bool want_hessian  = (hessian != nullptr);
    Assert(!want_hessian || want_gradient, ExcInternalError());
    if (rhs)
      *rhs = 0.;
    if (hessian)
      *hessian = 0.;

    const FiniteElement<dim> &fe            = dof_handler.get_fe();
    const unsigned int        dofs_per_cell = fe.n_dofs_per_cell();

    // Function objects are shared between threads: FunctionParser is
    // thread safe for evaluation, and set_time happens before the loop.
    Function<dim> *traction =
      bc.has_traction() ? &bc.traction_function() : nullptr;
    Function<dim> *body_force =
      bc.has_body_force() ? &bc.body_force_function() : nullptr;
    if (traction)
      traction->set_time(time);
    if (body_force)
      body_force->set_time(time);

    const NodalValueReader   nodal_values(u, dof_handler.locally_owned_dofs());
    const CellAssembler<dim> assembler{materials,
                                       bc,
                                       u,
                                       nodal_values,
                                       fe,
                                       traction,
                                       body_force,
                                       dofs_per_cell,
                                       want_gradient,
                                       want_hessian};
    auto cell_worker = [&](const auto &cell, Scratch<dim> &s, Copy &c) {
      assembler.cell(cell, s, c);
    };
    auto boundary_worker =
      [&](const auto &cell, const unsigned int face_no, Scratch<dim> &s, Copy &c) {
        assembler.traction_face(cell, face_no, s, c);
      };

    Evaluation    result;
    double        force_sq = 0.;
    scatter.begin(hessian, rhs, constraints, dof_handler.locally_owned_dofs(),
                  dof_handler.get_triangulation().n_active_cells(),
                  dofs_per_cell);
    auto       copier   = [&](const Copy &c) {
      if (!c.active)
        return;
      result.strain_energy += c.strain_energy;
      result.external_work += c.external_work;
      result.min_J = std::min(result.min_J, c.min_J);
      force_sq += c.force_sq;
      result.round_off += c.modulus_volume;
      if (!c.admissible)
        {
          result.admissible = false;
          return;
        }
      if (want_hessian)
        {
          if (!scatter.add(c.cell_index, c.dofs, c.matrix, c.rhs))
            constraints.distribute_local_to_global(c.matrix, c.rhs, c.dofs,
                                                   *hessian, *rhs);
        }
      else if (want_gradient)
        constraints.distribute_local_to_global(c.rhs, c.dofs, *rhs);
    };

    using namespace MeshWorker;
    AssembleFlags flags = assemble_own_cells;
    if (bc.has_traction())
      flags |= assemble_boundary_faces;
    Scratch<dim> scratch(mapping, fe, bc.has_traction(), bc.has_body_force());
    mesh_loop(filter_iterators(dof_handler.active_cell_iterators(),
                               IteratorFilters::LocallyOwnedCell()),
              cell_worker,
              copier,
              scratch,
              Copy(),
              flags,
              boundary_worker);
    sum_over_ranks(result, force_sq, dof_handler.get_communicator());

    if (rhs)
      rhs->compress(VectorOperation::add);
    if (hessian)
      hessian->compress(VectorOperation::add);
    return result;
  }

  template class EnergyFunctional<2>;
  template class EnergyFunctional<3>;
} // namespace Signorini
