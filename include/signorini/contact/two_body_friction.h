#pragma once

#include <signorini/contact/friction_term.h>
#include <signorini/contact/two_body.h>

#include <vector>

namespace Signorini
{
  namespace Contact
  {
    /**
     * Coulomb friction between two deformable bodies (doc/friction.md,
     * "Two bodies"), node by node on body 1's contact boundary Gamma_C:
     * each node is paired with the closest point of body 2's contact
     * surface (TwoBodyContact::node_partners(), re-paired whenever lambda
     * is re-lagged), and its slip is measured against that material point
     * of body 2:
     *
     *   du_k = (u_k - u_n,k) - sum_v N_v (u_v - u_n,v),
     *
     * v the vertices of the partner face, N_v the weights of the point,
     * u_n the state at the step's start. The normal is body 2's outward
     * normal there and lambda_k = max(0, f_k . n_k), f_k body 1's nodal
     * force in the model's force record (the penalty force of the
     * indicator function, in the nodal or the integral form; both passes
     * with two-pass). The term couples a node's DoFs with those of its
     * partner face's vertices; the couplings go into the two-body model's
     * sparsity pattern (TwoBodyContact::set_node_couplings()).
     */
    template <int dim>
    class TwoBodyFriction : public NodeFriction<dim>
    {
    public:
      /// @p record: the scene's model, whose force record gives lambda;
      /// @p geometry: its pass of body 1 against body 2 (the same object
      /// unless the model is two-pass).
      TwoBodyFriction(const FrictionParameters &parameters,
                      const Model<dim>         &record,
                      TwoBodyContact<dim>      &geometry);

      const BoundaryNodes<dim> &
      boundary() const override
      {
        return geometry.contact_nodes_on_boundary();
      }

    protected:
      void
      lag(const VectorType               &u,
          std::vector<double>            &normal_forces,
          std::vector<TangentBasis<dim>> &bases) override;

      void
      set_partner_reference(const VectorType &u) override;

      void
      subtract_partners(const VectorType            &u,
                        std::vector<Tensor<1, dim>> &du,
                        std::vector<bool>           &has) const override;

      void
      add_partner_coupling(const unsigned int                    k,
                           typename NodeFriction<dim>::Coupling &c) const override;

      const AffineConstraints<double> &
      condensation(const AffineConstraints<double> &constraints) const override
      {
        return geometry.assembly_constraints(constraints);
      }

      std::vector<types::global_dof_index>
      history_dofs() const override;

    private:
      using Partner = typename TwoBodyContact<dim>::Partner;

      const Model<dim>             &record;
      TwoBodyContact<dim>          &geometry;
      std::vector<Partner>          partners;
      std::vector<IndicatorFace<dim>> reference_faces; // at u_n
    };
  } // namespace Contact
} // namespace Signorini
