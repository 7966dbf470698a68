#include <signorini/archive_io.h>
#include <signorini/contact/friction_term.h>
#include <signorini/contact/rigid_foundation.h>
#include <signorini/contact/samples.h>
#include <signorini/contact/two_body_friction.h>
#include <signorini/contact/two_pass.h>
#include <signorini/input_error.h>

#include <deal.II/base/mpi.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace Signorini
{
  namespace Contact
  {
    template <int dim>
    void
    FrictionTerm<dim>::add_output_fields(DataOut<dim> &data_out, const VectorType &u) const
    {
      std::vector<std::vector<double>> values(column_names().size());
      for (const auto &p : point_samples(u))
        {
          const auto row = profile_values(p);
          for (unsigned int f = 0; f < row.size(); ++f)
            values[f].push_back(row[f]);
        }
      boundary().add_fields(data_out, column_names(), values);
    }

    template <int dim>
    std::vector<std::string>
    FrictionTerm<dim>::column_names()
    {
      std::vector<std::string> names;
      for (unsigned int d = 0; d < dim; ++d)
        names.push_back(std::string("friction_traction_") + "xyz"[d]);
      for (unsigned int d = 0; d < dim; ++d)
        names.push_back(std::string("friction_slip_") + "xyz"[d]);
      names.push_back("friction_status");
      return names;
    }

    template <int dim>
    std::string
    FrictionTerm<dim>::profile_header()
    {
      std::string header;
      for (const auto &name : column_names())
        header += (header.empty() ? "" : ",") + name;
      return header;
    }

    template <int dim>
    std::vector<double>
    FrictionTerm<dim>::profile_values(const PointSample &p)
    {
      std::vector<double> row;
      for (unsigned int d = 0; d < dim; ++d)
        row.push_back(p.weight > 0. ? p.force[d] / p.weight : 0.);
      for (unsigned int d = 0; d < dim; ++d)
        row.push_back(p.slip[d]);
      row.push_back(static_cast<double>(p.status));
      return row;
    }

    template <int dim>
    NodeFriction<dim>::NodeFriction(const FrictionParameters &parameters,
                                    const MPI_Comm            comm)
      : FrictionTerm<dim>(parameters)
      , mixing(5, comm)
    {}

    template <int dim>
    void
    NodeFriction<dim>::lag_all(const VectorType &u)
    {
      lag(u, lambda, basis);
      // The active set of the output (contact/samples.h): a node whose
      // force is below 1e-6 of the largest is open. The interior point
      // method's multipliers never vanish exactly.
      const double threshold = active_threshold(lambda, this->boundary().get_communicator());
      for (double &l : lambda)
        if (l <= threshold)
          l = 0.;
    }

    template <int dim>
    void
    NodeFriction<dim>::save_state(OutputArchive &archive, MeshState &mesh) const
    {
      const auto         dofs = history_dofs();
      const unsigned int n    = history.size();
      archive << n << history_times;
      for (const auto &lambdas : history)
        mesh.save_dof_field(dofs, lambdas);
    }

    template <int dim>
    void
    NodeFriction<dim>::load_state(InputArchive &archive, MeshState &mesh)
    {
      const auto   dofs = history_dofs();
      unsigned int n    = 0;
      archive >> n >> history_times;
      history.clear();
      for (unsigned int i = 0; i < n; ++i)
        history.push_back(mesh.load_dof_field(dofs));
    }

    template <int dim>
    void
    NodeFriction<dim>::reset()
    {
      reference.clear();
      lambda.clear();
      basis.clear();
      laws.clear();
      history.clear();
      history_times.clear();
      mixing.clear();
      last_change = 0.;
      scale       = 0.;
      started     = false;
    }

    template <int dim>
    std::vector<Tensor<1, dim>>
    NodeFriction<dim>::increments(const VectorType &u, std::vector<bool> &has) const
    {
      const auto                 &nodes = this->boundary().nodes();
      std::vector<Tensor<1, dim>> du(nodes.size());
      for (unsigned int k = 0; k < nodes.size(); ++k)
        for (unsigned int c = 0; c < dim; ++c)
          du[k][c] = u[nodes[k].dofs[c]] - reference[k][c];
      subtract_partners(u, du, has);
      return du;
    }

    template <int dim>
    void
    NodeFriction<dim>::coupling(const unsigned int k, Coupling &c) const
    {
      const auto &node = this->boundary().nodes()[k];
      c.dofs.assign(node.dofs.begin(), node.dofs.begin() + dim);
      c.components.resize(dim);
      for (unsigned int d = 0; d < dim; ++d)
        c.components[d] = d;
      c.factors.assign(dim, 1.);
      add_partner_coupling(k, c);
    }

    template <int dim>
    void
    NodeFriction<dim>::refresh_scale()
    {
      double sum = 0.;
      for (const double l : lambda)
        sum += l * l;
      const double mu = this->parameters.coefficient;
      scale = mu * std::sqrt(Utilities::MPI::sum(sum, this->boundary().get_communicator()));
    }

    template <int dim>
    void
    NodeFriction<dim>::start_step(const VectorType &u, const double time)
    {
      const auto &nodes = this->boundary().nodes();
      reference.resize(nodes.size());
      for (unsigned int k = 0; k < nodes.size(); ++k)
        for (unsigned int c = 0; c < dim; ++c)
          reference[k][c] = u[nodes[k].dofs[c]];
      set_partner_reference(u);
      started = true;
      laws.clear();
      for (unsigned int k = 0; k < nodes.size(); ++k)
        laws.emplace_back(this->parameters.coefficient,
                          this->parameters.slip_length_at(nodes[k].h));
      lag_all(u);
      mixing.clear();
      last_change = std::numeric_limits<double>::infinity();
      // A run's start without contact forces (load time 0): the first
      // point of the history.
      if (history.empty())
        {
          double largest = 0.;
          for (const double l : lambda)
            largest = std::max(largest, l);
          if (Utilities::MPI::max(largest, this->boundary().get_communicator()) == 0.)
            step_done(0.);
        }
      // Proportional loading makes the normal forces grow with the load
      // time: extrapolate the last two converged steps' forces to this
      // one (exact for a linear problem whose contact status holds, such
      // as ssnv128; then the outer loop needs two iterations).
      if (history.size() == 2 && history[0].size() == lambda.size() &&
          history[1].size() == lambda.size() && history_times[1] > history_times[0])
        {
          const double slope =
            (time - history_times[1]) / (history_times[1] - history_times[0]);
          for (unsigned int k = 0; k < lambda.size(); ++k)
            lambda[k] = std::max(0., history[1][k] + slope * (history[1][k] - history[0][k]));
        }
      refresh_scale();
    }

    template <int dim>
    void
    NodeFriction<dim>::step_done(const double time)
    {
      history.push_back(lambda);
      history_times.push_back(time);
      if (history.size() > 2)
        {
          history.erase(history.begin());
          history_times.erase(history_times.begin());
        }
    }

    template <int dim>
    double
    NodeFriction<dim>::add(const VectorType                &u,
                           const AffineConstraints<double> &constraints,
                           VectorType                      *rhs,
                           MatrixType                      *hessian) const
    {
      AssertThrow(started, ExcMessage("the friction term is used before start_step()"));
      std::vector<bool>                has;
      const auto                       du = increments(u, has);
      const AffineConstraints<double> &c =
        (rhs || hessian) ? condensation(constraints) : constraints;
      double             value = 0.;
      Vector<double>     gradient;
      FullMatrix<double> matrix;
      Vector<double>     local_rhs;
      FullMatrix<double> local_matrix;
      Coupling           coupled;
      for (unsigned int k = 0; k < laws.size(); ++k)
        {
          if (lambda[k] <= 0. || !has[k])
            continue;
          value += laws[k].evaluate_rigid(basis[k], du[k], lambda[k],
                                          rhs ? &gradient : nullptr,
                                          hessian ? &matrix : nullptr);
          if (!rhs && !hessian)
            continue;
          // D_k(du_k) with du_k linear in the coupled DoFs: the chain rule
          // through the factors.
          coupling(k, coupled);
          const unsigned int n = coupled.dofs.size();
          if (rhs)
            {
              local_rhs.reinit(n);
              for (unsigned int i = 0; i < n; ++i)
                local_rhs(i) = -coupled.factors[i] * gradient(coupled.components[i]);
            }
          if (hessian)
            {
              local_matrix.reinit(n, n);
              for (unsigned int i = 0; i < n; ++i)
                for (unsigned int j = 0; j < n; ++j)
                  local_matrix(i, j) = coupled.factors[i] * coupled.factors[j] *
                                       matrix(coupled.components[i], coupled.components[j]);
            }
          if (rhs && hessian)
            c.distribute_local_to_global(local_matrix, local_rhs, coupled.dofs, *hessian, *rhs);
          else if (rhs)
            c.distribute_local_to_global(local_rhs, coupled.dofs, *rhs);
          else
            c.distribute_local_to_global(local_matrix, coupled.dofs, *hessian);
        }
      if (rhs)
        rhs->compress(VectorOperation::add);
      if (hessian)
        hessian->compress(VectorOperation::add);
      return Utilities::MPI::sum(value, this->boundary().get_communicator());
    }

    template <int dim>
    double
    NodeFriction<dim>::update(const VectorType &u)
    {
      // lambda was the input of the last solve; lag_all() makes it its
      // output.
      const std::vector<double> old = lambda;
      lag_all(u);
      AssertThrow(old.size() == lambda.size(),
                  ExcMessage("the friction term is updated before start_step()"));
      double change = 0., largest = 0.;
      for (unsigned int k = 0; k < lambda.size(); ++k)
        {
          change  = std::max(change, std::abs(lambda[k] - old[k]));
          largest = std::max(largest, lambda[k]);
        }
      // The scale of the change: the largest normal force now or at the
      // last converged step. On its own the present largest vanishes with
      // the contact (unloading to zero force), and a change at the
      // interior point method's noise level would read as a relative
      // change of order 1 and never settle.
      if (!history.empty())
        for (const double l : history.back())
          largest = std::max(largest, l);
      const MPI_Comm comm = this->boundary().get_communicator();
      change              = Utilities::MPI::max(change, comm);
      largest             = Utilities::MPI::max(largest, comm);
      const double relative = largest > 0. ? change / largest : 0.;
      // Not yet settled: the next solve takes the accelerated forces.
      if (relative > this->parameters.outer_tolerance)
        {
          // A change larger than the last one: the mixing's history has
          // stopped describing the map (noise of the inner solves near
          // the tolerance, a node switching between stick and slip, or a
          // mode that flips sign from one iteration to the next). Restart
          // it with a half step, which damps such a flipping mode.
          if (relative > last_change)
            {
              mixing.clear();
              for (unsigned int k = 0; k < lambda.size(); ++k)
                lambda[k] = 0.5 * (old[k] + lambda[k]);
            }
          else
            lambda = mixing.next(old, lambda);
        }
      last_change = relative;
      refresh_scale();
      return relative;
    }

    template <int dim>
    std::vector<typename FrictionTerm<dim>::PointSample>
    NodeFriction<dim>::point_samples(const VectorType &u) const
    {
      std::vector<typename FrictionTerm<dim>::PointSample> samples;
      const auto &nodes = this->boundary().nodes();
      // Before the first load step (the initial output) every node is open.
      // (a flag, not laws.size(): a rank without contact nodes must still
      // take part in increments()'s collective calls).
      std::vector<bool>           has;
      std::vector<Tensor<1, dim>> du;
      if (started)
        du = increments(u, has);
      for (unsigned int k = 0; k < nodes.size(); ++k)
        {
          typename FrictionTerm<dim>::PointSample p;
          p.X      = nodes[k].X;
          p.weight = nodes[k].weight;
          if (!started || !has[k])
            {
              samples.push_back(p);
              continue;
            }
          p.normal_force = lambda[k];
          const auto s   = basis[k].project(du[k]);
          p.slip         = basis[k].lift(s);
          p.status       = laws[k].status(s, lambda[k]);
          p.dissipation  = laws[k].dissipated_energy(s, lambda[k]);
          // The friction force on the node's body: minus dD/du.
          p.force = -basis[k].lift(laws[k].evaluate(s, lambda[k]).traction);
          samples.push_back(p);
        }
      return samples;
    }

    template <int dim>
    RigidFriction<dim>::RigidFriction(const FrictionParameters   &parameters,
                                      const RigidFoundation<dim> &foundation)
      : NodeFriction<dim>(parameters,
                          foundation.contact_nodes_on_boundary().get_communicator())
      , foundation(foundation)
    {}

    template <int dim>
    const BoundaryNodes<dim> &
    RigidFriction<dim>::boundary() const
    {
      return foundation.contact_nodes_on_boundary();
    }

    template <int dim>
    void
    RigidFriction<dim>::lag(const VectorType               &u,
                            std::vector<double>            &normal_forces,
                            std::vector<TangentBasis<dim>> &bases)
    {
      const auto                &nodes  = foundation.nodes();
      const std::vector<double> &forces = foundation.forces();
      normal_forces.resize(nodes.size());
      bases.resize(nodes.size());
      for (unsigned int k = 0; k < nodes.size(); ++k)
        {
          const auto s     = foundation.evaluate(nodes[k], u);
          normal_forces[k] = std::max(0., forces[k]) * s.grad.norm();
          bases[k]         = tangent_basis(s.grad);
        }
    }

    template <int dim>
    std::vector<types::global_dof_index>
    RigidFriction<dim>::history_dofs() const
    {
      // The DoFs the foundation keeps its force record on.
      return foundation.force_dofs();
    }

    template <int dim>
    std::unique_ptr<FrictionTerm<dim>>
    create_friction_term(const FrictionParameters &parameters, Model<dim> &model)
    {
      if (!parameters.active())
        return nullptr;
      if (const auto *rigid = dynamic_cast<const RigidFoundation<dim> *>(&model))
        return std::make_unique<RigidFriction<dim>>(parameters, *rigid);
      if (auto *two_body = dynamic_cast<TwoBodyContact<dim> *>(&model))
        return std::make_unique<TwoBodyFriction<dim>>(parameters, model, *two_body);
      if (auto *two_pass = dynamic_cast<TwoPassContact<dim> *>(&model))
        return std::make_unique<TwoBodyFriction<dim>>(parameters, model,
                                                      two_pass->first_pass());
      throw InputError("Contact > Friction > Coefficient",
                       "Coulomb friction is available against the rigid foundation "
                       "and between two bodies; with Contact > Type = " +
                         model.type_name() + " it is not (doc/friction.md): set 0");
    }

    template <int dim>
    Evaluation
    FrictionObjective<dim>::evaluate(const VectorType                &u,
                                     const AffineConstraints<double> &constraints,
                                     VectorType                      *rhs,
                                     MatrixType                      *hessian)
    {
      Evaluation e = inner.evaluate(u, constraints, rhs, hessian);
      if (!friction || !e.admissible)
        return e;
      e.value += friction->add(u, constraints, rhs, hessian);
      e.force_scale = std::hypot(e.force_scale, friction->force_scale());
      if (!std::isfinite(e.value))
        e.admissible = false;
      return e;
    }

    template class FrictionTerm<2>;
    template class FrictionTerm<3>;
    template class NodeFriction<2>;
    template class NodeFriction<3>;
    template class RigidFriction<2>;
    template class RigidFriction<3>;
    template class FrictionObjective<2>;
    template class FrictionObjective<3>;
    template std::unique_ptr<FrictionTerm<2>>
    create_friction_term(const FrictionParameters &, Model<2> &);
    template std::unique_ptr<FrictionTerm<3>>
    create_friction_term(const FrictionParameters &, Model<3> &);
  } // namespace Contact
} // namespace Signorini
