#include <signorini/contact/boundary_nodes.h>
#include <signorini/output/atomic_file.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>

#include <algorithm>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace Signorini
{
  namespace Contact
  {
    template <int dim>
    BoundaryNodes<dim>::BoundaryNodes(const DoFHandler<dim> &dof_handler,
                                      const Mapping<dim>    &mapping)
      : dof_handler(dof_handler)
      , mapping(mapping)
    {}

    template <int dim>
    void
    BoundaryNodes<dim>::setup(const std::set<types::boundary_id> &boundary_ids,
                              const AffineConstraints<double>    &hanging_constraints)
    {
      ids                         = boundary_ids;
      const MPI_Comm     comm     = dof_handler.get_communicator();
      const auto        &fe       = dof_handler.get_fe();
      const IndexSet     owned    = dof_handler.locally_owned_dofs();
      const IndexSet     relevant = DoFTools::extract_locally_relevant_dofs(dof_handler);
      const unsigned int first    = 0; // the component that identifies a node
      auto on_contact = [&](const auto &cell, const unsigned int f) {
        return cell->face(f)->at_boundary() &&
               boundary_ids.count(cell->face(f)->boundary_id()) > 0;
      };

      scalar_fe = std::make_unique<FE_Q<dim>>(fe.degree);
      scalar_dof_handler.reinit(dof_handler.get_triangulation());
      scalar_dof_handler.distribute_dofs(*scalar_fe);
      scalar_hanging.clear();
      scalar_hanging.reinit(DoFTools::extract_locally_relevant_dofs(scalar_dof_handler));
      DoFTools::make_hanging_node_constraints(scalar_dof_handler, scalar_hanging);
      scalar_hanging.close();

      // Tributary weights and mean adjacent face size, summed over the
      // contact faces of the locally owned cells into the DoF owners.
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
            if (on_contact(cell, f))
              {
                fe_face.reinit(cell, f);
                cell->get_dof_indices(dofs);
                const double diameter = cell->face(f)->diameter();
                for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
                  if (fe.system_to_component_index(i).first == first &&
                      fe.has_support_on_face(i, f))
                    {
                      double w = 0.;
                      for (unsigned int q = 0; q < fe_face.n_quadrature_points; ++q)
                        w += fe_face.shape_value(i, q) * fe_face.JxW(q);
                      // A hanging node's share goes to the nodes it
                      // follows, with its constraint weights: the
                      // tributary weights of the contact nodes then still
                      // add up to the area of Gamma_C, and a node next to
                      // a refinement edge gets no pressure spike.
                      if (hanging_constraints.is_constrained(dofs[i]))
                        for (const auto &[parent, c] :
                             *hanging_constraints.get_constraint_entries(dofs[i]))
                          weight(parent) += c * w;
                      else
                        weight(dofs[i]) += w;
                      face_size(dofs[i]) += diameter;
                      face_count(dofs[i]) += 1.;
                    }
              }
      weight.compress(VectorOperation::add);
      face_size.compress(VectorOperation::add);
      face_count.compress(VectorOperation::add);

      // The nodes this rank owns, found from its owned and ghost cells
      // (the owner of a DoF may touch the boundary only through a ghost
      // cell).
      node_list.clear();
      std::set<types::global_dof_index> seen, hanging;
      const Quadrature<dim> support(fe.base_element(0).get_unit_support_points());
      FEValues<dim> fe_support(mapping, fe, support, update_quadrature_points);
      std::vector<types::global_dof_index> scalar_dofs(scalar_fe->n_dofs_per_cell());
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (!cell->is_artificial())
          for (const auto f : cell->face_indices())
            if (on_contact(cell, f))
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
                    if (ci.first != first || !fe.has_support_on_face(i, f))
                      continue;
                    const types::global_dof_index dof = dofs[i];
                    if (owned.is_element(dof) && hanging_constraints.is_constrained(dof))
                      hanging.insert(dof);
                    if (!owned.is_element(dof) || seen.count(dof) > 0 ||
                        hanging_constraints.is_constrained(dof))
                      continue;
                    seen.insert(dof);
                    if (!reinitialized)
                      {
                        fe_support.reinit(cell);
                        reinitialized = true;
                      }
                    BoundaryNode<dim> node;
                    for (unsigned int c = 0; c < dim; ++c)
                      node.dofs[c] = dofs[fe.component_to_system_index(c, ci.second)];
                    node.X      = fe_support.quadrature_point(ci.second);
                    node.weight = weight(dof);
                    node.h      = face_size(dof) /
                             std::max(static_cast<double>(face_count(dof)), 1.);
                    node.scalar_dof = scalar_dofs[ci.second];
                    node_list.push_back(node);
                  }
              }
      std::sort(node_list.begin(), node_list.end(),
                [](const auto &a, const auto &b) { return a.dofs[0] < b.dofs[0]; });
      n_global_nodes =
        Utilities::MPI::sum(static_cast<unsigned int>(node_list.size()), comm);
      n_hanging_nodes =
        Utilities::MPI::sum(static_cast<unsigned int>(hanging.size()), comm);
      double h_sum = 0., h_smallest = std::numeric_limits<double>::max();
      for (const auto &n : node_list)
        {
          h_sum += n.h;
          h_smallest = std::min(h_smallest, n.h);
        }
      h_sum  = Utilities::MPI::sum(h_sum, comm);
      mean_h = (n_global_nodes > 0 ? h_sum / n_global_nodes : 0.);
      min_h  = Utilities::MPI::min(h_smallest, comm);
    }

    template <int dim>
    void
    BoundaryNodes<dim>::add_fields(DataOut<dim>                           &data_out,
                                   const std::vector<std::string>          &names,
                                   const std::vector<std::vector<double>> &values) const
    {
      const MPI_Comm  comm     = dof_handler.get_communicator();
      const IndexSet &owned    = scalar_dof_handler.locally_owned_dofs();
      const IndexSet  relevant = DoFTools::extract_locally_relevant_dofs(scalar_dof_handler);
      for (unsigned int f = 0; f < names.size(); ++f)
        {
          VectorType field(owned, comm);
          for (unsigned int k = 0; k < node_list.size(); ++k)
            if (owned.is_element(node_list[k].scalar_dof))
              field(node_list[k].scalar_dof) = values[f][k];
          field.compress(VectorOperation::insert);
          VectorType &kept = fields[names[f]];
          kept.reinit(owned, relevant, comm);
          kept = field;
          data_out.add_data_vector(scalar_dof_handler, kept, names[f]);
        }
    }

    template <int dim>
    VectorType
    BoundaryNodes<dim>::nodal_field(const std::vector<double> &values) const
    {
      const MPI_Comm  comm     = dof_handler.get_communicator();
      const IndexSet &owned    = scalar_dof_handler.locally_owned_dofs();
      const IndexSet  relevant = DoFTools::extract_locally_relevant_dofs(scalar_dof_handler);
      VectorType      field(owned, comm);
      for (unsigned int k = 0; k < node_list.size(); ++k)
        if (owned.is_element(node_list[k].scalar_dof))
          field(node_list[k].scalar_dof) = values[k];
      field.compress(VectorOperation::insert);
      scalar_hanging.distribute(field);
      VectorType ghosted(owned, relevant, comm);
      ghosted = field;
      return ghosted;
    }

    template <int dim>
    void
    BoundaryNodes<dim>::write_csv(const std::string                      &file,
                                  const std::string                      &header,
                                  const std::vector<std::vector<double>> &rows) const
    {
      const MPI_Comm comm = dof_handler.get_communicator();
      const auto     all  = Utilities::MPI::gather(comm, rows, 0);
      if (Utilities::MPI::this_mpi_process(comm) != 0)
        return;
      std::vector<std::vector<double>> sorted;
      for (const auto &part : all)
        sorted.insert(sorted.end(), part.begin(), part.end());
      std::sort(sorted.begin(), sorted.end());
      AtomicFile    file_out(file);
      std::ostream &out = file_out.stream();
      out << header << "\n" << std::setprecision(10);
      for (const auto &row : sorted)
        {
          for (unsigned int i = 0; i < row.size(); ++i)
            out << (i ? "," : "") << row[i];
          out << "\n";
        }
      file_out.commit();
    }

    template <int dim>
    std::string
    BoundaryNodes<dim>::profile_header(const std::string &middle, const bool reference)
    {
      std::ostringstream header;
      const char        *axes = "xyz";
      for (unsigned int d = 0; d < dim; ++d)
        header << (d ? "," : "") << "X" << axes[d];
      for (unsigned int d = 0; d < dim; ++d)
        header << "," << axes[d];
      header << "," << middle;
      for (unsigned int d = 0; d < dim; ++d)
        header << ",force_" << axes[d];
      header << ",weight";
      if (reference)
        header << ",reference_pressure";
      return header.str();
    }

    template <int dim>
    std::vector<std::pair<Point<dim>, double>>
    BoundaryNodes<dim>::gather_sorted(
      const std::vector<std::pair<Point<dim>, double>> &local) const
    {
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

    template class BoundaryNodes<2>;
    template class BoundaryNodes<3>;
  } // namespace Contact
} // namespace Signorini
