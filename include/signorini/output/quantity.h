#pragma once

// A quantity of interest with its reference: light enough for the Hertz
// reference and the report.

#include <algorithm>
#include <cmath>
#include <string>

namespace Signorini
{
  using namespace dealii;

  /// A computed quantity of interest, with its reference where one exists.
  struct Quantity
  {
    std::string name;
    double      value         = 0.;
    bool        has_reference = false;
    double      reference     = 0.;
    double      tolerance     = 0.; // relative; 0: not checked

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

    template <class Archive>
    void
    serialize(Archive &ar, const unsigned int)
    {
      ar &name &value &has_reference &reference &tolerance;
    }
  };
} // namespace Signorini
