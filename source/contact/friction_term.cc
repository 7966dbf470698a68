#include <signorini/archive_io.h>
#include <signorini/contact/friction_term.h>
#include <signorini/contact/rigid_foundation.h>
#include <signorini/contact/samples.h>
#include <signorini/input_error.h>

#include <deal.II/base/mpi.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <cmath>

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
    RigidFriction<dim>::RigidFriction(const FrictionParameters   &parameters,
                                      const RigidFoundation<dim> &foundation)
      : FrictionTerm<dim>(parameters)
      , foundation(foundation)
      , mixing(5, foundation.contact_nodes_on_boundary().get_communicator())
    {}

    template <int dim>
    Tensor<1, dim>
    RigidFriction<dim>::increment(const unsigned int k, const VectorType &u) const
    {
      Tensor<1, dim> du;
      const auto    &node = foundation.nodes()[k];
      for (unsigned int c = 0; c < dim; ++c)
        du[c] = u[node.dofs[c]] - reference[k][c];
      return du;
    }

    template <int dim>
    void
    RigidFriction<dim>::lag(const VectorType &u)
    {
      const auto                &nodes  = foundation.nodes();
      const std::vector<double> &forces = foundation.forces();
      lambda.resize(nodes.size());
      basis.resize(nodes.size());
      for (unsigned int k = 0; k < nodes.size(); ++k)
        {
          const auto s = foundation.evaluate(nodes[k], u);
          lambda[k]    = std::max(0., forces[k]) * s.grad.norm();
          basis[k]     = tangent_basis(s.grad);
        }
      // The active set of the output (contact/samples.h): a node whose
      // force is below 1e-6 of the largest is open. The interior point
      // method's multipliers never vanish exactly.
      const double threshold = active_threshold(lambda, boundary().get_communicator());
      for (double &l : lambda)
        if (l <= threshold)
          l = 0.;
    }

    template <int dim>
    void
    RigidFriction<dim>::save_state(OutputArchive &archive, MeshState &mesh) const
    {
      // On the DoFs the foundation keeps its force record on.
      const auto         dofs = foundation.force_dofs();
      const unsigned int n    = history.size();
      archive << n << history_times;
      for (const auto &lambdas : history)
        mesh.save_dof_field(dofs, lambdas);
    }

    template <int dim>
    void
    RigidFriction<dim>::load_state(InputArchive &archive, MeshState &mesh)
    {
      const auto   dofs = foundation.force_dofs();
      unsigned int n    = 0;
      archive >> n >> history_times;
      history.clear();
      for (unsigned int i = 0; i < n; ++i)
        history.push_back(mesh.load_dof_field(dofs));
    }

    template <int dim>
    const BoundaryNodes<dim> &
    RigidFriction<dim>::boundary() const
    {
      return foundation.contact_nodes_on_boundary();
    }

    template <int dim>
    void
    RigidFriction<dim>::start_step(const VectorType &u, const double time)
    {
      const auto &nodes = foundation.nodes();
      reference.resize(nodes.size());
      laws.clear();
      for (unsigned int k = 0; k < nodes.size(); ++k)
        {
          for (unsigned int c = 0; c < dim; ++c)
            reference[k][c] = u[nodes[k].dofs[c]];
          laws.emplace_back(this->parameters.coefficient,
                            this->parameters.slip_length_at(nodes[k].h));
        }
      lag(u);
      mixing.clear();
      // A run's start without contact forces (load time 0): the first
      // point of the history.
      if (history.empty())
        {
          double largest = 0.;
          for (const double l : lambda)
            largest = std::max(largest, l);
          if (Utilities::MPI::max(largest, boundary().get_communicator()) == 0.)
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
    }

    template <int dim>
    void
    RigidFriction<dim>::step_done(const double time)
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
    RigidFriction<dim>::add(const VectorType                &u,
                            const AffineConstraints<double> &constraints,
                            VectorType                      *rhs,
                            MatrixType                      *hessian) const
    {
      AssertThrow(laws.size() == foundation.nodes().size(),
                  ExcMessage("the friction term is used before start_step()"));
      double                               value = 0.;
      Vector<double>                       gradient;
      FullMatrix<double>                   matrix;
      Vector<double>                       local_rhs(dim);
      std::vector<types::global_dof_index> dofs(dim);
      for (unsigned int k = 0; k < laws.size(); ++k)
        {
          if (lambda[k] <= 0.)
            continue;
          const auto &node = foundation.nodes()[k];
          value += laws[k].evaluate_rigid(basis[k], increment(k, u), lambda[k],
                                          rhs ? &gradient : nullptr,
                                          hessian ? &matrix : nullptr);
          if (!rhs && !hessian)
            continue;
          for (unsigned int i = 0; i < dim; ++i)
            dofs[i] = node.dofs[i];
          if (rhs)
            for (unsigned int i = 0; i < dim; ++i)
              local_rhs(i) = -gradient(i);
          if (rhs && hessian)
            constraints.distribute_local_to_global(matrix, local_rhs, dofs, *hessian, *rhs);
          else if (rhs)
            constraints.distribute_local_to_global(local_rhs, dofs, *rhs);
          else
            constraints.distribute_local_to_global(matrix, dofs, *hessian);
        }
      if (rhs)
        rhs->compress(VectorOperation::add);
      if (hessian)
        hessian->compress(VectorOperation::add);
      return Utilities::MPI::sum(value, boundary().get_communicator());
    }

    template <int dim>
    double
    RigidFriction<dim>::update(const VectorType &u)
    {
      // lambda was the input of the last solve; lag() makes it its output.
      const std::vector<double> old = lambda;
      lag(u);
      AssertThrow(old.size() == lambda.size(),
                  ExcMessage("the friction term is updated before start_step()"));
      double change = 0., largest = 0.;
      for (unsigned int k = 0; k < lambda.size(); ++k)
        {
          change  = std::max(change, std::abs(lambda[k] - old[k]));
          largest = std::max(largest, lambda[k]);
        }
      const MPI_Comm comm = boundary().get_communicator();
      change              = Utilities::MPI::max(change, comm);
      largest             = Utilities::MPI::max(largest, comm);
      const double relative = largest > 0. ? change / largest : 0.;
      // Not yet settled: the next solve takes the accelerated forces.
      if (relative > this->parameters.outer_tolerance)
        lambda = mixing.next(old, lambda);
      return relative;
    }

    template <int dim>
    std::vector<typename FrictionTerm<dim>::PointSample>
    RigidFriction<dim>::point_samples(const VectorType &u) const
    {
      std::vector<typename FrictionTerm<dim>::PointSample> samples;
      const auto &nodes = foundation.nodes();
      // Before the first load step (the initial output) every node is open.
      const bool started = laws.size() == nodes.size();
      for (unsigned int k = 0; k < nodes.size(); ++k)
        {
          typename FrictionTerm<dim>::PointSample p;
          p.X            = nodes[k].X;
          p.weight       = nodes[k].weight;
          if (!started)
            {
              samples.push_back(p);
              continue;
            }
          p.normal_force = lambda[k];
          const auto s   = basis[k].project(increment(k, u));
          p.slip         = basis[k].lift(s);
          p.status       = laws[k].status(s, lambda[k]);
          p.dissipation  = laws[k].dissipated_energy(s, lambda[k]);
          // The foundation's force on the body: minus dD/du.
          p.force = -basis[k].lift(laws[k].evaluate(s, lambda[k]).traction);
          samples.push_back(p);
        }
      return samples;
    }

    template <int dim>
    std::unique_ptr<FrictionTerm<dim>>
    create_friction_term(const FrictionParameters &parameters, const Model<dim> &model)
    {
      if (!parameters.active())
        return nullptr;
      if (const auto *rigid = dynamic_cast<const RigidFoundation<dim> *>(&model))
        return std::make_unique<RigidFriction<dim>>(parameters, *rigid);
      throw InputError("Contact > Friction > Coefficient",
                       "Coulomb friction is available against the rigid foundation "
                       "(Contact > Type = rigid foundation); with Contact > Type = " +
                         model.type_name() +
                         " it is not yet (doc/friction.md): set 0 (frictionless)");
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
      if (!std::isfinite(e.value))
        e.admissible = false;
      return e;
    }

    template class FrictionTerm<2>;
    template class FrictionTerm<3>;
    template class RigidFriction<2>;
    template class RigidFriction<3>;
    template class FrictionObjective<2>;
    template class FrictionObjective<3>;
    template std::unique_ptr<FrictionTerm<2>>
    create_friction_term(const FrictionParameters &, const Model<2> &);
    template std::unique_ptr<FrictionTerm<3>>
    create_friction_term(const FrictionParameters &, const Model<3> &);
  } // namespace Contact
} // namespace Signorini
