#pragma once

#include <signorini/output/report.h>
#include <signorini/output/summary.h>
#include <signorini/parameters/scene_parameters.h>
#include <signorini/output/postprocess.h>
#include <signorini/problem/problem.h>
#include <signorini/scene/scene.h>
#include <signorini/solvers/step_solver.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>

#include <functional>
#include <memory>
#include <string>

namespace Signorini
{
  using namespace dealii;

  /**
   * The driver of one run. It holds one object per kind of thing and
   * chooses no implementation itself:
   *
   *   Parameters::Scene (the parsed file)
   *     -> Scene (mesh, DoFs, constraints, sparsity, state vectors)
   *     -> Problem (energy, contact model from its factory, constraints)
   *     -> StepSolver (from its factory: Newton, penalty continuation
   *        or Ipopt)
   *     -> load steps with step cutting, then adaptive refinement cycles
   *     -> Postprocessor (quantities, VTU), contact quantities,
   *        summary.json written from the report and by each part.
   */
  template <int dim>
  class Simulator
  {
  public:
    /**
     * Parse the scene from @p prm (already read from @p parameter_file),
     * build the mesh and check the input. Throws InputError on bad input,
     * before anything is written. With @p restart_checkpoint (a checkpoint
     * folder, whose parameters the caller has checked against @p prm),
     * the mesh, the solution and the state of every part are those of
     * the checkpoint, and run() continues from there.
     */
    Simulator(ParameterHandler  &prm,
              const std::string &parameter_file,
              const bool         quiet,
              MPI_Comm           comm,
              const std::string &restart_checkpoint = "");

    /**
     * Create the output folder, write used_parameters.prm, solve every
     * load step and write the output. Returns the report; its status is
     * "converged", "failed" (then reason says why, the output of the
     * last converged step is on disk and summary.json says so) or
     * "interrupted" (SIGINT or SIGTERM: a checkpoint of the last
     * converged step is on disk, see Interruption).
     */
    const Report &
    run(ParameterHandler &prm);

  private:
    /// After the scene's DoFs were (re)distributed: the constraints, the
    /// step solver and the report's mesh data.
    void
    setup_dofs();

    /// Record the converged state of time @p t: quantities, the step
    /// record and, with a @p series name, the graphical output.
    void
    complete_step(const double                       t,
                  const unsigned int                 step,
                  const StepStatistics              &stats,
                  Report::Step                      &record,
                  const std::string                 &series);

    /// Solve the load path from the current time; throws SolveFailure
    /// when a step cannot be cut further. Each converged step's fields go
    /// to the output @p series (empty: none); @p cycle is the refinement
    /// cycle the path belongs to (0: the run's own path).
    void
    load_path(const Timer       &run_timer,
              const std::string &series = "solution",
              const unsigned int cycle  = 0);

    /**
     * The final load again on adaptively refined meshes, from the
     * current cycle. Without friction a cycle solves the final load from
     * the previous mesh's answer, transferred. Friction depends on the
     * load path (the stick zone is where the last step's slip stayed
     * below the slip length, from the state of the step before), so with
     * friction a cycle runs the whole load path again from rest on its
     * new mesh (start_path()).
     */
    void
    refinement_cycles(const Timer &run_timer);

    /// The state at rest on the current mesh, ready for the load path
    /// from t = 0: zero displacement, no contact forces, a friction term
    /// and a step solver without history.
    void
    start_path();

    /// The estimated errors of the report's quantities from the cycles so
    /// far (also into the last cycle's record), and whether they meet the
    /// target accuracy. Throws InputError for a target quantity that the
    /// run does not report or cannot estimate.
    void
    estimate_errors();

    /// Wall time of every phase so far, the largest over the ranks,
    /// including the runs this one was restarted from.
    std::map<std::string, double>
    phase_times() const;

    /// Wall time since the start of the run (and of the runs it was
    /// restarted from), the largest over the ranks.
    double
    elapsed(const Timer &run_timer) const;

    /// phase_times() with "setup" and "total": the report's timing
    /// (collective).
    std::map<std::string, double>
    run_times(const Timer &run_timer) const;

    /// The report of the last resume point: its record with the steps
    /// and cycles converged by then.
    Report
    resumed_report() const;

    /// Record the current state as the one a checkpoint saves (after
    /// every converged step and every new mesh).
    void
    snapshot();

    /// Write a checkpoint of the last snapshot if one is due (or always,
    /// with @p force); collective.
    void
    checkpoint(const Timer &run_timer, const bool force);

    /// Continue from the checkpoint in @p folder (after setup_dofs()).
    void
    restore(const std::string &folder);

    /// The state of a run that a checkpoint keeps.
    struct ResumePoint
    {
      double       time = 0., dt = 0.;
      unsigned int step = 0;
      bool         mesh_ready = false;   // a refined mesh, not yet solved
      bool         mesh_as_built = true; // no refinement cycle yet
      bool         refined_back  = false; // coarser-mesh estimate, cycle 1
      unsigned int refined_cells = 0;    // flagged to make that mesh
      Report       report;               // without steps and cycles
      std::size_t  n_steps = 0, n_cycles = 0; // of report's, at this point
      VectorType   solution;             // locally owned
      VectorType   pattern;              // locally relevant
      std::string  parts;                // model, solver, output: the same on every rank
      MeshState    mesh_state;           // their state on nodes and cells
      std::map<std::string, unsigned long long> file_sizes; // appended files
    };

    MPI_Comm           comm;
    ConditionalOStream pcout;
    ConditionalOStream progress;
    Parameters::Scene  parameters;
    // Created once the input is checked: a TimerOutput destroyed during
    // exception unwinding would print a notice over the error message.
    std::unique_ptr<TimerOutput>        timer;
    double                              setup_seconds = 0.;
    std::unique_ptr<Scene<dim>>         scene;
    std::unique_ptr<Problem<dim>>       problem;
    std::unique_ptr<StepSolver<dim>>    solver;
    /// The solver's AMG builds already put into a step record.
    unsigned int                        amg_builds_counted = 0;
    std::unique_ptr<Postprocessor<dim>> postprocessor;
    VectorType                          failed_iterate;
    Report                              report;
    std::unique_ptr<LoadStepTable>      load_steps;
    /// Write summary.json as the report stands (collective): at the start
    /// (status "running"), after every refinement cycle, so that a run
    /// killed from outside (e.g. for lack of memory) keeps the cycles it
    /// finished and their estimates, and at the end. Set in run().
    std::function<void()> summary;

    // Where the run is: load time and step size, converged steps, and in
    // the refinement cycles whether the current mesh is refined and not
    // yet solved. Restored from a checkpoint.
    double       time = 0., dt = 0.;
    unsigned int step = 0;
    bool         mesh_ready    = false;
    bool         mesh_as_built = true;
    unsigned int refined_cells = 0;
    std::string  activity = "setup"; // for the message of an interruption
    /// With 'Estimate from a coarser mesh': the cells coarsened at the
    /// start (Refinement::coarsen_once()), and whether they are refined
    /// back (cycle 1).
    std::vector<CellId::binary_type> coarsened_parents;
    bool                             refined_back = false;

    ResumePoint                   resume;
    std::string                   restart_folder;
    std::string                   used_parameters; // ShortPRM text
    std::map<std::string, double> previous_times; // of the runs before
    unsigned int                  checkpoint_sequence = 0;
    unsigned int                  steps_since_checkpoint = 0;
    double                        last_checkpoint_time   = 0.;
    bool                          periodic_checkpoints   = false;
  };
} // namespace Signorini
