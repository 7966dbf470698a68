#pragma once

#include <signorini/boundary_conditions.h>
#include <signorini/contact/hertz.h>
#include <signorini/contact/penalty.h>
#include <signorini/contact/rigid_foundation.h>
#include <signorini/contact/two_body.h>
#include <signorini/incompressibility.h>
#include <signorini/ipopt_solver.h>
#include <signorini/energy_functional.h>
#include <signorini/json.h>
#include <signorini/linear_solver.h>
#include <signorini/material/interface.h>
#include <signorini/mesh.h>
#include <signorini/newton.h>
#include <signorini/postprocess.h>
#include <signorini/refinement.h>
#include <signorini/types.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/lac/affine_constraints.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace Signorini
{
  using namespace dealii;

  /// Declare every entry of a scene parameter file.
  void
  declare_parameters(ParameterHandler &prm);

  /**
   * What a run did, for summary.json, the screen and the test driver.
   */
  struct Report
  {
    struct Step
    {
      double       time;
      unsigned int newton_iterations;
      unsigned int backtracks;
      unsigned int regularized;
      unsigned int linear_iterations;
      unsigned int linear_fallbacks = 0; // iterative solves redone directly
      unsigned int cuts_before;
      double       residual;
      double       energy;
      double       min_J;
      // Solver-specific: penalty stages, or Ipopt's status.
      std::vector<Contact::Stage> stages;
      std::string                 solver_status;
      // Contact state at the end of the step.
      unsigned int active_nodes       = 0;
      double       penetration_ratio  = 0.;
      Tensor<1, 3> contact_force_vector; // on body 1 (or the body)
      unsigned long long pairs = 0;         // two bodies: evaluated pairs
    };

    /// One adaptive refinement cycle: the mesh it solved on and what it
    /// found (cycle 0 is the load path on the initial mesh).
    struct Cycle
    {
      unsigned int          cycle = 0;
      unsigned long long    n_cells = 0;
      unsigned long long    n_dofs  = 0;
      unsigned int          contact_nodes     = 0;
      unsigned int          newton_iterations = 0; // of this cycle
      unsigned int          refined_cells     = 0; // flagged to make its mesh
      double                h_min = 0.;
      double                cycle_seconds = 0.;  // wall time of this cycle
      double                wall_seconds  = 0.;  // since the run started
      std::vector<Quantity> quantities;
      std::map<std::string, double> timing; // per phase, since the start
    };

    std::string              scene;
    std::string              parameter_file;
    std::string              output_directory;
    unsigned int             dimension = 0;
    unsigned int             degree    = 0;
    unsigned long long       n_cells   = 0;
    unsigned long long       n_dofs    = 0;
    unsigned int             n_ranks   = 1;
    double                   h_min     = 0.;
    double                   h_max     = 0.;
    std::vector<std::string> materials;
    std::string              solver;
    std::string              linear_solver;
    std::string              status = "not run";
    std::string              reason;
    double                   final_time        = 0.;
    unsigned int             step_cuts         = 0;
    unsigned int             newton_iterations = 0;
    std::vector<Step>        steps;
    std::vector<Cycle>       cycles; // with Mesh refinement > Number of cycles > 0
    double                   peak_memory_mb = 0.; // largest VmHWM of the ranks
    // Contact.
    std::string  contact_type = "none";
    std::string  foundation;
    unsigned int contact_nodes             = 0;
    double       initial_penalty           = 0.;
    bool         penetration_tolerance_met = true;
    int          derivative_test_errors    = -1;
    unsigned int incompressibility_constraints = 0;
    std::vector<Quantity>    quantities;
    std::map<std::string, double> timing;
  };

  /**
   * One scene: the mesh of its bodies, their materials, boundary
   * conditions and loads, solved by load stepping with a Newton
   * minimiser of the total potential energy, with output after each step.
   *
   * Data flow: parameters -> mesh (build_scene_mesh) -> DoFs and
   * constraints -> EnergyFunctional (assembly) -> NewtonMinimizer (with
   * LinearSolver) per load step -> Postprocessor (quantities, reactions,
   * VTU/HDF5, CSV) -> summary.json.
   */
  template <int dim>
  class Simulator
  {
  public:
    /**
     * Parse the scene from @p prm (already read from @p parameter_file),
     * build the mesh and check the input. Throws InputError on bad input,
     * before anything is written.
     */
    Simulator(ParameterHandler  &prm,
              const std::string &parameter_file,
              const bool         quiet,
              MPI_Comm           comm);

    /**
     * Create the output folder, write used_parameters.prm, solve every
     * load step and write the output. Returns the report; its status is
     * "converged" or "failed" (then reason says why, the output of the
     * last converged step is on disk and summary.json says so).
     */
    const Report &
    run(ParameterHandler &prm);

  private:
    void
    setup_dofs();
    /// (Re)build the Hessian's sparsity pattern, with the two-body contact
    /// couplings found at the ghosted state @p u.
    void
    build_matrix(const VectorType &u);
    AffineConstraints<double>
    boundary_constraints(const double time, const bool homogeneous) const;
    AffineConstraints<double>
    increment_constraints(const double time) const;
    /// The contact model as a penalty term (rigid foundation or two
    /// bodies), nullptr if the scene declares no contact.
    Contact::PenaltyTerm<dim> *
    penalty_term() const
    {
      if (contact)
        return contact.get();
      return two_body.get();
    }
    /// The penalty's scale mu_0 from the current contact mesh size.
    void
    update_penalty_scale();
    /// Quantities, the step record and the graphical output after a
    /// converged solve at time @p t (step @p step of series @p series).
    void
    complete_step(const double                       t,
                  const unsigned int                 step,
                  const NewtonMinimizer::Statistics &stats,
                  Report::Step                      &record,
                  const std::string                 &series);
    /// Estimate, mark, refine and coarsen, and transfer the solution to the
    /// new mesh. Returns the number of cells flagged for refinement.
    unsigned int
    refine_mesh();
    bool
    solve_load_step(const double                 time,
                    NewtonMinimizer::Statistics &stats,
                    Report::Step                &record);
    std::vector<Quantity>
    contact_quantities(Report::Step &record);
    void
    write_summary() const;

    MPI_Comm           comm;
    ConditionalOStream pcout;
    ConditionalOStream progress;
    // Created once the input is checked: a TimerOutput destroyed during
    // exception unwinding would print a notice over the error message.
    std::unique_ptr<TimerOutput> timer;
    double                       setup_seconds = 0.;

    // Parameters.
    std::string                 output_directory;
    MeshParameters              mesh_parameters;
    std::vector<BodyGeometry>   geometries;
    std::vector<types::material_id> material_ids;
    double                      end_time = 1.;
    unsigned int                n_steps  = 1;
    double                      min_step_fraction = 1e-4;
    NewtonMinimizer::Parameters newton_parameters;
    LinearSolver::Parameters    linear_parameters;
    bool                        has_prescribed_motion = false;
    std::string                 method = "newton";
    Contact::ContinuationParameters          continuation_parameters;
    typename IpoptSolver<dim>::Parameters    ipopt_parameters;
    Contact::HertzReference                  hertz;
    RefinementParameters                     refinement_parameters;
    std::set<types::material_id>             incompressible_ids;

    // Discretisation.
    parallel::distributed::Triangulation<dim> triangulation;
    std::unique_ptr<FESystem<dim>>            fe;
    std::unique_ptr<MappingQ<dim>>            mapping;
    DoFHandler<dim>                           dof_handler;
    IndexSet                                  locally_owned;
    IndexSet                                  locally_relevant;
    AffineConstraints<double>                 hanging_constraints;
    AffineConstraints<double>                 homogeneous_constraints;

    // Physics.
    BoundaryConditions<dim>                                   bc;
    std::vector<std::unique_ptr<Material::Interface>>         material_objects;
    std::map<types::material_id, const Material::Interface *> materials;
    std::unique_ptr<EnergyFunctional<dim>>                    energy;
    std::unique_ptr<Postprocessor<dim>>                       postprocessor;
    std::unique_ptr<Contact::RigidFoundation<dim>>            contact;
    std::unique_ptr<Contact::TwoBodyContact<dim>>             two_body;
    std::unique_ptr<Incompressibility<dim>>                   incompressibility;
    std::unique_ptr<IpoptSolver<dim>>                         ipopt;
    std::vector<double> contact_forces; // nodal, of the last solve
    double              mu0     = 0.;  // first penalty factor
    double              last_mu = 0.;  // final penalty of the last step
    double              scene_size = 0.; // bounding-box diameter

    // Linear algebra.
    std::unique_ptr<LinearSolver> linear_solver;
    MatrixType hessian;
    VectorType solution;         // locally owned
    VectorType solution_ghosted; // locally relevant
    VectorType rhs;

    Report report;
  };
} // namespace Signorini
