#pragma once

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
    } // namespace Mindlin
  } // namespace Contact
} // namespace Signorini
