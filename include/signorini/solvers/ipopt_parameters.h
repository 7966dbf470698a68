#pragma once

// This header holds the parameter struct alone, so that the scene's
// parameters (parameters/scene_parameters.h) include no solver or model.

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace Signorini
{
  using namespace dealii;

  /// The "Solver > Ipopt" subsection.
  struct IpoptParameters
  {
    double       tolerance       = 1e-9;
    unsigned int max_iterations  = 500;
    std::string  mu_strategy     = "adaptive";
    int          print_level     = 0;
    int          file_print_level = 5;
    std::string  options_file;
    std::string  derivative_test = "none";
    double       derivative_test_perturbation = 1e-3;
    bool         warm_start      = true;
    double       warm_start_mu   = 1e-6;
    /// Penalty stages minimised by Ipopt: no step moves a DoF by more than
    /// this fraction of the scene's size (0: no limit).
    double       max_increment   = 0.1;
    /// Ipopt's mumps_pivot_order (set from Linear solver > MUMPS ordering).
    int          mumps_pivot_order = 4;

    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm, const std::string &prm_directory);
  };
} // namespace Signorini
