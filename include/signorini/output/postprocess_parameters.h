#pragma once

// This header holds the parameter struct alone, so that the scene's
// parameters (parameters/scene_parameters.h) include no solver or model.

#include <deal.II/base/data_out_base.h>
#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace Signorini
{
  using namespace dealii;

  /// The "Postprocess" and "Output" subsections, parsed.
  struct PostprocessParameters
  {
    int          mean_displacement_boundary  = -1;
    unsigned int mean_displacement_component = 0;
    std::string  mean_displacement_name;
    bool         has_reference = false;
    double       reference     = 0.;
    double       tolerance     = 0.;
    std::vector<int> reaction_boundaries; // checked against the mesh later

    std::string  format   = "vtu";
    unsigned int interval = 1;
    /// Output > Compression: zlib level of the VTU data.
    DataOutBase::VtkFlags::ZlibCompressionLevel compression =
      DataOutBase::VtkFlags::best_speed;
    /// Output > Verbosity.
    enum class Verbosity
    {
      quiet,
      normal,
      verbose
    };
    Verbosity verbosity = Verbosity::normal;

    /// Declares both subsections (at the top level of @p prm).
    static void
    declare_parameters(ParameterHandler &prm);
    /// Reads both subsections (from the top level of @p prm).
    void
    parse_parameters(ParameterHandler &prm, const unsigned int dim);
  };
} // namespace Signorini
