#pragma once

#include <signorini/scene/boundary_conditions.h>
#include <signorini/contact/model.h>
#include <signorini/material/interface.h>
#include <signorini/parameters/scene_parameters.h>
#include <signorini/types.h>

#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/fe/mapping_q_cache.h>
#include <deal.II/lac/affine_constraints.h>

#include <map>
#include <memory>
#include <set>
#include <vector>

namespace Signorini
{
  using namespace dealii;

  /// The number of DoFs of @p dof_handler that lie on no locally owned
  /// cell of any rank (collective; deal.II 9.4 leaves such DoFs on some 3D
  /// meshes on several ranks).
  template <int dim>
  unsigned int
  n_dofs_on_no_cell(const DoFHandler<dim> &dof_handler);

  /**
   * The discretised scene: the mesh of the bodies and their materials, the
   * boundary conditions, the finite element and mapping, the DoFs, their
   * constraints, the Hessian's sparsity pattern (with the couplings the
   * contact model asks for), the state vectors, and refinement with
   * solution transfer. It knows no solver and no concrete contact model.
   */
  template <int dim>
  class Scene
  {
  public:
    /**
     * Build the mesh of @p parameters and check it against them (every
     * cell belongs to an active body, every referenced boundary id
     * exists); InputError on bad input. With a @p mesh_file (a
     * checkpoint's, written by save()), the coarse mesh of @p parameters
     * is refined as the saved one instead (on any number of ranks); call
     * load_attached() after setup_dofs().
     */
    Scene(const Parameters::Scene &parameters,
          MPI_Comm                 comm,
          const std::string       &mesh_file = "");

    /**
     * Write the mesh into @p mesh_file with, attached cell by cell, the
     * locally owned vectors @p vectors (the solution and the state the
     * Hessian's sparsity pattern was built at) and the fields of a
     * MeshState: @p dof_fields (locally owned vectors on the DoFs) and
     * @p cell_fields (one value per active cell, by active cell index),
     * these on the cells where one of them is not zero. Collective.
     */
    void
    save(const std::string                         &mesh_file,
         const std::vector<const VectorType *>     &vectors,
         const std::vector<const VectorType *>     &dof_fields,
         const std::vector<const Vector<double> *> &cell_fields) const;

    /// The bytes of the fields that save() attaches to the cells, on all
    /// ranks (collective).
    unsigned long long
    field_bytes(const std::vector<const VectorType *>     &dof_fields,
                const std::vector<const Vector<double> *> &cell_fields) const;

    /**
     * What save() attached to @p mesh_file, after setup_dofs(): into
     * @p vectors its @p n_vectors vectors, then its @p n_dof_fields fields
     * on the DoFs (locally owned, on this scene's DoFs), into
     * @p cell_fields its @p n_cell_fields fields on cells (valid on the
     * locally owned cells). With @p loaded_here this mesh is the one the
     * constructor loaded from @p mesh_file: the data comes with it, on any
     * number of ranks. Otherwise this mesh was built from the parameters
     * (the same cells as the saved mesh, on another partition when the
     * number of ranks differs): the saved mesh is loaded beside it and
     * the values are copied from its cells to the cells with the same
     * CellId. Collective; std::runtime_error, on every rank, if the two
     * meshes do not have the same cells.
     */
    void
    load_attached(const std::string           &mesh_file,
                  const bool                   loaded_here,
                  const unsigned int           n_vectors,
                  const unsigned int           n_dof_fields,
                  const unsigned int           n_cell_fields,
                  std::vector<VectorType>     &vectors,
                  std::vector<Vector<double>> &cell_fields);

    /**
     * Distribute the DoFs, build the constraints, (re)initialise the state
     * vectors to zero, set up @p contact (may be null) and build the
     * Hessian's sparsity pattern with its couplings.
     */
    void
    setup_dofs(Contact::Model<dim> *contact);

    /// Compute the mapping's support points of the current mesh.
    void
    cache_mapping();

    /// On several ranks: throw std::runtime_error with the reason if a DoF
    /// lies on no cell of any rank (deal.II 9.4's DoF distribution does
    /// that on some 3D meshes with hanging nodes; collective).
    void
    check_every_dof_on_a_cell() const;

    /// Rebuild the Hessian's sparsity pattern with the contact couplings
    /// found at the ghosted state @p u (collective).
    void
    build_matrix(const VectorType &u);

    /// Hanging nodes and the Dirichlet data at @p time (or zero data).
    AffineConstraints<double>
    boundary_constraints(const double time, const bool homogeneous) const;

    /// The DoFs of 'Fixed points' on this mesh into fixed_point_dofs
    /// (InputError if a point is no vertex of the mesh; collective; once
    /// per mesh, in setup_dofs()).
    void
    locate_fixed_points();

    /// Hanging nodes, and on Dirichlet DoFs the step from the current
    /// solution to the values at @p time.
    AffineConstraints<double>
    increment_constraints(const double time) const;

    /**
     * Refine and coarsen the flagged cells, transfer the solution, set up
     * the DoFs again (with @p contact) and give new Dirichlet nodes their
     * values at @p time.
     */
    void
    refine_and_transfer(Contact::Model<dim> *contact, const double time);

    /// Largest small-strain Young's modulus of the bodies' materials.
    double
    max_young_modulus() const;

    MPI_Comm                                   comm;
    parallel::distributed::Triangulation<dim> triangulation;
    std::unique_ptr<FESystem<dim>>             fe;
    /// The cells' MappingQ with its support points computed once per mesh
    /// (setup_dofs()): a curved boundary's manifold is then not asked for
    /// them again at every FEValues::reinit() of every evaluation.
    std::unique_ptr<MappingQCache<dim>>        mapping;
    DoFHandler<dim>                            dof_handler;
    IndexSet                                   locally_owned;
    IndexSet                                   locally_relevant;
    AffineConstraints<double>                  hanging_constraints;
    AffineConstraints<double>                  homogeneous_constraints;
    /// The locally relevant DoFs that 'Fixed points' hold at zero.
    std::vector<types::global_dof_index>       fixed_point_dofs;

    BoundaryConditions<dim>                                   bc;
    std::map<types::material_id, const Material::Interface *> materials;
    std::vector<std::shared_ptr<Material::Interface>>         material_objects;
    std::vector<types::material_id>                           material_ids;
    std::set<types::boundary_id>                              boundary_ids;

    MatrixType hessian;
    VectorType solution;         // locally owned
    VectorType solution_ghosted; // locally relevant
    VectorType rhs;
    /// The state the Hessian's sparsity pattern was last built at (its
    /// contact couplings depend on it): what a checkpoint keeps so that
    /// the restarted run has the same matrix structure.
    VectorType pattern_state; // locally relevant

    unsigned long long n_cells = 0, n_dofs = 0;
    double             h_min = 0., h_max = 0.;
    double             size  = 0.; // diameter of the bounding box

  private:
    /// The data save() attached, on the mesh of @p dofs just loaded: the
    /// first @p n_vectors of @p vectors, then @p n_dof_fields fields, and
    /// @p cell_fields (each sized already).
    static void
    unpack_attached(const DoFHandler<dim>       &dofs,
                    const unsigned int           n_vectors,
                    const unsigned int           n_dof_fields,
                    std::vector<VectorType>     &vectors,
                    std::vector<Vector<double>> &cell_fields);

    /// Ghosted copies (locally relevant) of the locally owned @p owned.
    std::vector<VectorType>
    ghosted_copies(const std::vector<const VectorType *> &owned) const;

    /// The values save() attaches to @p cell for the fields (@p fields
    /// ghosted): its DoF values of every field, then its cell values;
    /// empty where all are zero.
    std::vector<double>
    field_values(const typename Triangulation<dim>::cell_iterator &cell,
                 const std::vector<VectorType>                    &fields,
                 const std::vector<const Vector<double> *>        &cell_fields) const;

    Contact::Model<dim> *contact_model = nullptr;
    /// What builds the coarse mesh again (load_attached()).
    MeshParameters            mesh_parameters;
    std::vector<BodyGeometry> geometries;
  };
} // namespace Signorini
