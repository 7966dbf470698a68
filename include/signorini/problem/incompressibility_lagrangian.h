#pragma once

#include <signorini/problem/incompressibility.h>
#include <signorini/problem/objective.h>

#include <vector>

namespace Signorini
{
  /**
   * The augmented Lagrangian of the incompressibility constraints
   * c_K(U) = int_K (J - 1) dV = 0 (Incompressibility) added to an
   * objective:
   *
   *   L(U) = f(U) + sum_K [ y_K c_K(U) + rho_K / 2 c_K(U)^2 ],
   *
   * for fixed multipliers y_K and weights rho_K, one per constrained cell
   * of this rank (in the order of Incompressibility::cells()). Its
   * gradient adds (y_K + rho_K c_K) grad c_K, its Hessian
   * (y_K + rho_K c_K) hess c_K + rho_K grad c_K grad c_K^T: cell blocks,
   * so the sparsity pattern of the energy's Hessian holds them. A
   * minimiser without equality constraints of its own (the interior point
   * method) minimises L and updates y_K <- y_K + rho_K c_K until every
   * |c_K| is small (InteriorPointStep).
   */
  template <int dim>
  class IncompressibilityLagrangian : public Objective
  {
  public:
    IncompressibilityLagrangian(Objective                    &base,
                                const Incompressibility<dim> &incompressibility,
                                const std::vector<double>    &multipliers,
                                const std::vector<double>    &weights);

    Evaluation
    evaluate(const VectorType                &u,
             const AffineConstraints<double> &constraints,
             VectorType                      *rhs,
             MatrixType                      *hessian) override;

    double
    max_step(const VectorType &u, const VectorType &d) override
    {
      return base.max_step(u, d);
    }

  private:
    Objective                    &base;
    const Incompressibility<dim> &incompressibility;
    const std::vector<double>    &y;
    const std::vector<double>    &rho;
  };
} // namespace Signorini
