#pragma once

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/fe/component_mask.h>

#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace Signorini
{
  using namespace dealii;

  /**
   * Dirichlet conditions and dead loads, from the "Boundary conditions"
   * subsection. Expressions are muparser strings with variables x, y (, z)
   * and the load-stepping time t; vector expressions separate their
   * components by ';'. A load that is not declared is not assembled.
   */
  /**
   * The "Boundary conditions" subsection as written: boundary lists and
   * function expressions (checked against the mesh's boundary ids and
   * compiled when the BoundaryConditions are set up), and the function
   * constants, parsed here.
   */
  struct BoundaryConditionParameters
  {
    std::string                   fixed_boundaries;
    std::string                   fixed_points;
    std::string                   prescribed_boundaries;
    std::string                   prescribed_displacement;
    std::string                   traction_boundaries;
    std::string                   traction;
    std::string                   body_force;
    std::map<std::string, double> constants;

    void
    parse_parameters(ParameterHandler &prm);

    /// The boundary ids that carry a condition: the ids of 'Fixed
    /// boundaries', 'Prescribed boundaries' and 'Traction boundaries'
    /// (an entry that is no id is left to BoundaryConditions::setup()'s
    /// error).
    std::set<types::boundary_id>
    condition_ids() const;
  };

  template <int dim>
  class BoundaryConditions
  {
  public:
    struct DirichletPart
    {
      types::boundary_id boundary_id;
      std::vector<bool>  components; // dim entries
      bool               prescribed; // false: zero displacement
    };

    static void
    declare_parameters(ParameterHandler &prm);

    /**
     * Parse and check against the boundary ids that exist in the mesh.
     * Throws InputError naming the entry on any problem.
     */
    /// Build the boundary conditions of @p parameters on a mesh whose
    /// boundary ids are @p mesh_boundary_ids (InputError on bad input).
    void
    setup(const BoundaryConditionParameters  &parameters,
          const std::set<types::boundary_id> &mesh_boundary_ids);

    /// Parse the current subsection of @p prm and set up (for tests).
    void
    parse_parameters(ParameterHandler                   &prm,
                     const std::set<types::boundary_id> &mesh_boundary_ids);

    /// Whether a Dirichlet part moves with the load time.
    bool
    has_prescribed_motion() const
    {
      for (const auto &part : dirichlet)
        if (part.prescribed)
          return true;
      return false;
    }

    const std::vector<DirichletPart> &
    dirichlet_parts() const
    {
      return dirichlet;
    }

    /// A mesh vertex whose displacement components are held at zero
    /// ('Fixed points': e.g. a rigid-body mode that no boundary can stop).
    struct FixedPoint
    {
      Point<dim>        point;
      std::vector<bool> components; // dim entries
      std::string       text;       // as written, for messages
    };

    const std::vector<FixedPoint> &
    fixed_points() const
    {
      return points;
    }

    /// The prescribed displacement u_D(x, t) (dim components).
    Function<dim> &
    prescribed_displacement() const
    {
      return *prescribed_function;
    }

    bool
    has_traction() const
    {
      return traction != nullptr;
    }
    bool
    is_traction_boundary(const types::boundary_id id) const
    {
      return traction_ids.count(id) > 0;
    }
    /// Dead traction t(X, t), force per unit reference area.
    Function<dim> &
    traction_function() const
    {
      return *traction;
    }

    bool
    has_body_force() const
    {
      return body_force != nullptr;
    }
    /// Dead body force rho0 f(X, t), force per unit reference volume.
    Function<dim> &
    body_force_function() const
    {
      return *body_force;
    }

  private:
    std::vector<DirichletPart>             dirichlet;
    std::vector<FixedPoint>                points;
    std::unique_ptr<FunctionParser<dim>>   prescribed_function;
    std::set<types::boundary_id>           traction_ids;
    std::unique_ptr<FunctionParser<dim>>   traction;
    std::unique_ptr<FunctionParser<dim>>   body_force;
  };

  /**
   * Parse a vector-valued muparser expression with variables x, y (, z), t
   * and the given constants; throws InputError naming @p key on failure.
   */
  template <int dim>
  std::unique_ptr<FunctionParser<dim>>
  parse_vector_function(const std::string                   &expression,
                        const std::map<std::string, double> &constants,
                        const std::string                   &key);

  /**
   * Parse a function of n variables with one component per entry of
   * @p parts (muparser syntax), variables named in @p variables (comma
   * separated, with ",t" last if @p time_dependent), and the given
   * constants. Throws InputError naming @p key if it does not parse or is
   * not finite at the origin.
   */
  template <int n>
  std::unique_ptr<FunctionParser<n>>
  parse_function(const std::vector<std::string>      &parts,
                 const std::string                   &variables,
                 const std::map<std::string, double> &constants,
                 const bool                           time_dependent,
                 const std::string                   &key);

  /// Parse "name=value, name=value" into constants; InputError on failure.
  std::map<std::string, double>
  parse_constants(const std::string &text, const std::string &key);
} // namespace Signorini
