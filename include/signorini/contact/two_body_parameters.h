#pragma once

// This header holds the parameter struct alone, so that the scene's
// parameters (parameters/scene_parameters.h) include no solver or model.

#include <signorini/contact/indicator.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/types.h>

namespace Signorini
{
  using namespace dealii;

  namespace Contact
  {
    /// The "Contact > Two bodies" subsection.
    struct TwoBodyParameters
    {
      types::boundary_id target_boundary = 0;
      bool               integral        = false;
      unsigned int       gauss_points    = 2;
      double             stretch         = 0.12;
      double             apex_depth      = 1.;
      double             search_margin   = 1.;
      double             max_motion      = 0.5;
      double             end_stretch     = 1.;
      /// 'Indicator shape'.
      IndicatorShape     shape           = IndicatorShape::partition;
      /// 'Hessian': which pair Hessians are projected (negative
      /// eigenvalues clipped).
      enum class HessianMode
      {
        exact,
        projected,
        adaptive
      };
      HessianMode hessian_mode = HessianMode::adaptive;
      /// 'Passes': 1, body 1's contact boundary against body 2's indicator
      /// (the poster's); 2, also body 2's target boundary against body 1's
      /// indicator, each pass with half the penalty factor.
      unsigned int passes = 1;

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);
    };
  } // namespace Contact
} // namespace Signorini
