#include <signorini/archive_io.h>
#include <signorini/driver/checkpoint.h>
#include <signorini/driver/mpi_environment.h>
#include <signorini/driver/simulator.h>
#include <signorini/first_error.h>
#include <signorini/input_error.h>
#include <signorini/interruption.h>
#include <signorini/output/atomic_file.h>
#include <signorini/output/contact_report.h>
#include <signorini/output/error_estimate.h>
#include <signorini/output/summary.h>
#include <signorini/problem/support.h>
#include <signorini/scene/refinement.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <cerrno>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace Signorini
{
  template <int dim>
  Simulator<dim>::Simulator(ParameterHandler  &prm,
                            const std::string &parameter_file,
                            const bool         quiet,
                            MPI_Comm           comm,
                            const std::string &restart_checkpoint)
    : comm(comm)
    , pcout(std::cout, Utilities::MPI::this_mpi_process(comm) == 0 && !quiet)
    , progress(std::cout, false)
  {
    Timer setup_timer;
    parameters.parse_parameters(prm, parameter_file);
    check_solver_compatibility(parameters, Utilities::MPI::n_mpi_processes(comm));
    report.parameter_file   = parameter_file;
    report.dimension        = dim;
    report.n_ranks          = Utilities::MPI::n_mpi_processes(comm);
    report.mpi_settings     = MpiEnvironment::applied();
    report.scene            = parameters.global.scene;
    report.output_directory = parameters.global.output_directory;
    report.degree           = parameters.discretization.degree;
    report.solver           = Parameters::selection_name(parameters.solver.method,
                                                  Parameters::Solver::methods());
    report.linear_solver    = parameters.solver.linear.name();
    report.iterative_linear_solver =
      parameters.solver.linear.type != LinearSolver::Parameters::Type::direct;
    for (const auto &body : parameters.bodies)
      report.materials.push_back(body.material->name());

    restart_folder = restart_checkpoint;
    if (!restart_folder.empty())
      {
        const auto header = Checkpoint::read_header(restart_folder);
        mesh_as_built     = header.mesh_as_built;
        refined_back      = header.refined_back;
      }
    scene = std::make_unique<Scene<dim>>(
      parameters, comm,
      mesh_as_built ? "" : Checkpoint::mesh_file(restart_folder));
    problem = std::make_unique<Problem<dim>>(parameters, *scene);
    Contact::Model<dim> *const contact = problem->contact.get();
    const auto                &refinement = parameters.refinement;
    if (refinement.band_refinements > 0 && mesh_as_built)
      {
        if (!contact)
          throw InputError("Mesh refinement > Contact band refinements",
                           "refines near the contact boundary, but the scene "
                           "declares no contact (Contact > Type)");
        Refinement::refine_contact_band(scene->triangulation,
                                        contact->band_surfaces(),
                                        refinement);
      }
    if (refinement.coarser_mesh_estimate && mesh_as_built)
      {
        // The load path on the coarser mesh; refinement_cycles() refines
        // these cells back. Both meshes count as built: a restart repeats
        // the same steps, which number the cells and DoFs the same way (a
        // mesh loaded from the checkpoint would not, after coarsening).
        coarsened_parents = Refinement::coarsen_once(scene->triangulation);
        if (coarsened_parents.empty())
          throw InputError("Mesh refinement > Estimate from a coarser mesh",
                           "no cell of the mesh can be coarsened: it has no "
                           "refinement level (Mesh > Global refinements and "
                           "Local refinements are 0, or the mesh file's cells "
                           "are all coarse cells)");
        if (refined_back)
          {
            Refinement::mark_cells(scene->triangulation, coarsened_parents);
            scene->triangulation.prepare_coarsening_and_refinement();
            scene->triangulation.execute_coarsening_and_refinement();
          }
      }
    postprocessor = std::make_unique<Postprocessor<dim>>(parameters.postprocess,
                                                         scene->dof_handler,
                                                         *scene->mapping,
                                                         scene->materials,
                                                         *problem->energy,
                                                         scene->hanging_constraints,
                                                         scene->boundary_ids,
                                                         report.output_directory);
    const bool talk = (Utilities::MPI::this_mpi_process(comm) == 0) && !quiet &&
                      postprocessor->verbosity() !=
                        PostprocessParameters::Verbosity::quiet;
    pcout.set_condition(talk);
    progress.set_condition(talk);
    // Each rank times its own phases (summary.json takes the largest over
    // the ranks, phase_times()). A TimerOutput on `comm` would reduce over
    // the ranks at the end of every section, so that an exception leaving
    // a section on one rank only would send a collective the other ranks
    // are not in.
    timer = std::make_unique<TimerOutput>(MPI_COMM_SELF, pcout, TimerOutput::never,
                                          TimerOutput::wall_times);
    try
      {
        solver = create_step_solver(parameters, *scene, *problem, *timer, progress);
        report.iteration_name = solver->iteration_name();
        scene->setup_dofs(contact);
        setup_dofs();
        if (!restart_folder.empty())
          restore(restart_folder);
      }
    catch (...)
      {
        timer.reset(); // quietly, while the exception is caught
        throw;
      }
    load_steps = std::make_unique<LoadStepTable>(
      report.output_directory, Utilities::MPI::this_mpi_process(comm) == 0,
      parameters.contact.friction.active(),
      contact ? contact->part_columns() : std::vector<std::string>());
    if (contact)
      {
        if (restart_folder.empty())
          contact->check_initial_state(scene->solution_ghosted);
        postprocessor->extra_fields = [this, contact](DataOut<dim> &data_out) {
          contact->samples().add_output_fields(data_out, scene->solution_ghosted,
                                                contact->forces());
          if (problem->friction)
            problem->friction->add_output_fields(data_out, scene->solution_ghosted);
        };
      }
    setup_seconds = Utilities::MPI::max(setup_timer.wall_time(), comm);
  }

  template <int dim>
  void
  Simulator<dim>::setup_dofs()
  {
    problem->setup_constraints();
    solver->setup();
    report.n_cells       = scene->n_cells;
    report.n_dofs        = scene->n_dofs;
    report.h_min         = scene->h_min;
    report.h_max         = scene->h_max;
    report.contact_nodes = problem->contact ? problem->contact->n_global_nodes() : 0;
  }

  namespace
  {
    /**
     * The converged steps of the load path that a step to load time @p t
     * continues: those after the last fall of the load time. A refinement
     * cycle with friction runs the path again from rest, so that the
     * friction's records summed or followed along the path (the
     * dissipated energy, Mindlin's load path) start again with it; a
     * step whose time is below the last step's starts a path of its own.
     */
    std::vector<Report::Step>
    path_steps(const std::vector<Report::Step> &steps, const double t)
    {
      if (!steps.empty() && t < steps.back().time)
        return {};
      std::size_t first = steps.size();
      while (first > 0 && (first == steps.size() ||
                           steps[first - 1].time <= steps[first].time))
        --first;
      return std::vector<Report::Step>(steps.begin() + first, steps.end());
    }
  } // namespace

  template <int dim>
  void
  Simulator<dim>::complete_step(const double                       t,
                                const unsigned int                 step,
                                const StepStatistics              &stats,
                                Report::Step                      &record,
                                const std::string                 &series)
  {
    report.iterations += stats.iterations;
    record.time              = t;
    record.iterations = stats.iterations;
    record.backtracks        = stats.backtracks;
    record.regularized       = stats.regularized_steps;
    record.linear_iterations = stats.linear_iterations;
    record.linear_solves     = stats.linear_solves;
    record.linear_fallbacks  = stats.linear_fallbacks;
    // The solver's count since it was made (setup keeps it; a restart
    // starts it again at 0).
    const unsigned int builds = solver->n_preconditioner_builds();
    record.amg_builds         = builds - std::min(builds, amg_builds_counted);
    amg_builds_counted        = builds;
    record.residual          = stats.residual;
    record.energy            = stats.evaluation.value;
    record.min_J             = stats.evaluation.min_J;
    report.final_time        = t;

    VectorType &u = scene->solution_ghosted;
    u             = scene->solution;
    {
      TimerOutput::Scope scope(*timer, "postprocessing");
      report.quantities = postprocessor->compute_quantities(u, t);
      if (problem->contact)
        for (const auto &q :
             contact_quantities(*problem->contact, parameters.contact.hertz, u,
                                record,
                                report.output_directory + "/contact_profile.csv",
                                problem->friction.get(),
                                path_steps(report.steps, t)))
          report.quantities.push_back(q);
      solver->add_quantities(report.quantities);
    }
    report.steps.push_back(record);
    load_steps->append(report.steps.size(), record, dim);
    if (!series.empty())
      {
        TimerOutput::Scope scope(*timer, "output");
        postprocessor->write_output(u, t, step,
                                    t >= parameters.load_stepping.end_time,
                                    series);
      }
  }


  template <int dim>
  void
  Simulator<dim>::load_path(const Timer       &run_timer,
                            const std::string &series,
                            const unsigned int cycle)
  {
    const double end_time  = parameters.load_stepping.end_time;
    const double full_step = end_time / parameters.load_stepping.n_steps;
    dt                     = (dt > 0. ? std::min(dt, full_step) : full_step);
    const double start_time    = time;
    const double start_elapsed = elapsed(run_timer);
    unsigned int cuts          = 0;
    // Steps converged in a row at the current (cut) step size.
    unsigned int since_cut     = 0;
    VectorType  &solution      = scene->solution;
    VectorType   backup(solution);
    while (time < end_time * (1. - 1e-12))
      {
        // After a cut the steps still land on the requested times (the
        // multiples of End time / Number of steps): a cut step is made up
        // within its own interval, so that a path's corner (e.g. the end
        // of an indentation before a slide) and the requested output times
        // are not stepped over.
        const double next_requested =
          full_step * std::ceil(time / full_step * (1. + 1e-12) + 1e-9);
        double t_new = std::min({time + dt, next_requested, end_time});
        if (end_time - t_new < 1e-9 * end_time)
          t_new = end_time;
        std::ostringstream what;
        what << "load step " << step + 1 << " (t = " << t_new << ")";
        activity = what.str();
        Interruption::throw_if_requested(comm);
        pcout << "Load step " << step + 1 << ": t = " << t_new
              << " (dt = " << t_new - time << ")" << std::endl;
        backup = solution;
        StepStatistics              stats;
        Report::Step                record{};
        std::vector<double>         backup_forces;
        if (problem->contact)
          backup_forces = problem->contact->forces();
        if (!solver->solve_step(t_new, stats, record))
          {
            failed_iterate = solution;
            solution       = backup;
            if (problem->contact)
              problem->contact->set_contact_forces(backup_forces);
            ++cuts;
            ++report.step_cuts;
            since_cut = 0;
            dt /= 2.;
            pcout << "  step failed (" << stats.reason << "); cutting to dt = "
                  << dt << std::endl;
            const double min_step =
              parameters.load_stepping.min_step_fraction * end_time;
            if (dt < min_step)
              {
                std::ostringstream msg;
                msg << "the load step from t = " << time << " to t = " << t_new
                    << " failed and the step size fell below the minimum "
                    << min_step
                    << " (Load stepping > Minimum step fraction); last "
                       "reason: "
                    << stats.reason;
                throw SolveFailure(msg.str());
              }
            continue;
          }
        time = t_new;
        ++step;
        record.cuts_before = cuts;
        cuts               = 0;
        complete_step(time, step, stats, record, series);
        // Grow back towards the requested step after an easy step, or
        // after two steps in a row at the cut size: a cut is for a hard
        // stretch of the path, not for the rest of it (otherwise one cut
        // early in a long path, where each step takes many iterations,
        // multiplies its step count).
        ++since_cut;
        if (dt < full_step &&
            (stats.iterations <= 5 * std::max<std::size_t>(1, record.stages.size()) ||
             since_cut >= 2))
          {
            dt        = std::min(2. * dt, full_step);
            since_cut = 0;
          }
        snapshot();
        checkpoint(run_timer, false);

        // Elapsed time and a linear estimate of the time left, on the
        // screen and in progress.json.
        const double spent = elapsed(run_timer);
        const double left  = (time > start_time) ?
                               (spent - start_elapsed) / (time - start_time) *
                                 (end_time - time) :
                               0.;
        pcout << "  converged; " << std::fixed << std::setprecision(1) << spent
              << " s elapsed, about " << left << " s left in the load path"
              << std::defaultfloat << std::setprecision(6) << std::endl;
        if (Utilities::MPI::this_mpi_process(comm) == 0)
          write_progress(report.output_directory, "running", time, end_time,
                         step, cycle, spent, left);
      }
  }

  template <int dim>
  std::map<std::string, double>
  Simulator<dim>::phase_times() const
  {
    std::map<std::string, double> times = previous_times;
    times.erase("total");
    times.erase("setup");
    for (const auto &entry : timer->get_summary_data(TimerOutput::total_wall_time))
      times[entry.first] += Utilities::MPI::max(entry.second, comm);
    return times;
  }

  template <int dim>
  double
  Simulator<dim>::elapsed(const Timer &run_timer) const
  {
    const auto previous = previous_times.find("total");
    return (previous == previous_times.end() ? 0. : previous->second) +
           setup_seconds + Utilities::MPI::max(run_timer.wall_time(), comm);
  }

  template <int dim>
  std::map<std::string, double>
  Simulator<dim>::run_times(const Timer &run_timer) const
  {
    auto       times          = phase_times();
    const auto previous_setup = previous_times.find("setup");
    times["setup"] =
      (previous_setup == previous_times.end() ? 0. : previous_setup->second) +
      setup_seconds;
    times["total"] = elapsed(run_timer);
    return times;
  }

  template <int dim>
  Report
  Simulator<dim>::resumed_report() const
  {
    Report r = resume.report;
    r.steps.assign(report.steps.begin(), report.steps.begin() + resume.n_steps);
    r.cycles.assign(report.cycles.begin(), report.cycles.begin() + resume.n_cycles);
    return r;
  }

  template <int dim>
  void
  Simulator<dim>::refinement_cycles(const Timer &run_timer)
  {
    const bool         back_to_scene_mesh = parameters.refinement.coarser_mesh_estimate;
    const unsigned int n_cycles = back_to_scene_mesh ? 1 : parameters.refinement.cycles;
    if (n_cycles == 0)
      return;
    const double end_time     = parameters.load_stepping.end_time;
    auto         record_cycle = [&](const unsigned int cycle,
                            const unsigned int iterations,
                            const unsigned int refined,
                            const double       cycle_seconds) {
      Report::Cycle c;
      c.cycle             = cycle;
      c.n_cells           = report.n_cells;
      c.n_dofs            = report.n_dofs;
      c.contact_nodes     = report.contact_nodes;
      c.iterations = iterations;
      c.refined_cells     = refined;
      c.h_min             = report.h_min;
      c.cycle_seconds     = cycle_seconds;
      c.wall_seconds      = elapsed(run_timer);
      c.quantities        = report.quantities;
      c.timing            = phase_times();
      report.cycles.push_back(c);
      estimate_errors();
      summary(); // a run killed from outside keeps its finished cycles
    };
    if (!report.cycles.empty())
      {
        // A restart: whether its cycles met the target, from the last
        // cycle's quantities (a restart inside a cycle's load path, with
        // friction, holds those of a step of that path).
        report.quantities = report.cycles.back().quantities;
        estimate_errors();
      }
    if (report.cycles.empty())
      {
        record_cycle(0, report.iterations, 0, elapsed(run_timer));
        {
          TimerOutput::Scope scope(*timer, "output");
          postprocessor->write_output(scene->solution_ghosted, 0, 0, true, "refinement");
        }
        snapshot();
        checkpoint(run_timer, false);
      }
    for (unsigned int cycle = report.cycles.size(); cycle <= n_cycles; ++cycle)
      {
        if (report.target_met)
          {
            pcout << "Target accuracy " << report.target_accuracy
                  << " met after refinement cycle " << cycle - 1 << std::endl;
            break;
          }
        activity = "refinement cycle " + std::to_string(cycle);
        Interruption::throw_if_requested(comm);
        Timer cycle_timer;
        if (!mesh_ready)
          {
            {
              // The frame being written reads the mesh, the DoFs and the
              // mapping that the refinement replaces.
              TimerOutput::Scope output_scope(*timer, "output");
              postprocessor->flush();
            }
            TimerOutput::Scope scope(*timer, "refinement");
            scene->solution_ghosted = scene->solution;
            refined_cells =
              back_to_scene_mesh ?
                Refinement::mark_cells(scene->triangulation, coarsened_parents) :
                Refinement::estimate_and_mark(scene->triangulation,
                                              *scene->mapping,
                                              scene->dof_handler,
                                              problem->contact.get(),
                                              scene->solution_ghosted,
                                              parameters.refinement);
            scene->refine_and_transfer(problem->contact.get(), end_time);
            setup_dofs();
            // With friction the cycle runs the load path from rest: the
            // state a checkpoint of the new mesh keeps (the friction
            // history of the old mesh's nodes has no place on it).
            if (problem->friction)
              start_path();
            if (back_to_scene_mesh)
              refined_back = true;
            else
              mesh_as_built = false;
            // A new mesh: what an interruption of this cycle's solve
            // saves and a restart continues from.
            mesh_ready = true;
            snapshot();
            checkpoint(run_timer, false);
          }
        pcout << "Refinement cycle " << cycle
              << (back_to_scene_mesh ? " (back to the scene's mesh)" : "") << ": "
              << refined_cells << " cells refined, " << report.n_cells << " cells, "
              << report.n_dofs << " DoFs";
        if (problem->contact)
          pcout << ", " << report.contact_nodes << " contact nodes";
        if (problem->friction)
          pcout << "; with friction the load path again from rest";
        pcout << std::endl;
        unsigned int iterations = 0;
        if (problem->friction)
          {
            // The whole path from rest on the new mesh (start_path()
            // above; a restart in the middle of it continues it).
            try
              {
                load_path(run_timer, "", cycle);
              }
            catch (const SolveFailure &e)
              {
                throw SolveFailure("refinement cycle " + std::to_string(cycle) + " (" +
                                   std::to_string(report.n_dofs) +
                                   " DoFs), its load path from rest: " + e.what());
              }
            for (const auto &s : path_steps(report.steps, end_time))
              iterations += s.iterations;
          }
        else
          {
            StepStatistics stats;
            Report::Step   record{};
            if (!solver->solve_step(end_time, stats, record))
              {
                // The previous mesh's solution is the last one on disk.
                std::ostringstream msg;
                msg << "refinement cycle " << cycle << " (" << report.n_dofs
                    << " DoFs) failed at t = " << end_time << ": " << stats.reason;
                throw SolveFailure(msg.str());
              }
            ++step;
            complete_step(end_time, step, stats, record, "");
            iterations = stats.iterations;
          }
        mesh_ready = false;
        {
          TimerOutput::Scope scope(*timer, "output");
          postprocessor->write_output(scene->solution_ghosted, cycle, cycle,
                                      true, "refinement");
        }
        record_cycle(cycle, iterations, refined_cells,
                     Utilities::MPI::max(cycle_timer.wall_time(), comm));
        snapshot();
        checkpoint(run_timer, false);
        const double spent = elapsed(run_timer); // collective
        if (Utilities::MPI::this_mpi_process(comm) == 0)
          write_progress(report.output_directory, "running", time, end_time,
                         step, cycle, spent, 0.);
      }
  }

  template <int dim>
  void
  Simulator<dim>::start_path()
  {
    // As run() starts the first path: at rest, the contact model's force
    // record zero (its setup() on the new mesh made it so).
    scene->solution         = 0.;
    scene->solution_ghosted = scene->solution;
    time                    = 0.;
    dt                      = 0.;
    if (problem->contact)
      problem->contact->set_contact_forces(
        std::vector<double>(problem->contact->forces().size(), 0.));
    if (problem->friction)
      problem->friction->reset();
    solver->start_path();
  }

  template <int dim>
  void
  Simulator<dim>::estimate_errors()
  {
    std::vector<double>                h;
    std::vector<std::vector<Quantity>> per_mesh;
    for (const auto &c : report.cycles)
      {
        h.push_back(c.h_min);
        per_mesh.push_back(c.quantities);
      }
    ErrorEstimate::add_estimates(h, per_mesh, report.quantities);
    if (!report.cycles.empty())
      report.cycles.back().quantities = report.quantities;

    const auto &refinement = parameters.refinement;
    report.target_accuracy = refinement.target_accuracy;
    if (refinement.target_accuracy <= 0.)
      return;
    std::vector<std::string> names = refinement.target_quantities;
    if (names.empty())
      for (const auto &q : report.quantities)
        if (q.estimable)
          names.push_back(q.name);
    report.target_unmet.clear();
    for (const auto &name : names)
      {
        const auto q = std::find_if(report.quantities.begin(),
                                    report.quantities.end(),
                                    [&](const Quantity &q) { return q.name == name; });
        if (q == report.quantities.end() || !q->estimable)
          {
            std::string estimable;
            for (const auto &other : report.quantities)
              if (other.estimable)
                estimable += (estimable.empty() ? "" : ", ") + other.name;
            throw InputError("Mesh refinement > Target quantities",
                             "'" + name + "' is not " +
                               (q == report.quantities.end() ?
                                  "a quantity of this scene" :
                                  "a quantity with an error estimate") +
                               "; this scene estimates: " + estimable);
          }
        // Two meshes give an estimate of an assumed order only: the
        // target needs the safeguarded one of three.
        if (!q->has_estimate || q->estimate_meshes < 3 ||
            q->estimated_relative_error() > refinement.target_accuracy)
          report.target_unmet.push_back(name);
      }
    report.target_met = report.target_unmet.empty();
  }

  template <int dim>
  void
  Simulator<dim>::snapshot()
  {
    resume.time          = time;
    resume.dt            = dt;
    resume.step          = step;
    resume.mesh_ready    = mesh_ready;
    resume.mesh_as_built = mesh_as_built;
    resume.refined_back  = refined_back;
    resume.refined_cells = refined_cells;
    // The step and cycle records only grow from here: keep their counts,
    // not a copy of them at every step.
    resume.n_steps  = report.steps.size();
    resume.n_cycles = report.cycles.size();
    {
      std::vector<Report::Step>  steps;
      std::vector<Report::Cycle> cycles;
      std::swap(steps, report.steps);
      std::swap(cycles, report.cycles);
      resume.report = report;
      std::swap(steps, report.steps);
      std::swap(cycles, report.cycles);
    }
    resume.solution      = VectorType(scene->solution);
    resume.pattern       = VectorType(scene->pattern_state);
    {
      std::ostringstream out;
      resume.mesh_state = MeshState();
      {
        OutputArchive archive(out);
        if (problem->contact)
          problem->contact->save_state(archive, resume.mesh_state);
        if (problem->friction)
          problem->friction->save_state(archive, resume.mesh_state);
        solver->save_state(archive, resume.mesh_state);
        postprocessor->save_state(archive);
      }
      resume.parts = out.str();
    }
    resume.file_sizes.clear();
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      for (const std::string name : {"load_steps.csv", "reactions.csv"})
        {
          const std::string file = report.output_directory + "/" + name;
          std::error_code   ec;
          const auto        size = std::filesystem::file_size(file, ec);
          if (!ec)
            resume.file_sizes[name] = size;
        }
  }

  namespace
  {
    /// Why @p folder's file system cannot take @p needed bytes ("" if it
    /// can, or if its free space cannot be told).
    std::string
    space_shortfall(const std::string &folder, const double needed)
    {
      std::error_code ec;
      const auto      space = std::filesystem::space(folder, ec);
      if (ec || static_cast<double>(space.available) >= needed)
        return "";
      std::ostringstream text;
      text << std::setprecision(3) << "its file system has "
           << space.available / 1e6 << " MB free, the checkpoint needs about "
           << needed / 1e6 << " MB";
      return text.str();
    }
  } // namespace

  template <int dim>
  void
  Simulator<dim>::checkpoint(const Timer &run_timer, const bool force)
  {
    ++steps_since_checkpoint;
    if (!force)
      {
        if (!periodic_checkpoints)
          return;
        const double minutes = parameters.checkpoint.every_minutes;
        if (steps_since_checkpoint < parameters.checkpoint.every_steps &&
            !(minutes > 0. &&
              elapsed(run_timer) - last_checkpoint_time >= 60. * minutes))
          return;
      }
    {
      // The snapshot names the field frame still being written: it is on
      // disk, and in its records, before the checkpoint is.
      TimerOutput::Scope scope(*timer, "output");
      postprocessor->flush();
    }
    TimerOutput::Scope scope(*timer, "checkpoint");
    const bool         root   = Utilities::MPI::this_mpi_process(comm) == 0;
    const std::string &output = report.output_directory;
    const unsigned int sequence = checkpoint_sequence;
    const std::string  final_folder = Checkpoint::folder(output, sequence);
    const std::string  folder =
      Checkpoint::root(output) + "/.writing-" + std::to_string(sequence);
    // A checkpoint that cannot be written ends the run as a failed output:
    // summary.json says why, and the last checkpoint and field frames stay.
    auto collective_check = [&](std::string error, const std::string &what) {
      error = Utilities::MPI::broadcast(comm, error, 0);
      if (!error.empty())
        throw OutputFailure("cannot " + what + " the checkpoint " +
                            final_folder + ": " + error);
    };
    // The state on nodes and cells as fields on the mesh: vectors on the
    // DoFs and values per active cell.
    const MeshState   &mesh_state = resume.mesh_state;
    const unsigned int n_dof_fields  = mesh_state.dof_entries.size();
    const unsigned int n_cell_fields = mesh_state.cell_entries.size();
    const std::vector<VectorType> fields =
      mesh_state.dof_vectors(scene->locally_owned, comm);
    const std::vector<Vector<double>> cell_fields =
      mesh_state.cell_vectors(scene->triangulation.n_active_cells());
    std::vector<const VectorType *> dof_fields;
    for (const auto &f : fields)
      dof_fields.push_back(&f);
    std::vector<const Vector<double> *> cell_vectors;
    for (const auto &f : cell_fields)
      cell_vectors.push_back(&f);
    std::size_t n_entries = 0;
    for (const auto &f : mesh_state.dof_entries)
      n_entries += f.size();
    for (const auto &f : mesh_state.cell_entries)
      n_entries += f.size();
    n_entries = Utilities::MPI::sum(n_entries, comm);
    const double field_bytes =
      n_dof_fields + n_cell_fields > 0 ?
        static_cast<double>(scene->field_bytes(dof_fields, cell_vectors)) :
        0.;
    {
      std::string error;
      if (root)
        {
          std::error_code ec;
          std::filesystem::remove_all(folder, ec);
          std::filesystem::create_directories(folder, ec);
          if (ec)
            error = ec.message();
          else
            {
              // p4est aborts the whole process when it cannot write the
              // mesh (MPI-IO on a full disk), so the space is checked
              // first, against a bound on what the checkpoint writes: the
              // mesh (p4est's quadrants, 12 bytes a cell here), the two
              // vectors on each cell (deal.II's fixed-size data), the
              // fields on the cells where they are not zero
              // (variable-size data, with its size per cell), each
              // rank's state file (the two vectors, the fields' entries
              // and the report) and the parameters, with a quarter more.
              const double cells    = static_cast<double>(scene->n_cells);
              const double per_cell =
                32. + 16. + 2. * 8. * scene->dof_handler.get_fe().n_dofs_per_cell();
              const double needed =
                1.25 * (cells * per_cell + 2. * 8. * static_cast<double>(scene->n_dofs) +
                        (field_bytes > 0. ? 4. * cells + field_bytes : 0.) +
                        16. * static_cast<double>(n_entries) +
                        2048. * (report.steps.size() + report.cycles.size()) +
                        used_parameters.size() + 65536. * report.n_ranks);
              error = space_shortfall(folder, needed);
              if (!error.empty())
                std::filesystem::remove_all(folder, ec);
            }
        }
      collective_check(error, "create");
    }

    scene->save(Checkpoint::mesh_file(folder), {&resume.solution, &resume.pattern},
                dof_fields, cell_vectors);

    Checkpoint::Header header;
    header.dimension      = dim;
    header.n_ranks        = Utilities::MPI::n_mpi_processes(comm);
    header.sequence       = sequence;
    header.parameter_file = report.parameter_file;
    header.parameters     = used_parameters;
    header.mesh_as_built  = resume.mesh_as_built;
    header.refined_back   = resume.refined_back;
    header.n_dof_fields   = n_dof_fields;
    header.n_cell_fields  = n_cell_fields;
    Report saved          = resumed_report();
    saved.timing          = run_times(run_timer);
    {
      // A write error throws from the archive, or leaves the stream
      // failed, on this rank only: its reason (the file, and the system's
      // word for what went wrong) becomes every rank's failure, named
      // after the lowest rank that met one.
      const std::string file =
        Checkpoint::state_file(folder, Utilities::MPI::this_mpi_process(comm));
      std::string error;
      try
        {
          errno = 0;
          std::ofstream out(file, std::ios::binary);
          {
            OutputArchive archive(out);
            archive << header;
            archive << resume.time << resume.dt << resume.step
                    << resume.mesh_ready << resume.refined_cells << saved
                    << resume.file_sizes << resume.parts;
            // This rank's entries of the vectors and of the fields, for a
            // restart on as many ranks on a mesh built as before (the
            // same DoF numbering and cells).
            std::vector<double> values;
            for (const VectorType *v : {&resume.solution, &resume.pattern})
              {
                values.clear();
                for (const auto i : scene->locally_owned)
                  values.push_back((*v)[i]);
                archive << values;
              }
            archive << mesh_state.dof_entries << mesh_state.cell_entries;
          }
          out.close();
          if (!out)
            error = write_failure(file);
        }
      catch (const std::exception &)
        {
          // The archive on a stream that failed (to open, or to write).
          error = write_failure(file);
        }
      error = first_error(comm, error);
      if (!error.empty())
        {
          // Nothing half written stays (and its space is free for
          // summary.json).
          std::error_code ec;
          if (root)
            std::filesystem::remove_all(folder, ec);
          throw OutputFailure("cannot write the checkpoint " + final_folder +
                              ": " + error);
        }
    }
    {
      std::string error;
      if (root)
        {
          std::ofstream prm(folder + "/parameters.prm");
          prm << used_parameters;
          std::error_code ec;
          std::filesystem::remove_all(final_folder, ec);
          std::filesystem::rename(folder, final_folder, ec);
          if (ec)
            error = ec.message();
          else
            {
              // Keep the newest ones.
              const auto all = Checkpoint::list(output);
              for (std::size_t i = 0;
                   i + parameters.checkpoint.keep < all.size();
                   ++i)
                std::filesystem::remove_all(all[i], ec);
            }
        }
      collective_check(error, "complete");
    }
    report.last_checkpoint = final_folder;
    resume.report.last_checkpoint = final_folder;
    ++checkpoint_sequence;
    steps_since_checkpoint = 0;
    last_checkpoint_time   = elapsed(run_timer);
    pcout << "  checkpoint " << final_folder << std::endl;
  }

  template <int dim>
  void
  Simulator<dim>::restore(const std::string &folder)
  {
    const unsigned int rank    = Utilities::MPI::this_mpi_process(comm);
    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(comm);
    // On as many ranks as the run that wrote it, each rank reads its own
    // state file; on another number, every rank reads rank 0's for what is
    // the same on every rank, and the state on nodes and cells comes from
    // the fields attached to the mesh.
    const unsigned int saved_ranks = Checkpoint::read_header(folder).n_ranks;
    const bool         same_ranks  = saved_ranks == n_ranks;
    const std::string  file = Checkpoint::state_file(folder, same_ranks ? rank : 0);
    if (!same_ranks)
      pcout << folder << " was written on " << saved_ranks
            << " MPI rank(s): its state is transferred to " << n_ranks << std::endl;
    // What fails there (a missing or damaged file) is every rank's error,
    // named after the first rank that met it: the other ranks must not go
    // on into the collectives below.
    Checkpoint::Header  header;
    Report              saved;
    std::string         parts;
    std::vector<double> values[2];
    MeshState           mesh_state;
    std::string         error;
    try
      {
        std::ifstream in(file, std::ios::binary);
        if (!in)
          throw std::runtime_error("cannot read '" + file + "'");
        InputArchive archive(in);
        archive >> header;
        archive >> time >> dt >> step >> mesh_ready >> refined_cells >> saved >>
          resume.file_sizes >> parts;
        if (same_ranks && header.mesh_as_built)
          {
            archive >> values[0] >> values[1];
            if (values[0].size() != scene->locally_owned.n_elements())
              throw std::runtime_error(
                file + " holds " + std::to_string(values[0].size()) +
                " DoFs of this rank, the mesh built from the parameters has " +
                std::to_string(scene->locally_owned.n_elements()));
            archive >> mesh_state.dof_entries >> mesh_state.cell_entries;
            if (mesh_state.dof_entries.size() != header.n_dof_fields ||
                mesh_state.cell_entries.size() != header.n_cell_fields)
              throw std::runtime_error(file + " holds other fields than its header names");
          }
      }
    catch (const std::exception &e)
      {
        error = e.what();
        if (error.find(file) == std::string::npos)
          error = file + ": " + error;
      }
    error = first_error(comm, error);
    if (!error.empty())
      throw InputError("--restart", error);

    // The solution, the state the Hessian's structure was built at, and
    // the fields of the parts' state.
    VectorType pattern(scene->locally_owned, comm);
    if (same_ranks && header.mesh_as_built)
      {
        // The same mesh, DoF numbering and cells as the run that wrote it:
        // entry by entry.
        std::size_t k = 0;
        for (const auto i : scene->locally_owned)
          {
            scene->solution[i] = values[0][k];
            pattern[i]         = values[1][k++];
          }
        mesh_state.dof_fields  = mesh_state.dof_vectors(scene->locally_owned, comm);
        mesh_state.cell_fields =
          mesh_state.cell_vectors(scene->triangulation.n_active_cells());
      }
    else
      {
        // Cell by cell: from the mesh loaded from the checkpoint, or, for
        // a mesh built from the parameters on another number of ranks,
        // from the checkpoint's mesh loaded beside it.
        std::vector<VectorType> vectors;
        try
          {
            scene->load_attached(Checkpoint::mesh_file(folder),
                                 !header.mesh_as_built,
                                 2,
                                 header.n_dof_fields,
                                 header.n_cell_fields,
                                 vectors,
                                 mesh_state.cell_fields);
          }
        catch (const std::runtime_error &e)
          {
            throw InputError("--restart",
                             std::string("cannot continue ") + folder + " on " +
                               std::to_string(n_ranks) + " rank(s): " + e.what());
          }
        scene->solution = vectors[0];
        pattern         = vectors[1];
        for (unsigned int f = 0; f < header.n_dof_fields; ++f)
          mesh_state.dof_fields.push_back(std::move(vectors[2 + f]));
      }
    scene->solution.compress(VectorOperation::insert);
    pattern.compress(VectorOperation::insert);
    scene->solution_ghosted = scene->solution;
    {
      VectorType ghosted(scene->locally_owned, scene->locally_relevant, comm);
      ghosted = pattern;
      scene->build_matrix(ghosted);
    }
    mesh_as_built = header.mesh_as_built;
    refined_back  = header.refined_back;

    report.take_record(saved);
    report.restarted_from.push_back(folder);
    previous_times = saved.timing;
    // With friction a cycle runs the whole path on its mesh: a checkpoint
    // in it (on the cycle's new mesh) continues that path.
    if (!report.cycles.empty() &&
        time < parameters.load_stepping.end_time * (1. - 1e-12) &&
        !(problem->friction && mesh_ready))
      throw InputError("Load stepping > End time",
                       "the checkpoint is in the refinement cycles, after the "
                       "load path to t = " + std::to_string(time) +
                         ": the load path cannot be extended any more");

    std::istringstream part_stream(parts);
    InputArchive       part_archive(part_stream);
    if (problem->contact)
      problem->contact->load_state(part_archive, mesh_state);
    if (problem->friction)
      problem->friction->load_state(part_archive, mesh_state);
    solver->load_state(part_archive, mesh_state);
    postprocessor->load_state(part_archive);

    // The appended files back to their state at the checkpoint.
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      for (const auto &[name, size] : resume.file_sizes)
        {
          const std::string path = report.output_directory + "/" + name;
          std::error_code   ec;
          if (std::filesystem::exists(path, ec) &&
              std::filesystem::file_size(path, ec) > size)
            std::filesystem::resize_file(path, size, ec);
        }
    checkpoint_sequence = header.sequence + 1;
  }

  template <int dim>
  const Report &
  Simulator<dim>::run(ParameterHandler &prm)
  {
    const bool         root = (Utilities::MPI::this_mpi_process(comm) == 0);
    const std::string &output_directory = report.output_directory;
    Timer              run_timer;
    {
      std::ostringstream text;
      prm.print_parameters(text, ParameterHandler::ShortPRM);
      used_parameters = text.str();
    }
    {
      std::string error;
      if (root)
        {
          std::error_code ec;
          std::filesystem::create_directories(output_directory, ec);
          // A new run replaces the checkpoints of an earlier one there.
          if (!ec && restart_folder.empty())
            std::filesystem::remove_all(Checkpoint::root(output_directory), ec);
          if (ec)
            error = ec.message();
          else
            {
              AtomicFile out(output_directory + "/used_parameters.prm");
              out.stream() << used_parameters;
              if (!out.commit())
                error = "cannot write into it";
            }
        }
      error = Utilities::MPI::broadcast(comm, error, 0);
      if (!error.empty())
        throw InputError("Output directory",
                         "cannot create '" + output_directory + "': " + error);
    }

    pcout << "Scene " << report.scene << ": " << dim << "D, " << report.n_cells
          << " cells, " << report.n_dofs << " DoFs (Q" << report.degree << "), "
          << report.n_ranks << " MPI rank(s)" << std::endl
          << "Output in " << output_directory << std::endl;
    if (!restart_folder.empty())
      pcout << "Restarted from " << restart_folder << " at t = " << time
            << " (" << step << " converged steps)" << std::endl;

    periodic_checkpoints = parameters.checkpoint.enabled(
      parameters.load_stepping.n_steps, report.n_dofs);
    // The constrained cells of every rank (cells() holds this rank's).
    const unsigned int incompressible_cells = Utilities::MPI::sum(
      problem->incompressibility ?
        static_cast<unsigned int>(problem->incompressibility->cells().size()) :
        0u,
      comm);
    // summary.json as the report stands; also after every refinement
    // cycle (refinement_cycles()).
    summary = [this, incompressible_cells]() {
      write_summary(report,
                    parameters.refinement,
                    problem->contact.get(),
                    *solver,
                    incompressible_cells,
                    comm);
    };
    // Until the run ends, summary.json says it is running: never the
    // summary of an earlier run in the same folder.
    report.status = "running";
    summary();
    // The first frame (HDF5 writes it here and now) failing is the run's
    // failed output, reported below like any other.
    std::string first_frame_error;
    if (restart_folder.empty())
      {
        load_steps->start(report.iteration_name, dim);
        scene->solution         = 0.;
        scene->solution_ghosted = scene->solution;
        try
          {
            postprocessor->write_output(scene->solution_ghosted, 0., 0, false);
          }
        catch (const OutputFailure &e)
          {
            first_frame_error = e.what();
          }
      }
    else
      scene->solution_ghosted = scene->solution;
    snapshot();
    try
      {
        if (!first_frame_error.empty())
          throw OutputFailure(first_frame_error);
        if (report.cycles.empty())
          {
            if (restart_folder.empty())
              check_support(*scene, *problem->energy, problem->contact.get(),
                            parameters.load_stepping.end_time);
            load_path(run_timer);
          }
        refinement_cycles(run_timer);
        report.status = "converged";
      }
    catch (const SolveFailure &e)
      {
        report.status = "failed";
        report.reason = e.what();
        // The solver's last iterate of the failed step, for diagnosis (not
        // part of the solution series).
        std::string snapshot_name;
        if (failed_iterate.size() > 0)
          {
            scene->solution_ghosted = failed_iterate;
            snapshot_name = postprocessor->write_snapshot(scene->solution_ghosted,
                                                          "failed_iterate");
            scene->solution_ghosted = scene->solution;
          }
        pcout << "Run failed: " << report.reason << std::endl
              << "The output of the last converged step (t = "
              << report.final_time << ") is in " << output_directory;
        if (!snapshot_name.empty())
          pcout << "; the solver's last iterate of the failed step is in "
                << snapshot_name << " there";
        pcout << std::endl;
      }
    catch (const OutputFailure &e)
      {
        report.status = "failed";
        report.reason = e.what();
        pcout << "Run failed: " << report.reason << std::endl;
      }
    catch (const Interruption::Interrupted &e)
      {
        // Back to the last converged state: its record, and a checkpoint
        // of it.
        const std::string during = activity;
        report                   = resumed_report();
        report.status            = "interrupted";
        report.interrupt_signal  = e.signal_number;
        report.interrupted_during = during;
        std::string no_checkpoint;
        try
          {
            checkpoint(run_timer, true);
          }
        catch (const OutputFailure &f)
          {
            no_checkpoint = f.what();
          }
        report.reason = Interruption::signal_name(e.signal_number) +
                        " received during " + during +
                        "; the last converged step (t = " +
                        std::to_string(report.final_time) + ")" +
                        (no_checkpoint.empty() ?
                           " is on disk; continue with: " +
                             (report.n_ranks > 1 ?
                                "mpirun -np " + std::to_string(report.n_ranks) + " " :
                                std::string()) +
                             "signorini --restart " + output_directory :
                           " has its field output on disk, but " + no_checkpoint);
        pcout << "Run interrupted: " << report.reason << std::endl;
      }

    // The last field frame, written in the background, is complete and in
    // its records before the run reports.
    try
      {
        TimerOutput::Scope scope(*timer, "output");
        postprocessor->flush();
      }
    catch (const OutputFailure &e)
      {
        report.status = "failed";
        report.reason = e.what();
        pcout << "Run failed: " << report.reason << std::endl;
      }
    {
      Utilities::System::MemoryStats memory;
      Utilities::System::get_memory_stats(memory);
      report.peak_memory_mb =
        Utilities::MPI::max(static_cast<double>(memory.VmHWM) / 1024., comm);
    }
    report.timing = run_times(run_timer);
    summary();
    if (root)
      write_progress(output_directory, report.status, report.final_time,
                     parameters.load_stepping.end_time, report.steps.size(),
                     report.last_cycle(),
                     report.timing["total"], 0.);
    if (postprocessor->verbosity() == PostprocessParameters::Verbosity::verbose)
      timer->print_summary();
    return report;
  }

  template class Simulator<2>;
  template class Simulator<3>;
} // namespace Signorini
