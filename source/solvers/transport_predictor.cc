#include <signorini/input_error.h>
#include <signorini/solvers/transport_predictor.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/mpi_remote_point_evaluation.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/numerics/vector_tools_evaluate.h>

#include <set>
#include <string>
#include <utility>
#include <vector>

namespace Signorini
{
  template <int dim>
  TransportPredictor<dim>::TransportPredictor(const Tensor<1, dim> &e)
    : direction(e / e.norm())
  {
    AssertThrow(e.norm() > 0., ExcMessage("The sliding direction is zero."));
  }

  template <int dim>
  typename TransportPredictor<dim>::Result
  TransportPredictor<dim>::apply(Scene<dim> &scene, const double time) const
  {
    Result                     result;
    const FiniteElement<dim>  &fe    = *scene.fe;
    const IndexSet            &owned = scene.locally_owned;
    const MPI_Comm             comm  = scene.comm;
    VectorType                &u     = scene.solution;
    scene.solution_ghosted           = u;
    const VectorType &previous       = scene.solution_ghosted;

    // The step's prescribed increment: per component, the mean of (new
    // value - current value) over the owned DoFs of the prescribed
    // boundaries; and the bodies those boundaries belong to.
    std::set<types::boundary_id> prescribed;
    for (const auto &part : scene.bc.dirichlet_parts())
      if (part.prescribed)
        prescribed.insert(part.boundary_id);
    const AffineConstraints<double> target = scene.boundary_constraints(time, false);
    std::vector<double>                  sums(2 * dim, 0.); // sums, then counts
    std::vector<bool>                    counted(owned.n_elements(), false);
    std::set<unsigned int>               sliders;
    std::vector<types::global_dof_index> face_dofs(fe.n_dofs_per_face());
    for (const auto &cell : scene.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary() && prescribed.count(face->boundary_id()) > 0)
            {
              sliders.insert(cell->material_id());
              face->get_dof_indices(face_dofs);
              for (unsigned int i = 0; i < face_dofs.size(); ++i)
                {
                  const types::global_dof_index dof = face_dofs[i];
                  // A Dirichlet line has no entries (a hanging node's has).
                  const auto *entries = target.get_constraint_entries(dof);
                  if (!owned.is_element(dof) || entries == nullptr ||
                      !entries->empty() || counted[owned.index_within_set(dof)])
                    continue;
                  counted[owned.index_within_set(dof)] = true;
                  const unsigned int c = fe.face_system_to_component_index(i).first;
                  sums[c] += target.get_inhomogeneity(dof) - previous[dof];
                  sums[dim + c] += 1.;
                }
            }
    sliders = Utilities::MPI::compute_set_union(sliders, comm);
    if (sliders.size() > 1)
      {
        std::string ids;
        for (const unsigned int id : sliders)
          ids += (ids.empty() ? "" : ", ") + std::to_string(id);
        throw InputError("Load stepping > Sliding direction",
                         "the prescribed displacements move boundaries of "
                         "several bodies (material ids " +
                           ids + "); steady sliding needs one slider");
      }
    if (sliders.empty())
      return result;
    Utilities::MPI::sum(sums, comm, sums);
    Tensor<1, dim> increment;
    for (unsigned int c = 0; c < dim; ++c)
      if (sums[dim + c] > 0.)
        increment[c] = sums[c] / sums[dim + c];
    const Tensor<1, dim> d = (increment * direction) * direction;
    if (!(d.norm() > 1e-12 * scene.size))
      return result;
    result.shift                       = d;
    const types::material_id slider    = *sliders.begin();

    // Each body's material id as a field (every DoF of a body carries it):
    // its interpolant at X - d tells which body X - d lies in.
    VectorType body(owned, comm);
    std::vector<types::global_dof_index> cell_dofs(fe.n_dofs_per_cell());
    for (const auto &cell : scene.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(cell_dofs);
          for (const auto dof : cell_dofs)
            if (owned.is_element(dof))
              body[dof] = cell->material_id();
        }
    body.compress(VectorOperation::insert);
    VectorType body_ghosted(owned, scene.locally_relevant, comm);
    body_ghosted = body;

    // The slider's DoFs shift by d; the other bodies' nodes ask for the
    // previous field at X - d (one point per node).
    std::vector<std::pair<types::global_dof_index, double>> values;
    struct Node
    {
      types::global_dof_index dofs[dim];
      types::material_id      body;
    };
    std::vector<Node>       nodes;
    std::vector<Point<dim>> points;
    std::vector<bool>       done(owned.n_elements(), false);
    const Quadrature<dim>   support(fe.get_unit_support_points());
    FEValues<dim> fe_values(*scene.mapping, fe, support, update_quadrature_points);
    for (const auto &cell : scene.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          cell->get_dof_indices(cell_dofs);
          for (unsigned int i = 0; i < cell_dofs.size(); ++i)
            {
              const auto [component, node] = fe.system_to_component_index(i);
              const types::global_dof_index dof = cell_dofs[i];
              if (component != 0 || !owned.is_element(dof) ||
                  done[owned.index_within_set(dof)])
                continue;
              Node n{{}, cell->material_id()};
              for (unsigned int c = 0; c < dim; ++c)
                {
                  n.dofs[c] = cell_dofs[fe.component_to_system_index(c, node)];
                  if (owned.is_element(n.dofs[c]))
                    done[owned.index_within_set(n.dofs[c])] = true;
                }
              if (n.body == slider)
                {
                  for (unsigned int c = 0; c < dim; ++c)
                    if (owned.is_element(n.dofs[c]))
                      values.emplace_back(n.dofs[c], previous[n.dofs[c]] + d[c]);
                }
              else
                {
                  // X - d, moved back by 1e-5 d: a shift by a whole number
                  // of cells puts every point on a vertex, for which deal.II
                  // 9.4 looks for the other cells around it among all
                  // cells (30 ms a step on prm/ironing.prm instead of 2.5).
                  nodes.push_back(n);
                  points.push_back(fe_values.quadrature_point(i) - (1. - 1e-5) * d);
                }
            }
        }
    // Reference-cell tolerance well below the 1e-5 d off the vertices.
    Utilities::MPI::RemotePointEvaluation<dim> evaluation(1e-8);
    const auto carried = VectorTools::point_values<dim>(
      *scene.mapping, scene.dof_handler, previous, points, evaluation);
    const auto found_in = VectorTools::point_values<dim>(evaluation,
                                                         scene.dof_handler,
                                                         body_ghosted);
    std::vector<types::global_dof_index> counts(2, 0);
    for (unsigned int k = 0; k < nodes.size(); ++k)
      {
        const bool inside = evaluation.point_found(k) &&
                            std::abs(found_in[k][0] - nodes[k].body) < 1e-6;
        ++counts[inside ? 0 : 1];
        if (inside)
          for (unsigned int c = 0; c < dim; ++c)
            if (owned.is_element(nodes[k].dofs[c]))
              values.emplace_back(nodes[k].dofs[c], carried[k][c]);
      }
    Utilities::MPI::sum(counts, comm, counts);
    result.carried = counts[0];
    result.kept    = counts[1];

    // Only insertions (a Trilinos vector written with both += and = would
    // compress the additions on the ranks that made some).
    for (const auto &[dof, value] : values)
      u[dof] = value;
    u.compress(VectorOperation::insert);
    scene.hanging_constraints.distribute(u);
    scene.solution_ghosted = u;
    return result;
  }

  template class TransportPredictor<2>;
  template class TransportPredictor<3>;
} // namespace Signorini
