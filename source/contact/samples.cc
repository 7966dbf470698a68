#include <signorini/contact/samples.h>

#include <deal.II/base/mpi.h>

#include <algorithm>

namespace Signorini
{
  namespace Contact
  {
    double
    active_threshold(const std::vector<double> &pressures, const MPI_Comm comm)
    {
      double largest = 0.;
      for (const double p : pressures)
        largest = std::max(largest, p);
      return 1e-6 * Utilities::MPI::max(largest, comm);
    }

    template <int dim>
    std::vector<std::pair<Point<dim>, double>>
    ContactSamples<dim>::gather_pressure(const std::vector<NodeSample> &samples) const
    {
      const auto  &boundary  = contact_nodes_on_boundary();
      const double threshold =
        active_threshold(pressures_of(samples), boundary.get_communicator());
      std::vector<std::pair<Point<dim>, double>> local;
      for (const NodeSample &sample : samples)
        if (sample.pressure > threshold)
          local.emplace_back(sample.x, sample.pressure);
      return boundary.gather_sorted(local);
    }

    template <int dim>
    void
    ContactSamples<dim>::add_output_fields(DataOut<dim>              &data_out,
                                           const VectorType          &u,
                                           const std::vector<double> &forces) const
    {
      const auto  &boundary  = contact_nodes_on_boundary();
      const auto   samples   = node_samples(u, forces);
      const auto   pressures = pressures_of(samples);
      const double threshold = active_threshold(pressures, boundary.get_communicator());
      std::vector<double> gap, active;
      for (const NodeSample &sample : samples)
        {
          gap.push_back(sample.gaps.front());
          active.push_back(sample.pressure > threshold ? 1. : 0.);
        }
      const std::string gaps = profile_gaps();
      boundary.add_fields(data_out,
                          {"contact_pressure", "contact_" + gaps.substr(0, gaps.find(',')),
                           "contact_active"},
                          {pressures, gap, active});
    }

    template <int dim>
    void
    ContactSamples<dim>::write_profile(const std::string &file,
                                       const VectorType &,
                                       const std::vector<double> &,
                                       const std::vector<NodeSample>                   &samples,
                                       const std::function<double(const Point<dim> &)> &reference,
                                       const std::string &extra_header) const
    {
      // X.., x.., the gaps, pressure, force.., weight[, reference].
      std::vector<std::vector<double>> rows;
      for (const NodeSample &sample : samples)
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
          row.insert(row.end(), sample.extra.begin(), sample.extra.end());
          rows.push_back(row);
        }
      const auto &boundary = contact_nodes_on_boundary();
      boundary.write_csv(file,
                         BoundaryNodes<dim>::profile_header(profile_gaps() + ",pressure",
                                                            bool(reference)) +
                           (extra_header.empty() ? "" : "," + extra_header),
                         rows);
    }

    template class ContactSamples<2>;
    template class ContactSamples<3>;
  } // namespace Contact
} // namespace Signorini
