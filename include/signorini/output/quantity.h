#pragma once

// A quantity of interest with its reference: light enough for the Hertz
// reference and the report.

#include <algorithm>
#include <cmath>
#include <string>

namespace Signorini
{
  /// A computed quantity of interest, with its reference where one exists.
  struct Quantity
  {
    std::string name;
    double      value         = 0.;
    bool        has_reference = false;
    double      reference     = 0.;
    double      tolerance     = 0.; // relative; 0: not checked

    /// A value of the continuous model that the discretisation
    /// approximates (a force, a length, a pressure): the refinement cycles
    /// estimate its discretisation error. Counts, solver measures and
    /// errors against an analytic reference are not.
    bool   estimable = false;
    /// What the estimated error is relative to; 0: |value|. The components
    /// of a vector take the vector's length, so that a component that
    /// vanishes by symmetry is not judged relative to its round-off.
    double scale = 0.;
    /// Set by the refinement cycles (output/error_estimate.h).
    bool   has_estimate    = false;
    double estimated_error = 0.; // absolute, same unit as value
    double observed_order  = 0.; // of the error in the smallest cell size
    unsigned int estimate_meshes = 0; // how many meshes the estimate used

    double
    relative_error() const
    {
      return std::abs(value - reference) /
             std::max(std::abs(reference), 1e-300);
    }
    bool
    within_tolerance() const
    {
      return !has_reference || tolerance <= 0. || relative_error() <= tolerance;
    }
    /// What estimated_error is measured against: scale, or |value|.
    double
    error_scale() const
    {
      return scale > 0. ? scale : std::abs(value);
    }
    /// estimated_error / error_scale() (0 when both are 0).
    double
    estimated_relative_error() const
    {
      return estimated_error == 0. ? 0. :
                                     estimated_error /
                                       std::max(error_scale(), 1e-300);
    }

    template <class Archive>
    void
    serialize(Archive &ar, const unsigned int)
    {
      ar &name &value &has_reference &reference &tolerance;
      ar &estimable &scale &has_estimate &estimated_error &observed_order;
      ar &estimate_meshes;
    }
  };
} // namespace Signorini
