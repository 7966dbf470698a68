#pragma once

// This header holds the parameter struct alone, so that the scene's
// parameters (parameters/scene_parameters.h) include no solver or model.

#include <deal.II/base/parameter_handler.h>

namespace Signorini
{
  using namespace dealii;

  /**
   * Penalty continuation (formulation.md section 4): minimise G_mu_k
   * for mu_0 < mu_1 < ... with Newton, each stage warm-started from the
   * last, until the largest penetration over the local mesh size (the
   * contact model's measure()) is at most the tolerance.
   *
   * Scale-free choices: mu_0 = c_0 E / h^2 (E the largest small-strain
   * Young's modulus of the bodies, h the smallest contact mesh size), for
   * which a node carrying a pressure p penetrates by about
   * h sqrt(p / (c_0 E)). Because the penetration of a node with a
   * given force falls like mu^(-1/2), the next factor is predicted from
   * the measured penetration: mu_{k+1} = mu_k (ratio / (f tol))^2 with
   * f the target fraction, bounded by the minimum and maximum growth.
   */
  struct ContinuationParameters
  {
    double       initial_factor        = 1.;
    double       penetration_tolerance = 1e-3;
    double       target_fraction       = 0.5;
    double       min_growth            = 4.;
    double       max_growth            = 1e3;
    unsigned int max_stages            = 20;
    bool         restart_each_step     = false;
    double       step_reduction        = 10;
    double       max_penalty_ratio     = 1e14; // cap of mu / mu_0
    unsigned int stage_iteration_target = 20;
    unsigned int max_stage_retries      = 3;
    // Relative residual tolerance of a stage that is not known to be the
    // last (0: every stage to the Newton tolerance).
    double       stage_tolerance        = 1e-6;
    // How the next stage starts: the tangent du/dmu at the converged
    // stage (one linear solve), or the extrapolation from two stages.
    enum class StagePredictor
    {
      tangent,
      extrapolation,
      none
    } stage_predictor = StagePredictor::tangent;

    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);
  };
} // namespace Signorini
