#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <functional>
#include <memory>
#include <string>

namespace Signorini
{
  using namespace dealii;

  namespace Contact
  {
    /**
     * The surface of a rigid foundation, x_d = psi(x_1, ..., x_{d-1}),
     * psi of class C^2 (formulation.md section 2). Points with
     * x_d >= psi(x') are outside the obstacle: the body must stay there.
     *
     * Implementations give psi with its first and second derivatives.
     * They take a full point x (the last coordinate is ignored) and return
     * the derivatives as dim-sized tensors whose entries along x_d are
     * zero, which is what the constraint g(x) = x_d - psi(x') needs.
     */
    template <int dim>
    class Foundation
    {
    public:
      struct Value
      {
        double         psi = 0.;
        Tensor<1, dim> gradient; // d psi / d x_i, i < dim - 1; 0 for i = dim-1
        Tensor<2, dim> hessian;  // d2 psi / d x_i d x_j; 0 in row/column dim-1
      };

      virtual ~Foundation() = default;

      virtual Value
      evaluate(const Point<dim> &x) const = 0;

      /// A one-line description for summary.json and the screen.
      virtual std::string
      description() const = 0;

      /// The "Foundation" subsection: shape and its parameters.
      static void
      declare_parameters(ParameterHandler &prm);

      /**
       * Build the foundation from the "Foundation" subsection; throws
       * InputError naming @p context (the subsection path) on bad input.
       */
      static std::unique_ptr<Foundation<dim>>
      create(ParameterHandler &prm, const std::string &context);
    };

    /**
     * Derivatives of a scalar function of a point by Richardson
     * extrapolation of central differences (Ridders' scheme): the step
     * starts at @p h0 and shrinks by 1.4 per level, and the tableau stops
     * when the error estimate grows. Typical accuracy: 1e-12 relative for
     * first, 1e-9 for second derivatives of smooth functions whose
     * features are larger than h0. Used for expression foundations whose
     * derivatives are not given.
     */
    template <int dim>
    void
    extrapolated_derivatives(const std::function<double(const Point<dim> &)> &f,
                             const Point<dim>  &x,
                             const unsigned int n_variables,
                             const double       h0,
                             Tensor<1, dim>    &gradient,
                             Tensor<2, dim>    &hessian);
  } // namespace Contact
} // namespace Signorini
