#include <signorini/contact/mindlin.h>
#include <signorini/output/contact_report.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace Signorini
{
  namespace
  {
    /**
     * The friction's quantities from its @p points (this rank's) and the
     * contact state @p summary: the friction force, the dissipated energy,
     * the sticking and slipping points and, with a Mindlin reference,
     * the stick zone and the tangential traction against
     * Cattaneo-Mindlin's under the measured load ratio Q/(mu P), and
     * Mindlin-Deresiewicz's when the load has turned back (the load ratios
     * of the @p previous steps and this one, signed along the direction of
     * the largest friction force among them: Mindlin::LoadPath).
     */
    template <int dim>
    std::vector<Quantity>
    friction_quantities(
      const Contact::FrictionTerm<dim>                              &friction,
      const std::vector<typename Contact::FrictionTerm<dim>::PointSample> &points,
      const typename Contact::Model<dim>::StateSummary              &summary,
      const Contact::HertzReference                                 &hertz,
      const std::vector<Report::Step>                               &previous,
      Report::Step                                                  &record)
    {
      const MPI_Comm comm = friction.boundary().get_communicator();
      typename Contact::FrictionTerm<dim>::Totals totals;
      for (const auto &p : points)
        {
          totals.force += p.force;
          totals.dissipation += p.dissipation;
          totals.n_stick += (p.status == Contact::FrictionStatus::stick);
          totals.n_slip += (p.status == Contact::FrictionStatus::slip);
        }
      for (unsigned int d = 0; d < dim; ++d)
        totals.force[d] = Utilities::MPI::sum(totals.force[d], comm);
      totals.dissipation = Utilities::MPI::sum(totals.dissipation, comm);
      totals.n_stick     = Utilities::MPI::sum(totals.n_stick, comm);
      totals.n_slip      = Utilities::MPI::sum(totals.n_slip, comm);

      for (unsigned int d = 0; d < dim; ++d)
        record.friction_force[d] = totals.force[d];
      record.dissipated_energy       = totals.dissipation;
      record.total_dissipated_energy =
        (previous.empty() ? 0. : previous.back().total_dissipated_energy) + totals.dissipation;
      record.stick_points            = totals.n_stick;
      record.slip_points             = totals.n_slip;

      std::vector<Quantity> quantities;
      const auto add = [&quantities](const std::string &name, const double value) {
        Quantity q;
        q.name  = name;
        q.value = value;
        quantities.push_back(q);
      };
      for (unsigned int d = 0; d < dim; ++d)
        add(std::string("friction_force_") + "xyz"[d], totals.force[d]);
      add("dissipated_energy", record.total_dissipated_energy);
      add("stick_points", totals.n_stick);
      add("slip_points", totals.n_slip);

      const auto &parameters = friction.friction_parameters();
      if (!parameters.mindlin_reference || !hertz.active())
        return quantities;
      // Cattaneo-Mindlin with the measured loads: Q the friction force's
      // magnitude, P the normal contact force (both of the modelled part).
      const double mu    = parameters.coefficient;
      const double Q     = totals.force.norm();
      const double P     = std::abs(summary.total_force[dim - 1]);
      const double ratio_of_norm = P > 0. ? Q / (mu * P) : 0.;
      // The load path: each step's friction force along the load's line,
      // 'Load direction' or that of the largest friction force so far (a
      // load that turns back stays on its line).
      Tensor<1, dim> line;
      if (!parameters.mindlin_load_direction.empty())
        {
          for (unsigned int d = 0; d < dim && d < parameters.mindlin_load_direction.size(); ++d)
            line[d] = parameters.mindlin_load_direction[d];
          line /= line.norm();
        }
      else
        {
          double largest = Q;
          if (Q > 0.)
            line = totals.force / Q;
          for (const auto &s : previous)
            {
              Tensor<1, dim> f;
              for (unsigned int d = 0; d < dim; ++d)
                f[d] = s.friction_force[d];
              if (f.norm() > largest)
                {
                  largest = f.norm();
                  line    = f / largest;
                }
            }
        }
      Contact::Mindlin::LoadPath path;
      const auto signed_ratio = [&](const Tensor<1, 3> &force, const Tensor<1, 3> &normal) {
        Tensor<1, dim> f;
        for (unsigned int d = 0; d < dim; ++d)
          f[d] = force[d];
        const double p = std::abs(normal[dim - 1]);
        return p > 0. ? f * line / (mu * p) : 0.;
      };
      for (const auto &s : previous)
        path.add(signed_ratio(s.friction_force, s.contact_force_vector));
      path.add(signed_ratio(record.friction_force, record.contact_force_vector));
      // Along a given direction the signed ratio's magnitude; otherwise
      // that of the whole friction force, as before.
      const double ratio =
        parameters.mindlin_load_direction.empty() ?
          ratio_of_norm :
          std::abs(signed_ratio(record.friction_force, record.contact_force_vector));
      add("tangential_load_ratio", ratio);
      const double a     = hertz.half_width();
      const double c_ref = a * path.stick_ratio(hertz.point_contact());
      // The stick zone's edges: midway between its outermost sticking
      // point and the nearest slipping point beyond it. A line contact
      // takes the half of the zone's width (its centre may shift with the
      // tangential load); a point contact, the radius of its area (below).
      const auto position = [&hertz](const Point<dim> &X) {
        return hertz.point_contact() ? std::abs(hertz.distance(X)) : hertz.distance(X);
      };
      const double big = std::numeric_limits<double>::max();
      double stick_lo = big, stick_hi = -big;
      for (const auto &p : points)
        if (p.status == Contact::FrictionStatus::stick)
          {
            const double r = position(p.X);
            stick_lo = std::min(stick_lo, r);
            stick_hi = std::max(stick_hi, r);
          }
      stick_lo = Utilities::MPI::min(stick_lo, comm);
      stick_hi = Utilities::MPI::max(stick_hi, comm);
      double slip_lo = -big, slip_hi = big; // the nearest slipping points
      for (const auto &p : points)
        if (p.status == Contact::FrictionStatus::slip)
          {
            const double r = position(p.X);
            if (r < stick_lo)
              slip_lo = std::max(slip_lo, r);
            if (r > stick_hi)
              slip_hi = std::min(slip_hi, r);
          }
      slip_lo = Utilities::MPI::max(slip_lo, comm);
      slip_hi = Utilities::MPI::min(slip_hi, comm);
      const double edge_hi = slip_hi < big ? 0.5 * (stick_hi + slip_hi) : stick_hi;
      const double edge_lo = slip_lo > -big ? 0.5 * (stick_lo + slip_lo) : stick_lo;
      // A point contact's stick zone is a disk only without coupling and
      // without a tilt of the pressure; the load's moment and the radial
      // tractions of the normal load shift it along the load and make it
      // lopsided, so that its farthest point overstates it. Its radius is
      // that of the disk of its area: the sticking points' tributary
      // areas over the modelled fraction (the 3D counterpart of the line
      // contact's width between its edges).
      double stick_area = 0.;
      for (const auto &p : points)
        if (p.status == Contact::FrictionStatus::stick)
          stick_area += p.weight;
      stick_area    = Utilities::MPI::sum(stick_area, comm);
      double radius = 0.;
      if (stick_hi >= stick_lo)
        radius = hertz.point_contact() ?
                   std::sqrt(stick_area / (numbers::PI * hertz.modelled_fraction)) :
                   0.5 * (edge_hi - edge_lo);
      Quantity c;
      c.name          = "stick_radius";
      c.value         = radius;
      c.has_reference = true;
      c.reference     = c_ref;
      c.tolerance     = parameters.tolerance_stick_radius;
      // A length of the continuous model: the refinement cycles estimate
      // its error, relative to Hertz's a (an error in c/a, which stays
      // meaningful when the stick zone vanishes in gross slip).
      c.estimable = true;
      c.scale     = a;
      quantities.push_back(c);
      record.tangential_load_ratio  = ratio;
      record.stick_radius           = radius;
      record.stick_radius_reference = c_ref;
      // The tangential traction along the load's line against Mindlin's
      // q(r) (Mindlin-Deresiewicz's after a reversal), relative L2 over
      // the contact nodes (tributary weights).
      const double mu_p0  = mu * hertz.peak_pressure();
      double       error2 = 0., norm2 = 0.;
      for (const auto &p : points)
        {
          if (p.weight <= 0.)
            continue;
          const double q_h = p.force * line / p.weight;
          const double q   = path.traction(std::abs(hertz.distance(p.X)), a, mu_p0,
                                         hertz.point_contact());
          error2 += p.weight * (q_h - q) * (q_h - q);
          norm2 += p.weight * q * q;
        }
      error2 = Utilities::MPI::sum(error2, comm);
      norm2  = Utilities::MPI::sum(norm2, comm);
      add("friction_traction_l2_error",
          norm2 > 0. ? std::sqrt(error2 / norm2) : std::numeric_limits<double>::quiet_NaN());
      return quantities;
    }
  } // namespace

  template <int dim>
  std::vector<Quantity>
  contact_quantities(const Contact::Model<dim>     &contact,
                     const Contact::HertzReference &hertz,
                     const VectorType              &u,
                     Report::Step                  &record,
                     const std::string             &profile_file,
                     const Contact::FrictionTerm<dim> *friction,
                     const std::vector<Report::Step>  &previous)
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
    // A model of several pairs: each pair's (and body's) quantities, and
    // the values of its load_steps.csv columns.
    const auto parts   = contact.part_quantities(u, profile_file);
    const auto columns = contact.part_columns();
    record.part_values.assign(columns.size(), 0.);
    for (const auto &q : parts)
      {
        const auto column = std::find(columns.begin(), columns.end(), q.name);
        if (column != columns.end())
          record.part_values[column - columns.begin()] = q.value;
        quantities.push_back(q);
      }
    if (!friction)
      {
        contact.samples().write_profile(profile_file, u, contact.forces(), samples,
                                        reference);
        return quantities;
      }
    auto       with_friction = samples;
    const auto points        = friction->point_samples(u);
    AssertThrow(points.size() == samples.size(),
                ExcMessage("the friction term's points are not the contact nodes"));
    for (unsigned int k = 0; k < points.size(); ++k)
      with_friction[k].extra = Contact::FrictionTerm<dim>::profile_values(points[k]);
    for (const auto &q : friction_quantities(*friction, points, summary, hertz,
                                             previous, record))
      quantities.push_back(q);
    contact.samples().write_profile(profile_file, u, contact.forces(), with_friction,
                                    reference, Contact::FrictionTerm<dim>::profile_header());
    return quantities;
  }

  template std::vector<Quantity>
  contact_quantities<2>(const Contact::Model<2> &, const Contact::HertzReference &,
                        const VectorType &, Report::Step &, const std::string &,
                        const Contact::FrictionTerm<2> *,
                        const std::vector<Report::Step> &);
  template std::vector<Quantity>
  contact_quantities<3>(const Contact::Model<3> &, const Contact::HertzReference &,
                        const VectorType &, Report::Step &, const std::string &,
                        const Contact::FrictionTerm<3> *,
                        const std::vector<Report::Step> &);
} // namespace Signorini
