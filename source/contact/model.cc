#include <signorini/contact/model.h>

#include <deal.II/base/mpi.h>

namespace Signorini
{
  namespace Contact
  {
    namespace
    {
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
      const auto     pressures = samples().nodal_pressures(u, forces);
      const double   threshold = active_threshold(pressures, comm);
      unsigned int   n         = 0;
      for (const double p : pressures)
        n += (p > threshold ? 1 : 0);
      return Utilities::MPI::sum(n, comm);
    }

    template class Model<2>;
    template class Model<3>;
  } // namespace Contact
} // namespace Signorini
