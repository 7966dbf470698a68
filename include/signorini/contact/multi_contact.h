#pragma once

#include <signorini/contact/pairs_parameters.h>

#include <signorini/contact/boundary_nodes.h>
#include <signorini/contact/model.h>
#include <signorini/contact/rigid_foundation.h>
#include <signorini/contact/two_body.h>
#include <signorini/types.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace Signorini
{
  namespace Contact
  {
    /**
     * Several contacts in one scene ('Contact > Type = pairs', issue 51):
     * one TwoBodyContact per two-body pair (a contact boundary on one body
     * kept out of another body's target boundary) and one RigidFoundation,
     * in its penalty form, per foundation boundary. The penalty term is the
     * sum of the parts' terms,
     *
     *   P(U) = sum_k s_k P_k(U),
     *
     * each part with its own penalty factor s_k mu: s_k = mu_0,k / mu_0,1
     * (the units of mu differ: c_0 E h for the indicator function,
     * c_0 E / h^2 for the foundation's gaps), so that each part sees the
     * penalty its own continuation would start from, and one continuation
     * drives them all. Everything the solvers ask of a PenaltyTerm is the
     * parts' answers combined as TwoPassContact combines its two passes:
     * the largest penetration, the smallest step, admissible when every
     * part is, a new pattern when any part needs one.
     *
     * The force record is the parts' records one after the other (each in
     * its own layout). The two-body parts record the whole reaction on
     * their target nodes (set_lumped_reaction), so that each pair's action
     * and reaction sum to zero.
     *
     * Output: its nodes are those of every contact and target boundary; a
     * node's force is the sum of what every part puts on it (so a scene's
     * contact_force is the resultant of all contact forces on all bodies:
     * the pairs' actions and reactions cancel, the foundation's reaction is
     * left), its gap the deepest penetration. Per pair: the resultant on
     * the contact body and on the target body, the contact area, the
     * active nodes, the Hertz quantities and the profile (part_quantities);
     * per body: the resultant of every contact force on it.
     */
    template <int dim>
    class MultiContact : public Model<dim>, public ContactSamples<dim>
    {
    public:
      using NodeSample = typename ContactSamples<dim>::NodeSample;

      MultiContact(const PairsParameters &parameters,
                   const DoFHandler<dim> &dof_handler,
                   const Mapping<dim>    &mapping);

      void
      setup(const AffineConstraints<double> &hanging_constraints,
            const AffineConstraints<double> &constraints) override;

      std::string
      type_name() const override
      {
        return "pairs";
      }

      /// "2 two-body pairs (0:10, 10:20), foundation 20, integral form".
      std::string
      description() const override;

      void
      check_initial_state(const VectorType &u) const override;

      void
      add_writable_rows(IndexSet &rows) const override;

      void
      add_sparsity(TrilinosWrappers::SparsityPattern &sparsity,
                   const AffineConstraints<double>   &constraints,
                   const VectorType                  &u) override;

      /// The contact nodes of every part (a node in several parts counts
      /// in each).
      unsigned int
      n_global_nodes() const override;

      double
      min_mesh_size() const override;

      double
      mean_mesh_size() const override;

      /// The first part's mu_0; the others get theirs through s_k.
      double
      initial_penalty(const double c0_E) const override;

      /// Each part's contact boundary with that part's distance (a
      /// boundary that is one pair's target is no band start of its own).
      std::vector<typename Model<dim>::BandSurface>
      band_surfaces() const override;

      double
      add_penalty(const VectorType                &u,
                  const double                     mu,
                  const AffineConstraints<double> &constraints,
                  VectorType                      *rhs,
                  MatrixType                      *hessian,
                  std::vector<double>             *forces = nullptr) const override;

      typename PenaltyTerm<dim>::Measure
      measure(const VectorType &u, const std::vector<double> &forces) const override;

      bool
      needs_new_pattern(const VectorType &u) override;

      /// The first part's contact boundary (summary.json's "boundary id").
      types::boundary_id
      contact_boundary_id() const override;

      /// Every contact and target boundary of the parts.
      const BoundaryNodes<dim> &
      contact_nodes_on_boundary() const override
      {
        return boundary;
      }

      bool
      admissible(const VectorType &u) const override;

      bool
      set_convexified(const bool on) override;

      bool
      limit_trial(const VectorType &u, VectorType &trial) const override;

      double
      max_step(const VectorType &u, const VectorType &d) const override;

      const ContactSamples<dim> &
      samples() const override
      {
        return *this;
      }

      double
      max_penetration_ratio(const VectorType &u) const override;

      /// Summed over the two-body parts.
      std::optional<unsigned long long>
      evaluated_pairs() const override;

      /// Summed over the two-body parts.
      std::optional<double>
      search_seconds() const override;

      /// The common entries ("contacts": the description), then "pairs":
      /// one block per part (its own summary block with its name,
      /// boundaries and penalty scale).
      void
      write_summary(Json &block) const override;

      void
      save_state(OutputArchive &archive, MeshState &mesh) const override;
      void
      load_state(InputArchive &archive, MeshState &mesh) override;

      /// The parts' force DoFs, one part after the other.
      std::vector<types::global_dof_index>
      force_dofs() const override;

      std::vector<Quantity>
      part_quantities(const VectorType  &u,
                      const std::string &profile_file) const override;

      std::vector<std::string>
      part_columns() const override;

      /// |f| / w of each node of contact_nodes_on_boundary().
      std::vector<double>
      nodal_pressures(const VectorType &u, const std::vector<double> &forces) const override;

      /// One sample per node of every contact and target boundary: the sum
      /// of the parts' forces on it, the deepest penetration.
      std::vector<NodeSample>
      node_samples(const VectorType &u, const std::vector<double> &forces) const override;

      std::string
      profile_gaps() const override
      {
        return "penetration";
      }

      /// ContactSamples' fields and contact_pair: the number of the pair
      /// that puts the largest force on the node (0: none).
      void
      add_output_fields(DataOut<dim>              &data_out,
                        const VectorType          &u,
                        const std::vector<double> &forces) const override;

    private:
      /// One contact: a two-body pair or a foundation boundary.
      struct Part
      {
        std::unique_ptr<Model<dim>> model;
        /// The same object as a two-body contact (null for the foundation).
        TwoBodyContact<dim> *two_body = nullptr;
        types::boundary_id   contact  = 0;
        types::boundary_id   target   = 0; // two-body pairs only
        HertzReference       hertz;
        double               scale  = 1.; // its mu over the first part's
        std::size_t          offset = 0;  // of its record in the record
        std::size_t          size   = 0;
        std::size_t          n_contact_entries = 0; // contact side's share
      };

      /// Part @p p's share of the record @p forces.
      std::vector<double>
      slice(const std::vector<double> &forces, const Part &p) const
      {
        return std::vector<double>(forces.begin() + p.offset,
                                   forces.begin() + p.offset + p.size);
      }

      /// node_samples(), and if @p pair is given the number (from 1) of the
      /// pair with the largest force on each node (0: none).
      std::vector<NodeSample>
      samples_and_pairs(const VectorType          &u,
                        const std::vector<double> &forces,
                        std::vector<double>       *pair) const;

      /// The index in boundary.nodes() of the node with first DoF @p dof.
      unsigned int
      node_index(const types::global_dof_index dof) const;

      /// Resultants of part @p p's forces (this rank's nodes): on its
      /// contact nodes and on its target nodes.
      void
      part_resultants(const Part                &p,
                      const std::vector<double> &forces,
                      Tensor<1, dim>            &on_contact,
                      Tensor<1, dim>            &on_target) const;

      /// Part @p k's quantities (named "pairK_...") and profile.
      void
      add_part_quantities(const unsigned int     k,
                          const VectorType      &u,
                          const std::string     &profile_file,
                          std::vector<Quantity> &quantities) const;

      PairsParameters        prm;
      const DoFHandler<dim> &dof_handler;
      std::vector<Part>      parts;
      BoundaryNodes<dim>     boundary;
      std::map<types::global_dof_index, unsigned int> index_of_dof;
      /// The body (0-based, in the order of prm.body_material_ids; -1:
      /// none) of each node of boundary.
      std::vector<int> node_body;
    };
  } // namespace Contact
} // namespace Signorini
