// The parameters of the laws of laws.h: their own entries of the Material
// subsection, how their constants are read and checked, and the examples
// the tests run.

#include <signorini/input_error.h>
#include <signorini/material/laws.h>
#include <signorini/parameters/lists.h>

namespace Signorini
{
  namespace Material
  {
    NeoHookeanLaw
    NeoHookeanLaw::from_parameters(ParameterHandler  &prm,
                                   const std::string &context)
    {
      const auto [mu, lambda] = lame_from_young_poisson(prm, context);
      return NeoHookeanLaw{mu, lambda};
    }

    std::vector<Example>
    NeoHookeanLaw::examples()
    {
      return {{"", {{"Young's modulus", "3"}, {"Poisson's ratio", "0.3"}}}};
    }

    void
    ElasHyperLaw::declare_parameters(ParameterHandler &prm)
    {
      prm.declare_entry("C10",
                        "1",
                        Patterns::Double(),
                        "ELAS_HYPER constant C10 [stress]; must be set: no "
                        "default is taken.",
                        /*has_to_be_set=*/true);
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
    }

    ElasHyperLaw
    ElasHyperLaw::from_parameters(ParameterHandler  &prm,
                                  const std::string &context)
    {
      ElasHyperLaw law;
      require_set(prm, "C10", context);
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
          const double nu = poisson_ratio(prm, context);
          law.K = 6. * (law.C10 + law.C01) / (3. * (1. - 2. * nu));
        }
      return law;
    }

    std::vector<Example>
    ElasHyperLaw::examples()
    {
      return {{"ELAS_HYPER neo-Hookean",
               {{"C10", "1.2345"}, {"Bulk modulus", "1234.5"}}},
              {"ELAS_HYPER Mooney-Rivlin",
               {{"C10", "0.709"}, {"C01", "2.3456"}, {"Bulk modulus", "2000"}}},
              {"ELAS_HYPER C20",
               {{"C10", "0.1234"},
                {"C01", "1.2345"},
                {"C20", "0.456"},
                {"Bulk modulus", "500"}}},
              {"ELAS_HYPER isochoric part",
               {{"C10", "0.709"},
                {"C01", "2.3456"},
                {"C20", "0.456"},
                {"Incompressible", "true"}}}};
    }

    SaintVenantKirchhoffLaw
    SaintVenantKirchhoffLaw::from_parameters(ParameterHandler  &prm,
                                             const std::string &context)
    {
      const auto [mu, lambda] = lame_from_young_poisson(prm, context);
      return SaintVenantKirchhoffLaw{mu, lambda};
    }

    std::vector<Example>
    SaintVenantKirchhoffLaw::examples()
    {
      return {{"", {{"Young's modulus", "3"}, {"Poisson's ratio", "0.3"}}}};
    }
  } // namespace Material
} // namespace Signorini
