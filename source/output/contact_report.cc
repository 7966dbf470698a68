#include <signorini/output/contact_report.h>

namespace Signorini
{
  template <int dim>
  std::vector<Quantity>
  contact_quantities(const Contact::Model<dim>     &contact,
                     const Contact::HertzReference &hertz,
                     const VectorType              &u,
                     Report::Step                  &record,
                     const std::string             &profile_file)
  {
    std::vector<Quantity> quantities;
    // The nodes' state once, for the summary, the Hertz samples and the
    // profile.
    const auto samples = contact.samples().node_samples(u, contact.forces());
    const auto summary = contact.summarize_state(u, samples);
    record.active_nodes           = summary.n_active;
    record.penetration_ratio      = summary.max_penetration_ratio;
    record.has_pairs              = summary.has_pairs;
    record.pairs                  = summary.pairs;
    for (unsigned int d = 0; d < dim; ++d)
      record.contact_force_vector[d] = summary.total_force[d];
    record.contact_moment = summary.moment;
    record.contact_area   = summary.area;
    std::vector<std::pair<Point<dim>, double>> pressure;
    if (hertz.active())
      pressure = contact.samples().gather_pressure(samples);

    const char *axes = "xyz";
    for (unsigned int d = 0; d < dim; ++d)
      {
        Quantity q;
        q.name  = std::string("contact_force_") + axes[d];
        q.value = summary.total_force[d];
        q.estimable = true;
        q.scale     = summary.total_force.norm();
        if (d == dim - 1 && hertz.active())
          {
            q.has_reference = true;
            q.reference     = hertz.modelled_fraction * hertz.load();
            q.tolerance     = hertz.tolerance_force;
          }
        quantities.push_back(q);
      }
    if (hertz.active())
      {
        // The Hertz contact area: 2a per unit thickness (line contact) or
        // pi a^2 (point contact), times the modelled fraction.
        const double a = hertz.half_width();
        Quantity     area;
        area.name          = "contact_area";
        area.value         = summary.area;
        area.has_reference = true;
        area.reference     = hertz.modelled_fraction *
                         (hertz.point_contact() ? numbers::PI * a * a : 2. * a);
        area.tolerance = hertz.tolerance_area;
        area.estimable = true;
        quantities.push_back(area);
      }
    Quantity active;
    active.name  = "active_contact_nodes";
    active.value = record.active_nodes;
    quantities.push_back(active);
    Quantity penetration;
    penetration.name  = "max_penetration_over_h";
    penetration.value = record.penetration_ratio;
    quantities.push_back(penetration);
    std::function<double(const Point<dim> &)> reference;
    if (hertz.active())
      {
        std::vector<std::pair<double, double>> samples;
        for (const auto &p : pressure)
          samples.emplace_back(hertz.distance(p.first), p.second);
        for (const auto &q : hertz.quantities(samples))
          quantities.push_back(q);
        reference = [&hertz](const Point<dim> &x) {
          return hertz.pressure(hertz.distance(x));
        };
      }
    contact.samples().write_profile(profile_file, u, contact.forces(), samples, reference);
    return quantities;
  }

  template <int dim>
  std::vector<Quantity>
  friction_quantities(const Contact::FrictionTerm<dim> &friction,
                      const VectorType                 &u,
                      const double                      previous_total,
                      const MPI_Comm                    comm,
                      Report::Step                     &record)
  {
    const auto totals = friction.totals(u, comm);
    for (unsigned int d = 0; d < dim; ++d)
      record.friction_force[d] = totals.force[d];
    record.dissipated_energy       = totals.dissipation;
    record.total_dissipated_energy = previous_total + totals.dissipation;
    record.stick_points            = totals.n_stick;
    record.slip_points             = totals.n_slip;
    std::vector<Quantity> quantities;
    const char           *axes = "xyz";
    for (unsigned int d = 0; d < dim; ++d)
      {
        Quantity q;
        q.name  = std::string("friction_force_") + axes[d];
        q.value = totals.force[d];
        quantities.push_back(q);
      }
    Quantity dissipated;
    dissipated.name  = "dissipated_energy";
    dissipated.value = record.total_dissipated_energy;
    quantities.push_back(dissipated);
    Quantity stick;
    stick.name  = "stick_points";
    stick.value = totals.n_stick;
    quantities.push_back(stick);
    Quantity slip;
    slip.name  = "slip_points";
    slip.value = totals.n_slip;
    quantities.push_back(slip);
    return quantities;
  }

  template std::vector<Quantity>
  friction_quantities<2>(const Contact::FrictionTerm<2> &, const VectorType &, double,
                         MPI_Comm, Report::Step &);
  template std::vector<Quantity>
  friction_quantities<3>(const Contact::FrictionTerm<3> &, const VectorType &, double,
                         MPI_Comm, Report::Step &);

  template std::vector<Quantity>
  contact_quantities<2>(const Contact::Model<2> &, const Contact::HertzReference &,
                        const VectorType &, Report::Step &, const std::string &);
  template std::vector<Quantity>
  contact_quantities<3>(const Contact::Model<3> &, const Contact::HertzReference &,
                        const VectorType &, Report::Step &, const std::string &);
} // namespace Signorini
