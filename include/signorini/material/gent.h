#pragma once

// The Gent law (A. N. Gent, Rubber Chem. Technol. 69, 1996), compressible
// form with an isochoric first invariant. Registered in
// source/material/registry.cc; its parameters are read in
// source/material/gent.cc.

#include <signorini/material/invariant_based.h>
#include <signorini/material/registry.h>

#include <array>
#include <cmath>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace Signorini
{
  namespace Material
  {
    /**
     * Gent:
     *   psi = -mu J_m/2 ln(1 - (I1b - 3)/J_m) + K/2 (J - 1)^2,
     *   I1b = J^(-2/3) I1.
     *
     * Constants:
     * - mu [stress], the small-strain shear modulus, and K [stress], the
     *   bulk modulus, from 'Young's modulus' E > 0 and 'Poisson's ratio'
     *   nu in (-1, 0.5): mu = E/(2(1+nu)), K = E/(3(1-2nu));
     * - J_m [-] > 0, 'Gent limiting extensibility': the largest value of
     *   I1b - 3. The energy is defined for J > 0 and I1b - 3 < J_m only
     *   (admissible()); it grows without bound as I1b - 3 -> J_m (the
     *   chains lock).
     *
     * Small strain: -J_m/2 ln(1 - x/J_m) = x/2 + O(x^2/J_m), so at F = I
     * the law is linear elasticity with shear modulus mu and bulk modulus
     * K, i.e. the Lamé pair (mu, K - 2 mu/3) = (mu, E nu/((1+nu)(1-2nu))).
     * As J_m -> infinity the law tends to the isochoric neo-Hookean
     * mu/2 (I1b - 3) + K/2 (J - 1)^2 (ELAS_HYPER with C10 = mu/2,
     * C01 = C20 = 0).
     *
     * The logarithm is evaluated as log1p(-(I1b - 3)/J_m), accurate when
     * (I1b - 3)/J_m is small (large J_m or small strain).
     */
    struct GentLaw
    {
      double mu  = 1.;
      double K   = 1.;
      double J_m = 1.;

      static constexpr const char *model_name = "Gent";
      static constexpr const char *help =
        "Gent: -mu J_m/2 ln(1 - (I1b - 3)/J_m) + K/2 (J - 1)^2 with "
        "I1b = J^(-2/3) I1, mu = E/(2(1+nu)), K = E/(3(1-2nu)) and "
        "J_m = 'Gent limiting extensibility' (states with I1b - 3 >= J_m "
        "are inadmissible; J_m -> infinity gives the isochoric neo-Hookean "
        "mu/2 (I1b - 3) + K/2 (J - 1)^2).";
      static constexpr bool uses_young_poisson = true;

      /// Gent limiting extensibility.
      static void
      declare_parameters(ParameterHandler &prm);

      static GentLaw
      from_parameters(ParameterHandler &prm, const std::string &context);

      static std::vector<Example>
      examples();

      /// I1b - 3 < J_m, written as I1^3 < (3 + J_m)^3 J^2 (I1, J > 0):
      /// no pow() for a test made at every quadrature point.
      bool
      admissible(const double I1, const double /*I2*/, const double J) const
      {
        const double b = 3. + J_m;
        return J > 0. && I1 * I1 * I1 < b * b * b * J * J;
      }

      template <typename Number>
      Number
      energy(const Number &I1, const Number & /*I2*/, const Number &J) const
      {
        using std::pow;
        const Number I1b = pow(J, -2. / 3.) * I1;
        const Number x   = (I1b - 3.) / J_m;
        return -0.5 * mu * J_m * log1p_minus(x) +
               0.5 * K * (J - 1.) * (J - 1.);
      }

      /// By isochoric_volumetric_derivatives() with
      /// W = -mu J_m/2 ln(1 - x), x = (I1b - 3)/J_m: W1 = mu/(2(1 - x)),
      /// W11 = mu/(2 J_m (1 - x)^2); U = K/2 (J - 1)^2.
      void
      invariant_derivatives(const double I1,
                            const double /*I2*/,
                            const double J,
                            double      &psi,
                            std::array<double, 3> &dpsi,
                            std::array<std::array<double, 3>, 3> &d2psi) const
      {
        const double a   = std::pow(J, -2. / 3.);
        const double I1b = a * I1;
        const double x   = (I1b - 3.) / J_m;
        const double W1  = 0.5 * mu / (1. - x);
        psi = -0.5 * mu * J_m * std::log1p(-x) + 0.5 * K * (J - 1.) * (J - 1.);
        isochoric_volumetric_derivatives(J, a, I1b, 0., W1, 0.,
                                         W1 / (J_m * (1. - x)), 0., 0.,
                                         K * (J - 1.), K, dpsi, d2psi);
      }

      std::string
      name() const
      {
        return "Gent";
      }

      std::pair<double, double>
      small_strain_lame() const
      {
        return {mu, K - 2. * mu / 3.};
      }

    private:
      /**
       * ln(1 - x) for double and for (nested) Sacado numbers. Sacado has no
       * log1p, and log(1 - x) loses the relative accuracy of a small x in
       * the value; the derivatives -x'/(1 - x) are accurate. So the value
       * (at every nesting level) is replaced by std::log1p(-x).
       */
      template <typename Number>
      static Number
      log1p_minus(const Number &x)
      {
        if constexpr (std::is_same_v<Number, double>)
          return std::log1p(-x);
        else
          {
            using std::log;
            Number r = log(1. - x);
            r.val()  = log1p_minus(x.val());
            return r;
          }
      }
    };
  } // namespace Material
} // namespace Signorini
