#include <signorini/input_error.h>
#include <signorini/simulator.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/multithread_info.h>
#include <deal.II/base/utilities.h>
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
                      Patterns::Selection("newton"),
                      "newton: Newton's method on the total potential "
                      "energy with an Armijo line search.");
    prm.enter_subsection("Newton");
    NewtonMinimizer::Parameters::declare_parameters(prm);
    prm.leave_subsection();
    prm.enter_subsection("Linear solver");
    LinearSolver::Parameters::declare_parameters(prm);
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
    prm.enter_subsection("Newton");
    newton_parameters.parse_parameters(prm);
    prm.leave_subsection();
    prm.enter_subsection("Linear solver");
    linear_parameters.parse_parameters(prm);
    report.linear_solver = linear_parameters.name();
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

    fe      = std::make_unique<FESystem<dim>>(FE_Q<dim>(report.degree), dim);
    mapping = std::make_unique<MappingQ<dim>>(report.degree);
    energy  = std::make_unique<EnergyFunctional<dim>>(dof_handler, *mapping,
                                                     materials, bc);
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
    setup_dofs();
    timer = std::make_unique<TimerOutput>(comm, pcout, TimerOutput::never,
                                          TimerOutput::wall_times);
    setup_seconds = Utilities::MPI::max(setup_timer.wall_time(), comm);
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

    TrilinosWrappers::SparsityPattern sparsity(locally_owned,
                                               locally_owned,
                                               locally_relevant,
                                               comm);
    DoFTools::make_sparsity_pattern(dof_handler,
                                    sparsity,
                                    homogeneous_constraints,
                                    false,
                                    Utilities::MPI::this_mpi_process(comm));
    sparsity.compress();
    hessian.reinit(sparsity);
    solution.reinit(locally_owned, comm);
    solution_ghosted.reinit(locally_owned, locally_relevant, comm);
    rhs.reinit(locally_owned, comm);

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
    report.h_max = Utilities::MPI::max(h_max, comm);
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
                                  NewtonMinimizer::Statistics &stats)
  {
    EnergyObjective<dim> objective(*energy, time);
    NewtonMinimizer newton(newton_parameters, *linear_solver, progress, *timer);
    if (has_prescribed_motion)
      {
        solution_ghosted = solution;
        const AffineConstraints<double> increment = increment_constraints(time);
        std::string                     reason;
        if (!newton.predictor(objective, increment, solution, solution_ghosted,
                              hessian, rhs, reason))
          {
            stats.reason = "predictor: " + reason;
            return false;
          }
      }
    stats = newton.minimize(objective, homogeneous_constraints, solution,
                            solution_ghosted, hessian, rhs);
    return stats.converged;
  }

  template <int dim>
  const Report &
  Simulator<dim>::run(ParameterHandler &prm)
  {
    const bool root = (Utilities::MPI::this_mpi_process(comm) == 0);
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
            if (!solve_load_step(t_new, stats))
              {
                solution = backup;
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
            report.newton_iterations += stats.iterations;
            report.steps.push_back({t,
                                    stats.iterations,
                                    stats.backtracks,
                                    stats.regularized_steps,
                                    stats.linear_iterations,
                                    cuts,
                                    stats.residual,
                                    stats.evaluation.value,
                                    stats.evaluation.min_J});
            cuts = 0;
            report.final_time = t;

            solution_ghosted = solution;
            {
              TimerOutput::Scope scope(*timer, "postprocessing");
              report.quantities =
                postprocessor->compute_quantities(solution_ghosted, t);
            }
            {
              TimerOutput::Scope scope(*timer, "output");
              postprocessor->write_output(solution_ghosted, t, step,
                                          t >= end_time);
            }
            // Grow back towards the requested step after easy steps.
            if (stats.iterations <= 5 && dt < full_step)
              dt = std::min(2. * dt, full_step);
          }
        report.status = "converged";
      }
    catch (const SolveFailure &e)
      {
        report.status = "failed";
        report.reason = e.what();
        pcout << "Run failed: " << report.reason << std::endl
              << "The output of the last converged step (t = "
              << report.final_time << ") is in " << output_directory
              << std::endl;
      }

    report.timing["setup"] = setup_seconds;
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
    j["newton iterations"]       = report.newton_iterations;
    Json steps = Json::array();
    for (const auto &s : report.steps)
      {
        Json o = Json::object();
        o["time"]              = s.time;
        o["newton iterations"] = s.newton_iterations;
        o["backtracks"]        = s.backtracks;
        o["regularized steps"] = s.regularized;
        o["linear iterations"] = s.linear_iterations;
        o["cuts before"]       = s.cuts_before;
        o["residual"]          = s.residual;
        o["energy"]            = s.energy;
        o["min J"]             = s.min_J;
        steps.push_back(o);
      }
    j["steps"] = steps;
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

    std::ofstream csv(output_directory + "/load_steps.csv");
    csv << "step,time,newton_iterations,backtracks,regularized_steps,"
           "linear_iterations,cuts_before,residual,energy,min_J\n"
        << std::setprecision(12);
    for (unsigned int i = 0; i < report.steps.size(); ++i)
      {
        const auto &s = report.steps[i];
        csv << i + 1 << "," << s.time << "," << s.newton_iterations << ","
            << s.backtracks << "," << s.regularized << ","
            << s.linear_iterations << "," << s.cuts_before << ","
            << s.residual << "," << s.energy << "," << s.min_J << "\n";
      }
  }

  template class Simulator<2>;
  template class Simulator<3>;
} // namespace Signorini
