// The interior point method's phases (solvers/interior_point_iteration.h),
// one at a time, on a problem whose every quantity the test computes by
// itself: a 4 x 4 mesh of Q1 elements with the diagonal energy
// E(u) = sum_i k/2 u_i^2 - f_i u_i (the bottom nodes pulled down by 0.05)
// and a curved rigid foundation under the bottom, g_k = y_k - psi(x_k) with
// psi(x) = -0.01 - 0.1 (x - 1/2)^2, written in the test as a
// NodeWiseConstraints (the constraint role alone, no contact model).
// - initialise: positive slacks and multipliers, slacks not below g;
// - residuals: the dual residual |f - k u + sum z grad g|, max |g - s| and
//   max s z as the test computes them (1e-12 relative);
// - form_system: K v = k v + sum_k (z/s grad g grad g^T - z hess g) v_k for
//   a varied v (1e-12 relative);
// - predictor and corrector: the step solves the linearised optimality
//   conditions H du - sum dz grad g = -(grad E - sum z grad g) and
//   grad g . du - ds = -(g - s) (1e-9 relative);
// - line_search and accept: a step length in (0, 1] that keeps every slack
//   and multiplier above (1 - tau) of its value (fraction to the boundary),
//   and slacks no smaller than the constraints after the step;
// - max_step: the largest step to the boundary of a given vector;
// - Barrier update: capped, the barrier of no iteration exceeds the one
//   before, where Mehrotra's rule raises it (a start with barrier 1e-6);
// - the whole method: every bottom node's displacement and multiplier as
//   the Newton solution of the node's own optimality conditions (1e-8 of
//   the pull, 1e-6 relative), in at most 30 iterations.

#include <signorini/contact/boundary_nodes.h>
#include <signorini/contact/node_wise_constraints.h>
#include <signorini/solvers/interior_point_iteration.h>
#include <signorini/solvers/linear_solver.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

using namespace Signorini;

namespace
{
  constexpr int    dim   = 2;
  constexpr double k     = 100.;  // stiffness of every DoF
  constexpr double pull  = 0.05;  // free fall of the bottom nodes
  constexpr double depth = -0.01; // psi at x = 1/2
  constexpr double bend  = 0.1;   // psi = depth - bend (x - 1/2)^2

  std::string
  verdict(const bool ok)
  {
    return ok ? "yes" : "NO";
  }

  /// The curved foundation as the constraint role alone.
  class Foundation : public Contact::NodeWiseConstraints<dim>
  {
  public:
    explicit Foundation(const Contact::BoundaryNodes<dim> &nodes)
      : nodes(nodes)
    {}

    const Contact::BoundaryNodes<dim> &
    contact_nodes_on_boundary() const override
    {
      return nodes;
    }

    State
    constraint(const Contact::BoundaryNode<dim> &node, const VectorType &u) const override
    {
      State s;
      for (unsigned int c = 0; c < dim; ++c)
        s.x[c] = node.X[c] + u[node.dofs[c]];
      const double t = s.x[0] - 0.5;
      s.g            = s.x[1] - (depth - bend * t * t);
      s.grad[0]      = 2. * bend * t;
      s.grad[1]      = 1.;
      s.hess[0][0]   = 2. * bend;
      return s;
    }

    double
    min_mesh_size() const override
    {
      return nodes.min_mesh_size();
    }

  private:
    const Contact::BoundaryNodes<dim> &nodes;
  };

  /// E(u) = sum k/2 u_i^2 - f_i u_i: rhs = f - k u, Hessian k I.
  class Diagonal : public Objective
  {
  public:
    explicit Diagonal(const VectorType &f)
      : f(f)
    {}

    Evaluation
    evaluate(const VectorType                &u,
             const AffineConstraints<double> &constraints,
             VectorType                      *rhs,
             MatrixType                      *hessian) override
    {
      (void)constraints;
      Evaluation e;
      for (const auto i : f.locally_owned_elements())
        e.value += 0.5 * k * u[i] * u[i] - f[i] * u[i];
      e.strain_energy = e.value;
      e.force_scale   = f.l2_norm();
      if (rhs)
        {
          for (const auto i : f.locally_owned_elements())
            (*rhs)[i] = f[i] - k * u[i];
          rhs->compress(VectorOperation::insert);
        }
      if (hessian)
        {
          *hessian = 0.;
          for (const auto i : f.locally_owned_elements())
            hessian->set(i, i, k);
          hessian->compress(VectorOperation::insert);
        }
      return e;
    }

  private:
    const VectorType &f;
  };

  double
  relative(const VectorType &a, const VectorType &b)
  {
    VectorType d(a);
    d -= b;
    return d.l2_norm() / std::max(b.l2_norm(), 1e-300);
  }

  /// The node's own optimality conditions k u - f = z grad g, g = 0 for
  /// the bottom node at X (f = (0, -k pull)), by Newton on (u_x, z).
  std::pair<Tensor<1, dim>, double>
  node_solution(const Point<dim> &X)
  {
    double ux = 0., z = k * pull;
    for (unsigned int it = 0; it < 50; ++it)
      {
        const double t  = X[0] + ux - 0.5;
        const double uy = -pull + z / k;
        // r1 = k ux - z 2 bend t, r2 = uy - psi(x) (g = 0 at y = X_y + uy)
        const double r1 = k * ux - z * 2. * bend * t;
        const double r2 = X[1] + uy - (depth - bend * t * t);
        const double a11 = k - 2. * bend * z, a12 = -2. * bend * t;
        const double a21 = 2. * bend * t, a22 = 1. / k;
        const double det = a11 * a22 - a12 * a21;
        ux -= (r1 * a22 - a12 * r2) / det;
        z -= (a11 * r2 - a21 * r1) / det;
      }
    Tensor<1, dim> u;
    u[0] = ux;
    u[1] = -pull + z / k;
    return {u, z};
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream                    out("output");
  const MPI_Comm                   comm = MPI_COMM_WORLD;

  Triangulation<dim> tria;
  GridGenerator::hyper_cube(tria, 0., 1., true); // y = 0: boundary id 2
  tria.refine_global(2);
  const FESystem<dim> fe(FE_Q<dim>(1), dim);
  DoFHandler<dim>     dof_handler(tria);
  dof_handler.distribute_dofs(fe);
  const MappingQ<dim> mapping(1);
  AffineConstraints<double> none;
  none.close();

  Contact::BoundaryNodes<dim> nodes(dof_handler, mapping);
  nodes.setup({2}, none);
  const Foundation foundation(nodes);

  const IndexSet owned = dof_handler.locally_owned_dofs();
  TrilinosWrappers::SparsityPattern sparsity(owned, comm);
  DoFTools::make_sparsity_pattern(dof_handler, sparsity, none, false);
  sparsity.compress();
  MatrixType K;
  K.reinit(sparsity);
  VectorType f(owned, comm), u(owned, comm), rhs(owned, comm), ghosted(owned, comm);
  for (const auto &node : nodes.nodes())
    f[node.dofs[1]] = -k * pull;
  f.compress(VectorOperation::insert);
  Diagonal energy(f);

  LinearSolver::Parameters linear;
  linear.type = LinearSolver::Parameters::Type::direct;
  const LinearSolver        solver(linear);
  ConditionalOStream        quiet(std::cout, false);
  TimerOutput               timer(comm, quiet, TimerOutput::never, TimerOutput::wall_times);
  InteriorPointParameters   parameters;
  InteriorPointMinimizer<dim> minimizer(parameters, solver, quiet, timer);
  minimizer.setup(foundation, none, comm);
  const auto  &list = nodes.nodes();
  const double tiny = 1e-14;

  // The state at u as the test computes it: constraints and dual residual
  // -(grad E - sum z grad g) = f - k u + sum z grad g.
  auto dual_residual = [&](const std::vector<double> &z) {
    VectorType r(f);
    r.add(-k, u);
    for (unsigned int n = 0; n < list.size(); ++n)
      {
        const auto s = foundation.constraint(list[n], u);
        for (unsigned int c = 0; c < dim; ++c)
          r[list[n].dofs[c]] += z[n] * s.grad[c];
      }
    return r;
  };

  {
    InteriorPointIteration<dim> ip(minimizer, energy, none, u, ghosted, K, rhs);
    const bool started = ip.initialise();
    const auto v0      = ip.view();
    bool       positive = started;
    for (unsigned int n = 0; n < list.size(); ++n)
      positive &= v0.s[n] > 0. && v0.z[n] > 0. &&
                  v0.s[n] >= foundation.constraint(list[n], u).g;
    out << "initialise: positive slacks and multipliers, slacks not below g: "
        << verdict(positive) << "\n";

    // Residuals.
    const auto r = ip.residuals(0);
    double     primal = 0., complementarity = 0.;
    for (unsigned int n = 0; n < list.size(); ++n)
      {
        primal = std::max(primal, std::abs(foundation.constraint(list[n], u).g - v0.s[n]));
        complementarity = std::max(complementarity, v0.s[n] * v0.z[n]);
      }
    const double dual = dual_residual(v0.z).l2_norm();
    std::cerr << "residuals: dual " << r.dual << " against " << dual << ", primal "
              << r.primal << " against " << primal << "\n";
    out << "residuals: as the test computes them: "
        << verdict(std::abs(r.dual - dual) <= 1e-12 * dual &&
                   std::abs(r.primal - primal) <= 1e-12 * primal + tiny &&
                   std::abs(r.complementarity - complementarity) <=
                     1e-12 * complementarity)
        << "\n";

    // The condensed matrix against its formula, applied to a varied v.
    ip.form_system();
    VectorType v(owned, comm), Kv(owned, comm), expected(owned, comm);
    for (const auto i : owned)
      v[i] = std::sin(1. + 0.7 * i);
    v.compress(VectorOperation::insert);
    K.vmult(Kv, v);
    expected = v;
    expected *= k;
    for (unsigned int n = 0; n < list.size(); ++n)
      {
        const auto s = foundation.constraint(list[n], u);
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = 0; j < dim; ++j)
            expected[list[n].dofs[i]] +=
              (v0.z[n] / v0.s[n] * s.grad[i] * s.grad[j] - v0.z[n] * s.hess[i][j]) *
              v[list[n].dofs[j]];
      }
    std::cerr << "form_system: " << relative(Kv, expected) << "\n";
    out << "form_system: K v as the formula: " << verdict(relative(Kv, expected) <= 1e-12)
        << "\n";

    // The step against the linearised optimality conditions.
    const bool stepped = ip.predictor(r) && ip.corrector(r);
    const auto step    = ip.view();
    VectorType lhs(step.du), dual_now = dual_residual(step.z);
    lhs *= k;
    double linear_primal = 0., scale = 0.;
    for (unsigned int n = 0; n < list.size(); ++n)
      {
        const auto s     = foundation.constraint(list[n], u);
        double     slope = 0.;
        for (unsigned int i = 0; i < dim; ++i)
          {
            slope += s.grad[i] * step.du[list[n].dofs[i]];
            double hess_du = 0.;
            for (unsigned int j = 0; j < dim; ++j)
              hess_du += s.hess[i][j] * step.du[list[n].dofs[j]];
            lhs[list[n].dofs[i]] += -step.z[n] * hess_du - step.dz[n] * s.grad[i];
          }
        linear_primal = std::max(linear_primal, std::abs(slope - step.ds[n] + s.g - step.s[n]));
        scale         = std::max(scale, std::abs(step.ds[n]));
      }
    std::cerr << "step: |du| " << step.du.l2_norm() << ", |lhs| " << lhs.l2_norm()
              << ", |dual| " << dual_now.l2_norm() << ", |ds| " << scale << "\n";
    std::cerr << "step: dual " << relative(lhs, dual_now) << ", primal "
              << linear_primal / scale << "\n";
    out << "predictor and corrector: a step that solves the linearised conditions: "
        << verdict(stepped && relative(lhs, dual_now) <= 1e-9 &&
                   linear_primal <= 1e-9 * scale)
        << "\n";

    // Fraction to the boundary and the accepted state.
    const std::vector<double> s_old(step.s), z_old(step.z), ds(step.ds), dz(step.dz);
    const bool searched = ip.line_search();
    const auto ls       = ip.view();
    const double tau    = std::max(0.99, 1. - ls.mu / (ip.force_scale() * ip.length_scale()));
    bool inside = searched && ls.alpha > 0. && ls.alpha <= 1. && ls.alpha_z > 0. &&
                  ls.alpha_z <= 1.;
    for (unsigned int n = 0; n < list.size(); ++n)
      inside &= s_old[n] + ls.alpha * ds[n] >= (1. - tau) * s_old[n] * (1. - 1e-12) &&
                z_old[n] + ls.alpha_z * dz[n] >= (1. - tau) * z_old[n] * (1. - 1e-12);
    std::cerr << "line search: alpha " << ls.alpha << ", alpha_z " << ls.alpha_z << "\n";
    out << "line_search: step lengths in (0, 1] within the fraction to the boundary: "
        << verdict(inside) << "\n";
    bool accepted = ip.accept();
    for (unsigned int n = 0; n < list.size(); ++n)
      accepted &= ip.view().s[n] >= foundation.constraint(list[n], u).g;
    out << "accept: slacks no smaller than the constraints: " << verdict(accepted) << "\n";

    // max_step on a vector of the test's: one entry of 1 falls by 4.
    std::vector<double> x(list.size(), 1.), dx(list.size(), 0.);
    dx[list.size() / 2] = -4.;
    const double to_boundary = ip.max_step(x, dx, 0.99);
    dx[list.size() / 2]      = 0.5;
    const double no_boundary = ip.max_step(x, dx, 0.99);
    out << "max_step: 0.99/4 to the boundary, 1 without: "
        << verdict(std::abs(to_boundary - 0.2475) <= 1e-15 && no_boundary == 1.) << "\n";
  }

  // "Barrier update": the barrier of each iteration, iterated by hand from
  // u = 0 with a small initial barrier (1e-6), where Mehrotra's sigma mu_avg
  // rises (1.9e-6 to 2.8e-3 within three iterations); capped, it never
  // rises, and both converge.
  std::vector<std::vector<double>> barriers(2);
  std::vector<bool>                converged(2, false);
  for (const bool capped : {true, false})
    {
      InteriorPointParameters rule;
      rule.capped_barrier  = capped;
      rule.initial_barrier = 1e-6;
      InteriorPointMinimizer<dim> m(rule, solver, quiet, timer);
      m.setup(foundation, none, comm);
      u = 0.;
      InteriorPointIteration<dim> ip(m, energy, none, u, ghosted, K, rhs);
      bool ran = ip.initialise();
      for (unsigned int it = 0; ran && it < 30; ++it)
        {
          const auto r = ip.residuals(it);
          if (ip.converged(r))
            {
              converged[capped ? 0 : 1] = true;
              break;
            }
          ip.form_system();
          ran = ip.predictor(r) && ip.corrector(r) && ip.line_search() && ip.accept();
          barriers[capped ? 0 : 1].push_back(ip.view().mu);
        }
    }
  const auto rises = [](const std::vector<double> &b) {
    for (std::size_t i = 1; i < b.size(); ++i)
      if (b[i] > b[i - 1] * (1. + 1e-12))
        return true;
    return false;
  };
  for (const unsigned int i : {0u, 1u})
    {
      std::cerr << (i == 0 ? "capped" : "Mehrotra") << " barriers:";
      for (const double b : barriers[i])
        std::cerr << " " << b;
      std::cerr << "\n";
    }
  out << "Barrier update = capped: converges, the barrier never rises: "
      << verdict(converged[0] && !barriers[0].empty() && !rises(barriers[0])) << "\n"
      << "Barrier update = Mehrotra: converges, the barrier rises: "
      << verdict(converged[1] && rises(barriers[1])) << "\n";

  // The whole method from u = 0 against each node's own solution.
  u = 0.;
  const auto stats = minimizer.minimize(energy, none, u, ghosted, K, rhs);
  double     du = 0., dz = 0.;
  for (unsigned int n = 0; n < list.size(); ++n)
    {
      const auto [exact_u, exact_z] = node_solution(list[n].X);
      for (unsigned int c = 0; c < dim; ++c)
        du = std::max(du, std::abs(u[list[n].dofs[c]] - exact_u[c]));
      dz = std::max(dz, std::abs(minimizer.multipliers()[n] - exact_z) / exact_z);
    }
  std::cerr << "minimize: " << stats.iterations << " iterations, |u - u*| " << du
            << ", |z - z*|/z* " << dz << "\n";
  out << "minimize: converged: " << verdict(stats.converged) << "\n"
      << "minimize: every node's displacement to 1e-8 of the pull: "
      << verdict(du <= 1e-8 * pull) << "\n"
      << "minimize: every node's multiplier to 1e-6: " << verdict(dz <= 1e-6) << "\n"
      << "minimize: at most 30 iterations: " << verdict(stats.iterations <= 30) << "\n";
}
