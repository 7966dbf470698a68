#pragma once

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <string>

namespace Signorini
{
  using namespace dealii;

  /**
   * The accuracy-versus-time study (signorini --study FILE.prm): the scene
   * of FILE.prm run over a series of meshes for each of up to eight method
   * variants (subsections "Study > Variant N", each a set of parameter
   * overrides and one entry whose values make the series; a variant with
   * refinement cycles makes its series from them). For every run or
   * cycle: DoFs, contact nodes, iterations, wall time per phase, peak
   * memory and the errors of the chosen quantities against the scene's
   * analytic references and against the converged solution of the
   * discrete model (Richardson extrapolation of the reference variant's
   * three finest runs, or its finest run). Writes study.csv, study.json
   * and, with python3-matplotlib, the plots of scripts/plot_study.py.
   */
  namespace Study
  {
    // Its parameters: parameters/study_parameters.h.

    /// Run the study of @p file (parsed into @p prm); returns the exit
    /// code (0: every run converged, 3: some failed, recorded as such).
    int
    run(const std::string &file, ParameterHandler &prm, MPI_Comm comm);
  } // namespace Study
} // namespace Signorini
