#include <signorini/contact/two_body_friction.h>

#include <algorithm>

namespace Signorini
{
  namespace Contact
  {
    template <int dim>
    TwoBodyFriction<dim>::TwoBodyFriction(const FrictionParameters &parameters,
                                          const Model<dim>         &record,
                                          TwoBodyContact<dim>      &geometry)
      : NodeFriction<dim>(parameters,
                          geometry.contact_nodes_on_boundary().get_communicator())
      , record(record)
      , geometry(geometry)
    {}

    template <int dim>
    void
    TwoBodyFriction<dim>::lag(const VectorType               &u,
                              std::vector<double>            &normal_forces,
                              std::vector<TangentBasis<dim>> &bases)
    {
      const auto                &nodes  = geometry.nodes();
      const std::vector<double> &forces = record.forces();
      const auto                 faces  = geometry.current_faces(u);
      // The normal and lambda from the closest point now; the slip from
      // the material point of the step's start (set_partner_reference()), kept,
      // or paired now for a node that had none (it was farther than a
      // face from body 2).
      const auto now = geometry.node_partners(u, faces);
      for (unsigned int k = 0; k < partners.size(); ++k)
        if (partners[k].face < 0)
          partners[k] = now[k];
      normal_forces.assign(nodes.size(), 0.);
      bases.resize(nodes.size());
      std::vector<std::pair<unsigned int, unsigned int>> couplings;
      for (unsigned int k = 0; k < nodes.size(); ++k)
        {
          if (partners[k].face < 0 || now[k].face < 0)
            {
              // Open, with any basis.
              Tensor<1, dim> up;
              up[dim - 1] = 1.;
              bases[k]    = tangent_basis(up);
              continue;
            }
          couplings.emplace_back(k, partners[k].face);
          Tensor<1, dim> f;
          for (unsigned int c = 0; c < dim; ++c)
            f[c] = forces[k * dim + c];
          normal_forces[k] = std::max(0., f * now[k].normal);
          bases[k]         = tangent_basis(now[k].normal);
        }
      geometry.set_node_couplings(std::move(couplings));
    }

    template <int dim>
    void
    TwoBodyFriction<dim>::set_partner_reference(const VectorType &u)
    {
      reference_faces = geometry.current_faces(u);
      // The material point of body 2 each node touches at the step's
      // start: its slip over the step is measured against that point for
      // the whole step. Re-pairing at every outer iteration would move
      // the point by up to a face, and with it the body 2 displacement
      // the slip subtracts: a node in stick (|s| below the slip length)
      // can then flip between stick and slip from one iteration to the
      // next, and the outer loop cycles.
      partners = geometry.node_partners(u, reference_faces);
    }

    template <int dim>
    void
    TwoBodyFriction<dim>::subtract_partners(const VectorType            &u,
                                            std::vector<Tensor<1, dim>> &du,
                                            std::vector<bool>           &has) const
    {
      const auto faces = geometry.current_faces(u);
      has.assign(du.size(), false);
      for (unsigned int k = 0; k < du.size(); ++k)
        if (k < partners.size() && partners[k].face >= 0)
          {
            has[k] = true;
            du[k] -= geometry.partner_displacement(faces, partners[k]) -
                     geometry.partner_displacement(reference_faces, partners[k]);
          }
    }

    template <int dim>
    void
    TwoBodyFriction<dim>::add_partner_coupling(const unsigned int                    k,
                                               typename NodeFriction<dim>::Coupling &c) const
    {
      const Partner &p = partners[k];
      for (unsigned int v = 0; v < TwoBodyContact<dim>::n_face_vertices; ++v)
        for (unsigned int d = 0; d < dim; ++d)
          {
            c.dofs.push_back(geometry.face_vertex_dof(p.face, v, d));
            c.components.push_back(d);
            c.factors.push_back(-p.shape[v]);
          }
    }

    template <int dim>
    std::vector<types::global_dof_index>
    TwoBodyFriction<dim>::history_dofs() const
    {
      std::vector<types::global_dof_index> dofs;
      for (const auto &node : geometry.nodes())
        dofs.push_back(node.dofs[0]);
      return dofs;
    }

    template class TwoBodyFriction<2>;
    template class TwoBodyFriction<3>;
  } // namespace Contact
} // namespace Signorini
