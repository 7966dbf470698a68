#include <signorini/interruption.h>
#include <signorini/output/atomic_file.h>
#include <signorini/output/summary.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/multithread_info.h>

#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace Signorini
{
  namespace
  {
    /**
     * The file of the first shared library mapped into this process whose
     * name starts with @p prefix (e.g. "libblas", "liblapack"), as the
     * kernel resolved it through Debian's alternatives: which BLAS or
     * LAPACK the run used. "unknown" where /proc is not readable.
     */
    std::string
    loaded_library(const std::string &prefix)
    {
      std::ifstream maps("/proc/self/maps");
      for (std::string line; std::getline(maps, line);)
        {
          const auto slash = line.rfind('/');
          if (slash != std::string::npos &&
              line.compare(slash + 1, prefix.size(), prefix) == 0)
            return line.substr(line.find('/'));
        }
      return "unknown";
    }

    /// The run's identity, status, mesh, machine and solver entries.
    void
    add_run_entries(Json &j, const Report &report)
    {
      j["program"]        = "signorini";
      j["scene"]          = report.scene;
      j["parameter file"] = report.parameter_file;
      j["status"]         = report.status;
      if (!report.reason.empty())
        j["reason"] = report.reason;
      if (report.interrupt_signal != 0)
        {
          j["interrupted by"]     = Interruption::signal_name(report.interrupt_signal);
          j["interrupted during"] = report.interrupted_during;
        }
      if (!report.last_checkpoint.empty())
        j["checkpoint"] = report.last_checkpoint;
      if (!report.restarted_from.empty())
        {
          Json from = Json::array();
          for (const auto &c : report.restarted_from)
            from.push_back(c);
          j["restarted from"] = from;
        }
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
      j["blas"]             = loaded_library("libblas");
      j["lapack"]           = loaded_library("liblapack");
      j["mpi settings"]     = report.mpi_settings;
      Json materials_json = Json::array();
      for (const auto &m : report.materials)
        materials_json.push_back(m);
      j["materials"] = materials_json;
      Json &solver = j["solver"];
      solver["method"]        = report.solver;
      solver["linear solver"] = report.linear_solver;
      if (report.iterative_linear_solver)
        {
          unsigned int builds = 0;
          for (const auto &step : report.steps)
            builds += step.amg_builds;
          solver["AMG builds"] = builds;
        }
    }

    /// The contact model's and the step solver's contact entries, and the
    /// contact state of the last load step.
    template <int dim>
    void
    add_contact_entries(Json                      &c,
                        const Report              &report,
                        const Contact::Model<dim> &contact,
                        const StepSolver<dim>     &step_solver)
    {
      contact.write_summary(c);
      step_solver.write_contact_summary(c);
      if (!report.steps.empty())
        {
          c["active nodes"]           = report.steps.back().active_nodes;
          c["max penetration over h"] = report.steps.back().penetration_ratio;
          const Report::Step &last = report.steps.back();
          c["area"]                 = last.contact_area;
          Json force = Json::array(), moment = Json::array();
          for (unsigned int d = 0; d < dim; ++d)
            force.push_back(last.contact_force_vector[d]);
          for (unsigned int d = (dim == 2 ? 2 : 0); d < 3; ++d)
            moment.push_back(last.contact_moment[d]);
          c["resultant force"] = force;
          c["resultant moment"] = moment;
          c["moment about"]     = "origin";
        }
      step_solver.write_friction_summary(c);
      if (!report.steps.empty() && report.steps.back().friction_iterations > 0)
        {
          const Report::Step &last = report.steps.back();
          Json               &f    = c["friction"];
          Json                force = Json::array();
          for (unsigned int d = 0; d < dim; ++d)
            force.push_back(last.friction_force[d]);
          f["friction force"]           = force;
          f["dissipated energy"]        = last.total_dissipated_energy;
          f["stick points"]             = last.stick_points;
          f["slip points"]              = last.slip_points;
          f["outer iterations, last step"] = last.friction_iterations;
        }
    }

    /// One object per load step (@p iterations: the name of its
    /// iteration count), with its contact state if there is contact.
    template <int dim>
    Json
    steps_json(const Report &report, const std::string &iterations, const bool contact)
    {
      Json steps = Json::array();
      for (const auto &s : report.steps)
        {
          Json o = Json::object();
          o["time"]              = s.time;
          o[iterations]          = s.iterations;
          o["backtracks"]        = s.backtracks;
          o["regularized steps"] = s.regularized;
          o["linear iterations"] = s.linear_iterations;
          o["linear solves"]     = s.linear_solves;
          o["linear fallbacks"]  = s.linear_fallbacks;
          if (report.iterative_linear_solver)
            o["AMG builds"] = s.amg_builds;
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
                  so[iterations]          = st.iterations;
                  so["max penetration over h"] = st.penetration_ratio;
                  if (!st.converged)
                    so["converged"] = false; // tried again with a smaller jump
                  stages.push_back(so);
                }
              o["penalty stages"] = stages;
            }
          if (contact)
            {
              o["active contact nodes"]   = s.active_nodes;
              o["max penetration over h"] = s.penetration_ratio;
              o["contact force"]          = s.contact_force_vector[dim - 1];
              o["contact area"]           = s.contact_area;
              if (s.has_pairs)
                o["evaluated pairs"] = s.pairs;
              if (s.friction_iterations > 0)
                {
                  o["friction iterations"] = s.friction_iterations;
                  o["friction force"]      = s.friction_force[0];
                  o["dissipated energy"]   = s.dissipated_energy;
                }
            }
          steps.push_back(o);
        }
      return steps;
    }

    /// The refinement settings and one object per refinement cycle.
    void
    add_refinement_entries(Json                       &r,
                           const Report               &report,
                           const RefinementParameters &refinement_parameters,
                           const std::string          &iterations)
    {
      r["estimator"]                = refinement_parameters.estimator_name();
      r["strategy"]                 = refinement_parameters.strategy ==
                              RefinementParameters::Strategy::fraction ?
                                        "fraction" :
                                        "number";
      r["refine fraction"]          = refinement_parameters.refine_fraction;
      r["coarsen fraction"]         = refinement_parameters.coarsen_fraction;
      r["maximum level"]            = refinement_parameters.max_level;
      r["contact band refinements"] = refinement_parameters.band_refinements;
      r["estimate from a coarser mesh"] = refinement_parameters.coarser_mesh_estimate;
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
          o[iterations]        = c.iterations;
          o["cycle wall time [s]"] = c.cycle_seconds;
          o["wall time since start [s]"] = c.wall_seconds;
          Json q = Json::object(), e = Json::object();
          for (const auto &qq : c.quantities)
            {
              q[qq.name] = qq.value;
              if (qq.has_estimate)
                e[qq.name] = qq.estimated_error;
            }
          o["quantities"]       = q;
          o["estimated errors"] = e;
          cycles.push_back(o);
        }
      r["cycles"] = cycles;
      if (report.target_accuracy > 0.)
        {
          Json t                      = Json::object();
          t["relative tolerance"]     = report.target_accuracy;
          Json names                  = Json::array();
          for (const auto &name : refinement_parameters.target_quantities)
            names.push_back(Json(name));
          t["quantities"]             = names;
          t["met"]                    = report.target_met;
          Json unmet                  = Json::array();
          for (const auto &name : report.target_unmet)
            unmet.push_back(Json(name));
          t["not met"]                = unmet;
          t["cycles"]                 = report.last_cycle();
          r["target accuracy"] = t;
        }
    }

    /// The quantities of the scene: value and, where there is one, the
    /// reference, the error and its tolerance.
    Json
    quantities_json(const Report &report)
    {
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
          if (q.has_estimate)
            {
              // The discretisation error from the refinement cycles.
              o["estimated error"]          = q.estimated_error;
              o["estimated relative error"] = q.estimated_relative_error();
              o["observed order"]           = q.observed_order;
              o["meshes in estimate"]       = q.estimate_meshes;
            }
          quantities[q.name] = o;
        }
      return quantities;
    }

    /// refinement_cycles.csv: one line per refinement cycle.
    void
    write_cycles_csv(std::ostream &cycles_csv, const Report &report)
    {
      cycles_csv << "cycle,cells,dofs,contact_nodes,refined_cells,h_min,"
                 << report.iteration_name
                 << "_iterations,cycle_wall_time,wall_time_since_start";
      // The columns are the first cycle's quantities; the estimated
      // errors follow, empty where a cycle has none yet.
      const auto &columns = report.cycles.front().quantities;
      for (const auto &q : columns)
        cycles_csv << "," << q.name;
      for (const auto &q : columns)
        if (q.estimable)
          cycles_csv << "," << q.name << "_estimated_error";
      cycles_csv << "\n" << std::setprecision(12);
      for (const auto &c : report.cycles)
        {
          cycles_csv << c.cycle << "," << c.n_cells << "," << c.n_dofs << ","
                     << c.contact_nodes << "," << c.refined_cells << ","
                     << c.h_min << "," << c.iterations << ","
                     << c.cycle_seconds << "," << c.wall_seconds;
          for (const auto &q : c.quantities)
            cycles_csv << "," << q.value;
          for (const auto &column : columns)
            if (column.estimable)
              {
                cycles_csv << ",";
                for (const auto &q : c.quantities)
                  if (q.name == column.name && q.has_estimate)
                    cycles_csv << q.estimated_error;
              }
          cycles_csv << "\n";
        }
    }
  } // namespace

  template <int dim>
  void
  write_summary(const Report               &report,
                const RefinementParameters &refinement_parameters,
                const Contact::Model<dim>  *contact,
                const StepSolver<dim>      &step_solver,
                const unsigned int          incompressibility_constraints,
                MPI_Comm                    comm)
  {
    const std::string &output_directory = report.output_directory;
    if (Utilities::MPI::this_mpi_process(comm) != 0)
      return;
    Json j = Json::object();
    add_run_entries(j, report);
    j["final time"]              = report.final_time;
    j["load steps"]              = static_cast<unsigned int>(report.steps.size());
    j["step cuts"]               = report.step_cuts;
    // Iterations are Newton's or Ipopt's (also per penalty stage).
    const std::string iterations = report.iteration_name + " iterations";
    j[iterations] = report.iterations;
    if (contact)
      add_contact_entries(j["contact"], report, *contact, step_solver);
    if (incompressibility_constraints > 0)
      j["incompressibility constraints"] = incompressibility_constraints;
    step_solver.write_summary(j);
    j["steps"] = steps_json<dim>(report, iterations, contact != nullptr);
    if (refinement_parameters.cycles > 0 || refinement_parameters.band_refinements > 0 ||
        refinement_parameters.coarser_mesh_estimate)
      add_refinement_entries(j["mesh refinement"], report, refinement_parameters,
                             iterations);
    j["quantities"] = quantities_json(report);
    Json timing     = Json::object();
    for (const auto &t : report.timing)
      timing[t.first] = t.second;
    // The search's share of the contact terms (this process's).
    if (contact)
      if (const auto seconds = contact->search_seconds())
        timing["contact search"] = *seconds;
    j["wall time [s]"] = timing;

    // Each file is renamed into place once complete: an interrupted write
    // leaves the previous version, never a truncated one.
    std::vector<std::unique_ptr<AtomicFile>> files;
    files.push_back(std::make_unique<AtomicFile>(output_directory + "/summary.json"));
    j.write(files.back()->stream());
    files.back()->stream() << "\n";

    if (!report.cycles.empty())
      {
        files.push_back(
          std::make_unique<AtomicFile>(output_directory + "/refinement_cycles.csv"));
        write_cycles_csv(files.back()->stream(), report);
      }

    for (auto &file : files)
      if (std::string reason; !file->commit(&reason))
        std::cerr << "signorini: warning: " << reason << std::endl;
  }

  LoadStepTable::LoadStepTable(const std::string              &output_directory,
                               const bool                      writer,
                               const bool                      friction,
                               const std::vector<std::string> &part_columns)
    : file(output_directory + "/load_steps.csv")
    , writer(writer)
    , friction(friction)
    , part_columns(part_columns)
  {}

  void
  LoadStepTable::start(const std::string &iteration_name, const unsigned int dim)
  {
    if (!writer)
      return;
    AtomicFile out(file);
    std::ostream &csv = out.stream();
    csv << "step,time," << iteration_name
        << "_iterations,backtracks,regularized_steps,"
           "linear_iterations,linear_fallbacks,cuts_before,residual,energy,min_J,"
           "penalty_stages,final_penalty,active_contact_nodes,"
           "max_penetration_over_h,contact_force";
    for (unsigned int d = 0; d < dim; ++d)
      csv << ",contact_force_" << "xyz"[d];
    csv << ",evaluated_pairs,contact_area";
    for (unsigned int d = (dim == 2 ? 2 : 0); d < 3; ++d)
      csv << ",contact_moment_" << "xyz"[d];
    if (friction)
      {
        csv << ",friction_iterations,friction_change";
        for (unsigned int d = 0; d < dim; ++d)
          csv << ",friction_force_" << "xyz"[d];
        csv << ",dissipated_energy,total_dissipated_energy,stick_points,slip_points,"
               "tangential_load_ratio,stick_radius,stick_radius_reference";
      }
    for (const auto &column : part_columns)
      csv << "," << column;
    csv << "\n";
    if (std::string reason; !out.commit(&reason))
      std::cerr << "signorini: warning: " << reason << std::endl;
  }

  void
  LoadStepTable::append(const unsigned int   index,
                        const Report::Step &s,
                        const unsigned int   dim)
  {
    if (!writer)
      return;
    // The whole row in one write, flushed at once: a reader (or a run
    // killed right now) sees whole rows only.
    std::ostringstream row;
    row << std::setprecision(12) << index << "," << s.time << ","
        << s.iterations << "," << s.backtracks << "," << s.regularized
        << "," << s.linear_iterations << "," << s.linear_fallbacks << ","
        << s.cuts_before << "," << s.residual << "," << s.energy << ","
        << s.min_J << "," << s.stages.size() << ","
        << (s.stages.empty() ? 0. : s.stages.back().mu) << ","
        << s.active_nodes << "," << s.penetration_ratio << ","
        << s.contact_force_vector[dim - 1];
    for (unsigned int d = 0; d < dim; ++d)
      row << "," << s.contact_force_vector[d];
    row << "," << s.pairs << "," << s.contact_area;
    for (unsigned int d = (dim == 2 ? 2 : 0); d < 3; ++d)
      row << "," << s.contact_moment[d];
    if (friction)
      {
        row << "," << s.friction_iterations << "," << s.friction_change;
        for (unsigned int d = 0; d < dim; ++d)
          row << "," << s.friction_force[d];
        row << "," << s.dissipated_energy << "," << s.total_dissipated_energy << ","
            << s.stick_points << "," << s.slip_points << "," << s.tangential_load_ratio << ","
            << s.stick_radius << "," << s.stick_radius_reference;
      }
    for (std::size_t i = 0; i < part_columns.size(); ++i)
      row << "," << (i < s.part_values.size() ? s.part_values[i] : 0.);
    row << "\n";
    std::ofstream csv(file, std::ios::app);
    csv << row.str() << std::flush;
    if (!csv)
      std::cerr << "signorini: warning: cannot append to " << file << std::endl;
  }

  void
  write_progress(const std::string &output_directory,
                 const std::string &status,
                 const double       time,
                 const double       end_time,
                 const unsigned int step,
                 const unsigned int cycle,
                 const double       elapsed_seconds,
                 const double       remaining_seconds)
  {
    Json j                            = Json::object();
    j["status"]                       = status;
    j["time"]                         = time;
    j["end time"]                     = end_time;
    j["load step"]                    = step;
    j["refinement cycle"]             = cycle;
    j["elapsed wall time [s]"]        = elapsed_seconds;
    j["estimated remaining time [s]"] = remaining_seconds;
    AtomicFile out(output_directory + "/progress.json");
    j.write(out.stream());
    out.stream() << "\n";
    if (std::string reason; !out.commit(&reason))
      std::cerr << "signorini: warning: " << reason << std::endl;
  }

  template void
  write_summary<2>(const Report &, const RefinementParameters &,
                   const Contact::Model<2> *, const StepSolver<2> &,
                   const unsigned int, MPI_Comm);
  template void
  write_summary<3>(const Report &, const RefinementParameters &,
                   const Contact::Model<3> *, const StepSolver<3> &,
                   const unsigned int, MPI_Comm);
} // namespace Signorini
