#pragma once

#include <signorini/contact/boundary_nodes.h>
#include <signorini/contact/foundation.h>
#include <signorini/contact/model.h>
#include <signorini/types.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>

#include <array>
#include <cmath>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace Signorini
{
  namespace Contact
  {
    /**
     * Frictionless contact of the bodies' boundary Gamma_2 (a boundary id)
     * with a rigid foundation x_d >= psi(x'): one constraint per degree-of-
     * freedom support point k on Gamma_2 (formulation.md section 2),
     *
     *   g_k(U) = X_d,k + U_d,k - psi(X'_k + U'_k) >= 0,
     *
     * with gradient e_d - grad psi and Hessian -hess psi in the node's
     * dim x dim block. Nodes whose vertical DoF is a hanging node are left
     * out (they follow their parents). Each MPI rank holds the nodes whose
     * DoFs it owns.
     *
     * Each node carries its tributary weight w_k = int_Gamma2 phi_k ds
     * (reference configuration; the lumped length or area of the node) and
     * a local mesh size h_k (mean diameter of the Gamma_2 faces at the
     * node). Contact pressure is the node's force over w_k; penetration is
     * reported relative to h_k.
     *
     * The class serves both solvers: the penalty term
     * mu/3 sum_k w_k <-g_k>^3 for Newton, and the constraint values and
     * derivatives for Ipopt. Given the nodal contact forces lambda_k >= 0
     * (along grad g_k) it computes the contact output: pressure, gap,
     * active set, total force, the CSV profile and the Hertz quantities.
     */
    template <int dim>
    class RigidFoundation : public Model<dim>,
                            public NodeWiseConstraints<dim>,
                            public ContactSamples<dim>
    {
    public:
      using Node = BoundaryNode<dim>;

      using State = typename NodeWiseConstraints<dim>::State;

      /// The model is its own constraint role.
      const NodeWiseConstraints<dim> *
      node_wise_constraints() const override
      {
        return this;
      }

      RigidFoundation(std::unique_ptr<Foundation<dim>> foundation,
                      const types::boundary_id          boundary_id,
                      const DoFHandler<dim>            &dof_handler,
                      const Mapping<dim>               &mapping);

      /// Collect the contact nodes (call after the DoFs are distributed).
      void
      setup(const AffineConstraints<double> &hanging_constraints);

      /// The same, as a Model (the Dirichlet data play no part here).
      void
      setup(const AffineConstraints<double> &hanging_constraints,
            const AffineConstraints<double> &constraints) override
      {
        (void)constraints;
        setup(hanging_constraints);
      }

      std::string
      type_name() const override
      {
        return "rigid foundation";
      }

      std::string
      description() const override
      {
        return surface->description();
      }

      /// Every node of Gamma_2 is a hanging node: nothing to constrain.
      void
      check_initial_state(const VectorType &u) const override;

      /// mu_0 = c_0 E / h^2, h the smallest h_k.
      double
      initial_penalty(const double c0_E) const override
      {
        return c0_E / std::pow(min_mesh_size(), 2);
      }

      /// The contact boundary, with the gap x_d - psi(x') in the reference
      /// configuration.
      std::vector<typename Model<dim>::BandSurface>
      band_surfaces() const override
      {
        return {{this->contact_boundary_id(), [this](const Point<dim> &X) {
                   return X[dim - 1] - surface->evaluate(X).psi;
                 }}};
      }

      State
      constraint(const Node &node, const VectorType &u) const override
      {
        return evaluate(node, u);
      }

      void
      write_summary(Json &block) const override;

      /// One force per node, on the node's first DoF.
      std::vector<types::global_dof_index>
      force_dofs() const override
      {
        std::vector<types::global_dof_index> dofs;
        for (const auto &node : boundary.nodes())
          dofs.push_back(node.dofs[0]);
        return dofs;
      }

      /// The nodes owned by this rank.
      const std::vector<Node> &
      nodes() const
      {
        return boundary.nodes();
      }

      unsigned int
      n_global_nodes() const override
      {
        return boundary.n_global();
      }

      /// Mean h_k over all nodes, the scale of penalty parameters.
      double
      mean_mesh_size() const override
      {
        return boundary.mean_mesh_size();
      }

      /// Smallest h_k: the finest contact resolution.
      double
      min_mesh_size() const override
      {
        return boundary.min_mesh_size();
      }

      const Foundation<dim> &
      foundation() const
      {
        return *surface;
      }

      /// Position, gap and derivatives of node @p node at the ghosted @p u.
      State
      evaluate(const Node &node, const VectorType &u) const;

      /**
       * Add the penalty term mu/3 sum_k w_k <-g_k>^3 and, if given, minus
       * its gradient to @p rhs and its Hessian to @p hessian (condensed
       * with @p constraints, then compressed: collective). Returns the
       * term's value summed over all ranks. If @p forces is given it
       * receives the nodal forces mu w_k <-g_k>^2.
       */
      double
      add_penalty(const VectorType                &u,
                  const double                     mu,
                  const AffineConstraints<double> &constraints,
                  VectorType                      *rhs,
                  MatrixType                      *hessian,
                  std::vector<double>             *forces = nullptr) const override;

      /**
       * Lift each node that is free at the ghosted @p u (g_k >= 0) and
       * whose vertical position in @p trial (locally owned) lies deeper
       * than the deepest penetration at @p u to that depth, moving its
       * vertical DoF only. Nothing moves while no node penetrates.
       */
      bool
      limit_trial(const VectorType &u, VectorType &trial) const override;

      typename PenaltyTerm<dim>::Measure
      measure(const VectorType &u, const std::vector<double> &forces) const override
      {
        return {max_penetration_ratio(u), this->n_active(u, forces)};
      }

      /// Largest <-g_k>/|grad g_k| / h_k over the nodes (collective).
      double
      max_penetration_ratio(const VectorType &u) const override;

      types::boundary_id
      contact_boundary_id() const override
      {
        return contact_boundary;
      }

      const BoundaryNodes<dim> &
      contact_nodes_on_boundary() const override
      {
        return boundary;
      }

      std::vector<double>
      nodal_pressures(const VectorType          &u,
                      const std::vector<double> &forces) const override
      {
        std::vector<double> p(contact_nodes().size());
        for (unsigned int k = 0; k < p.size(); ++k)
          p[k] = pressure(contact_nodes()[k], evaluate(contact_nodes()[k], u), forces[k]);
        return p;
      }

      const ContactSamples<dim> &
      samples() const override
      {
        return *this;
      }

      /// The profile's nodes: gaps are the signed distance g/|grad g|
      /// ("gap") and the penetration over the local mesh size.
      std::vector<typename Model<dim>::NodeSample>
      node_samples(const VectorType &u, const std::vector<double> &forces) const override;

      std::string
      profile_gaps() const override
      {
        return "gap,penetration_over_h";
      }

    private:
      /// Pressure of @p node in state @p s carrying the force @p force
      /// along grad g: force |grad g| / w_k.
      static double
      pressure(const Node &node, const State &s, const double force)
      {
        return force * s.grad.norm() / node.weight;
      }

      const std::vector<Node> &
      contact_nodes() const
      {
        return boundary.nodes();
      }

      std::unique_ptr<Foundation<dim>> surface;
      types::boundary_id               contact_boundary;
      const DoFHandler<dim>           &dof_handler;
      BoundaryNodes<dim>               boundary;
    };
  } // namespace Contact
} // namespace Signorini
