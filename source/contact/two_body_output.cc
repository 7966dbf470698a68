#include <signorini/archive_io.h>
#include <signorini/contact/two_body.h>
#include <signorini/input_error.h>

#include <deal.II/base/geometry_info.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/rtree.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>

// TwoBodyContact: what a state with its nodal forces reports (node
// samples, penetration, profile CSV with body 2's side, summary.json block).

namespace Signorini
{
  namespace Contact
  {
    template <int dim>
    std::vector<double>
    TwoBodyContact<dim>::node_pressures(const std::vector<double> &forces) const
    {
      std::vector<double> p(nodes().size(), 0.);
      for (unsigned int k = 0; k < nodes().size(); ++k)
        {
          Tensor<1, dim> f;
          for (unsigned int d = 0; d < dim; ++d)
            f[d] = forces[k * dim + d];
          p[k] = f.norm() / nodes()[k].weight;
        }
      return p;
    }

    template <int dim>
    typename TwoBodyContact<dim>::PenetrationRatios
    TwoBodyContact<dim>::penetration_ratios(const VectorType &u) const
    {
      const MPI_Comm comm  = dof_handler.get_communicator();
      const auto     faces = current_faces(u);
      double         gauss_ratio = 0.;
      if (prm.integral)
        {
          std::vector<Point<dim>> xg;
          for (const auto &p : points)
            xg.push_back(position(p, u));
          gauss_ratio = penetration_ratio(xg, points, faces);
        }
      const double node_ratio = penetration_ratio(node_positions(u), node_points, faces);
      return {Utilities::MPI::max(std::max(node_ratio, gauss_ratio), comm),
              Utilities::MPI::max(prm.integral ? gauss_ratio : node_ratio, comm)};
    }

    template <int dim>
    typename PenaltyTerm<dim>::Measure
    TwoBodyContact<dim>::measure(const VectorType          &u,
                                 const std::vector<double> &forces) const
    {
      return {penetration_ratios(u).penalised, this->n_active(u, forces)};
    }

    template <int dim>
    std::vector<typename Model<dim>::NodeSample>
    TwoBodyContact<dim>::node_samples(const VectorType          &u,
                                      const std::vector<double> &forces) const
    {
      const auto          pressures = node_pressures(forces);
      const auto          x         = node_positions(u);
      std::vector<double> depths;
      penetration_ratio(x, node_points, current_faces(u), &depths);
      std::vector<typename Model<dim>::NodeSample> samples;
      for (unsigned int k = 0; k < nodes().size(); ++k)
        {
          typename Model<dim>::NodeSample sample;
          sample.X        = nodes()[k].X;
          sample.x        = x[k];
          sample.gaps     = {depths[k]};
          sample.pressure = pressures[k];
          for (unsigned int d = 0; d < dim; ++d)
            sample.force[d] = forces[k * dim + d];
          sample.weight = nodes()[k].weight;
          samples.push_back(sample);
        }
      return samples;
    }

    template <int dim>
    void
    TwoBodyContact<dim>::write_profile(
      const std::string                                  &file,
      const VectorType                                   &u,
      const std::vector<double>                          &forces,
      const std::vector<typename Model<dim>::NodeSample> &samples,
      const std::function<double(const Point<dim> &)>    &reference_pressure,
      const std::string                                  &extra_header) const
    {
      ContactSamples<dim>::write_profile(file, u, forces, samples, reference_pressure,
                                         extra_header);
      // Body 2's side beside it: NAME_target.csv.
      const auto dot = file.rfind(".csv");
      write_target_profile((dot == std::string::npos ? file : file.substr(0, dot)) +
                             "_target.csv",
                           u, forces);
    }

    template <int dim>
    void
    TwoBodyContact<dim>::write_target_profile(const std::string         &file,
                                              const VectorType          &u,
                                              const std::vector<double> &forces) const
    {
      const MPI_Comm                   comm = dof_handler.get_communicator();
      const std::size_t                n1   = nodes().size();
      std::vector<std::vector<double>> rows;
      target_force        = Tensor<1, dim>();
      target_max_pressure = 0.;
      for (unsigned int k = 0; k < target.nodes().size(); ++k)
        {
          const auto    &n = target.nodes()[k];
          Tensor<1, dim> f;
          if ((n1 + k + 1) * dim <= forces.size())
            for (unsigned int d = 0; d < dim; ++d)
              f[d] = forces[(n1 + k) * dim + d];
          const double pressure = f.norm() / n.weight;
          target_force += f;
          target_max_pressure = std::max(target_max_pressure, pressure);
          std::vector<double> row;
          for (unsigned int d = 0; d < dim; ++d)
            row.push_back(n.X[d]);
          for (unsigned int d = 0; d < dim; ++d)
            row.push_back(n.X[d] + u[n.dofs[d]]);
          row.push_back(pressure);
          for (unsigned int d = 0; d < dim; ++d)
            row.push_back(f[d]);
          row.push_back(n.weight);
          rows.push_back(row);
        }
      for (unsigned int d = 0; d < dim; ++d)
        target_force[d] = Utilities::MPI::sum(target_force[d], comm);
      target_max_pressure = Utilities::MPI::max(target_max_pressure, comm);
      target.write_csv(file, BoundaryNodes<dim>::profile_header("pressure", false), rows);
    }

    template <int dim>
    void
    TwoBodyContact<dim>::check_initial_state(const VectorType &u) const
    {
      if (!admissible(u))
        throw InputError("Body 2 > Geometry",
                         "at the start, a point of body 1's contact boundary "
                         "(Contact > Contact boundary id) lies inside body 2 "
                         "deeper than the layer in which the indicator "
                         "function of its surface acts: move the bodies "
                         "apart (a penetration within that layer is "
                         "allowed)");
    }

    template <int dim>
    void
    TwoBodyContact<dim>::write_summary(Json &c) const
    {
      this->write_common_summary(c, "target");
      c["target boundary id"] = static_cast<unsigned int>(prm.target_boundary);
      c["form"]               = prm.integral ? "integral" : "nodal";
      if (prm.integral)
        c["gauss points per face"] = prm.gauss_points;
      c["stretch"]           = prm.stretch;
      c["indicator shape"] =
        prm.shape == IndicatorShape::partition ? "partition" : "simplex";
      if (all_bodies)
        {
          Json ids = Json::array();
          for (const auto id : contact_ids)
            ids.push_back(static_cast<unsigned int>(id));
          c["all bodies"] = ids; // every body's boundaries against the others'
        }
      else if (self)
        {
          // The target side is the contact side itself.
          Json &sc = c["self contact"];
          sc["exclusion radius"]                  = exclusion_radius_;
          sc["skipped faces per evaluation point"] = skipped_per_point;
        }
      else
      {
        // Body 2's side, from the reaction of the penalty term on its
        // target nodes (at the last profile written).
        Json &t = c["target side"];
        t["nodes"] = target.n_global();
        Json force = Json::array();
        for (unsigned int d = 0; d < dim; ++d)
          force.push_back(target_force[d]);
        t["reaction on the target nodes"] = force;
        t["max pressure"]                 = target_max_pressure;
      }
      c["apex depth"]        = prm.apex_depth;
      Json &b                = c["broad phase"];
      b["target faces"]      = stats.target_faces;
      b["evaluation points"] = stats.points;
      b["evaluated pairs, last evaluation"] = stats.last_pairs;
      b["evaluated pairs, largest"]         = stats.max_pairs;
      b["pairs in the sparsity pattern"]    = stats.pattern_pairs;
      b["sparsity pattern builds"]          = stats.pattern_builds;
      b["search wall time [s]"]             = stats.search_seconds;
    }

    // Instantiations of the member functions defined in this file.
    template std::vector<double> TwoBodyContact<2>::node_pressures(const std::vector<double> &forces) const;
    template std::vector<double> TwoBodyContact<3>::node_pressures(const std::vector<double> &forces) const;
    template typename TwoBodyContact<2>::PenetrationRatios TwoBodyContact<2>::penetration_ratios(const VectorType &) const;
    template typename TwoBodyContact<3>::PenetrationRatios TwoBodyContact<3>::penetration_ratios(const VectorType &) const;
    template typename PenaltyTerm<2>::Measure TwoBodyContact<2>::measure(const VectorType &u, const std::vector<double> &forces) const;
    template typename PenaltyTerm<3>::Measure TwoBodyContact<3>::measure(const VectorType &u, const std::vector<double> &forces) const;
    template std::vector<typename Model<2>::NodeSample> TwoBodyContact<2>::node_samples(const VectorType &, const std::vector<double> &) const;
    template std::vector<typename Model<3>::NodeSample> TwoBodyContact<3>::node_samples(const VectorType &, const std::vector<double> &) const;
    template void TwoBodyContact<2>::write_profile( const std::string &file, const VectorType &u, const std::vector<double> &forces, const std::vector<typename Model<2>::NodeSample> &samples, const std::function<double(const Point<2> &)> &reference_pressure, const std::string &extra_header) const;
    template void TwoBodyContact<3>::write_profile( const std::string &file, const VectorType &u, const std::vector<double> &forces, const std::vector<typename Model<3>::NodeSample> &samples, const std::function<double(const Point<3> &)> &reference_pressure, const std::string &extra_header) const;
    template void TwoBodyContact<2>::write_target_profile(const std::string &, const VectorType &, const std::vector<double> &) const;
    template void TwoBodyContact<3>::write_target_profile(const std::string &, const VectorType &, const std::vector<double> &) const;
    template void TwoBodyContact<2>::check_initial_state(const VectorType &u) const;
    template void TwoBodyContact<3>::check_initial_state(const VectorType &u) const;
    template <int dim>
    void
    TwoBodyContact<dim>::save_state(OutputArchive &archive, MeshState &mesh) const
    {
      Model<dim>::save_state(archive, mesh);
      archive << stats.last_pairs << stats.max_pairs << stats.pattern_pairs
              << stats.pattern_builds;
    }

    template <int dim>
    void
    TwoBodyContact<dim>::load_state(InputArchive &archive, MeshState &mesh)
    {
      Model<dim>::load_state(archive, mesh);
      archive >> stats.last_pairs >> stats.max_pairs >> stats.pattern_pairs >>
        stats.pattern_builds;
    }

    template <int dim>
    std::vector<types::global_dof_index>
    TwoBodyContact<dim>::force_dofs() const
    {
      std::vector<types::global_dof_index> dofs;
      for (const auto *list : {&boundary, &target})
        for (const auto &node : list->nodes())
          for (unsigned int d = 0; d < dim; ++d)
            dofs.push_back(node.dofs[d]);
      return dofs;
    }

    template void TwoBodyContact<2>::save_state(OutputArchive &, MeshState &) const;
    template void TwoBodyContact<3>::save_state(OutputArchive &, MeshState &) const;
    template void TwoBodyContact<2>::load_state(InputArchive &, MeshState &);
    template void TwoBodyContact<3>::load_state(InputArchive &, MeshState &);
    template std::vector<types::global_dof_index> TwoBodyContact<2>::force_dofs() const;
    template std::vector<types::global_dof_index> TwoBodyContact<3>::force_dofs() const;
    template void TwoBodyContact<2>::write_summary(Json &c) const;
    template void TwoBodyContact<3>::write_summary(Json &c) const;
  } // namespace Contact
} // namespace Signorini
