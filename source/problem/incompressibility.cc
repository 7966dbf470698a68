#include <signorini/problem/incompressibility.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe.h>
#include <deal.II/fe/fe_values_extractors.h>

namespace Signorini
{
  template <int dim>
  Incompressibility<dim>::Incompressibility(
    const DoFHandler<dim>              &dof_handler,
    const Mapping<dim>                 &mapping,
    const std::set<types::material_id> &materials)
    : dof_handler(dof_handler)
    , fe_values(mapping,
                dof_handler.get_fe(),
                QGauss<dim>(dof_handler.get_fe().degree + 1),
                update_gradients | update_JxW_values)
  {
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && materials.count(cell->material_id()) > 0)
        constrained_cells.push_back(cell);
  }

  template <int dim>
  double
  Incompressibility<dim>::evaluate(
    const typename DoFHandler<dim>::active_cell_iterator &cell,
    const VectorType                                     &u,
    Vector<double>                                       *gradient,
    FullMatrix<double>                                   *hessian,
    const double                                          factor) const
  {
    fe_values.reinit(cell);
    const FEValuesExtractors::Vector displacement(0);
    const FiniteElement<dim>        &fe     = fe_values.get_fe();
    const unsigned int               n_dofs = fe_values.dofs_per_cell;
    std::vector<Tensor<2, dim>>      grad_u(fe_values.n_quadrature_points);
    fe_values[displacement].get_function_gradients(u, grad_u);
    if (gradient)
      gradient->reinit(n_dofs);
    if (hessian)
      hessian->reinit(n_dofs, n_dofs);
    // Each shape function is primitive: A_i = e_c(i) (x) Grad phi_i, so
    // with G_i = F^-T Grad phi_i (the spatial gradient of phi_i),
    //   tr(F^-1 A_i)           = G_i[c(i)],
    //   tr(F^-1 A_j F^-1 A_i)  = G_i[c(j)] G_j[c(i)],
    // two products per pair instead of a tensor product.
    std::vector<unsigned int> component(n_dofs);
    for (unsigned int i = 0; i < n_dofs; ++i)
      {
        component[i] = fe.system_to_component_index(i).first;
        AssertThrow(component[i] < dim,
                    ExcMessage("Incompressibility: the element must have the "
                               "displacement components only"));
      }
    double                      value = 0.;
    std::vector<Tensor<1, dim>> G(n_dofs);
    for (unsigned int q = 0; q < fe_values.n_quadrature_points; ++q)
      {
        const Tensor<2, dim> F   = unit_symmetric_tensor<dim>() + grad_u[q];
        const double         J   = determinant(F);
        const double         JxW = fe_values.JxW(q);
        value += (J - 1.) * JxW;
        if (!gradient && !hessian)
          continue;
        const Tensor<2, dim> Finv_T = transpose(invert(F));
        for (unsigned int i = 0; i < n_dofs; ++i)
          G[i] = Finv_T * fe_values.shape_grad(i, q);
        if (gradient)
          for (unsigned int i = 0; i < n_dofs; ++i)
            (*gradient)(i) += J * G[i][component[i]] * JxW;
        if (hessian)
          {
            const double w = factor * J * JxW;
            for (unsigned int i = 0; i < n_dofs; ++i)
              {
                const unsigned int ci  = component[i];
                const double       tri = G[i][ci];
                for (unsigned int j = 0; j <= i; ++j)
                  {
                    const unsigned int cj = component[j];
                    const double h = w * (tri * G[j][cj] - G[i][cj] * G[j][ci]);
                    (*hessian)(i, j) += h;
                    if (j != i)
                      (*hessian)(j, i) += h;
                  }
              }
          }
      }
    return value;
  }

  template class Incompressibility<2>;
  template class Incompressibility<3>;
} // namespace Signorini
