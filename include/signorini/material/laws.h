#pragma once

// The strain-energy laws of formulation.md section 1, each as a small
// value type: its constants, energy(I1, I2, J) templated on the number type
// (so that it is differentiated exactly), its small-strain Lamé pair, and
// the static members by which it is registered (model_name, help,
// from_parameters, ...; see doc/materials.md). The parameter code is in
// source/material/laws.cc. Linear elasticity is not invariant based and
// lives in linear_elastic.h, the Gent law in gent.h.

#include <signorini/material/invariant_based.h>
#include <signorini/material/registry.h>

#include <array>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace Signorini
{
  namespace Material
  {
    /**
     * Compressible neo-Hookean, ln J form:
     *   psi = mu/2 (I1 - 3) - mu ln J + lambda/2 (ln J)^2.
     * Constants: the Lamé pair mu, lambda [stress], from 'Young's modulus'
     * E > 0 and 'Poisson's ratio' nu in (-1, 0.5):
     * mu = E/(2(1+nu)), lambda = E nu/((1+nu)(1-2nu)). They are also its
     * small-strain Lamé constants.
     */
    struct NeoHookeanLaw
    {
      double mu     = 1.;
      double lambda = 1.;

      static constexpr const char *model_name = "neo-Hookean";
      static constexpr const char *help =
        "neo-Hookean: mu/2 (I1 - 3) - mu ln J + lambda/2 (ln J)^2.";
      static constexpr bool uses_young_poisson = true;

      static NeoHookeanLaw
      from_parameters(ParameterHandler &prm, const std::string &context);

      static std::vector<Example>
      examples();

      template <typename Number>
      Number
      energy(const Number &I1, const Number & /*I2*/, const Number &J) const
      {
        using std::log;
        const Number lnJ = log(J);
        return 0.5 * mu * (I1 - 3.) - mu * lnJ + 0.5 * lambda * lnJ * lnJ;
      }

      /// psi_1 = mu/2, psi_J = (lambda ln J - mu)/J,
      /// psi_JJ = (lambda + mu - lambda ln J)/J^2, the others 0.
      void
      invariant_derivatives(const double I1,
                            const double /*I2*/,
                            const double J,
                            double      &psi,
                            std::array<double, 3> &dpsi,
                            std::array<std::array<double, 3>, 3> &d2psi) const
      {
        const double lnJ = std::log(J);
        psi     = 0.5 * mu * (I1 - 3.) - mu * lnJ + 0.5 * lambda * lnJ * lnJ;
        // psi_J in the order in which Sacado differentiates energy(), so
        // that it rounds as its oracle does: in a body that barely strains
        // (tests/hertz_stiff_block) P = mu F + J psi_J F^-T is a
        // difference of terms 1e5 times larger, and the last bit of psi_J
        // decided whether a load step converged within its iterations.
        const double r = 1. / J;
        dpsi    = {{0.5 * mu, 0., -mu * r + (0.5 * lambda * r * lnJ +
                                            0.5 * lambda * lnJ * r)}};
        d2psi   = {};
        d2psi[2][2] = (lambda + mu - lambda * lnJ) / (J * J);
      }

      std::string
      name() const
      {
        return "neo-Hookean (ln J)";
      }

      std::pair<double, double>
      small_strain_lame() const
      {
        return {mu, lambda};
      }
    };

    /**
     * Code_Aster ELAS_HYPER (Mooney-Rivlin family):
     *   psi = C10 (I1b - 3) + C01 (I2b - 3) + C20 (I1b - 3)^2 + K/2 (J - 1)^2
     * with I1b = J^(-2/3) I1, I2b = J^(-4/3) I2. Neo-Hookean in the
     * Code_Aster sense is C01 = C20 = 0, Mooney-Rivlin is C20 = 0.
     * With @p include_volumetric false the K term is dropped (for
     * incompressibility imposed as a constraint).
     * Constants [stress]: 'C10', 'C01' (C10 + C01 > 0: the small-strain
     * shear modulus is 2 (C10 + C01)), 'C20' >= 0, and the bulk modulus
     * K = 'Bulk modulus' if > 0, else K = 6 (C10 + C01)/(3 (1 - 2 nu)) from
     * 'Poisson's ratio' nu (the Code_Aster convention). Small-strain Lamé
     * pair: mu = 2 (C10 + C01), lambda = K - 2 mu/3.
     */
    struct ElasHyperLaw
    {
      double C10                = 1.;
      double C01                = 0.;
      double C20                = 0.;
      double K                  = 1.;
      bool   include_volumetric = true;

      static constexpr const char *model_name = "ELAS_HYPER";
      static constexpr const char *help =
        "ELAS_HYPER (Code_Aster): C10 (I1b - 3) + C01 (I2b - 3) + "
        "C20 (I1b - 3)^2 + K/2 (J - 1)^2 with I1b = J^(-2/3) I1, "
        "I2b = J^(-4/3) I2 (Mooney-Rivlin: C20 = 0; neo-Hookean in the "
        "Code_Aster sense: C01 = C20 = 0).";
      static constexpr bool uses_young_poisson      = false;
      static constexpr bool supports_incompressible = true;

      /// C10, C01, C20, Bulk modulus.
      static void
      declare_parameters(ParameterHandler &prm);

      static ElasHyperLaw
      from_parameters(ParameterHandler &prm, const std::string &context);

      static std::vector<Example>
      examples();

      template <typename Number>
      Number
      energy(const Number &I1, const Number &I2, const Number &J) const
      {
        using std::pow;
        const Number I1b = pow(J, -2. / 3.) * I1;
        const Number I2b = pow(J, -4. / 3.) * I2;
        Number psi = C10 * (I1b - 3.) + C01 * (I2b - 3.) +
                     C20 * (I1b - 3.) * (I1b - 3.);
        if (include_volumetric)
          psi += 0.5 * K * (J - 1.) * (J - 1.);
        return psi;
      }

      /// By isochoric_volumetric_derivatives() with
      /// W = C10 (I1b - 3) + C01 (I2b - 3) + C20 (I1b - 3)^2 and
      /// U = K/2 (J - 1)^2 (or 0).
      void
      invariant_derivatives(const double I1,
                            const double I2,
                            const double J,
                            double      &psi,
                            std::array<double, 3> &dpsi,
                            std::array<std::array<double, 3>, 3> &d2psi) const
      {
        const double a   = std::pow(J, -2. / 3.);
        const double I1b = a * I1;
        const double I2b = a * a * I2;
        const double U   = include_volumetric ? 0.5 * K * (J - 1.) * (J - 1.) : 0.;
        const double U1  = include_volumetric ? K * (J - 1.) : 0.;
        const double U2  = include_volumetric ? K : 0.;
        psi = C10 * (I1b - 3.) + C01 * (I2b - 3.) +
              C20 * (I1b - 3.) * (I1b - 3.) + U;
        isochoric_volumetric_derivatives(J, a, I1b, I2b,
                                         C10 + 2. * C20 * (I1b - 3.), C01,
                                         2. * C20, 0., 0., U1, U2,
                                         dpsi, d2psi);
      }

      std::string
      name() const
      {
        return include_volumetric ? "ELAS_HYPER (Mooney-Rivlin family)" :
                                    "ELAS_HYPER (Mooney-Rivlin family), "
                                    "incompressible (J = 1 constraints)";
      }

      std::pair<double, double>
      small_strain_lame() const
      {
        const double mu = 2. * (C10 + C01);
        return {mu, K - 2. * mu / 3.};
      }
    };

    /**
     * Saint Venant-Kirchhoff: psi = lambda/2 (tr E)^2 + mu tr(E^2),
     * E = (C - I)/2, i.e. tr E = (I1 - 3)/2 and
     * tr(E^2) = (I1^2 - 2 I2 - 2 I1 + 3)/4.
     * Constants: mu, lambda [stress] from 'Young's modulus' and 'Poisson's
     * ratio' as for NeoHookeanLaw (also its small-strain Lamé pair).
     */
    struct SaintVenantKirchhoffLaw
    {
      double mu     = 1.;
      double lambda = 1.;

      static constexpr const char *model_name = "Saint Venant-Kirchhoff";
      static constexpr const char *help =
        "Saint Venant-Kirchhoff: lambda/2 (tr E)^2 + mu tr(E^2).";
      static constexpr bool uses_young_poisson = true;

      static SaintVenantKirchhoffLaw
      from_parameters(ParameterHandler &prm, const std::string &context);

      static std::vector<Example>
      examples();

      template <typename Number>
      Number
      energy(const Number &I1, const Number &I2, const Number & /*J*/) const
      {
        const Number trE  = 0.5 * (I1 - 3.);
        const Number trE2 = 0.25 * (I1 * I1 - 2. * I2 - 2. * I1 + 3.);
        return 0.5 * lambda * trE * trE + mu * trE2;
      }

      /// psi_1 = lambda tr E/2 + mu (I1 - 1)/2, psi_2 = -mu/2,
      /// psi_11 = lambda/4 + mu/2, the others 0.
      void
      invariant_derivatives(const double I1,
                            const double I2,
                            const double /*J*/,
                            double      &psi,
                            std::array<double, 3> &dpsi,
                            std::array<std::array<double, 3>, 3> &d2psi) const
      {
        const double trE  = 0.5 * (I1 - 3.);
        const double trE2 = 0.25 * (I1 * I1 - 2. * I2 - 2. * I1 + 3.);
        psi   = 0.5 * lambda * trE * trE + mu * trE2;
        dpsi  = {{0.5 * lambda * trE + 0.5 * mu * (I1 - 1.), -0.5 * mu, 0.}};
        d2psi = {};
        d2psi[0][0] = 0.25 * lambda + 0.5 * mu;
      }

      std::string
      name() const
      {
        return "Saint Venant-Kirchhoff";
      }

      std::pair<double, double>
      small_strain_lame() const
      {
        return {mu, lambda};
      }
    };
  } // namespace Material
} // namespace Signorini
