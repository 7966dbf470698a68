#pragma once

#include <vector>

// This header holds the parameter struct alone, so that the scene's
// parameters (parameters/scene_parameters.h) can include it without the
// friction law or a contact model.
//
// Entered into the scene as "Contact > Friction"
// (Parameters::ContactSection): read and checked; a coefficient > 0 is
// refused with exit 2 until a contact model uses the law (issue 50's next
// step); then the solver compatibility check refuses friction with a
// solver that cannot do it.

#include <deal.II/base/parameter_handler.h>

namespace Signorini
{
  using namespace dealii;

  namespace Contact
  {
    /**
     * The "Contact > Friction" subsection: Coulomb's coefficient, the slip
     * length of the regularised law (contact/friction_law.h) and the outer
     * fixed-point loop that updates the lagged normal forces and tangent
     * bases (doc/friction.md).
     */
    struct FrictionParameters
    {
      /// mu >= 0 [-]; 0 (the default) is frictionless.
      double coefficient = 0.;
      /// eps / h_k [-]: the slip length as a fraction of the contact
      /// point's local mesh size h_k (slip_length_at()).
      double slip_length = 1e-4;
      /// Relative change of the normal forces between outer iterations
      /// below which the loop stops [-].
      double outer_tolerance = 1e-6;
      /// At most this many outer iterations per load step.
      unsigned int max_outer_iterations = 10;
      /// "Mindlin reference": compare the stick zone and the tangential
      /// traction with Cattaneo-Mindlin's (contact/mindlin.h).
      bool   mindlin_reference      = false;
      double tolerance_stick_radius = 0.; // relative; 0: not checked
      /// The tangential load's direction for the Mindlin reference (2 or
      /// 3 entries, missing ones 0); empty: that of the largest friction
      /// force of the load path.
      std::vector<double> mindlin_load_direction;

      /// Whether the scene has friction.
      bool
      active() const
      {
        return coefficient > 0.;
      }

      /// The slip length [length] at a point of local mesh size @p h.
      double
      slip_length_at(const double h) const
      {
        return slip_length * h;
      }

      /// Declare the entries in the current subsection (the caller
      /// enters "Contact", then "Friction").
      static void
      declare_parameters(ParameterHandler &prm);

      /// Read the entries of the current subsection, then check().
      void
      parse_parameters(ParameterHandler &prm);

      /// Throws an InputError naming "Contact > Friction > KEY" for a
      /// coefficient that is negative or not finite, a slip length or an
      /// outer tolerance that is not > 0 and finite, or no outer
      /// iteration.
      void
      check() const;
    };
  } // namespace Contact
} // namespace Signorini
