#pragma once

#include <deal.II/base/parameter_handler.h>

namespace Signorini
{
  namespace Study
  {
    /// The most variants a study compares ("Study > Variant 1" to "N").
    constexpr unsigned int max_variants = 12;

    /// The "Study" subsection of a scene: the quantities whose errors
    /// `signorini --study` reports, and its variants (driver/study.h).
    /// Ignored by an ordinary run.
    void
    declare_parameters(dealii::ParameterHandler &prm);
  } // namespace Study
} // namespace Signorini
