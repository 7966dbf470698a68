#pragma once

#include <signorini/contact/boundary_nodes.h>
#include <signorini/contact/contact_state.h>
#include <signorini/contact/node_wise_constraints.h>
#include <signorini/contact/penalty.h>
#include <signorini/contact/samples.h>
#include <signorini/output/json.h>
#include <signorini/output/quantity.h>
#include <signorini/types.h>

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace Signorini
{
  namespace Contact
  {
    /**
     * A contact model: everything the driver, the step solvers and the
     * output need of one, so that none of them names a concrete model.
     * Most of it is in four roles, each an interface of its own, so that
     * a caller that needs one role sees only that one:
     *
     * - the energy term mu P(U) with its line search safeguards
     *   (PenaltyTerm, contact/penalty.h; inherited): what the penalty
     *   continuation takes;
     * - for models that have them, the node-wise inequality constraints
     *   g_k(U) >= 0 (NodeWiseConstraints, node_wise_constraints()): what
     *   Ipopt and the interior point method take;
     * - the samples for output (ContactSamples, contact/samples.h,
     *   samples()): one NodeSample per node (position, gaps, pressure,
     *   force, weight), from which the pressures, the active set, the
     *   resultants, the area, the profile CSV and the VTU fields come;
     * - the state carried from one load step to the next (ContactState,
     *   contact/contact_state.h; inherited): the nodal contact forces of
     *   the last solve, which solvers hand over with set_contact_forces(),
     *   and the checkpoint.
     *
     * Model itself adds the geometry (its nodes' count and mesh sizes,
     * the couplings it adds to the Hessian's sparsity pattern, the
     * distance that the band refinement of the potential contact zone
     * uses), the first penalty factor, the summary of a state and its
     * entries in summary.json's contact block.
     *
     * A new model is a class derived from this one plus one registration
     * line (contact/registry.h, doc/architecture.md).
     */
    template <int dim>
    class Model : public PenaltyTerm<dim>, public ContactState
    {
    public:
      /// The contact state of a solution, for the step record.
      struct StateSummary
      {
        unsigned int   n_nodes               = 0;
        unsigned int   n_active              = 0;
        double         max_penetration_ratio = 0.; // penetration over h
        Tensor<1, dim> total_force;                // on body 1 (or the body)
        double         max_pressure          = 0.;
        /// Contact area (length in 2D): the tributary weights (reference
        /// configuration) of the active nodes.
        double         area = 0.;
        /// Moment of the nodal contact forces about the origin, from the
        /// nodes' current positions (2D: only the z component).
        Tensor<1, 3>   moment;
        bool           has_pairs = false;          // a broad phase exists
        unsigned long long pairs = 0;               // pairs evaluated last
      };

      /// "rigid foundation", "two bodies": the summary's contact type.
      virtual std::string
      type_name() const = 0;

      /// What the contact is with, for the summary and the screen.
      virtual std::string
      description() const = 0;

      /**
       * Collect the model's nodes and points after the DoFs are
       * distributed. @p hanging_constraints: hanging nodes only;
       * @p constraints: hanging nodes and homogeneous Dirichlet data.
       * Resets the force record to zero forces.
       */
      virtual void
      setup(const AffineConstraints<double> &hanging_constraints,
            const AffineConstraints<double> &constraints) = 0;

      /// Throw an InputError if the start state @p u (ghosted) is one the
      /// model cannot act on (collective).
      virtual void
      check_initial_state(const VectorType &u) const
      {
        (void)u;
      }

      /// Rows beyond the locally relevant ones that this rank writes into
      /// (couplings with DoFs other ranks own).
      virtual void
      add_writable_rows(IndexSet &rows) const
      {
        (void)rows;
      }

      /// Add the couplings the model needs at the ghosted state @p u,
      /// condensed with @p constraints (collective).
      virtual void
      add_sparsity(TrilinosWrappers::SparsityPattern &sparsity,
                   const AffineConstraints<double>   &constraints,
                   const VectorType                  &u)
      {
        (void)sparsity;
        (void)constraints;
        (void)u;
      }

      /// Number of contact nodes on all ranks.
      virtual unsigned int
      n_global_nodes() const = 0;

      /// Smallest and mean mesh size on the contact boundary.
      virtual double
      min_mesh_size() const = 0;
      virtual double
      mean_mesh_size() const = 0;

      /**
       * The first penalty factor mu_0 for the scale @p c0_E (the initial
       * penalty factor c_0 times the largest small-strain Young's modulus):
       * its units are the model's (c_0 E / h^2 for node-wise gaps,
       * c_0 E h for the indicator function, in 2D and 3D).
       */
      virtual double
      initial_penalty(const double c0_E) const = 0;

      /// A contact boundary and a distance (>= 0 outside, any sign
      /// inside) of a point of the reference configuration from where
      /// contact can happen on it.
      using BandSurface =
        std::pair<types::boundary_id, std::function<double(const Point<dim> &)>>;

      /**
       * The surfaces the band refinement of Gamma_C starts from, before the
       * DoFs exist: the contact boundary with its distance; with pairs each
       * pair's (collective when called: a distance may gather from every
       * rank).
       */
      virtual std::vector<BandSurface>
      band_surfaces() const = 0;

      /// The model's node-wise constraints, if its registry entry declares
      /// them (Capabilities::node_wise_constraints), else none.
      virtual const NodeWiseConstraints<dim> *
      node_wise_constraints() const
      {
        return nullptr;
      }

      /// The output role: the model's nodes as samples (a model made of
      /// parts hands out the part that owns its nodes).
      virtual const ContactSamples<dim> &
      samples() const = 0;

      using NodeSample = typename ContactSamples<dim>::NodeSample;

      /**
       * Largest penetration over the local mesh size at the ghosted state
       * @p u, of every point the model reports (collective): the nodes,
       * and for a model that penalises other points those too.
       */
      virtual double
      max_penetration_ratio(const VectorType &u) const = 0;

      /// Pairs the broad phase evaluated last, for a model that has one.
      virtual std::optional<unsigned long long>
      evaluated_pairs() const
      {
        return std::nullopt;
      }

      /// Wall time of the geometric search so far in this process (part
      /// of the contact terms' time), for a model that searches [s].
      virtual std::optional<double>
      search_seconds() const
      {
        return std::nullopt;
      }

      /**
       * Active set, penetration, total force, moment, area and largest
       * pressure of the ghosted state @p u, from its @p samples
       * (samples().node_samples() at @p u; collective). A node is active
       * when its pressure exceeds 1e-6 of the largest on any rank.
       */
      StateSummary
      summarize_state(const VectorType &u, const std::vector<NodeSample> &samples) const;

      /// The number of active nodes (as summarize_state() counts them) for
      /// the nodal @p forces at @p u, on all ranks (collective).
      unsigned int
      n_active(const VectorType &u, const std::vector<double> &forces) const;

      /// The model's part of summary.json's "contact" block.
      virtual void
      write_summary(Json &block) const = 0;

      /**
       * For a model made of several contacts (pairs): each contact's own
       * quantities at the ghosted state @p u with the nodal forces
       * forces(), named with the contact (resultants, area, Hertz), and
       * its profile beside @p profile_file (collective). None by default.
       */
      virtual std::vector<Quantity>
      part_quantities(const VectorType &u, const std::string &profile_file) const
      {
        (void)u;
        (void)profile_file;
        return {};
      }

      /// The names of the quantities of part_quantities() that
      /// load_steps.csv gets as columns (known before any step).
      virtual std::vector<std::string>
      part_columns() const
      {
        return {};
      }

    protected:
      /// The block's entries every model has: type, boundary id, what the
      /// contact is with (under @p with_key), nodes and mesh sizes.
      void
      write_common_summary(Json &block, const std::string &with_key) const
      {
        block["type"]        = type_name();
        block["boundary id"] =
          static_cast<unsigned int>(this->contact_boundary_id());
        block[with_key]         = description();
        block["nodes"]          = n_global_nodes();
        block["hanging nodes"]  = this->contact_nodes_on_boundary().n_hanging();
        block["mean mesh size"] = mean_mesh_size();
        block["min mesh size"]  = min_mesh_size();
      }
    };
  } // namespace Contact
} // namespace Signorini
