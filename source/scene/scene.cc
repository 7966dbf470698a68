#include <signorini/first_error.h>
#include <signorini/input_error.h>
#include <signorini/scene/mesh.h>
#include <signorini/scene/scene.h>

#include <stdexcept>

#include <deal.II/base/mpi.h>
#include <deal.II/distributed/solution_transfer.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <deal.II/numerics/vector_tools.h>

#include <boost/serialization/string.hpp>
#include <boost/serialization/utility.hpp>
#include <boost/serialization/vector.hpp>

#include <algorithm>
#include <cstring>
#include <limits>
#include <map>
#include <string>

namespace Signorini
{
  template <int dim>
  Scene<dim>::Scene(const Parameters::Scene &p,
                    MPI_Comm                 comm,
                    const std::string       &mesh_file)
    : comm(comm)
    , triangulation(comm, Triangulation<dim>::limit_level_difference_at_vertices)
    , dof_handler(triangulation)
  {
    material_ids = p.material_ids();
    std::vector<BodyGeometry> geometries;
    for (const auto &body : p.bodies)
      {
        geometries.push_back(body.geometry);
        material_objects.push_back(body.material);
        materials[body.material_id] = body.material.get();
      }
    mesh_parameters  = p.mesh;
    this->geometries = geometries;
    build_scene_mesh(p.mesh, geometries, material_ids, triangulation,
                     !mesh_file.empty());
    if (!mesh_file.empty())
      triangulation.load(mesh_file);

    // Every cell must belong to a body, and every body must have cells.
    std::set<types::material_id> mesh_material_ids;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        mesh_material_ids.insert(cell->material_id());
    std::vector<unsigned int> local_ids(mesh_material_ids.begin(),
                                        mesh_material_ids.end());
    std::set<unsigned int> all_ids;
    for (const auto &ids : Utilities::MPI::all_gather(comm, local_ids))
      all_ids.insert(ids.begin(), ids.end());
    for (const auto id : all_ids)
      if (materials.count(id) == 0)
        throw InputError(p.mesh.source == MeshParameters::Source::gmsh ?
                           p.mesh.gmsh_file :
                           std::string("Body 1 > Material id"),
                         "the mesh has cells with material id " +
                           std::to_string(id) +
                           " but no active body has this material id");
    for (const auto id : material_ids)
      if (all_ids.count(id) == 0)
        throw InputError("Mesh",
                         "no cell of the mesh has material id " +
                           std::to_string(id) + " of an active body");

    const std::vector<types::boundary_id> ids = triangulation.get_boundary_ids();
    boundary_ids = std::set<types::boundary_id>(ids.begin(), ids.end());
    bc.setup(p.boundary_conditions, boundary_ids);
    if (bc.dirichlet_parts().empty())
      throw InputError("Boundary conditions > Fixed boundaries",
                       "no displacement is imposed anywhere, so the bodies "
                       "can move rigidly and the energy has no minimiser");


    fe = std::make_unique<FESystem<dim>>(FE_Q<dim>(p.discretization.degree), dim);
    // Its support points are computed by setup_dofs(), after any further
    // refinement of the mesh (no one uses the mapping before).
    mapping = std::make_unique<MappingQCache<dim>>(p.discretization.mapping_degree);
  }

  namespace
  {
    /// One cell's values as save() attaches them: the DoF values of each
    /// of @p dof_vectors (ghosted) on @p cell, then its value in each of
    /// @p cell_fields (by active cell index).
    template <int dim>
    std::vector<double>
    cell_values(const typename DoFHandler<dim>::active_cell_iterator &cell,
                const std::vector<VectorType>                        &dof_vectors,
                const std::vector<const Vector<double> *>            &cell_fields)
    {
      std::vector<double> values;
      Vector<double>      local(cell->get_fe().n_dofs_per_cell());
      for (const auto &v : dof_vectors)
        {
          cell->get_dof_values(v, local);
          values.insert(values.end(), local.begin(), local.end());
        }
      for (const auto *c : cell_fields)
        values.push_back((*c)[cell->active_cell_index()]);
      return values;
    }

    /// The inverse of cell_values(): @p values (as it lays them out) into
    /// the @p n_dof_vectors vectors from @p first_vector on, and into
    /// @p cell_fields.
    template <int dim>
    void
    set_cell_values(const typename DoFHandler<dim>::active_cell_iterator &cell,
                    const double                                         *values,
                    const std::vector<VectorType>::iterator               first_vector,
                    const unsigned int                                    n_dof_vectors,
                    std::vector<Vector<double>>                          &cell_fields)
    {
      const unsigned int per_cell = cell->get_fe().n_dofs_per_cell();
      Vector<double>     local(per_cell);
      for (unsigned int v = 0; v < n_dof_vectors; ++v)
        {
          std::copy(values + v * per_cell, values + (v + 1) * per_cell, local.begin());
          cell->set_dof_values(local, *(first_vector + v));
        }
      for (unsigned int c = 0; c < cell_fields.size(); ++c)
        cell_fields[c][cell->active_cell_index()] = values[n_dof_vectors * per_cell + c];
    }
  } // namespace

  template <int dim>
  void
  Scene<dim>::save(const std::string                         &mesh_file,
                   const std::vector<const VectorType *>     &vectors,
                   const std::vector<const VectorType *>     &dof_fields,
                   const std::vector<const Vector<double> *> &cell_fields) const
  {
    // Both attachments read the values of each cell's DoFs: ghosted
    // copies.
    const std::vector<VectorType> ghosted = ghosted_copies(vectors);
    std::vector<const VectorType *> attached;
    for (const auto &v : ghosted)
      attached.push_back(&v);
    parallel::distributed::SolutionTransfer<dim, VectorType> transfer(dof_handler);
    transfer.prepare_for_serialization(attached);

    // The fields are zero away from the contact nodes (the nodal ones):
    // each cell carries their values only where one of them is not zero
    // (variable-size data).
    const std::vector<VectorType> fields = ghosted_copies(dof_fields);
    if (!fields.empty() || !cell_fields.empty())
      {
        auto &tria = const_cast<parallel::distributed::Triangulation<dim> &>(triangulation);
        tria.register_data_attach(
          [this, &fields, &cell_fields](
            const typename Triangulation<dim>::cell_iterator &cell,
            const typename parallel::distributed::Triangulation<dim>::CellStatus) {
            const std::vector<double> values = field_values(cell, fields, cell_fields);
            std::vector<char>         data(values.size() * sizeof(double));
            std::memcpy(data.data(), values.data(), data.size());
            return data;
          },
          /*returns_variable_size_data=*/true);
      }
    triangulation.save(mesh_file);
  }

  template <int dim>
  std::vector<VectorType>
  Scene<dim>::ghosted_copies(const std::vector<const VectorType *> &owned) const
  {
    std::vector<VectorType> copies(owned.size());
    for (unsigned int v = 0; v < owned.size(); ++v)
      {
        copies[v].reinit(locally_owned, locally_relevant, comm);
        copies[v] = *owned[v];
      }
    return copies;
  }

  template <int dim>
  std::vector<double>
  Scene<dim>::field_values(const typename Triangulation<dim>::cell_iterator &cell,
                           const std::vector<VectorType>                    &fields,
                           const std::vector<const Vector<double> *> &cell_fields) const
  {
    const typename DoFHandler<dim>::active_cell_iterator dof_cell(&triangulation,
                                                                  cell->level(),
                                                                  cell->index(),
                                                                  &dof_handler);
    std::vector<double> values = cell_values<dim>(dof_cell, fields, cell_fields);
    if (std::none_of(values.begin(), values.end(), [](const double x) { return x != 0.; }))
      values.clear();
    return values;
  }

  template <int dim>
  unsigned long long
  Scene<dim>::field_bytes(const std::vector<const VectorType *>     &dof_fields,
                          const std::vector<const Vector<double> *> &cell_fields) const
  {
    const std::vector<VectorType> fields = ghosted_copies(dof_fields);
    unsigned long long            bytes  = 0;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        bytes += sizeof(double) * field_values(cell, fields, cell_fields).size();
    return Utilities::MPI::sum(bytes, comm);
  }

  template <int dim>
  void
  Scene<dim>::unpack_attached(const DoFHandler<dim>       &dofs,
                              const unsigned int           n_vectors,
                              const unsigned int           n_dof_fields,
                              std::vector<VectorType>     &vectors,
                              std::vector<Vector<double>> &cell_fields)
  {
    auto &tria = const_cast<parallel::distributed::Triangulation<dim> &>(
      dynamic_cast<const parallel::distributed::Triangulation<dim> &>(
        dofs.get_triangulation()));
    std::vector<VectorType *> targets;
    for (unsigned int v = 0; v < n_vectors; ++v)
      targets.push_back(&vectors[v]);
    parallel::distributed::SolutionTransfer<dim, VectorType> transfer(dofs);
    transfer.deserialize(targets);
    if (n_dof_fields == 0 && cell_fields.empty())
      return;
    const unsigned int per_cell = dofs.get_fe().n_dofs_per_cell();
    const unsigned int size     = n_dof_fields * per_cell + cell_fields.size();
    // The handle of the fields' attachment (save()'s callback is not
    // called on load).
    const unsigned int handle = tria.register_data_attach(
      [](const typename Triangulation<dim>::cell_iterator &,
         const typename parallel::distributed::Triangulation<dim>::CellStatus) {
        return std::vector<char>();
      },
      /*returns_variable_size_data=*/true);
    std::string error;
    tria.notify_ready_to_unpack(
      handle,
      [&](const typename Triangulation<dim>::cell_iterator &cell,
          const typename parallel::distributed::Triangulation<dim>::CellStatus,
          const boost::iterator_range<std::vector<char>::const_iterator> &data) {
        if (data.empty())
          return; // every field is zero on this cell
        if (static_cast<std::size_t>(data.size()) != size * sizeof(double))
          {
            error = "a cell carries " + std::to_string(data.size()) +
                    " bytes of fields instead of " +
                    std::to_string(size * sizeof(double));
            return;
          }
        std::vector<double> values(size);
        std::memcpy(values.data(), &*data.begin(), data.size());
        const typename DoFHandler<dim>::active_cell_iterator dof_cell(&tria,
                                                                      cell->level(),
                                                                      cell->index(),
                                                                      &dofs);
        set_cell_values<dim>(dof_cell, values.data(), vectors.begin() + n_vectors,
                             n_dof_fields, cell_fields);
      });
    for (unsigned int f = 0; f < n_dof_fields; ++f)
      vectors[n_vectors + f].compress(VectorOperation::insert);
    error = first_error(dofs.get_communicator(), error);
    if (!error.empty())
      throw std::runtime_error(error);
  }

  namespace
  {
    /// The active cell of @p tria with @p id, if this rank has it (locally
    /// owned, ghost or artificial), else tria.end().
    template <int dim>
    typename Triangulation<dim>::cell_iterator
    find_active_cell(const Triangulation<dim> &tria, const CellId &id)
    {
      auto cell = tria.create_cell_iterator(CellId(id.get_coarse_cell_id(), {}));
      for (const auto child : id.get_child_indices())
        {
          if (!cell->has_children())
            return tria.end();
          cell = cell->child(child);
        }
      return cell->has_children() ? tria.end() : cell;
    }
  } // namespace

  template <int dim>
  void
  Scene<dim>::load_attached(const std::string           &mesh_file,
                            const bool                   loaded_here,
                            const unsigned int           n_vectors,
                            const unsigned int           n_dof_fields,
                            const unsigned int           n_cell_fields,
                            std::vector<VectorType>     &vectors,
                            std::vector<Vector<double>> &cell_vectors)
  {
    vectors.assign(n_vectors + n_dof_fields, VectorType());
    for (auto &v : vectors)
      v.reinit(locally_owned, comm);
    cell_vectors.assign(n_cell_fields, Vector<double>(triangulation.n_active_cells()));
    if (loaded_here)
      {
        unpack_attached(dof_handler, n_vectors, n_dof_fields, vectors, cell_vectors);
        return;
      }

    // The saved mesh beside this one: the same coarse mesh, refined as
    // saved, partitioned among this run's ranks.
    parallel::distributed::Triangulation<dim> saved(
      comm, Triangulation<dim>::limit_level_difference_at_vertices);
    build_scene_mesh(mesh_parameters, geometries, material_ids, saved, true);
    saved.load(mesh_file);
    if (saved.n_global_active_cells() != triangulation.n_global_active_cells())
      throw std::runtime_error(
        mesh_file + " has " + std::to_string(saved.n_global_active_cells()) +
        " cells, the mesh the parameters build has " +
        std::to_string(triangulation.n_global_active_cells()));
    DoFHandler<dim> saved_dofs(saved);
    saved_dofs.distribute_dofs(*fe);
    const IndexSet saved_owned = saved_dofs.locally_owned_dofs();
    const IndexSet saved_relevant = DoFTools::extract_locally_relevant_dofs(saved_dofs);
    const unsigned int      n_all = n_vectors + n_dof_fields;
    std::vector<VectorType> owned(n_all), values(n_all);
    for (unsigned int v = 0; v < n_all; ++v)
      owned[v].reinit(saved_owned, comm);
    std::vector<Vector<double>> saved_cells(n_cell_fields,
                                            Vector<double>(saved.n_active_cells()));
    unpack_attached(saved_dofs, n_vectors, n_dof_fields, owned, saved_cells);
    for (unsigned int v = 0; v < n_all; ++v)
      {
        values[v].reinit(saved_owned, saved_relevant, comm);
        values[v] = owned[v];
      }

    // Each locally owned cell takes the values of the saved cell with its
    // CellId: in one piece where that cell is locally owned here too (p4est
    // partitions both meshes the same way, so that is every cell), the
    // others from the rank that owns them.
    std::vector<const Vector<double> *> saved_cell_fields;
    for (const auto &c : saved_cells)
      saved_cell_fields.push_back(&c);
    // One saved cell's values: every vector's DoF values, then the cell
    // values (laid out as save() attaches them).
    auto values_of = [&](const typename Triangulation<dim>::cell_iterator &source) {
      const typename DoFHandler<dim>::active_cell_iterator dof_cell(&saved,
                                                                    source->level(),
                                                                    source->index(),
                                                                    &saved_dofs);
      return cell_values<dim>(dof_cell, values, saved_cell_fields);
    };
    auto set_cell = [&](const typename DoFHandler<dim>::active_cell_iterator &cell,
                        const std::vector<double>                            &all) {
      set_cell_values<dim>(cell, all.data(), vectors.begin(), n_all, cell_vectors);
    };
    std::map<std::string, typename DoFHandler<dim>::active_cell_iterator> missing;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const auto source = find_active_cell(saved, cell->id());
          if (source != saved.end() && source->is_locally_owned())
            set_cell(cell, values_of(source));
          else
            missing[cell->id().to_string()] = cell;
        }
    if (Utilities::MPI::logical_or(!missing.empty(), comm))
      {
        std::vector<std::string> wanted;
        for (const auto &m : missing)
          wanted.push_back(m.first);
        std::vector<std::pair<std::string, std::vector<double>>> answers;
        for (const auto &list : Utilities::MPI::all_gather(comm, wanted))
          for (const auto &id : list)
            {
              const auto source = find_active_cell(saved, CellId(id));
              if (source != saved.end() && source->is_locally_owned())
                answers.emplace_back(id, values_of(source));
            }
        for (const auto &list : Utilities::MPI::all_gather(comm, answers))
          for (const auto &[id, all] : list)
            {
              const auto m = missing.find(id);
              if (m != missing.end())
                {
                  set_cell(m->second, all);
                  missing.erase(m);
                }
            }
        const unsigned int lost =
          Utilities::MPI::sum(static_cast<unsigned int>(missing.size()), comm);
        if (lost > 0)
          throw std::runtime_error(
            std::to_string(lost) + " cells of the mesh the parameters build are not "
            "in " + mesh_file + ": the meshes differ");
      }
    for (auto &v : vectors)
      v.compress(VectorOperation::insert);
  }

  template <int dim>
  double
  Scene<dim>::max_young_modulus() const
  {
    double E_max = 0.;
    for (const auto &m : material_objects)
      E_max = std::max(E_max, Material::small_strain_young_poisson(*m).first);
    return E_max;
  }

  template <int dim>
  unsigned int
  n_dofs_on_no_cell(const DoFHandler<dim> &dof_handler)
  {
    const MPI_Comm comm  = dof_handler.get_communicator();
    const IndexSet owned = dof_handler.locally_owned_dofs();
    // Every rank marks the DoFs of its cells; the owners read the marks.
    VectorType marks;
    marks.reinit(owned, DoFTools::extract_locally_relevant_dofs(dof_handler), comm, true);
    std::vector<types::global_dof_index> dofs;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          dofs.resize(cell->get_fe().n_dofs_per_cell());
          cell->get_dof_indices(dofs);
          for (const auto i : dofs)
            marks(i) = 1.;
        }
    marks.compress(VectorOperation::insert);
    unsigned int orphans = 0;
    for (const auto i : owned)
      orphans += (marks[i] == 0.);
    return Utilities::MPI::sum(orphans, comm);
  }

  template <int dim>
  void
  Scene<dim>::check_every_dof_on_a_cell() const
  {
    if (Utilities::MPI::n_mpi_processes(comm) == 1)
      return;
    const unsigned int orphans = n_dofs_on_no_cell(dof_handler);
    if (orphans > 0)
      throw std::runtime_error(
        "deal.II's DoF distribution on " +
        std::to_string(Utilities::MPI::n_mpi_processes(comm)) + " MPI ranks left " +
        std::to_string(orphans) + " of its " + std::to_string(dof_handler.n_dofs()) +
        " DoFs on no cell (a deal.II 9.4 problem with some 3D meshes with hanging "
        "nodes on several ranks whose coarse cells are not in standard "
        "orientation); the system would be singular. Run this mesh on another "
        "number of ranks or change its refinement.");
  }

  template unsigned int n_dofs_on_no_cell(const DoFHandler<2> &);
  template unsigned int n_dofs_on_no_cell(const DoFHandler<3> &);

  template <int dim>
  void
  Scene<dim>::cache_mapping()
  {
    // The cache drops its points at any change of the mesh; the points
    // are those MappingQ computes (bitwise the same results), for every
    // cell this rank has, on every level.
    mapping->initialize(MappingQ<dim>(mapping->get_degree()), triangulation);
  }

  template <int dim>
  void
  Scene<dim>::setup_dofs(Contact::Model<dim> *contact)
  {
    contact_model = contact;
    cache_mapping();
    dof_handler.distribute_dofs(*fe);
    locally_owned    = dof_handler.locally_owned_dofs();
    locally_relevant = DoFTools::extract_locally_relevant_dofs(dof_handler);
    check_every_dof_on_a_cell();

    hanging_constraints.clear();
    hanging_constraints.reinit(locally_relevant);
    DoFTools::make_hanging_node_constraints(dof_handler, hanging_constraints);
    hanging_constraints.close();
    locate_fixed_points();
    homogeneous_constraints = boundary_constraints(0., true);

    solution.reinit(locally_owned, comm);
    solution_ghosted.reinit(locally_owned, locally_relevant, comm);
    pattern_state.reinit(locally_owned, locally_relevant, comm);
    rhs.reinit(locally_owned, comm);
    if (contact)
      contact->setup(hanging_constraints, homogeneous_constraints);
    build_matrix(solution_ghosted);

    n_cells = triangulation.n_global_active_cells();
    n_dofs  = dof_handler.n_dofs();
    double h_lo = std::numeric_limits<double>::max(), h_hi = 0.;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          h_lo = std::min(h_lo, cell->diameter());
          h_hi = std::max(h_hi, cell->diameter());
        }
    h_min = Utilities::MPI::min(h_lo, comm);
    h_max = Utilities::MPI::max(h_hi, comm);
    const auto box = GridTools::compute_bounding_box(triangulation);
    size = box.get_boundary_points().first.distance(box.get_boundary_points().second);
  }

  template <int dim>
  void
  Scene<dim>::build_matrix(const VectorType &u)
  {
    if (&u != &pattern_state)
      pattern_state = u;
    // Contact couplings may reach DoFs owned by other ranks: their rows
    // must be writable here.
    IndexSet writable = locally_relevant;
    if (contact_model)
      contact_model->add_writable_rows(writable);
    TrilinosWrappers::SparsityPattern sparsity(locally_owned,
                                               locally_owned,
                                               writable,
                                               comm);
    DoFTools::make_sparsity_pattern(dof_handler,
                                    sparsity,
                                    homogeneous_constraints,
                                    false,
                                    Utilities::MPI::this_mpi_process(comm));
    if (contact_model)
      contact_model->add_sparsity(sparsity, homogeneous_constraints, u);
    sparsity.compress();
    hessian.reinit(sparsity);
  }

  template <int dim>
  AffineConstraints<double>
  Scene<dim>::boundary_constraints(const double time, const bool homogeneous) const
  {
    AffineConstraints<double> constraints(locally_relevant);
    DoFTools::make_hanging_node_constraints(dof_handler, constraints);
    const Functions::ZeroFunction<dim> zero(dim);
    bc.prescribed_displacement().set_time(time);
    for (const auto &part : bc.dirichlet_parts())
      VectorTools::interpolate_boundary_values(
        *mapping,
        dof_handler,
        part.boundary_id,
        (part.prescribed && !homogeneous) ?
          static_cast<const Function<dim> &>(bc.prescribed_displacement()) :
          static_cast<const Function<dim> &>(zero),
        constraints,
        ComponentMask(part.components));
    for (const auto dof : fixed_point_dofs)
      if (!constraints.is_constrained(dof))
        constraints.add_line(dof);
    constraints.close();
    return constraints;
  }

  template <int dim>
  void
  Scene<dim>::locate_fixed_points()
  {
    // Each point's vertex: one within 1e-8 of the mesh's size.
    fixed_point_dofs.clear();
    if (bc.fixed_points().empty())
      return;
    const double size = GridTools::diameter(triangulation);
    for (const auto &fixed : bc.fixed_points())
      {
        bool found = false;
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (!cell->is_artificial())
            for (const auto v : cell->vertex_indices())
              if (cell->vertex(v).distance(fixed.point) <= 1e-8 * size)
                {
                  found = true;
                  for (unsigned int c = 0; c < dim; ++c)
                    if (fixed.components[c])
                      fixed_point_dofs.push_back(cell->vertex_dof_index(v, c));
                }
        if (!Utilities::MPI::logical_or(found, triangulation.get_communicator()))
          throw InputError("Boundary conditions > Fixed points",
                           "'" + fixed.text + "' is not a vertex of the mesh "
                           "(none within 1e-8 of the scene's size)");
      }
    // A vertex is found from each of its cells.
    std::sort(fixed_point_dofs.begin(), fixed_point_dofs.end());
    fixed_point_dofs.erase(std::unique(fixed_point_dofs.begin(), fixed_point_dofs.end()),
                           fixed_point_dofs.end());
  }

  template <int dim>
  AffineConstraints<double>
  Scene<dim>::increment_constraints(const double time) const
  {
    // Hanging nodes, and on Dirichlet dofs: target value - current value.
    const AffineConstraints<double> target = boundary_constraints(time, false);
    AffineConstraints<double>       increment(locally_relevant);
    DoFTools::make_hanging_node_constraints(dof_handler, increment);
    for (const auto &line : target.get_lines())
      // A hanging node whose parents are all Dirichlet DoFs also has an
      // empty line after close(); its increment follows from its parents'.
      if (line.entries.empty() && !increment.is_constrained(line.index))
        {
          increment.add_line(line.index);
          increment.set_inhomogeneity(line.index,
                                      line.inhomogeneity -
                                        solution_ghosted[line.index]);
        }
    increment.close();
    return increment;
  }

  template <int dim>
  void
  Scene<dim>::refine_and_transfer(Contact::Model<dim> *contact, const double time)
  {
    solution_ghosted = solution;
    parallel::distributed::SolutionTransfer<dim, VectorType> transfer(dof_handler);
    triangulation.prepare_coarsening_and_refinement();
    transfer.prepare_for_coarsening_and_refinement(solution_ghosted);
    triangulation.execute_coarsening_and_refinement();
    setup_dofs(contact);
    transfer.interpolate(solution);
    // New nodes on the Dirichlet boundaries take their prescribed values,
    // hanging nodes follow their parents.
    boundary_constraints(time, false).distribute(solution);
    solution_ghosted = solution;
  }

  template class Scene<2>;
  template class Scene<3>;
} // namespace Signorini
