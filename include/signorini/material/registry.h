#pragma once

// The list of material laws that a parameter file can name (Material >
// Model). Each law is registered by one line in source/material/registry.cc;
// the registry then gives the Model selection and its help text
// (Material::declare_parameters), finds the law that Material::create
// builds, and lets the tests loop over every law. doc/materials.md says how
// to add a law.

#include <signorini/material/interface.h>

#include <deal.II/base/parameter_handler.h>

#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace Signorini
{
  namespace Material
  {
    using namespace dealii;

    /**
     * A set of constants that exercises a law: entries of the Material
     * subsection and their values (entries not listed keep their
     * defaults). The tests (tests/material_derivatives.cc) build every
     * example of every registered law and check its derivatives.
     */
    struct Example
    {
      /// How the tests name this example; empty: the material's name().
      std::string label;
      std::vector<std::pair<std::string, std::string>> settings;
    };

    /**
     * One registered law. Built from a law type by
     * registration<Law>() (source/material/registry.cc), which reads the
     * static members documented in doc/materials.md.
     */
    struct LawEntry
    {
      /// The value of Material > Model that selects the law.
      std::string name;
      /// The law's sentence(s) in the help text of Model; starts with name.
      std::string help;
      /// Whether the law takes its constants from 'Young's modulus' and
      /// 'Poisson's ratio' (the help text of Young's modulus lists these
      /// laws).
      bool uses_young_poisson = false;
      /// Whether 'Incompressible = true' is allowed (the law drops its
      /// volumetric term and the solver imposes J = 1).
      bool supports_incompressible = false;
      /// Whether psi(QF) = psi(F) for rotations Q (false for small-strain
      /// linear elasticity).
      bool frame_invariant = true;
      /// Declare the law's own entries of the Material subsection (the
      /// shared ones, Model, Young's modulus, Poisson's ratio and
      /// Incompressible, are declared by Material::declare_parameters).
      std::function<void(ParameterHandler &)> declare_parameters;
      /**
       * Build the law from the current (Material) subsection of a
       * ParameterHandler; invalid constants throw an InputError naming
       * "context > Entry".
       */
      std::function<std::unique_ptr<Interface>(ParameterHandler &,
                                               const std::string &context)>
        create;
      /**
       * For a law written as energy(I1, I2, J) that also gives its
       * invariant derivatives in closed form: the same law built as
       * create() does, but differentiated by Sacado
       * (Differentiation::automatic), the oracle against which the tests
       * check the closed form. Empty for other laws.
       */
      std::function<std::unique_ptr<Interface>(ParameterHandler &,
                                               const std::string &context)>
        create_automatic;
      /// At least one example (the tests use them).
      std::vector<Example> examples;
    };

    /**
     * Every registered law, in the order of the Model selection. Built on
     * first use (a function-local static: no dependence on the order in
     * which the shared library's static objects are initialised), and
     * checked then: unique names without '|' or ',', help starting with the
     * name, at least one example; a violation is a programming error and
     * throws std::logic_error.
     */
    const std::vector<LawEntry> &
    registered_laws();

    /// The law registered as @p name, or nullptr.
    const LawEntry *
    find_law(const std::string &name);

    // Readers of constants shared by the laws' from_parameters().

    /// The entry @p key as a finite number > 0, else an InputError
    /// "context > key: must be a finite number > 0, got ...".
    double
    positive_constant(ParameterHandler  &prm,
                      const std::string &context,
                      const std::string &key);

    /// 'Poisson's ratio' in (-1, 0.5), else an InputError.
    double
    poisson_ratio(ParameterHandler &prm, const std::string &context);

    /**
     * The Lamé constants (mu, lambda) = (E/(2(1+nu)),
     * E nu/((1+nu)(1-2nu))) from 'Young's modulus' E > 0 and 'Poisson's
     * ratio' nu (checked in this order).
     */
    std::pair<double, double>
    lame_from_young_poisson(ParameterHandler  &prm,
                            const std::string &context);
  } // namespace Material
} // namespace Signorini
