#pragma once

#include <vector>

namespace Signorini
{
  namespace Contact
  {
    /**
     * Cattaneo-Mindlin: a Hertz contact of elastically similar bodies
     * (so that the normal and the tangential problems uncouple) under the
     * normal load P, then a tangential load Q < mu P. The contact zone of
     * half-width (radius) a keeps a central stick zone of half-width
     * (radius) c, and slips in a <= |r| <= c (Johnson, Contact Mechanics,
     * 7.1 and 7.2).
     */
    namespace Mindlin
    {
      /// c/a for the tangential load ratio Q/(mu P) in [0, 1]:
      /// sqrt(1 - Q/(mu P)) for a cylinder (line contact),
      /// (1 - Q/(mu P))^(1/3) for a sphere (point contact).
      double
      stick_ratio(const double load_ratio, const bool point_contact);

      /**
       * The tangential traction at the distance r from the contact's
       * centre, for the peak Hertz pressure p0, the half-width (radius) a
       * and the stick half-width (radius) c:
       *
       *   q(r) = mu p0 [ sqrt(1 - r^2/a^2) - (c/a) sqrt(1 - r^2/c^2) ],
       *
       * each root taken as 0 beyond its zone; the same form for a cylinder
       * and a sphere.
       */
      double
      traction(const double r, const double a, const double c, const double mu_p0);

      /**
       * A tangential load that moves back and forth along one line
       * (Mindlin and Deresiewicz 1953; Johnson, Contact Mechanics, 7.2),
       * given by its load ratios rho = Q/(mu P), signed along the line, one
       * per load step. Loading from 0 (the virgin branch) keeps the stick
       * zone c/a = stick_ratio(|rho|). A reversal at rho_r starts a branch
       * on which a reverse slip zone spreads inwards from the edge: its
       * stick zone is c'/a = stick_ratio(|rho - rho_r|/2), and its traction
       * is the traction at the reversal minus twice the virgin traction
       * of the load change |rho - rho_r|/2 (the superposition of the
       * paper). Masing's memory closes loops: a branch that comes back to
       * the reversal before its own start continues the branch before
       * that, and one that comes back to -rho_r of the first reversal
       * continues the virgin branch. For monotonic loading this is
       * stick_ratio() and traction() with the load ratio |rho|.
       */
      class LoadPath
      {
      public:
        /// The next step's load ratio Q/(mu P), signed along the line;
        /// changes of at most 1e-9 are not movements (round-off of a
        /// state without tangential load).
        void
        add(const double ratio);

        /// c/a under the last load ratio added.
        double
        stick_ratio(const bool point_contact) const;

        /// The tangential traction along the line at the distance r from
        /// the contact's centre under the last load ratio added, for the
        /// half-width (radius) a and mu p0.
        double
        traction(const double r,
                 const double a,
                 const double mu_p0,
                 const bool   point_contact) const;

        /// The reversal points still remembered, oldest first.
        const std::vector<double> &
        reversals() const
        {
          return reversal_points;
        }

      private:
        std::vector<double> reversal_points;
        double              last      = 0.;
        int                 direction = 0; // of the current branch: +1, -1, 0 (none yet)
      };
    } // namespace Mindlin
  } // namespace Contact
} // namespace Signorini
