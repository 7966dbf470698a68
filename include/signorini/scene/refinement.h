#pragma once

#include <signorini/scene/refinement_parameters.h>

#include <signorini/contact/boundary_nodes.h>
#include <signorini/contact/model.h>
#include <signorini/types.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/grid/cell_id.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/vector.h>

#include <functional>
#include <string>
#include <vector>

namespace Signorini
{
  using namespace dealii;

  namespace Refinement
  {
    /**
     * Refine, @p parameters.band_refinements times, the cells within
     * band_width of the part of each contact boundary of @p surfaces
     * (boundary id and initial gap, a function of the reference position)
     * whose gap is at most band_gap (all of it if band_gap < 0): the
     * potential contact zones. Independent of the partition (collective).
     */
    template <int dim>
    void
    refine_contact_band(
      parallel::distributed::Triangulation<dim> &triangulation,
      const std::vector<std::pair<types::boundary_id, std::function<double(const Point<dim> &)>>>
                                 &surfaces,
      const RefinementParameters &parameters);

    /**
     * Coarsen every cell once where its siblings allow (all of them
     * active; p4est's balance may keep some), and return, the same on
     * every rank and sorted, the CellIds (binary) of the parents that
     * were candidates: refining the active ones among them
     * (mark_cells()) restores the mesh. Collective.
     */
    template <int dim>
    std::vector<CellId::binary_type>
    coarsen_once(parallel::distributed::Triangulation<dim> &triangulation);

    /// Flag for refinement the locally owned active cells whose id is in
    /// @p cells (sorted); returns the number flagged on all ranks.
    template <int dim>
    unsigned int
    mark_cells(parallel::distributed::Triangulation<dim> &triangulation,
               const std::vector<CellId::binary_type>     &cells);

    /// Kelly's indicator of the displacement @p u (ghosted), per active
    /// cell (values on the locally owned cells).
    template <int dim>
    Vector<float>
    kelly(const Mapping<dim>    &mapping,
          const DoFHandler<dim> &dof_handler,
          const VectorType      &u);

    /**
     * The contact indicator per active cell: for each face of the cell on
     * the boundaries of @p nodes (Gamma_C; with pairs every pair's contact
     * and target surfaces), (max - min of the nodal contact pressure over the face's
     * nodes) times sqrt(|F|), the L2(F) size of the pressure's
     * interpolation error. Large on the contact zone's edges (where p
     * falls to 0) and where p varies quickly; zero away from contact.
     * @p pressures has one value per node of @p nodes (collective).
     */
    template <int dim>
    Vector<float>
    contact(const DoFHandler<dim>             &dof_handler,
            const Contact::BoundaryNodes<dim> &nodes,
            const std::vector<double>         &pressures);

    /**
     * The cells (by active cell index; locally owned ones) with a vertex
     * within @p depth times the extent of the contact zone (the nodes of
     * @p nodes with a positive pressure, reference positions) of one of
     * its nodes: the region whose stresses the contact sets (collective).
     */
    template <int dim>
    std::vector<bool>
    contact_zone(const DoFHandler<dim>             &dof_handler,
                 const Contact::BoundaryNodes<dim> &nodes,
                 const std::vector<double>         &pressures,
                 const double                       depth);

    /**
     * Set refinement and coarsening flags from @p indicators with the
     * strategy of @p parameters, never beyond its maximum level, and never
     * on a cell whose indicator is zero. If @p zone is not empty and
     * 'Uniform contact zone' is on, every cell of the zone below the
     * finest level the marked zone cells will reach is flagged too, and
     * none is coarsened: the zone keeps one mesh size. (Collective.)
     * Returns the number of cells flagged for refinement on all ranks.
     */
    template <int dim>
    unsigned int
    mark(parallel::distributed::Triangulation<dim> &triangulation,
         const Vector<float>                       &indicators,
         const RefinementParameters                &parameters,
         const std::vector<bool>                   &zone = {});

    /**
     * One adaptive step's marking: the indicators of the parameters'
     * estimator at the ghosted state @p u (Kelly, the contact pressure's
     * changes along Gamma_C with @p contact's pressures, or both scaled by
     * their largest values; Kelly alone without contact) and the uniform
     * contact zone, then mark(). Returns the number of cells flagged for
     * refinement.
     */
    template <int dim>
    unsigned int
    estimate_and_mark(parallel::distributed::Triangulation<dim> &triangulation,
                      const Mapping<dim>                        &mapping,
                      const DoFHandler<dim>                     &dof_handler,
                      const Contact::Model<dim>                 *contact,
                      const VectorType                          &u,
                      const RefinementParameters                &parameters);
  } // namespace Refinement
} // namespace Signorini
