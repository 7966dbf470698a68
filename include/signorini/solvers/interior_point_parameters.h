#pragma once

// This header holds the parameter struct alone, so that the scene's
// parameters (parameters/scene_parameters.h) include no solver or model.

#include <deal.II/base/parameter_handler.h>

namespace Signorini
{
  using namespace dealii;

  /// The "Solver > Interior point" subsection.
  struct InteriorPointParameters
  {
    double       tolerance              = 1e-10;
    /// A stalled iteration keeps its best iterate if every relative
    /// residual is at most this (0: never).
    double       acceptable_tolerance   = 1e-6;
    unsigned int max_iterations         = 100;
    double       initial_barrier        = 1e-1;
    double       warm_start_barrier     = 1e-3;
    double       initial_slack          = 1e-2;
    /// Mehrotra's barrier sigma mu_avg is capped at the previous
    /// iteration's barrier ("Barrier update = capped"), or may rise.
    bool         capped_barrier         = true;
    bool         warm_start             = true;
    bool         active_set_polish      = true;
    /// Active-set updates allowed inside one polish attempt, or automatic
    /// (0 with a direct linear solver, 6 with an iterative one).
    static constexpr unsigned int automatic = static_cast<unsigned int>(-1);
    unsigned int polish_updates         = automatic;
    double       armijo_c1              = 1e-4;
    unsigned int max_backtracks         = 30;
    double       initial_regularization = 1e-8;
    /// No DoF moves by more than this fraction of the scene's size in one
    /// step; a step below 'Increment tolerance' (the same fraction) with
    /// the constraints met ends the iteration.
    double       max_increment          = 0.1;
    double       increment_tolerance    = 1e-14;
    unsigned int max_regularizations    = 12;
    // Incompressible bodies (augmented Lagrangian, InteriorPointStep).
    double       incompressibility_weight    = 100.;
    double       incompressibility_tolerance = 1e-10;
    unsigned int max_multiplier_updates      = 30;

    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);
  };
} // namespace Signorini
