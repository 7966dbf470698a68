#include <signorini/contact/rigid_foundation.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <fstream>
#include <iomanip>
#include <set>

namespace Signorini
{
  namespace Contact
  {
    template <int dim>
    RigidFoundation<dim>::RigidFoundation(
      std::unique_ptr<Foundation<dim>> foundation,
      const types::boundary_id          boundary_id,
      const DoFHandler<dim>            &dof_handler,
      const Mapping<dim>               &mapping)
      : surface(std::move(foundation))
      , contact_boundary(boundary_id)
      , dof_handler(dof_handler)
      , mapping(mapping)
    {}

    template <int dim>
    void
    RigidFoundation<dim>::setup(const AffineConstraints<double> &hanging_constraints)
    {
      const MPI_Comm   comm = dof_handler.get_communicator();
      const auto      &fe   = dof_handler.get_fe();
      const IndexSet   owned = dof_handler.locally_owned_dofs();
      const IndexSet   relevant = DoFTools::extract_locally_relevant_dofs(dof_handler);
      const unsigned int vertical = dim - 1;

      scalar_fe = std::make_unique<FE_Q<dim>>(fe.degree);
      scalar_dof_handler.reinit(dof_handler.get_triangulation());
      scalar_dof_handler.distribute_dofs(*scalar_fe);
      const IndexSet scalar_owned = scalar_dof_handler.locally_owned_dofs();
      const IndexSet scalar_relevant =
        DoFTools::extract_locally_relevant_dofs(scalar_dof_handler);
      pressure_field.reinit(scalar_owned, scalar_relevant, comm);
      gap_field.reinit(scalar_owned, scalar_relevant, comm);
      active_field.reinit(scalar_owned, scalar_relevant, comm);

      // Tributary weights and mean adjacent face size, summed over the
      // Gamma_2 faces of the locally owned cells into the DoF owners.
      VectorType weight, face_size, face_count;
      weight.reinit(owned, relevant, comm, true);
      face_size.reinit(owned, relevant, comm, true);
      face_count.reinit(owned, relevant, comm, true);
      FEFaceValues<dim> fe_face(mapping, fe, QGauss<dim - 1>(fe.degree + 1),
                                update_values | update_JxW_values);
      std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const auto f : cell->face_indices())
            if (cell->face(f)->at_boundary() &&
                cell->face(f)->boundary_id() == contact_boundary)
              {
                fe_face.reinit(cell, f);
                cell->get_dof_indices(dofs);
                const double diameter = cell->face(f)->diameter();
                for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
                  if (fe.system_to_component_index(i).first == vertical &&
                      fe.has_support_on_face(i, f))
                    {
                      double w = 0.;
                      for (unsigned int q = 0; q < fe_face.n_quadrature_points; ++q)
                        w += fe_face.shape_value(i, q) * fe_face.JxW(q);
                      weight(dofs[i]) += w;
                      face_size(dofs[i]) += diameter;
                      face_count(dofs[i]) += 1.;
                    }
              }
      weight.compress(VectorOperation::add);
      face_size.compress(VectorOperation::add);
      face_count.compress(VectorOperation::add);

      // The nodes this rank owns, found from its owned and ghost cells
      // (the owner of a DoF may touch Gamma_2 only through a ghost cell).
      contact_nodes.clear();
      std::set<types::global_dof_index> seen;
      const Quadrature<dim> support(fe.base_element(0).get_unit_support_points());
      FEValues<dim> fe_support(mapping, fe, support, update_quadrature_points);
      std::vector<types::global_dof_index> scalar_dofs(scalar_fe->n_dofs_per_cell());
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (!cell->is_artificial())
          for (const auto f : cell->face_indices())
            if (cell->face(f)->at_boundary() &&
                cell->face(f)->boundary_id() == contact_boundary)
              {
                cell->get_dof_indices(dofs);
                const typename DoFHandler<dim>::active_cell_iterator scalar_cell(
                  &dof_handler.get_triangulation(), cell->level(), cell->index(),
                  &scalar_dof_handler);
                scalar_cell->get_dof_indices(scalar_dofs);
                bool reinitialized = false;
                for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
                  {
                    const auto ci = fe.system_to_component_index(i);
                    if (ci.first != vertical || !fe.has_support_on_face(i, f))
                      continue;
                    const types::global_dof_index dof = dofs[i];
                    if (!owned.is_element(dof) || seen.count(dof) > 0 ||
                        hanging_constraints.is_constrained(dof))
                      continue;
                    seen.insert(dof);
                    if (!reinitialized)
                      {
                        fe_support.reinit(cell);
                        reinitialized = true;
                      }
                    Node node;
                    for (unsigned int c = 0; c < dim; ++c)
                      node.dofs[c] = dofs[fe.component_to_system_index(c, ci.second)];
                    node.X          = fe_support.quadrature_point(ci.second);
                    node.weight     = weight(dof);
                    node.h          = face_size(dof) / std::max(static_cast<double>(face_count(dof)), 1.);
                    node.scalar_dof = scalar_dofs[ci.second];
                    contact_nodes.push_back(node);
                  }
              }
      std::sort(contact_nodes.begin(), contact_nodes.end(),
                [](const Node &a, const Node &b) { return a.dofs[0] < b.dofs[0]; });
      n_global = Utilities::MPI::sum(static_cast<unsigned int>(contact_nodes.size()), comm);
      double h_sum = 0., h_min = std::numeric_limits<double>::max();
      for (const auto &n : contact_nodes)
        {
          h_sum += n.h;
          h_min = std::min(h_min, n.h);
        }
      h_sum    = Utilities::MPI::sum(h_sum, comm);
      mean_h   = (n_global > 0 ? h_sum / n_global : 0.);
      min_h    = Utilities::MPI::min(h_min, comm);
    }

    template <int dim>
    typename RigidFoundation<dim>::State
    RigidFoundation<dim>::evaluate(const Node &node, const VectorType &u) const
    {
      State s;
      for (unsigned int c = 0; c < dim; ++c)
        s.x[c] = node.X[c] + u[node.dofs[c]];
      const auto psi = surface->evaluate(s.x);
      s.g            = s.x[dim - 1] - psi.psi;
      s.grad         = -psi.gradient;
      s.grad[dim - 1] += 1.;
      s.hess = -psi.hessian;
      return s;
    }

    template <int dim>
    double
    RigidFoundation<dim>::add_penalty(const VectorType                &u,
                                      const double                     mu,
                                      const AffineConstraints<double> &constraints,
                                      VectorType                      *rhs,
                                      MatrixType                      *hessian,
                                      std::vector<double>             *forces) const
    {
      double                               value = 0.;
      FullMatrix<double>                   local_matrix(dim, dim);
      Vector<double>                       local_rhs(dim);
      std::vector<types::global_dof_index> dofs(dim);
      if (forces)
        forces->assign(contact_nodes.size(), 0.);
      for (unsigned int k = 0; k < contact_nodes.size(); ++k)
        {
          const Node  &node = contact_nodes[k];
          const State  s    = evaluate(node, u);
          if (s.g >= 0.)
            continue;
          const double p = -s.g;
          value += mu / 3. * node.weight * p * p * p;
          if (forces)
            (*forces)[k] = mu * node.weight * p * p;
          if (!rhs && !hessian)
            continue;
          for (unsigned int i = 0; i < dim; ++i)
            {
              dofs[i]      = node.dofs[i];
              // minus the gradient -mu w p^2 grad g
              local_rhs(i) = mu * node.weight * p * p * s.grad[i];
              for (unsigned int j = 0; j < dim; ++j)
                local_matrix(i, j) =
                  mu * node.weight * (2. * p * s.grad[i] * s.grad[j] - p * p * s.hess[i][j]);
            }
          if (rhs && hessian)
            constraints.distribute_local_to_global(local_matrix, local_rhs, dofs,
                                                   *hessian, *rhs);
          else if (rhs)
            constraints.distribute_local_to_global(local_rhs, dofs, *rhs);
          else
            constraints.distribute_local_to_global(local_matrix, dofs, *hessian);
        }
      if (rhs)
        rhs->compress(VectorOperation::add);
      if (hessian)
        hessian->compress(VectorOperation::add);
      return Utilities::MPI::sum(value, dof_handler.get_communicator());
    }

    template <int dim>
    double
    RigidFoundation<dim>::active_threshold(const std::vector<double> &forces) const
    {
      double largest = 0.;
      for (const double f : forces)
        largest = std::max(largest, f);
      return 1e-6 * Utilities::MPI::max(largest, dof_handler.get_communicator());
    }

    template <int dim>
    typename RigidFoundation<dim>::Summary
    RigidFoundation<dim>::summarize(const VectorType          &u,
                                    const std::vector<double> &forces) const
    {
      const MPI_Comm comm = dof_handler.get_communicator();
      Summary        summary;
      summary.n_nodes        = n_global;
      const double threshold = active_threshold(forces);
      for (unsigned int k = 0; k < contact_nodes.size(); ++k)
        {
          const State s = evaluate(contact_nodes[k], u);
          summary.max_penetration = std::max(summary.max_penetration, s.penetration());
          summary.max_penetration_ratio =
            std::max(summary.max_penetration_ratio, s.penetration() / contact_nodes[k].h);
          summary.total_force += forces[k] * s.grad;
          if (forces[k] > threshold)
            {
              ++summary.n_active;
              summary.max_pressure =
                std::max(summary.max_pressure,
                         pressure(contact_nodes[k], s, forces[k]));
            }
        }
      summary.n_active        = Utilities::MPI::sum(summary.n_active, comm);
      summary.max_penetration = Utilities::MPI::max(summary.max_penetration, comm);
      summary.max_penetration_ratio =
        Utilities::MPI::max(summary.max_penetration_ratio, comm);
      summary.max_pressure = Utilities::MPI::max(summary.max_pressure, comm);
      for (unsigned int d = 0; d < dim; ++d)
        summary.total_force[d] = Utilities::MPI::sum(summary.total_force[d], comm);
      return summary;
    }

    template <int dim>
    std::vector<std::pair<Point<dim>, double>>
    RigidFoundation<dim>::gather_pressure(const VectorType          &u,
                                          const std::vector<double> &forces) const
    {
      std::vector<std::pair<Point<dim>, double>> local;
      const double threshold = active_threshold(forces);
      for (unsigned int k = 0; k < contact_nodes.size(); ++k)
        if (forces[k] > threshold)
          {
            const State s = evaluate(contact_nodes[k], u);
            local.emplace_back(s.x, pressure(contact_nodes[k], s, forces[k]));
          }
      std::vector<std::pair<Point<dim>, double>> all;
      for (const auto &part :
           Utilities::MPI::all_gather(dof_handler.get_communicator(), local))
        all.insert(all.end(), part.begin(), part.end());
      std::sort(all.begin(), all.end(), [](const auto &a, const auto &b) {
        for (unsigned int d = 0; d < dim; ++d)
          if (a.first[d] != b.first[d])
            return a.first[d] < b.first[d];
        return false;
      });
      return all;
    }

    template <int dim>
    void
    RigidFoundation<dim>::write_profile(
      const std::string                               &file,
      const VectorType                                &u,
      const std::vector<double>                       &forces,
      const std::function<double(const Point<dim> &)> &reference_pressure) const
    {
      // One row per node: X, x, gap, penetration/h, pressure, force
      // vector, tributary weight.
      std::vector<std::vector<double>> rows;
      for (unsigned int k = 0; k < contact_nodes.size(); ++k)
        {
          const Node  &n = contact_nodes[k];
          const State  s = evaluate(n, u);
          std::vector<double> row;
          for (unsigned int d = 0; d < dim; ++d)
            row.push_back(n.X[d]);
          for (unsigned int d = 0; d < dim; ++d)
            row.push_back(s.x[d]);
          row.push_back(s.g / s.grad.norm());
          row.push_back(s.penetration() / n.h);
          row.push_back(pressure(n, s, forces[k]));
          for (unsigned int d = 0; d < dim; ++d)
            row.push_back(forces[k] * s.grad[d]);
          row.push_back(n.weight);
          if (reference_pressure)
            row.push_back(reference_pressure(s.x));
          rows.push_back(row);
        }
      const MPI_Comm comm = dof_handler.get_communicator();
      const auto     all  = Utilities::MPI::gather(comm, rows, 0);
      if (Utilities::MPI::this_mpi_process(comm) != 0)
        return;
      std::vector<std::vector<double>> sorted;
      for (const auto &part : all)
        sorted.insert(sorted.end(), part.begin(), part.end());
      std::sort(sorted.begin(), sorted.end());
      std::ofstream out(file);
      const char   *axes = "xyz";
      for (unsigned int d = 0; d < dim; ++d)
        out << (d ? "," : "") << "X" << axes[d];
      for (unsigned int d = 0; d < dim; ++d)
        out << "," << axes[d];
      out << ",gap,penetration_over_h,pressure";
      for (unsigned int d = 0; d < dim; ++d)
        out << ",force_" << axes[d];
      out << ",weight";
      if (reference_pressure)
        out << ",reference_pressure";
      out << "\n" << std::setprecision(10);
      for (const auto &row : sorted)
        {
          for (unsigned int i = 0; i < row.size(); ++i)
            out << (i ? "," : "") << row[i];
          out << "\n";
        }
    }

    template <int dim>
    void
    RigidFoundation<dim>::add_output_fields(DataOut<dim>              &data_out,
                                            const VectorType          &u,
                                            const std::vector<double> &forces)
    {
      const MPI_Comm comm = dof_handler.get_communicator();
      VectorType     nodal_pressure(scalar_dof_handler.locally_owned_dofs(), comm);
      VectorType     gap(nodal_pressure), active(nodal_pressure);
      const double   threshold = active_threshold(forces);
      for (unsigned int k = 0; k < contact_nodes.size(); ++k)
        {
          const Node &n = contact_nodes[k];
          const State s = evaluate(n, u);
          if (scalar_dof_handler.locally_owned_dofs().is_element(n.scalar_dof))
            {
              nodal_pressure(n.scalar_dof) = pressure(n, s, forces[k]);
              gap(n.scalar_dof)      = s.g / s.grad.norm();
              active(n.scalar_dof)   = (forces[k] > threshold ? 1. : 0.);
            }
        }
      nodal_pressure.compress(VectorOperation::insert);
      gap.compress(VectorOperation::insert);
      active.compress(VectorOperation::insert);
      pressure_field = nodal_pressure;
      gap_field      = gap;
      active_field   = active;
      data_out.add_data_vector(scalar_dof_handler, pressure_field, "contact_pressure");
      data_out.add_data_vector(scalar_dof_handler, gap_field, "contact_gap");
      data_out.add_data_vector(scalar_dof_handler, active_field, "contact_active");
    }

    template class RigidFoundation<2>;
    template class RigidFoundation<3>;
  } // namespace Contact
} // namespace Signorini
