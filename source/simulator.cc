#include <signorini/input_error.h>
#include <signorini/simulator.h>
#include <signorini/study.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/multithread_info.h>
#include <deal.II/base/utilities.h>
#include <deal.II/distributed/solution_transfer.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <deal.II/numerics/vector_tools.h>

#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace Signorini
{
  namespace
  {
    constexpr unsigned int max_bodies = 2;

    std::string
    body_section(const unsigned int b)
    {
      return "Body " + std::to_string(b + 1);
    }
  } // namespace

  void
  declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Dimension",
                      "2",
                      Patterns::Integer(2, 3),
                      "Space dimension: 2 (plane strain) or 3.");
    prm.declare_entry("Scene name",
                      "",
                      Patterns::Anything(),
                      "Name of the scene in summary.json; empty: the "
                      "parameter file name without its extension.");
    prm.declare_entry("Output directory",
                      "",
                      Patterns::Anything(),
                      "Folder for every output file, created if needed; "
                      "empty: output/<scene name>. Relative paths are "
                      "relative to the working directory.");

    prm.enter_subsection("Discretization");
    prm.declare_entry("Polynomial degree",
                      "1",
                      Patterns::Integer(1, 2),
                      "Degree p of the FE_Q(p)^dim displacement element; the "
                      "mapping is of the same degree (curved cells follow "
                      "curved boundaries for p = 2).");
    prm.leave_subsection();

    prm.enter_subsection("Mesh");
    MeshParameters::declare_parameters(prm);
    prm.leave_subsection();

    prm.enter_subsection("Mesh refinement");
    RefinementParameters::declare_parameters(prm);
    prm.leave_subsection();

    Study::declare_parameters(prm);

    for (unsigned int b = 0; b < max_bodies; ++b)
      {
        prm.enter_subsection(body_section(b));
        prm.declare_entry("Active",
                          b == 0 ? "true" : "false",
                          Patterns::Bool(),
                          "Whether the scene has this body.");
        prm.declare_entry("Material id",
                          std::to_string(b),
                          Patterns::Integer(0, 255),
                          "Cells with this material id belong to the body "
                          "(generated meshes give all the body's cells this "
                          "id; in a Gmsh file it is the physical tag).");
        prm.enter_subsection("Geometry");
        BodyGeometry::declare_parameters(prm);
        prm.leave_subsection();
        prm.enter_subsection("Material");
        Material::declare_parameters(prm);
        prm.leave_subsection();
        prm.leave_subsection();
      }

    prm.enter_subsection("Boundary conditions");
    BoundaryConditions<2>::declare_parameters(prm);
    prm.leave_subsection();

    prm.enter_subsection("Load stepping");
    prm.declare_entry("End time",
                      "1",
                      Patterns::Double(),
                      "Loads and prescribed displacements are functions of "
                      "the pseudo-time t, stepped from 0 to this value; > 0.");
    prm.declare_entry("Number of steps",
                      "1",
                      Patterns::Integer(),
                      "Initial number of equal load steps; >= 1. A step "
                      "whose Newton solve fails is halved and retried.");
    prm.declare_entry("Minimum step fraction",
                      "1e-4",
                      Patterns::Double(),
                      "Smallest step size, as a fraction of the end time, "
                      "that step cutting may reach before the run fails; in "
                      "(0, 1].");
    prm.leave_subsection();

    prm.enter_subsection("Solver");
    prm.declare_entry("Method",
                      "newton",
                      Patterns::Selection("newton|newton-penalty|ipopt"),
                      "newton: Newton's method on the total potential "
                      "energy with an Armijo line search (no contact). "
                      "newton-penalty: the same on E + mu/3 sum w_k "
                      "<-g_k>^3 with penalty continuation (contact; runs "
                      "with MPI). ipopt: the interior point optimiser with "
                      "the contact and incompressibility constraints and "
                      "exact derivatives (one MPI rank); for two-body "
                      "contact it minimises each stage of the penalty "
                      "continuation without constraints.");
    prm.enter_subsection("Newton");
    NewtonMinimizer::Parameters::declare_parameters(prm);
    prm.leave_subsection();
    prm.enter_subsection("Penalty");
    Contact::ContinuationParameters::declare_parameters(prm);
    prm.leave_subsection();
    prm.enter_subsection("Ipopt");
    IpoptSolver<2>::Parameters::declare_parameters(prm);
    prm.leave_subsection();
    prm.enter_subsection("Linear solver");
    LinearSolver::Parameters::declare_parameters(prm);
    prm.leave_subsection();
    prm.leave_subsection();

    prm.enter_subsection("Contact");
    prm.declare_entry("Type",
                      "none",
                      Patterns::Selection("none|rigid foundation|two bodies"),
                      "none: no contact (no contact structures are built). "
                      "rigid foundation: the boundary 'Contact boundary id' "
                      "must stay above the surface of the Foundation "
                      "subsection (node-wise constraints). two bodies: the "
                      "boundary 'Contact boundary id' of body 1 must stay "
                      "out of body 2, whose surface is the Two bodies "
                      "subsection's 'Target boundary id' (smooth indicator "
                      "function, penalty; Method = newton-penalty).");
    prm.declare_entry("Contact boundary id",
                      "0",
                      Patterns::Integer(0, 255),
                      "Gamma_2 (Gamma_C of body 1 for two bodies): the "
                      "boundary id of the potential contact boundary.");
    prm.enter_subsection("Foundation");
    Contact::Foundation<2>::declare_parameters(prm);
    prm.leave_subsection();
    prm.enter_subsection("Two bodies");
    Contact::TwoBodyParameters::declare_parameters(prm);
    prm.leave_subsection();
    prm.enter_subsection("Hertz reference");
    Contact::HertzReference::declare_parameters(prm);
    prm.leave_subsection();
    prm.leave_subsection();

    Postprocessor<2>::declare_parameters(prm);
  }

  namespace
  {
    /// The energy functional at a fixed load time, as a Newton objective.
    template <int dim>
    class EnergyObjective : public Objective
    {
    public:
      EnergyObjective(const EnergyFunctional<dim> &energy, const double time)
        : energy(energy)
        , time(time)
      {}

      Evaluation
      evaluate(const VectorType                &u,
               const AffineConstraints<double> &constraints,
               VectorType                      *rhs,
               MatrixType                      *hessian) override
      {
        return energy.evaluate(u, time, constraints, rhs, hessian);
      }

    private:
      const EnergyFunctional<dim> &energy;
      const double                 time;
    };
  } // namespace

  template <int dim>
  Simulator<dim>::Simulator(ParameterHandler  &prm,
                            const std::string &parameter_file,
                            const bool         quiet,
                            MPI_Comm           comm)
    : comm(comm)
    , pcout(std::cout, Utilities::MPI::this_mpi_process(comm) == 0 && !quiet)
    , progress(std::cout, false)
    , triangulation(comm,
                    Triangulation<dim>::limit_level_difference_at_vertices)
    , dof_handler(triangulation)
  {
    Timer                       setup_timer;
    const std::filesystem::path file(parameter_file);
    report.parameter_file = parameter_file;
    report.dimension      = dim;
    report.n_ranks        = Utilities::MPI::n_mpi_processes(comm);
    report.scene          = prm.get("Scene name");
    if (report.scene.empty())
      report.scene = file.stem().string();
    output_directory = prm.get("Output directory");
    if (output_directory.empty())
      output_directory = "output/" + report.scene;
    report.output_directory = output_directory;

    prm.enter_subsection("Discretization");
    report.degree = prm.get_integer("Polynomial degree");
    prm.leave_subsection();

    prm.enter_subsection("Mesh");
    mesh_parameters.parse_parameters(prm, file.parent_path().string());
    prm.leave_subsection();
    prm.enter_subsection("Mesh refinement");
    refinement_parameters.parse_parameters(prm);
    prm.leave_subsection();

    for (unsigned int b = 0; b < max_bodies; ++b)
      {
        const std::string section = body_section(b);
        prm.enter_subsection(section);
        if (prm.get_bool("Active"))
          {
            const types::material_id id = prm.get_integer("Material id");
            if (std::find(material_ids.begin(), material_ids.end(), id) !=
                material_ids.end())
              throw InputError(section + " > Material id",
                               "material id " + std::to_string(id) +
                                 " is already used by another body");
            material_ids.push_back(id);
            prm.enter_subsection("Geometry");
            geometries.emplace_back();
            geometries.back().parse_parameters(prm, dim, section + " > Geometry");
            prm.leave_subsection();
            prm.enter_subsection("Material");
            if (prm.get_bool("Incompressible"))
              incompressible_ids.insert(id);
            material_objects.push_back(
              Material::create(prm, section + " > Material"));
            materials[id] = material_objects.back().get();
            report.materials.push_back(material_objects.back()->name());
            prm.leave_subsection();
          }
        prm.leave_subsection();
      }
    if (material_ids.empty())
      throw InputError("Body 1 > Active", "the scene has no active body");

    prm.enter_subsection("Load stepping");
    end_time          = prm.get_double("End time");
    const int steps   = prm.get_integer("Number of steps");
    min_step_fraction = prm.get_double("Minimum step fraction");
    if (!(end_time > 0.) || !std::isfinite(end_time))
      throw InputError("Load stepping > End time",
                       "must be > 0, got " + prm.get("End time"));
    if (steps < 1)
      throw InputError("Load stepping > Number of steps",
                       "must be >= 1, got " + prm.get("Number of steps"));
    if (!(min_step_fraction > 0. && min_step_fraction <= 1.))
      throw InputError("Load stepping > Minimum step fraction",
                       "must lie in (0, 1], got " +
                         prm.get("Minimum step fraction"));
    n_steps = steps;
    prm.leave_subsection();

    prm.enter_subsection("Solver");
    report.solver = prm.get("Method");
    method        = report.solver;
    prm.enter_subsection("Newton");
    newton_parameters.parse_parameters(prm);
    prm.leave_subsection();
    prm.enter_subsection("Penalty");
    continuation_parameters.parse_parameters(prm);
    prm.leave_subsection();
    prm.enter_subsection("Ipopt");
    ipopt_parameters.parse_parameters(prm, file.parent_path().string());
    prm.leave_subsection();
    prm.enter_subsection("Linear solver");
    linear_parameters.parse_parameters(prm);
    report.linear_solver = linear_parameters.name();
    ipopt_parameters.mumps_pivot_order = linear_parameters.mumps_ordering;
    prm.leave_subsection();
    prm.leave_subsection();

    build_scene_mesh(mesh_parameters, geometries, material_ids, triangulation);

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
        throw InputError(mesh_parameters.source == MeshParameters::Source::gmsh ?
                           mesh_parameters.gmsh_file :
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
    const std::set<types::boundary_id>    boundary_ids(ids.begin(), ids.end());
    prm.enter_subsection("Boundary conditions");
    bc.parse_parameters(prm, boundary_ids);
    prm.leave_subsection();
    if (bc.dirichlet_parts().empty())
      throw InputError("Boundary conditions > Fixed boundaries",
                       "no displacement is imposed anywhere, so the bodies "
                       "can move rigidly and the energy has no minimiser");
    for (const auto &part : bc.dirichlet_parts())
      has_prescribed_motion |= part.prescribed;

    // Contact and the solver that can handle what the scene declares.
    prm.enter_subsection("Contact");
    report.contact_type = prm.get("Type");
    std::unique_ptr<Contact::Foundation<dim>> foundation;
    types::boundary_id                        contact_id = 0;
    if (report.contact_type == "rigid foundation")
      {
        contact_id = prm.get_integer("Contact boundary id");
        if (boundary_ids.count(contact_id) == 0)
          throw InputError("Contact > Contact boundary id",
                           "boundary id " + prm.get("Contact boundary id") +
                             " does not exist in the mesh");
        prm.enter_subsection("Foundation");
        foundation = Contact::Foundation<dim>::create(prm, "Contact > Foundation");
        report.foundation = foundation->description();
        prm.leave_subsection();
      }
    Contact::TwoBodyParameters two_body_parameters;
    const bool                 two_bodies = (report.contact_type == "two bodies");
    if (two_bodies)
      {
        if (material_ids.size() < 2)
          throw InputError("Contact > Type",
                           "two bodies needs Body 2 > Active = true");
        contact_id = prm.get_integer("Contact boundary id");
        prm.enter_subsection("Two bodies");
        two_body_parameters.parse_parameters(prm);
        prm.leave_subsection();
        for (const auto &[key, id] :
             {std::make_pair(std::string("Contact boundary id"), contact_id),
              std::make_pair(std::string("Two bodies > Target boundary id"),
                             two_body_parameters.target_boundary)})
          if (boundary_ids.count(id) == 0)
            throw InputError("Contact > " + key,
                             "boundary id " + std::to_string(id) +
                               " does not exist in the mesh");
        report.foundation = std::string("body 2, ") +
                            (two_body_parameters.integral ? "integral" : "nodal") +
                            " form";
      }
    prm.enter_subsection("Hertz reference");
    hertz.parse_parameters(prm);
    prm.leave_subsection();
    prm.leave_subsection();
    if (hertz.active() && !foundation && !two_bodies)
      throw InputError("Contact > Hertz reference > Line load",
                       "a Hertz reference needs contact (Contact > Type)");
    if (hertz.active() && hertz.contact_modulus <= 0.)
      {
        // 1/E* = sum over the bodies in contact of (1 - nu^2)/E.
        double compliance = 0.;
        for (unsigned int b = 0; b < (two_bodies ? 2u : 1u); ++b)
          {
            const auto [E, nu] =
              Material::small_strain_young_poisson(*material_objects[b]);
            compliance += (1. - nu * nu) / E;
          }
        hertz.contact_modulus = 1. / compliance;
      }
    if (method == "newton" && (foundation || two_bodies))
      throw InputError("Solver > Method",
                       "the scene declares contact (Contact > Type = " +
                         report.contact_type +
                         "), which Method = newton cannot handle: use "
                         "newton-penalty");
    if (method == "newton-penalty" && !foundation && !two_bodies)
      throw InputError("Solver > Method",
                       "newton-penalty needs contact (Contact > Type); the "
                       "scene declares none: use newton");
    if (!incompressible_ids.empty() && method != "ipopt")
      throw InputError("Body 1 > Material > Incompressible",
                       "J = 1 constraints need Solver > Method = ipopt, not " +
                         method);
    if (method == "ipopt" && report.n_ranks > 1)
      throw InputError("Solver > Method",
                       "ipopt runs on one MPI rank, and this run has " +
                         std::to_string(report.n_ranks) +
                         ": run it without mpirun, or use newton-penalty");

    fe      = std::make_unique<FESystem<dim>>(FE_Q<dim>(report.degree), dim);
    mapping = std::make_unique<MappingQ<dim>>(report.degree);
    energy  = std::make_unique<EnergyFunctional<dim>>(dof_handler, *mapping,
                                                     materials, bc);
    if (foundation)
      contact = std::make_unique<Contact::RigidFoundation<dim>>(
        std::move(foundation), contact_id, dof_handler, *mapping);
    if (two_bodies)
      two_body = std::make_unique<Contact::TwoBodyContact<dim>>(
        two_body_parameters, contact_id, dof_handler, *mapping);
    if (refinement_parameters.band_refinements > 0)
      {
        if (!contact && !two_body)
          throw InputError("Mesh refinement > Contact band refinements",
                           "refines near the contact boundary, but the scene "
                           "declares no contact (Contact > Type)");
        std::function<double(const Point<dim> &)> gap;
        if (contact)
          gap = [this](const Point<dim> &X) {
            return X[dim - 1] - contact->foundation().evaluate(X).psi;
          };
        else
          {
            // Distance to the bounding box of body 2's cells.
            Point<dim> lo, hi;
            for (unsigned int d = 0; d < dim; ++d)
              {
                lo[d] = std::numeric_limits<double>::max();
                hi[d] = -lo[d];
              }
            for (const auto &cell : triangulation.active_cell_iterators())
              if (cell->is_locally_owned() && cell->material_id() == material_ids[1])
                for (const auto v : cell->vertex_indices())
                  for (unsigned int d = 0; d < dim; ++d)
                    {
                      lo[d] = std::min(lo[d], cell->vertex(v)[d]);
                      hi[d] = std::max(hi[d], cell->vertex(v)[d]);
                    }
            for (unsigned int d = 0; d < dim; ++d)
              {
                lo[d] = Utilities::MPI::min(lo[d], comm);
                hi[d] = Utilities::MPI::max(hi[d], comm);
              }
            gap = [lo, hi](const Point<dim> &X) {
              double d2 = 0.;
              for (unsigned int d = 0; d < dim; ++d)
                {
                  const double out = std::max({lo[d] - X[d], X[d] - hi[d], 0.});
                  d2 += out * out;
                }
              return std::sqrt(d2);
            };
          }
        Refinement::refine_contact_band(triangulation, contact_id,
                                        refinement_parameters, gap);
      }
    if (refinement_parameters.cycles > 0 && method == "ipopt" && report.n_ranks > 1)
      throw InputError("Mesh refinement > Number of cycles",
                       "ipopt runs on one rank");
    postprocessor = std::make_unique<Postprocessor<dim>>(prm,
                                                         dof_handler,
                                                         *mapping,
                                                         materials,
                                                         *energy,
                                                         hanging_constraints,
                                                         boundary_ids,
                                                         output_directory);
    const std::string verbosity = postprocessor->verbosity();
    const bool        talk = (Utilities::MPI::this_mpi_process(comm) == 0) &&
                      !quiet && verbosity != "quiet";
    pcout.set_condition(talk);
    progress.set_condition(talk);
    linear_solver = std::make_unique<LinearSolver>(linear_parameters);
    timer = std::make_unique<TimerOutput>(comm, pcout, TimerOutput::never,
                                          TimerOutput::wall_times);
    try
      {
        setup_dofs();
      }
    catch (...)
      {
        timer.reset(); // quietly, while the exception is caught
        throw;
      }
    update_penalty_scale();
    report.initial_penalty = mu0;
    last_mu                = mu0;
    if (contact)
      {
        if (report.contact_nodes == 0)
          throw InputError("Contact > Contact boundary id",
                           "boundary " + std::to_string(contact->boundary_id()) +
                             " has no contact node (every node on it is a "
                             "hanging node)");
        postprocessor->extra_fields = [this](DataOut<dim> &data_out) {
          contact->add_output_fields(data_out, solution_ghosted, contact_forces);
        };
      }
    if (two_body)
      {
        // The start state (u = 0) must be one the penalty can act on: a
        // point of Gamma_C inside body 2 below the indicator layer would be
        // pulled through, not pushed out (collective).
        if (!two_body->admissible(solution_ghosted))
          throw InputError("Body 2 > Geometry",
                           "at the start, a point of body 1's contact boundary "
                           "(Contact > Contact boundary id) lies inside body 2 "
                           "deeper than the layer in which the indicator "
                           "function of its surface acts: move the bodies "
                           "apart (a penetration within that layer is "
                           "allowed)");
        postprocessor->extra_fields = [this](DataOut<dim> &data_out) {
          two_body->add_output_fields(data_out, solution_ghosted, contact_forces);
        };
      }
    setup_seconds = Utilities::MPI::max(setup_timer.wall_time(), comm);
  }

  template <int dim>
  void
  Simulator<dim>::update_penalty_scale()
  {
    // The penalty scale: the largest small-strain Young's modulus.
    double E_max = 0.;
    for (const auto &m : material_objects)
      E_max = std::max(E_max, Material::small_strain_young_poisson(*m).first);
    if (contact)
      {
        report.contact_nodes = contact->n_global_nodes();
        mu0 = continuation_parameters.initial_factor * E_max /
              std::pow(contact->min_mesh_size(), 2);
      }
    if (two_body)
      {
        report.contact_nodes = two_body->n_global_nodes();
        // mu P has the units of energy per length^(dim-1) times Phi (<= 1
        // inside a simplex): mu_0 = c_0 E h.
        mu0 = continuation_parameters.initial_factor * E_max *
              std::pow(two_body->min_mesh_size(), dim - 1);
      }
  }

  template <int dim>
  void
  Simulator<dim>::setup_dofs()
  {
    dof_handler.distribute_dofs(*fe);
    locally_owned    = dof_handler.locally_owned_dofs();
    locally_relevant = DoFTools::extract_locally_relevant_dofs(dof_handler);

    hanging_constraints.clear();
    hanging_constraints.reinit(locally_relevant);
    DoFTools::make_hanging_node_constraints(dof_handler, hanging_constraints);
    hanging_constraints.close();
    homogeneous_constraints = boundary_constraints(0., true);

    solution.reinit(locally_owned, comm);
    solution_ghosted.reinit(locally_owned, locally_relevant, comm);
    rhs.reinit(locally_owned, comm);
    if (two_body)
      {
        two_body->setup(hanging_constraints, homogeneous_constraints);
        contact_forces.assign(two_body->nodes().size() * dim, 0.);
      }
    build_matrix(solution_ghosted);

    if (contact)
      {
        contact->setup(hanging_constraints);
        contact_forces.assign(contact->nodes().size(), 0.);
      }
    if (!incompressible_ids.empty())
      {
        incompressibility = std::make_unique<Incompressibility<dim>>(
          dof_handler, *mapping, incompressible_ids);
        report.incompressibility_constraints = incompressibility->cells().size();
      }
    if (method == "ipopt")
      {
        ipopt = std::make_unique<IpoptSolver<dim>>(ipopt_parameters,
                                                   dof_handler,
                                                   *energy,
                                                   contact.get(),
                                                   incompressibility.get(),
                                                   output_directory,
                                                   progress,
                                                   *timer);
        ipopt->setup(homogeneous_constraints, hessian);
        if (two_body)
          ipopt->set_penalty(two_body.get(),
                             [this](const VectorType &u) { build_matrix(u); });
      }

    std::vector<std::vector<bool>> modes;
    DoFTools::extract_constant_modes(dof_handler, ComponentMask(dim, true), modes);
    linear_solver->set_constant_modes(modes, report.degree > 1);

    report.n_cells = triangulation.n_global_active_cells();
    report.n_dofs  = dof_handler.n_dofs();
    double h_min = std::numeric_limits<double>::max(), h_max = 0.;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          h_min = std::min(h_min, cell->diameter());
          h_max = std::max(h_max, cell->diameter());
        }
    report.h_min = Utilities::MPI::min(h_min, comm);
    {
      const auto box = GridTools::compute_bounding_box(triangulation);
      scene_size     = box.get_boundary_points().first.distance(
        box.get_boundary_points().second);
    }
    if (ipopt)
      ipopt->set_step_limit(newton_parameters.max_increment * scene_size);
    report.h_max = Utilities::MPI::max(h_max, comm);
  }

  template <int dim>
  void
  Simulator<dim>::build_matrix(const VectorType &u)
  {
    // Two-body contact couples a body 1 point with body 2's vertices,
    // possibly owned by other ranks: their rows must be writable here.
    IndexSet writable = locally_relevant;
    if (two_body)
      writable.add_indices(two_body->coupled_rows());
    TrilinosWrappers::SparsityPattern sparsity(locally_owned,
                                               locally_owned,
                                               writable,
                                               comm);
    DoFTools::make_sparsity_pattern(dof_handler,
                                    sparsity,
                                    homogeneous_constraints,
                                    false,
                                    Utilities::MPI::this_mpi_process(comm));
    if (two_body)
      two_body->add_sparsity(sparsity, homogeneous_constraints, u);
    sparsity.compress();
    hessian.reinit(sparsity);
  }

  template <int dim>
  AffineConstraints<double>
  Simulator<dim>::boundary_constraints(const double time,
                                       const bool   homogeneous) const
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
    constraints.close();
    return constraints;
  }

  template <int dim>
  AffineConstraints<double>
  Simulator<dim>::increment_constraints(const double time) const
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
  bool
  Simulator<dim>::solve_load_step(const double                 time,
                                  NewtonMinimizer::Statistics &stats,
                                  Report::Step                &record)
  {
    if (method == "ipopt" && !two_body)
      {
        solution_ghosted = solution;
        const AffineConstraints<double> target = boundary_constraints(time, false);
        const auto result = ipopt->solve(time, target, solution_ghosted);
        solution                = solution_ghosted;
        stats.iterations        = result.iterations;
        stats.converged         = result.success;
        record.solver_status    = result.status;
        report.derivative_test_errors =
          std::max(report.derivative_test_errors, result.derivative_test_errors);
        if (!result.success)
          {
            stats.reason = result.failure();
            return false;
          }
        if (contact)
          contact_forces = result.contact_forces;
        TimerOutput::Scope scope(*timer, "assembly");
        stats.evaluation = energy->evaluate(solution_ghosted, time,
                                            homogeneous_constraints, nullptr, nullptr);
        stats.residual = 0.;
        return true;
      }

    NewtonMinimizer newton(newton_parameters, *linear_solver, progress, *timer);
    newton.set_length_scale(scene_size);
    const double    mu_start =
      continuation_parameters.restart_each_step ?
        mu0 :
        std::max(mu0, last_mu / continuation_parameters.step_reduction);
    std::unique_ptr<Objective> objective;
    Contact::PenaltyTerm<dim> *const term = penalty_term();
    const typename Contact::PenaltyObjective<dim>::PatternBuilder rebuild =
      [this](const VectorType &u) {
        TimerOutput::Scope scope(*timer, "sparsity pattern");
        build_matrix(u);
      };
    // The predictor's objective: G_mu with the first stage's penalty for
    // contact (with either stage solver), so that its step is checked
    // against the contact's admissibility too.
    if (method == "newton")
      objective = std::make_unique<EnergyObjective<dim>>(*energy, time);
    else
      {
        auto penalised = std::make_unique<Contact::PenaltyObjective<dim>>(
          *energy, *term, time, mu_start, rebuild);
        penalised->timer = timer.get();
        objective        = std::move(penalised);
      }
    if (has_prescribed_motion)
      {
        solution_ghosted = solution;
        const AffineConstraints<double> increment = increment_constraints(time);
        std::string                     reason;
        if (!newton.predictor(*objective, increment, solution, solution_ghosted,
                              hessian, rhs, reason))
          {
            stats.reason = "predictor: " + reason;
            return false;
          }
      }
    if (method == "newton")
      {
        stats = newton.minimize(*objective, homogeneous_constraints, solution,
                                solution_ghosted, hessian, rhs);
        return stats.converged;
      }

    // Each stage of the continuation: Newton on G_mu, or Ipopt as an
    // unconstrained minimiser of G_mu (two-body contact, Method = ipopt).
    Contact::StageSolver solve_stage = [&](const double mu, VectorType &u) {
      Contact::PenaltyObjective<dim> stage(*energy, *term, time, mu, rebuild);
      stage.timer = timer.get();
      return newton.minimize(stage, homogeneous_constraints, u,
                             solution_ghosted, hessian, rhs);
    };
    if (method == "ipopt")
      {
        const AffineConstraints<double> target = boundary_constraints(time, false);
        solve_stage = [&, target](const double mu, VectorType &u) {
          solution_ghosted = u;
          const auto result = ipopt->solve(time, target, solution_ghosted, mu);
          u                 = solution_ghosted;
          NewtonMinimizer::Statistics s;
          s.converged  = result.success;
          s.iterations = result.iterations;
          if (!result.success)
            s.reason = result.failure();
          else
            s.evaluation = energy->evaluate(solution_ghosted, time,
                                            homogeneous_constraints, nullptr,
                                            nullptr);
          record.solver_status = result.status;
          return s;
        };
      }
    const Contact::ContinuationResult result =
      Contact::penalty_continuation(continuation_parameters, solve_stage, *energy,
                                    *term, time, mu_start, mu0,
                                    homogeneous_constraints, solution,
                                    solution_ghosted, progress);
    stats            = result.last;
    stats.iterations = result.newton_iterations;
    stats.linear_iterations = result.linear_iterations; // over all stages
    stats.linear_fallbacks  = result.linear_fallbacks;
    stats.converged  = result.converged;
    stats.reason     = result.reason;
    record.stages    = result.stages;
    if (!result.converged)
      return false;
    contact_forces = result.forces;
    last_mu        = result.stages.back().mu;
    if (!result.tolerance_met)
      {
        report.penetration_tolerance_met = false;
        std::ostringstream status;
        if (result.capped)
          status << "penetration tolerance not met: mu capped at "
                 << result.stages.back().mu
                 << " (Solver > Penalty > Maximum penalty ratio)";
        else
          status << "penetration tolerance not met in "
                 << continuation_parameters.max_stages
                 << " stages (Solver > Penalty > Maximum stages)";
        record.solver_status = status.str();
      }
    return true;
  }

  template <int dim>
  std::vector<Quantity>
  Simulator<dim>::contact_quantities(Report::Step &record)
  {
    std::vector<Quantity> quantities;
    Tensor<1, dim>        total_force;
    std::vector<std::pair<Point<dim>, double>> pressure;
    if (contact)
      {
        const auto summary = contact->summarize(solution_ghosted, contact_forces);
        record.active_nodes      = summary.n_active;
        record.penetration_ratio = summary.max_penetration_ratio;
        total_force              = summary.total_force;
        if (hertz.active())
          pressure = contact->gather_pressure(solution_ghosted, contact_forces);
      }
    else
      {
        const auto summary = two_body->summarize(solution_ghosted, contact_forces);
        record.active_nodes      = summary.n_active;
        record.penetration_ratio = summary.max_penetration_ratio;
        total_force              = summary.total_force;
        record.pairs             = two_body->pair_statistics().last_pairs;
        if (hertz.active())
          pressure = two_body->gather_pressure(solution_ghosted, contact_forces);
      }
    for (unsigned int d = 0; d < dim; ++d)
      record.contact_force_vector[d] = total_force[d];
    const char *axes = "xyz";
    for (unsigned int d = 0; d < dim; ++d)
      {
        Quantity q;
        q.name  = std::string("contact_force_") + axes[d];
        q.value = total_force[d];
        if (d == dim - 1 && hertz.active())
          {
            q.has_reference = true;
            q.reference     = hertz.modelled_fraction * hertz.line_load;
            q.tolerance     = hertz.tolerance_force;
          }
        quantities.push_back(q);
      }
    Quantity active;
    active.name  = "active_contact_nodes";
    active.value = record.active_nodes;
    quantities.push_back(active);
    Quantity penetration;
    penetration.name  = "max_penetration_over_h";
    penetration.value = record.penetration_ratio;
    quantities.push_back(penetration);
    if (hertz.active())
      {
        std::vector<std::pair<double, double>> samples;
        for (const auto &p : pressure)
          samples.emplace_back(p.first[0], p.second);
        for (const auto &q : hertz.quantities(samples))
          quantities.push_back(q);
      }
    std::function<double(const Point<dim> &)> reference;
    if (hertz.active())
      reference = [this](const Point<dim> &x) { return hertz.pressure(x[0]); };
    const std::string profile = output_directory + "/contact_profile.csv";
    if (contact)
      contact->write_profile(profile, solution_ghosted, contact_forces, reference);
    else
      two_body->write_profile(profile, solution_ghosted, contact_forces, reference);
    return quantities;
  }

  template <int dim>
  void
  Simulator<dim>::complete_step(const double                       t,
                                const unsigned int                 step,
                                const NewtonMinimizer::Statistics &stats,
                                Report::Step                      &record,
                                const std::string                 &series)
  {
    report.newton_iterations += stats.iterations;
    record.time              = t;
    record.newton_iterations = stats.iterations;
    record.backtracks        = stats.backtracks;
    record.regularized       = stats.regularized_steps;
    record.linear_iterations = stats.linear_iterations;
    record.linear_fallbacks  = stats.linear_fallbacks;
    record.residual          = stats.residual;
    record.energy            = stats.evaluation.value;
    record.min_J             = stats.evaluation.min_J;
    report.final_time        = t;

    solution_ghosted = solution;
    {
      TimerOutput::Scope scope(*timer, "postprocessing");
      report.quantities = postprocessor->compute_quantities(solution_ghosted, t);
      if (contact || two_body)
        for (const auto &q : contact_quantities(record))
          report.quantities.push_back(q);
      if (report.derivative_test_errors >= 0)
        {
          Quantity q;
          q.name  = "ipopt_derivative_test_errors";
          q.value = report.derivative_test_errors;
          report.quantities.push_back(q);
        }
    }
    report.steps.push_back(record);
    if (!series.empty())
      {
        TimerOutput::Scope scope(*timer, "output");
        postprocessor->write_output(solution_ghosted, t, step, t >= end_time, series);
      }
  }

  template <int dim>
  unsigned int
  Simulator<dim>::refine_mesh()
  {
    TimerOutput::Scope scope(*timer, "refinement");
    using Estimator      = RefinementParameters::Estimator;
    const auto estimator = refinement_parameters.estimator;
    solution_ghosted = solution;
    // The nodal contact pressure behind the contact indicator and zone.
    const Contact::PenaltyTerm<dim> *const term = penalty_term();
    std::vector<double> pressures;
    std::vector<bool>   zone;
    if (term)
      {
        pressures = term->nodal_pressures(solution_ghosted, contact_forces);
        if (refinement_parameters.uniform_zone)
          zone = Refinement::contact_zone(dof_handler,
                                          term->contact_nodes_on_boundary(),
                                          pressures,
                                          refinement_parameters.zone_depth);
      }
    auto contact_indicator = [&]() {
      return Refinement::contact(dof_handler,
                                 term->contact_nodes_on_boundary(),
                                 term->contact_boundary_id(),
                                 pressures);
    };
    Vector<float> indicators;
    if (estimator == Estimator::kelly || !(contact || two_body))
      indicators = Refinement::kelly(*mapping, dof_handler, solution_ghosted);
    else if (estimator == Estimator::contact)
      indicators = contact_indicator();
    else
      {
        // Each indicator scaled by its largest value on any rank.
        indicators = Refinement::kelly(*mapping, dof_handler, solution_ghosted);
        const Vector<float> pressure = contact_indicator();
        const double max_k = Utilities::MPI::max(
          static_cast<double>(indicators.linfty_norm()), comm);
        const double max_c = Utilities::MPI::max(
          static_cast<double>(pressure.linfty_norm()), comm);
        if (max_k > 0.)
          indicators *= static_cast<float>(1. / max_k);
        if (max_c > 0.)
          indicators.add(static_cast<float>(1. / max_c), pressure);
      }
    const unsigned int refined =
      Refinement::mark(triangulation, indicators, refinement_parameters, zone);

    // Transfer the solution: the next solve starts from it.
    parallel::distributed::SolutionTransfer<dim, VectorType> transfer(dof_handler);
    triangulation.prepare_coarsening_and_refinement();
    transfer.prepare_for_coarsening_and_refinement(solution_ghosted);
    triangulation.execute_coarsening_and_refinement();
    setup_dofs();
    transfer.interpolate(solution);
    // New nodes on the Dirichlet boundaries take their prescribed values,
    // hanging nodes follow their parents.
    boundary_constraints(end_time, false).distribute(solution);
    solution_ghosted = solution;
    update_penalty_scale();
    return refined;
  }

  template <int dim>
  const Report &
  Simulator<dim>::run(ParameterHandler &prm)
  {
    const bool root = (Utilities::MPI::this_mpi_process(comm) == 0);
    Timer      run_timer;
    {
      std::string error;
      if (root)
        {
          std::error_code ec;
          std::filesystem::create_directories(output_directory, ec);
          if (ec)
            error = ec.message();
          else
            {
              std::ofstream out(output_directory + "/used_parameters.prm");
              prm.print_parameters(out, ParameterHandler::ShortPRM);
              if (!out)
                error = "cannot write into it";
            }
        }
      error = Utilities::MPI::broadcast(comm, error, 0);
      if (!error.empty())
        throw InputError("Output directory",
                         "cannot create '" + output_directory + "': " + error);
    }

    pcout << "Scene " << report.scene << ": " << dim << "D, "
          << report.n_cells << " cells, " << report.n_dofs << " DoFs (Q"
          << report.degree << "), " << report.n_ranks << " MPI rank(s)"
          << std::endl
          << "Output in " << output_directory << std::endl;

    solution         = 0.;
    solution_ghosted = solution;
    postprocessor->write_output(solution_ghosted, 0., 0, false);

    const double   full_step = end_time / n_steps;
    double         t         = 0.;
    double         dt        = full_step;
    unsigned int   step      = 0;
    unsigned int   cuts      = 0;
    VectorType     backup(solution);
    VectorType     failed_iterate;
    try
      {
        while (t < end_time * (1. - 1e-12))
          {
            double t_new = std::min(t + dt, end_time);
            if (end_time - t_new < 1e-9 * end_time)
              t_new = end_time;
            pcout << "Load step " << step + 1 << ": t = " << t_new
                  << " (dt = " << t_new - t << ")" << std::endl;
            backup = solution;
            NewtonMinimizer::Statistics stats;
            Report::Step                record{};
            const std::vector<double>   backup_forces = contact_forces;
            if (!solve_load_step(t_new, stats, record))
              {
                failed_iterate = solution;
                solution       = backup;
                contact_forces = backup_forces;
                ++cuts;
                ++report.step_cuts;
                dt /= 2.;
                pcout << "  step failed (" << stats.reason << "); cutting to dt = "
                      << dt << std::endl;
                if (dt < min_step_fraction * end_time)
                  {
                    std::ostringstream msg;
                    msg << "the load step from t = " << t << " to t = " << t_new
                        << " failed and the step size fell below the minimum "
                        << min_step_fraction * end_time
                        << " (Load stepping > Minimum step fraction); last "
                           "reason: "
                        << stats.reason;
                    throw SolveFailure(msg.str());
                  }
                continue;
              }
            t = t_new;
            ++step;
            record.cuts_before = cuts;
            cuts               = 0;
            complete_step(t, step, stats, record, "solution");
            // Grow back towards the requested step after easy steps.
            if (stats.iterations <= 5 * std::max<std::size_t>(1, record.stages.size()) &&
                dt < full_step)
              dt = std::min(2. * dt, full_step);
          }
        // Adaptive refinement cycles: the final load again on each new
        // mesh, from the solution transferred from the previous one.
        auto record_cycle = [&](const unsigned int cycle,
                                const unsigned int iterations,
                                const unsigned int refined,
                                const double       cycle_seconds) {
          Report::Cycle c;
          c.cycle             = cycle;
          c.n_cells           = report.n_cells;
          c.n_dofs            = report.n_dofs;
          c.contact_nodes     = report.contact_nodes;
          c.newton_iterations = iterations;
          c.refined_cells     = refined;
          c.h_min             = report.h_min;
          c.cycle_seconds     = cycle_seconds;
          c.wall_seconds =
            setup_seconds + Utilities::MPI::max(run_timer.wall_time(), comm);
          c.quantities = report.quantities;
          for (const auto &entry :
               timer->get_summary_data(TimerOutput::total_wall_time))
            c.timing[entry.first] = Utilities::MPI::max(entry.second, comm);
          report.cycles.push_back(c);
        };
        if (refinement_parameters.cycles > 0)
          {
            record_cycle(0, report.newton_iterations, 0,
                         setup_seconds +
                           Utilities::MPI::max(run_timer.wall_time(), comm));
            TimerOutput::Scope scope(*timer, "output");
            postprocessor->write_output(solution_ghosted, 0, 0, true, "refinement");
          }
        for (unsigned int cycle = 1; cycle <= refinement_parameters.cycles; ++cycle)
          {
            Timer              cycle_timer;
            const unsigned int refined = refine_mesh();
            pcout << "Refinement cycle " << cycle << ": " << refined
                  << " cells refined, " << report.n_cells << " cells, "
                  << report.n_dofs << " DoFs";
            if (contact || two_body)
              pcout << ", " << report.contact_nodes << " contact nodes";
            pcout << std::endl;
            NewtonMinimizer::Statistics stats;
            Report::Step                record{};
            if (!solve_load_step(end_time, stats, record))
              {
                // The previous mesh's solution is the last one on disk.
                std::ostringstream msg;
                msg << "refinement cycle " << cycle << " (" << report.n_dofs
                    << " DoFs) failed at t = " << end_time << ": "
                    << stats.reason;
                throw SolveFailure(msg.str());
              }
            ++step;
            complete_step(end_time, step, stats, record, "");
            {
              TimerOutput::Scope scope(*timer, "output");
              postprocessor->write_output(solution_ghosted, cycle, cycle, true,
                                          "refinement");
            }
            record_cycle(cycle, stats.iterations, refined,
                         Utilities::MPI::max(cycle_timer.wall_time(), comm));
          }
        report.status = "converged";
      }
    catch (const SolveFailure &e)
      {
        report.status = "failed";
        report.reason = e.what();
        // The solver's last iterate of the failed step, for diagnosis (not
        // part of the solution series).
        std::string snapshot;
        if (failed_iterate.size() > 0)
          {
            solution_ghosted = failed_iterate;
            snapshot = postprocessor->write_snapshot(solution_ghosted, "failed_iterate");
            solution_ghosted = solution;
          }
        pcout << "Run failed: " << report.reason << std::endl
              << "The output of the last converged step (t = "
              << report.final_time << ") is in " << output_directory;
        if (!snapshot.empty())
          pcout << "; the solver's last iterate of the failed step is in "
                << snapshot << " there";
        pcout << std::endl;
      }

    {
      Utilities::System::MemoryStats memory;
      Utilities::System::get_memory_stats(memory);
      report.peak_memory_mb =
        Utilities::MPI::max(static_cast<double>(memory.VmHWM) / 1024., comm);
    }
    report.timing["setup"] = setup_seconds;
    report.timing["total"] =
      setup_seconds + Utilities::MPI::max(run_timer.wall_time(), comm);
    for (const auto &entry :
         timer->get_summary_data(TimerOutput::total_wall_time))
      report.timing[entry.first] = Utilities::MPI::max(entry.second, comm);
    write_summary();
    if (postprocessor->verbosity() == "verbose")
      timer->print_summary();
    return report;
  }

  template <int dim>
  void
  Simulator<dim>::write_summary() const
  {
    if (Utilities::MPI::this_mpi_process(comm) != 0)
      return;
    Json j = Json::object();
    j["program"]        = "signorini";
    j["scene"]          = report.scene;
    j["parameter file"] = report.parameter_file;
    j["status"]         = report.status;
    if (!report.reason.empty())
      j["reason"] = report.reason;
    j["dimension"] = report.dimension;
    Json &mesh     = j["mesh"];
    mesh["cells"]  = report.n_cells;
    mesh["dofs"]   = report.n_dofs;
    mesh["polynomial degree"] = report.degree;
    mesh["h min"]  = report.h_min;
    mesh["h max"]  = report.h_max;
    j["mpi ranks"] = report.n_ranks;
    j["peak memory MB"] = report.peak_memory_mb;
    j["threads per rank"] = MultithreadInfo::n_threads();
    Json materials_json = Json::array();
    for (const auto &m : report.materials)
      materials_json.push_back(m);
    j["materials"] = materials_json;
    Json &solver = j["solver"];
    solver["method"]        = report.solver;
    solver["linear solver"] = report.linear_solver;
    j["final time"]              = report.final_time;
    j["load steps"]              = static_cast<unsigned int>(report.steps.size());
    j["step cuts"]               = report.step_cuts;
    // Iterations are Newton's or Ipopt's (also per penalty stage).
    const std::string iterations =
      method == "ipopt" ? "ipopt iterations" : "newton iterations";
    j[iterations] = report.newton_iterations;
    if (contact || two_body)
      {
        Json &c                 = j["contact"];
        c["type"]               = report.contact_type;
        c["boundary id"]        = static_cast<unsigned int>(
          contact ? contact->boundary_id() : two_body->boundary_id());
        c[contact ? "foundation" : "target"] = report.foundation;
        c["nodes"]              = report.contact_nodes;
        c["hanging nodes"] =
          penalty_term()->contact_nodes_on_boundary()
            .n_hanging();
        c["mean mesh size"]     = contact ? contact->mean_mesh_size() :
                                            two_body->mean_mesh_size();
        c["min mesh size"]      = contact ? contact->min_mesh_size() :
                                            two_body->min_mesh_size();
        if (two_body)
          {
            const auto &p    = two_body->parameters();
            const auto &ps   = two_body->pair_statistics();
            c["target boundary id"] = static_cast<unsigned int>(p.target_boundary);
            c["form"]         = p.integral ? "integral" : "nodal";
            if (p.integral)
              c["gauss points per face"] = p.gauss_points;
            c["stretch"]      = p.stretch;
            c["apex depth"]   = p.apex_depth;
            Json &b           = c["broad phase"];
            b["target faces"] = ps.target_faces;
            b["evaluation points"] = ps.points;
            b["evaluated pairs, last evaluation"] = ps.last_pairs;
            b["evaluated pairs, largest"] = ps.max_pairs;
            b["pairs in the sparsity pattern"] = ps.pattern_pairs;
            b["sparsity pattern builds"] = ps.pattern_builds;
          }
        // Penalty continuation: Newton's, or Ipopt's for two bodies.
        if (method == "newton-penalty" || two_body)
          {
            c["initial penalty"]           = report.initial_penalty;
            c["final penalty"]             = last_mu;
            c["penetration tolerance"]     = continuation_parameters.penetration_tolerance;
            c["penetration tolerance met"] = report.penetration_tolerance_met;
          }
        if (!report.steps.empty())
          {
            c["active nodes"]           = report.steps.back().active_nodes;
            c["max penetration over h"] = report.steps.back().penetration_ratio;
          }
      }
    if (incompressibility)
      j["incompressibility constraints"] = report.incompressibility_constraints;
    if (method == "ipopt" && report.derivative_test_errors >= 0)
      j["ipopt derivative test errors"] = report.derivative_test_errors;
    Json steps = Json::array();
    for (const auto &s : report.steps)
      {
        Json o = Json::object();
        o["time"]              = s.time;
        o[iterations]          = s.newton_iterations;
        o["backtracks"]        = s.backtracks;
        o["regularized steps"] = s.regularized;
        o["linear iterations"] = s.linear_iterations;
        o["linear fallbacks"]  = s.linear_fallbacks;
        o["cuts before"]       = s.cuts_before;
        o["residual"]          = s.residual;
        o["energy"]            = s.energy;
        o["min J"]             = s.min_J;
        if (!s.solver_status.empty())
          o["solver status"] = s.solver_status;
        if (!s.stages.empty())
          {
            Json stages = Json::array();
            for (const auto &st : s.stages)
              {
                Json so                 = Json::object();
                so["mu"]                = st.mu;
                so[iterations]          = st.newton_iterations;
                so["max penetration over h"] = st.penetration_ratio;
                if (!st.converged)
                  so["converged"] = false; // tried again with a smaller jump
                stages.push_back(so);
              }
            o["penalty stages"] = stages;
          }
        if (contact || two_body)
          {
            o["active contact nodes"]   = s.active_nodes;
            o["max penetration over h"] = s.penetration_ratio;
            o["contact force"]          = s.contact_force_vector[dim - 1];
            if (two_body)
              o["evaluated pairs"] = s.pairs;
          }
        steps.push_back(o);
      }
    j["steps"] = steps;
    if (refinement_parameters.cycles > 0 || refinement_parameters.band_refinements > 0)
      {
        Json &r = j["mesh refinement"];
        r["estimator"]                = refinement_parameters.estimator_name();
        r["strategy"]                 = refinement_parameters.strategy ==
                                RefinementParameters::Strategy::fraction ?
                                          "fraction" :
                                          "number";
        r["refine fraction"]          = refinement_parameters.refine_fraction;
        r["coarsen fraction"]         = refinement_parameters.coarsen_fraction;
        r["maximum level"]            = refinement_parameters.max_level;
        r["contact band refinements"] = refinement_parameters.band_refinements;
        Json cycles = Json::array();
        for (const auto &c : report.cycles)
          {
            Json o               = Json::object();
            o["cycle"]           = c.cycle;
            o["cells"]           = c.n_cells;
            o["dofs"]            = c.n_dofs;
            o["contact nodes"]   = c.contact_nodes;
            o["refined cells"]   = c.refined_cells;
            o["h min"]           = c.h_min;
            o[iterations]        = c.newton_iterations;
            o["cycle wall time [s]"] = c.cycle_seconds;
            o["wall time since start [s]"] = c.wall_seconds;
            Json q = Json::object();
            for (const auto &qq : c.quantities)
              q[qq.name] = qq.value;
            o["quantities"] = q;
            cycles.push_back(o);
          }
        r["cycles"] = cycles;
      }
    Json quantities = Json::object();
    for (const auto &q : report.quantities)
      {
        Json o     = Json::object();
        o["value"] = q.value;
        if (q.has_reference)
          {
            o["reference"]      = q.reference;
            o["relative error"] = q.relative_error();
            if (q.tolerance > 0.)
              {
                o["tolerance"]        = q.tolerance;
                o["within tolerance"] = q.within_tolerance();
              }
          }
        quantities[q.name] = o;
      }
    j["quantities"] = quantities;
    Json timing     = Json::object();
    for (const auto &t : report.timing)
      timing[t.first] = t.second;
    j["wall time [s]"] = timing;

    std::ofstream out(output_directory + "/summary.json");
    j.write(out);
    out << "\n";

    if (!report.cycles.empty())
      {
        std::ofstream cycles_csv(output_directory + "/refinement_cycles.csv");
        cycles_csv << "cycle,cells,dofs,contact_nodes,refined_cells,h_min,"
                   << (method == "ipopt" ? "ipopt" : "newton")
                   << "_iterations,cycle_wall_time,wall_time_since_start";
        for (const auto &q : report.cycles.front().quantities)
          cycles_csv << "," << q.name;
        cycles_csv << "\n" << std::setprecision(12);
        for (const auto &c : report.cycles)
          {
            cycles_csv << c.cycle << "," << c.n_cells << "," << c.n_dofs << ","
                       << c.contact_nodes << "," << c.refined_cells << ","
                       << c.h_min << "," << c.newton_iterations << ","
                       << c.cycle_seconds << "," << c.wall_seconds;
            for (const auto &q : c.quantities)
              cycles_csv << "," << q.value;
            cycles_csv << "\n";
          }
      }

    std::ofstream csv(output_directory + "/load_steps.csv");
    csv << "step,time," << (method == "ipopt" ? "ipopt" : "newton")
        << "_iterations,backtracks,regularized_steps,"
           "linear_iterations,linear_fallbacks,cuts_before,residual,energy,min_J,"
           "penalty_stages,final_penalty,active_contact_nodes,"
           "max_penetration_over_h,contact_force";
    for (unsigned int d = 0; d < dim; ++d)
      csv << ",contact_force_" << "xyz"[d];
    csv << ",evaluated_pairs\n"
        << std::setprecision(12);
    for (unsigned int i = 0; i < report.steps.size(); ++i)
      {
        const auto &s = report.steps[i];
        csv << i + 1 << "," << s.time << "," << s.newton_iterations << ","
            << s.backtracks << "," << s.regularized << ","
            << s.linear_iterations << "," << s.linear_fallbacks << ","
            << s.cuts_before << ","
            << s.residual << "," << s.energy << "," << s.min_J << ","
            << s.stages.size() << ","
            << (s.stages.empty() ? 0. : s.stages.back().mu) << ","
            << s.active_nodes << "," << s.penetration_ratio << ","
            << s.contact_force_vector[dim - 1];
        for (unsigned int d = 0; d < dim; ++d)
          csv << "," << s.contact_force_vector[d];
        csv << "," << s.pairs << "\n";
      }
  }

  template class Simulator<2>;
  template class Simulator<3>;
} // namespace Signorini
