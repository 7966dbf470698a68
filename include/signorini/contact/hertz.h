#pragma once

#include <signorini/output/quantity.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <cmath>
#include <string>
#include <vector>

namespace Signorini
{
  using namespace dealii;

  namespace Contact
  {
    /**
     * Hertz contact (formulation.md section 5) as the reference of a
     * contact scene. Line contact (2D, plane strain): a cylinder of
     * effective radius R pressed by the force P per unit thickness,
     *
     *   a = sqrt(4 P R / (pi E*)),  p0 = 2 P / (pi a),
     *
     * with s = x - x_axis. Point contact (3D): a sphere of radius R pressed
     * by the total force P,
     *
     *   a = (3 P R / (4 E*))^(1/3),  p0 = 3 P / (2 pi a^2),
     *
     * with s = the distance from the vertical line through (x_c, y_c). In
     * both, p(s) = p0 sqrt(1 - s^2 / a^2). P is always the load on the
     * whole body; a mesh that holds a part of it (a half or quarter
     * cylinder, an octant or quarter ball) carries 'Modelled fraction' of
     * it.
     *
     * From a computed pressure profile it measures p0 (the pressure of the
     * node nearest the axis or centre), a (least-squares fit of
     * p^2 = p0^2 - (p0/a)^2 s^2 over the nodes with p >= 0.25 max p, which
     * leaves out the nodes at the edge of the contact zone) and the total
     * force.
     */
    struct HertzReference
    {
      double line_load         = 0.; // P per unit thickness; 0: not line contact
      double point_load        = 0.; // P, total force; 0: not point contact
      double radius            = 1.; // effective radius R (R* of two curves)
      double axis              = 0.; // x of the axis (or of the centre)
      double axis_y            = 0.; // y of the centre (point contact)
      double modelled_fraction = 1.; // of the body (0.5 with symmetry)
      double contact_modulus   = 0.; // E*; 0: from the body's material
      double tolerance_a       = 0.;
      double tolerance_p0      = 0.;
      double tolerance_force   = 0.;
      double tolerance_area    = 0.; // on the contact area (length in 2D)
      bool   p0_from_fit       = false; // else: the node nearest the axis

      bool
      active() const
      {
        return line_load > 0. || point_load > 0.;
      }
      bool
      point_contact() const
      {
        return point_load > 0.;
      }
      /**
       * The effective radius R* of two surfaces of radii @p r1 and @p r2 at
       * the contact, 1/R* = 1/R1 + 1/R2, i.e. R* = R1 R2 / (R1 + R2); a
       * concave surface counts negative, a flat one (@p r2 = 0) leaves R1.
       */
      static double
      combined_radius(const double r1, const double r2)
      {
        return r2 == 0. ? r1 : r1 * r2 / (r1 + r2);
      }

      /// P: force per unit thickness (line) or total force (point).
      double
      load() const
      {
        return point_contact() ? point_load : line_load;
      }
      /// a: the contact half-width (line) or radius (point).
      double
      half_width() const;
      double
      peak_pressure() const;
      /// p(s) at the distance @p s from the axis or centre.
      double
      pressure(const double s) const;

      /// s of a point: x - x_axis (line) or the horizontal distance from
      /// the centre (point).
      template <int dim>
      double
      distance(const Point<dim> &x) const
      {
        if (point_contact() && dim == 3)
          {
            const double dx = x[0] - axis, dy = x[1] - axis_y;
            return std::sqrt(dx * dx + dy * dy);
          }
        return x[0] - axis;
      }

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);

      /**
       * Quantities hertz_a, hertz_p0, contact_nodes_inside_a, the other p0
       * (fit or axis node) and hertz_pressure_l2_error from (distance s,
       * pressure) samples of the contact boundary's nodes (s from
       * distance()). The last is the relative L2 error of the sampled
       * profile against Hertz's p(s), by the trapezoidal rule over the
       * samples sorted by s: sqrt(int (p_h - p)^2 ds / int p^2 ds) for line
       * contact, and with the weight s of the area element 2 pi s ds for
       * point contact (the samples at about the same s, scattered around
       * the centre, share that ring's weight).
       */
      std::vector<Quantity>
      quantities(const std::vector<std::pair<double, double>> &samples) const;
    };
  } // namespace Contact
} // namespace Signorini
