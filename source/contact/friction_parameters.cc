#include <signorini/contact/friction_parameters.h>
#include <signorini/input_error.h>

#include <deal.II/base/utilities.h>

#include <cmath>
#include <sstream>
#include <string>

namespace Signorini
{
  namespace Contact
  {
    namespace
    {
      const std::string where = "Contact > Friction > ";

      std::string
      text(const double value)
      {
        std::ostringstream s;
        s << value;
        return s.str();
      }
    } // namespace

    void
    FrictionParameters::declare_parameters(ParameterHandler &prm)
    {
      prm.declare_entry("Coefficient",
                        "0",
                        Patterns::Double(),
                        "Coulomb's friction coefficient mu [-], >= 0: a "
                        "sliding contact point carries the tangential "
                        "traction mu times its normal pressure. 0 (the "
                        "default): frictionless, and nothing of friction is "
                        "evaluated.");
      prm.declare_entry("Slip length",
                        "1e-4",
                        Patterns::Double(),
                        "The slip length eps of the regularised Coulomb law, "
                        "as a fraction of each contact point's local mesh "
                        "size h (eps = this x h) [-], > 0. A point whose "
                        "slip over the load step is below eps sticks "
                        "elastically, with the tangential stiffness "
                        "2 mu lambda / eps (lambda its normal force); at "
                        "or beyond eps it slides with |t_T| = mu lambda. "
                        "Smaller values are closer to exact Coulomb and "
                        "make the tangential stiffness larger: on "
                        "cattaneo_mindlin_2d, c/a is the same at 1e-4, 1e-5 "
                        "and 1e-6, and 0.03-0.07 larger at 1e-3; the run "
                        "takes 0.75x the time at 1e-3 and 3.5x at 1e-6 "
                        "(doc/friction.md).");
      prm.declare_entry("Outer tolerance",
                        "1e-6",
                        Patterns::Double(),
                        "The outer fixed-point loop of a load step, which "
                        "lags the normal forces and tangent bases, stops "
                        "when the normal forces change by less than this, "
                        "relative to the largest of them (max_k |lambda_k "
                        "- lambda_k,previous| / max_k lambda_k) [-], > 0.");
      prm.declare_entry("Maximum outer iterations",
                        "10",
                        Patterns::Integer(),
                        "At most this many outer iterations (minimisations "
                        "with updated normal forces and bases) per load "
                        "step, >= 1; a load step whose loop has not met the "
                        "'Outer tolerance' by then fails.");
      prm.enter_subsection("Mindlin reference");
      prm.declare_entry("Active",
                        "false",
                        Patterns::Bool(),
                        "Compare the stick zone and the tangential traction "
                        "with Cattaneo-Mindlin's solution for the Hertz "
                        "contact of Contact > Hertz reference under the "
                        "measured tangential load Q < mu P: c/a = "
                        "sqrt(1 - Q/(mu P)) for a cylinder (2D), "
                        "(1 - Q/(mu P))^(1/3) for a sphere (3D). Adds "
                        "stick_radius and friction_traction_l2_error to "
                        "the quantities. Needs a Hertz reference and "
                        "elastically similar bodies (an incompressible body "
                        "on the rigid foundation).");
      prm.declare_entry("Tolerance stick radius",
                        "0",
                        Patterns::Double(0.),
                        "Relative tolerance on stick_radius (0: not "
                        "checked).");
      prm.declare_entry("Load direction",
                        "",
                        Patterns::Anything(),
                        "The direction of the tangential load, 2 or 3 "
                        "comma-separated components (missing ones are 0; a "
                        "third is ignored in 2D), not all zero; its length "
                        "does not matter. The load ratio is then the "
                        "friction force's component along it over mu P, "
                        "signed, and the traction is compared along it. "
                        "Needed with a symmetry plane along the load (a "
                        "half ball): the modelled part's friction force has "
                        "a component normal to that plane, from the radial "
                        "tractions of the normal load, which the whole "
                        "body's cancels. Empty: the direction of the largest "
                        "friction force of the load path so far.");
      prm.leave_subsection();
    }

    void
    FrictionParameters::parse_parameters(ParameterHandler &prm)
    {
      coefficient     = prm.get_double("Coefficient");
      slip_length     = prm.get_double("Slip length");
      outer_tolerance = prm.get_double("Outer tolerance");
      const long iterations = prm.get_integer("Maximum outer iterations");
      if (iterations < 1)
        throw InputError(where + "Maximum outer iterations",
                         "must be >= 1, got " + prm.get("Maximum outer iterations"));
      max_outer_iterations = static_cast<unsigned int>(iterations);
      prm.enter_subsection("Mindlin reference");
      mindlin_reference      = prm.get_bool("Active");
      tolerance_stick_radius = prm.get_double("Tolerance stick radius");
      {
        const std::string key  = where + "Mindlin reference > Load direction";
        const std::string text = prm.get("Load direction");
        mindlin_load_direction.clear();
        for (const std::string &item : Utilities::split_string_list(text, ','))
          {
            double value = 0.;
            try
              {
                value = Utilities::string_to_double(item);
              }
            catch (...)
              {
                throw InputError(key, "'" + item + "' is not a number");
              }
            mindlin_load_direction.push_back(value);
          }
        double norm2 = 0.;
        for (const double v : mindlin_load_direction)
          norm2 += v * v;
        if (!mindlin_load_direction.empty() &&
            (mindlin_load_direction.size() < 2 || mindlin_load_direction.size() > 3 ||
             !(norm2 > 0.) || !std::isfinite(norm2)))
          throw InputError(key,
                           "must be 2 or 3 finite components, not all zero, got '" + text +
                             "'");
      }
      prm.leave_subsection();
      check();
    }

    void
    FrictionParameters::check() const
    {
      if (!(coefficient >= 0.) || !std::isfinite(coefficient))
        throw InputError(where + "Coefficient",
                         "must be a finite number >= 0, got " + text(coefficient));
      if (!(slip_length > 0.) || !std::isfinite(slip_length))
        throw InputError(where + "Slip length",
                         "must be a finite number > 0 (a fraction of the mesh "
                         "size), got " + text(slip_length));
      if (!(outer_tolerance > 0.) || !std::isfinite(outer_tolerance))
        throw InputError(where + "Outer tolerance",
                         "must be a finite number > 0, got " + text(outer_tolerance));
      if (max_outer_iterations < 1)
        throw InputError(where + "Maximum outer iterations",
                         "must be >= 1, got " + std::to_string(max_outer_iterations));
    }
  } // namespace Contact
} // namespace Signorini
