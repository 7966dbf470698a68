#pragma once

#include <signorini/solvers/interior_point.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <limits>
#include <string>
#include <vector>

namespace Signorini
{
  using namespace dealii;

  /**
   * One call of InteriorPointMinimizer::minimize(), in named phases. The
   * minimiser's loop (interior_point.cc) reads as the algorithm:
   *
   *   initialise                      energy, constraints, s and z
   *   per iteration:
   *     residuals                     r_d, |g - s|, s z and the average gap
   *     converged / stalled           the tests that end the iteration
   *     polish                        Newton steps on the settled active set
   *     form_system                   H plus the condensed node blocks
   *     predictor                     the affine step and the centring sigma
   *     corrector                     Mehrotra's step, a descent direction
   *                                   of the merit function
   *     below_increment_tolerance     a step below round-off
   *     line_search                   fraction to the boundary, backtracking
   *                                   on the merit function
   *     accept                        u, s, z of the accepted step
   *
   * Each phase is a member function of at most about 150 lines; the state
   * they share (slacks, multipliers, constraint states, directions) is held
   * here for the duration of one solve. The warm-start data (multipliers,
   * last barrier, last regularisation) belong to the minimiser, which
   * outlives the solve.
   */
  template <int dim>
  class InteriorPointIteration
  {
  public:
    using Minimizer  = InteriorPointMinimizer<dim>;
    using Statistics = typename Minimizer::Statistics;
    using State      = typename Contact::NodeWiseConstraints<dim>::State;

    /// The residuals of an iterate, over all ranks.
    struct Residuals
    {
      double dual            = 0.; // |grad E - sum z grad g|_2
      double primal          = 0.; // max |g_k - s_k|
      double complementarity = 0.; // max s_k z_k
      double mu_average      = 0.; // sum s_k z_k / m

      bool
      finite() const;
    };

    InteriorPointIteration(Minimizer                       &minimizer,
                           Objective                       &objective,
                           const AffineConstraints<double> &constraints,
                           VectorType                      &u,
                           VectorType                      &ghosted,
                           MatrixType                      &matrix,
                           VectorType                      &rhs);

    /// Evaluate the energy and the constraints at u and choose the first
    /// slacks and multipliers (warm start: the last solve's multipliers).
    /// False if u is inadmissible (the reason is in statistics()).
    bool
    initialise();

    /// The residuals at the current iterate; records them in the
    /// statistics and prints the iteration's line.
    Residuals
    residuals(const unsigned int iteration);

    /// Every residual within the tolerance (the warm-start data are kept).
    bool
    converged(const Residuals &r);

    /**
     * Records the best acceptable iterate; true if the largest relative
     * residual has not halved in 5 iterations and an acceptable iterate
     * exists: u, s and z are then that iterate's and the statistics say so.
     */
    bool
    stalled(const Residuals &r, const unsigned int iteration);

    /**
     * If stalled() recorded an acceptable iterate, make it the result
     * (u, s, z and the statistics, whose note names @p short_event), say
     * @p event with it and return true; else false. After a stall, and
     * after a line search that finds no decrease: near a solution whose
     * forces vanish (the end of an unloading with friction) the merit
     * function's changes fall below what the line search can resolve
     * once an acceptable iterate has been passed.
     */
    bool
    take_best(const std::string &event,
              const std::string &short_event,
              const unsigned int iteration);

    /**
     * The active-set polish, if it applies (direct solver, complementarity
     * nearly met, the active set changed since the last attempt on any
     * rank): true if it converged (the statistics hold the result).
     */
    bool
    polish_if_settled(const Residuals &r, const unsigned int iteration);

    /// Add the condensed node blocks -z hess g + (z/s) grad g grad g^T to
    /// the energy's Hessian.
    void
    form_system();

    /**
     * The affine step (targets -s z), with inertia correction if the
     * matrix is not positive definite, and the barrier of the corrector:
     * mu = max(sigma mu_avg, tol unit / 10), sigma = (mu_aff / mu_avg)^3.
     * False if no regularisation gave a direction.
     */
    bool
    predictor(const Residuals &r);

    /**
     * The corrector step, or the centred or the pure centring step when
     * the former is no descent direction of the merit function; sets the
     * merit function's penalty nu. False if none could be solved.
     */
    bool
    corrector(const Residuals &r);

    /// The step is below the increment tolerance with the constraints and
    /// complementarity met: converged (the warm-start data are kept).
    bool
    below_increment_tolerance(const Residuals &r);

    /// Fraction to the boundary, the step limit and the backtracking line
    /// search on the merit function; false if it found no decrease.
    bool
    line_search();

    /// Take the step found by line_search(); false if the new state is
    /// inadmissible.
    bool
    accept();

    /// Ends the iteration as failed with @p reason.
    Statistics
    fail(const std::string &reason);

    /// Ends the iteration as converged: the warm-start data are kept with
    /// the barrier @p mu_average.
    Statistics
    finish(const double mu_average);

    Statistics
    statistics() const
    {
      return stats;
    }

    /// F: the energy's force scale at the start.
    double
    force_scale() const
    {
      return F;
    }

    /// h: the smallest contact mesh size (or cell size without contact).
    double
    length_scale() const
    {
      return h;
    }

    /// The iterate and the last step, read-only (for the phase tests):
    /// slacks, multipliers, their steps, the displacement step, the
    /// barrier of the step and the accepted step lengths.
    struct View
    {
      const std::vector<double> &s, &z, &ds, &dz;
      const VectorType          &du;
      double                     mu, alpha, alpha_z;
    };
    View
    view() const
    {
      return {s, z, ds, dz, d, mu, alpha, alpha_z};
    }

    /// The largest alpha <= 1 with x + alpha dx >= (1 - tau) x over the
    /// active nodes of every rank (fraction to the boundary).
    double
    max_step(const std::vector<double> &x,
             const std::vector<double> &dx,
             const double               tau) const;

  private:
    /// The energy, its gradient and Hessian at u (ghosted gets u).
    void
    full_evaluation();
    /// The constraint states of the active nodes at @p x.
    void
    evaluate_constraints(const VectorType &x, std::vector<State> &states) const;
    /// b = dual + sum_k grad g_k (c_k - z_k r_k) / s_k for the targets c.
    void
    corrected_rhs(const std::vector<double> &targets);
    /// ds from the displacement step @p du.
    void
    recover(const VectorType &du);
    /// out = -grad E + sum_k f_k grad g_k at the current state.
    void
    dual_residual(const std::vector<double> &f, VectorType &out);
    /// max_i |K_ii| over all ranks.
    double
    largest_diagonal() const;
    /// Solve K d = b; false if the solve fails or d has non-positive
    /// curvature.
    bool
    solve_direction();
    /// Add delta I to K until solve_direction() succeeds.
    bool
    regularise_and_solve();
    /// Newton steps on the active set @p start_set (updated inside, see
    /// interior_point_polish.cc); whether kept.
    bool
    polish(const std::vector<char> &start_set, const unsigned int iteration);
    /// Frees the pinned nodes with a negative force and pins the free ones
    /// that penetrate by more than tol h (their zp restart at zero).
    void
    update_pinned(std::vector<char> &pinned, std::vector<double> &zp);
    /// Add the pinned nodes' stiff penalty to the right-hand side @p b_p
    /// (and to K when @p with_matrix).
    void
    add_pinned_blocks(const std::vector<char>   &pinned,
                      const std::vector<double> &zp,
                      const double               rho,
                      const bool                 with_matrix,
                      VectorType                &b_p);
    /// The pinned nodes' forces from equilibrium (zero on free nodes) and
    /// the largest penetration (all, free nodes) and negative force.
    struct PolishCheck
    {
      double penetration      = 0.;
      double free_penetration = 0.;
      double negative         = 0.;
    };
    PolishCheck
    equilibrium_forces(const std::vector<char> &pinned,
                       const VectorType        &forces,
                       std::vector<double>     &zp) const;

    Minimizer                       &minimizer;
    const InteriorPointParameters   &parameters;
    Objective                       &objective;
    const AffineConstraints<double> &constraints;
    VectorType                      &u;
    VectorType                      &ghosted;
    MatrixType                      &K;
    VectorType                      &rhs;
    const MPI_Comm                   comm;

    const std::vector<Contact::BoundaryNode<dim>> &nodes;
    const unsigned int                             n; // this rank's nodes
    const double m; // constraints on all ranks (at least 1)
    const double h; // the smallest contact mesh size
    double       F    = 1.; // the energy's force scale at the start
    double       unit = 1.; // F h: the scale of s z and of mu

    Statistics          stats;
    Evaluation          e;
    std::vector<State>  state, trial_state;
    std::vector<double> &z; // the minimiser's multipliers
    std::vector<double> s, ds, dz, c, ds_aff, dz_aff, s_trial;
    VectorType          dual, b, d, d_raw, trial;

    std::vector<types::global_dof_index> dofs;
    FullMatrix<double>                   block;
    Vector<double>                       local;

    double mu      = 0.; // the barrier of the step
    double nu      = 0.; // the merit function's penalty on |g - s|
    double slope   = 0.; // the merit function's slope along the step
    double phi     = 0.; // the merit function at u
    double barrier = 0., violation = 0.; // sum ln s, sum |g - s|
    double alpha   = 0., alpha_z = 0.;   // accepted step lengths

    // The acceptable iterate with the smallest largest relative residual,
    // and the last iteration at which that residual halved (stall test).
    struct Best
    {
      double              error     = std::numeric_limits<double>::infinity();
      unsigned int        iteration = 0;
      double              dual      = 0.;
      double              mu_avg    = 0.;
      VectorType          u;
      std::vector<double> s, z;
    } best;
    double       progress_error     = std::numeric_limits<double>::infinity();
    unsigned int progress_iteration = 0;

    std::vector<char> last_polished;
  };
} // namespace Signorini
