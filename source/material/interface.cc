#include <signorini/input_error.h>
#include <signorini/material/interface.h>
#include <signorini/material/registry.h>

#include <cmath>
#include <limits>
#include <vector>

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

    bool
    Interface::first_piola(const Tensor<2, 3> &F, Tensor<2, 3> &P) const
    {
      Response<3> r;
      if (!evaluate(F, r, true))
        return false;
      P = r.P;
      return true;
    }

    bool
    Interface::evaluate_plane_strain(const Tensor<2, 2> &F,
                                     Response<2>        &response,
                                     const bool          want_derivatives) const
    {
      Response<3> r3;
      const bool  ok = evaluate(embed(F), r3, want_derivatives);
      response.psi   = r3.psi;
      if (ok && want_derivatives)
        for (unsigned int i = 0; i < 2; ++i)
          for (unsigned int j = 0; j < 2; ++j)
            {
              response.P[i][j] = r3.P[i][j];
              for (unsigned int k = 0; k < 2; ++k)
                for (unsigned int l = 0; l < 2; ++l)
                  response.A[i][j][k][l] = r3.A[i][j][k][l];
            }
      return ok;
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
        return material.evaluate_plane_strain(F, response, want_derivatives);
    }

    template <int dim>
    Tensor<2, 3>
    cauchy_stress(const Interface &material, const Tensor<2, dim> &F)
    {
      const Tensor<2, 3> F3 = embed(F);
      Tensor<2, 3>       P;
      if (!material.first_piola(F3, P))
        {
          Tensor<2, 3> nan;
          for (unsigned int i = 0; i < 3; ++i)
            for (unsigned int j = 0; j < 3; ++j)
              nan[i][j] = std::numeric_limits<double>::quiet_NaN();
          return nan;
        }
      return P * transpose(F3) / determinant(F3);
    }

    std::pair<double, double>
    small_strain_young_poisson(const Interface &material)
    {
      const auto [mu, lambda] = material.small_strain_lame();
      return {mu * (3. * lambda + 2. * mu) / (lambda + mu),
              lambda / (2. * (lambda + mu))};
    }

    namespace
    {
      /// "a", "a and b", "a, b and c" (or "a, b or c").
      std::string
      enumerate(const std::vector<std::string> &names,
                const std::string              &conjunction = "and")
      {
        std::string text;
        for (unsigned int i = 0; i < names.size(); ++i)
          text += (i == 0                    ? "" :
                   i + 1 == names.size() ? " " + conjunction + " " :
                                             ", ") +
                  names[i];
        return text;
      }

      /// The names of the registered laws that have @p property.
      template <typename Property>
      std::vector<std::string>
      laws_with(const Property &property)
      {
        std::vector<std::string> names;
        for (const LawEntry &law : registered_laws())
          if (property(law))
            names.push_back(law.name);
        return names;
      }
    } // namespace

    void
    declare_parameters(ParameterHandler &prm)
    {
      // The Model selection and its help come from the registry
      // (registry.cc): every law's name and its help sentence(s).
      std::string names, help = "Strain energy density psi(F).";
      for (const LawEntry &law : registered_laws())
        {
          names += (names.empty() ? "" : "|") + law.name;
          help += " " + law.help;
        }
      help += " In 2D every law is used in plane strain (F33 = 1).";
      prm.declare_entry("Model",
                        "neo-Hookean",
                        Patterns::Selection(names),
                        help);
      prm.declare_entry(
        "Young's modulus",
        "1",
        Patterns::Double(),
        "E [stress] for " +
          enumerate(laws_with([](const LawEntry &law) {
            return law.uses_young_poisson;
          })) +
          "; must be > 0, and must be set: no default is taken.",
        /*has_to_be_set=*/true);
      prm.declare_entry(
        "Poisson's ratio",
        "0.3",
        Patterns::Double(),
        "nu [-], in (-1, 0.5). With E it gives mu = E/(2(1+nu)) and "
        "lambda = E nu/((1+nu)(1-2nu)). For ELAS_HYPER it gives the bulk "
        "modulus K = 6 (C10 + C01)/(3 (1 - 2 nu)) (the Code_Aster "
        "convention) unless 'Bulk modulus' is set.");
      // The laws' own constants.
      for (const LawEntry &law : registered_laws())
        law.declare_parameters(prm);
      // Read for every law (Material::create, and the simulator, which
      // adds the J = 1 constraints).
      prm.declare_entry(
        "Incompressible",
        "false",
        Patterns::Bool(),
        enumerate(laws_with([](const LawEntry &law) {
          return law.supports_incompressible;
        })) +
          " only, with Solver > Method = ipopt: drop the volumetric term "
          "K/2 (J - 1)^2 and impose J = 1 as one equality "
          "int_K (J - 1) dV = 0 per cell (use Polynomial degree = 2: the "
          "Q2/P0 pair). Poisson's ratio and Bulk modulus are then unused.");
    }

    std::unique_ptr<Interface>
    create(ParameterHandler &prm, const std::string &context)
    {
      const std::string model = prm.get("Model");
      const LawEntry   *law   = find_law(model);
      if (law == nullptr)
        throw InputError(context + " > Model", "unknown model " + model);
      if (!law->supports_incompressible && prm.get_bool("Incompressible"))
        throw InputError(context + " > Incompressible",
                         "is only available for Model = " +
                           enumerate(laws_with([](const LawEntry &l) {
                                       return l.supports_incompressible;
                                     }),
                                     "or") +
                           ", not " + model);
      return law->create(prm, context);
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
