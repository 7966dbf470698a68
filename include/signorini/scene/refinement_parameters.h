#pragma once

// This header holds the parameter struct alone, so that the scene's
// parameters (parameters/scene_parameters.h) include no solver or model.

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace Signorini
{
  using namespace dealii;

  /**
   * The "Mesh refinement" subsection: adaptive refinement cycles within a
   * scene (solve, estimate, refine and coarsen, transfer the solution as
   * the next initial guess, solve again), and an initial refinement of the
   * potential contact zone only.
   */
  struct RefinementParameters
  {
    enum class Estimator
    {
      kelly,    // gradient jumps of the displacement across faces
      contact,  // changes of the contact pressure along Gamma_C
      combined  // both, each scaled by its largest value
    };
    enum class Strategy
    {
      fraction, // refine the cells holding this fraction of the total
      number    // refine this fraction of the cells
    };

    unsigned int cycles           = 0;
    Estimator    estimator        = Estimator::combined;
    Strategy     strategy         = Strategy::fraction;
    double       refine_fraction  = 0.3;
    double       coarsen_fraction = 0.;
    unsigned int max_level        = 12;
    unsigned int band_refinements = 0;
    double       band_width       = 0.;
    double       band_gap         = -1.;
    bool         uniform_zone     = true;
    double       zone_depth       = 1.;
    /// Target accuracy mode: stop the cycles once every quantity of
    /// target_quantities (all estimable ones if empty) has an estimated
    /// relative error at most target_accuracy; 0: run all the cycles.
    double                   target_accuracy = 0.;
    std::vector<std::string> target_quantities;
    /// Estimate the errors of a run without cycles from a second, coarser
    /// mesh: solve the load path with every cell coarsened once (where
    /// its siblings allow), then refine those cells back and solve the
    /// final load on the scene's own mesh (refinement cycle 1).
    bool coarser_mesh_estimate = false;

    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);

    std::string
    estimator_name() const;
  };
} // namespace Signorini
