#include <signorini/input_error.h>
#include <signorini/contact/pairs_parameters.h>
#include <signorini/contact/registry.h>
#include <signorini/material/interface.h>
#include <signorini/parameters/lists.h>
#include <signorini/parameters/scene_parameters.h>
#include <signorini/parameters/study_parameters.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>

namespace Signorini
{
  namespace Parameters
  {
    void
    Global::declare_parameters(ParameterHandler &prm)
    {
      prm.declare_entry("Dimension",
                        "2",
                        Patterns::Integer(2, 3),
                        "Space dimension: 2 (plane strain) or 3.");
      prm.declare_entry("Scene name",
                        "",
                        Patterns::Anything(),
                        "Name of the scene in summary.json; empty: the "
                        "parameter file name without its extension.");
      prm.declare_entry("Output directory",
                        "",
                        Patterns::Anything(),
                        "Folder for every output file, created if needed; "
                        "empty: output/<scene name>. Relative paths are "
                        "relative to the working directory.");
    }

    void
    Global::parse_parameters(ParameterHandler &prm, const std::string &file)
    {
      const std::filesystem::path path(file);
      parameter_file      = file;
      parameter_directory = path.parent_path().string();
      dimension           = prm.get_integer("Dimension");
      scene               = prm.get("Scene name");
      if (scene.empty())
        scene = path.stem().string();
      output_directory = prm.get("Output directory");
      if (output_directory.empty())
        output_directory = "output/" + scene;
    }

    void
    Discretization::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Discretization");
      prm.declare_entry("Polynomial degree",
                        "1",
                        Patterns::Integer(1, 2),
                        "Degree p of the FE_Q(p)^dim displacement element; "
                        "the mapping is of the same degree unless 'Mapping "
                        "degree' says otherwise (curved cells follow curved "
                        "boundaries for p = 2).");
      prm.declare_entry("Mapping degree",
                        "0",
                        Patterns::Integer(0, 3),
                        "Degree of the MappingQ that maps the cells; 0: the "
                        "polynomial degree. 2 with Q1 elements makes the "
                        "cells at a curved boundary follow its manifold "
                        "(sphere, cylinder), so that areas and volumes there, "
                        "e.g. the area of a ball's flat top whose rim is "
                        "curved and with it the total of a traction on it, "
                        "are exact to O(h^4) instead of O(h^2); the contact "
                        "nodes are the same.");
      prm.leave_subsection();
    }

    void
    Discretization::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Discretization");
      degree         = prm.get_integer("Polynomial degree");
      mapping_degree = prm.get_integer("Mapping degree");
      if (mapping_degree == 0)
        mapping_degree = degree;
      prm.leave_subsection();
    }

    std::string
    Body::section(const unsigned int b)
    {
      return "Body " + std::to_string(b + 1);
    }

    void
    Body::declare_parameters(ParameterHandler &prm, const unsigned int b)
    {
      prm.enter_subsection(section(b));
      prm.declare_entry("Active",
                        b == 0 ? "true" : "false",
                        Patterns::Bool(),
                        "Whether the scene has this body.");
      prm.declare_entry("Material id",
                        std::to_string(b),
                        Patterns::Integer(0, 255),
                        "Cells with this material id belong to the body "
                        "(generated meshes give all the body's cells this "
                        "id; in a Gmsh file it is the physical tag).");
      prm.declare_entry("Self contact",
                        "false",
                        Patterns::Bool(),
                        "Whether this body may fold onto itself: each of its "
                        "'Self contact boundary ids' is kept out of the body "
                        "itself, as a self-contact pair of Contact > Type = "
                        "pairs (the same as listing the ids in Contact > "
                        "Pairs > Self-contact boundary ids; numbered after "
                        "those).");
      prm.declare_entry("Self contact boundary ids",
                        "",
                        Patterns::Anything(),
                        "With 'Self contact = true': the boundary ids of this "
                        "body, separated by commas, that may touch the body "
                        "itself (e.g. 0, a ring's or tube's inner surface).");
      prm.enter_subsection("Geometry");
      BodyGeometry::declare_parameters(prm);
      prm.leave_subsection();
      prm.enter_subsection("Material");
      Material::declare_parameters(prm);
      prm.leave_subsection();
      prm.leave_subsection();
    }

    void
    LoadStepping::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Load stepping");
      prm.declare_entry("End time",
                        "1",
                        Patterns::Double(),
                        "Loads and prescribed displacements are functions of "
                        "the pseudo-time t, stepped from 0 to this value; > 0.");
      prm.declare_entry("Number of steps",
                        "1",
                        Patterns::Integer(),
                        "Initial number of equal load steps; >= 1. A step "
                        "whose Newton solve fails is halved and retried.");
      prm.declare_entry("Minimum step fraction",
                        "1e-4",
                        Patterns::Double(),
                        "Smallest step size, as a fraction of the end time, "
                        "that step cutting may reach before the run fails; in "
                        "(0, 1].");
      prm.declare_entry("Sliding direction",
                        "",
                        Patterns::Anything(),
                        "Steady sliding (e.g. ironing): the direction, one "
                        "entry per coordinate, along which the body that the "
                        "prescribed displacements move (the slider; one body) "
                        "slides over the others. Each load step then starts "
                        "from the previous state carried along by the step's "
                        "prescribed motion along this direction, d: the "
                        "slider shifted by d, and every other body's "
                        "displacement at X taken from X - d, where the "
                        "deformation was one step earlier (nodes with X - d "
                        "outside their body keep theirs). Empty: each step "
                        "starts from the previous state (with the tangent "
                        "predictor of the prescribed increment).");
      prm.leave_subsection();
    }

    void
    LoadStepping::parse_parameters(ParameterHandler &prm, const unsigned int dim)
    {
      prm.enter_subsection("Load stepping");
      end_time          = prm.get_double("End time");
      const int steps   = prm.get_integer("Number of steps");
      min_step_fraction = prm.get_double("Minimum step fraction");
      if (!(end_time > 0.) || !std::isfinite(end_time))
        throw InputError("Load stepping > End time",
                         "must be > 0, got " + prm.get("End time"));
      if (steps < 1)
        throw InputError("Load stepping > Number of steps",
                         "must be >= 1, got " + prm.get("Number of steps"));
      if (!(min_step_fraction > 0. && min_step_fraction <= 1.))
        throw InputError("Load stepping > Minimum step fraction",
                         "must lie in (0, 1], got " +
                           prm.get("Minimum step fraction"));
      n_steps = steps;
      sliding_direction.clear();
      const std::string key = "Sliding direction";
      const auto        n   = Utilities::split_string_list(prm.get(key)).size();
      if (n > 0)
        {
          if (n != dim)
            throw InputError("Load stepping > " + key,
                             "needs " + std::to_string(dim) +
                               " entries (Dimension), got '" + prm.get(key) + "'");
          sliding_direction = get_list<double>(prm, key, dim, "Load stepping");
          double norm = 0.;
          for (const double x : sliding_direction)
            norm += x * x;
          if (!(norm > 0.))
            throw InputError("Load stepping > " + key,
                             "must not be the zero vector, got '" + prm.get(key) + "'");
          for (double &x : sliding_direction)
            x /= std::sqrt(norm);
        }
      prm.leave_subsection();
    }

    const SelectionTable<Solver::Method> &
    Solver::methods()
    {
      static const SelectionTable<Method> table = {
        {Method::newton, "newton"},
        {Method::newton_penalty, "newton-penalty"},
        {Method::ipopt, "ipopt"},
        {Method::interior_point, "interior-point"},
        {Method::automatic, "automatic"}};
      return table;
    }

    void
    Solver::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Solver");
      prm.declare_entry("Method",
                        "automatic",
                        Patterns::Selection(selection_pattern(methods())),
                        "automatic (the default): interior-point for a "
                        "rigid foundation (the default scene's solver) and "
                        "for incompressible bodies without contact, "
                        "newton-penalty for two bodies (ipopt if a body is "
                        "incompressible), newton without contact; the "
                        "summary names the method used. "
                        "newton: Newton's method on the total potential "
                        "energy with an Armijo line search (no contact). "
                        "newton-penalty: the same on E + mu/3 sum w_k "
                        "<-g_k>^3 with penalty continuation (contact; runs "
                        "with MPI). ipopt: the interior point optimiser with "
                        "the contact and incompressibility constraints and "
                        "exact derivatives (one MPI rank); for two-body "
                        "contact it minimises each stage of the penalty "
                        "continuation without constraints. interior-point: "
                        "the program's own primal-dual interior point method "
                        "with the rigid foundation's node-wise constraints "
                        "(Mehrotra predictor-corrector, the Newton system "
                        "condensed onto the displacement and solved by the "
                        "Linear solver; runs with MPI).");
      prm.enter_subsection("Newton");
      NewtonParameters::declare_parameters(prm);
      prm.leave_subsection();
      prm.enter_subsection("Penalty");
      ContinuationParameters::declare_parameters(prm);
      prm.leave_subsection();
      prm.enter_subsection("Ipopt");
      IpoptParameters::declare_parameters(prm);
      prm.leave_subsection();
      prm.enter_subsection("Interior point");
      InteriorPointParameters::declare_parameters(prm);
      prm.leave_subsection();
      prm.enter_subsection("Linear solver");
      LinearSolver::Parameters::declare_parameters(prm);
      prm.leave_subsection();
      prm.leave_subsection();
    }

    void
    Solver::parse_parameters(ParameterHandler &prm, const std::string &prm_directory)
    {
      prm.enter_subsection("Solver");
      method = selection_value(prm.get("Method"), methods());
      prm.enter_subsection("Newton");
      newton.parse_parameters(prm);
      prm.leave_subsection();
      prm.enter_subsection("Penalty");
      penalty.parse_parameters(prm);
      prm.leave_subsection();
      prm.enter_subsection("Ipopt");
      ipopt.parse_parameters(prm, prm_directory);
      prm.leave_subsection();
      prm.enter_subsection("Interior point");
      interior_point.parse_parameters(prm);
      prm.leave_subsection();
      prm.enter_subsection("Linear solver");
      linear.parse_parameters(prm);
      ipopt.mumps_pivot_order = linear.mumps_ordering;
      prm.leave_subsection();
      prm.leave_subsection();
    }

    void
    ContactSection::declare_parameters(ParameterHandler &prm)
    {
      const auto &models = Signorini::Contact::registered_models();
      std::string names = "none", help = "none: no contact (no contact structures are built).";
      for (const auto &model : models)
        {
          names += "|" + model.name;
          help += " " + model.help;
        }
      prm.enter_subsection("Contact");
      prm.declare_entry("Type", "none", Patterns::Selection(names), help);
      prm.declare_entry("Contact boundary id",
                        "0",
                        Patterns::Integer(0, 255),
                        "Gamma_2 (Gamma_C of body 1 for two bodies): the "
                        "boundary id of the potential contact boundary.");
      for (const auto &model : models)
        model.declare_parameters(prm);
      prm.enter_subsection("Hertz reference");
      Signorini::Contact::HertzReference::declare_parameters(prm);
      prm.leave_subsection();
      prm.enter_subsection("Friction");
      Signorini::Contact::FrictionParameters::declare_parameters(prm);
      prm.leave_subsection();
      prm.leave_subsection();
    }

    std::string
    ContactSection::type() const
    {
      return model ? model->name : "none";
    }

    bool
    ContactSection::node_wise_constraints() const
    {
      return model && model->capabilities.node_wise_constraints;
    }

    void
    ContactSection::parse_parameters(ParameterHandler &prm, const unsigned int dim)
    {
      prm.enter_subsection("Contact");
      model            = Signorini::Contact::find_model(prm.get("Type"));
      model_parameters = model ? model->parse_parameters(prm, dim) : nullptr;
      boundary_id      = prm.get_integer("Contact boundary id");
      prm.enter_subsection("Hertz reference");
      hertz.parse_parameters(prm);
      prm.leave_subsection();
      prm.enter_subsection("Friction");
      friction.parse_parameters(prm);
      prm.leave_subsection();
      prm.leave_subsection();
    }

    void
    Scene::declare_parameters(ParameterHandler &prm)
    {
      Global::declare_parameters(prm);
      Discretization::declare_parameters(prm);

      prm.enter_subsection("Mesh");
      MeshParameters::declare_parameters(prm);
      prm.leave_subsection();

      prm.enter_subsection("Mesh refinement");
      RefinementParameters::declare_parameters(prm);
      prm.leave_subsection();

      Study::declare_parameters(prm);

      for (unsigned int b = 0; b < Body::max_bodies; ++b)
        Body::declare_parameters(prm, b);

      prm.enter_subsection("Boundary conditions");
      BoundaryConditions<2>::declare_parameters(prm);
      prm.leave_subsection();

      LoadStepping::declare_parameters(prm);
      Solver::declare_parameters(prm);
      ContactSection::declare_parameters(prm);
      PostprocessParameters::declare_parameters(prm);
      CheckpointParameters::declare_parameters(prm);
    }

    void
    Scene::parse_parameters(ParameterHandler &prm, const std::string &file)
    {
      global.parse_parameters(prm, file);
      const unsigned int dim = global.dimension;
      discretization.parse_parameters(prm);

      prm.enter_subsection("Mesh");
      mesh.parse_parameters(prm, global.parameter_directory);
      prm.leave_subsection();
      prm.enter_subsection("Mesh refinement");
      refinement.parse_parameters(prm);
      prm.leave_subsection();

      bodies.clear();
      for (unsigned int b = 0; b < Body::max_bodies; ++b)
        {
          const std::string section = Body::section(b);
          prm.enter_subsection(section);
          if (prm.get_bool("Active"))
            {
              Body body;
              body.material_id = prm.get_integer("Material id");
              for (const auto &other : bodies)
                if (other.material_id == body.material_id)
                  throw InputError(section + " > Material id",
                                   "material id " +
                                     std::to_string(body.material_id) +
                                     " is already used by another body");
              if (prm.get_bool("Self contact"))
                {
                  const std::string key = section + " > Self contact boundary ids";
                  for (const auto &entry :
                       Utilities::split_string_list(prm.get("Self contact boundary ids")))
                    {
                      char      *end = nullptr;
                      const long id  = std::strtol(entry.c_str(), &end, 10);
                      if (entry.empty() || *end != '\0' || id < 0 || id > 255)
                        throw InputError(key, "'" + entry +
                                                "' is not a boundary id (0 to 255)");
                      body.self_contact_ids.push_back(static_cast<types::boundary_id>(id));
                    }
                  if (body.self_contact_ids.empty())
                    throw InputError(key, "'Self contact = true' needs the boundary ids "
                                          "of this body that may touch it");
                }
              prm.enter_subsection("Geometry");
              body.geometry.parse_parameters(prm, dim, section + " > Geometry");
              prm.leave_subsection();
              prm.enter_subsection("Material");
              body.incompressible = prm.get_bool("Incompressible");
              body.material = Material::create(prm, section + " > Material");
              prm.leave_subsection();
              bodies.push_back(std::move(body));
            }
          prm.leave_subsection();
        }
      if (bodies.empty())
        throw InputError("Body 1 > Active", "the scene has no active body");

      load_stepping.parse_parameters(prm, dim);
      solver.parse_parameters(prm, global.parameter_directory);

      prm.enter_subsection("Boundary conditions");
      boundary_conditions.parse_parameters(prm);
      prm.leave_subsection();

      contact.parse_parameters(prm, dim);
      if (solver.method == Solver::Method::automatic)
        {
          const bool incompressible = !incompressible_ids().empty();
          using Method              = Solver::Method;
          solver.method =
            !contact.active() ?
              (incompressible ? Method::interior_point : Method::newton) :
            contact.node_wise_constraints() ?
              Method::interior_point :
              (incompressible ? Method::ipopt : Method::newton_penalty);
        }
      if (contact.active() && bodies.size() < contact.model->capabilities.bodies)
        throw InputError("Contact > Type",
                         contact.type() + " needs Body 2 > Active = true");
      auto &hertz = contact.hertz;
      const std::string hertz_load = std::string("Contact > Hertz reference > ") +
                                     (hertz.point_contact() ? "Point load" : "Line load");
      if (hertz.active() && !contact.active())
        throw InputError(hertz_load,
                         "a Hertz reference needs contact (Contact > Type)");
      if (hertz.point_contact() && dim != 3)
        throw InputError(hertz_load,
                         "point contact (a sphere) needs Dimension = 3; in 2D "
                         "use 'Line load'");
      if (hertz.line_load > 0. && dim != 2)
        throw InputError(hertz_load,
                         "line contact is per unit thickness (Dimension = 2); "
                         "in 3D use 'Point load' (a sphere)");
      if (contact.friction.mindlin_reference && !(hertz.active() && contact.friction.active()))
        throw InputError("Contact > Friction > Mindlin reference > Active",
                         "Mindlin's solution needs a Hertz reference (Contact > "
                         "Hertz reference) and friction (Coefficient > 0)");
      if (hertz.active() && hertz.contact_modulus <= 0.)
        {
          // 1/E* = sum over the bodies in contact of (1 - nu^2)/E.
          double compliance = 0.;
          const unsigned int n = contact.model->capabilities.bodies;
          for (unsigned int b = 0; b < n; ++b)
            compliance += hertz_compliance(bodies[b]);
          hertz.contact_modulus = 1. / compliance;
        }
      const auto *pairs_parameters =
        dynamic_cast<const Signorini::Contact::ParsedParameters<
          Signorini::Contact::PairsParameters> *>(contact.model_parameters.get());
      for (unsigned int b = 0; b < bodies.size(); ++b)
        if (!bodies[b].self_contact_ids.empty() && !pairs_parameters)
          throw InputError(Body::section(b) + " > Self contact",
                           "self-contact is a contact pair: it needs Contact > "
                           "Type = pairs");
      if (pairs_parameters)
        parse_pairs(pairs_parameters->value);

      postprocess.parse_parameters(prm, dim);
      checkpoint.parse_parameters(prm);
    }

    double
    Scene::hertz_compliance(const Body &body)
    {
      // An incompressible body (J = 1 constraints, no bulk term): nu = 1/2
      // and E = 3 G, so (1 - nu^2)/E = 1/(4 G).
      if (body.incompressible)
        return 1. / (4. * body.material->small_strain_lame().first);
      const auto [E, nu] = Material::small_strain_young_poisson(*body.material);
      return (1. - nu * nu) / E;
    }

    void
    Scene::add_free_surface_pair(Signorini::Contact::PairsParameters &pairs) const
    {
      const unsigned int dim = global.dimension;
      const std::string  key = "Contact > Pairs > Contact boundaries";
      if (mesh.source != MeshParameters::Source::generated)
        {
          if (bodies.size() < 2)
            return;
          throw InputError(key, "the bodies of a Gmsh mesh do not say which of "
                                "their surfaces may touch before it is read: "
                                "name them, or set 'Two-body pairs' to a list "
                                "of pairs or to none");
        }
      const std::set<types::boundary_id> conditions = boundary_conditions.condition_ids();
      std::vector<types::boundary_id> free;
      unsigned int                    bodies_with_free = 0;
      for (const auto &body : bodies)
        {
          bool any = false;
          for (const auto id : body.geometry.boundary_ids(dim))
            if (!conditions.count(id))
              {
                free.push_back(id);
                any = true;
              }
          bodies_with_free += any;
        }
      if (bodies_with_free < 2)
        return;
      Signorini::Contact::PairsParameters::Pair pair;
      pair.contact = pair.target = free.front();
      pair.all                   = true;
      pairs.contact_boundaries   = free;
      pairs.pairs.insert(pairs.pairs.begin(), pair);
      pairs.hertz.insert(pairs.hertz.begin(), Signorini::Contact::HertzReference());
    }

    void
    Scene::parse_pairs(const Signorini::Contact::PairsParameters &parsed)
    {
      const unsigned int dim   = global.dimension;
      auto               pairs = parsed;
      if (contact.hertz.active())
        throw InputError("Contact > Hertz reference > " +
                           std::string(contact.hertz.point_contact() ? "Point load" :
                                                                       "Line load"),
                         "with Type = pairs each pair has its own reference: "
                         "Contact > Pairs > Pair K > Hertz reference");
      pairs.body_material_ids = material_ids();
      // The bodies' self-contact boundaries: pairs after the listed ones,
      // before the foundation's (whose Hertz references move with them).
      for (const auto &body : bodies)
        for (const auto id : body.self_contact_ids)
          {
            const std::string key =
              Body::section(&body - bodies.data()) + " > Self contact boundary ids";
            for (const auto &other : pairs.pairs)
              if (other.self && other.contact == id)
                throw InputError(key, "boundary id " + std::to_string(id) +
                                        " is already a self-contact pair");
            if (mesh.source == MeshParameters::Source::generated)
              {
                const auto own = body.geometry.boundary_ids(dim);
                if (std::find(own.begin(), own.end(), id) == own.end())
                  throw InputError(key, "boundary id " + std::to_string(id) +
                                          " is not one of this body's");
              }
            Signorini::Contact::PairsParameters::Pair pair;
            pair.contact = pair.target = id;
            pair.self                  = true;
            pairs.hertz.insert(pairs.hertz.begin() + pairs.pairs.size(),
                               Signorini::Contact::HertzReference());
            pairs.pairs.push_back(pair);
          }
      if (pairs.automatic_all)
        add_free_surface_pair(pairs);
      if (pairs.n_pairs() == 0)
        throw InputError("Contact > Pairs > Two-body pairs",
                         "Type = pairs needs at least one pair: the default "
                         "'all' found free surfaces on fewer than two bodies, "
                         "and there is no self-contact or foundation boundary "
                         "id");
      // The body that carries boundary @p id (a generated mesh: the
      // shapes' ids), or none.
      const auto body_of = [&](const types::boundary_id id) -> const Body * {
        if (mesh.source != MeshParameters::Source::generated)
          return nullptr;
        for (const auto &body : bodies)
          for (const auto shape_id : body.geometry.boundary_ids(dim))
            if (shape_id == id)
              return &body;
        return nullptr;
      };
      for (unsigned int k = 0; k < pairs.n_pairs(); ++k)
        {
          auto &h = pairs.hertz[k];
          if (!h.active())
            continue;
          const std::string section =
            "Contact > Pairs > Pair " + std::to_string(k + 1) + " > Hertz reference > ";
          if (!pairs.is_foundation(k) && pairs.pairs[k].all)
            throw InputError(section + (h.point_contact() ? "Point load" : "Line load"),
                             "pair " + std::to_string(k + 1) +
                               " is every body against every other ('Two-body "
                               "pairs = all'): no one Hertz reference applies");
          if (h.point_contact() && dim != 3)
            throw InputError(section + "Point load",
                             "point contact (a sphere) needs Dimension = 3; in 2D "
                             "use 'Line load'");
          if (h.line_load > 0. && dim != 2)
            throw InputError(section + "Line load",
                             "line contact is per unit thickness (Dimension = 2); "
                             "in 3D use 'Point load' (a sphere)");
          if (h.contact_modulus > 0.)
            continue;
          // 1/E* from the pair's bodies (one against the foundation).
          std::vector<types::boundary_id> ids;
          if (pairs.is_foundation(k))
            ids = {pairs.foundation_ids[k - pairs.pairs.size()]};
          else
            ids = {pairs.pairs[k].contact, pairs.pairs[k].target};
          double compliance = 0.;
          for (const auto id : ids)
            {
              const Body *body = body_of(id);
              if (!body)
                throw InputError(section + "Contact modulus",
                                 "no body of the scene's built-in shapes carries "
                                 "boundary id " +
                                   std::to_string(id) +
                                   " (a Gmsh mesh does not say before it is "
                                   "read): give E* here");
              compliance += hertz_compliance(*body);
            }
          h.contact_modulus = 1. / compliance;
        }
      contact.model_parameters = std::make_shared<
        const Signorini::Contact::ParsedParameters<Signorini::Contact::PairsParameters>>(
        std::move(pairs));
    }

    std::vector<types::material_id>
    Scene::material_ids() const
    {
      std::vector<types::material_id> ids;
      for (const auto &b : bodies)
        ids.push_back(b.material_id);
      return ids;
    }

    std::set<types::material_id>
    Scene::incompressible_ids() const
    {
      std::set<types::material_id> ids;
      for (const auto &b : bodies)
        if (b.incompressible)
          ids.insert(b.material_id);
      return ids;
    }
  } // namespace Parameters

  void
  declare_parameters(ParameterHandler &prm)
  {
    Parameters::Scene::declare_parameters(prm);
  }
} // namespace Signorini
