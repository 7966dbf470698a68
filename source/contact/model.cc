#include <signorini/archive_io.h>
#include <signorini/contact/model.h>

namespace Signorini
{
  namespace Contact
  {
    template <int dim>
    void
    Model<dim>::save_state(OutputArchive &archive) const
    {
      archive << nodal_forces;
    }

    template <int dim>
    void
    Model<dim>::load_state(InputArchive &archive)
    {
      std::vector<double> forces;
      archive >> forces;
      // The checkpoint's mesh, the same ranks: the same contact nodes.
      AssertThrow(forces.size() == nodal_forces.size() || nodal_forces.empty(),
                  ExcMessage("the checkpoint has " + std::to_string(forces.size()) +
                             " contact nodes on this rank, the restarted run " +
                             std::to_string(nodal_forces.size())));
      nodal_forces = std::move(forces);
    }

    template <int dim>
    void
    Model<dim>::write_profile(const std::string                               &file,
                              const VectorType                                &u,
                              const std::vector<double>                       &forces,
                              const std::function<double(const Point<dim> &)> &reference) const
    {
      // X.., x.., the gaps, pressure, force.., weight[, reference].
      std::vector<std::vector<double>> rows;
      for (const NodeSample &sample : node_samples(u, forces))
        {
          std::vector<double> row;
          for (unsigned int d = 0; d < dim; ++d)
            row.push_back(sample.X[d]);
          for (unsigned int d = 0; d < dim; ++d)
            row.push_back(sample.x[d]);
          row.insert(row.end(), sample.gaps.begin(), sample.gaps.end());
          row.push_back(sample.pressure);
          for (unsigned int d = 0; d < dim; ++d)
            row.push_back(sample.force[d]);
          row.push_back(sample.weight);
          if (reference)
            row.push_back(reference(sample.x));
          rows.push_back(row);
        }
      const auto &boundary = this->contact_nodes_on_boundary();
      boundary.write_csv(file,
                         BoundaryNodes<dim>::profile_header(profile_gaps() + ",pressure",
                                                            bool(reference)),
                         rows);
    }

    template class Model<2>;
    template class Model<3>;
  } // namespace Contact
} // namespace Signorini
