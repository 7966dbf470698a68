#include <signorini/input_error.h>
#include <signorini/material/interface.h>
#include <signorini/material/invariant_based.h>
#include <signorini/material/laws.h>
#include <signorini/material/linear_elastic.h>

namespace Signorini
{
  namespace Material
  {
    template <int dim>
    Tensor<2, 3>
    embed(const Tensor<2, dim> &F)
    {
      Tensor<2, 3> F3;
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          F3[i][j] = F[i][j];
      for (unsigned int i = dim; i < 3; ++i)
        F3[i][i] = 1.;
      return F3;
    }

    template <int dim>
    bool
    evaluate(const Interface      &material,
             const Tensor<2, dim> &F,
             Response<dim>        &response,
             const bool            want_derivatives)
    {
      if constexpr (dim == 3)
        return material.evaluate(F, response, want_derivatives);
      else
        {
          Response<3> r3;
          const bool  ok = material.evaluate(embed(F), r3, want_derivatives);
          response.psi   = r3.psi;
          if (ok && want_derivatives)
            for (unsigned int i = 0; i < dim; ++i)
              for (unsigned int j = 0; j < dim; ++j)
                {
                  response.P[i][j] = r3.P[i][j];
                  for (unsigned int k = 0; k < dim; ++k)
                    for (unsigned int l = 0; l < dim; ++l)
                      response.A[i][j][k][l] = r3.A[i][j][k][l];
                }
          return ok;
        }
    }

    template <int dim>
    Tensor<2, 3>
    cauchy_stress(const Interface &material, const Tensor<2, dim> &F)
    {
      const Tensor<2, 3> F3 = embed(F);
      Response<3>        r;
      if (!material.evaluate(F3, r, true))
        {
          Tensor<2, 3> nan;
          for (unsigned int i = 0; i < 3; ++i)
            for (unsigned int j = 0; j < 3; ++j)
              nan[i][j] = std::numeric_limits<double>::quiet_NaN();
          return nan;
        }
      return r.P * transpose(F3) / determinant(F3);
    }

    std::pair<double, double>
    small_strain_young_poisson(const Interface &material)
    {
      const auto [mu, lambda] = material.small_strain_lame();
      return {mu * (3. * lambda + 2. * mu) / (lambda + mu),
              lambda / (2. * (lambda + mu))};
    }

    void
    declare_parameters(ParameterHandler &prm)
    {
      prm.declare_entry(
        "Model",
        "neo-Hookean",
        Patterns::Selection(
          "neo-Hookean|ELAS_HYPER|Saint Venant-Kirchhoff|linear elastic"),
        "Strain energy density psi(F). "
        "neo-Hookean: mu/2 (I1 - 3) - mu ln J + lambda/2 (ln J)^2. "
        "ELAS_HYPER (Code_Aster): C10 (I1b - 3) + C01 (I2b - 3) + "
        "C20 (I1b - 3)^2 + K/2 (J - 1)^2 with I1b = J^(-2/3) I1, "
        "I2b = J^(-4/3) I2 (Mooney-Rivlin: C20 = 0; neo-Hookean in the "
        "Code_Aster sense: C01 = C20 = 0). "
        "Saint Venant-Kirchhoff: lambda/2 (tr E)^2 + mu tr(E^2). "
        "linear elastic: lambda/2 (tr eps)^2 + mu eps:eps (small strain). "
        "In 2D every law is used in plane strain (F33 = 1).");
      prm.declare_entry("Young's modulus",
                        "1",
                        Patterns::Double(),
                        "E [stress] for neo-Hookean, Saint Venant-Kirchhoff "
                        "and linear elastic; must be > 0.");
      prm.declare_entry(
        "Poisson's ratio",
        "0.3",
        Patterns::Double(),
        "nu [-], in (-1, 0.5). With E it gives mu = E/(2(1+nu)) and "
        "lambda = E nu/((1+nu)(1-2nu)). For ELAS_HYPER it gives the bulk "
        "modulus K = 6 (C10 + C01)/(3 (1 - 2 nu)) (the Code_Aster "
        "convention) unless 'Bulk modulus' is set.");
      prm.declare_entry("C10",
                        "1",
                        Patterns::Double(),
                        "ELAS_HYPER constant C10 [stress].");
      prm.declare_entry("C01",
                        "0",
                        Patterns::Double(),
                        "ELAS_HYPER constant C01 [stress].");
      prm.declare_entry("C20",
                        "0",
                        Patterns::Double(),
                        "ELAS_HYPER constant C20 [stress].");
      prm.declare_entry("Bulk modulus",
                        "-1",
                        Patterns::Double(),
                        "ELAS_HYPER bulk modulus K [stress]; a value <= 0 "
                        "means: compute it from Poisson's ratio.");
      prm.declare_entry("Incompressible",
                        "false",
                        Patterns::Bool(),
                        "ELAS_HYPER only, with Solver > Method = ipopt: drop "
                        "the volumetric term K/2 (J - 1)^2 and impose J = 1 "
                        "as one equality int_K (J - 1) dV = 0 per cell (use "
                        "Polynomial degree = 2: the Q2/P0 pair). Poisson's "
                        "ratio and Bulk modulus are then unused.");
    }

    namespace
    {
      double
      get_positive(ParameterHandler  &prm,
                   const std::string &context,
                   const std::string &key)
      {
        const double v = prm.get_double(key);
        if (!(v > 0.) || !std::isfinite(v))
          throw InputError(context + " > " + key,
                           "must be a finite number > 0, got " +
                             prm.get(key));
        return v;
      }

      double
      get_poisson(ParameterHandler &prm, const std::string &context)
      {
        const double nu = prm.get_double("Poisson's ratio");
        if (!(nu > -1. && nu < 0.5))
          throw InputError(
            context + " > Poisson's ratio",
            "must lie in (-1, 0.5) for a compressible law, got " +
              prm.get("Poisson's ratio") +
              " (nu = 0.5 is incompressible: impose J = 1 as a "
              "constraint instead)");
        return nu;
      }
    } // namespace

    std::unique_ptr<Interface>
    create(ParameterHandler &prm, const std::string &context)
    {
      const std::string model = prm.get("Model");
      if (model == "ELAS_HYPER")
        {
          ElasHyperLaw law;
          law.C10 = prm.get_double("C10");
          law.C01 = prm.get_double("C01");
          law.C20 = prm.get_double("C20");
          if (!(law.C10 + law.C01 > 0.))
            throw InputError(context + " > C10, C01",
                             "C10 + C01 must be > 0 (the small-strain shear "
                             "modulus is 2 (C10 + C01)), got C10 = " +
                               prm.get("C10") + ", C01 = " + prm.get("C01"));
          if (law.C20 < 0.)
            throw InputError(context + " > C20",
                             "must be >= 0, got " + prm.get("C20"));
          const double K = prm.get_double("Bulk modulus");
          if (prm.get_bool("Incompressible"))
            law.include_volumetric = false;
          else if (K > 0.)
            law.K = K;
          else
            {
              const double nu = get_poisson(prm, context);
              law.K = 6. * (law.C10 + law.C01) / (3. * (1. - 2. * nu));
            }
          return std::make_unique<InvariantLaw<ElasHyperLaw>>(law);
        }

      if (prm.get_bool("Incompressible"))
        throw InputError(context + " > Incompressible",
                         "is only available for Model = ELAS_HYPER, not " +
                           model);
      const double E      = get_positive(prm, context, "Young's modulus");
      const double nu     = get_poisson(prm, context);
      const double mu     = E / (2. * (1. + nu));
      const double lambda = E * nu / ((1. + nu) * (1. - 2. * nu));
      if (model == "neo-Hookean")
        return std::make_unique<InvariantLaw<NeoHookeanLaw>>(
          NeoHookeanLaw{mu, lambda});
      if (model == "Saint Venant-Kirchhoff")
        return std::make_unique<InvariantLaw<SaintVenantKirchhoffLaw>>(
          SaintVenantKirchhoffLaw{mu, lambda});
      if (model == "linear elastic")
        return std::make_unique<LinearElastic>(mu, lambda);
      throw InputError(context + " > Model", "unknown model " + model);
    }

    template Tensor<2, 3> embed<2>(const Tensor<2, 2> &);
    template Tensor<2, 3> embed<3>(const Tensor<2, 3> &);
    template bool
    evaluate<2>(const Interface &, const Tensor<2, 2> &, Response<2> &, bool);
    template bool
    evaluate<3>(const Interface &, const Tensor<2, 3> &, Response<3> &, bool);
    template Tensor<2, 3>
    cauchy_stress<2>(const Interface &, const Tensor<2, 2> &);
    template Tensor<2, 3>
    cauchy_stress<3>(const Interface &, const Tensor<2, 3> &);
  } // namespace Material
} // namespace Signorini
