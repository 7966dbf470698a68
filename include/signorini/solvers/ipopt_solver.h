#pragma once

#include <signorini/solvers/ipopt_parameters.h>

#include <signorini/archive.h>

#include <signorini/contact/friction_term.h>
#include <signorini/contact/penalty.h>
#include <signorini/contact/node_wise_constraints.h>
#include <signorini/problem/energy_functional.h>
#include <signorini/problem/incompressibility.h>
#include <signorini/types.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace Signorini
{
  using namespace dealii;

  /**
   * Constrained minimisation of the total potential energy with the
   * interior point optimiser Ipopt (formulation.md (11)):
   *
   *   min E(U)  subject to  g_k(U) >= 0 (rigid foundation contact),
   *                         c_K(U) = 0 (incompressibility per cell),
   *
   * with exact derivatives: the gradient of E, the sparse constraint
   * Jacobian, and the sparse Hessian of the Lagrangian
   * sigma grad^2 E + sum lambda_k grad^2 g_k + sum lambda_K grad^2 c_K.
   * The optimisation variables are the DoFs that are neither Dirichlet
   * nor hanging-node constrained; the others follow from the constraints.
   * The Hessian's sparsity is the finite element pattern restricted to
   * the free DoFs (lower triangle), built once per mesh.
   *
   * With a penalty term (set_penalty(): two-body contact) the objective
   * is G_mu = E + mu P and Ipopt is an unconstrained minimiser of each
   * stage of the penalty continuation, as in the poster: its inertia
   * correction regularises the Hessian where mu grad^2 P is indefinite,
   * and a state the term calls inadmissible is reported to Ipopt as a
   * failed evaluation, which makes its line search step back. When the
   * term's couplings leave the Hessian's sparsity pattern, the pattern is
   * rebuilt at that state, Ipopt is stopped after the iteration and
   * restarted from its last iterate with the new structure.
   *
   * Ipopt runs on one MPI rank. Between load steps the solver warm-starts
   * from the previous primal and dual solution.
   */
  template <int dim>
  class IpoptSolver
  {
  public:
    using Parameters = IpoptParameters;

    struct Result
    {
      bool                success    = false;
      std::string         status;
      unsigned int        iterations = 0;
      std::vector<double> contact_forces;      // per contact node (>= 0)
      std::vector<double> pressure_multipliers; // per constrained cell
      int                 derivative_test_errors = -1; // -1: not run

      /// "Ipopt returned STATUS after N iterations", for failure reasons.
      std::string
      failure() const
      {
        return "Ipopt returned " + status + " after " +
               std::to_string(iterations) + " iterations";
      }
    };

    using PatternBuilder = typename Contact::PenaltyObjective<dim>::PatternBuilder;

    IpoptSolver(const Parameters                  &parameters,
                const DoFHandler<dim>             &dof_handler,
                const EnergyFunctional<dim>       &energy,
                const Contact::NodeWiseConstraints<dim> *contact,
                const Incompressibility<dim>      *incompressibility,
                const std::string                 &output_directory,
                ConditionalOStream                &progress,
                TimerOutput                       &timer);
    ~IpoptSolver();

    /**
     * Build the variable map and the sparsity structures. @p constraints:
     * the homogeneous Dirichlet and hanging-node constraints; @p hessian:
     * the problem's matrix (its pattern is used).
     */
    void
    setup(const AffineConstraints<double> &constraints, MatrixType &hessian);

    /**
     * Add mu P(U) of @p term to the objective of every following solve
     * (mu is solve()'s argument). @p rebuild_pattern re-initialises the
     * matrix given to setup() with the couplings the term needs at a
     * state.
     */
    void
    set_penalty(Contact::PenaltyTerm<dim> *term,
                const PatternBuilder      &rebuild_pattern);

    /**
     * With a penalty term: a trial point that moves a DoF by more than
     * @p max_increment from the last accepted iterate, or further than
     * the term's max_step() allows (a body 1 point must not cross body
     * 2's thin penalty layer in one step), counts as a failed evaluation,
     * so Ipopt's line search steps back. A body held only by contact has
     * a singular Hessian until it touches, and Ipopt's full step would
     * carry it through the other body. 0: no limit.
     */
    void
    set_step_limit(const double max_increment);

    /// Add the lagged friction term @p term (null: none) to the objective
    /// of every following solve: f, its gradient and its Hessian
    /// (doc/friction.md). The step's outer loop re-lags it between solves.
    void
    set_friction(const Contact::FrictionTerm<dim> *term)
    {
      friction = term;
    }

    /**
     * Minimise at load time @p time. @p target: the Dirichlet values and
     * hanging nodes at this time (inhomogeneous constraints, used to
     * complete each iterate). @p u (ghosted, serial) holds the start and
     * receives the last iterate, whether or not Ipopt succeeded. @p mu:
     * the penalty factor, if set_penalty() was called.
     */
    Result
    solve(const double                     time,
          const AffineConstraints<double> &target,
          VectorType                      &u,
          const double                     mu = 0.);

    class Problem;

    /// Save and load the warm-start data (whether to warm-start, the
    /// last multipliers) for checkpoints; load after setup().
    void
    save_state(OutputArchive &archive) const;
    void
    load_state(InputArchive &archive);

  private:
    friend class Problem;

    /// Add value * d(dof)/d(variables) to @p row: the DoF's own variable
    /// or, for a hanging node, its parents' (Dirichlet DoFs drop out).
    void
    add_condensed(const types::global_dof_index dof,
                  const double                  value,
                  std::map<int, double>        &row) const;

    /// Record the lower-triangle Hessian structure of the matrix's pattern.
    void
    setup_hessian_structure();

    /// Copy the matrix's lower triangle into Ipopt's @p values, in the
    /// structure recorded last (entries the matrix lacks are zero, entries
    /// outside the structure are dropped if the pattern was rebuilt).
    void
    read_hessian(double *values) const;

    Parameters                           parameters;
    const DoFHandler<dim>               &dof_handler;
    const EnergyFunctional<dim>         &energy;
    const Contact::NodeWiseConstraints<dim> *contact;
    const Incompressibility<dim>        *incompressibility;
    Contact::PenaltyTerm<dim>           *penalty = nullptr;
    const Contact::FrictionTerm<dim>    *friction = nullptr;
    PatternBuilder                       rebuild_pattern;
    bool                                 pattern_stale = false;
    bool                                 non_finite_stop = false;
    double                               max_increment = 0.;
    std::string                          output_directory;
    ConditionalOStream                  &progress;
    TimerOutput                         &timer;

    const AffineConstraints<double> *constraints = nullptr;
    MatrixType                      *hessian     = nullptr;
    std::vector<types::global_dof_index> free_dofs;  // variable -> DoF
    std::vector<int>                     variable_of; // DoF -> variable or -1
    // Contact rows: the nodes with a free component, and their entries.
    std::vector<unsigned int>              contact_rows;
    std::vector<std::vector<std::pair<unsigned int, int>>> contact_entries; // (component, variable)
    // Incompressibility rows: the sorted variables each cell row touches.
    std::vector<std::vector<int>> cell_entries;
    // Lower-triangle Hessian structure, in matrix row iteration order.
    std::vector<int> hessian_rows, hessian_cols;
    std::vector<int>          local_rows;    // Epetra row of each variable
    std::vector<unsigned int> row_starts;    // CSR offsets into row_positions
    std::vector<int>          row_positions; // entry index within the row
    unsigned int     n_jacobian_entries = 0;

    // Warm start.
    bool                warm = false;
    std::vector<double> last_lambda;

    // The Ipopt application (created once: it keeps its journal open).
    struct Application;
    std::unique_ptr<Application> application;
    bool                         application_has_file = false;
    void
    create_application(const bool with_output_file);
  };
} // namespace Signorini
