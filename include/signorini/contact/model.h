#pragma once

#include <signorini/archive.h>
#include <signorini/contact/boundary_nodes.h>
#include <signorini/contact/node_wise_constraints.h>
#include <signorini/contact/penalty.h>
#include <signorini/mesh_state.h>
#include <signorini/output/json.h>
#include <signorini/types.h>

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <deal.II/numerics/data_out.h>

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
     *
     * - Enforcement, in two roles that the solvers see separately: the
     *   penalty term mu P(U) of PenaltyTerm (every model) with its line
     *   search safeguards, and, for models that have them, the node-wise
     *   inequality constraints g_k(U) >= 0 of NodeWiseConstraints
     *   (node_wise_constraints(): what Ipopt and the interior point
     *   method take).
     * - Geometry: its nodes on Gamma_C, their mesh sizes, the couplings it
     *   adds to the Hessian's sparsity pattern and the distance that the
     *   band refinement of the potential contact zone uses.
     * - State: the nodal contact forces of the last solve, owned here (their
     *   layout is the model's: one number per node for a rigid foundation,
     *   dim for two bodies). The model turns a state and forces into one
     *   NodeSample per node (position, gaps, pressure, force, weight); the
     *   pressures, the active set, the resultants, the area, the profile
     *   CSV and the VTU fields are all computed here from those samples.
     *   The model adds its own entries to summary.json's contact block.
     *
     * A new model is a class derived from this one plus one registration
     * line (contact/registry.h, doc/architecture.md).
     */
    template <int dim>
    class Model : public PenaltyTerm<dim>
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

      /**
       * A distance (>= 0 outside, any sign inside) of a point of the
       * reference configuration from where contact can happen, for the
       * band refinement of Gamma_C before the DoFs exist (collective when
       * called: it may gather from every rank).
       */
      virtual std::function<double(const Point<dim> &)>
      band_distance() const = 0;

      /// The model's node-wise constraints, if its registry entry declares
      /// them (Capabilities::node_wise_constraints), else none.
      virtual const NodeWiseConstraints<dim> *
      node_wise_constraints() const
      {
        return nullptr;
      }

      /// The nodal contact forces of the last converged solve (read only:
      /// they change through set_contact_forces()). The output functions
      /// below take the forces as an argument (these, or a failed
      /// iterate's): one name per output.
      const std::vector<double> &
      forces() const
      {
        return nodal_forces;
      }

      /**
       * Take the nodal contact forces of a converged solve, in the layout
       * of forces(): the interior point method's multipliers, Ipopt's
       * (max(-lambda_k, 0)), the penalty continuation's record, or the
       * record from before a load step that is cut. This is the one way
       * forces enter a model from outside (setup() resets them and
       * load_state() reads them from a checkpoint), and where a term that
       * lags the normal force (friction) will take it.
       */
      void
      set_contact_forces(std::vector<double> forces)
      {
        AssertThrow(forces.size() == nodal_forces.size(),
                    ExcMessage("contact forces of " + std::to_string(forces.size()) +
                               " entries for a model whose record has " +
                               std::to_string(nodal_forces.size())));
        nodal_forces = std::move(forces);
      }

      /// One contact node as the output sees it: the model's whole
      /// contribution to the profile, the VTU fields, the pressures, the
      /// active set, the resultants and the summary block.
      struct NodeSample
      {
        Point<dim>          X, x;   // reference and current position
        std::vector<double> gaps;   // the model's gap measures (profile_gaps())
        double              pressure = 0.;
        Tensor<1, dim>      force;  // the nodal contact force
        double              weight = 0.; // tributary length or area
      };

      /// This rank's contact nodes for the nodal @p forces at the ghosted
      /// state @p u, in the order of contact_nodes_on_boundary().
      virtual std::vector<NodeSample>
      node_samples(const VectorType &u, const std::vector<double> &forces) const = 0;

      /// The names of NodeSample::gaps, comma-separated (profile columns;
      /// the first one is also the VTU field contact_NAME).
      virtual std::string
      profile_gaps() const = 0;

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

      /**
       * Active set, penetration, total force, moment, area and largest
       * pressure of the ghosted state @p u, from its @p samples
       * (node_samples() at @p u; collective). A node is active when its
       * pressure exceeds 1e-6 of the largest on any rank.
       */
      StateSummary
      summarize_state(const VectorType &u, const std::vector<NodeSample> &samples) const;

      /// The number of active nodes (as summarize_state() counts them) for
      /// the nodal @p forces at @p u, on all ranks (collective).
      unsigned int
      n_active(const VectorType &u, const std::vector<double> &forces) const;

      /// (current position, pressure) of the active nodes of @p samples
      /// (node_samples()), on every rank, sorted by position (collective).
      std::vector<std::pair<Point<dim>, double>>
      gather_pressure(const std::vector<NodeSample> &samples) const;

      /// The profile along Gamma_C as CSV (rank 0 writes; collective): one
      /// row per entry of @p samples (node_samples() at @p u for the nodal
      /// @p forces), with a reference pressure where @p reference is
      /// given. A model may write more beside it (two bodies: body 2's
      /// side, from @p u and @p forces).
      virtual void
      write_profile(const std::string                               &file,
                    const VectorType                                &u,
                    const std::vector<double>                       &forces,
                    const std::vector<NodeSample>                   &samples,
                    const std::function<double(const Point<dim> &)> &reference) const;

      /// The nodal fields contact_pressure, contact_GAP (the first of
      /// profile_gaps()) and contact_active for the nodal @p forces; the
      /// vectors live with the contact nodes until the next call.
      void
      add_output_fields(DataOut<dim>              &data_out,
                        const VectorType          &u,
                        const std::vector<double> &forces) const;

      /// The model's part of summary.json's "contact" block.
      virtual void
      write_summary(Json &block) const = 0;

      /**
       * Save what the model carries from one load step to the next into a
       * checkpoint: the nodal forces as a field on their DoFs into
       * @p mesh (force_dofs()), and what a model adds (into @p archive
       * only what is the same on every rank). load_state() reads it back
       * after the DoFs of the restarted run's mesh are set up, on any
       * number of ranks.
       */
      virtual void
      save_state(OutputArchive &archive, MeshState &mesh) const;
      virtual void
      load_state(InputArchive &archive, MeshState &mesh);

      /// The DoF each entry of the nodal forces belongs to (this rank's
      /// nodes): the force's component on that node.
      virtual std::vector<types::global_dof_index>
      force_dofs() const = 0;

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

      std::vector<double> nodal_forces;
    };
  } // namespace Contact
} // namespace Signorini
