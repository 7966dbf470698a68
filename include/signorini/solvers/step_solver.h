#pragma once

#include <signorini/archive.h>
#include <signorini/mesh_state.h>
#include <signorini/output/json.h>
#include <signorini/solvers/linear_solver.h>
#include <signorini/solvers/newton.h>
#include <signorini/solvers/transport_predictor.h>
#include <signorini/output/report.h>
#include <signorini/solvers/ipopt_solver.h>
#include <signorini/parameters/scene_parameters.h>
#include <signorini/problem/problem.h>
#include <signorini/scene/scene.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>

#include <memory>
#include <string>
#include <vector>

namespace Signorini
{
  /// What a step solver reports of one solve: iterations, line search,
  /// linear solves, the final evaluation and, on failure, the reason.
  using StepStatistics = NewtonMinimizer::Statistics;

  /**
   * A step solver: minimises the scene's problem at one load time, from
   * the scene's current solution, and leaves the result (or, on failure,
   * its last iterate) there. It reports its own statistics: iterations,
   * its part of summary.json and any quantities of its own.
   *
   * Implementations: NewtonStep (no contact), PenaltyStep (penalty
   * continuation; each stage minimised by Newton or Ipopt), IpoptStep
   * (Ipopt with the contact and incompressibility constraints) and
   * InteriorPointStep (the program's interior point method with the rigid
   * foundation's constraints, on any number of ranks). They are
   * made by create_step_solver(), which holds the table of which method
   * handles which scene.
   */
  template <int dim>
  class StepSolver
  {
  public:
    StepSolver(const Parameters::Scene &parameters,
               Scene<dim>              &scene,
               Problem<dim>            &problem,
               TimerOutput             &timer,
               ConditionalOStream      &progress);

    virtual ~StepSolver() = default;

    /// Called after the scene's DoFs are (re)distributed.
    virtual void
    setup();

    /**
     * A load path starts again from rest (after setup(): a refinement
     * cycle with friction runs the whole path on its new mesh): forget
     * what carries from one load step to the next, so that the path is
     * solved as in a run that starts on this mesh. Nothing by default:
     * setup() already starts the interior point method and Ipopt cold.
     */
    virtual void
    start_path()
    {}

    /**
     * Minimise at load time @p time. Returns whether it converged; @p stats
     * and @p record receive the iterations, the final evaluation and the
     * solver's own record (penalty stages, status). On success the contact
     * model's forces are those of the new solution.
     */
    virtual bool
    solve(const double                 time,
          StepStatistics              &stats,
          Report::Step                &record) = 0;

    /**
     * One load step: solve(), and with friction the outer loop around it
     * (doc/friction.md, section 2). The friction term takes the step's
     * start as the slip's reference and lags the normal forces of the
     * last converged step; after each converged solve it re-lags them
     * from the new force record, until their relative change is at most
     * Contact > Friction > Outer tolerance. A loop that reaches Maximum
     * outer iterations fails the step (which the driver then cuts).
     * Without friction this is solve().
     */
    bool
    solve_step(const double    time,
               StepStatistics &stats,
               Report::Step   &record);

    /// Whether solve() itself runs the friction loop (inside a fixed-point
    /// loop of its own), so that solve_step() only starts the step.
    virtual bool
    lags_friction() const
    {
      return false;
    }

    /// Whether a re-solve after a large change of the lag starts from the
    /// step's start (friction_restart_change). The interior point method
    /// only: newton-penalty's re-solve from the step's start runs its
    /// penalty path again, and cattaneo_mindlin_two_body_2d with the slip
    /// length 1e-6 h then failed its pressing (cuts below the minimum
    /// step); from the last solve it converges.
    virtual bool
    restarts_friction() const
    {
      return false;
    }

    /// "newton", "ipopt" or "interior_point": the name of the iteration
    /// counts in the output.
    virtual std::string
    iteration_name() const
    {
      return "newton";
    }

    /// How many AMG hierarchies the step solver's linear solver has built
    /// so far (0 with the direct solver, and for Ipopt's own solves).
    unsigned int
    n_preconditioner_builds() const
    {
      return linear_solver.n_preconditioner_builds();
    }

    /// The solver's entries of summary.json's "contact" block.
    virtual void
    write_contact_summary(Json &block) const
    {
      (void)block;
    }

    /**
     * The solver's top-level entries of summary.json. Here: the ordering
     * MUMPS used (in "solver"); a solver with entries of its own calls
     * this too.
     */
    virtual void
    write_summary(Json &summary) const;

    /// The friction settings into summary.json's contact block (under
    /// "friction"), if the scene has friction.
    void
    write_friction_summary(Json &contact) const;

    /// Quantities of the solver's own, reported with each step.
    virtual void
    add_quantities(std::vector<Quantity> &quantities) const
    {
      (void)quantities;
    }

    /**
     * Save what the solver carries from one load step to the next (the
     * penalty of the last step, Ipopt's or the interior point method's
     * multipliers for its warm start) into a checkpoint: into @p archive
     * what is the same on every rank (or what only a one-rank solver
     * has), into @p mesh what lives on nodes or cells. load_state() reads
     * it back after setup() on the restarted run's mesh. Nothing by
     * default.
     */
    virtual void
    save_state(OutputArchive &archive, MeshState &mesh) const
    {
      (void)archive;
      (void)mesh;
    }
    virtual void
    load_state(InputArchive &archive, MeshState &mesh)
    {
      (void)archive;
      (void)mesh;
    }

  protected:
    /**
     * One update of the friction loop after its outer iteration
     * @p iteration converged (with the model's force record set): re-lag
     * the friction term at the solution, record the iteration and the
     * change in @p record and print them. Returns the relative change of
     * the normal forces.
     */
    double
    update_friction(const unsigned int iteration, Report::Step &record);

    /// The reason of a friction loop whose normal forces still changed by
    /// @p change after @p iterations outer iterations.
    std::string
    friction_failure(const double change, const unsigned int iterations) const;

    /**
     * A re-solve of the friction loop whose lagged normal forces changed
     * by more than this (relative) starts from the step's start (with
     * restarts_friction()), as the
     * first solve did, not from the last solve: that solve's slips were
     * those of other normal forces (none at all after a frictionless first
     * solve, or a lag extrapolated past the end of the pressing), and
     * pulling the nodes that now stick back from them took the interior
     * point method 19-24 iterations of short steps (cattaneo_mindlin_2d's
     * pressing steps), 6-10 from the step's start.
     */
    static constexpr double friction_restart_change = 0.1;

    /// True during the re-solves of the friction loop: they start from a
    /// converged state at the step's load time, so predict() does
    /// nothing (its tangent step would only perturb that state by up to
    /// the inner tolerance, and with it the normal forces the outer loop
    /// compares).
    bool friction_resolve = false;

    /// Called before each re-solve of the friction loop, from a converged
    /// state whose lagged normal forces changed by @p change (relative).
    virtual void
    prepare_friction_resolve(const double change)
    {
      (void)change;
    }

    /**
     * With Load stepping > Sliding direction: carry the previous step's
     * state along for the step to @p time (TransportPredictor) and say so
     * on the progress stream. The Newton-based step solvers call it first
     * (through predict(), whose tangent step is kept only if it lowers the
     * energy below the Dirichlet increment alone's, carried or not).
     */
    void
    carry_along(const double time);

    /**
     * For step solvers the transport predictor is not used with: drop it,
     * and say so on the progress stream (@p solver names the solver).
     */
    void
    without_transport(const std::string &solver);

    /**
     * The tangent predictor for prescribed boundary motion: one linear step
     * of @p objective towards the Dirichlet values at @p time. Returns false
     * (with the reason in @p stats) if it fails; does nothing if no
     * boundary moves.
     */
    bool
    predict(NewtonMinimizer             &newton,
            Objective                   &objective,
            const double                 time,
            StepStatistics              &stats);

    /// A Newton minimiser for one load step.
    NewtonMinimizer
    newton() const;

    /**
     * Ipopt on the current DoFs, set up with the scene's constraints and
     * Hessian pattern and with the step limit: @p contact's node-wise
     * constraints and @p incompressibility's equalities (either may be
     * null).
     */
    std::unique_ptr<IpoptSolver<dim>>
    make_ipopt(const Contact::NodeWiseConstraints<dim> *contact,
               const Incompressibility<dim> *incompressibility) const;

    const Parameters::Scene &parameters;
    Scene<dim>              &scene;
    Problem<dim>            &problem;
    TimerOutput             &timer;
    ConditionalOStream      &progress;
    LinearSolver             linear_solver;
    /// Set with Load stepping > Sliding direction.
    std::unique_ptr<TransportPredictor<dim>> transport;
  };

  /**
   * The step solver for @p parameters' Solver > Method and the scene they
   * declare. The caller has passed check_solver_compatibility() (the
   * driver does so right after parsing, before the mesh is built).
   */
  template <int dim>
  std::unique_ptr<StepSolver<dim>>
  create_step_solver(const Parameters::Scene &parameters,
                     Scene<dim>              &scene,
                     Problem<dim>            &problem,
                     TimerOutput             &timer,
                     ConditionalOStream      &progress);

  /// InputError if the method cannot handle the scene (contact without a
  /// contact method, J = 1 constraints without Ipopt, Ipopt on several
  /// ranks, the interior point method without a rigid foundation); needs
  /// no mesh.
  void
  check_solver_compatibility(const Parameters::Scene &parameters,
                             const unsigned int       n_ranks);
} // namespace Signorini
