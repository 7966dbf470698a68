#pragma once

#include <signorini/output/penalty_stage.h>
#include <signorini/output/postprocess.h>

#include <deal.II/base/tensor.h>

#include <map>
#include <string>
#include <vector>

namespace Signorini
{
  using namespace dealii;

  /**
   * What a run did, for summary.json, the screen and the test driver.
   */
  struct Report
  {
    struct Step
    {
      double       time;
      /// Iterations of the step's method (iteration_name: Newton, Ipopt or
      /// the interior point method), over all penalty stages.
      unsigned int iterations;
      unsigned int backtracks;
      unsigned int regularized;
      unsigned int linear_iterations;
      unsigned int linear_solves = 0; // linear solves of the step (iterative or direct)
      unsigned int linear_fallbacks = 0; // iterative solves redone directly
      /// AMG hierarchies built since the previous step ended (cut
      /// attempts included; CG or MINRES + AMG only).
      unsigned int amg_builds = 0;
      unsigned int cuts_before;
      double       residual;
      double       energy;
      double       min_J;
      // Solver-specific: penalty stages, or Ipopt's status.
      std::vector<PenaltyStage> stages;
      std::string                 solver_status;
      // Contact state at the end of the step.
      unsigned int active_nodes       = 0;
      double       penetration_ratio  = 0.;
      Tensor<1, 3> contact_force_vector; // on body 1 (or the body)
      Tensor<1, 3> contact_moment;       // of those forces about the origin
      double       contact_area = 0.;    // length in 2D
      bool               has_pairs = false; // the contact has a broad phase
      unsigned long long pairs     = 0;     // pairs it evaluated last
      // Coulomb friction (zero without): the outer loop's iterations and
      // its last relative change of the normal forces, the friction force
      // on body 1 (or the body), the energy dissipated in this step and
      // up to it, and the sticking and slipping contact points.
      unsigned int friction_iterations = 0;
      double       friction_change     = 0.;
      Tensor<1, 3> friction_force;
      double       dissipated_energy       = 0.; // this step
      double       total_dissipated_energy = 0.; // all steps up to this one
      unsigned int stick_points = 0;
      unsigned int slip_points  = 0;
      // With a Mindlin reference (0 without): the stick zone's half-width
      // (radius) and Mindlin's for the step's load ratio Q/(mu P).
      double stick_radius           = 0.;
      double stick_radius_reference = 0.;
      double tangential_load_ratio  = 0.;
      // A model of several contact pairs: the values of its
      // part_columns() (per pair and per body resultants, areas).
      std::vector<double> part_values;

      template <class Archive>
      void
      serialize(Archive &ar, const unsigned int)
      {
        ar &time &iterations &backtracks &regularized &linear_iterations;
        ar &linear_fallbacks &cuts_before &residual &energy &min_J &stages;
        ar &solver_status &active_nodes &penetration_ratio;
        ar &contact_force_vector &contact_moment &contact_area &has_pairs &pairs;
        ar &linear_solves &amg_builds;
        ar &friction_iterations &friction_change &friction_force;
        ar &dissipated_energy &total_dissipated_energy &stick_points &slip_points;
        ar &stick_radius &stick_radius_reference &tangential_load_ratio;
        ar &part_values;
      }
    };

    /// One adaptive refinement cycle: the mesh it solved on and what it
    /// found (cycle 0 is the load path on the initial mesh).
    struct Cycle
    {
      unsigned int          cycle = 0;
      unsigned long long    n_cells = 0;
      unsigned long long    n_dofs  = 0;
      unsigned int          contact_nodes     = 0;
      unsigned int          iterations = 0; // of this cycle
      unsigned int          refined_cells     = 0; // flagged to make its mesh
      double                h_min = 0.;
      double                cycle_seconds = 0.;  // wall time of this cycle
      double                wall_seconds  = 0.;  // since the run started
      std::vector<Quantity> quantities;
      std::map<std::string, double> timing; // per phase, since the start

      template <class Archive>
      void
      serialize(Archive &ar, const unsigned int)
      {
        ar &cycle &n_cells &n_dofs &contact_nodes &iterations;
        ar &refined_cells &h_min &cycle_seconds &wall_seconds &quantities &timing;
      }
    };

    std::string              scene;
    std::string              parameter_file;
    std::string              output_directory;
    unsigned int             dimension = 0;
    unsigned int             degree    = 0;
    unsigned long long       n_cells   = 0;
    unsigned long long       n_dofs    = 0;
    unsigned int             n_ranks   = 1;
    /// Open MPI settings the program made before MPI_Init ("" if none).
    std::string              mpi_settings;
    double                   h_min     = 0.;
    double                   h_max     = 0.;
    std::vector<std::string> materials;
    std::string              solver;         // Solver > Method
    std::string              iteration_name = "newton"; // or "ipopt"
    std::string              linear_solver;
    bool                     iterative_linear_solver = false; // CG or MINRES + AMG
    /// "running", "converged", "failed" or "interrupted".
    std::string              status = "not run";
    std::string              reason;
    /// With status "interrupted": the signal, and what was running.
    int                      interrupt_signal = 0;
    std::string              interrupted_during;
    /// The checkpoint written last, if any ("" otherwise), and the ones
    /// this run was restarted from.
    std::string              last_checkpoint;
    std::vector<std::string> restarted_from;
    double                   final_time        = 0.;
    unsigned int             step_cuts         = 0;
    unsigned int             iterations        = 0; // all steps, iteration_name's
    std::vector<Step>        steps;
    std::vector<Cycle>       cycles; // with Mesh refinement > Number of cycles > 0
    /// The number of the last refinement cycle recorded (0 without any).
    unsigned int
    last_cycle() const
    {
      return cycles.empty() ? 0 : cycles.size() - 1;
    }
    /// Target accuracy mode (Mesh refinement > Target accuracy > 0): the
    /// target, whether the last cycle met it, and the quantities whose
    /// estimated relative error is still above it (or has no estimate).
    double                   target_accuracy = 0.;
    bool                     target_met      = false;
    std::vector<std::string> target_unmet;
    double                   peak_memory_mb = 0.; // largest VmHWM of the ranks
    unsigned int contact_nodes = 0; // 0: no contact
    std::vector<Quantity>    quantities;
    std::map<std::string, double> timing;

    /// The part of the report that a checkpoint keeps: what the run did
    /// up to its last converged state (not the mesh data, which the
    /// restarted run recomputes, nor the status).
    template <class Archive>
    void
    serialize(Archive &ar, const unsigned int)
    {
      ar &final_time &step_cuts &iterations &steps &cycles &quantities;
      ar &timing &restarted_from;
    }

    /// Take from @p saved the part that serialize() keeps (a restart).
    void
    take_record(const Report &saved)
    {
      final_time        = saved.final_time;
      step_cuts         = saved.step_cuts;
      iterations = saved.iterations;
      steps             = saved.steps;
      cycles            = saved.cycles;
      quantities        = saved.quantities;
      timing            = saved.timing;
      restarted_from    = saved.restarted_from;
    }
  };

} // namespace Signorini
