#pragma once

#include <signorini/contact/boundary_nodes.h>
#include <signorini/types.h>

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/numerics/data_out.h>

#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace Signorini
{
  namespace Contact
  {
    /**
     * The output role of a contact model: its contact nodes as samples
     * (position, gaps, pressure, force, weight), from which the pressures,
     * the active set, the resultants, the area, the profile CSV and the
     * VTU fields are computed. The output reaches it through
     * Model::samples(), so a model made of parts (two passes) hands out the
     * part that owns its nodes instead of forwarding each function.
     */
    template <int dim>
    class ContactSamples
    {
    public:
      virtual ~ContactSamples() = default;

      /// One contact node as the output sees it: the model's whole
      /// contribution to the profile, the VTU fields, the pressures, the
      /// active set, the resultants and the summary block.
      struct NodeSample
      {
        Point<dim>          X, x;   // reference and current position
        std::vector<double> gaps;   // the model's gap measures (profile_gaps())
        double              pressure = 0.;
        Tensor<1, dim>      force;  // the nodal contact force
        double              weight = 0.; // tributary length or area
        /// Further profile columns (friction's), named by write_profile's
        /// @p extra_header.
        std::vector<double> extra;
      };

      /// The nodes of the contact boundary Gamma_C (this rank's).
      virtual const BoundaryNodes<dim> &
      contact_nodes_on_boundary() const = 0;

      /// The contact pressure at each node of contact_nodes_on_boundary()
      /// for the state @p u with nodal @p forces (local).
      virtual std::vector<double>
      nodal_pressures(const VectorType &u, const std::vector<double> &forces) const = 0;

      /// This rank's contact nodes for the nodal @p forces at the ghosted
      /// state @p u, in the order of contact_nodes_on_boundary().
      virtual std::vector<NodeSample>
      node_samples(const VectorType &u, const std::vector<double> &forces) const = 0;

      /// The names of NodeSample::gaps, comma-separated (profile columns;
      /// the first one is also the VTU field contact_NAME).
      virtual std::string
      profile_gaps() const = 0;

      /// The profile along Gamma_C as CSV (rank 0 writes; collective): one
      /// row per entry of @p samples (node_samples() at @p u for the nodal
      /// @p forces), with a reference pressure where @p reference is
      /// given. A model may write more beside it (two bodies: body 2's
      /// side, from @p u and @p forces).
      virtual void
      write_profile(const std::string                               &file,
                    const VectorType                                &u,
                    const std::vector<double>                       &forces,
                    const std::vector<NodeSample>                   &samples,
                    const std::function<double(const Point<dim> &)> &reference,
                    const std::string &extra_header = "") const;

      /// (current position, pressure) of the active nodes of @p samples
      /// (node_samples()), on every rank, sorted by position (collective).
      std::vector<std::pair<Point<dim>, double>>
      gather_pressure(const std::vector<NodeSample> &samples) const;

      /// The nodal fields contact_pressure, contact_GAP (the first of
      /// profile_gaps()) and contact_active for the nodal @p forces; the
      /// vectors live with the contact nodes until the next call. A model
      /// may add more fields (a model of several pairs: the pair id).
      virtual void
      add_output_fields(DataOut<dim>              &data_out,
                        const VectorType          &u,
                        const std::vector<double> &forces) const;
    };

    /// 1e-6 of the largest of @p pressures on any rank: the pressure a
    /// node must exceed to count as active.
    double
    active_threshold(const std::vector<double> &pressures, const MPI_Comm comm);

    /// The pressures of @p samples (NodeSample of any dimension).
    template <typename Sample>
    std::vector<double>
    pressures_of(const std::vector<Sample> &samples)
    {
      std::vector<double> p;
      for (const Sample &s : samples)
        p.push_back(s.pressure);
      return p;
    }
  } // namespace Contact
} // namespace Signorini
