#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/tensor.h>

#include <memory>
#include <string>

namespace Signorini
{
  namespace Material
  {
    using namespace dealii;

    /**
     * What a material returns at one deformation gradient: the strain
     * energy density psi (energy per unit reference volume), the first
     * Piola-Kirchhoff stress P = dpsi/dF and the tangent A = d2psi/dFdF
     * (A[i][j][k][l] = d2psi / dF_ij dF_kl).
     */
    template <int dim>
    struct Response
    {
      double         psi = 0.;
      Tensor<2, dim> P;
      Tensor<4, dim> A;
    };

    /**
     * A hyperelastic material. Materials are written once, in three
     * dimensions; plane strain is the 3D law at F33 = 1 (see
     * evaluate() below), so no material knows about the space dimension.
     */
    class Interface
    {
    public:
      virtual ~Interface() = default;

      /**
       * Evaluate psi, and P and A when @p want_derivatives, at the 3D
       * deformation gradient @p F. Returns false if F is outside the
       * domain of the energy (J <= 0 for the finite-strain laws); the
       * response is then undefined and callers treat the state as
       * inadmissible.
       */
      virtual bool
      evaluate(const Tensor<2, 3> &F,
               Response<3>        &response,
               const bool          want_derivatives) const = 0;

      /**
       * The same in plane strain: @p F is the in-plane block of a 3D
       * deformation gradient with F33 = 1, and P and A are the in-plane
       * blocks of the 3D quantities (exact, because F33 is held fixed).
       * The default embeds F and calls evaluate(); a law may override it
       * to compute only the in-plane blocks.
       */
      virtual bool
      evaluate_plane_strain(const Tensor<2, 2> &F,
                            Response<2>        &response,
                            const bool          want_derivatives) const;

      /**
       * The first Piola-Kirchhoff stress P at the 3D deformation gradient
       * @p F, without the tangent (output). Returns false where evaluate()
       * would. The default calls evaluate(); a law may compute P alone.
       */
      virtual bool
      first_piola(const Tensor<2, 3> &F, Tensor<2, 3> &P) const;

      /// A name for output, e.g. "neo-Hookean (ln J)".
      virtual std::string
      name() const = 0;

      /**
       * An estimate of the small-strain Lamé constants (mu, lambda) at
       * F = I; solvers use them for scale-free parameters (penalty,
       * regularisation).
       */
      virtual std::pair<double, double>
      small_strain_lame() const = 0;
    };

    /**
     * Evaluate @p material at the @p dim -dimensional deformation
     * gradient @p F. For dim == 2 the deformation is plane strain
     * (Interface::evaluate_plane_strain()): F is embedded in 3D with
     * F33 = 1, and P and A are the in-plane blocks of the 3D quantities.
     */
    template <int dim>
    bool
    evaluate(const Interface      &material,
             const Tensor<2, dim> &F,
             Response<dim>        &response,
             const bool            want_derivatives);

    /// The 3D deformation gradient of a dim-dimensional one (F33 = 1 in 2D).
    template <int dim>
    Tensor<2, 3>
    embed(const Tensor<2, dim> &F);

    /**
     * The Cauchy stress sigma = P F^T / J as a 3x3 tensor (the
     * out-of-plane stress of plane strain included), for output.
     */
    template <int dim>
    Tensor<2, 3>
    cauchy_stress(const Interface &material, const Tensor<2, dim> &F);

    /// Young's modulus E and Poisson's ratio nu at F = I, from
    /// Interface::small_strain_lame().
    std::pair<double, double>
    small_strain_young_poisson(const Interface &material);

    /// Declare the entries of a "Material" subsection.
    void
    declare_parameters(ParameterHandler &prm);

    /**
     * Create the material described by the current subsection of @p prm.
     * @p context names the subsection in error messages. Inconsistent
     * constants throw an InputError naming the entry.
     */
    std::unique_ptr<Interface>
    create(ParameterHandler &prm, const std::string &context);
  } // namespace Material
} // namespace Signorini
