#pragma once

namespace Signorini
{
  /// One stage of a penalty continuation as a load step's record keeps it
  /// (solvers/penalty_continuation.h makes them; summary.json and the
  /// checkpoints read them).
  struct PenaltyStage
  {
    double       mu                = 0.;
    unsigned int iterations        = 0; // of the stage's minimiser (Newton or Ipopt)
    double       penetration_ratio = 0.;
    // false: the stage's solver failed and the stage was tried again
    // from the previous stage's solution with a smaller jump in mu.
    bool converged = true;

    template <class Archive>
    void
    serialize(Archive &ar, const unsigned int)
    {
      ar &mu &iterations &penetration_ratio &converged;
    }
  };
} // namespace Signorini
