#include <signorini/input_error.h>
#include <signorini/scene/refinement.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/distributed/grid_refinement.h>
#include <deal.II/numerics/error_estimator.h>
#include <deal.II/numerics/rtree.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace Signorini
{
  void
  RefinementParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Number of cycles",
                      "0",
                      Patterns::Integer(0, 30),
                      "Adaptive refinement cycles after the load path is "
                      "solved: estimate, refine and coarsen, transfer the "
                      "solution to the new mesh as the initial guess, and "
                      "solve the final load again. 0: the mesh stays as "
                      "built. summary.json and refinement_cycles.csv record "
                      "every cycle; the VTU of each is in refinement.pvd.");
    prm.declare_entry("Target accuracy",
                      "0",
                      Patterns::Double(0., 1.),
                      "Target accuracy mode [-]: run the refinement cycles "
                      "until the estimated discretisation error of every "
                      "quantity in 'Target quantities', relative to the "
                      "quantity (to the vector's length for a component of "
                      "a force), is at most this; 'Number of cycles' is then "
                      "the most cycles it may take, and at least 2 (an "
                      "estimate needs three meshes). A run that ends its "
                      "cycles above the target exits as a run outside its "
                      "tolerances. The estimates come from the cycles' "
                      "values (doc/accuracy-cost.md) and are in summary.json "
                      "with any number of cycles. 0: run all the cycles.");
    prm.declare_entry("Estimate from a coarser mesh",
                      "false",
                      Patterns::Bool(),
                      "Give every quantity of a run without refinement "
                      "cycles an estimated error: solve the load path on "
                      "the scene's mesh with every cell coarsened once "
                      "(where its siblings allow), then refine those cells "
                      "back and solve the final load again on the scene's "
                      "own mesh from the transferred answer (reported as "
                      "refinement cycles 0 and 1). The estimate is the "
                      "change between the two meshes (order 1 assumed). "
                      "Costs the coarse solve (about a quarter of the run "
                      "in 2D, an eighth in 3D) and the final solve from a "
                      "close start. Not with 'Number of cycles' > 0, whose "
                      "meshes give the estimates.");
    prm.declare_entry("Target quantities",
                      "",
                      Patterns::List(Patterns::Anything()),
                      "The quantities (names as in summary.json, e.g. "
                      "hertz_a, hertz_p0) the target accuracy applies to; "
                      "empty: every quantity with an estimate.");
    prm.declare_entry("Estimator",
                      "combined",
                      Patterns::Selection("kelly|contact|combined"),
                      "Which cells to refine. kelly: jumps of the "
                      "displacement gradient across faces (stress "
                      "concentrations). contact: how much the contact "
                      "pressure changes across each face of the contact "
                      "boundary (the contact zone's edges and where the "
                      "pressure varies fast); zero away from contact. "
                      "combined: the sum of both, each divided by its "
                      "largest value.");
    prm.declare_entry("Strategy",
                      "fraction",
                      Patterns::Selection("fraction|number"),
                      "fraction: refine the cells with the largest "
                      "indicators that together hold 'Refine fraction' of "
                      "the total (and coarsen those holding 'Coarsen "
                      "fraction'). number: refine that fraction of the "
                      "cells (and coarsen that fraction). Cells with a zero "
                      "indicator are never refined.");
    prm.declare_entry("Refine fraction",
                      "0.3",
                      Patterns::Double(0., 1.),
                      "See Strategy [-].");
    prm.declare_entry("Coarsen fraction",
                      "0",
                      Patterns::Double(0., 1.),
                      "See Strategy [-]. Refine plus coarsen fraction must "
                      "not exceed 1.");
    prm.declare_entry("Maximum level",
                      "12",
                      Patterns::Integer(1, 30),
                      "No cell is refined beyond this level (the coarse mesh "
                      "is level 0; Global and Local refinements count).");
    prm.declare_entry("Uniform contact zone",
                      "true",
                      Patterns::Bool(),
                      "Keep the cells near the contact zone (within 'Contact "
                      "zone depth' times its extent of the nodes with a "
                      "pressure) at one level: when any of them is refined, "
                      "all coarser ones are too. On a graded mesh the nodal "
                      "contact pressure zigzags by about the size of the "
                      "grading (measured: +-0.5% on Hertz), while on an "
                      "evenly spaced one it is smooth and converges faster.");
    prm.declare_entry("Contact zone depth",
                      "1",
                      Patterns::Double(0.),
                      "See 'Uniform contact zone' [-]: the stresses under a "
                      "Hertz contact vary over a depth of about the contact "
                      "width.");
    prm.declare_entry("Contact band refinements",
                      "0",
                      Patterns::Integer(0, 20),
                      "Before the first solve, refine this many times the "
                      "cells near the potential contact zone only: the part "
                      "of the contact boundary (Contact > Contact boundary "
                      "id; with Type = pairs each pair's contact boundary, "
                      "with its own gap) whose initial gap is at most "
                      "'Contact band gap', and the cells within 'Contact "
                      "band width' of it.");
    prm.declare_entry("Contact band width",
                      "0",
                      Patterns::Double(0.),
                      "Distance from the potential contact zone within which "
                      "cells are refined [length]; 0: the cells that touch "
                      "it.");
    prm.declare_entry("Contact band gap",
                      "-1",
                      Patterns::Double(),
                      "The potential contact zone: the points of the contact "
                      "boundary whose gap in the reference configuration is "
                      "at most this [length] (to the foundation psi, or to "
                      "the bounding box of body 2). Negative: the whole "
                      "contact boundary.");
  }

  void
  RefinementParameters::parse_parameters(ParameterHandler &prm)
  {
    cycles = prm.get_integer("Number of cycles");
    const std::string e = prm.get("Estimator");
    estimator = (e == "kelly" ? Estimator::kelly :
                 e == "contact" ? Estimator::contact : Estimator::combined);
    strategy = (prm.get("Strategy") == "number" ? Strategy::number :
                                                  Strategy::fraction);
    refine_fraction  = prm.get_double("Refine fraction");
    coarsen_fraction = prm.get_double("Coarsen fraction");
    if (refine_fraction + coarsen_fraction > 1.)
      throw InputError("Mesh refinement > Coarsen fraction",
                       "Refine fraction + Coarsen fraction = " +
                         std::to_string(refine_fraction + coarsen_fraction) +
                         " exceeds 1");
    max_level        = prm.get_integer("Maximum level");
    band_refinements = prm.get_integer("Contact band refinements");
    band_width       = prm.get_double("Contact band width");
    band_gap         = prm.get_double("Contact band gap");
    uniform_zone     = prm.get_bool("Uniform contact zone");
    zone_depth       = prm.get_double("Contact zone depth");
    target_accuracy  = prm.get_double("Target accuracy");
    target_quantities =
      Utilities::split_string_list(prm.get("Target quantities"), ',');
    if (target_accuracy > 0. && cycles < 2)
      throw InputError("Mesh refinement > Target accuracy",
                       "a target accuracy needs 'Number of cycles' >= 2 (the "
                       "error estimate needs three meshes); it is " +
                         std::to_string(cycles));
    coarser_mesh_estimate = prm.get_bool("Estimate from a coarser mesh");
    if (coarser_mesh_estimate && cycles > 0)
      throw InputError("Mesh refinement > Estimate from a coarser mesh",
                       "the refinement cycles' meshes give the estimates "
                       "already: set 'Number of cycles' = 0 (it is " +
                         std::to_string(cycles) + ") or this entry to false");
    if (!std::isfinite(band_width) || !std::isfinite(band_gap))
      throw InputError("Mesh refinement > Contact band width",
                       "the band width and gap must be finite numbers");
  }

  std::string
  RefinementParameters::estimator_name() const
  {
    return estimator == Estimator::kelly   ? "kelly" :
           estimator == Estimator::contact ? "contact" :
                                             "combined";
  }

  namespace Refinement
  {
    namespace
    {
      /// The points of @p local of every rank, on every rank.
      template <int dim>
      std::vector<Point<dim>>
      all_points(const MPI_Comm comm, const std::vector<Point<dim>> &local)
      {
        std::vector<Point<dim>> points;
        for (const auto &part : Utilities::MPI::all_gather(comm, local))
          points.insert(points.end(), part.begin(), part.end());
        return points;
      }

      /// Whether a vertex of @p cell lies within @p radius of the nearest
      /// point of @p tree.
      template <class Cell, class Tree>
      bool
      near(const Cell &cell, const Tree &tree, const double radius)
      {
        for (const auto v : cell->vertex_indices())
          {
            std::vector<std::decay_t<decltype(cell->vertex(v))>> nearest;
            tree.query(boost::geometry::index::nearest(cell->vertex(v), 1),
                       std::back_inserter(nearest));
            if (!nearest.empty() && nearest[0].distance(cell->vertex(v)) <= radius)
              return true;
          }
        return false;
      }
    } // namespace

    template <int dim>
    void
    refine_contact_band(
      parallel::distributed::Triangulation<dim> &triangulation,
      const std::vector<std::pair<types::boundary_id, std::function<double(const Point<dim> &)>>>
                                 &surfaces,
      const RefinementParameters &parameters)
    {
      const MPI_Comm comm = triangulation.get_communicator();
      for (unsigned int round = 0; round < parameters.band_refinements; ++round)
        {
          // The vertices of the potential contact zone, from every rank.
          std::vector<Point<dim>> local;
          for (const auto &cell : triangulation.active_cell_iterators())
            if (cell->is_locally_owned())
              for (const auto f : cell->face_indices())
                for (const auto &[contact_id, gap] : surfaces)
                  if (cell->face(f)->at_boundary() && cell->face(f)->boundary_id() == contact_id)
                    for (const auto v : cell->face(f)->vertex_indices())
                      {
                        const Point<dim> &X = cell->face(f)->vertex(v);
                        if (parameters.band_gap < 0. || gap(X) <= parameters.band_gap)
                          local.push_back(X);
                      }
          const std::vector<Point<dim>> zone = all_points(comm, local);
          if (zone.empty())
            return;
          const auto tree = pack_rtree(zone);

          for (const auto &cell : triangulation.active_cell_iterators())
            if (cell->is_locally_owned() &&
                static_cast<unsigned int>(cell->level()) < parameters.max_level &&
                near(cell, tree, parameters.band_width + 1e-10 * cell->diameter()))
              cell->set_refine_flag();
          triangulation.execute_coarsening_and_refinement();
        }
    }

    template <int dim>
    std::vector<CellId::binary_type>
    coarsen_once(parallel::distributed::Triangulation<dim> &triangulation)
    {
      std::vector<CellId::binary_type> local;
      for (const auto &cell : triangulation.active_cell_iterators())
        if (cell->is_locally_owned() && cell->level() > 0)
          {
            const auto parent = cell->parent();
            bool       family = true;
            for (unsigned int c = 0; c < parent->n_children(); ++c)
              family = family && !parent->child(c)->has_children();
            if (family)
              local.push_back(parent->id().template to_binary<dim>());
            cell->set_coarsen_flag();
          }
      std::sort(local.begin(), local.end());
      local.erase(std::unique(local.begin(), local.end()), local.end());
      triangulation.execute_coarsening_and_refinement();
      std::vector<CellId::binary_type> all;
      for (const auto &part : Utilities::MPI::all_gather(triangulation.get_communicator(), local))
        all.insert(all.end(), part.begin(), part.end());
      std::sort(all.begin(), all.end());
      all.erase(std::unique(all.begin(), all.end()), all.end());
      return all;
    }

    template <int dim>
    unsigned int
    mark_cells(parallel::distributed::Triangulation<dim> &triangulation,
               const std::vector<CellId::binary_type>     &cells)
    {
      unsigned int flagged = 0;
      for (const auto &cell : triangulation.active_cell_iterators())
        if (cell->is_locally_owned() &&
            std::binary_search(cells.begin(), cells.end(),
                               cell->id().template to_binary<dim>()))
          {
            cell->set_refine_flag();
            ++flagged;
          }
      return Utilities::MPI::sum(flagged, triangulation.get_communicator());
    }

    template <int dim>
    Vector<float>
    kelly(const Mapping<dim> &mapping, const DoFHandler<dim> &dof_handler, const VectorType &u)
    {
      Vector<float> indicators(dof_handler.get_triangulation().n_active_cells());
      KellyErrorEstimator<dim>::estimate(mapping,
                                         dof_handler,
                                         QGauss<dim - 1>(dof_handler.get_fe().degree + 1),
                                         {},
                                         u,
                                         indicators);
      return indicators;
    }

    template <int dim>
    Vector<float>
    contact(const DoFHandler<dim>             &dof_handler,
            const Contact::BoundaryNodes<dim> &nodes,
            const std::vector<double>         &pressures)
    {
      // Every face the nodes lie on: one contact boundary, or with pairs
      // every pair's contact and target surfaces.
      const auto &contact_ids = nodes.boundary_ids();
      const auto   &tria = dof_handler.get_triangulation();
      Vector<float> indicators(tria.n_active_cells());
      const VectorType p = nodes.nodal_field(pressures);
      const auto      &scalar = nodes.scalar_dofs();
      const auto      &fe     = scalar.get_fe();
      std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
      for (const auto &cell : scalar.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            double eta = 0.;
            for (const auto f : cell->face_indices())
              if (cell->face(f)->at_boundary() &&
                  contact_ids.count(cell->face(f)->boundary_id()) > 0)
                {
                  cell->get_dof_indices(dofs);
                  double lo = std::numeric_limits<double>::max(), hi = -lo;
                  for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
                    if (fe.has_support_on_face(i, f))
                      {
                        lo = std::min(lo, p[dofs[i]]);
                        hi = std::max(hi, p[dofs[i]]);
                      }
                  eta += (hi - lo) * std::sqrt(cell->face(f)->measure());
                }
            indicators[cell->active_cell_index()] = eta;
          }
      return indicators;
    }

    template <int dim>
    std::vector<bool>
    contact_zone(const DoFHandler<dim>             &dof_handler,
                 const Contact::BoundaryNodes<dim> &nodes,
                 const std::vector<double>         &pressures,
                 const double                       depth)
    {
      const auto       &tria = dof_handler.get_triangulation();
      const MPI_Comm    comm = dof_handler.get_communicator();
      std::vector<bool> zone(tria.n_active_cells(), false);
      double            p_max = 0.;
      for (const double p : pressures)
        p_max = std::max(p_max, p);
      p_max = Utilities::MPI::max(p_max, comm);
      if (p_max <= 0.)
        return zone;
      // The nodes with a pressure, of every rank.
      std::vector<Point<dim>> local;
      double                  h = 0.;
      for (unsigned int k = 0; k < pressures.size(); ++k)
        if (pressures[k] > 1e-6 * p_max)
          {
            local.push_back(nodes.nodes()[k].X);
            h = std::max(h, nodes.nodes()[k].h);
          }
      h = Utilities::MPI::max(h, comm);
      const std::vector<Point<dim>> points = all_points(comm, local);
      Point<dim> lo = points[0], hi = points[0];
      for (const auto &p : points)
        for (unsigned int d = 0; d < dim; ++d)
          {
            lo[d] = std::min(lo[d], p[d]);
            hi[d] = std::max(hi[d], p[d]);
          }
      // The zone's extent (at least one element), times the depth factor.
      const double radius = depth * std::max(lo.distance(hi), h);
      const auto   tree   = pack_rtree(points);
      for (const auto &cell : tria.active_cell_iterators())
        if (cell->is_locally_owned() && near(cell, tree, radius))
          zone[cell->active_cell_index()] = true;
      return zone;
    }

    template <int dim>
    unsigned int
    mark(parallel::distributed::Triangulation<dim> &triangulation,
         const Vector<float>                       &indicators,
         const RefinementParameters                &parameters,
         const std::vector<bool>                   &zone)
    {
      if (parameters.strategy == RefinementParameters::Strategy::fraction)
        parallel::distributed::GridRefinement::refine_and_coarsen_fixed_fraction(
          triangulation, indicators, parameters.refine_fraction,
          parameters.coarsen_fraction);
      else
        parallel::distributed::GridRefinement::refine_and_coarsen_fixed_number(
          triangulation, indicators, parameters.refine_fraction,
          parameters.coarsen_fraction);
      for (const auto &cell : triangulation.active_cell_iterators())
        if (cell->is_locally_owned() && cell->refine_flag_set() &&
            indicators[cell->active_cell_index()] <= 0.f)
          cell->clear_refine_flag();
      if (parameters.uniform_zone && !zone.empty())
        {
          // The finest level any zone cell reaches with these flags.
          int target = -1;
          for (const auto &cell : triangulation.active_cell_iterators())
            if (cell->is_locally_owned() && zone[cell->active_cell_index()])
              target = std::max(target, cell->level() + (cell->refine_flag_set() ? 1 : 0));
          target = Utilities::MPI::max(target, triangulation.get_communicator());
          for (const auto &cell : triangulation.active_cell_iterators())
            if (cell->is_locally_owned() && zone[cell->active_cell_index()])
              {
                cell->clear_coarsen_flag();
                if (cell->level() < target)
                  cell->set_refine_flag();
              }
        }
      unsigned int flagged = 0;
      for (const auto &cell : triangulation.active_cell_iterators())
        if (cell->is_locally_owned() && cell->refine_flag_set())
          {
            if (static_cast<unsigned int>(cell->level()) >= parameters.max_level)
              cell->clear_refine_flag();
            else
              ++flagged;
          }
      return Utilities::MPI::sum(flagged, triangulation.get_communicator());
    }

    template <int dim>
    unsigned int
    estimate_and_mark(parallel::distributed::Triangulation<dim> &triangulation,
                      const Mapping<dim>                        &mapping,
                      const DoFHandler<dim>                     &dof_handler,
                      const Contact::Model<dim>                 *term,
                      const VectorType                          &u,
                      const RefinementParameters                &parameters)
    {
      using Estimator      = RefinementParameters::Estimator;
      const auto estimator = parameters.estimator;
      const MPI_Comm comm  = dof_handler.get_communicator();
      // The nodal contact pressure behind the contact indicator and zone.
      std::vector<double> pressures;
      std::vector<bool>   zone;
      if (term)
        {
          pressures = term->samples().nodal_pressures(u, term->forces());
          if (parameters.uniform_zone)
            zone = contact_zone(dof_handler,
                                term->contact_nodes_on_boundary(),
                                pressures,
                                parameters.zone_depth);
        }
      auto contact_indicator = [&]() {
        return contact(dof_handler, term->contact_nodes_on_boundary(), pressures);
      };
      Vector<float> indicators;
      if (estimator == Estimator::kelly || !term)
        indicators = kelly(mapping, dof_handler, u);
      else if (estimator == Estimator::contact)
        indicators = contact_indicator();
      else
        {
          // Each indicator scaled by its largest value on any rank.
          indicators                   = kelly(mapping, dof_handler, u);
          const Vector<float> pressure = contact_indicator();
          const double        max_k    = Utilities::MPI::max(
            static_cast<double>(indicators.linfty_norm()), comm);
          const double max_c = Utilities::MPI::max(
            static_cast<double>(pressure.linfty_norm()), comm);
          if (max_k > 0.)
            indicators *= static_cast<float>(1. / max_k);
          if (max_c > 0.)
            indicators.add(static_cast<float>(1. / max_c), pressure);
        }
      return mark(triangulation, indicators, parameters, zone);
    }

    template void
    refine_contact_band<2>(
      parallel::distributed::Triangulation<2> &,
      const std::vector<std::pair<types::boundary_id, std::function<double(const Point<2> &)>>> &,
      const RefinementParameters &);
    template void
    refine_contact_band<3>(
      parallel::distributed::Triangulation<3> &,
      const std::vector<std::pair<types::boundary_id, std::function<double(const Point<3> &)>>> &,
      const RefinementParameters &);
    template std::vector<CellId::binary_type>
    coarsen_once<2>(parallel::distributed::Triangulation<2> &);
    template std::vector<CellId::binary_type>
    coarsen_once<3>(parallel::distributed::Triangulation<3> &);
    template unsigned int
    mark_cells<2>(parallel::distributed::Triangulation<2> &,
                  const std::vector<CellId::binary_type> &);
    template unsigned int
    mark_cells<3>(parallel::distributed::Triangulation<3> &,
                  const std::vector<CellId::binary_type> &);
    template Vector<float>
    kelly<2>(const Mapping<2> &, const DoFHandler<2> &, const VectorType &);
    template Vector<float>
    kelly<3>(const Mapping<3> &, const DoFHandler<3> &, const VectorType &);
    template Vector<float>
    contact<2>(const DoFHandler<2> &,
               const Contact::BoundaryNodes<2> &,
               const std::vector<double> &);
    template Vector<float>
    contact<3>(const DoFHandler<3> &,
               const Contact::BoundaryNodes<3> &,
               const std::vector<double> &);
    template std::vector<bool>
    contact_zone<2>(const DoFHandler<2> &, const Contact::BoundaryNodes<2> &,
                    const std::vector<double> &, const double);
    template std::vector<bool>
    contact_zone<3>(const DoFHandler<3> &, const Contact::BoundaryNodes<3> &,
                    const std::vector<double> &, const double);
    template unsigned int
    mark<2>(parallel::distributed::Triangulation<2> &, const Vector<float> &,
            const RefinementParameters &, const std::vector<bool> &);
    template unsigned int
    mark<3>(parallel::distributed::Triangulation<3> &, const Vector<float> &,
            const RefinementParameters &, const std::vector<bool> &);
    template unsigned int
    estimate_and_mark<2>(parallel::distributed::Triangulation<2> &,
                         const Mapping<2> &, const DoFHandler<2> &,
                         const Contact::Model<2> *, const VectorType &,
                         const RefinementParameters &);
    template unsigned int
    estimate_and_mark<3>(parallel::distributed::Triangulation<3> &,
                         const Mapping<3> &, const DoFHandler<3> &,
                         const Contact::Model<3> *, const VectorType &,
                         const RefinementParameters &);
  } // namespace Refinement
} // namespace Signorini
