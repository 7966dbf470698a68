#include <signorini/problem/incompressibility_lagrangian.h>

#include <deal.II/base/mpi.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <cmath>

namespace Signorini
{
  template <int dim>
  IncompressibilityLagrangian<dim>::IncompressibilityLagrangian(
    Objective                    &base,
    const Incompressibility<dim> &incompressibility,
    const std::vector<double>    &multipliers,
    const std::vector<double>    &weights)
    : base(base)
    , incompressibility(incompressibility)
    , y(multipliers)
    , rho(weights)
  {
    AssertThrow(y.size() == incompressibility.cells().size() &&
                  rho.size() == y.size(),
                ExcMessage("one multiplier and one weight per constrained cell"));
  }

  template <int dim>
  Evaluation
  IncompressibilityLagrangian<dim>::evaluate(const VectorType                &u,
                                             const AffineConstraints<double> &constraints,
                                             VectorType                      *rhs,
                                             MatrixType                      *hessian)
  {
    Evaluation e = base.evaluate(u, constraints, rhs, hessian);
    if (!e.admissible)
      return e;
    const auto        &cells = incompressibility.cells();
    Vector<double>     gradient;
    FullMatrix<double> matrix;
    std::vector<types::global_dof_index> dofs;
    double             added = 0.;
    for (unsigned int k = 0; k < cells.size(); ++k)
      {
        const double c =
          incompressibility.evaluate(cells[k], u, rhs ? &gradient : nullptr,
                                     hessian ? &matrix : nullptr, 1.);
        const double lambda = y[k] + rho[k] * c;
        added += y[k] * c + 0.5 * rho[k] * c * c;
        if (!rhs)
          continue;
        dofs.resize(gradient.size());
        cells[k]->get_dof_indices(dofs);
        if (hessian)
          {
            // (y + rho c) hess c (in matrix, factor 1) + rho grad c grad c^T
            for (unsigned int i = 0; i < gradient.size(); ++i)
              for (unsigned int j = 0; j < gradient.size(); ++j)
                matrix(i, j) = lambda * matrix(i, j) + rho[k] * gradient(i) * gradient(j);
          }
        gradient *= -lambda; // rhs holds minus the gradient
        if (hessian)
          constraints.distribute_local_to_global(matrix, gradient, dofs, *hessian, *rhs);
        else
          constraints.distribute_local_to_global(gradient, dofs, *rhs);
      }
    const MPI_Comm comm = u.get_mpi_communicator();
    added               = Utilities::MPI::sum(added, comm);
    e.value += added;
    e.strain_energy += added;
    if (!std::isfinite(e.value))
      e.admissible = false;
    if (rhs)
      rhs->compress(VectorOperation::add);
    if (hessian)
      hessian->compress(VectorOperation::add);
    return e;
  }

  template class IncompressibilityLagrangian<2>;
  template class IncompressibilityLagrangian<3>;
} // namespace Signorini
