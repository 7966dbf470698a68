#pragma once
// The contact models that a parameter file can name (Contact > Type). Each
// model is registered by one line in source/contact/registry.cc (or, for a
// model outside the library such as a test's, by one register_model()
// call before the parameters are declared); the registry then gives the
// Type selection and its help text, declares and parses each model's own
// subsection, builds the model, and tells the solvers what the model
// offers (Capabilities). doc/architecture.md, 'Extending', says how to add
// a model.

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/types.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>

#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace Signorini
{
  namespace Contact
  {
    using namespace dealii;

    template <int dim>
    class Model;

    /// What a model offers the solvers: which method suits which contact
    /// is decided from these alone (check_solver_compatibility,
    /// create_step_solver).
    struct Capabilities
    {
      /// Node-wise inequality constraints g_k(U) >= 0 with useful
      /// gradients (Model::constraint): Ipopt and the interior point
      /// method impose them. Without them, Method = ipopt minimises
      /// penalty stages and interior-point refuses the scene.
      bool node_wise_constraints = false;
      /// The deformable bodies in contact (1: a body against a rigid
      /// obstacle; 2: Body 1 against Body 2, which must be active). Hertz's
      /// contact modulus sums the compliances of this many bodies.
      unsigned int bodies = 1;
      /// Whether the model acts on 'Contact boundary id' (checked against
      /// the mesh); a model of several pairs names its boundaries itself.
      bool contact_boundary_id = true;
    };

    /// A model's parsed subsection(s); each model derives its own (or uses
    /// ParsedParameters<T>) and reads it back in its create function.
    struct ModelParameters
    {
      virtual ~ModelParameters() = default;
    };

    /// A model's parameters held as one value of type @p T.
    template <typename T>
    struct ParsedParameters : ModelParameters
    {
      explicit ParsedParameters(T value)
        : value(std::move(value))
      {}
      T value;
    };

    /// The value of @p parameters, which hold a @p T (ParsedParameters<T>).
    template <typename T>
    const T &
    parsed(const ModelParameters &parameters)
    {
      return static_cast<const ParsedParameters<T> &>(parameters).value;
    }

    /// A boundary id that a model's parameters name: its key (under
    /// "Contact > ") and the id, checked against the mesh.
    using NamedBoundaryId = std::pair<std::string, types::boundary_id>;

    /**
     * One registered contact model.
     */
    struct ModelEntry
    {
      template <int dim>
      using Creator = std::function<std::unique_ptr<Model<dim>>(const ModelParameters &,
                                                                types::boundary_id,
                                                                const DoFHandler<dim> &,
                                                                const Mapping<dim> &)>;

      /// The value of Contact > Type that selects the model.
      std::string name;
      /// The model's sentence(s) in the help text of Type; starts with name.
      std::string help;
      Capabilities capabilities;
      /// Declare the model's own subsections of "Contact" (prm is in it).
      std::function<void(ParameterHandler &)> declare_parameters;
      /// Parse them (prm is in "Contact") for a scene of dimension @p dim;
      /// bad values throw an InputError naming "Contact > ... > Entry".
      std::function<std::shared_ptr<const ModelParameters>(ParameterHandler &,
                                                           const unsigned int dim)>
        parse_parameters;
      /// The boundary ids that the parameters name besides 'Contact
      /// boundary id' (may be empty).
      std::function<std::vector<NamedBoundaryId>(const ModelParameters &)> boundary_ids;
      /// Build the model on the contact boundary @p boundary_id.
      Creator<2> create_2d;
      Creator<3> create_3d;

      /// Set both create functions from one generic callable
      /// (parameters, boundary id, DoFHandler<dim>, Mapping<dim>) ->
      /// std::unique_ptr<Model<dim>>.
      template <typename Create>
      void
      set_create(const Create &create)
      {
        create_2d = create;
        create_3d = create;
      }
    };

    /**
     * Every registered model, in the order of the Type selection (after
     * "none"): the library's, then those added by register_model(). Checked
     * when first built: unique names without '|' or ',', help starting
     * with the name, every function set (boundary_ids may be empty); a
     * violation is a programming error and throws std::logic_error.
     */
    const std::vector<ModelEntry> &
    registered_models();

    /// The model registered as @p name, or nullptr ("none" is no model).
    const ModelEntry *
    find_model(const std::string &name);

    /// Add a model from outside the library (a test, a user's plug-in);
    /// call it before the parameters are declared.
    void
    register_model(ModelEntry entry);
  } // namespace Contact
} // namespace Signorini
