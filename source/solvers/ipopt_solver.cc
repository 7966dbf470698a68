#include <signorini/archive_io.h>
#include <signorini/interruption.h>
#include <signorini/input_error.h>
#include <signorini/solvers/ipopt_solver.h>

#include <deal.II/base/mpi.h>

#include <Epetra_CrsMatrix.h>
#include <IpIpoptApplication.hpp>
#include <IpSolveStatistics.hpp>
#include <IpTNLP.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <fstream>
#include <iomanip>
#include <map>
#include <regex>
#include <sstream>

namespace Signorini
{
  namespace
  {
    std::string
    status_name(const Ipopt::ApplicationReturnStatus s)
    {
      switch (s)
        {
          case Ipopt::Solve_Succeeded:
            return "Solve_Succeeded";
          case Ipopt::Solved_To_Acceptable_Level:
            return "Solved_To_Acceptable_Level";
          case Ipopt::Infeasible_Problem_Detected:
            return "Infeasible_Problem_Detected";
          case Ipopt::Search_Direction_Becomes_Too_Small:
            return "Search_Direction_Becomes_Too_Small";
          case Ipopt::Diverging_Iterates:
            return "Diverging_Iterates";
          case Ipopt::User_Requested_Stop:
            return "User_Requested_Stop";
          case Ipopt::Feasible_Point_Found:
            return "Feasible_Point_Found";
          case Ipopt::Maximum_Iterations_Exceeded:
            return "Maximum_Iterations_Exceeded";
          case Ipopt::Restoration_Failed:
            return "Restoration_Failed";
          case Ipopt::Error_In_Step_Computation:
            return "Error_In_Step_Computation";
          case Ipopt::Maximum_CpuTime_Exceeded:
            return "Maximum_CpuTime_Exceeded";
          case Ipopt::Not_Enough_Degrees_Of_Freedom:
            return "Not_Enough_Degrees_Of_Freedom";
          case Ipopt::Invalid_Problem_Definition:
            return "Invalid_Problem_Definition";
          case Ipopt::Invalid_Option:
            return "Invalid_Option";
          case Ipopt::Invalid_Number_Detected:
            return "Invalid_Number_Detected";
          default:
            return "Ipopt internal error (" + std::to_string(static_cast<int>(s)) + ")";
        }
    }
  } // namespace

  template <int dim>
  struct IpoptSolver<dim>::Application
  {
    Ipopt::SmartPtr<Ipopt::IpoptApplication> app;
  };

  void
  IpoptParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Tolerance",
                      "1e-9",
                      Patterns::Double(0.),
                      "Ipopt 'tol': relative tolerance of the scaled "
                      "optimality error (stationarity, feasibility, "
                      "complementarity).");
    prm.declare_entry("Maximum iterations",
                      "500",
                      Patterns::Integer(1),
                      "Ipopt 'max_iter' per load step.");
    prm.declare_entry("Maximum increment",
                      "0.1",
                      Patterns::Double(0.),
                      "Penalty stages (two bodies): no Ipopt step moves a "
                      "DoF by more than this fraction of the scene's size "
                      "(bounding-box diameter); 0: no limit.");
    prm.declare_entry("Mu strategy",
                      "adaptive",
                      Patterns::Selection("adaptive|monotone"),
                      "Ipopt 'mu_strategy': update of the barrier parameter.");
    prm.declare_entry("Print level",
                      "0",
                      Patterns::Integer(0, 12),
                      "Ipopt 'print_level' on the screen (0: nothing; the "
                      "program prints one line per iteration itself at "
                      "Output > Verbosity = normal).");
    prm.declare_entry("File print level",
                      "5",
                      Patterns::Integer(0, 12),
                      "Ipopt 'file_print_level' of ipopt.out in the output "
                      "folder (0: no file).");
    prm.declare_entry("Options file",
                      "",
                      Patterns::Anything(),
                      "An ipopt.opt-style file with further Ipopt options, "
                      "read after the ones above (relative paths are "
                      "relative to the parameter file). Empty: none.");
    prm.declare_entry("Derivative test",
                      "none",
                      Patterns::Selection("none|first-order|second-order"),
                      "Run Ipopt's finite-difference derivative checker "
                      "at the start of every load step; the number of "
                      "errors it reports goes into summary.json.");
    prm.declare_entry("Derivative test perturbation",
                      "1e-3",
                      Patterns::Double(0.),
                      "Ipopt 'point_perturbation_radius': the checker "
                      "evaluates at the starting point moved randomly by up "
                      "to this [length] (0: at the starting point).");
    prm.declare_entry("Warm start",
                      "true",
                      Patterns::Bool(),
                      "Start every load step after the first from the "
                      "previous step's primal and dual solution (Ipopt "
                      "'warm_start_init_point').");
    prm.declare_entry("Warm start mu",
                      "1e-6",
                      Patterns::Double(0.),
                      "Initial barrier parameter 'mu_init' of warm-started "
                      "steps.");
  }

  void
  IpoptParameters::parse_parameters(ParameterHandler  &prm,
                                                 const std::string &prm_directory)
  {
    tolerance        = prm.get_double("Tolerance");
    max_iterations   = prm.get_integer("Maximum iterations");
    max_increment    = prm.get_double("Maximum increment");
    mu_strategy      = prm.get("Mu strategy");
    print_level      = prm.get_integer("Print level");
    file_print_level = prm.get_integer("File print level");
    options_file     = prm.get("Options file");
    if (!options_file.empty() && options_file[0] != '/' && !prm_directory.empty())
      options_file = prm_directory + "/" + options_file;
    if (!options_file.empty() && !std::ifstream(options_file))
      throw InputError("Solver > Ipopt > Options file",
                       "cannot read '" + options_file + "'");
    derivative_test              = prm.get("Derivative test");
    derivative_test_perturbation = prm.get_double("Derivative test perturbation");
    warm_start                   = prm.get_bool("Warm start");
    warm_start_mu                = prm.get_double("Warm start mu");
    if (!(tolerance > 0.))
      throw InputError("Solver > Ipopt > Tolerance", "must be > 0");
  }

  /// The TNLP Ipopt sees: variables are the free DoFs.
  template <int dim>
  class IpoptSolver<dim>::Problem : public Ipopt::TNLP
  {
  public:
    using Index  = Ipopt::Index;
    using Number = Ipopt::Number;

    Problem(IpoptSolver<dim>                &solver,
            const double                     time,
            const double                     mu,
            const AffineConstraints<double> &target,
            VectorType                      &u,
            Result                          &result)
      : s(solver)
      , time(time)
      , mu(mu)
      , target(target)
      , u(u)
      , result(result)
      , rhs(u.locally_owned_elements(), u.get_mpi_communicator())
      , start(u)
      , accepted(u)
      , step(u.locally_owned_elements(), u.get_mpi_communicator())
      , owned(u.locally_owned_elements(), u.get_mpi_communicator())
    {}

    bool
    get_nlp_info(Index &n, Index &m, Index &nnz_jac_g, Index &nnz_h_lag,
                 IndexStyleEnum &index_style) override
    {
      n           = s.free_dofs.size();
      m           = s.contact_rows.size() + s.cell_entries.size();
      nnz_jac_g   = s.n_jacobian_entries;
      nnz_h_lag   = s.hessian_rows.size();
      index_style = TNLP::C_STYLE;
      return true;
    }

    bool
    get_bounds_info(Index n, Number *x_l, Number *x_u, Index m, Number *g_l,
                    Number *g_u) override
    {
      for (Index i = 0; i < n; ++i)
        {
          x_l[i] = -2e19;
          x_u[i] = 2e19;
        }
      const Index n_contact = s.contact_rows.size();
      for (Index r = 0; r < m; ++r)
        {
          g_l[r] = 0.;
          g_u[r] = (r < n_contact ? 2e19 : 0.);
        }
      return true;
    }

    bool
    get_starting_point(Index n, bool init_x, Number *x, bool init_z,
                       Number *z_L, Number *z_U, Index m, bool init_lambda,
                       Number *lambda) override
    {
      if (init_x)
        for (Index i = 0; i < n; ++i)
          x[i] = start[s.free_dofs[i]];
      if (init_z)
        for (Index i = 0; i < n; ++i)
          z_L[i] = z_U[i] = 0.;
      if (init_lambda)
        for (Index r = 0; r < m; ++r)
          lambda[r] = (s.last_lambda.size() == static_cast<std::size_t>(m) ?
                         s.last_lambda[r] :
                         0.);
      return true;
    }

    bool
    eval_f(Index, const Number *x, bool new_x, Number &obj_value) override
    {
      update(x, new_x);
      const Evaluation e = evaluate(nullptr);
      obj_value          = e.value;
      return e.admissible && std::isfinite(e.value);
    }

    bool
    eval_grad_f(Index n, const Number *x, bool new_x, Number *grad_f) override
    {
      update(x, new_x);
      // Ipopt asks for the gradient at accepted iterates only (trial
      // points of its line search get eval_f): the origin of step limits.
      accepted           = u;
      const Evaluation e = evaluate(&rhs);
      bool finite = true;
      for (Index i = 0; i < n; ++i)
        {
          grad_f[i] = -rhs[s.free_dofs[i]];
          finite    = finite && std::isfinite(grad_f[i]);
        }
      return e.admissible && finite;
    }

    bool
    eval_g(Index, const Number *x, bool new_x, Index, Number *g) override
    {
      update(x, new_x);
      TimerOutput::Scope scope(s.timer, "constraints");
      Index              r = 0;
      for (const unsigned int k : s.contact_rows)
        g[r++] = s.contact->constraint(s.contact->contact_nodes_on_boundary().nodes()[k], u).g;
      if (s.incompressibility)
        for (const auto &cell : s.incompressibility->cells())
          g[r++] = s.incompressibility->evaluate(cell, u, nullptr, nullptr);
      return std::all_of(g, g + r, [](const Number v) { return std::isfinite(v); });
    }

    bool
    eval_jac_g(Index, const Number *x, bool new_x, Index, Index, Index *iRow,
               Index *jCol, Number *values) override
    {
      if (values == nullptr)
        {
          Index k = 0, r = 0;
          for (const auto &entries : s.contact_entries)
            {
              for (const auto &e : entries)
                {
                  iRow[k]   = r;
                  jCol[k++] = e.second;
                }
              ++r;
            }
          for (const auto &entries : s.cell_entries)
            {
              for (const int v : entries)
                {
                  iRow[k]   = r;
                  jCol[k++] = v;
                }
              ++r;
            }
          return true;
        }
      update(x, new_x);
      TimerOutput::Scope scope(s.timer, "constraints");
      Index              k = 0;
      for (unsigned int r = 0; r < s.contact_rows.size(); ++r)
        {
          const auto state =
            s.contact->constraint(s.contact->contact_nodes_on_boundary().nodes()[s.contact_rows[r]], u);
          for (const auto &e : s.contact_entries[r])
            values[k++] = state.grad[e.first];
        }
      if (s.incompressibility)
        {
          Vector<double>                       gradient;
          std::vector<types::global_dof_index> dofs(
            s.dof_handler.get_fe().n_dofs_per_cell());
          unsigned int c = 0;
          for (const auto &cell : s.incompressibility->cells())
            {
              s.incompressibility->evaluate(cell, u, &gradient, nullptr);
              cell->get_dof_indices(dofs);
              const std::map<int, double> row = condense(dofs, gradient);
              for (const int v : s.cell_entries[c])
                {
                  const auto it = row.find(v);
                  values[k++]   = (it == row.end() ? 0. : it->second);
                }
              ++c;
            }
        }
      return true;
    }

    bool
    eval_h(Index, const Number *x, bool new_x, Number obj_factor, Index,
           const Number *lambda, bool, Index, Index *iRow, Index *jCol,
           Number *values) override
    {
      if (values == nullptr)
        {
          for (std::size_t k = 0; k < s.hessian_rows.size(); ++k)
            {
              iRow[k] = s.hessian_rows[k];
              jCol[k] = s.hessian_cols[k];
            }
          return true;
        }
      update(x, new_x);
      if (s.penalty && s.penalty->needs_new_pattern(u))
        {
          // The couplings left the pattern: assemble on a new one, give
          // Ipopt what fits its structure for this iteration, and stop
          // after it (intermediate_callback) to restart with the new one.
          TimerOutput::Scope scope(s.timer, "sparsity pattern");
          s.rebuild_pattern(u);
          s.pattern_stale = true;
        }
      TimerOutput::Scope scope(s.timer, "assembly");
      MatrixType        &H = *s.hessian;
      const Evaluation   e = s.energy.evaluate(u, time, *s.constraints, &rhs, &H);
      if (!e.admissible)
        return false;
      if (s.friction)
        s.friction->add(u, *s.constraints, nullptr, &H);
      H *= obj_factor;
      if (s.penalty)
        s.penalty->add_penalty(u, obj_factor * mu, *s.constraints, nullptr, &H);
      std::vector<types::global_dof_index> node_dofs(dim);
      FullMatrix<double>                   local(dim, dim);
      for (unsigned int r = 0; r < s.contact_rows.size(); ++r)
        {
          const auto &node  = s.contact->contact_nodes_on_boundary().nodes()[s.contact_rows[r]];
          const auto  state = s.contact->constraint(node, u);
          for (unsigned int i = 0; i < dim; ++i)
            {
              node_dofs[i] = node.dofs[i];
              for (unsigned int j = 0; j < dim; ++j)
                local(i, j) = lambda[r] * state.hess[i][j];
            }
          s.constraints->distribute_local_to_global(local, node_dofs, H);
        }
      if (s.incompressibility)
        {
          FullMatrix<double>                   cell_matrix;
          std::vector<types::global_dof_index> dofs(
            s.dof_handler.get_fe().n_dofs_per_cell());
          Index r = s.contact_rows.size();
          for (const auto &cell : s.incompressibility->cells())
            {
              s.incompressibility->evaluate(cell, u, nullptr, &cell_matrix, lambda[r++]);
              cell->get_dof_indices(dofs);
              s.constraints->distribute_local_to_global(cell_matrix, dofs, H);
            }
        }
      H.compress(VectorOperation::add);
      s.read_hessian(values);
      return std::all_of(values, values + s.hessian_rows.size(),
                         [](const Number v) { return std::isfinite(v); });
    }

    void
    finalize_solution(Ipopt::SolverReturn, Index, const Number *x,
                      const Number *, const Number *, Index m,
                      const Number *, const Number *lambda, Number,
                      const Ipopt::IpoptData *,
                      Ipopt::IpoptCalculatedQuantities *) override
    {
      update(x, true);
      s.last_lambda.assign(lambda, lambda + m);
      const std::size_t n_contact = s.contact_rows.size();
      if (s.contact)
        {
          result.contact_forces.assign(s.contact->contact_nodes_on_boundary().nodes().size(), 0.);
          for (std::size_t r = 0; r < n_contact; ++r)
            // Ipopt's Lagrangian is f + lambda g: a pressing contact has
            // lambda <= 0.
            result.contact_forces[s.contact_rows[r]] = std::max(-lambda[r], 0.);
        }
      result.pressure_multipliers.assign(lambda + n_contact, lambda + m);
    }

    bool
    intermediate_callback(Ipopt::AlgorithmMode, Index iter, Number obj_value,
                          Number inf_pr, Number inf_du, Number mu, Number,
                          Number, Number, Number, Index,
                          const Ipopt::IpoptData *,
                          Ipopt::IpoptCalculatedQuantities *) override
    {
      // A rebuilt sparsity pattern: stop here, solve() restarts Ipopt.
      // A signal: stop here, solve() ends the step.
      if (s.pattern_stale || Interruption::received() != 0)
        return false;
      // Ipopt's own state gone non-finite (e.g. with constraint values of
      // 1e300 its barrier parameter became NaN, and the next
      // factorisation never returned): stop with a reason.
      if (!std::isfinite(obj_value) || !std::isfinite(inf_pr) ||
          !std::isfinite(inf_du) || !std::isfinite(mu))
        {
          s.non_finite_stop = true;
          return false;
        }
      std::ostringstream line;
      line << "    ipopt it " << std::setw(3) << iter << "  E "
           << std::scientific << std::setprecision(10) << obj_value
           << "  inf_pr " << std::setprecision(2) << inf_pr << "  inf_du "
           << inf_du << "  mu " << mu;
      s.progress << line.str() << std::endl;
      return true;
    }

  private:
    /**
     * E, or G_mu = E + mu P with a penalty term (PenaltyObjective: the
     * same admissibility as for Newton), at the current state; minus the
     * gradient into @p minus_gradient if given. A state beyond the step
     * limits is not admissible.
     */
    Evaluation
    evaluate(VectorType *minus_gradient)
    {
      if (!within_step_limit())
        {
          Evaluation e;
          e.admissible = false;
          return e;
        }
      TimerOutput::Scope scope(s.timer, "assembly");
      if (!s.penalty)
        {
          EnergyObjective<dim>            energy(s.energy, time);
          Contact::FrictionObjective<dim> objective(energy, s.friction);
          return objective.evaluate(u, *s.constraints, minus_gradient, nullptr);
        }
      Contact::PenaltyObjective<dim>  penalty(s.energy, *s.penalty, time, mu);
      Contact::FrictionObjective<dim> objective(penalty, s.friction);
      return objective.evaluate(u, *s.constraints, minus_gradient, nullptr);
    }

    /// Whether the current state is within the step limits from the last
    /// accepted iterate (set_step_limit()).
    bool
    within_step_limit()
    {
      if (!s.penalty || !(s.max_increment > 0.))
        return true;
      owned = u;
      step  = accepted;
      step.sadd(-1., 1., owned);
      if (step.linfty_norm() > s.max_increment)
        return false;
      return s.penalty->max_step(accepted, step) >= 1. - 1e-12;
    }

    void
    update(const Number *x, const bool new_x)
    {
      if (!new_x && initialized)
        return;
      for (std::size_t i = 0; i < s.free_dofs.size(); ++i)
        u[s.free_dofs[i]] = x[i];
      target.distribute(u);
      initialized = true;
    }

    std::map<int, double>
    condense(const std::vector<types::global_dof_index> &dofs,
             const Vector<double>                       &values) const
    {
      std::map<int, double> row;
      for (unsigned int i = 0; i < dofs.size(); ++i)
        s.add_condensed(dofs[i], values(i), row);
      return row;
    }

    IpoptSolver<dim>                &s;
    const double                     time;
    const double                     mu;
    const AffineConstraints<double> &target;
    VectorType                      &u;
    Result                          &result;
    VectorType                       rhs;
    const VectorType                 start;
    VectorType                       accepted; // last accepted iterate
    VectorType                       step, owned; // work vectors (owned)
    bool                             initialized = false;
  };

  template <int dim>
  IpoptSolver<dim>::IpoptSolver(const Parameters                    &parameters,
                                const DoFHandler<dim>               &dof_handler,
                                const EnergyFunctional<dim>         &energy,
                                const Contact::NodeWiseConstraints<dim> *contact,
                                const Incompressibility<dim>        *incompressibility,
                                const std::string                   &output_directory,
                                ConditionalOStream                  &progress,
                                TimerOutput                         &timer)
    : parameters(parameters)
    , dof_handler(dof_handler)
    , energy(energy)
    , contact(contact)
    , incompressibility(incompressibility)
    , output_directory(output_directory)
    , progress(progress)
    , timer(timer)
    , application(std::make_unique<Application>())
  {}

  template <int dim>
  IpoptSolver<dim>::~IpoptSolver() = default;

  template <int dim>
  void
  IpoptSolver<dim>::add_condensed(const types::global_dof_index dof,
                                  const double                  value,
                                  std::map<int, double>        &row) const
  {
    if (variable_of[dof] >= 0)
      row[variable_of[dof]] += value;
    else if (const auto *entries = constraints->get_constraint_entries(dof))
      for (const auto &e : *entries)
        if (variable_of[e.first] >= 0)
          row[variable_of[e.first]] += e.second * value;
  }

  template <int dim>
  void
  IpoptSolver<dim>::setup(const AffineConstraints<double> &homogeneous,
                          MatrixType                      &matrix)
  {
    constraints = &homogeneous;
    hessian     = &matrix;
    free_dofs.clear();
    variable_of.assign(dof_handler.n_dofs(), -1);
    for (types::global_dof_index i = 0; i < dof_handler.n_dofs(); ++i)
      if (!homogeneous.is_constrained(i))
        {
          variable_of[i] = free_dofs.size();
          free_dofs.push_back(i);
        }

    n_jacobian_entries = 0;
    contact_rows.clear();
    contact_entries.clear();
    if (contact)
      for (unsigned int k = 0; k < contact->contact_nodes_on_boundary().nodes().size(); ++k)
        {
          std::vector<std::pair<unsigned int, int>> entries;
          for (unsigned int c = 0; c < dim; ++c)
            if (variable_of[contact->contact_nodes_on_boundary().nodes()[k].dofs[c]] >= 0)
              entries.emplace_back(c, variable_of[contact->contact_nodes_on_boundary().nodes()[k].dofs[c]]);
          if (entries.empty())
            continue; // a node held entirely by Dirichlet conditions
          n_jacobian_entries += entries.size();
          contact_rows.push_back(k);
          contact_entries.push_back(entries);
        }

    cell_entries.clear();
    if (incompressibility)
      {
        std::vector<types::global_dof_index> dofs(dof_handler.get_fe().n_dofs_per_cell());
        for (const auto &cell : incompressibility->cells())
          {
            cell->get_dof_indices(dofs);
            std::map<int, double> row;
            for (const auto dof : dofs)
              add_condensed(dof, 1., row);
            std::vector<int> entries;
            for (const auto &e : row)
              entries.push_back(e.first);
            n_jacobian_entries += entries.size();
            cell_entries.push_back(entries);
          }
      }

    setup_hessian_structure();
    warm = false;
    last_lambda.clear();

    // Check the options now, before any output exists; the application
    // that writes ipopt.out is made at the first solve.
    create_application(false);
  }

  template <int dim>
  void
  IpoptSolver<dim>::set_penalty(Contact::PenaltyTerm<dim> *term,
                                const PatternBuilder      &rebuild)
  {
    penalty         = term;
    rebuild_pattern = rebuild;
  }

  template <int dim>
  void
  IpoptSolver<dim>::set_step_limit(const double limit)
  {
    max_increment = limit;
  }

  template <int dim>
  void
  IpoptSolver<dim>::setup_hessian_structure()
  {
    hessian_rows.clear();
    hessian_cols.clear();
    local_rows.clear();
    row_starts.assign(1, 0);
    row_positions.clear();
    const Epetra_CrsMatrix &epetra = hessian->trilinos_matrix();
    for (std::size_t v = 0; v < free_dofs.size(); ++v)
      {
        local_rows.push_back(epetra.RowMap().LID(static_cast<int>(free_dofs[v])));
        int     n_entries;
        double *row_values;
        int    *row_columns;
        epetra.ExtractMyRowView(local_rows.back(), n_entries, row_values, row_columns);
        for (int p = 0; p < n_entries; ++p)
          {
            const int c = variable_of[epetra.ColMap().GID(row_columns[p])];
            if (c >= 0 && c <= static_cast<int>(v))
              {
                hessian_rows.push_back(v);
                hessian_cols.push_back(c);
                row_positions.push_back(p);
              }
          }
        row_starts.push_back(row_positions.size());
      }
    pattern_stale = false;
  }

  template <int dim>
  void
  IpoptSolver<dim>::read_hessian(double *values) const
  {
    const Epetra_CrsMatrix &epetra = hessian->trilinos_matrix();
    std::size_t             k      = 0;
    if (!pattern_stale)
      {
        // Straight from the Epetra rows, at the positions recorded by
        // setup_hessian_structure().
        for (std::size_t v = 0; v < free_dofs.size(); ++v)
          {
            int     n_entries;
            double *row_values;
            int    *row_columns;
            epetra.ExtractMyRowView(local_rows[v], n_entries, row_values, row_columns);
            for (unsigned int p = row_starts[v]; p < row_starts[v + 1]; ++p)
              values[k++] = row_values[row_positions[p]];
          }
      }
    else
      {
        // The matrix has a new pattern: look every entry up by column.
        std::map<int, double> row;
        for (std::size_t v = 0; v < free_dofs.size(); ++v)
          {
            int     n_entries;
            double *row_values;
            int    *row_columns;
            epetra.ExtractMyRowView(epetra.RowMap().LID(static_cast<int>(free_dofs[v])),
                                    n_entries, row_values, row_columns);
            row.clear();
            for (int p = 0; p < n_entries; ++p)
              {
                const int c = variable_of[epetra.ColMap().GID(row_columns[p])];
                if (c >= 0)
                  row[c] = row_values[p];
              }
            for (unsigned int p = row_starts[v]; p < row_starts[v + 1]; ++p)
              {
                const auto it = row.find(hessian_cols[k]);
                values[k++]   = (it == row.end() ? 0. : it->second);
              }
          }
      }
    AssertThrow(k == hessian_rows.size(), ExcInternalError());
  }

  template <int dim>
  void
  IpoptSolver<dim>::create_application(const bool with_output_file)
  {
    // Options: ours first, then the options file may override them.
    auto &app = application->app;
    app       = IpoptApplicationFactory();
    auto options = app->Options();
    options->SetNumericValue("tol", parameters.tolerance);
    options->SetIntegerValue("max_iter", parameters.max_iterations);
    options->SetStringValue("mu_strategy", parameters.mu_strategy);
    options->SetIntegerValue("print_level", parameters.print_level);
    options->SetStringValue("hessian_approximation", "exact");
    options->SetStringValue("sb", "yes");
    // A deterministic ordering (see Linear solver > MUMPS ordering).
    options->SetIntegerValue("mumps_pivot_order", parameters.mumps_pivot_order);
    if (with_output_file && parameters.file_print_level > 0)
      {
        options->SetStringValue("output_file", output_directory + "/ipopt.out");
        options->SetIntegerValue("file_print_level", parameters.file_print_level);
      }
    if (parameters.derivative_test != "none")
      {
        options->SetStringValue("derivative_test", parameters.derivative_test);
        options->SetNumericValue("point_perturbation_radius",
                                 parameters.derivative_test_perturbation);
      }
    // Ipopt prints what is wrong with an options file to the screen.
    std::ostringstream    chatter;
    std::streambuf *const cout_buffer = std::cout.rdbuf(chatter.rdbuf());
    const Ipopt::ApplicationReturnStatus status =
      app->Initialize(parameters.options_file);
    std::cout.rdbuf(cout_buffer);
    if (status != Ipopt::Solve_Succeeded)
      {
        std::string text = chatter.str();
        std::replace(text.begin(), text.end(), '\n', ' ');
        // Name the line of the options file that Ipopt does not know.
        std::ifstream in(parameters.options_file);
        std::string   line;
        for (unsigned int number = 1; std::getline(in, line); ++number)
          {
            std::istringstream words(line);
            std::string        name;
            if (!(words >> name) || name[0] == '#')
              continue;
            if (IsNull(app->RegOptions()->GetOption(name)))
              throw InputError(parameters.options_file + ":" +
                                 std::to_string(number),
                               "'" + name + "' is not an Ipopt option");
          }
        throw InputError(parameters.options_file.empty() ? "Solver > Ipopt" :
                                                           parameters.options_file,
                         "Ipopt rejected its options (" + status_name(status) +
                           ")" + (text.empty() ? "" : ": " + text));
      }
    application_has_file = with_output_file;
  }

  template <int dim>
  typename IpoptSolver<dim>::Result
  IpoptSolver<dim>::solve(const double                     time,
                          const AffineConstraints<double> &target,
                          VectorType                      &u,
                          const double                     mu)
  {
    Result result;
    if (!application_has_file)
      create_application(true);
    auto  &app     = application->app;
    auto   options = app->Options();
    if (warm && parameters.warm_start)
      {
        options->SetStringValue("warm_start_init_point", "yes");
        options->SetNumericValue("mu_init", parameters.warm_start_mu);
        options->SetNumericValue("warm_start_bound_push", 1e-9);
        options->SetNumericValue("warm_start_mult_bound_push", 1e-9);
      }
    std::size_t offset = 0;
    if (parameters.derivative_test != "none" && parameters.file_print_level > 0)
      offset = std::filesystem::exists(output_directory + "/ipopt.out") ?
                 std::filesystem::file_size(output_directory + "/ipopt.out") :
                 0;

    Ipopt::ApplicationReturnStatus status;
    non_finite_stop = false;
    for (unsigned int attempt = 0;; ++attempt)
      {
        if (penalty && !pattern_stale && penalty->needs_new_pattern(u))
          {
            TimerOutput::Scope scope(timer, "sparsity pattern");
            rebuild_pattern(u);
            pattern_stale = true;
          }
        if (pattern_stale)
          setup_hessian_structure();
        Ipopt::SmartPtr<Ipopt::TNLP> problem =
          new Problem(*this, time, mu, target, u, result);
        status = app->OptimizeTNLP(problem);
        if (IsValid(app->Statistics()))
          result.iterations += app->Statistics()->IterationCount();
        Interruption::throw_if_requested(u.get_mpi_communicator());
        // Stopped for a new sparsity pattern: go on from the last iterate
        // (finalize_solution() left it in u), with a bound on restarts.
        if (!(status == Ipopt::User_Requested_Stop && pattern_stale && attempt < 20))
          break;
        progress << "    ipopt: contact couplings changed, restarting with a "
                    "new sparsity pattern"
                 << std::endl;
      }
    result.status = non_finite_stop ?
                      "Invalid_Number_Detected (non-finite objective, "
                      "residual or barrier parameter in Ipopt's iteration)" :
                      status_name(status);
    result.success = (status == Ipopt::Solve_Succeeded ||
                      status == Ipopt::Solved_To_Acceptable_Level);
    if (result.success)
      warm = true;

    if (parameters.derivative_test != "none" && parameters.file_print_level > 0)
      {
        std::ifstream in(output_directory + "/ipopt.out");
        in.seekg(offset);
        std::string     line;
        const std::regex detected("Derivative checker detected ([0-9]+) error");
        std::smatch     match;
        while (std::getline(in, line))
          if (line.find("No errors detected by derivative checker") !=
              std::string::npos)
            result.derivative_test_errors = 0;
          else if (std::regex_search(line, match, detected))
            result.derivative_test_errors = std::stoi(match[1]);
      }
    return result;
  }

  template <int dim>
  void
  IpoptSolver<dim>::save_state(OutputArchive &archive) const
  {
    archive << warm << last_lambda;
  }

  template <int dim>
  void
  IpoptSolver<dim>::load_state(InputArchive &archive)
  {
    archive >> warm >> last_lambda;
  }

  template class IpoptSolver<2>;
  template class IpoptSolver<3>;
} // namespace Signorini
