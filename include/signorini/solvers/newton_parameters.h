#pragma once

// This header holds the parameter struct alone, so that the scene's
// parameters (parameters/scene_parameters.h) include no solver or model.

#include <deal.II/base/parameter_handler.h>

namespace Signorini
{
  using namespace dealii;

  /// The "Solver > Newton" subsection (NewtonMinimizer::Parameters).
  struct NewtonParameters
  {
    unsigned int max_iterations     = 50;
    double       residual_tolerance = 1e-10;
    double       absolute_tolerance = 1e-14;
    double       energy_tolerance   = 1e-12;
    double       armijo_c1          = 1e-4;
    double       backtrack_factor   = 0.5;
    unsigned int max_backtracks     = 30;
    double       initial_shift      = 1e-6;
    unsigned int max_shifts         = 8;
    bool         inertia_test       = true;
    bool         limit_trials       = true;
    double       max_increment      = 0.1;
    double       increment_tolerance = 1e-14;

    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);
  };
} // namespace Signorini
