#include <signorini/solvers/interior_point_iteration.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace Signorini
{
  namespace
  {
    template <int dim>
    const std::vector<Contact::BoundaryNode<dim>> &
    constraint_nodes(const Contact::NodeWiseConstraints<dim> *contact)
    {
      static const std::vector<Contact::BoundaryNode<dim>> no_nodes;
      return contact ? contact->contact_nodes_on_boundary().nodes() : no_nodes;
    }
  } // namespace

  template <int dim>
  bool
  InteriorPointIteration<dim>::Residuals::finite() const
  {
    return std::isfinite(dual) && std::isfinite(primal) && std::isfinite(complementarity);
  }

  template <int dim>
  InteriorPointIteration<dim>::InteriorPointIteration(
    Minimizer                       &minimizer,
    Objective                       &objective,
    const AffineConstraints<double> &constraints,
    VectorType                      &u,
    VectorType                      &ghosted,
    MatrixType                      &matrix,
    VectorType                      &rhs)
    : minimizer(minimizer)
    , parameters(minimizer.parameters)
    , objective(objective)
    , constraints(constraints)
    , u(u)
    , ghosted(ghosted)
    , K(matrix)
    , rhs(rhs)
    , comm(u.get_mpi_communicator())
    , nodes(constraint_nodes(minimizer.contact))
    , n(nodes.size())
    , m(std::max(1u, minimizer.n_constraints))
    , h(minimizer.contact ? minimizer.contact->min_mesh_size() :
                            minimizer.h_without_constraints)
    , state(n)
    , trial_state(n)
    , z(minimizer.z)
    , s(n, 0.)
    , ds(n, 0.)
    , dz(n, 0.)
    , c(n, 0.)
    , ds_aff(n, 0.)
    , dz_aff(n, 0.)
    , s_trial(n, 0.)
    , dual(rhs)
    , b(rhs)
    , d(rhs)
    , d_raw(rhs)
    , trial(u)
    , dofs(dim)
    , block(dim, dim)
    , local(dim)
  {}

  template <int dim>
  void
  InteriorPointIteration<dim>::full_evaluation()
  {
    TimerOutput::Scope scope(minimizer.timer, "assembly");
    ghosted = u;
    e       = objective.evaluate(ghosted, constraints, &rhs, &K);
  }

  template <int dim>
  void
  InteriorPointIteration<dim>::evaluate_constraints(const VectorType   &x,
                                                    std::vector<State> &states) const
  {
    TimerOutput::Scope scope(minimizer.timer, "constraints");
    for (unsigned int k = 0; k < n; ++k)
      if (minimizer.active[k])
        states[k] = minimizer.contact->constraint(nodes[k], x);
  }

  template <int dim>
  bool
  InteriorPointIteration<dim>::initialise()
  {
    full_evaluation();
    stats.evaluation = e;
    if (!e.admissible)
      {
        stats.reason = "the initial state is inadmissible (min J = " +
                       std::to_string(e.min_J) + ")";
        return false;
      }
    evaluate_constraints(ghosted, state);
    F                 = e.force_scale > 0. ? e.force_scale : 1.;
    unit              = F * h;
    stats.force_scale = F;

    // Starting slacks and multipliers.
    const bool   warm_start = minimizer.warm && parameters.warm_start;
    const double mu_0 =
      (!warm_start                  ? parameters.initial_barrier :
       minimizer.next_barrier > 0. ? minimizer.next_barrier :
                                     parameters.warm_start_barrier) *
      unit;
    minimizer.next_barrier = 0.;
    for (unsigned int k = 0; k < n; ++k)
      {
        if (!minimizer.active[k])
          {
            z[k] = 0.;
            continue;
          }
        const double push  = parameters.initial_slack * nodes[k].h;
        const double z_old = warm_start ? z[k] : 0.;
        s[k] = std::max(state[k].g, z_old > 0. ? std::min(push, mu_0 / z_old) : push);
        z[k] = std::max(z_old, mu_0 / s[k]);
      }
    mu = mu_0;
    return true;
  }

  template <int dim>
  void
  InteriorPointIteration<dim>::corrected_rhs(const std::vector<double> &targets)
  {
    b = dual;
    for (unsigned int k = 0; k < n; ++k)
      if (minimizer.active[k])
        {
          const double r = state[k].g - s[k];
          for (unsigned int i = 0; i < dim; ++i)
            {
              dofs[i]  = nodes[k].dofs[i];
              local(i) = state[k].grad[i] * (targets[k] - z[k] * r) / s[k];
            }
          constraints.distribute_local_to_global(local, dofs, b);
        }
    b.compress(VectorOperation::add);
  }

  template <int dim>
  void
  InteriorPointIteration<dim>::recover(const VectorType &du)
  {
    for (unsigned int k = 0; k < n; ++k)
      if (minimizer.active[k])
        {
          double slope_k = 0.;
          for (unsigned int i = 0; i < dim; ++i)
            slope_k += state[k].grad[i] * du[nodes[k].dofs[i]];
          ds[k] = slope_k + state[k].g - s[k];
        }
  }

  template <int dim>
  double
  InteriorPointIteration<dim>::max_step(const std::vector<double> &x,
                                        const std::vector<double> &dx,
                                        const double               tau) const
  {
    double step = 1.;
    for (unsigned int k = 0; k < n; ++k)
      if (minimizer.active[k] && dx[k] < 0.)
        step = std::min(step, -tau * x[k] / dx[k]);
    return Utilities::MPI::min(step, comm);
  }

  template <int dim>
  void
  InteriorPointIteration<dim>::dual_residual(const std::vector<double> &f,
                                             VectorType                &out)
  {
    out = rhs;
    for (unsigned int k = 0; k < n; ++k)
      if (minimizer.active[k])
        {
          for (unsigned int i = 0; i < dim; ++i)
            {
              dofs[i]  = nodes[k].dofs[i];
              local(i) = f[k] * state[k].grad[i];
            }
          constraints.distribute_local_to_global(local, dofs, out);
        }
    out.compress(VectorOperation::add);
  }

  template <int dim>
  double
  InteriorPointIteration<dim>::largest_diagonal() const
  {
    double largest = 0.;
    for (const auto i : u.locally_owned_elements())
      largest = std::max(largest, std::abs(K.diag_element(i)));
    return Utilities::MPI::max(largest, comm);
  }

  template <int dim>
  typename InteriorPointIteration<dim>::Residuals
  InteriorPointIteration<dim>::residuals(const unsigned int iteration)
  {
    dual_residual(z, dual);
    Residuals r;
    double    gap = 0.;
    for (unsigned int k = 0; k < n; ++k)
      if (minimizer.active[k])
        {
          r.primal          = std::max(r.primal, std::abs(state[k].g - s[k]));
          r.complementarity = std::max(r.complementarity, s[k] * z[k]);
          gap += s[k] * z[k];
        }
    r.dual            = dual.l2_norm();
    r.primal          = Utilities::MPI::max(r.primal, comm);
    r.complementarity = Utilities::MPI::max(r.complementarity, comm);
    r.mu_average      = Utilities::MPI::sum(gap, comm) / m;

    stats.iterations = iteration;
    stats.residual   = r.dual;
    stats.evaluation = e;
    std::ostringstream line;
    line << "    ip it " << std::setw(2) << iteration << "  |r_d|/F " << std::scientific
         << std::setprecision(3) << r.dual / F << "  |g-s|/h " << r.primal / h
         << "  max sz/Fh " << r.complementarity / unit << "  E "
         << std::setprecision(10) << e.value;
    minimizer.progress << line.str() << std::endl;
    return r;
  }

  template <int dim>
  bool
  InteriorPointIteration<dim>::converged(const Residuals &r)
  {
    const double tol = parameters.tolerance;
    return r.dual <= tol * F && r.primal <= tol * h && r.complementarity <= tol * unit;
  }

  template <int dim>
  typename InteriorPointIteration<dim>::Statistics
  InteriorPointIteration<dim>::finish(const double mu_average)
  {
    stats.converged   = true;
    minimizer.mu_last = mu_average;
    minimizer.warm    = true;
    return stats;
  }

  template <int dim>
  typename InteriorPointIteration<dim>::Statistics
  InteriorPointIteration<dim>::fail(const std::string &reason)
  {
    stats.reason = reason;
    return stats;
  }

  template <int dim>
  bool
  InteriorPointIteration<dim>::stalled(const Residuals &r, const unsigned int iteration)
  {
    constexpr unsigned int stall_iterations = 5;
    const double           error =
      std::max({r.dual / F, r.primal / h, r.complementarity / unit});
    // The best acceptable iterate (the only kind that can be returned, so
    // the only kind kept).
    if (error < best.error && error <= parameters.acceptable_tolerance)
      {
        best.error     = error;
        best.iteration = iteration;
        best.dual      = r.dual;
        best.mu_avg    = r.mu_average;
        best.u         = u;
        best.s         = s;
        best.z         = z;
      }
    if (error < 0.5 * progress_error)
      {
        progress_error     = error;
        progress_iteration = iteration;
        return false;
      }
    if (iteration < progress_iteration + stall_iterations)
      return false;
    return take_best("no progress in " + std::to_string(stall_iterations) + " iterations",
                     "stalled", iteration);
  }

  template <int dim>
  bool
  InteriorPointIteration<dim>::take_best(const std::string &event,
                                         const std::string &short_event,
                                         const unsigned int iteration)
  {
    if (best.error > parameters.acceptable_tolerance)
      return false;
    minimizer.progress << "      " << event << ": the iterate of iteration " << best.iteration
                       << " (largest relative residual " << std::scientific
                       << std::setprecision(3) << best.error
                       << ") meets the acceptable tolerance" << std::endl;
    u = best.u;
    s = best.s;
    z = best.z;
    full_evaluation();
    stats.iterations = iteration;
    stats.residual   = best.dual;
    stats.evaluation = e;
    std::ostringstream note;
    note << "converged to the acceptable tolerance (" << short_event
         << "; largest relative residual "
         << std::scientific << std::setprecision(2) << best.error << ")";
    stats.reason = note.str();
    finish(best.mu_avg);
    return true;
  }

  template <int dim>
  bool
  InteriorPointIteration<dim>::polish_if_settled(const Residuals   &r,
                                                 const unsigned int iteration)
  {
    // Iterative solves need ML's kept hierarchy of the scaled matrix, which
    // sees the pinned rows' stiff penalty as a unit diagonal (ML's hierarchy
    // of the unscaled matrix made CG crawl); a new PETSc hierarchy for
    // every matrix (GAMG, BoomerAMG without 'Keep preconditioner') copes.
    const auto &linear = minimizer.linear_solver.get_parameters();
    const bool  cg     = linear.type == LinearSolver::Parameters::Type::cg_amg;
    if (!parameters.active_set_polish || minimizer.n_constraints == 0 ||
        (linear.type != LinearSolver::Parameters::Type::direct &&
         !(cg && (linear.keep_preconditioner ||
                  linear.amg_package != LinearSolver::Parameters::AmgPackage::ml))) ||
        r.complementarity > 1e-4 * unit || r.primal > parameters.tolerance * h)
      return false;
    std::vector<char> pinned(n, 0);
    for (unsigned int k = 0; k < n; ++k)
      pinned[k] = minimizer.active[k] && z[k] / F > s[k] / h;
    // The polish is collective: every rank tries it if the active set
    // changed on any rank (a rank without contact nodes sees none change;
    // deciding locally hung 4-rank runs).
    // Without a pinned node the bodies held by contact alone are free (a
    // singular matrix); the polish waits for a contact zone.
    if (Utilities::MPI::max(pinned != last_polished ? 1. : 0., comm) == 0. ||
        Utilities::MPI::max(std::count(pinned.begin(), pinned.end(), 1) > 0 ? 1. : 0.,
                            comm) == 0.)
      return false;
    last_polished = pinned;
    if (!polish(pinned, iteration))
      return false;
    minimizer.mu_last = r.mu_average;
    return true;
  }

  template <int dim>
  void
  InteriorPointIteration<dim>::form_system()
  {
    TimerOutput::Scope scope(minimizer.timer, "assembly");
    for (unsigned int k = 0; k < n; ++k)
      if (minimizer.active[k])
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

  template <int dim>
  bool
  InteriorPointIteration<dim>::solve_direction()
  {
    TimerOutput::Scope scope(minimizer.timer, "linear solve");
    LinearSolver::Info info;
    std::string        message;
    d_raw = 0.;
    if (!stats.count_linear_solve(
          minimizer.linear_solver.solve(K, d_raw, b, info, message), info, message))
      return false;
    // d_raw: the solution before the constraints are distributed (zero on
    // constrained DoFs); b.d = d.K.d <= 0 is non-positive curvature.
    const double curvature = b * d_raw;
    if (!(curvature > 1e-14 * b.l2_norm() * d_raw.l2_norm()))
      return false;
    d = d_raw;
    constraints.distribute(d);
    return true;
  }

  template <int dim>
  bool
  InteriorPointIteration<dim>::regularise_and_solve()
  {
    const double max_diagonal = largest_diagonal();
    double       delta        = 0.;
    double       tau =
      std::max(parameters.initial_regularization, minimizer.last_regularization / 3.);
    bool solved = false;
    for (unsigned int r = 0; r < parameters.max_regularizations && !solved;
         ++r, tau *= 10.)
      {
        const double next = tau * max_diagonal;
        for (const auto i : u.locally_owned_elements())
          if (!constraints.is_constrained(i))
            K.add(i, i, next - delta);
        K.compress(VectorOperation::add);
        delta  = next;
        solved = solve_direction();
        if (solved)
          minimizer.last_regularization = tau;
        minimizer.progress << "      condensed matrix not positive definite: delta/max K_jj = "
                           << std::scientific << std::setprecision(1) << tau
                           << (solved ? "" : " (again)") << std::endl;
      }
    ++stats.regularized_steps;
    return solved;
  }

  template <int dim>
  bool
  InteriorPointIteration<dim>::predictor(const Residuals &r)
  {
    for (unsigned int k = 0; k < n; ++k)
      c[k] = minimizer.active[k] ? -s[k] * z[k] : 0.;
    corrected_rhs(c);
    if (!solve_direction() && !regularise_and_solve())
      {
        stats.reason =
          "no positive definite condensed matrix after " +
          std::to_string(parameters.max_regularizations) + " regularisations" +
          (stats.linear_failures > 0 ? "; the last linear solve: " + stats.linear_message :
                                       "");
        return false;
      }
    recover(d);
    for (unsigned int k = 0; k < n; ++k)
      if (minimizer.active[k])
        {
          ds_aff[k] = ds[k];
          dz_aff[k] = (c[k] - z[k] * ds[k]) / s[k];
        }
    const double alpha_s_aff = max_step(s, ds_aff, 1.);
    const double alpha_z_aff = max_step(z, dz_aff, 1.);
    double       gap_aff     = 0.;
    for (unsigned int k = 0; k < n; ++k)
      if (minimizer.active[k])
        gap_aff += (s[k] + alpha_s_aff * ds_aff[k]) * (z[k] + alpha_z_aff * dz_aff[k]);
    const double mu_aff = Utilities::MPI::sum(gap_aff, comm) / m;
    const double sigma  = std::min(1., std::pow(mu_aff / r.mu_average, 3));
    // Capped: never above the previous iteration's barrier (mu_0 at the
    // first), see "Barrier update".
    const double previous = mu;
    mu                    = sigma * r.mu_average;
    if (parameters.capped_barrier && previous > 0.)
      mu = std::min(mu, previous);
    mu = std::max(mu, 0.1 * parameters.tolerance * unit);
    return true;
  }

  template <int dim>
  bool
  InteriorPointIteration<dim>::corrector(const Residuals &r)
  {
    // Far from the solution the corrector's second-order term can turn the
    // step into an ascent direction of the merit function phi = E - mu sum
    // ln s + nu sum |g - s| (e.g. a body that falls freely onto the
    // foundation: the affine step's large ds dz pushes it back up); then
    // the centred step without that term, and last the pure centring step
    // (mu = mu_avg).
    barrier   = 0.;
    violation = 0.;
    for (unsigned int k = 0; k < n; ++k)
      if (minimizer.active[k])
        {
          barrier += std::log(s[k]);
          violation += std::abs(state[k].g - s[k]);
        }
    barrier   = Utilities::MPI::sum(barrier, comm);
    violation = Utilities::MPI::sum(violation, comm);
    slope     = 0.;
    bool found = false;
    for (unsigned int variant = 0; variant < 3 && !found; ++variant)
      {
        if (variant == 2)
          mu = std::max(mu, r.mu_average);
        for (unsigned int k = 0; k < n; ++k)
          c[k] = minimizer.active[k] ?
                   mu - s[k] * z[k] - (variant == 0 ? ds_aff[k] * dz_aff[k] : 0.) :
                   0.;
        corrected_rhs(c);
        if (!solve_direction())
          continue;
        recover(d);
        double barrier_slope = 0., z_plus = 0.;
        for (unsigned int k = 0; k < n; ++k)
          if (minimizer.active[k])
            {
              dz[k] = (c[k] - z[k] * ds[k]) / s[k];
              barrier_slope += ds[k] / s[k];
              z_plus = std::max(z_plus, std::abs(z[k] + dz[k]));
            }
        // nu from this iteration's multiplier estimates alone (exact
        // penalty: above every |z + dz|), not the largest of all
        // iterations: one spurious estimate early on (4e5 against
        // multipliers of 0.1 on SSNV187's corner, from a regularised step)
        // kept nu at 6e5, which turned the round-off of |g - s| (1e-16 per
        // node) into merit increases of 3e-11 against a slope of 6e-12,
        // and the line search stalled at 1.9e-8 F.
        const double nu_trial = 1.5 * Utilities::MPI::max(z_plus, comm);
        slope = -(rhs * d_raw) - mu * Utilities::MPI::sum(barrier_slope, comm) -
                nu_trial * violation;
        if (slope < 0. || variant == 2)
          {
            nu    = nu_trial;
            found = true;
          }
        else
          minimizer.progress << "      " << (variant == 0 ? "corrector" : "centred")
                             << " step is no descent direction of the merit function"
                             << std::endl;
      }
    if (!found)
      {
        stats.reason = "the corrector step failed" +
                       (stats.linear_failures > 0 ? ": " + stats.linear_message :
                                                    std::string(""));
        return false;
      }
    phi = e.value - mu * barrier + nu * violation;
    return true;
  }

  template <int dim>
  bool
  InteriorPointIteration<dim>::below_increment_tolerance(const Residuals &r)
  {
    // A displacement step below round-off of the geometry with the
    // constraints and complementarity met: nothing is left to gain (the
    // dual residual of an ill-conditioned Hessian, nu = 0.4999, stalls
    // above the tolerance at round-off level).
    const double tol = parameters.tolerance;
    if (!(minimizer.increment_limit > 0. && r.primal <= tol * h &&
          r.complementarity <= tol * unit && d.linfty_norm() <= minimizer.increment_limit))
      return false;
    minimizer.progress << "      step " << std::scientific << std::setprecision(2)
                       << d.linfty_norm() << " is below the increment tolerance"
                       << std::endl;
    return true;
  }

  template <int dim>
  bool
  InteriorPointIteration<dim>::line_search()
  {
    TimerOutput::Scope scope(minimizer.timer, "line search");
    const double       tau = std::max(0.99, 1. - mu / unit);
    alpha                  = max_step(s, ds, tau);
    alpha_z                = max_step(z, dz, tau);
    if (minimizer.step_limit > 0.)
      {
        const double largest = d.linfty_norm();
        if (largest * alpha > minimizer.step_limit)
          alpha = minimizer.step_limit / largest;
      }
    const double noise = 1e3 * std::numeric_limits<double>::epsilon() *
                         (std::abs(e.strain_energy) + std::abs(e.external_work) +
                          std::abs(e.value) + mu * std::abs(barrier) + nu * violation);

    for (unsigned int j = 0; j <= parameters.max_backtracks; ++j)
      {
        trial = u;
        trial.add(alpha, d);
        ghosted                  = trial;
        const Evaluation trial_e = objective.evaluate(ghosted, constraints, nullptr, nullptr);
        if (trial_e.admissible)
          {
            evaluate_constraints(ghosted, trial_state);
            double trial_barrier = 0., trial_violation = 0.;
            for (unsigned int k = 0; k < n; ++k)
              if (minimizer.active[k])
                {
                  s_trial[k] = s[k] + alpha * ds[k];
                  trial_barrier += std::log(s_trial[k]);
                  trial_violation += std::abs(trial_state[k].g - s_trial[k]);
                }
            const double phi_trial = trial_e.value -
                                     mu * Utilities::MPI::sum(trial_barrier, comm) +
                                     nu * Utilities::MPI::sum(trial_violation, comm);
            if (std::isfinite(phi_trial) &&
                (phi_trial <= phi + parameters.armijo_c1 * alpha * std::min(slope, 0.) ||
                 phi_trial <= phi + noise))
              return true;
          }
        ++stats.backtracks;
        alpha *= 0.5;
      }
    stats.reason = "the line search found no admissible decrease of the merit function after " +
                   std::to_string(parameters.max_backtracks) + " backtracks";
    return false;
  }

  template <int dim>
  bool
  InteriorPointIteration<dim>::accept()
  {
    if (alpha < 1.)
      minimizer.progress << "      step length " << std::scientific << std::setprecision(3)
                         << alpha << " (multipliers " << alpha_z << ")" << std::endl;
    // u, s along the step, z with its own step; slacks no smaller than the
    // constraints, multipliers near the central path.
    u = trial;
    std::swap(state, trial_state);
    for (unsigned int k = 0; k < n; ++k)
      if (minimizer.active[k])
        {
          s[k] = std::max(s_trial[k], state[k].g);
          z[k] = z[k] + alpha_z * dz[k];
          z[k] = std::min(std::max(z[k], mu / (1e10 * s[k])), 1e10 * mu / s[k]);
        }
    full_evaluation();
    if (!e.admissible)
      {
        stats.reason = "inadmissible state after the line search";
        return false;
      }
    return true;
  }

  template class InteriorPointIteration<2>;
  template class InteriorPointIteration<3>;
} // namespace Signorini
