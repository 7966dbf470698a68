#include <signorini/contact/registry.h>
#include <signorini/contact/rigid_foundation.h>
#include <signorini/input_error.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <fstream>
#include <iomanip>
#include <set>

namespace Signorini
{
  namespace Contact
  {
    template <int dim>
    RigidFoundation<dim>::RigidFoundation(
      std::unique_ptr<Foundation<dim>> foundation,
      const types::boundary_id          boundary_id,
      const DoFHandler<dim>            &dof_handler,
      const Mapping<dim>               &mapping)
      : surface(std::move(foundation))
      , contact_boundary(boundary_id)
      , dof_handler(dof_handler)
      , boundary(dof_handler, mapping)
    {}

    template <int dim>
    void
    RigidFoundation<dim>::setup(const AffineConstraints<double> &hanging_constraints)
    {
      boundary.setup({contact_boundary}, hanging_constraints);
      this->nodal_forces.assign(boundary.nodes().size(), 0.);
    }

    template <int dim>
    void
    RigidFoundation<dim>::check_initial_state(const VectorType &u) const
    {
      (void)u;
      if (n_global_nodes() == 0)
        throw InputError("Contact > Contact boundary id",
                         "boundary " + std::to_string(contact_boundary) +
                           " has no contact node (every node on it is a "
                           "hanging node)");
    }

    template <int dim>
    void
    RigidFoundation<dim>::write_summary(Json &block) const
    {
      this->write_common_summary(block, "foundation");
    }

    template <int dim>
    typename RigidFoundation<dim>::State
    RigidFoundation<dim>::evaluate(const Node &node, const VectorType &u) const
    {
      State s;
      for (unsigned int c = 0; c < dim; ++c)
        s.x[c] = node.X[c] + u[node.dofs[c]];
      const auto psi = surface->evaluate(s.x);
      s.g            = s.x[dim - 1] - psi.psi;
      s.grad         = -psi.gradient;
      s.grad[dim - 1] += 1.;
      s.hess = -psi.hessian;
      return s;
    }

    template <int dim>
    double
    RigidFoundation<dim>::add_penalty(const VectorType                &u,
                                      const double                     mu,
                                      const AffineConstraints<double> &constraints,
                                      VectorType                      *rhs,
                                      MatrixType                      *hessian,
                                      std::vector<double>             *forces) const
    {
      double                               value = 0.;
      FullMatrix<double>                   local_matrix(dim, dim);
      Vector<double>                       local_rhs(dim);
      std::vector<types::global_dof_index> dofs(dim);
      if (forces)
        forces->assign(contact_nodes().size(), 0.);
      for (unsigned int k = 0; k < contact_nodes().size(); ++k)
        {
          const Node  &node = contact_nodes()[k];
          const State  s    = evaluate(node, u);
          if (s.g >= 0.)
            continue;
          const double p = -s.g;
          value += mu / 3. * node.weight * p * p * p;
          if (forces)
            (*forces)[k] = mu * node.weight * p * p;
          if (!rhs && !hessian)
            continue;
          for (unsigned int i = 0; i < dim; ++i)
            {
              dofs[i]      = node.dofs[i];
              // minus the gradient -mu w p^2 grad g
              local_rhs(i) = mu * node.weight * p * p * s.grad[i];
              for (unsigned int j = 0; j < dim; ++j)
                local_matrix(i, j) =
                  mu * node.weight * (2. * p * s.grad[i] * s.grad[j] - p * p * s.hess[i][j]);
            }
          if (rhs && hessian)
            constraints.distribute_local_to_global(local_matrix, local_rhs, dofs,
                                                   *hessian, *rhs);
          else if (rhs)
            constraints.distribute_local_to_global(local_rhs, dofs, *rhs);
          else
            constraints.distribute_local_to_global(local_matrix, dofs, *hessian);
        }
      if (rhs)
        rhs->compress(VectorOperation::add);
      if (hessian)
        hessian->compress(VectorOperation::add);
      return Utilities::MPI::sum(value, dof_handler.get_communicator());
    }

    template <int dim>
    bool
    RigidFoundation<dim>::limit_trial(const VectorType &u, VectorType &trial) const
    {
      const MPI_Comm comm  = dof_handler.get_communicator();
      double         depth = 0.;
      for (const Node &node : contact_nodes())
        depth = std::max(depth, evaluate(node, u).penetration());
      depth = Utilities::MPI::max(depth, comm);
      if (depth <= 0.)
        return false;
      unsigned int moved = 0;
      for (const Node &node : contact_nodes())
        {
          if (evaluate(node, u).g < 0. ||
              !trial.in_local_range(node.dofs[dim - 1]))
            continue;
          Point<dim> x;
          for (unsigned int c = 0; c < dim; ++c)
            x[c] = node.X[c] + trial[node.dofs[c]];
          const double g = x[dim - 1] - surface->evaluate(x).psi;
          if (g < -depth)
            {
              trial[node.dofs[dim - 1]] += -depth - g;
              ++moved;
            }
        }
      // The writes above leave the vector in 'add' mode on the ranks that
      // wrote: every rank compresses, so that all agree (collective).
      trial.compress(VectorOperation::add);
      return Utilities::MPI::sum(moved, comm) > 0;
    }

    template <int dim>
    double
    RigidFoundation<dim>::max_penetration_ratio(const VectorType &u) const
    {
      double ratio = 0.;
      for (const Node &node : contact_nodes())
        ratio = std::max(ratio, evaluate(node, u).penetration() / node.h);
      return Utilities::MPI::max(ratio, dof_handler.get_communicator());
    }

    template <int dim>
    std::vector<typename Model<dim>::NodeSample>
    RigidFoundation<dim>::node_samples(const VectorType          &u,
                                       const std::vector<double> &forces) const
    {
      // Gaps: the signed distance g/|grad g| and the penetration over h.
      std::vector<typename Model<dim>::NodeSample> samples;
      for (unsigned int k = 0; k < contact_nodes().size(); ++k)
        {
          const Node  &n = contact_nodes()[k];
          const State  s = evaluate(n, u);
          typename Model<dim>::NodeSample sample;
          sample.X        = n.X;
          sample.x        = s.x;
          sample.gaps     = {s.g / s.grad.norm(), s.penetration() / n.h};
          sample.pressure = pressure(n, s, forces[k]);
          sample.force    = forces[k] * s.grad;
          sample.weight   = n.weight;
          samples.push_back(sample);
        }
      return samples;
    }

    template class RigidFoundation<2>;
    template class RigidFoundation<3>;

    ModelEntry
    rigid_foundation_model()
    {
      ModelEntry entry;
      entry.name = "rigid foundation";
      entry.help = "rigid foundation: the boundary 'Contact boundary id' must stay above "
                   "the surface of the Foundation subsection (node-wise constraints).";
      entry.capabilities.node_wise_constraints = true;
      entry.capabilities.bodies                = 1;
      entry.declare_parameters                 = [](ParameterHandler &prm) {
        prm.enter_subsection("Foundation");
        Foundation<2>::declare_parameters(prm);
        prm.leave_subsection();
      };
      entry.parse_parameters = [](ParameterHandler &prm, const unsigned int dim) {
        FoundationParameters foundation;
        prm.enter_subsection("Foundation");
        foundation.parse_parameters(prm, dim, "Contact > Foundation");
        prm.leave_subsection();
        return std::make_shared<const ParsedParameters<FoundationParameters>>(
          std::move(foundation));
      };
      entry.set_create([](const ModelParameters   &parameters,
                          const types::boundary_id boundary_id,
                          const auto              &dof_handler,
                          const auto              &mapping) {
        constexpr int dim = std::decay_t<decltype(dof_handler)>::dimension;
        return std::unique_ptr<Model<dim>>(std::make_unique<RigidFoundation<dim>>(
          Foundation<dim>::create(parsed<FoundationParameters>(parameters)),
          boundary_id,
          dof_handler,
          mapping));
      });
      return entry;
    }
  } // namespace Contact
} // namespace Signorini
