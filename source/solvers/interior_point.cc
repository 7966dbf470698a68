#include <signorini/archive_io.h>
#include <signorini/input_error.h>
#include <signorini/interruption.h>
#include <signorini/solvers/interior_point.h>

#include <deal.II/base/mpi.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

namespace Signorini
{
  void
  InteriorPointParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Tolerance",
                      "1e-10",
                      Patterns::Double(0.),
                      "Converged when |grad E - sum z_k grad g_k|_2 <= this "
                      "* force scale, max |g_k - s_k| <= this * h and max "
                      "s_k z_k <= this * force scale * h (h: the smallest "
                      "contact mesh size; force scale as for Newton).");
    prm.declare_entry("Acceptable tolerance",
                      "1e-6",
                      Patterns::Double(0.),
                      "When the largest of the three relative residuals of "
                      "'Tolerance' has not halved in 5 iterations, the "
                      "iteration has stalled (the dual residual of an "
                      "iterative linear solver's steps can stall a little "
                      "above 'Tolerance'): the best iterate so far is kept "
                      "as converged if its residuals are all at most this "
                      "(like Ipopt's acceptable_tol), else the iteration "
                      "goes on; 0: never.");
    prm.declare_entry("Maximum iterations",
                      "100",
                      Patterns::Integer(1),
                      "Interior point iterations per load step.");
    prm.declare_entry("Initial barrier",
                      "0.1",
                      Patterns::Double(0.),
                      "Barrier parameter mu_0 of a cold start, relative to "
                      "force scale * h [-]: the starting multipliers are "
                      "z_k = mu_0 / s_k.");
    prm.declare_entry("Warm start barrier",
                      "1e-3",
                      Patterns::Double(0.),
                      "mu_0 of a warm-started load step, relative to force "
                      "scale * h [-]. Interior point iterations of the whole "
                      "load path with 1e-6 / 1e-4 / 1e-3 / 1e-2: "
                      "prm/default.prm 14 / 13 / 12 / 13, the same with 8 "
                      "load steps 53 / 41 / 48 / 51, hertz_groove.prm in 4 "
                      "steps 29 / 22 / 22 / 25, hertz_sphere.prm in 4 steps "
                      "36 (one step cut) / 33 (one cut) / 32 / 35; "
                      "doc/performance.md.");
    prm.declare_entry("Initial slack",
                      "0.01",
                      Patterns::Double(0.),
                      "Slacks start at s_k = max(g_k, this * h_k) on a cold "
                      "start (at most this * h_k above g_k when warm) [-].");
    prm.declare_entry("Warm start",
                      "true",
                      Patterns::Bool(),
                      "Start every load step after the first from the "
                      "previous step's multipliers (the displacement always "
                      "starts from the previous step).");
    prm.declare_entry("Active-set polish",
                      "true",
                      Patterns::Bool(),
                      "Once max s_k z_k <= 1e-4 force scale * h, try to finish "
                      "the load step with Newton steps on the active set the "
                      "iterate shows (gaps pinned to zero where z_k / F > "
                      "s_k / h, the other nodes free), and keep the result "
                      "only if it meets the tolerances with no penetration "
                      "and no negative force; each distinct active set is "
                      "tried once; with a direct linear solver only (the "
                      "stiff penalty slows CG + AMG down). After the first "
                      "step, chord steps reuse its factorisation while each "
                      "divides the residual by 10 (at most 3 factorisations "
                      "and 6 steps; the iteration count counts the "
                      "factorised ones). A node at the edge of the contact "
                      "zone whose gap and force both vanish otherwise makes "
                      "the last iterations converge only linearly: "
                      "prm/hertz_peer.prm at 202 692 DoFs, 8 -> 5 "
                      "factorisations (doc/performance.md).");
    prm.declare_entry("Armijo parameter",
                      "1e-4",
                      Patterns::Double(0., 1.),
                      "Sufficient decrease of the merit function "
                      "E - mu sum ln s_k + nu sum |g_k - s_k|.");
    prm.declare_entry("Maximum backtracks",
                      "30",
                      Patterns::Integer(0),
                      "Halvings of the step in the line search.");
    prm.declare_entry("Initial regularization",
                      "1e-8",
                      Patterns::Double(0.),
                      "First delta / max_j |K_jj| added to the diagonal of "
                      "the condensed matrix K when it is not positive "
                      "definite (grown tenfold per retry).");
    prm.declare_entry("Maximum regularizations",
                      "12",
                      Patterns::Integer(0),
                      "Retries with a larger delta before the step fails.");
    prm.declare_entry("Incompressibility weight",
                      "100",
                      Patterns::Double(0.),
                      "Incompressible bodies: the J = 1 constraints c_K = "
                      "int_K (J - 1) dV = 0 enter as an augmented Lagrangian "
                      "sum_K y_K c_K + rho_K/2 c_K^2, rho_K = this * mu_K / "
                      "|K| (mu_K: the small-strain shear modulus of the "
                      "cell's material, |K| its volume); after each "
                      "converged interior point solve y_K += rho_K c_K.");
    prm.declare_entry("Incompressibility tolerance",
                      "1e-10",
                      Patterns::Double(0.),
                      "Incompressible bodies: the multiplier updates stop "
                      "when every |c_K| / |K| is at most this.");
    prm.declare_entry("Maximum multiplier updates",
                      "30",
                      Patterns::Integer(1),
                      "Incompressible bodies: the load step fails if the "
                      "tolerance is not met after this many updates.");
  }

  void
  InteriorPointParameters::parse_parameters(ParameterHandler &prm)
  {
    tolerance              = prm.get_double("Tolerance");
    acceptable_tolerance   = prm.get_double("Acceptable tolerance");
    max_iterations         = prm.get_integer("Maximum iterations");
    initial_barrier        = prm.get_double("Initial barrier");
    warm_start_barrier     = prm.get_double("Warm start barrier");
    initial_slack          = prm.get_double("Initial slack");
    warm_start             = prm.get_bool("Warm start");
    active_set_polish      = prm.get_bool("Active-set polish");
    armijo_c1              = prm.get_double("Armijo parameter");
    max_backtracks         = prm.get_integer("Maximum backtracks");
    initial_regularization = prm.get_double("Initial regularization");
    max_regularizations    = prm.get_integer("Maximum regularizations");
    incompressibility_weight    = prm.get_double("Incompressibility weight");
    incompressibility_tolerance = prm.get_double("Incompressibility tolerance");
    max_multiplier_updates      = prm.get_integer("Maximum multiplier updates");
    const std::string section = "Solver > Interior point > ";
    if (!(incompressibility_weight > 0.))
      throw InputError(section + "Incompressibility weight", "must be > 0");
    if (!(incompressibility_tolerance > 0.))
      throw InputError(section + "Incompressibility tolerance", "must be > 0");
    if (!(tolerance > 0.))
      throw InputError(section + "Tolerance", "must be > 0");
    if (!(initial_barrier > 0.))
      throw InputError(section + "Initial barrier", "must be > 0");
    if (!(warm_start_barrier > 0.))
      throw InputError(section + "Warm start barrier", "must be > 0");
    if (!(initial_slack > 0.))
      throw InputError(section + "Initial slack", "must be > 0");
    if (!(armijo_c1 > 0.))
      throw InputError(section + "Armijo parameter", "must lie in (0, 1)");
    if (!(initial_regularization > 0.))
      throw InputError(section + "Initial regularization", "must be > 0");
  }

  template <int dim>
  InteriorPointMinimizer<dim>::InteriorPointMinimizer(const Parameters   &parameters,
                                                      const LinearSolver &linear_solver,
                                                      ConditionalOStream &progress,
                                                      TimerOutput        &timer)
    : parameters(parameters)
    , linear_solver(linear_solver)
    , progress(progress)
    , timer(timer)
  {}

  template <int dim>
  void
  InteriorPointMinimizer<dim>::setup(const Contact::Model<dim>       &model,
                                     const AffineConstraints<double> &constraints,
                                     const MPI_Comm                   communicator)
  {
    contact          = &model;
    configured       = true;
    const auto &list = model.contact_nodes_on_boundary().nodes();
    active.assign(list.size(), false);
    unsigned int count = 0;
    for (unsigned int k = 0; k < list.size(); ++k)
      {
        for (unsigned int c = 0; c < dim; ++c)
          if (!constraints.is_constrained(list[k].dofs[c]))
            active[k] = true;
        count += active[k];
      }
    n_constraints = Utilities::MPI::sum(count, communicator);
    z.assign(list.size(), 0.);
    warm                = false;
    mu_last             = 0.;
    last_regularization = 0.;
  }

  template <int dim>
  void
  InteriorPointMinimizer<dim>::setup_without_constraints(const double h)
  {
    contact               = nullptr;
    configured            = true;
    h_without_constraints = h;
    active.clear();
    z.clear();
    n_constraints       = 0;
    warm                = false;
    mu_last             = 0.;
    last_regularization = 0.;
  }

  template <int dim>
  typename InteriorPointMinimizer<dim>::Statistics
  InteriorPointMinimizer<dim>::minimize(Objective                       &objective,
                                        const AffineConstraints<double> &constraints,
                                        VectorType                      &u,
                                        VectorType                      &ghosted,
                                        MatrixType                      &K,
                                        VectorType                      &rhs)
  {
    Statistics stats;
    AssertThrow(configured, ExcMessage("setup() was not called"));
    const MPI_Comm comm = u.get_mpi_communicator();
    static const std::vector<Contact::BoundaryNode<dim>> no_nodes;
    const auto &nodes = contact ? contact->contact_nodes_on_boundary().nodes() : no_nodes;
    const unsigned int n = nodes.size();
    const double   m     = std::max(1u, n_constraints);
    const double   h     = contact ? contact->min_mesh_size() : h_without_constraints;

    auto sum = [comm](const double x) { return Utilities::MPI::sum(x, comm); };
    auto max = [comm](const double x) { return Utilities::MPI::max(x, comm); };
    auto min = [comm](const double x) { return Utilities::MPI::min(x, comm); };

    std::vector<State>  state(n), trial_state(n);
    auto evaluate_constraints = [&](const VectorType &x, std::vector<State> &states) {
      TimerOutput::Scope scope(timer, "constraints");
      for (unsigned int k = 0; k < n; ++k)
        if (active[k])
          states[k] = contact->constraint(nodes[k], x);
    };

    // The energy at u: value, minus its gradient into rhs and its Hessian
    // into K (condensed with the homogeneous constraints).
    Evaluation e;
    auto       full_evaluation = [&]() {
      TimerOutput::Scope scope(timer, "assembly");
      ghosted = u;
      e       = objective.evaluate(ghosted, constraints, &rhs, &K);
    };
    full_evaluation();
    stats.evaluation = e;
    if (!e.admissible)
      {
        stats.reason = "the initial state is inadmissible (min J = " +
                       std::to_string(e.min_J) + ")";
        return stats;
      }
    evaluate_constraints(ghosted, state);
    const double F    = e.force_scale > 0. ? e.force_scale : 1.;
    const double unit = F * h; // the scale of s_k z_k and of mu
    stats.force_scale = F;

    // Starting slacks and multipliers.
    std::vector<double> s(n, 0.), ds(n, 0.), dz(n, 0.);
    const bool   warm_start = warm && parameters.warm_start;
    const double mu_0 =
      (warm_start ? parameters.warm_start_barrier : parameters.initial_barrier) * unit;
    for (unsigned int k = 0; k < n; ++k)
      {
        if (!active[k])
          {
            z[k] = 0.;
            continue;
          }
        const double push = parameters.initial_slack * nodes[k].h;
        const double z_old = warm_start ? z[k] : 0.;
        s[k] = std::max(state[k].g, z_old > 0. ? std::min(push, mu_0 / z_old) : push);
        z[k] = std::max(z_old, mu_0 / s[k]);
      }

    VectorType dual(rhs), b(rhs), d(rhs), d_raw(rhs), trial(u);
    std::vector<types::global_dof_index> dofs(dim);
    FullMatrix<double>                   block(dim, dim);
    Vector<double>                       local(dim);

    // b = dual + sum_k grad g_k (c_k - z_k r_k) / s_k for targets c.
    auto corrected_rhs = [&](const std::vector<double> &c) {
      b = dual;
      for (unsigned int k = 0; k < n; ++k)
        if (active[k])
          {
            const double r = state[k].g - s[k];
            for (unsigned int i = 0; i < dim; ++i)
              {
                dofs[i]  = nodes[k].dofs[i];
                local(i) = state[k].grad[i] * (c[k] - z[k] * r) / s[k];
              }
            constraints.distribute_local_to_global(local, dofs, b);
          }
      b.compress(VectorOperation::add);
    };
    // ds, dz from dU (distributed, in d).
    auto recover = [&](const VectorType &du) {
      for (unsigned int k = 0; k < n; ++k)
        if (active[k])
          {
            double slope = 0.;
            for (unsigned int i = 0; i < dim; ++i)
              slope += state[k].grad[i] * du[nodes[k].dofs[i]];
            ds[k] = slope + state[k].g - s[k];
          }
    };
    // The largest alpha <= 1 with x + alpha dx >= (1 - tau) x.
    auto max_step = [&](const std::vector<double> &x, const std::vector<double> &dx,
                        const double tau) {
      double alpha = 1.;
      for (unsigned int k = 0; k < n; ++k)
        if (active[k] && dx[k] < 0.)
          alpha = std::min(alpha, -tau * x[k] / dx[k]);
      return min(alpha);
    };

    // out = -grad E + sum_k f_k grad g_k (at the current state): the dual
    // residual for the multipliers f (zero off the active nodes).
    auto dual_residual = [&](const std::vector<double> &f, VectorType &out) {
      out = rhs;
      for (unsigned int k = 0; k < n; ++k)
        if (active[k])
          {
            for (unsigned int i = 0; i < dim; ++i)
              {
                dofs[i]  = nodes[k].dofs[i];
                local(i) = f[k] * state[k].grad[i];
              }
            constraints.distribute_local_to_global(local, dofs, out);
          }
      out.compress(VectorOperation::add);
    };
    // max_i |K_ii| over all ranks.
    auto largest_diagonal = [&]() {
      double largest = 0.;
      for (const auto i : u.locally_owned_elements())
        largest = std::max(largest, std::abs(K.diag_element(i)));
      return max(largest);
    };

    // Active-set polish (see 'Active-set polish'): Newton steps on E with
    // the gaps of the pinned nodes held at zero by a stiff penalty rho (its
    // multiplier estimate z - rho (g + grad g . du) would lose digits, so
    // the forces come from equilibrium instead: z_k = grad E . grad g_k /
    // |grad g_k|^2 at the node) and the other nodes free. The first step
    // factorises the Hessian with the pinned blocks; the next ones are chord
    // steps on that factorisation (only the gradient is evaluated and K
    // keeps its values, so the direct solver solves again without
    // factorising) as long as each divides |r_d| by at least 10, and
    // refactorise at the current state otherwise: at most 3 factorisations
    // and 6 steps. Kept, with z of the free nodes zero and s = max(g, 0),
    // if the dual residual is at most tol F, no node penetrates by more
    // than tol h and no pinned force is negative; otherwise u is restored
    // and the iteration goes on. Returns whether it was kept; stats then
    // hold the result.
    std::vector<char> last_polished;
    auto polish = [&](const std::vector<char> &pinned, const unsigned int it) {
      const VectorType    u_start(u);
      std::vector<double> zp(n, 0.);
      for (unsigned int k = 0; k < n; ++k)
        if (pinned[k])
          zp[k] = z[k];
      const double rho = 1e6 * largest_diagonal();
      VectorType   b_p(rhs), du(rhs), residual(rhs), forces(ghosted);
      bool         kept = false, refactorise = true;
      unsigned int steps = 0, factorisations = 0;
      double       r = 0., r_previous = std::numeric_limits<double>::infinity();
      while (steps < 6 && !kept && (!refactorise || factorisations < 3))
        {
          {
            TimerOutput::Scope scope(timer, "assembly");
            if (refactorise && steps > 0)
              {
                ghosted = u;
                e       = objective.evaluate(ghosted, constraints, &rhs, &K);
              }
            b_p = rhs;
            for (unsigned int k = 0; k < n; ++k)
              if (pinned[k])
                {
                  for (unsigned int i = 0; i < dim; ++i)
                    {
                      dofs[i]  = nodes[k].dofs[i];
                      local(i) = (zp[k] - rho * state[k].g) * state[k].grad[i];
                      for (unsigned int j = 0; j < dim; ++j)
                        block(i, j) = -zp[k] * state[k].hess[i][j] +
                                      rho * state[k].grad[i] * state[k].grad[j];
                    }
                  if (refactorise)
                    constraints.distribute_local_to_global(block, local, dofs, K, b_p);
                  else
                    constraints.distribute_local_to_global(local, dofs, b_p);
                }
            if (refactorise)
              K.compress(VectorOperation::add);
            b_p.compress(VectorOperation::add);
          }
          if (refactorise)
            ++factorisations;
          bool solved = false;
          {
            TimerOutput::Scope scope(timer, "linear solve");
            LinearSolver::Info info;
            std::string        message;
            du     = 0.;
            solved = stats.count_linear_solve(
              linear_solver.solve(K, du, b_p, info, message), info, message);
          }
          ++steps;
          if (!solved)
            break;
          constraints.distribute(du);
          u.add(1., du);
          {
            // The gradient only: K keeps the values just factorised.
            TimerOutput::Scope scope(timer, "assembly");
            ghosted = u;
            e       = objective.evaluate(ghosted, constraints, &rhs, nullptr);
          }
          evaluate_constraints(ghosted, state);
          if (!e.admissible)
            break;
          // Forces from equilibrium (rhs = -grad E), then the dual residual.
          forces = rhs;
          double penetration = 0., free_penetration = 0., negative = 0.;
          for (unsigned int k = 0; k < n; ++k)
            if (active[k])
              {
                penetration = std::max(penetration, -state[k].g);
                if (!pinned[k])
                  {
                    free_penetration = std::max(free_penetration, -state[k].g);
                    zp[k]            = 0.;
                    continue;
                  }
                double along = 0., norm2 = 0.;
                for (unsigned int i = 0; i < dim; ++i)
                  {
                    along -= forces[nodes[k].dofs[i]] * state[k].grad[i];
                    norm2 += state[k].grad[i] * state[k].grad[i];
                  }
                zp[k]    = along / norm2;
                negative = std::max(negative, -zp[k]);
              }
          dual_residual(zp, residual);
          r                = residual.l2_norm();
          penetration      = max(penetration);
          free_penetration = max(free_penetration);
          negative         = max(negative);
          progress << "      active-set polish step " << steps
                   << (refactorise ? "" : " (chord)") << ": |r_d|/F "
                   << std::scientific << std::setprecision(3) << r / F
                   << ", largest penetration / h " << penetration / h
                   << ", most negative force / F " << -negative / F << std::endl;
          // A free node in the foundation or a pinned node pulling: the
          // active set is not the solution's. The pinned gaps reach zero
          // as the forces converge (the penalty holds them to r / rho).
          if (free_penetration > parameters.tolerance * h || negative > 0.)
            break;
          kept = r <= parameters.tolerance * F && penetration <= parameters.tolerance * h;
          // A step that made the residual grow or shrink less than 10x:
          // the next one refactorises (after a refactorising step, chord).
          refactorise = !refactorise && r > 0.1 * r_previous;
          r_previous  = r;
        }
      if (!kept)
        {
          progress << "      active-set polish not kept" << std::endl;
          u = u_start;
          full_evaluation();
          evaluate_constraints(ghosted, state);
          return false;
        }
      for (unsigned int k = 0; k < n; ++k)
        if (active[k])
          {
            z[k] = zp[k];
            s[k] = std::max(state[k].g, 0.);
          }
      stats.iterations = it + factorisations;
      stats.residual   = r;
      stats.evaluation = e;
      stats.converged  = true;
      warm             = true;
      return true;
    };

    std::vector<double> c(n, 0.), ds_aff(n, 0.), dz_aff(n, 0.);
    double              nu = 0.; // the merit function's penalty on |g - s|
    // The acceptable iterate with the smallest largest relative residual,
    // and the last iteration at which that residual halved (stall test).
    constexpr unsigned int stall_iterations = 5;
    struct
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
    double              mu = mu_0;
    for (unsigned int it = 0;; ++it)
      {
        Interruption::throw_if_requested(comm);

        // Residuals at the current iterate.
        dual_residual(z, dual);
        double primal = 0., complementarity = 0., gap = 0.;
        for (unsigned int k = 0; k < n; ++k)
          if (active[k])
            {
              primal          = std::max(primal, std::abs(state[k].g - s[k]));
              complementarity = std::max(complementarity, s[k] * z[k]);
              gap += s[k] * z[k];
            }
        const double dual_norm = dual.l2_norm();
        primal                 = max(primal);
        complementarity        = max(complementarity);
        const double mu_avg    = sum(gap) / m;

        stats.iterations = it;
        stats.residual   = dual_norm;
        stats.evaluation = e;
        {
          std::ostringstream line;
          line << "    ip it " << std::setw(2) << it << "  |r_d|/F "
               << std::scientific << std::setprecision(3) << dual_norm / F
               << "  |g-s|/h " << primal / h << "  max sz/Fh "
               << complementarity / unit << "  E " << std::setprecision(10)
               << e.value;
          progress << line.str() << std::endl;
        }
        if (!std::isfinite(dual_norm) || !std::isfinite(primal) ||
            !std::isfinite(complementarity))
          {
            stats.reason = "the residual is not finite";
            return stats;
          }
        const double tol = parameters.tolerance;
        if (dual_norm <= tol * F && primal <= tol * h && complementarity <= tol * unit)
          {
            stats.converged = true;
            mu_last         = mu_avg;
            warm            = true;
            return stats;
          }
        // Stall: the largest relative residual has not halved in
        // stall_iterations iterations. The best acceptable iterate (the
        // only kind that can be returned, so the only kind kept) is kept.
        {
          const double error =
            std::max({dual_norm / F, primal / h, complementarity / unit});
          if (error < best.error && error <= parameters.acceptable_tolerance)
            {
              best.error      = error;
              best.iteration  = it;
              best.dual       = dual_norm;
              best.mu_avg     = mu_avg;
              best.u          = u;
              best.s          = s;
              best.z          = z;
            }
          if (error < 0.5 * progress_error)
            {
              progress_error     = error;
              progress_iteration = it;
            }
          else if (it >= progress_iteration + stall_iterations &&
                   best.error <= parameters.acceptable_tolerance)
            {
              progress << "      no progress in " << stall_iterations
                       << " iterations: the iterate of iteration "
                       << best.iteration << " (largest relative residual "
                       << std::scientific << std::setprecision(3) << best.error
                       << ") meets the acceptable tolerance" << std::endl;
              u = best.u;
              s = best.s;
              z = best.z;
              full_evaluation();
              stats.iterations = it;
              stats.residual   = best.dual;
              stats.evaluation = e;
              stats.converged  = true;
              std::ostringstream note;
              note << "converged to the acceptable tolerance (stalled; largest "
                      "relative residual "
                   << std::scientific << std::setprecision(2) << best.error << ")";
              stats.reason = note.str();
              mu_last      = best.mu_avg;
              warm         = true;
              return stats;
            }
        }
        // Active-set polish: Newton steps on the active set the iterate
        // shows, kept only if they meet every tolerance (header).
        if (parameters.active_set_polish && n_constraints > 0 &&
            linear_solver.get_parameters().type == LinearSolver::Parameters::Type::direct &&
            complementarity <= 1e-4 * unit && primal <= tol * h)
          {
            std::vector<char> pinned(n, 0);
            for (unsigned int k = 0; k < n; ++k)
              pinned[k] = active[k] && z[k] / F > s[k] / h;
            // The polish is collective: every rank tries it if the active
            // set changed on any rank (a rank without contact nodes sees
            // none change; deciding locally hung 4-rank runs).
            if (max(pinned != last_polished ? 1. : 0.) > 0.)
              {
                last_polished = pinned;
                if (polish(pinned, it))
                  {
                    mu_last = mu_avg;
                    return stats;
                  }
              }
          }
        if (it == parameters.max_iterations)
          {
            std::ostringstream msg;
            msg << "no convergence in " << it
                << " interior point iterations (|r_d|/F = " << dual_norm / F
                << ", |g - s|/h = " << primal / h << ", max s z/(F h) = "
                << complementarity / unit << ")";
            stats.reason = msg.str();
            return stats;
          }

        // The condensed matrix: the energy's Hessian plus the node blocks
        // -z hess g + (z/s) grad g grad g^T.
        {
          TimerOutput::Scope scope(timer, "assembly");
          for (unsigned int k = 0; k < n; ++k)
            if (active[k])
              {
                for (unsigned int i = 0; i < dim; ++i)
                  {
                    dofs[i] = nodes[k].dofs[i];
                    for (unsigned int j = 0; j < dim; ++j)
                      block(i, j) = -z[k] * state[k].hess[i][j] +
                                    z[k] / s[k] * state[k].grad[i] * state[k].grad[j];
                  }
                constraints.distribute_local_to_global(block, dofs, K);
              }
          K.compress(VectorOperation::add);
        }

        // Solve K d = b; false if the solve fails or d has non-positive
        // curvature (b.d = d.K.d <= 0). d_raw: the solution before the
        // constraints are distributed (zero on constrained DoFs).
        auto solve = [&]() {
          TimerOutput::Scope scope(timer, "linear solve");
          LinearSolver::Info info;
          std::string        message;
          d_raw      = 0.;
          if (!stats.count_linear_solve(
                linear_solver.solve(K, d_raw, b, info, message), info, message))
            return false;
          const double curvature = b * d_raw;
          if (!(curvature > 1e-14 * b.l2_norm() * d_raw.l2_norm()))
            return false;
          d = d_raw;
          constraints.distribute(d);
          return true;
        };

        // The predictor (affine) step, with inertia correction.
        for (unsigned int k = 0; k < n; ++k)
          c[k] = active[k] ? -s[k] * z[k] : 0.;
        corrected_rhs(c);
        bool         solved = solve();
        double       delta  = 0.;
        if (!solved)
          {
            const double max_diagonal = largest_diagonal();
            double tau   = std::max(parameters.initial_regularization,
                                  last_regularization / 3.);
            for (unsigned int r = 0; r < parameters.max_regularizations && !solved;
                 ++r, tau *= 10.)
              {
                const double next = tau * max_diagonal;
                for (const auto i : u.locally_owned_elements())
                  if (!constraints.is_constrained(i))
                    K.add(i, i, next - delta);
                K.compress(VectorOperation::add);
                delta  = next;
                solved = solve();
                if (solved)
                  last_regularization = tau;
                progress << "      condensed matrix not positive definite: delta/max K_jj = "
                         << std::scientific << std::setprecision(1) << tau
                         << (solved ? "" : " (again)") << std::endl;
              }
            ++stats.regularized_steps;
            if (!solved)
              {
                stats.reason = "no positive definite condensed matrix after " +
                               std::to_string(parameters.max_regularizations) +
                               " regularisations" +
                               (stats.linear_failures > 0 ?
                                  "; the last linear solve: " + stats.linear_message :
                                  "");
                return stats;
              }
          }
        recover(d);
        for (unsigned int k = 0; k < n; ++k)
          if (active[k])
            {
              ds_aff[k] = ds[k];
              dz_aff[k] = (c[k] - z[k] * ds[k]) / s[k];
            }
        const double alpha_s_aff = max_step(s, ds_aff, 1.);
        const double alpha_z_aff = max_step(z, dz_aff, 1.);
        double       gap_aff     = 0.;
        for (unsigned int k = 0; k < n; ++k)
          if (active[k])
            gap_aff += (s[k] + alpha_s_aff * ds_aff[k]) * (z[k] + alpha_z_aff * dz_aff[k]);
        const double mu_aff = sum(gap_aff) / m;
        const double sigma  = std::min(1., std::pow(mu_aff / mu_avg, 3));
        mu = std::max(sigma * mu_avg, 0.1 * parameters.tolerance * unit);

        // The corrector step with the same matrix. Far from the solution
        // its second-order term can turn the step into an ascent direction
        // of the merit function phi = E - mu sum ln s + nu sum |g - s|
        // (e.g. a body that falls freely onto the foundation: the affine
        // step's large ds dz pushes it back up); then the centred step
        // without that term, and last the pure centring step (mu = mu_avg).
        double barrier = 0., violation = 0.;
        for (unsigned int k = 0; k < n; ++k)
          if (active[k])
            {
              barrier += std::log(s[k]);
              violation += std::abs(state[k].g - s[k]);
            }
        barrier   = sum(barrier);
        violation = sum(violation);
        double slope = 0.;
        bool   found = false;
        for (unsigned int variant = 0; variant < 3 && !found; ++variant)
          {
            if (variant == 2)
              mu = std::max(mu, mu_avg);
            for (unsigned int k = 0; k < n; ++k)
              c[k] = active[k] ? mu - s[k] * z[k] -
                                   (variant == 0 ? ds_aff[k] * dz_aff[k] : 0.) :
                                 0.;
            corrected_rhs(c);
            if (!solve())
              continue;
            recover(d);
            double barrier_slope = 0., z_plus = 0.;
            for (unsigned int k = 0; k < n; ++k)
              if (active[k])
                {
                  dz[k] = (c[k] - z[k] * ds[k]) / s[k];
                  barrier_slope += ds[k] / s[k];
                  z_plus = std::max(z_plus, std::abs(z[k] + dz[k]));
                }
            // nu from this iteration's multiplier estimates alone (exact
            // penalty: above every |z + dz|), not the largest of all
            // iterations: one spurious estimate early on (4e5 against
            // multipliers of 0.1 on SSNV187's corner, from a regularised
            // step) kept nu at 6e5, which turned the round-off of |g - s|
            // (1e-16 per node) into merit increases of 3e-11 against a
            // slope of 6e-12, and the line search stalled at 1.9e-8 F.
            const double nu_trial = 1.5 * max(z_plus);
            slope = -(rhs * d_raw) - mu * sum(barrier_slope) - nu_trial * violation;
            if (slope < 0. || variant == 2)
              {
                nu    = nu_trial;
                found = true;
              }
            else
              progress << "      " << (variant == 0 ? "corrector" : "centred")
                       << " step is no descent direction of the merit function"
                       << std::endl;
          }
        if (!found)
          {
            stats.reason = "the corrector step failed" +
                           (stats.linear_failures > 0 ? ": " + stats.linear_message :
                                                        std::string(""));
            return stats;
          }
        const double phi = e.value - mu * barrier + nu * violation;
        // A displacement step below round-off of the geometry with the
        // constraints and complementarity met: nothing is left to gain (the
        // dual residual of an ill-conditioned Hessian, nu = 0.4999, stalls
        // above the tolerance at round-off level).
        if (increment_limit > 0. && primal <= tol * h && complementarity <= tol * unit &&
            d.linfty_norm() <= increment_limit)
          {
            progress << "      step " << std::scientific << std::setprecision(2)
                     << d.linfty_norm() << " is below the increment tolerance"
                     << std::endl;
            stats.converged = true;
            mu_last         = mu_avg;
            warm            = true;
            return stats;
          }

        // Step lengths: fraction to the boundary, step limit.
        TimerOutput::Scope scope(timer, "line search");
        const double tau     = std::max(0.99, 1. - mu / unit);
        double       alpha   = max_step(s, ds, tau);
        const double alpha_z = max_step(z, dz, tau);
        if (step_limit > 0.)
          {
            const double largest = d.linfty_norm();
            if (largest * alpha > step_limit)
              alpha = step_limit / largest;
          }
        const double noise = 1e3 * std::numeric_limits<double>::epsilon() *
                             (std::abs(e.strain_energy) + std::abs(e.external_work) +
                              std::abs(e.value) + mu * std::abs(barrier) + nu * violation);

        bool       accepted = false;
        Evaluation trial_e;
        std::vector<double> s_trial(n, 0.);
        for (unsigned int j = 0; j <= parameters.max_backtracks; ++j)
          {
            trial = u;
            trial.add(alpha, d);
            ghosted = trial;
            trial_e = objective.evaluate(ghosted, constraints, nullptr, nullptr);
            if (trial_e.admissible)
              {
                evaluate_constraints(ghosted, trial_state);
                double trial_barrier = 0., trial_violation = 0.;
                for (unsigned int k = 0; k < n; ++k)
                  if (active[k])
                    {
                      s_trial[k] = s[k] + alpha * ds[k];
                      trial_barrier += std::log(s_trial[k]);
                      trial_violation += std::abs(trial_state[k].g - s_trial[k]);
                    }
                const double phi_trial = trial_e.value - mu * sum(trial_barrier) +
                                         nu * sum(trial_violation);
                if (std::isfinite(phi_trial) &&
                    (phi_trial <= phi + parameters.armijo_c1 * alpha * std::min(slope, 0.) ||
                     phi_trial <= phi + noise))
                  {
                    accepted = true;
                    break;
                  }
              }
            ++stats.backtracks;
            alpha *= 0.5;
          }
        if (!accepted)
          {
            stats.reason = "the line search found no admissible decrease of the "
                           "merit function after " +
                           std::to_string(parameters.max_backtracks) + " backtracks";
            return stats;
          }
        scope.stop();
        if (alpha < 1.)
          progress << "      step length " << std::scientific << std::setprecision(3)
                   << alpha << " (multipliers " << alpha_z << ")" << std::endl;

        // Accept: u, s along the step, z with its own step; slacks no
        // smaller than the constraints, multipliers near the central path.
        u = trial;
        std::swap(state, trial_state);
        for (unsigned int k = 0; k < n; ++k)
          if (active[k])
            {
              s[k] = std::max(s_trial[k], state[k].g);
              z[k] = z[k] + alpha_z * dz[k];
              z[k] = std::min(std::max(z[k], mu / (1e10 * s[k])), 1e10 * mu / s[k]);
            }
        full_evaluation();
        if (!e.admissible)
          {
            stats.reason = "inadmissible state after the line search";
            return stats;
          }
      }
  }

  template <int dim>
  void
  InteriorPointMinimizer<dim>::save_state(OutputArchive &archive) const
  {
    archive << warm << z << mu_last << last_regularization;
  }

  template <int dim>
  void
  InteriorPointMinimizer<dim>::load_state(InputArchive &archive)
  {
    std::vector<double> saved;
    archive >> warm >> saved >> mu_last >> last_regularization;
    if (saved.size() == z.size())
      z = saved;
    else
      warm = false;
  }

  template class InteriorPointMinimizer<2>;
  template class InteriorPointMinimizer<3>;
} // namespace Signorini
