// The active-set polish of the interior point method (doc/contact.md,
// 'Active-set polish'): Newton steps on E with the gaps of the pinned nodes
// held at zero by a stiff penalty rho and the other nodes free.
#include <signorini/solvers/interior_point_iteration.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>

namespace Signorini
{
  template <int dim>
  void
  InteriorPointIteration<dim>::add_pinned_blocks(const std::vector<char>   &pinned,
                                                 const std::vector<double> &zp,
                                                 const double               rho,
                                                 const bool                 with_matrix,
                                                 VectorType                &b_p)
  {
    TimerOutput::Scope scope(minimizer.timer, "assembly");
    b_p = rhs;
    for (unsigned int k = 0; k < n; ++k)
      if (pinned[k])
        {
          for (unsigned int i = 0; i < dim; ++i)
            {
              dofs[i]  = nodes[k].dofs[i];
              local(i) = (zp[k] - rho * state[k].g) * state[k].grad[i];
              for (unsigned int j = 0; j < dim; ++j)
                block(i, j) =
                  -zp[k] * state[k].hess[i][j] + rho * state[k].grad[i] * state[k].grad[j];
            }
          if (with_matrix)
            constraints.distribute_local_to_global(block, local, dofs, K, b_p);
          else
            constraints.distribute_local_to_global(local, dofs, b_p);
        }
    if (with_matrix)
      K.compress(VectorOperation::add);
    b_p.compress(VectorOperation::add);
  }

  template <int dim>
  typename InteriorPointIteration<dim>::PolishCheck
  InteriorPointIteration<dim>::equilibrium_forces(const std::vector<char> &pinned,
                                                  const VectorType        &forces,
                                                  std::vector<double>     &zp) const
  {
    // z_k = grad E . grad g_k / |grad g_k|^2 at a pinned node (forces =
    // -grad E): the penalty's multiplier estimate z - rho (g + grad g . du)
    // would lose digits.
    PolishCheck check;
    for (unsigned int k = 0; k < n; ++k)
      if (minimizer.active[k])
        {
          check.penetration = std::max(check.penetration, -state[k].g);
          if (!pinned[k])
            {
              check.free_penetration = std::max(check.free_penetration, -state[k].g);
              zp[k]                  = 0.;
              continue;
            }
          double along = 0., norm2 = 0.;
          for (unsigned int i = 0; i < dim; ++i)
            {
              along -= forces[nodes[k].dofs[i]] * state[k].grad[i];
              norm2 += state[k].grad[i] * state[k].grad[i];
            }
          zp[k]          = along / norm2;
          check.negative = std::max(check.negative, -zp[k]);
        }
    check.penetration      = Utilities::MPI::max(check.penetration, comm);
    check.free_penetration = Utilities::MPI::max(check.free_penetration, comm);
    check.negative         = Utilities::MPI::max(check.negative, comm);
    return check;
  }

  template <int dim>
  void
  InteriorPointIteration<dim>::update_pinned(std::vector<char>   &pinned,
                                             std::vector<double> &zp)
  {
    unsigned int changed = 0;
    for (unsigned int k = 0; k < n; ++k)
      if (minimizer.active[k])
        {
          if (pinned[k] && zp[k] < 0.)
            pinned[k] = 0;
          else if (!pinned[k] && -state[k].g > parameters.tolerance * h)
            pinned[k] = 1;
          else
            continue;
          zp[k] = 0.;
          ++changed;
        }
    minimizer.progress << "      active set updated: "
                       << Utilities::MPI::sum(changed, comm) << " nodes" << std::endl;
  }

  /*
   * The first step factorises the Hessian with the pinned blocks; the next
   * ones are chord steps on that factorisation (only the gradient is
   * evaluated and K keeps its values, so the direct solver solves again
   * without factorising and a kept AMG hierarchy is reused) as long as each
   * divides |r_d| by at least 10, and refactorise at the current state
   * otherwise: at most 3 factorisations and 6 steps. A step after which a
   * free node penetrates by more than tol h or a pinned node pulls shows
   * that the active set is not the solution's: with 'Active-set polish
   * updates' left, those nodes are pinned / freed and the steps go on from
   * there (3 more steps and one more factorisation per update); otherwise
   * the attempt ends. Kept, with z of the free nodes zero and s = max(g,
   * 0), if the dual residual is at most tol F, no node penetrates by more
   * than tol h and no pinned force is negative; otherwise u is restored and
   * the iteration goes on. When kept, the statistics hold the result.
   */
  template <int dim>
  bool
  InteriorPointIteration<dim>::polish(const std::vector<char> &start_set,
                                      const unsigned int       iteration)
  {
    std::vector<char>   pinned(start_set);
    const VectorType    u_start(u);
    std::vector<double> zp(n, 0.);
    for (unsigned int k = 0; k < n; ++k)
      if (pinned[k])
        zp[k] = z[k];
    const double rho = 1e6 * largest_diagonal();
    VectorType   b_p(rhs), du(rhs), residual(rhs), forces(ghosted);
    bool         kept = false, refactorise = true;
    unsigned int steps = 0, factorisations = 0, updates = 0;
    // Each update costs a factorisation with a direct solver (an interior
    // point iteration solves twice with one), a solve with CG + AMG (an
    // interior point iteration solves twice).
    const unsigned int max_updates =
      parameters.polish_updates != InteriorPointParameters::automatic ?
        parameters.polish_updates :
      minimizer.linear_solver.get_parameters().type ==
          LinearSolver::Parameters::Type::direct ?
        0 :
        6;
    double       r = 0., r_previous = std::numeric_limits<double>::infinity();
    while (steps < 6 + 3 * updates && !kept &&
           (!refactorise || factorisations < 3 + updates))
      {
        if (refactorise && steps > 0)
          {
            TimerOutput::Scope scope(minimizer.timer, "assembly");
            ghosted = u;
            e       = objective.evaluate(ghosted, constraints, &rhs, &K);
          }
        add_pinned_blocks(pinned, zp, rho, refactorise, b_p);
        if (refactorise)
          ++factorisations;
        bool solved = false;
        {
          TimerOutput::Scope scope(minimizer.timer, "linear solve");
          LinearSolver::Info info;
          std::string        message;
          du     = 0.;
          solved = stats.count_linear_solve(
            minimizer.linear_solver.solve(K, du, b_p, info, message), info, message);
        }
        ++steps;
        if (!solved)
          {
            minimizer.progress << "      active-set polish step " << steps
                               << ": the linear solve failed (" << stats.linear_message
                               << ")" << std::endl;
            break;
          }
        constraints.distribute(du);
        u.add(1., du);
        {
          // The gradient only: K keeps the values just factorised.
          TimerOutput::Scope scope(minimizer.timer, "assembly");
          ghosted = u;
          e       = objective.evaluate(ghosted, constraints, &rhs, nullptr);
        }
        evaluate_constraints(ghosted, state);
        if (!e.admissible)
          break;
        forces                  = rhs;
        const PolishCheck check = equilibrium_forces(pinned, forces, zp);
        dual_residual(zp, residual);
        r = residual.l2_norm();
        minimizer.progress << "      active-set polish step " << steps
                           << (refactorise ? "" : " (chord)") << ": |r_d|/F "
                           << std::scientific << std::setprecision(3) << r / F
                           << ", largest penetration / h " << check.penetration / h
                           << ", most negative force / F " << -check.negative / F
                           << std::endl;
        // A free node in the foundation or a pinned node pulling: the
        // active set is not the solution's. The pinned gaps reach zero as
        // the forces converge (the penalty holds them to r / rho).
        if (check.free_penetration > parameters.tolerance * h || check.negative > 0.)
          {
            if (updates == max_updates)
              break;
            update_pinned(pinned, zp);
            ++updates;
            refactorise = true;
            r_previous  = std::numeric_limits<double>::infinity();
            continue;
          }
        kept = r <= parameters.tolerance * F && check.penetration <= parameters.tolerance * h;
        // A step that made the residual grow or shrink less than 10x: the
        // next one refactorises (after a refactorising step, chord).
        refactorise = !refactorise && r > 0.1 * r_previous;
        r_previous  = r;
      }
    if (!kept)
      {
        minimizer.progress << "      active-set polish not kept" << std::endl;
        u = u_start;
        full_evaluation();
        evaluate_constraints(ghosted, state);
        return false;
      }
    for (unsigned int k = 0; k < n; ++k)
      if (minimizer.active[k])
        {
          z[k] = zp[k];
          s[k] = std::max(state[k].g, 0.);
        }
    stats.iterations = iteration + factorisations;
    stats.residual   = r;
    stats.evaluation = e;
    stats.converged  = true;
    minimizer.warm   = true;
    return true;
  }

  // The members defined here (the class itself is instantiated in
  // interior_point_iteration.cc).
#define SIGNORINI_INSTANTIATE(dim)                                                     \
  template void InteriorPointIteration<dim>::add_pinned_blocks(                        \
    const std::vector<char> &, const std::vector<double> &, const double, const bool,  \
    VectorType &);                                                                     \
  template typename InteriorPointIteration<dim>::PolishCheck                           \
  InteriorPointIteration<dim>::equilibrium_forces(const std::vector<char> &,           \
                                                  const VectorType &,                  \
                                                  std::vector<double> &) const;        \
  template void InteriorPointIteration<dim>::update_pinned(std::vector<char> &,        \
                                                          std::vector<double> &);      \
  template bool InteriorPointIteration<dim>::polish(const std::vector<char> &,         \
                                                    const unsigned int);
  SIGNORINI_INSTANTIATE(2)
  SIGNORINI_INSTANTIATE(3)
#undef SIGNORINI_INSTANTIATE
} // namespace Signorini
