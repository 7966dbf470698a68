#include <signorini/scene/boundary_conditions.h>
#include <signorini/input_error.h>

#include <deal.II/base/utilities.h>
#include <deal.II/lac/vector.h>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <sstream>

namespace Signorini
{
  template <int dim>
  void
  BoundaryConditions<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry(
      "Fixed boundaries",
      "",
      Patterns::Anything(),
      "Zero displacement: a comma-separated list of 'boundary id: "
      "components', components from x, y, z, e.g. '2: y, 0: x' for a "
      "roller on boundary 2 and another on boundary 0, or '2: xy' to "
      "clamp boundary 2.");
    prm.declare_entry(
      "Fixed points",
      "",
      Patterns::Anything(),
      "Zero displacement at single mesh vertices: a ';'-separated list of "
      "'coordinates: components' [length], e.g. '0, 0: x; 0, 12.7: x' to "
      "hold x at two vertices on the line x = 0 (the rigid-body motion a "
      "full ring between frictionless plates would have). Each point must "
      "be a vertex of the mesh (within 1e-8 of the scene's size); the "
      "components as in 'Fixed boundaries'.");
    prm.declare_entry(
      "Prescribed boundaries",
      "",
      Patterns::Anything(),
      "Prescribed displacement u = 'Prescribed displacement'(x, t) on these "
      "boundary components, same format as 'Fixed boundaries'.");
    prm.declare_entry("Prescribed displacement",
                      "0; 0; 0",
                      Patterns::Anything(),
                      "u_D(x, y[, z], t) [length], dim components "
                      "separated by ';'.");
    prm.declare_entry("Traction boundaries",
                      "",
                      Patterns::List(Patterns::Integer(0, 255)),
                      "Boundary ids that carry the dead traction below.");
    prm.declare_entry("Traction",
                      "0; 0; 0",
                      Patterns::Anything(),
                      "Dead traction t(x, y[, z], t) [force/reference "
                      "area], dim components; x is the reference position "
                      "(nominal traction, e.g. '0; -0.876*t').");
    prm.declare_entry("Body force",
                      "",
                      Patterns::Anything(),
                      "Dead body force rho0 f(x, y[, z], t) [force/reference "
                      "volume], dim components; empty: none (nothing is "
                      "assembled).");
    prm.declare_entry("Function constants",
                      "",
                      Patterns::Anything(),
                      "Constants usable in every expression of this "
                      "subsection, e.g. 'p=0.876, L=1'.");
  }

  std::map<std::string, double>
  parse_constants(const std::string &text, const std::string &key)
  {
    std::map<std::string, double> constants;
    for (const std::string &item : Utilities::split_string_list(text, ','))
      {
        const std::vector<std::string> kv = Utilities::split_string_list(item, '=');
        double value = 0;
        try
          {
            if (kv.size() != 2)
              throw std::invalid_argument("no '='");
            value = Utilities::string_to_double(kv[1]);
          }
        catch (...)
          {
            throw InputError(key,
                             "'" + item + "' is not of the form name=number");
          }
        constants[kv[0]] = value;
      }
    return constants;
  }

  template <int n>
  std::unique_ptr<FunctionParser<n>>
  parse_function(const std::vector<std::string>      &parts,
                 const std::string                   &variables,
                 const std::map<std::string, double> &constants,
                 const bool                           time_dependent,
                 const std::string                   &key)
  {
    std::string expression;
    for (const auto &p : parts)
      expression += (expression.empty() ? "" : "; ") + p;
    auto f = std::make_unique<FunctionParser<n>>(parts.size());
    // muparser writes its diagnostics to std::cerr before deal.II throws;
    // keep them off the user's screen, the exception says the same.
    std::ostringstream     muparser_chatter;
    std::streambuf *const  cerr_buffer = std::cerr.rdbuf(muparser_chatter.rdbuf());
    try
      {
        f->initialize(variables, parts, constants, time_dependent);
        // muparser reports some errors only at evaluation.
        Vector<double> v(parts.size());
        f->vector_value(Point<n>(), v);
        std::cerr.rdbuf(cerr_buffer);
        for (unsigned int c = 0; c < parts.size(); ++c)
          if (!std::isfinite(v[c]))
            throw InputError(key,
                             "'" + expression + "' is not finite at the origin" +
                               (time_dependent ? ", t = 0" : ""));
      }
    catch (const InputError &)
      {
        throw;
      }
    catch (const std::exception &e)
      {
        std::cerr.rdbuf(cerr_buffer);
        throw InputError(key,
                         "cannot parse '" + expression + "' (variables " +
                           variables + "): " + essential_message(e.what()));
      }
    return f;
  }

  template <int dim>
  std::unique_ptr<FunctionParser<dim>>
  parse_vector_function(const std::string                   &expression,
                        const std::map<std::string, double> &constants,
                        const std::string                   &key)
  {
    std::vector<std::string> parts =
      Utilities::split_string_list(expression, ';');
    // Entries declared for 3D may carry a third component in 2D.
    if (parts.size() == 3 && dim == 2)
      parts.resize(2);
    if (parts.size() != dim)
      throw InputError(key,
                       "needs " + std::to_string(dim) +
                         " components separated by ';', got '" + expression +
                         "'");
    return parse_function<dim>(parts, dim == 2 ? "x,y,t" : "x,y,z,t",
                               constants, true, key);
  }

  namespace
  {
    template <int dim>
    std::vector<typename BoundaryConditions<dim>::DirichletPart>
    parse_parts(const std::string                   &text,
                const std::string                   &key,
                const bool                           prescribed,
                const std::set<types::boundary_id>  &mesh_ids)
    {
      std::vector<typename BoundaryConditions<dim>::DirichletPart> parts;
      for (const std::string &item : Utilities::split_string_list(text, ','))
        {
          const std::vector<std::string> kv =
            Utilities::split_string_list(item, ':');
          typename BoundaryConditions<dim>::DirichletPart part;
          part.prescribed = prescribed;
          part.components.assign(dim, false);
          int id = -1;
          try
            {
              if (kv.size() != 2)
                throw std::invalid_argument("");
              id = Utilities::string_to_int(kv[0]);
            }
          catch (...)
            {
              throw InputError(key,
                               "'" + item +
                                 "' is not of the form 'boundary id: "
                                 "components' (e.g. '2: y')");
            }
          if (id < 0 || mesh_ids.count(id) == 0)
            {
              std::string ids;
              for (const auto i : mesh_ids)
                ids += (ids.empty() ? "" : ", ") + std::to_string(i);
              throw InputError(key,
                               "boundary id " + kv[0] +
                                 " does not exist in the mesh (it has " +
                                 ids + ")");
            }
          part.boundary_id = id;
          for (const char c : kv[1])
            {
              const int comp = (c == 'x' ? 0 : c == 'y' ? 1 : c == 'z' ? 2 : -1);
              if (comp < 0 || comp >= dim)
                throw InputError(key,
                                 "component '" + std::string(1, c) + "' in '" +
                                   item + "' is not one of " +
                                   (dim == 2 ? "x, y" : "x, y, z"));
              part.components[comp] = true;
            }
          parts.push_back(part);
        }
      return parts;
    }
  } // namespace

  void
  BoundaryConditionParameters::parse_parameters(ParameterHandler &prm)
  {
    constants = parse_constants(prm.get("Function constants"),
                                "Boundary conditions > Function constants");
    fixed_boundaries        = prm.get("Fixed boundaries");
    fixed_points            = prm.get("Fixed points");
    prescribed_boundaries   = prm.get("Prescribed boundaries");
    prescribed_displacement = prm.get("Prescribed displacement");
    traction_boundaries     = prm.get("Traction boundaries");
    traction                = prm.get("Traction");
    body_force              = prm.get("Body force");
  }

  std::set<types::boundary_id>
  BoundaryConditionParameters::condition_ids() const
  {
    std::set<types::boundary_id> ids;
    for (const auto *list : {&fixed_boundaries, &prescribed_boundaries, &traction_boundaries})
      for (const auto &entry : Utilities::split_string_list(*list))
        {
          // '1: x' (fixed, prescribed) or '2' (traction).
          const std::string id    = Utilities::trim(entry.substr(0, entry.find(':')));
          char             *end   = nullptr;
          const long        value = std::strtol(id.c_str(), &end, 10);
          if (!id.empty() && *end == '\0' && value >= 0 && value <= 255)
            ids.insert(static_cast<types::boundary_id>(value));
        }
    return ids;
  }

  template <int dim>
  void
  BoundaryConditions<dim>::parse_parameters(
    ParameterHandler                   &prm,
    const std::set<types::boundary_id> &mesh_ids)
  {
    BoundaryConditionParameters p;
    p.parse_parameters(prm);
    setup(p, mesh_ids);
  }

  template <int dim>
  void
  BoundaryConditions<dim>::setup(const BoundaryConditionParameters  &p,
                                 const std::set<types::boundary_id> &mesh_ids)
  {
    const std::string ctx       = "Boundary conditions > ";
    const auto       &constants = p.constants;

    dirichlet = parse_parts<dim>(p.fixed_boundaries,
                                 ctx + "Fixed boundaries", false, mesh_ids);
    const auto prescribed = parse_parts<dim>(p.prescribed_boundaries,
                                             ctx + "Prescribed boundaries",
                                             true, mesh_ids);
    dirichlet.insert(dirichlet.end(), prescribed.begin(), prescribed.end());

    // A component of a boundary may be fixed or prescribed, not both.
    std::map<types::boundary_id, std::vector<int>> owner;
    for (const auto &part : dirichlet)
      {
        auto &o = owner[part.boundary_id];
        o.resize(dim, -1);
        for (unsigned int c = 0; c < dim; ++c)
          if (part.components[c])
            {
              if (o[c] >= 0 && o[c] != int(part.prescribed))
                throw InputError(ctx + "Prescribed boundaries",
                                 "component " + std::string(1, "xyz"[c]) +
                                   " of boundary " +
                                   std::to_string(part.boundary_id) +
                                   " is both fixed and prescribed");
              o[c] = part.prescribed;
            }
      }

    points.clear();
    for (const std::string &item : Utilities::split_string_list(p.fixed_points, ';'))
      {
        const std::vector<std::string> kv = Utilities::split_string_list(item, ':');
        FixedPoint                      fixed;
        fixed.text = item;
        fixed.components.assign(dim, false);
        std::vector<std::string> coordinates;
        if (kv.size() == 2)
          coordinates = Utilities::split_string_list(kv[0], ',');
        bool ok = kv.size() == 2 && coordinates.size() == dim && !kv[1].empty();
        for (unsigned int d = 0; ok && d < dim; ++d)
          try
            {
              fixed.point[d] = Utilities::string_to_double(coordinates[d]);
              ok             = std::isfinite(fixed.point[d]);
            }
          catch (...)
            {
              ok = false;
            }
        if (!ok)
          throw InputError(ctx + "Fixed points",
                           "'" + item + "' is not of the form 'coordinates: components' "
                           "with " + std::to_string(dim) + " coordinates (e.g. '" +
                             (dim == 2 ? "0, 0: x" : "0, 0, 0: xy") + "')");
        for (const char c : kv[1])
          {
            const int comp = (c == 'x' ? 0 : c == 'y' ? 1 : c == 'z' ? 2 : -1);
            if (comp < 0 || comp >= dim)
              throw InputError(ctx + "Fixed points",
                               "component '" + std::string(1, c) + "' in '" + item +
                                 "' is not one of " + (dim == 2 ? "x, y" : "x, y, z"));
            fixed.components[comp] = true;
          }
        points.push_back(fixed);
      }

    prescribed_function =
      parse_vector_function<dim>(p.prescribed_displacement,
                                 constants,
                                 ctx + "Prescribed displacement");

    traction_ids.clear();
    traction.reset();
    for (const std::string &s :
         Utilities::split_string_list(p.traction_boundaries))
      {
        const int id = Utilities::string_to_int(s);
        if (mesh_ids.count(id) == 0)
          throw InputError(ctx + "Traction boundaries",
                           "boundary id " + s + " does not exist in the mesh");
        const auto it = owner.find(id);
        if (it != owner.end() &&
            std::count(it->second.begin(), it->second.end(), -1) == 0)
          throw InputError(ctx + "Traction boundaries",
                           "boundary " + s +
                             " has every displacement component imposed, so "
                             "a traction on it would do nothing: "
                             "contradictory boundary conditions");
        traction_ids.insert(id);
      }
    if (!traction_ids.empty())
      traction = parse_vector_function<dim>(p.traction,
                                            constants,
                                            ctx + "Traction");

    body_force.reset();
    if (!p.body_force.empty())
      body_force = parse_vector_function<dim>(p.body_force,
                                              constants,
                                              ctx + "Body force");
  }

  template std::unique_ptr<FunctionParser<1>>
  parse_function<1>(const std::vector<std::string> &, const std::string &,
                    const std::map<std::string, double> &, const bool,
                    const std::string &);
  template std::unique_ptr<FunctionParser<2>>
  parse_function<2>(const std::vector<std::string> &, const std::string &,
                    const std::map<std::string, double> &, const bool,
                    const std::string &);
  template class BoundaryConditions<2>;
  template class BoundaryConditions<3>;
  template std::unique_ptr<FunctionParser<2>>
  parse_vector_function<2>(const std::string &,
                           const std::map<std::string, double> &,
                           const std::string &);
  template std::unique_ptr<FunctionParser<3>>
  parse_vector_function<3>(const std::string &,
                           const std::map<std::string, double> &,
                           const std::string &);
} // namespace Signorini
