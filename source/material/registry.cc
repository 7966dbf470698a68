#include <signorini/input_error.h>
#include <signorini/material/gent.h>
#include <signorini/material/invariant_based.h>
#include <signorini/material/laws.h>
#include <signorini/material/linear_elastic.h>
#include <signorini/material/registry.h>
#include <signorini/parameters/lists.h>

#include <cmath>
#include <stdexcept>
#include <type_traits>

namespace Signorini
{
  namespace Material
  {
    namespace
    {
      // Optional static members of a law type (doc/materials.md).
      template <typename Law, typename = void>
      struct has_declare_parameters : std::false_type
      {};
      template <typename Law>
      struct has_declare_parameters<
        Law,
        std::void_t<decltype(Law::declare_parameters(
          std::declval<ParameterHandler &>()))>> : std::true_type
      {};

      template <typename Law, typename = void>
      struct supports_incompressible : std::false_type
      {};
      template <typename Law>
      struct supports_incompressible<
        Law,
        std::void_t<decltype(Law::supports_incompressible)>>
        : std::bool_constant<Law::supports_incompressible>
      {};

      template <typename Law, typename = void>
      struct frame_invariant : std::true_type
      {};
      template <typename Law>
      struct frame_invariant<Law,
                             std::void_t<decltype(Law::frame_invariant)>>
        : std::bool_constant<Law::frame_invariant>
      {};

      /**
       * The registry entry of a law type. Required static members:
       * model_name, help, uses_young_poisson, from_parameters(prm,
       * context) and examples(); optional: declare_parameters(prm),
       * supports_incompressible (default false), frame_invariant (default
       * true). A type derived from Interface is used as it is; any other
       * is a law struct with energy(I1, I2, J), wrapped in InvariantLaw
       * (and, if it has invariant_derivatives(), also registered with its
       * Sacado oracle, create_automatic).
       */
      template <typename Law>
      LawEntry
      registration()
      {
        LawEntry entry;
        entry.name                    = Law::model_name;
        entry.help                    = Law::help;
        entry.uses_young_poisson      = Law::uses_young_poisson;
        entry.supports_incompressible = supports_incompressible<Law>::value;
        entry.frame_invariant         = frame_invariant<Law>::value;
        if constexpr (has_declare_parameters<Law>::value)
          entry.declare_parameters = [](ParameterHandler &prm) {
            Law::declare_parameters(prm);
          };
        else
          entry.declare_parameters = [](ParameterHandler &) {};
        entry.create = [](ParameterHandler  &prm,
                          const std::string &context)
          -> std::unique_ptr<Interface> {
          if constexpr (std::is_base_of_v<Interface, Law>)
            return std::make_unique<Law>(Law::from_parameters(prm, context));
          else
            return std::make_unique<InvariantLaw<Law>>(
              Law::from_parameters(prm, context));
        };
        if constexpr (!std::is_base_of_v<Interface, Law>)
          if constexpr (InvariantLaw<Law>::closed_form_available)
            entry.create_automatic = [](ParameterHandler  &prm,
                                        const std::string &context)
              -> std::unique_ptr<Interface> {
              return std::make_unique<InvariantLaw<Law>>(
                Law::from_parameters(prm, context),
                Differentiation::automatic);
            };
        entry.examples = Law::examples();
        return entry;
      }

      void
      check_registry(const std::vector<LawEntry> &laws)
      {
        for (unsigned int i = 0; i < laws.size(); ++i)
          {
            const LawEntry &law = laws[i];
            auto fail = [&](const std::string &what) {
              throw std::logic_error("material law '" + law.name +
                                     "' is registered with " + what);
            };
            if (law.name.empty() ||
                law.name.find_first_of("|,") != std::string::npos)
              fail("an empty name or one with '|' or ','");
            for (unsigned int j = 0; j < i; ++j)
              if (laws[j].name == law.name)
                fail("a name registered before");
            if (law.help.compare(0, law.name.size(), law.name) != 0)
              fail("a help text that does not start with its name");
            if (law.examples.empty())
              fail("no example");
          }
      }
    } // namespace

    const std::vector<LawEntry> &
    registered_laws()
    {
      // One line per law, in the order in which the Model selection lists
      // them; a new law goes at the end (doc/materials.md).
      static const std::vector<LawEntry> laws = [] {
        std::vector<LawEntry> list = {
          registration<NeoHookeanLaw>(),
          registration<ElasHyperLaw>(),
          registration<SaintVenantKirchhoffLaw>(),
          registration<LinearElastic>(),
          registration<GentLaw>(),
        };
        check_registry(list);
        return list;
      }();
      return laws;
    }

    const LawEntry *
    find_law(const std::string &name)
    {
      for (const LawEntry &law : registered_laws())
        if (law.name == name)
          return &law;
      return nullptr;
    }

    double
    positive_constant(ParameterHandler  &prm,
                      const std::string &context,
                      const std::string &key)
    {
      const double v = prm.get_double(key);
      if (!(v > 0.) || !std::isfinite(v))
        throw InputError(context + " > " + key,
                         "must be a finite number > 0, got " + prm.get(key));
      return v;
    }

    double
    poisson_ratio(ParameterHandler &prm, const std::string &context)
    {
      const double nu = prm.get_double("Poisson's ratio");
      if (!(nu > -1. && nu < 0.5))
        throw InputError(context + " > Poisson's ratio",
                         "must lie in (-1, 0.5) for a compressible law, got " +
                           prm.get("Poisson's ratio") +
                           " (nu = 0.5 is incompressible: impose J = 1 as a "
                           "constraint instead)");
      return nu;
    }

    std::pair<double, double>
    lame_from_young_poisson(ParameterHandler  &prm,
                            const std::string &context)
    {
      require_set(prm, "Young's modulus", context);
      const double E  = positive_constant(prm, context, "Young's modulus");
      const double nu = poisson_ratio(prm, context);
      return {E / (2. * (1. + nu)), E * nu / ((1. + nu) * (1. - 2. * nu))};
    }
  } // namespace Material
} // namespace Signorini
