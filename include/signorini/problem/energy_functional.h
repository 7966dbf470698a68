#pragma once

#include <signorini/scene/boundary_conditions.h>
#include <signorini/material/interface.h>
#include <signorini/problem/cell_scatter.h>
#include <signorini/problem/objective.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>

#include <map>

namespace Signorini
{
  /**
   * The total potential energy of formulation.md (5),
   *
   *   E(u) = int_Omega psi(F) dV - int_Omega rho0 f . u dV
   *          - int_Gamma1 t . u dA,
   *
   * with dead loads, and its first and second derivatives with respect to
   * the nodal displacements, assembled in one pass over the locally owned
   * cells (MeshWorker::mesh_loop, threaded; MPI-parallel through Trilinos).
   * Each cell takes its material from its material id. Body force and
   * traction are integrated only when the scene declares them.
   */
  template <int dim>
  class EnergyFunctional
  {
  public:
    EnergyFunctional(
      const DoFHandler<dim>                                           &dof_handler,
      const Mapping<dim>                                              &mapping,
      const std::map<types::material_id, const Material::Interface *> &materials,
      const BoundaryConditions<dim>                                    &bc);

    /**
     * Evaluate at the ghosted displacement @p u and load time @p time.
     * If @p rhs is given it receives minus the gradient, and if
     * @p hessian is given it receives the Hessian, both condensed with
     * @p constraints (whose inhomogeneities, if any, are applied to the
     * right-hand side, so that H d = rhs with d from the constraints is
     * the Newton system). Vectors and matrix are zeroed first.
     */
    Evaluation
    evaluate(const VectorType                &u,
             const double                     time,
             const AffineConstraints<double> &constraints,
             VectorType                      *rhs,
             MatrixType                      *hessian) const;

  private:
    const DoFHandler<dim>                                           &dof_handler;
    const Mapping<dim>                                              &mapping;
    const std::map<types::material_id, const Material::Interface *> &materials;
    const BoundaryConditions<dim>                                    &bc;
    /// Positions of the cells' Hessian entries, kept between evaluations
    /// while the matrix's pattern stays the same.
    mutable CellScatter scatter;
  };
  /// The energy functional at a fixed load time, as an Objective (what a
  /// Newton or interior point minimiser sees when there is no penalty).
  template <int dim>
  class EnergyObjective : public Objective
  {
  public:
    EnergyObjective(const EnergyFunctional<dim> &energy, const double time)
      : energy(energy)
      , time(time)
    {}

    Evaluation
    evaluate(const VectorType                &u,
             const AffineConstraints<double> &constraints,
             VectorType                      *rhs,
             MatrixType                      *hessian) override
    {
      return energy.evaluate(u, time, constraints, rhs, hessian);
    }

  private:
    const EnergyFunctional<dim> &energy;
    const double                 time;
  };
} // namespace Signorini
