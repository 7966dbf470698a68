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
   * samples (with the force's reference). Records the contact state in
   * @p record and writes the profile CSV @p profile_file (collective).
   */
  template <int dim>
  std::vector<Quantity>
  contact_quantities(const Contact::Model<dim>     &contact,
                     const Contact::HertzReference &hertz,
                     const VectorType              &u,
                     Report::Step                  &record,
                     const std::string             &profile_file);

  /**
   * The friction state of the ghosted solution @p u after a converged
   * load step: the friction force, the dissipated energy (of the step, and
   * summed with @p previous_total of the steps before), the sticking and
   * slipping points into @p record, and their quantities (collective).
   */
  template <int dim>
  std::vector<Quantity>
  friction_quantities(const Contact::FrictionTerm<dim> &friction,
                      const VectorType                 &u,
                      const double                      previous_total,
                      const MPI_Comm                    comm,
                      Report::Step                     &record);
} // namespace Signorini
