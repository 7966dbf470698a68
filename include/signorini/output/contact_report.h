#pragma once

#include <signorini/contact/friction_term.h>
#include <signorini/contact/hertz.h>
#include <signorini/contact/model.h>
#include <signorini/output/report.h>

#include <string>
#include <vector>

namespace Signorini
{
  /**
   * The contact quantities of a converged state: the components of the
   * total contact force, the active nodes, the largest penetration over h
   * and, if @p hertz is active, the Hertz quantities from the pressure
   * samples (with the force's reference). With @p friction: the friction
   * force, the dissipated energy (of the step, and summed with that of
   * the @p previous steps), the sticking and slipping points, and, with a
   * Mindlin reference, stick_radius and the tangential traction's L2 error
   * against the reference of the load path that the @p previous steps'
   * friction forces and this one's describe (contact/mindlin.h); the profile then
   * has the friction's columns too. Records the contact state in
   * @p record and writes the profile CSV @p profile_file (collective).
   */
  template <int dim>
  std::vector<Quantity>
  contact_quantities(const Contact::Model<dim>     &contact,
                     const Contact::HertzReference &hertz,
                     const VectorType              &u,
                     Report::Step                  &record,
                     const std::string             &profile_file,
                     const Contact::FrictionTerm<dim> *friction = nullptr,
                     const std::vector<Report::Step>  &previous = {});

} // namespace Signorini
