#pragma once

#include <signorini/solvers/interior_point_parameters.h>

#include <signorini/archive.h>
#include <signorini/mesh_state.h>
#include <signorini/contact/node_wise_constraints.h>
#include <signorini/problem/objective.h>
#include <signorini/solvers/linear_solver.h>
#include <signorini/solvers/newton.h>
#include <signorini/types.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>
#include <deal.II/lac/affine_constraints.h>

#include <vector>

namespace Signorini
{
  using namespace dealii;

  template <int dim>
  class InteriorPointIteration;

  /**
   * A primal-dual interior point method for
   *
   *   min E(U)  subject to  g_k(U) >= 0, k = the contact model's nodes,
   *
   * on the project's distributed vectors and matrices (formulation.md
   * section 2), where each g_k depends on the dim DoFs of its own node.
   * With a slack s_k > 0 and a multiplier z_k > 0 per constraint, Newton's
   * method on the perturbed optimality conditions
   *
   *   grad E - sum_k z_k grad g_k = 0,   g_k - s_k = 0,   s_k z_k = mu,
   *
   * is condensed node by node onto the displacement: with
   * r_k = g_k - s_k and a complementarity target c_k,
   *
   *   (H - sum z_k hess g_k + sum (z_k / s_k) grad g_k grad g_k^T) dU
   *     = -grad E + sum z_k grad g_k + sum grad g_k (c_k - z_k r_k) / s_k,
   *
   * ds_k = grad g_k . dU + r_k,  dz_k = (c_k - z_k ds_k) / s_k.
   *
   * The node blocks fall into the finite element pattern of H, so the
   * system is the Newton system of the energy with extra entries on the
   * contact nodes' diagonal blocks and is solved by the same LinearSolver
   * (direct or AMG-preconditioned Krylov, on any number of MPI ranks).
   *
   * - Barrier: Mehrotra's predictor-corrector. The affine step (c = -s z)
   *   gives the centring sigma = (mu_aff / mu_avg)^3, the corrector solves
   *   again with c = sigma mu_avg - s z - ds_aff dz_aff (the direct solver
   *   reuses its factorisation for the second right-hand side).
   * - Step: fraction to the boundary tau = max(0.99, 1 - mu / mu_unit) for
   *   s and z separately; a backtracking line search on the merit function
   *   E - mu sum ln s_k + nu sum |g_k - s_k| from the largest step that
   *   keeps s > 0, no DoF moving by more than the step limit; a state
   *   with J <= 0 is rejected. After the step, s_k = max(s_k, g_k) and z_k
   *   is kept within [mu / (1e10 s_k), 1e10 mu / s_k].
   * - Inertia: if the solve fails or the direction has non-positive
   *   curvature (b.dU <= 0 for the system K dU = b), delta I is added to
   *   the matrix (delta a multiple of its largest diagonal entry, tried
   *   from 1/3 of the last successful one and grown tenfold) and the step
   *   is solved again.
   * - Convergence: |grad E - sum z grad g|_2 <= tol F, max |g_k - s_k| <=
   *   tol h and max s_k z_k <= tol F h, with F the energy's force scale at
   *   the start and h the smallest contact mesh size; or the last two with
   *   a displacement step below the increment tolerance (round-off); or,
   *   when the largest of the three relative residuals has not halved in
   *   5 iterations (a stall: the steps of an iterative linear solver can
   *   leave the dual residual a little above tol), the best iterate so
   *   far if all three are at most the acceptable tolerance (reported in
   *   Statistics::reason).
   * - Warm start: the previous step's multipliers; slacks s_k = max(g_k,
   *   min(initial slack h_k, mu_0 / z_k)) and z_k >= mu_0 / s_k.
   *
   * The multipliers z_k are the nodal contact forces (along grad g_k).
   */
  template <int dim>
  class InteriorPointMinimizer
  {
  public:
    using Parameters = InteriorPointParameters;
    using Statistics = NewtonMinimizer::Statistics;

    InteriorPointMinimizer(const Parameters   &parameters,
                           const LinearSolver &linear_solver,
                           ConditionalOStream &progress,
                           TimerOutput        &timer);

    /**
     * Take the nodes of @p contact (its node-wise constraints) on the
     * current DoFs; a node whose DoFs are all constrained by
     * @p constraints (homogeneous Dirichlet data) carries no constraint.
     * Forgets the warm-start data.
     */
    void
    setup(const Contact::NodeWiseConstraints<dim> &contact,
          const AffineConstraints<double> &constraints,
          const MPI_Comm                   communicator);

    /**
     * No node-wise constraints (a scene without contact whose objective
     * carries its equality constraints itself, e.g. incompressibility by
     * an augmented Lagrangian): the iteration is Newton's with the merit
     * line search. @p h is the length scale of the step tests (the
     * smallest cell size).
     */
    void
    setup_without_constraints(const double h);

    /// No DoF moves by more than @p limit in one step (0: no limit). A
    /// step of at most @p increment_tolerance in every DoF, with the
    /// constraints and complementarity met, ends the iteration as converged
    /// (0: never).
    void
    set_step_limits(const double limit, const double increment_tolerance)
    {
      step_limit      = limit;
      increment_limit = increment_tolerance;
    }

    /**
     * Minimise @p objective subject to the constraints from @p u (locally
     * owned entries, satisfying @p constraints' inhomogeneities). @p ghosted,
     * @p matrix and @p rhs are work objects with the layout and sparsity
     * of the problem. On return @p u holds the last iterate.
     */
    Statistics
    minimize(Objective                       &objective,
             const AffineConstraints<double> &constraints,
             VectorType                      &u,
             VectorType                      &ghosted,
             MatrixType                      &matrix,
             VectorType                      &rhs);

    /// The multipliers z_k of the last solve, one per contact node of this
    /// rank (0 for a node without a constraint): the nodal contact forces.
    const std::vector<double> &
    multipliers() const
    {
      return z;
    }

    /// The barrier parameter at the end of the last solve.
    double
    final_barrier() const
    {
      return mu_last;
    }

    /**
     * Start the next solve, if it is warm, from the barrier @p relative x
     * force scale x h instead of 'Warm start barrier': for a re-solve from
     * a converged state whose objective changed a little (the friction
     * loop's next outer iteration, doc/friction.md). Only the next solve.
     */
    void
    restart_barrier(const double relative)
    {
      next_barrier = relative;
    }

    /**
     * The warm-start data, for checkpoints: the multipliers as a field on
     * their nodes' first DoFs into @p mesh, whether they start the next
     * solve, the last barrier and regularisation into @p archive (the
     * same on every rank). The slacks are not kept: a warm start sets
     * them from the constraints and these multipliers. Load after setup()
     * on the restarted run's mesh, on any number of ranks.
     */
    void
    save_state(OutputArchive &archive, MeshState &mesh) const;
    void
    load_state(InputArchive &archive, MeshState &mesh);

  private:
    /// The first DoF of each contact node: where z is kept in a
    /// checkpoint.
    std::vector<types::global_dof_index>
    multiplier_dofs() const;

    // One call of minimize(), in named phases; it reads and keeps the
    // warm-start data below.
    friend class InteriorPointIteration<dim>;

    Parameters          parameters;
    const LinearSolver &linear_solver;
    ConditionalOStream &progress;
    TimerOutput        &timer;
    double              step_limit      = 0.;
    double              increment_limit = 0.;

    const Contact::NodeWiseConstraints<dim> *contact = nullptr;
    bool                       configured = false;
    double                     h_without_constraints = 0.;
    std::vector<bool>          active; // the node carries a constraint
    unsigned int               n_constraints = 0; // over all ranks

    // Warm start.
    bool                warm = false;
    double              next_barrier = 0.; // restart_barrier(); 0: none
    std::vector<double> z;
    double              mu_last = 0.;
    double              last_regularization = 0.;
  };
} // namespace Signorini
