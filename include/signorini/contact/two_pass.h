#pragma once

#include <signorini/contact/two_body.h>

#include <string>
#include <vector>

namespace Signorini
{
  namespace Contact
  {
    /**
     * Two-body contact evaluated in two passes ('Passes = two-pass'): the
     * first pass keeps body 1's contact boundary Gamma_C out of body 2
     * (body 2's indicator function, as TwoBodyContact does alone), the
     * second keeps body 2's target boundary out of body 1 (body 1's
     * indicator function on Gamma_C, the roles of the two boundaries
     * swapped), each with half of mu:
     *
     *   P(U) = 1/2 sum_i w_i Phi_2(x_i) + 1/2 sum_j w_j Phi_1(y_j)
     *
     * (nodal form; the integral form integrates both). In the one-pass
     * evaluation body 2 receives the contact force as point loads at body
     * 1's nodes rather than the consistent load of its own shape
     * functions; the second pass gives each body a load of its own nodes,
     * which is what the contact patch test asks of a node-to-surface
     * scheme (doc/two_bodies.md).
     *
     * The force record has the first pass's layout (dim numbers per node
     * of Gamma_C, then per node of the target boundary): on each node the
     * sum of what both passes put there, so that the pressures, the
     * profiles and the resultants of both bodies count both passes. The
     * penetration that steers the penalty continuation is the larger of
     * the two passes'.
     */
    template <int dim>
    class TwoPassContact : public Model<dim>
    {
    public:
      TwoPassContact(const TwoBodyParameters &parameters,
                     const types::boundary_id contact_boundary,
                     const DoFHandler<dim>   &dof_handler,
                     const Mapping<dim>      &mapping);

      /// Both passes; checks that the second pass's nodes are the first
      /// pass's in the swapped order (collective).
      void
      setup(const AffineConstraints<double> &hanging_constraints,
            const AffineConstraints<double> &constraints) override;

      std::string
      type_name() const override
      {
        return first.type_name();
      }

      std::string
      description() const override
      {
        return first.description() + ", two passes";
      }

      void
      check_initial_state(const VectorType &u) const override;

      void
      add_writable_rows(IndexSet &rows) const override
      {
        first.add_writable_rows(rows);
        second.add_writable_rows(rows);
      }

      void
      add_sparsity(TrilinosWrappers::SparsityPattern &sparsity,
                   const AffineConstraints<double>   &constraints,
                   const VectorType                  &u) override
      {
        first.add_sparsity(sparsity, constraints, u);
        second.add_sparsity(sparsity, constraints, u);
      }

      unsigned int
      n_global_nodes() const override
      {
        return first.n_global_nodes();
      }

      /// The smaller of the two bodies' smallest contact faces.
      double
      min_mesh_size() const override
      {
        return std::min(first.min_mesh_size(), second.min_mesh_size());
      }

      double
      mean_mesh_size() const override
      {
        return first.mean_mesh_size();
      }

      double
      initial_penalty(const double c0_E) const override
      {
        return std::min(first.initial_penalty(c0_E), second.initial_penalty(c0_E));
      }

      std::vector<typename Model<dim>::BandSurface>
      band_surfaces() const override
      {
        return first.band_surfaces();
      }

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
      needs_new_pattern(const VectorType &u) override
      {
        // Both passes are asked on every rank (collective).
        const bool a = first.needs_new_pattern(u);
        const bool b = second.needs_new_pattern(u);
        return a || b;
      }

      types::boundary_id
      contact_boundary_id() const override
      {
        return first.contact_boundary_id();
      }

      const BoundaryNodes<dim> &
      contact_nodes_on_boundary() const override
      {
        return first.contact_nodes_on_boundary();
      }

      bool
      admissible(const VectorType &u) const override
      {
        const bool a = first.admissible(u);
        const bool b = second.admissible(u);
        return a && b;
      }

      bool
      set_convexified(const bool on) override
      {
        const bool a = first.set_convexified(on);
        const bool b = second.set_convexified(on);
        return a || b;
      }

      double
      max_step(const VectorType &u, const VectorType &d) const override
      {
        return std::min(first.max_step(u, d), second.max_step(u, d));
      }

      /// The first pass's samples: body 1's nodes on Gamma_C (and body 2's
      /// side in the profile), for forces in the first pass's layout, which
      /// is this model's record (it sums both passes).
      const ContactSamples<dim> &
      samples() const override
      {
        return first;
      }

      /// Body 1's nodes in body 2, body 2's nodes in body 1, the larger.
      double
      max_penetration_ratio(const VectorType &u) const override
      {
        const double a = first.max_penetration_ratio(u);
        const double b = second.max_penetration_ratio(u);
        return std::max(a, b);
      }

      std::optional<unsigned long long>
      evaluated_pairs() const override
      {
        return *first.evaluated_pairs() + *second.evaluated_pairs();
      }

      std::optional<double>
      search_seconds() const override
      {
        return *first.search_seconds() + *second.search_seconds();
      }

      /// The first pass's block, "passes": 2 and the second pass's broad
      /// phase.
      void
      write_summary(Json &block) const override;

      /// Both passes' states and the forces, in the first pass's layout.
      void
      save_state(OutputArchive &archive, MeshState &mesh) const override;
      void
      load_state(InputArchive &archive, MeshState &mesh) override;

      std::vector<types::global_dof_index>
      force_dofs() const override
      {
        return first.force_dofs();
      }

      /// The first pass: body 1's Gamma_C against body 2 (what friction
      /// pairs the nodes of Gamma_C with).
      TwoBodyContact<dim> &
      first_pass()
      {
        return first;
      }

    private:
      /// The second pass's forces (body 2's nodes, then body 1's) added
      /// to @p forces in the first pass's layout.
      void
      add_second_pass(const std::vector<double> &second_forces,
                      std::vector<double>       &forces) const;

      /// The first pass's layout of @p forces in the second pass's.
      std::vector<double>
      swapped(const std::vector<double> &forces) const;

      TwoBodyContact<dim> first, second;
    };
  } // namespace Contact
} // namespace Signorini
