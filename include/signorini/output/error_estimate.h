#pragma once

// Discretisation error estimates of the quantities of interest from a
// sequence of refined meshes (the adaptive refinement cycles).

#include <signorini/output/quantity.h>

#include <vector>

namespace Signorini
{
  namespace ErrorEstimate
  {
    /// An estimate of |Q_h - Q|, Q the value of the continuous model.
    struct Estimate
    {
      bool   valid = false;
      double error = 0.; // absolute
      /// The order p in |Q_h - Q| ~ C h^p: fitted with four or more
      /// meshes, the assumed 1 with two or three.
      double order = 0.;
      /// The extrapolated Q (the fit's limit), or the finest value.
      double limit = 0.;
      /// How many meshes the estimate used (2, 3 or 4).
      unsigned int meshes = 0;
    };

    /**
     * Estimate the error of the last of @p values, found on meshes of
     * size @p h (the smallest cell diameter, finest last). Meshes whose h
     * is not smaller than the previous one's (no cell became smaller) are
     * taken as a repetition of that mesh: the later value replaces it.
     *
     * - Four or more meshes: the last four are fitted by least squares
     *   with Q + C h^p, p from 0.5 to 3 in steps of 0.05; the estimate is
     *   the larger of |Q_h - Q| and the fit's root mean square residual
     *   (a value that scatters about its trend is not trusted beyond its
     *   scatter).
     * - Three meshes: Richardson's estimate with the assumed order p = 1,
     *   |Q_2 - Q_1| / (r - 1) with r = h_1 / h_2, or the same with the
     *   previous difference reduced by r^2 if that is larger (a sequence
     *   that oscillates can make one difference small by chance). At most
     *   r + 1 = 3 times the error of a sequence of order 2 (r = 2).
     * - Two meshes: |Q_1 - Q_0| / (r - 1).
     * - Fewer, or a value that is not finite: no estimate.
     *
     * How well this brackets the true error on the committed scenes is
     * measured by benchmarks/error_estimates.py (doc/accuracy-cost.md).
     */
    Estimate
    estimate(const std::vector<double> &h, const std::vector<double> &values);

    /**
     * Set has_estimate, estimated_error and observed_order of every
     * estimable quantity in @p latest from its values on the meshes of
     * sizes @p h (@p per_mesh[i] holds the quantities found on mesh i;
     * finest last, and @p latest is what the finest found). Quantities
     * missing on some mesh are estimated from the meshes that have them.
     */
    void
    add_estimates(const std::vector<double>                &h,
                  const std::vector<std::vector<Quantity>> &per_mesh,
                  std::vector<Quantity>                    &latest);
  } // namespace ErrorEstimate
} // namespace Signorini
