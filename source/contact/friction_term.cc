#include <signorini/contact/friction_term.h>
#include <signorini/contact/rigid_foundation.h>
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
    typename FrictionTerm<dim>::Totals
    FrictionTerm<dim>::totals(const VectorType &u, const MPI_Comm comm) const
    {
      Totals t;
      for (const auto &p : point_samples(u))
        {
          t.force += p.force;
          t.dissipation += p.dissipation;
          t.n_stick += (p.status == FrictionStatus::stick);
          t.n_slip += (p.status == FrictionStatus::slip);
        }
      for (unsigned int d = 0; d < dim; ++d)
        t.force[d] = Utilities::MPI::sum(t.force[d], comm);
      t.dissipation = Utilities::MPI::sum(t.dissipation, comm);
      t.n_stick     = Utilities::MPI::sum(t.n_stick, comm);
      t.n_slip      = Utilities::MPI::sum(t.n_slip, comm);
      return t;
    }

    template <int dim>
    RigidFriction<dim>::RigidFriction(const FrictionParameters   &parameters,
                                      const RigidFoundation<dim> &foundation)
      : FrictionTerm<dim>(parameters)
      , foundation(foundation)
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
    }

    template <int dim>
    void
    RigidFriction<dim>::start_step(const VectorType &u)
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
      return Utilities::MPI::sum(value, foundation.contact_nodes_on_boundary().get_communicator());
    }

    template <int dim>
    double
    RigidFriction<dim>::update(const VectorType &u)
    {
      const std::vector<double> old = lambda;
      lag(u);
      double change = 0., largest = 0.;
      for (unsigned int k = 0; k < lambda.size(); ++k)
        {
          change  = std::max(change, std::abs(lambda[k] - (k < old.size() ? old[k] : 0.)));
          largest = std::max(largest, lambda[k]);
        }
      const MPI_Comm comm = foundation.contact_nodes_on_boundary().get_communicator();
      change              = Utilities::MPI::max(change, comm);
      largest             = Utilities::MPI::max(largest, comm);
      return largest > 0. ? change / largest : 0.;
    }

    template <int dim>
    std::vector<typename FrictionTerm<dim>::PointSample>
    RigidFriction<dim>::point_samples(const VectorType &u) const
    {
      std::vector<typename FrictionTerm<dim>::PointSample> samples;
      const auto &nodes = foundation.nodes();
      for (unsigned int k = 0; k < laws.size(); ++k)
        {
          typename FrictionTerm<dim>::PointSample p;
          p.X            = nodes[k].X;
          p.weight       = nodes[k].weight;
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
