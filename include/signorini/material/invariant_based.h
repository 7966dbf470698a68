#pragma once

#include <signorini/material/interface.h>

#include <deal.II/differentiation/ad/sacado_product_types.h>

#include <Sacado.hpp>

#include <array>
#include <cmath>
#include <type_traits>

namespace Signorini
{
  namespace Material
  {
    /**
     * Base class of isotropic laws written as psi(I1, I2, J), with
     * C = F^T F, I1 = tr C, I2 = (I1^2 - tr C^2)/2 and J = det F.
     * evaluate() applies the chain rule once for all laws:
     *
     *   P = psi_1 dI1/dF + psi_2 dI2/dF + psi_J dJ/dF,
     *   A = sum_ab psi_ab dIa/dF (x) dIb/dF + sum_a psi_a d2Ia/dFdF,
     *
     *   dI1/dF = 2F,  dI2/dF = 2(I1 F - F C),  dJ/dF = J F^-T,
     *   d2I1/dF_ij dF_kl = 2 d_ik d_jl,
     *   d2I2/dF_ij dF_kl = 2(2 F_ij F_kl + I1 d_ik d_jl - d_ik C_lj
     *                        - F_il F_kj - B_ik d_jl),  B = F F^T,
     *   d2J/dF_ij dF_kl = J (Finv_ji Finv_lk - Finv_jk Finv_li).
     *
     * States with J <= 0, states outside the law's own domain (see
     * admissible()) and states where psi or P is not finite are rejected
     * (evaluate() returns false).
     */
    class InvariantBased : public Interface
    {
    public:
      bool
      evaluate(const Tensor<2, 3> &F,
               Response<3>        &response,
               const bool          want_derivatives) const override;

      /// Only the in-plane blocks of P and A are computed.
      bool
      evaluate_plane_strain(const Tensor<2, 2> &F,
                            Response<2>        &response,
                            const bool want_derivatives) const override;

      /// P without the tangent A (the same values as evaluate()'s P).
      bool
      first_piola(const Tensor<2, 3> &F, Tensor<2, 3> &P) const override;

    protected:
      /**
       * Whether the invariants (I1, I2, J), J > 0, lie in the domain of
       * the energy. All of J > 0 by default; a law whose energy is defined
       * on less (Gent: I1b - 3 < J_m) says so here, so that evaluate()
       * returns false there without evaluating the energy.
       */
      virtual bool
      admissible(const std::array<double, 3> &invariants) const;

      /**
       * psi and its first and second partial derivatives with respect to
       * (I1, I2, J), in that order. Called only with J > 0 and admissible
       * invariants.
       */
      virtual void
      invariant_energy(const std::array<double, 3>       &invariants,
                       double                            &psi,
                       std::array<double, 3>             &dpsi,
                       std::array<std::array<double, 3>, 3> &d2psi,
                       const bool want_derivatives) const = 0;

    private:
      /// evaluate() at the in-plane block @p Fb of F (in 3D, F itself;
      /// in plane strain F = diag(Fb, 1)), keeping the dim x dim blocks of
      /// P and A (A only if @p want_tangent).
      template <int dim>
      bool
      evaluate_blocks(const Tensor<2, dim> &Fb,
                      Response<dim>        &response,
                      const bool            want_derivatives,
                      const bool            want_tangent = true) const;
    };

    /**
     * The invariant derivatives of an energy split into an isochoric and a
     * volumetric part, psi = W(I1b, I2b) + U(J) with I1b = J^(-2/3) I1 and
     * I2b = J^(-4/3) I2, from the partial derivatives of W with respect to
     * (I1b, I2b) (@p W1, @p W2, @p W11, @p W12, @p W22) and U'(J), U''(J)
     * (@p U1, @p U2); @p a = J^(-2/3). With p = dI1b/dJ = -2/3 I1b/J and
     * q = dI2b/dJ = -4/3 I2b/J:
     *
     *   psi_1 = a W1,  psi_2 = a^2 W2,  psi_J = p W1 + q W2 + U',
     *   psi_11 = a^2 W11,  psi_12 = a^3 W12,  psi_22 = a^4 W22,
     *   psi_1J = a (p W11 + q W12) - 2/3 a W1/J,
     *   psi_2J = a^2 (p W12 + q W22) - 4/3 a^2 W2/J,
     *   psi_JJ = p^2 W11 + 2 p q W12 + q^2 W22
     *            + 10/9 I1b W1/J^2 + 28/9 I2b W2/J^2 + U''.
     */
    inline void
    isochoric_volumetric_derivatives(
      const double                          J,
      const double                          a,
      const double                          I1b,
      const double                          I2b,
      const double                          W1,
      const double                          W2,
      const double                          W11,
      const double                          W12,
      const double                          W22,
      const double                          U1,
      const double                          U2,
      std::array<double, 3>                &dpsi,
      std::array<std::array<double, 3>, 3> &d2psi)
    {
      const double b = a * a;
      const double p = -2. / 3. * I1b / J;
      const double q = -4. / 3. * I2b / J;
      dpsi[0]        = a * W1;
      dpsi[1]        = b * W2;
      dpsi[2]        = p * W1 + q * W2 + U1;
      d2psi[0][0]    = b * W11;
      d2psi[0][1] = d2psi[1][0] = a * b * W12;
      d2psi[1][1]               = b * b * W22;
      d2psi[0][2] = d2psi[2][0] = a * (p * W11 + q * W12) - 2. / 3. * a * W1 / J;
      d2psi[1][2] = d2psi[2][1] = b * (p * W12 + q * W22) - 4. / 3. * b * W2 / J;
      d2psi[2][2] = p * p * W11 + 2. * p * q * W12 + q * q * W22 +
                    (10. / 9. * I1b * W1 + 28. / 9. * I2b * W2) / (J * J) + U2;
    }

    /// How InvariantLaw obtains the invariant derivatives of psi.
    enum class Differentiation
    {
      /// The law's own closed form (invariant_derivatives()) if it has
      /// one, else automatic differentiation.
      closed_form,
      /// Nested Sacado numbers on energy(), always (the tests' oracle).
      automatic
    };

    /**
     * Adapter that differentiates a law's energy(I1, I2, J). A new law only
     * writes
     *
     *   template <typename Number>
     *   Number energy(const Number &I1, const Number &I2, const Number &J) const;
     *
     * and its derivatives are then computed exactly with nested
     * forward-mode automatic differentiation (Sacado SFad of SFad: no
     * truncation error, no heap allocation). If its energy is not defined
     * for every J > 0, it also writes
     *
     *   bool admissible(double I1, double I2, double J) const;
     *
     * which InvariantBased::admissible() then calls. A law may also give
     * its derivatives in closed form, which is several times faster:
     *
     *   void invariant_derivatives(double I1, double I2, double J,
     *                              double &psi, std::array<double, 3> &dpsi,
     *                              std::array<std::array<double, 3>, 3> &d2psi) const;
     *
     * (psi, dpsi/d(I1, I2, J), the symmetric d2psi). It is then used
     * unless the adapter is built with Differentiation::automatic, which
     * the tests do to check the closed form against the Sacado
     * derivatives of energy().
     */
    template <typename Law>
    class InvariantLaw : public InvariantBased
    {
      template <typename L, typename = void>
      struct has_closed_form : std::false_type
      {};
      template <typename L>
      struct has_closed_form<
        L,
        std::void_t<decltype(std::declval<const L &>().invariant_derivatives(
          0.,
          0.,
          1.,
          std::declval<double &>(),
          std::declval<std::array<double, 3> &>(),
          std::declval<std::array<std::array<double, 3>, 3> &>()))>>
        : std::true_type
      {};

      template <typename L, typename = void>
      struct has_admissible : std::false_type
      {};
      template <typename L>
      struct has_admissible<
        L,
        std::void_t<decltype(std::declval<const L &>().admissible(0., 0., 1.))>>
        : std::true_type
      {};

    public:
      /// Whether the law gives its invariant derivatives in closed form.
      static constexpr bool closed_form_available = has_closed_form<Law>::value;

      explicit InvariantLaw(
        const Law            &law,
        const Differentiation differentiation = Differentiation::closed_form)
        : law(law)
        , use_closed_form(closed_form_available &&
                          differentiation == Differentiation::closed_form)
      {}

      std::string
      name() const override
      {
        return law.name();
      }

      std::pair<double, double>
      small_strain_lame() const override
      {
        return law.small_strain_lame();
      }

      const Law &
      get_law() const
      {
        return law;
      }

    protected:
      bool
      admissible(const std::array<double, 3> &I) const override
      {
        if constexpr (has_admissible<Law>::value)
          return law.admissible(I[0], I[1], I[2]);
        else
          return true;
      }

      void
      invariant_energy(const std::array<double, 3>          &I,
                       double                               &psi,
                       std::array<double, 3>                &dpsi,
                       std::array<std::array<double, 3>, 3> &d2psi,
                       const bool want_derivatives) const override
      {
        if (!want_derivatives)
          {
            psi = law.energy(I[0], I[1], I[2]);
            return;
          }
        if constexpr (closed_form_available)
          if (use_closed_form)
            {
              law.invariant_derivatives(I[0], I[1], I[2], psi, dpsi, d2psi);
              return;
            }
        using Inner = Sacado::Fad::SFad<double, 3>;
        using Outer = Sacado::Fad::SFad<Inner, 3>;
        std::array<Outer, 3> x;
        for (int a = 0; a < 3; ++a)
          x[a] = Outer(3, a, Inner(3, a, I[a]));
        const Outer e = law.energy(x[0], x[1], x[2]);
        psi           = e.val().val();
        for (int a = 0; a < 3; ++a)
          {
            dpsi[a] = e.dx(a).val();
            for (int b = 0; b < 3; ++b)
              d2psi[a][b] = e.dx(a).dx(b);
          }
      }

    private:
      Law  law;
      bool use_closed_form;
    };
  } // namespace Material
} // namespace Signorini
