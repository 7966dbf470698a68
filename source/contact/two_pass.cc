#include <signorini/archive_io.h>
#include <signorini/contact/two_pass.h>
#include <signorini/input_error.h>

#include <deal.II/base/mpi.h>

#include <algorithm>

namespace Signorini
{
  namespace Contact
  {
    namespace
    {
      /// The second pass's parameters: the target is body 1's contact
      /// boundary.
      TwoBodyParameters
      swapped_parameters(TwoBodyParameters parameters, const types::boundary_id contact)
      {
        parameters.target_boundary = contact;
        return parameters;
      }
    } // namespace

    template <int dim>
    TwoPassContact<dim>::TwoPassContact(const TwoBodyParameters &parameters,
                                        const types::boundary_id contact_boundary,
                                        const DoFHandler<dim>   &dof_handler,
                                        const Mapping<dim>      &mapping)
      : first(parameters, contact_boundary, dof_handler, mapping)
      , second(swapped_parameters(parameters, contact_boundary),
               parameters.target_boundary,
               dof_handler,
               mapping)
    {
      // Each body's record must hold the whole reaction of the pass that
      // tests the other body's nodes against it.
      first.set_lumped_reaction(true);
      second.set_lumped_reaction(true);
    }

    template <int dim>
    void
    TwoPassContact<dim>::setup(const AffineConstraints<double> &hanging_constraints,
                               const AffineConstraints<double> &constraints)
    {
      first.setup(hanging_constraints, constraints);
      second.setup(hanging_constraints, constraints);
      // The same boundaries collected the same way: the second pass's
      // contact nodes are the first pass's target nodes and vice versa.
      const auto same = [](const BoundaryNodes<dim> &a, const BoundaryNodes<dim> &b) {
        if (a.nodes().size() != b.nodes().size())
          return false;
        for (unsigned int k = 0; k < a.nodes().size(); ++k)
          if (a.nodes()[k].dofs != b.nodes()[k].dofs)
            return false;
        return true;
      };
      AssertThrow(same(first.target_nodes(), second.contact_nodes_on_boundary()) &&
                    same(first.contact_nodes_on_boundary(), second.target_nodes()),
                  ExcMessage("two-pass contact: the passes collected different nodes"));
      this->nodal_forces.assign(first.forces().size(), 0.);
    }

    template <int dim>
    void
    TwoPassContact<dim>::check_initial_state(const VectorType &u) const
    {
      first.check_initial_state(u);
      // The second pass's own message would name the boundaries the other
      // way round.
      if (!second.admissible(u))
        throw InputError("Body 2 > Geometry",
                         "at the start, a point of body 2's target boundary "
                         "(Contact > Two bodies > Target boundary id) lies inside "
                         "body 1 deeper than the layer in which the indicator "
                         "function of body 1's contact boundary acts (Passes = "
                         "two-pass): move the bodies apart (a penetration within "
                         "that layer is allowed)");
    }

    template <int dim>
    std::vector<double>
    TwoPassContact<dim>::swapped(const std::vector<double> &forces) const
    {
      const std::size_t   n1 = first.nodes().size() * dim;
      std::vector<double> out(forces.begin() + n1, forces.end());
      out.insert(out.end(), forces.begin(), forces.begin() + n1);
      return out;
    }

    template <int dim>
    void
    TwoPassContact<dim>::add_second_pass(const std::vector<double> &second_forces,
                                         std::vector<double>       &forces) const
    {
      // The second pass's record: body 2's nodes (n2 of them), then body
      // 1's; the first pass's: body 1's (n1), then body 2's.
      const std::size_t n1 = first.nodes().size() * dim;
      const std::size_t n2 = second.nodes().size() * dim;
      AssertThrow(second_forces.size() == forces.size() && n1 + n2 == forces.size(),
                  ExcInternalError());
      for (std::size_t i = 0; i < n1; ++i)
        forces[i] += second_forces[n2 + i];
      for (std::size_t j = 0; j < n2; ++j)
        forces[n1 + j] += second_forces[j];
    }

    template <int dim>
    double
    TwoPassContact<dim>::add_penalty(const VectorType                &u,
                                     const double                     mu,
                                     const AffineConstraints<double> &constraints,
                                     VectorType                      *rhs,
                                     MatrixType                      *hessian,
                                     std::vector<double>             *forces) const
    {
      std::vector<double> second_forces;
      const double        value =
        first.add_penalty(u, 0.5 * mu, constraints, rhs, hessian, forces) +
        second.add_penalty(u, 0.5 * mu, constraints, rhs, hessian,
                           forces ? &second_forces : nullptr);
      if (forces)
        add_second_pass(second_forces, *forces);
      return value;
    }

    template <int dim>
    typename PenaltyTerm<dim>::Measure
    TwoPassContact<dim>::measure(const VectorType &u, const std::vector<double> &forces) const
    {
      const double a = first.measure(u, forces).max_penetration_ratio;
      const double b = second.measure(u, swapped(forces)).max_penetration_ratio;
      return {std::max(a, b), this->n_active(u, forces)};
    }

    template <int dim>
    void
    TwoPassContact<dim>::write_summary(Json &block) const
    {
      first.write_summary(block);
      block["passes"] = 2;
      Json second_block;
      second.write_summary(second_block);
      block["second pass broad phase"] = second_block["broad phase"];
    }

    template <int dim>
    void
    TwoPassContact<dim>::save_state(OutputArchive &archive, MeshState &mesh) const
    {
      Model<dim>::save_state(archive, mesh);
      first.save_state(archive, mesh);
      second.save_state(archive, mesh);
    }

    template <int dim>
    void
    TwoPassContact<dim>::load_state(InputArchive &archive, MeshState &mesh)
    {
      Model<dim>::load_state(archive, mesh);
      first.load_state(archive, mesh);
      second.load_state(archive, mesh);
    }

    template class TwoPassContact<2>;
    template class TwoPassContact<3>;
  } // namespace Contact
} // namespace Signorini
