#include <signorini/archive_io.h>
#include <signorini/input_error.h>
#include <signorini/interruption.h>
#include <signorini/solvers/interior_point.h>
#include <signorini/solvers/interior_point_iteration.h>

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
                      "goes on. The same iterate is kept when the line "
                      "search finds no decrease (else the step fails); "
                      "0: never.");
    prm.declare_entry("Maximum increment",
                      "0.1",
                      Patterns::Double(0.),
                      "No step moves a DoF by more than this fraction of the "
                      "scene's size (bounding-box diameter); 0: no limit.");
    prm.declare_entry("Increment tolerance",
                      "1e-14",
                      Patterns::Double(0.),
                      "Converged also when the step moves no DoF by more "
                      "than this fraction of the scene's size while the "
                      "constraints and complementarity are met: the dual "
                      "residual is then at its round-off level; 0: never.");
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
    prm.declare_entry("Barrier update",
                      "capped",
                      Patterns::Selection("capped|Mehrotra"),
                      "Mehrotra: each iteration's barrier is sigma mu_avg, "
                      "sigma = (mu_aff / mu_avg)^3, and may rise above the "
                      "previous one; capped: the same, but never above the "
                      "previous iteration's barrier (the pure centring step, "
                      "tried when no other step lowers the merit function, "
                      "still raises it). A rise met a contact node whose "
                      "slack the fraction to the boundary had taken to 1e-9 "
                      "with a multiplier of 1e-8: its barrier force mu/s was "
                      "twice the load, and the step that followed inverted "
                      "elements (prm/hertz_sphere.prm at 1.2e6 DoFs: 10 "
                      "iterations with Mehrotra, 8 capped; "
                      "doc/performance.md).");
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
                      "tried once, and only once some node is pinned (the "
                      "bodies held by contact alone are free otherwise). "
                      "After the first step, chord steps reuse its "
                      "factorisation (or kept AMG hierarchy) while each "
                      "divides the residual by 10 (at most 3 factorisations "
                      "and 6 steps, plus 1 and 3 per active-set update; the "
                      "iteration count counts the factorised ones). Under "
                      "CG + AMG it needs the kept, diagonally scaled "
                      "hierarchy (Linear solver > Keep preconditioner), "
                      "which sees the pinned rows' stiff penalty as a unit "
                      "diagonal. A node at the edge of the contact "
                      "zone whose gap and force both vanish otherwise makes "
                      "the last iterations converge only linearly: "
                      "prm/hertz_peer.prm at 202 692 DoFs, 8 -> 5 "
                      "factorisations (doc/performance.md).");
    prm.declare_entry("Active-set polish updates",
                      "automatic",
                      Patterns::Anything(),
                      "automatic, or a number from 0 to 20. When a polish "
                      "step leaves a free node in the foundation (by more "
                      "than Tolerance * h) or a pinned node pulling, pin / "
                      "free those nodes and go on from there, at most this "
                      "many times per attempt (0: the attempt ends at the "
                      "first such step). automatic: 0 with the direct "
                      "linear solver, where each update is a factorisation "
                      "(and an interior point iteration solves twice with "
                      "one), 6 with CG + AMG, where each update is one "
                      "solve against an iteration's two: prm/hertz_sphere."
                      "prm at 169 773 DoFs on 2 ranks, 19 interior point "
                      "iterations without the polish, 17 with it and no "
                      "update, 7 + 7 with updates (doc/performance.md).");
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
    capped_barrier         = prm.get("Barrier update") == "capped";
    warm_start             = prm.get_bool("Warm start");
    active_set_polish      = prm.get_bool("Active-set polish");
    {
      const std::string updates = prm.get("Active-set polish updates");
      if (updates == "automatic")
        polish_updates = automatic;
      else
        {
          std::size_t end   = 0;
          int         value = -1;
          try
            {
              value = std::stoi(updates, &end);
            }
          catch (const std::exception &)
            {
              end = 0;
            }
          if (end == 0 || end != updates.size() || value < 0 || value > 20)
            throw InputError("Solver > Interior point > Active-set polish updates",
                             "must be 'automatic' or a number from 0 to 20, not '" +
                               updates + "'");
          polish_updates = value;
        }
    }
    armijo_c1              = prm.get_double("Armijo parameter");
    max_backtracks         = prm.get_integer("Maximum backtracks");
    initial_regularization = prm.get_double("Initial regularization");
    max_increment          = prm.get_double("Maximum increment");
    increment_tolerance    = prm.get_double("Increment tolerance");
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
  InteriorPointMinimizer<dim>::setup(const Contact::NodeWiseConstraints<dim> &node_constraints,
                                     const AffineConstraints<double> &constraints,
                                     const MPI_Comm                   communicator)
  {
    contact          = &node_constraints;
    configured       = true;
    const auto &list = node_constraints.contact_nodes_on_boundary().nodes();
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
    AssertThrow(configured, ExcMessage("setup() was not called"));
    InteriorPointIteration<dim> ip(*this, objective, constraints, u, ghosted, K, rhs);
    if (!ip.initialise())
      return ip.statistics();
    for (unsigned int it = 0;; ++it)
      {
        Interruption::throw_if_requested(u.get_mpi_communicator());
        const auto r = ip.residuals(it);
        if (!r.finite())
          return ip.fail("the residual is not finite");
        if (ip.converged(r))
          return ip.finish(r.mu_average);
        if (ip.stalled(r, it) || ip.polish_if_settled(r, it))
          return ip.statistics();
        if (it == parameters.max_iterations)
          {
            std::ostringstream msg;
            msg << "no convergence in " << it << " interior point iterations (|r_d|/F = "
                << r.dual / ip.force_scale() << ", |g - s|/h = " << r.primal / ip.length_scale()
                << ", max s z/(F h) = "
                << r.complementarity / (ip.force_scale() * ip.length_scale()) << ")";
            return ip.fail(msg.str());
          }
        ip.form_system();
        if (!ip.predictor(r) || !ip.corrector(r))
          return ip.statistics();
        if (ip.below_increment_tolerance(r))
          return ip.finish(r.mu_average);
        if (!ip.line_search())
          {
            ip.take_best("no decrease along the step", "line search failed", it);
            return ip.statistics();
          }
        if (!ip.accept())
          return ip.statistics();
      }
  }

  template <int dim>
  void
  InteriorPointMinimizer<dim>::save_state(OutputArchive &archive, MeshState &mesh) const
  {
    archive << warm << mu_last << last_regularization;
    mesh.save_dof_field(multiplier_dofs(), z);
  }

  template <int dim>
  void
  InteriorPointMinimizer<dim>::load_state(InputArchive &archive, MeshState &mesh)
  {
    archive >> warm >> mu_last >> last_regularization;
    z = mesh.load_dof_field(multiplier_dofs());
  }

  template <int dim>
  std::vector<types::global_dof_index>
  InteriorPointMinimizer<dim>::multiplier_dofs() const
  {
    std::vector<types::global_dof_index> dofs;
    if (contact)
      for (const auto &node : contact->contact_nodes_on_boundary().nodes())
        dofs.push_back(node.dofs[0]);
    return dofs;
  }

  template class InteriorPointMinimizer<2>;
  template class InteriorPointMinimizer<3>;
} // namespace Signorini
