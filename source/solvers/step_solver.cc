#include <signorini/contact/registry.h>
#include <signorini/input_error.h>
#include <signorini/output/json.h>
#include <signorini/solvers/interior_point_step.h>
#include <signorini/solvers/ipopt_step.h>
#include <signorini/solvers/newton_step.h>
#include <signorini/solvers/penalty_step.h>
#include <signorini/solvers/step_solver.h>

#include <deal.II/base/quadrature.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>

#include <iomanip>
#include <sstream>

namespace Signorini
{
  template <int dim>
  StepSolver<dim>::StepSolver(const Parameters::Scene &parameters,
                              Scene<dim>              &scene,
                              Problem<dim>            &problem,
                              TimerOutput             &timer,
                              ConditionalOStream      &progress)
    : parameters(parameters)
    , scene(scene)
    , problem(problem)
    , timer(timer)
    , progress(progress)
    , linear_solver(parameters.solver.linear)
  {
    if (const auto &e = parameters.load_stepping.sliding_direction; !e.empty())
      {
        Tensor<1, dim> direction;
        for (unsigned int c = 0; c < dim; ++c)
          direction[c] = e[c];
        transport = std::make_unique<TransportPredictor<dim>>(direction);
      }
  }

  template <int dim>
  void
  StepSolver<dim>::without_transport(const std::string &solver)
  {
    if (!transport)
      return;
    transport.reset();
    progress << "Note: Load stepping > Sliding direction is not used with "
             << solver << "; each load step starts from the previous state"
             << std::endl;
  }

  template <int dim>
  void
  StepSolver<dim>::carry_along(const double time)
  {
    if (!transport)
      return;
    TimerOutput::Scope scope(timer, "transport");
    const auto         result = transport->apply(scene, time);
    if (result.shift.norm() > 0.)
      progress << "    carried along by d = (" << result.shift << "): "
               << result.carried << " nodes from X - d, " << result.kept
               << " kept" << std::endl;
  }

  template <int dim>
  void
  StepSolver<dim>::write_summary(Json &summary) const
  {
    // Only what a restarted run reports alike (the counts of analyses and
    // factorisations start again at a restart, so they are not here).
    if (const std::string ordering = linear_solver.ordering_used(); !ordering.empty())
      {
        // "pord on node blocks of 2": MUMPS ordered the graph of the nodes
        // (2 or 3 unknowns each), not that of the unknowns.
        const int block = linear_solver.ordering_block();
        summary["solver"]["ordering"] =
          ordering + (block > 1 ? " on node blocks of " + std::to_string(block) : "");
      }
  }

  namespace
  {
    /**
     * The rigid motions of the scene's mesh at the support points of the
     * locally owned DoFs (reference configuration): the dim translations,
     * then the rotations about the centre of the support points, scaled by
     * the scene's size so that they are of the order of the translations.
     */
    template <int dim>
    NearNullSpace
    rigid_motions(const Scene<dim> &scene)
    {
      const FiniteElement<dim> &fe      = *scene.fe;
      const IndexSet           &owned   = scene.locally_owned;
      const std::size_t         n_owned = owned.n_elements();

      NearNullSpace result;
      result.owned          = owned;
      result.n_translations = dim;
      result.higher_order   = fe.degree > 1;

      std::vector<Point<dim>> points(n_owned);
      std::vector<int>        component(n_owned, -1);
      FEValues<dim>           fe_values(*scene.mapping,
                              fe,
                              Quadrature<dim>(fe.get_unit_support_points()),
                              update_quadrature_points);
      std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
      for (const auto &cell : scene.dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            fe_values.reinit(cell);
            cell->get_dof_indices(dofs);
            for (unsigned int i = 0; i < dofs.size(); ++i)
              if (owned.is_element(dofs[i]))
                {
                  const auto k = owned.index_within_set(dofs[i]);
                  if (component[k] < 0)
                    {
                      component[k] = fe.system_to_component_index(i).first;
                      points[k]    = fe_values.quadrature_point(i);
                    }
                }
          }

      // The centre: the mean of all support points (the same on any number
      // of ranks).
      std::vector<double> sum(dim + 1, 0.);
      for (std::size_t k = 0; k < n_owned; ++k)
        if (component[k] == 0)
          {
            for (unsigned int d = 0; d < dim; ++d)
              sum[d] += points[k][d];
            sum[dim] += 1.;
          }
      Utilities::MPI::sum(sum, scene.dof_handler.get_communicator(), sum);
      Point<dim> centre;
      for (unsigned int d = 0; d < dim; ++d)
        centre[d] = sum[dim] > 0. ? sum[d] / sum[dim] : 0.;
      const double scale = scene.size > 0. ? 1. / scene.size : 1.;

      const unsigned int n_rotations = dim == 2 ? 1 : 3;
      result.modes.assign(dim + n_rotations, std::vector<double>(n_owned, 0.));
      bool node_by_node = true;
      for (std::size_t k = 0; k < n_owned; ++k)
        {
          const int c = component[k];
          AssertThrow(c >= 0, ExcMessage("near null space: an owned DoF on no owned cell"));
          const Tensor<1, dim> r = scale * (points[k] - centre);
          result.modes[c][k]     = 1.;
          if (dim == 2)
            // rotation about z: (-y, x)
            result.modes[2][k] = (c == 0 ? -r[1] : r[0]);
          else
            {
              // rotation about the axis a: a x r, component c
              for (unsigned int a = 0; a < 3; ++a)
                {
                  const unsigned int c1 = (a + 1) % 3, c2 = (a + 2) % 3;
                  result.modes[dim + a][k] =
                    (c == static_cast<int>(c1) ? -r[c2] :
                     c == static_cast<int>(c2) ? r[c1] :
                                                 0.);
                }
            }
          // ML's "PDE equations" needs the DoFs of a node consecutive and
          // ordered by component, which deal.II's numbering of FE_Q^dim
          // gives: check it rather than assume it.
          if (owned.nth_index_in_set(k) % dim != static_cast<unsigned int>(c) ||
              (c > 0 && points[k].distance(points[k - 1]) >
                          1e-12 * (scene.size > 0. ? scene.size : 1.)))
            node_by_node = false;
        }
      node_by_node =
        Utilities::MPI::min(node_by_node ? 1 : 0,
                            scene.dof_handler.get_communicator()) == 1;
      result.dofs_per_node = node_by_node ? dim : 1;
      return result;
    }
  } // namespace

  template <int dim>
  void
  StepSolver<dim>::setup()
  {
    linear_solver.set_near_null_space(rigid_motions(scene));
  }

  template <int dim>
  NewtonMinimizer
  StepSolver<dim>::newton() const
  {
    NewtonMinimizer newton(parameters.solver.newton, linear_solver, progress, timer);
    newton.set_length_scale(scene.size);
    if (friction_resolve)
      newton.iterate_at_least_once();
    return newton;
  }

  template <int dim>
  std::unique_ptr<IpoptSolver<dim>>
  StepSolver<dim>::make_ipopt(const Contact::NodeWiseConstraints<dim> *contact,
                              const Incompressibility<dim> *incompressibility) const
  {
    auto ipopt = std::make_unique<IpoptSolver<dim>>(parameters.solver.ipopt,
                                                    scene.dof_handler,
                                                    *problem.energy,
                                                    contact,
                                                    incompressibility,
                                                    parameters.global.output_directory,
                                                    progress,
                                                    timer);
    ipopt->setup(scene.homogeneous_constraints, scene.hessian);
    ipopt->set_step_limit(parameters.solver.ipopt.max_increment * scene.size);
    return ipopt;
  }

  template <int dim>
  bool
  StepSolver<dim>::predict(NewtonMinimizer             &newton,
                           Objective                   &objective,
                           const double                 time,
                           StepStatistics              &stats)
  {
    if (friction_resolve)
      return true;
    carry_along(time);
    if (!scene.bc.has_prescribed_motion())
      return true;
    scene.solution_ghosted = scene.solution;
    const AffineConstraints<double> increment = scene.increment_constraints(time);
    std::string                     reason;
    if (!newton.predictor(objective, increment, scene.solution,
                          scene.solution_ghosted, scene.hessian, scene.rhs,
                          reason))
      {
        stats.reason = "predictor: " + reason;
        return false;
      }
    return true;
  }


  template <int dim>
  bool
  NewtonStep<dim>::solve(const double                 time,
                         StepStatistics              &stats,
                         Report::Step                &record)
  {
    (void)record;
    auto                 &scene  = this->scene;
    NewtonMinimizer       newton = this->newton();
    EnergyObjective<dim>  objective(*this->problem.energy, time);
    if (!this->predict(newton, objective, time, stats))
      return false;
    stats = newton.minimize(objective, scene.homogeneous_constraints,
                            scene.solution, scene.solution_ghosted,
                            scene.hessian, scene.rhs);
    return stats.converged;
  }

  template <int dim>
  bool
  StepSolver<dim>::solve_step(const double    time,
                              StepStatistics &stats,
                              Report::Step   &record)
  {
    Contact::FrictionTerm<dim> *friction = problem.friction.get();
    if (!friction)
      return solve(time, stats, record);
    const auto &p = friction->friction_parameters();
    scene.solution_ghosted = scene.solution;
    friction->start_step(scene.solution_ghosted, time);
    if (lags_friction())
      {
        const bool ok = solve(time, stats, record);
        if (ok)
          friction->step_done(time);
        return ok;
      }
    // The counts add up over the outer iterations; the rest is the last
    // solve's.
    const auto add_counts = [](StepStatistics &to, const StepStatistics &from) {
      to.iterations += from.iterations;
      to.backtracks += from.backtracks;
      to.regularized_steps += from.regularized_steps;
      to.convexified_steps += from.convexified_steps;
      to.linear_iterations += from.linear_iterations;
      to.linear_solves += from.linear_solves;
      to.linear_fallbacks += from.linear_fallbacks;
      to.linear_failures += from.linear_failures;
    };
    StepStatistics   earlier;    // the counts of the outer iterations before
    const VectorType step_start = restarts_friction() ? scene.solution : VectorType();
    for (unsigned int m = 0;; ++m)
      {
        stats = StepStatistics();
        // After a large change of the lag: from the step's start, with
        // its predictor, as the first solve.
        const bool restart =
          m > 0 && restarts_friction() && record.friction_change > friction_restart_change;
        if (restart)
          scene.solution = step_start;
        if (m > 0)
          prepare_friction_resolve(record.friction_change);
        friction_resolve           = m > 0 && !restart;
        const bool ok              = solve(time, stats, record);
        friction_resolve           = false;
        record.friction_iterations = m + 1;
        if (!ok)
          break;
        const double change = update_friction(m, record);
        if (change <= p.outer_tolerance)
          break;
        if (m + 1 >= p.max_outer_iterations)
          {
            stats.converged = false;
            stats.reason    = friction_failure(change, p.max_outer_iterations);
            break;
          }
        add_counts(earlier, stats);
      }
    add_counts(stats, earlier);
    if (stats.converged)
      friction->step_done(time);
    return stats.converged;
  }

  template <int dim>
  double
  StepSolver<dim>::update_friction(const unsigned int iteration, Report::Step &record)
  {
    scene.solution_ghosted     = scene.solution;
    const double change        = problem.friction->update(scene.solution_ghosted);
    record.friction_iterations = iteration + 1;
    record.friction_change     = change;
    progress << "    friction update " << iteration << ": max |d lambda| / max lambda = "
             << std::scientific << std::setprecision(3) << change << std::defaultfloat
             << std::endl;
    return change;
  }

  template <int dim>
  std::string
  StepSolver<dim>::friction_failure(const double change, const unsigned int iterations) const
  {
    const auto        &p = problem.friction->friction_parameters();
    std::ostringstream reason;
    reason << "the friction loop did not converge: the normal forces still changed by "
           << change << " of the largest after " << iterations
           << " outer iterations (Contact > Friction > Maximum outer iterations, Outer "
              "tolerance = "
           << p.outer_tolerance << ")";
    return reason.str();
  }

  template <int dim>
  void
  StepSolver<dim>::write_friction_summary(Json &contact) const
  {
    if (!problem.friction)
      return;
    const auto &p = problem.friction->friction_parameters();
    Json       &f = contact["friction"];
    f["coefficient"]              = p.coefficient;
    f["slip length over h"]       = p.slip_length;
    f["outer tolerance"]          = p.outer_tolerance;
    f["maximum outer iterations"] = p.max_outer_iterations;
  }

  void
  check_solver_compatibility(const Parameters::Scene &p, const unsigned int n_ranks)
  {
    // Asked of the contact model's capabilities only (contact/registry.h).
    using Method         = Parameters::Solver::Method;
    const Method      m       = p.solver.method;
    const bool        contact = p.contact.active();
    const std::string method  = Parameters::selection_name(m, Parameters::Solver::methods());
    if (m == Method::newton && contact)
      throw InputError("Solver > Method",
                       "the scene declares contact (Contact > Type = " + p.contact.type() +
                         "), which Method = newton cannot handle: use " +
                         (p.contact.node_wise_constraints() ?
                            std::string("interior-point (the default scene's "
                                        "solver; or newton-penalty, or ipopt "
                                        "on one rank)") :
                            std::string("newton-penalty (or ipopt on one "
                                        "rank)")) +
                         ", or leave Method out (automatic)");
    if (m == Method::newton_penalty && !contact)
      throw InputError("Solver > Method",
                       "newton-penalty needs contact (Contact > Type); the "
                       "scene declares none: use newton");
    const bool incompressible = !p.incompressible_ids().empty();
    if (incompressible && m != Method::ipopt && m != Method::interior_point)
      throw InputError("Body 1 > Material > Incompressible",
                       "J = 1 constraints need Solver > Method = ipopt or "
                       "interior-point, not " +
                         method);
    if (m == Method::interior_point && !p.contact.node_wise_constraints() &&
        !(incompressible && !contact))
      {
        std::string with_constraints;
        for (const auto &model : Contact::registered_models())
          if (model.capabilities.node_wise_constraints)
            with_constraints += (with_constraints.empty() ? "" : " or ") + model.name;
        throw InputError("Solver > Method",
                         "interior-point handles the node-wise constraints of "
                         "Contact > Type = " +
                           with_constraints + ", and this scene has Contact > Type = " +
                           p.contact.type() + ": use " +
                           (contact ? "newton-penalty or ipopt" : "newton"));
      }
    if (p.contact.friction.active())
      {
        const std::string key = "Contact > Friction > Coefficient";
        if (!contact)
          throw InputError(key, "friction needs contact (Contact > Type); the scene "
                                "declares none: set 0");
        if (m == Method::ipopt && !p.contact.node_wise_constraints())
          throw InputError(key, "between two bodies, friction works with Solver > "
                                "Method = newton-penalty; Ipopt as the penalty stages' "
                                "minimiser does not take it (doc/friction.md)");
      }
    if (m == Method::ipopt && n_ranks > 1)
      throw InputError("Solver > Method",
                       "ipopt runs on one MPI rank, and this run has " +
                         std::to_string(n_ranks) +
                         ": run it without mpirun, or use newton-penalty");
  }

  template <int dim>
  std::unique_ptr<StepSolver<dim>>
  create_step_solver(const Parameters::Scene &parameters,
                     Scene<dim>              &scene,
                     Problem<dim>            &problem,
                     TimerOutput             &timer,
                     ConditionalOStream      &progress)
  {
    using Method = Parameters::Solver::Method;
    // method x contact: which algorithm solves a load step.
    switch (parameters.solver.method)
      {
        case Method::newton:
          return std::make_unique<NewtonStep<dim>>(parameters, scene, problem,
                                                   timer, progress);
        case Method::newton_penalty:
          return std::make_unique<PenaltyStep<dim>>(parameters, scene, problem,
                                                    timer, progress, false);
        case Method::ipopt:
          // A model without constraints (the indicator function: its
          // constraint Phi = 0 has a zero gradient on the surface) is
          // enforced by penalty stages, each minimised by Ipopt.
          if (parameters.contact.active() && !parameters.contact.node_wise_constraints())
            return std::make_unique<PenaltyStep<dim>>(parameters, scene,
                                                      problem, timer, progress,
                                                      true);
          return std::make_unique<IpoptStep<dim>>(parameters, scene, problem,
                                                  timer, progress);
        case Method::interior_point:
          return std::make_unique<InteriorPointStep<dim>>(parameters, scene,
                                                          problem, timer,
                                                          progress);
        case Method::automatic: // resolved by Parameters::Scene
          break;
      }
    return nullptr;
  }

  template class StepSolver<2>;
  template class StepSolver<3>;
  template class NewtonStep<2>;
  template class NewtonStep<3>;
  template std::unique_ptr<StepSolver<2>>
  create_step_solver<2>(const Parameters::Scene &, Scene<2> &, Problem<2> &,
                        TimerOutput &, ConditionalOStream &);
  template std::unique_ptr<StepSolver<3>>
  create_step_solver<3>(const Parameters::Scene &, Scene<3> &, Problem<3> &,
                        TimerOutput &, ConditionalOStream &);
} // namespace Signorini
