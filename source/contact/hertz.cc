#include <signorini/contact/hertz.h>
#include <signorini/input_error.h>
#include <signorini/parameters/lists.h>

#include <deal.II/base/utilities.h>

#include <deal.II/base/numbers.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace Signorini
{
  namespace Contact
  {
    double
    HertzReference::half_width() const
    {
      if (point_contact())
        return std::cbrt(3. * point_load * radius / (4. * contact_modulus));
      return std::sqrt(4. * line_load * radius / (numbers::PI * contact_modulus));
    }

    double
    HertzReference::peak_pressure() const
    {
      const double a = half_width();
      if (point_contact())
        return 3. * point_load / (2. * numbers::PI * a * a);
      return 2. * line_load / (numbers::PI * a);
    }

    double
    HertzReference::pressure(const double s) const
    {
      const double r = s / half_width();
      return std::abs(r) < 1. ? peak_pressure() * std::sqrt(1. - r * r) : 0.;
    }

    void
    HertzReference::declare_parameters(ParameterHandler &prm)
    {
      prm.declare_entry("Line load",
                        "0",
                        Patterns::Double(0.),
                        "Line contact (2D): P, force per unit thickness on "
                        "the whole cylinder [force/length]; 0: no line "
                        "contact reference.");
      prm.declare_entry("Point load",
                        "0",
                        Patterns::Double(0.),
                        "Point contact (3D, a sphere): P, total force on "
                        "the whole sphere [force]: a = (3 P R / (4 E*))^(1/3), "
                        "p0 = 3 P / (2 pi a^2). 0: no point contact "
                        "reference. At most one of 'Line load' and 'Point "
                        "load' is > 0; neither: the scene has no Hertz "
                        "reference.");
      prm.declare_entry("Radius",
                        "1",
                        Patterns::Double(0.),
                        "Radius R1 of the contact body's surface at the "
                        "contact point [length]; with 'Second radius' = 0 "
                        "the effective radius R of the formulas, which may "
                        "then be given already combined, 1/R = 1/R1 + 1/R2 "
                        "(a concave foundation of radius R2 counts "
                        "negative: 1/R = 1/R1 - 1/R2).");
      prm.declare_entry("Second radius",
                        "0",
                        Patterns::Double(),
                        "Radius R2 of the other surface at the contact "
                        "point [length]: body 2's (two cylinders, two "
                        "spheres) or a curved foundation's, negative if it "
                        "is concave (R2 < -R1: a groove or cup wider than "
                        "the body). The formulas then use the effective "
                        "radius R* = R1 R2 / (R1 + R2), i.e. 1/R* = 1/R1 + "
                        "1/R2. 0: the other surface is flat (a plane, a "
                        "block) or R2 is already in 'Radius'.");
      prm.declare_entry("Axis position",
                        "0",
                        Patterns::List(Patterns::Double(), 1, 2),
                        "Line contact: x of the cylinder's axis [length]. "
                        "Point contact: x, y of the vertical line through "
                        "the sphere's centre (y = 0 if only x is given); "
                        "the pressure is a function of the distance from "
                        "it.");
      prm.declare_entry("Modelled fraction",
                        "1",
                        Patterns::Double(0., 1.),
                        "Fraction of the body the mesh holds (0.5 for a "
                        "quarter disk with a symmetry line, 0.25 for an "
                        "octant ball with two symmetry planes): the "
                        "reference total contact force is this times P.");
      prm.declare_entry("Contact modulus",
                        "0",
                        Patterns::Double(0.),
                        "E* [stress]; 0: E / (1 - nu^2) of Body 1's "
                        "small-strain moduli (a rigid foundation).");
      prm.declare_entry("Tolerance a",
                        "0",
                        Patterns::Double(0.),
                        "Relative tolerance on the contact half-width a (0: "
                        "not checked).");
      prm.declare_entry("Tolerance p0",
                        "0",
                        Patterns::Double(0.),
                        "Relative tolerance on the peak pressure p0 (0: not "
                        "checked).");
      prm.declare_entry("Peak pressure from",
                        "axis node",
                        Patterns::Selection("axis node|fit"),
                        "Which estimate of p0 is hertz_p0 (checked against "
                        "the tolerance): axis node: the pressure of the node "
                        "nearest the axis; fit: sqrt(A) of the least-squares "
                        "fit p^2 = A - B x^2 that also gives a (less "
                        "sensitive to node-to-node scatter of the nodal "
                        "pressure). The other estimate is reported as "
                        "hertz_p0_fit or hertz_p0_axis_node.");
      prm.declare_entry("Tolerance force",
                        "0",
                        Patterns::Double(0.),
                        "Relative tolerance on the total contact force (0: "
                        "not checked).");
      prm.declare_entry("Tolerance area",
                        "0",
                        Patterns::Double(0.),
                        "Relative tolerance on the contact area (quantity "
                        "contact_area: the tributary length (2D) or area "
                        "(3D) of the contact nodes with a positive "
                        "pressure) against Hertz's 2a (line contact, per "
                        "unit thickness) or pi a^2 (point contact), times "
                        "'Modelled fraction' (0: not checked).");
    }

    void
    HertzReference::parse_parameters(ParameterHandler &prm)
    {
      line_load         = prm.get_double("Line load");
      point_load        = prm.get_double("Point load");
      radius            = prm.get_double("Radius");
      {
        const std::string context = "Contact > Hertz reference";
        const auto        n =
          Utilities::split_string_list(prm.get("Axis position")).size();
        const auto position =
          get_list<double>(prm, "Axis position", std::max<std::size_t>(n, 1), context);
        axis   = position[0];
        axis_y = position.size() > 1 ? position[1] : 0.;
      }
      modelled_fraction = prm.get_double("Modelled fraction");
      contact_modulus   = prm.get_double("Contact modulus");
      tolerance_a       = prm.get_double("Tolerance a");
      tolerance_p0      = prm.get_double("Tolerance p0");
      tolerance_force   = prm.get_double("Tolerance force");
      tolerance_area    = prm.get_double("Tolerance area");
      p0_from_fit       = (prm.get("Peak pressure from") == "fit");
      if (line_load > 0. && point_load > 0.)
        throw InputError("Contact > Hertz reference > Point load",
                         "give either 'Line load' (line contact, 2D) or "
                         "'Point load' (point contact, 3D), not both");
      if (active() && !(radius > 0.))
        throw InputError("Contact > Hertz reference > Radius", "must be > 0");
      const double second_radius = prm.get_double("Second radius");
      if (active() && second_radius != 0.)
        {
          // A concave second surface must be wider than the first (else
          // the contact is conforming, or the body does not fit).
          if (!(second_radius > 0. || -second_radius > radius))
            throw InputError("Contact > Hertz reference > Second radius",
                             "a concave surface (R2 < 0) must be wider than "
                             "the body: -R2 > R1 = " + prm.get("Radius") +
                               ", got " + prm.get("Second radius"));
          radius = combined_radius(radius, second_radius);
        }
      if (active() && !(modelled_fraction > 0.))
        throw InputError("Contact > Hertz reference > Modelled fraction",
                         "must be > 0");
    }

    std::vector<Quantity>
    HertzReference::quantities(
      const std::vector<std::pair<double, double>> &samples) const
    {
      std::vector<Quantity> q(5);
      q[0].name          = "hertz_a";
      q[0].has_reference = true;
      q[0].reference     = half_width();
      q[0].tolerance     = tolerance_a;
      q[0].value         = std::numeric_limits<double>::quiet_NaN();
      q[1].name          = "hertz_p0";
      q[1].has_reference = true;
      q[1].reference     = peak_pressure();
      q[1].tolerance     = tolerance_p0;
      q[1].value         = std::numeric_limits<double>::quiet_NaN();
      q[2].name          = "contact_nodes_inside_a";
      q[3].name          = p0_from_fit ? "hertz_p0_axis_node" : "hertz_p0_fit";
      q[3].value         = std::numeric_limits<double>::quiet_NaN();
      q[0].estimable = q[1].estimable = q[3].estimable = true;
      q[4].name          = "hertz_pressure_l2_error";
      q[4].value         = std::numeric_limits<double>::quiet_NaN();
      if (samples.empty())
        return q;

      {
        std::vector<std::pair<double, double>> sorted(samples);
        std::sort(sorted.begin(), sorted.end());
        // The trapezoidal rule: sample i weighs half its two intervals
        // (times s, the ring's circumference over 2 pi, for point contact).
        double error2 = 0., norm2 = 0.;
        for (std::size_t i = 0; i < sorted.size(); ++i)
          {
            const double weight =
              0.5 *
              (sorted[std::min(i + 1, sorted.size() - 1)].first -
               sorted[i > 0 ? i - 1 : 0].first) *
              (point_contact() ? std::abs(sorted[i].first) : 1.);
            const double reference = pressure(sorted[i].first);
            const double e         = sorted[i].second - reference;
            error2 += weight * e * e;
            norm2 += weight * reference * reference;
          }
        if (norm2 > 0.)
          q[4].value = std::sqrt(error2 / norm2);
      }

      double p_max = 0., nearest = std::numeric_limits<double>::max();
      for (const auto &s : samples)
        {
          p_max = std::max(p_max, s.second);
          const double d = std::abs(s.first);
          if (d < nearest)
            {
              nearest    = d;
              q[1].value = s.second;
            }
          if (d < half_width())
            q[2].value += 1.;
        }
      // Least squares of p^2 = A - B s^2 over the well-loaded nodes.
      double       sx = 0., sy = 0., sxx = 0., sxy = 0.;
      unsigned int n = 0;
      for (const auto &s : samples)
        if (s.second >= 0.25 * p_max)
          {
            const double x = s.first * s.first;
            const double y = s.second * s.second;
            sx += x;
            sy += y;
            sxx += x * x;
            sxy += x * y;
            ++n;
          }
      const double det = n * sxx - sx * sx;
      if (n >= 2 && det > 0.)
        {
          const double slope     = (n * sxy - sx * sy) / det; // -B
          const double intercept = (sy - slope * sx) / n;     // A
          if (slope < 0. && intercept > 0.)
            {
              q[0].value = std::sqrt(-intercept / slope);
              q[3].value = std::sqrt(intercept); // the fit's p0
            }
        }
      if (p0_from_fit) // q[1] holds the axis node's value
        std::swap(q[1].value, q[3].value);
      return q;
    }
  } // namespace Contact
} // namespace Signorini
