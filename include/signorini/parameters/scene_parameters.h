#pragma once

// Only the modules' parameter structs: no solver, contact model or output
// class (doc/architecture.md, 'Headers').
#include <signorini/contact/friction_parameters.h>
#include <signorini/contact/hertz.h>
#include <signorini/output/postprocess_parameters.h>
#include <signorini/parameters/checkpoint_parameters.h>
#include <signorini/parameters/selection.h>
#include <signorini/scene/boundary_conditions.h>
#include <signorini/scene/mesh.h>
#include <signorini/scene/refinement_parameters.h>
#include <signorini/solvers/continuation_parameters.h>
#include <signorini/solvers/interior_point_parameters.h>
#include <signorini/solvers/ipopt_parameters.h>
#include <signorini/solvers/linear_solver.h>
#include <signorini/solvers/newton_parameters.h>

#include <deal.II/base/parameter_handler.h>

#include <memory>
#include <set>
#include <string>
#include <vector>

namespace Signorini
{
  using namespace dealii;

  namespace Material
  {
    class Interface;
  }
  namespace Contact
  {
    struct ModelEntry;
    struct ModelParameters;
    struct PairsParameters;
  } // namespace Contact

  /**
   * Everything a scene file says, parsed into typed values before any mesh
   * or solver exists. One struct per subsection, each with its
   * declare_parameters() and parse_parameters() side by side; Selection
   * entries become enum class values here, and every check that needs no
   * mesh is done here. Nothing outside these structs (and the structs of
   * the components they hold: MeshParameters, NewtonMinimizer::Parameters,
   * ...) reads the ParameterHandler.
   */
  namespace Parameters
  {
    /// Top level: Dimension, Scene name, Output directory.
    struct Global
    {
      unsigned int dimension = 2;
      std::string  scene;            // never empty after parsing
      std::string  output_directory; // never empty after parsing
      std::string  parameter_file;
      std::string  parameter_directory; // relative paths in the file

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm, const std::string &file);
    };

    /// "Discretization".
    struct Discretization
    {
      unsigned int degree         = 1; // FE_Q(p)^dim
      unsigned int mapping_degree = 1; // MappingQ (p unless given)

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);
    };

    /// "Body 1", "Body 2": an active body's cells, shape and material.
    struct Body
    {
      /// 'Body 1' to 'Body 24' are declared (issue 51: any number of
      /// bodies; each declared body adds its Geometry and Material entries
      /// to every parameter listing).
      static constexpr unsigned int max_bodies = 24;

      types::material_id                   material_id = 0;
      BodyGeometry                         geometry;
      std::shared_ptr<Material::Interface> material;
      bool                                 incompressible = false;
      /// 'Self contact boundary ids' with 'Self contact = true': each kept
      /// out of this body (a self-contact pair of Contact > Type = pairs).
      std::vector<types::boundary_id>      self_contact_ids;

      /// "Body N" for the body with index @p b (0-based).
      static std::string
      section(const unsigned int b);

      static void
      declare_parameters(ParameterHandler &prm, const unsigned int b);
    };

    /// "Load stepping".
    struct LoadStepping
    {
      double       end_time          = 1.;
      unsigned int n_steps           = 1;
      double       min_step_fraction = 1e-4;
      /// Steady sliding: the slider's direction (dim entries, unit length),
      /// or empty (TransportPredictor).
      std::vector<double> sliding_direction;

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm, const unsigned int dim);
    };

    /// "Solver": the step solver and the parameters of each algorithm.
    struct Solver
    {
      enum class Method
      {
        newton,         // Newton on E (no contact)
        newton_penalty, // penalty continuation, stages minimised by Newton
        ipopt,          // Ipopt: constraints, or penalty stages (two bodies)
        interior_point, // our primal-dual interior point (rigid foundation)
        automatic       // the entry's default; Scene::parse_parameters
                        // replaces it by the solver the scene calls for
      };

      Method                       method = Method::newton;
      NewtonParameters             newton;
      ContinuationParameters       penalty;
      IpoptParameters              ipopt;
      InteriorPointParameters      interior_point;
      LinearSolver::Parameters     linear;

      /// The names of the methods in the parameter file.
      static const SelectionTable<Method> &
      methods();

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm, const std::string &prm_directory);
    };

    /// "Contact": the registered model that Type names (contact/registry.h)
    /// with its parsed subsections, the contact boundary and the Hertz
    /// reference.
    struct ContactSection
    {
      const Signorini::Contact::ModelEntry *model = nullptr; // Type = none: null
      std::shared_ptr<const Signorini::Contact::ModelParameters> model_parameters;
      types::boundary_id                   boundary_id = 0;
      Signorini::Contact::HertzReference   hertz;
      /// "Contact > Friction": Coulomb friction (doc/friction.md); which
      /// models and solvers take it is checked by
      /// check_solver_compatibility().
      Signorini::Contact::FrictionParameters friction;

      /// Whether the scene declares contact.
      bool
      active() const
      {
        return model != nullptr;
      }

      /// Type: "none" or the model's registered name.
      std::string
      type() const;

      /// Whether the model has node-wise constraints (its capabilities),
      /// which Ipopt and the interior point method impose.
      bool
      node_wise_constraints() const;

      static void
      declare_parameters(ParameterHandler &prm);
      /// Reads Type, the boundary id, the model's own subsections (for a
      /// scene of dimension @p dim) and the Hertz reference.
      void
      parse_parameters(ParameterHandler &prm, const unsigned int dim);
    };

    /**
     * The whole scene file. parse_parameters() reads every subsection and
     * checks what can be checked without the mesh; the checks that need
     * the mesh (boundary and material ids) are the Scene's.
     */
    struct Scene
    {
      Global                         global;
      Discretization                 discretization;
      MeshParameters                 mesh;
      RefinementParameters           refinement;
      std::vector<Body>              bodies; // the active ones
      BoundaryConditionParameters    boundary_conditions;
      LoadStepping                   load_stepping;
      Solver                         solver;
      ContactSection                 contact;
      PostprocessParameters          postprocess;
      CheckpointParameters           checkpoint;

      static void
      declare_parameters(ParameterHandler &prm);

      /// @p file: the parameter file @p prm was read from (its folder is
      /// the base of the relative paths in it).
      void
      parse_parameters(ParameterHandler &prm, const std::string &file);

      /// The material ids of the active bodies, in body order.
      std::vector<types::material_id>
      material_ids() const;

      /// The material ids of the bodies with J = 1 constraints.
      std::set<types::material_id>
      incompressible_ids() const;

    private:
      /// (1 - nu^2)/E of @p body, its share of Hertz's 1/E*.
      static double
      hertz_compliance(const Body &body);

      /// Type = pairs: the bodies' material ids and each pair's Hertz E*
      /// (from its bodies where 'Contact modulus' = 0) into the model's
      /// parameters; a scene-wide Hertz reference is refused.
      void
      parse_pairs(const Signorini::Contact::PairsParameters &pairs);

      /// 'Two-body pairs = all' without 'Contact boundaries': the
      /// all-bodies pair over the free surfaces of the built-in shapes
      /// (the ids no boundary condition names), as pair 1, if two bodies
      /// have one; InputError on a Gmsh mesh of several bodies.
      void
      add_free_surface_pair(Signorini::Contact::PairsParameters &pairs) const;
    };
  } // namespace Parameters

  /// Declare every entry of a scene parameter file.
  void
  declare_parameters(ParameterHandler &prm);
} // namespace Signorini
