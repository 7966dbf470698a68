#pragma once

#include <signorini/contact/boundary_nodes.h>
#include <signorini/types.h>

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <algorithm>

namespace Signorini
{
  namespace Contact
  {
    /**
     * The constraint role of a contact model: one inequality g_k(U) >= 0
     * per contact node k, with its exact gradient and Hessian in the
     * node's dim x dim block. This is all that the constrained solvers
     * (Ipopt, the interior point method) see of the contact; a model
     * offers it through Model::node_wise_constraints() when its registry
     * entry declares the capability.
     */
    template <int dim>
    class NodeWiseConstraints
    {
    public:
      virtual ~NodeWiseConstraints() = default;

      /// One constraint at a state: the current position of the node, g
      /// and its derivatives.
      struct State
      {
        Point<dim>     x;
        double         g = 0.;
        Tensor<1, dim> grad;
        Tensor<2, dim> hess;
        /// Geometric penetration depth (>= 0), first order: <-g>/|grad g|.
        double
        penetration() const
        {
          return std::max(-g, 0.) / grad.norm();
        }
      };

      /// The constrained nodes (this rank's), one constraint each.
      virtual const BoundaryNodes<dim> &
      contact_nodes_on_boundary() const = 0;

      /// The constraint of @p node at the ghosted state @p u.
      virtual State
      constraint(const BoundaryNode<dim> &node, const VectorType &u) const = 0;

      /// Smallest mesh size at the constrained nodes (the scale of the
      /// interior point method's slack bounds).
      virtual double
      min_mesh_size() const = 0;
    };
  } // namespace Contact
} // namespace Signorini
