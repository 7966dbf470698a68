// Shared by the contact derivative tests: central-difference check of an
// assembled penalty term along one direction.
#pragma once

#include <signorini/contact/penalty.h>

#include <cmath>
#include <utility>

namespace Signorini
{
  /**
   * For the term mu P at the (locally owned) state @p u, with minus its
   * gradient @p rhs and the Hessian @p matrix assembled there: the relative
   * errors, along the direction @p v, of the directional derivative against
   * differences of the value, and of H v against differences of minus the
   * gradient (step @p h).
   */
  template <int dim>
  std::pair<double, double>
  penalty_fd_errors(const Contact::PenaltyTerm<dim>   &term,
                    const double                       mu,
                    const AffineConstraints<double>   &constraints,
                    const IndexSet                    &relevant,
                    const VectorType                  &u,
                    const VectorType                  &rhs,
                    const MatrixType                  &matrix,
                    const VectorType                  &v,
                    const double                       h = 1e-6)
  {
    const IndexSet owned = u.locally_owned_elements();
    const MPI_Comm comm  = u.get_mpi_communicator();
    auto evaluate = [&](const double step, VectorType &minus_gradient) {
      VectorType shifted(u);
      shifted.add(step, v);
      VectorType ghosted(owned, relevant, comm);
      ghosted = shifted;
      return term.add_penalty(ghosted, mu, constraints, &minus_gradient, nullptr);
    };
    VectorType   rp(owned, comm), rm(owned, comm);
    const double vp          = evaluate(h, rp);
    const double vm          = evaluate(-h, rm);
    const double directional = -(rhs * v);
    VectorType   Hv(owned, comm);
    matrix.vmult(Hv, v);
    VectorType fd(rm);
    fd.add(-1., rp);
    fd /= (2 * h);
    fd -= Hv;
    return std::make_pair(std::abs((vp - vm) / (2 * h) - directional) /
                            std::abs(directional),
                          fd.l2_norm() / Hv.l2_norm());
  }
} // namespace Signorini
