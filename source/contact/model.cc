#include <signorini/archive_io.h>
#include <signorini/contact/model.h>

#include <deal.II/base/mpi.h>

namespace Signorini
{
  namespace Contact
  {
    template <int dim>
    void
    Model<dim>::save_state(OutputArchive &archive, MeshState &mesh) const
    {
      (void)archive;
      mesh.save_dof_field(force_dofs(), nodal_forces);
    }

    template <int dim>
    void
    Model<dim>::load_state(InputArchive &archive, MeshState &mesh)
    {
      (void)archive;
      const auto dofs = force_dofs();
      AssertThrow(dofs.size() == nodal_forces.size(),
                  ExcMessage("the contact model's forces and their DoFs differ in size"));
      nodal_forces = mesh.load_dof_field(dofs);
    }

    namespace
    {
      /// 1e-6 of the largest of @p pressures on any rank: the pressure a
      /// node must exceed to count as active.
      double
      active_threshold(const std::vector<double> &pressures, const MPI_Comm comm)
      {
        double largest = 0.;
        for (const double p : pressures)
          largest = std::max(largest, p);
        return 1e-6 * Utilities::MPI::max(largest, comm);
      }

      template <typename Sample>
      std::vector<double>
      pressures_of(const std::vector<Sample> &samples)
      {
        std::vector<double> p;
        for (const Sample &s : samples)
          p.push_back(s.pressure);
        return p;
      }

      /// Add the moment x x f (about the origin) of the force @p f at @p x
      /// to @p moment (2D: the z component only).
      template <int dim>
      void
      add_moment(Tensor<1, 3> &moment, const Point<dim> &x, const Tensor<1, dim> &f)
      {
        if constexpr (dim == 2)
          moment[2] += x[0] * f[1] - x[1] * f[0];
        else
          for (unsigned int i = 0; i < 3; ++i)
            moment[i] += x[(i + 1) % 3] * f[(i + 2) % dim] - x[(i + 2) % 3] * f[(i + 1) % dim];
      }
    } // namespace

    template <int dim>
    typename Model<dim>::StateSummary
    Model<dim>::summarize_state(const VectorType              &u,
                                const std::vector<NodeSample> &samples) const
    {
      const MPI_Comm comm      = this->contact_nodes_on_boundary().get_communicator();
      const double   threshold = active_threshold(pressures_of(samples), comm);
      StateSummary   s;
      s.n_nodes = n_global_nodes();
      for (const NodeSample &sample : samples)
        {
          s.total_force += sample.force;
          add_moment(s.moment, sample.x, sample.force);
          if (sample.pressure > threshold)
            {
              ++s.n_active;
              s.area += sample.weight;
              s.max_pressure = std::max(s.max_pressure, sample.pressure);
            }
        }
      s.n_active     = Utilities::MPI::sum(s.n_active, comm);
      s.max_pressure = Utilities::MPI::max(s.max_pressure, comm);
      s.area         = Utilities::MPI::sum(s.area, comm);
      for (unsigned int d = 0; d < dim; ++d)
        s.total_force[d] = Utilities::MPI::sum(s.total_force[d], comm);
      for (unsigned int i = 0; i < 3; ++i)
        s.moment[i] = Utilities::MPI::sum(s.moment[i], comm);
      s.max_penetration_ratio = max_penetration_ratio(u);
      if (const auto pairs = evaluated_pairs())
        {
          s.has_pairs = true;
          s.pairs     = *pairs;
        }
      return s;
    }

    template <int dim>
    unsigned int
    Model<dim>::n_active(const VectorType &u, const std::vector<double> &forces) const
    {
      const MPI_Comm comm      = this->contact_nodes_on_boundary().get_communicator();
      const auto     pressures = this->nodal_pressures(u, forces);
      const double   threshold = active_threshold(pressures, comm);
      unsigned int   n         = 0;
      for (const double p : pressures)
        n += (p > threshold ? 1 : 0);
      return Utilities::MPI::sum(n, comm);
    }

    template <int dim>
    std::vector<std::pair<Point<dim>, double>>
    Model<dim>::gather_pressure(const std::vector<NodeSample> &samples) const
    {
      const auto  &boundary  = this->contact_nodes_on_boundary();
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
    Model<dim>::add_output_fields(DataOut<dim>              &data_out,
                                  const VectorType          &u,
                                  const std::vector<double> &forces) const
    {
      const auto  &boundary  = this->contact_nodes_on_boundary();
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
    Model<dim>::write_profile(const std::string &file,
                              const VectorType &,
                              const std::vector<double> &,
                              const std::vector<NodeSample>                   &samples,
                              const std::function<double(const Point<dim> &)> &reference) const
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
