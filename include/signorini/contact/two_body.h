#pragma once

#include <signorini/contact/two_body_parameters.h>

#include <signorini/contact/boundary_nodes.h>
#include <signorini/contact/indicator.h>
#include <signorini/contact/model.h>
#include <signorini/types.h>

#include <deal.II/base/index_set.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <deal.II/numerics/rtree.h>

#include <cmath>
#include <functional>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace Signorini
{
  namespace Contact
  {
    /**
     * Replace the symmetric matrix @p H by its positive semidefinite part
     * sum_{lambda_k > 0} lambda_k v_k v_k^T (negative eigenvalues set to
     * zero), as projected Newton methods do with non-convex penalty terms.
     * Throws std::runtime_error with the reason if @p H has a non-finite
     * entry or the eigensolver (LAPACK dsyev, its INFO checked) fails or
     * returns a non-finite eigenvalue; add_penalty() then ends the solve
     * on every rank
     * with a SolveFailure that gives it.
     */
    void
    project_to_positive_semidefinite(FullMatrix<double> &H);

    /**
     * Frictionless contact between two deformable bodies through the
     * smooth indicator function Phi of body 2 (formulation.md sections
     * 3-4): body 1's contact boundary Gamma_C ('Contact boundary id') must
     * stay out of body 2, whose potential contact surface is 'Target
     * boundary id'. The penalty term is
     *
     *   nodal:    P(U) = sum_i w_i Phi(x_i),   x_i the support points of
     *             Gamma_C (w_i their tributary lengths/areas),
     *   integral: P(U) = int_Gamma_C Phi(X + u) ds, with K Gauss points per
     *             face in the reference configuration,
     *
     * so that both forms approximate the same integral and mu has the same
     * meaning (units: energy per length^(dim-1)). Phi is the sum over body
     * 2's contact faces of IndicatorFace terms built from the current
     * positions of each face's vertices and of the opposite face's
     * vertices, so a pair term depends on the body 1 point (through u1)
     * and on 2^dim vertices of body 2 (through u2); its gradient and
     * Hessian, coupled blocks included, come from IndicatorFace's
     * automatic differentiation and the chain rule through the shape
     * functions.
     *
     * Broad phase: the boxes of body 2's face terms, at the current
     * positions, go into an R-tree (boost geometry through deal.II's
     * pack_rtree); a point is evaluated only against the faces whose box
     * contains it. Every rank holds the current vertex positions of all
     * of body 2's contact faces (gathered at each evaluation: a few
     * numbers per face) and evaluates the points it owns.
     *
     * Sparsity: the matrix holds the couplings of the pairs found with
     * boxes enlarged by 'Search margin' face sizes. Before a Hessian is
     * assembled, needs_new_pattern() checks that every pair with Phi > 0
     * is among them; if not, the caller rebuilds the pattern
     * (add_sparsity()) at the current state.
     *
     * Penetration is the distance of a Gamma_C point inside body 2 (to the
     * base plane of the simplex that contains it), over the size of that
     * face of body 2. Contact forces on body 1 are minus the gradient of
     * mu P with respect to its DoFs; the pressure of a node is the size of
     * its force over its tributary weight.
     */
    template <int dim>
    class TwoBodyContact : public Model<dim>, public ContactSamples<dim>
    {
    public:
      /// What the broad phase did, for summary.json.
      struct PairStatistics
      {
        unsigned int       target_faces       = 0; // body 2 faces on Gamma
        unsigned int       points             = 0; // body 1 points (all ranks)
        unsigned long long last_pairs         = 0; // evaluated, last call
        unsigned long long max_pairs          = 0; // evaluated, largest
        unsigned long long pattern_pairs      = 0; // in the sparsity pattern
        unsigned int       pattern_builds     = 0;
        /// Wall time of the search on this rank (gathering the current
        /// faces, building their R-trees, querying them) [s].
        double             search_seconds     = 0.;
      };

      TwoBodyContact(const TwoBodyParameters &parameters,
                     const types::boundary_id contact_boundary,
                     const DoFHandler<dim>   &dof_handler,
                     const Mapping<dim>      &mapping);

      /**
       * Collect body 1's nodes and evaluation points and body 2's faces
       * (call after the DoFs are distributed). @p constraints (hanging
       * nodes and Dirichlet data) tells which of body 2's DoFs are
       * constrained and on which DoFs they depend. Throws InputError if
       * either boundary is empty or both lie on one body.
       */
      void
      setup(const AffineConstraints<double> &hanging_constraints,
            const AffineConstraints<double> &constraints) override;

      std::string
      type_name() const override
      {
        return "two bodies";
      }

      /// "body 2, nodal form" or "body 2, integral form".
      std::string
      description() const override
      {
        return std::string("body 2, ") + (prm.integral ? "integral" : "nodal") +
               " form";
      }

      /**
       * The start state (u = 0) must be one the penalty can act on: a
       * point of Gamma_C inside body 2 below the indicator layer would be
       * pulled through, not pushed out (collective).
       */
      void
      check_initial_state(const VectorType &u) const override;

      void
      add_writable_rows(IndexSet &rows) const override
      {
        rows.add_indices(extra_rows);
      }

      /// mu P is an energy (per unit thickness in 2D) and P = sum w_i Phi
      /// has the units of w_i, a length^(dim-1) (Phi <= 1 is a number), so
      /// mu is a stress times a length in 2D and in 3D: mu_0 = c_0 E h, h
      /// the smallest target face.
      double
      initial_penalty(const double c0_E) const override
      {
        return c0_E * min_face_size;
      }

      /// The contact boundary, with band_distance().
      std::vector<typename Model<dim>::BandSurface>
      band_surfaces() const override
      {
        return {{contact_boundary, band_distance()}};
      }

      /// Over the nodes and, for the integral form, the Gauss points.
      double
      max_penetration_ratio(const VectorType &u) const override
      {
        return penetration_ratios(u).all;
      }

      std::optional<unsigned long long>
      evaluated_pairs() const override
      {
        return stats.last_pairs;
      }

      std::optional<double>
      search_seconds() const override
      {
        return stats.search_seconds;
      }

      /// Form, indicator shape and broad-phase statistics.
      void
      write_summary(Json &block) const override;

      /// The forces (on their nodes' DoFs) and the broad phase's
      /// statistics (the same on every rank).
      void
      save_state(OutputArchive &archive, MeshState &mesh) const override;
      void
      load_state(InputArchive &archive, MeshState &mesh) override;

      /// dim forces per node, on the node's DoFs: body 1's contact nodes,
      /// then body 2's target nodes.
      std::vector<types::global_dof_index>
      force_dofs() const override;

      /// Rows beyond the locally relevant ones that this rank's pairs may
      /// write to: the sparsity pattern's extra writable rows.
      const IndexSet &
      coupled_rows() const
      {
        return extra_rows;
      }

      /**
       * Find the pairs at the ghosted state @p u with the enlarged boxes
       * and add their couplings, condensed with @p constraints, to
       * @p sparsity (collective).
       */
      void
      add_sparsity(TrilinosWrappers::SparsityPattern &sparsity,
                   const AffineConstraints<double>   &constraints,
                   const VectorType                  &u) override;

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

      /**
       * Phi is positive only in a layer of depth apex depth x cell depth
       * inside body 2: a point that crosses the layer within one step
       * feels nothing and tunnels through. The step is limited so that no
       * point of Gamma_C and no vertex of body 2's contact faces moves by
       * more than 'Maximum motion' times the thinnest layer.
       */
      double
      max_step(const VectorType &u, const VectorType &d) const override;

      /// With 'Hessian = adaptive': project the pair Hessians while on.
      bool
      set_convexified(const bool on) override
      {
        if (prm.hessian_mode != TwoBodyParameters::HessianMode::adaptive)
          return false;
        convexified = on;
        return true;
      }

      /**
       * False if a point of Gamma_C lies inside one of body 2's contact
       * cells where Phi = 0 (it has passed through the layer where the
       * penalty acts: under a vertex the layer is only about s/(s + 1/2)
       * of the cell deep, and the penalty would let it go), or where it is
       * past the crest of Phi (grad Phi . m < 0, m pointing from the face
       * into its cell: the penalty force pushes it deeper, and a larger mu
       * would pull it through). The line search then backtracks.
       */
      bool
      admissible(const VectorType &u) const override;

      types::boundary_id
      contact_boundary_id() const override
      {
        return contact_boundary;
      }

      const BoundaryNodes<dim> &
      contact_nodes_on_boundary() const override
      {
        return boundary;
      }

      /// |f_k| / w_k: the force record's magnitude per unit area.
      std::vector<double>
      nodal_pressures(const VectorType          &u,
                      const std::vector<double> &forces) const override
      {
        (void)u;
        return node_pressures(forces);
      }

      /// Nodes of Gamma_C; the force record holds dim numbers per node,
      /// then dim per node of body 2's target boundary (the reaction).
      const std::vector<BoundaryNode<dim>> &
      nodes() const
      {
        return boundary.nodes();
      }
      unsigned int
      n_global_nodes() const override
      {
        return boundary.n_global();
      }
      /// Smallest size of a body 2 contact face: the penalty scale.
      double
      min_mesh_size() const override
      {
        return min_face_size;
      }
      double
      mean_mesh_size() const override
      {
        return mean_face_size;
      }
      const TwoBodyParameters &
      parameters() const
      {
        return prm;
      }
      /**
       * Record the reaction of each pair on the opposite face's vertices of
       * the target face (the apex of its indicator term, inside body 2) on
       * the face's own vertices, so that the target nodes' part of the
       * force record holds the whole reaction (its resultant is exact).
       * Only the record (pressures, profiles, resultants) changes, not the
       * penalty's gradient or Hessian. Off by default: the one-pass
       * outputs report the reaction on the target nodes alone.
       */
      void
      set_lumped_reaction(const bool on)
      {
        lumped_reaction = on;
      }

      /// Body 2's nodes on the target boundary (this rank's): the second
      /// part of the force record.
      const BoundaryNodes<dim> &
      target_nodes() const
      {
        return target;
      }
      const PairStatistics &
      pair_statistics() const
      {
        return stats;
      }

      const ContactSamples<dim> &
      samples() const override
      {
        return *this;
      }

      /// The profile's nodes: the one gap is the penetration depth into
      /// body 2 (>= 0).
      std::vector<typename Model<dim>::NodeSample>
      node_samples(const VectorType &u, const std::vector<double> &forces) const override;

      std::string
      profile_gaps() const override
      {
        return "penetration";
      }

      /// ContactSamples' profile, and body 2's side beside it
      /// (NAME_target.csv).
      void
      write_profile(const std::string                                    &file,
                    const VectorType                                     &u,
                    const std::vector<double>                            &forces,
                    const std::vector<typename Model<dim>::NodeSample>   &samples,
                    const std::function<double(const Point<dim> &)> &reference_pressure,
                    const std::string &extra_header = "") const override;

      static constexpr unsigned int n_face_vertices =
        IndicatorFace<dim>::n_face_vertices;
      static constexpr unsigned int n_target_dofs =
        IndicatorFace<dim>::n_variables - dim;

      /**
       * Self-contact (issue 51): the contact boundary is kept out of its
       * own body, the target boundary being the same boundary. A point of
       * Gamma_C is not evaluated against a face term one of whose vertices
       * (the face's or the opposite face's) lies within @p exclusion_radius
       * of the point in the reference configuration: the faces around the
       * point itself, whose layers it lies on or in without any contact.
       * The radius must exceed the largest face so that a point never
       * meets a face term that shares its DoFs; the surfaces that can
       * touch must lie farther apart than it in the reference
       * configuration. The force record then holds the contact nodes
       * alone (each node's force is the sum of what it feels as a contact
       * point and as a target vertex), and there are no target nodes.
       * Call before setup().
       */
      void
      set_self_contact(const double exclusion_radius)
      {
        self             = true;
        exclusion_radius_ = exclusion_radius;
      }

      bool
      self_contact() const
      {
        return self && !all_bodies;
      }

      /**
       * Every body against every other ('Two-body pairs = all'): the
       * boundaries @p ids are at once the contact boundary and the target
       * surface, and a point of one body is evaluated against the faces of
       * every other body (one R-tree over all of them: the search costs
       * what the points and the faces near them cost, not what the pairs
       * of bodies do), never against its own body's. The force record
       * holds the nodes' totals, as with self-contact. Call before setup().
       */
      void
      set_all_bodies(const std::set<types::boundary_id> &ids)
      {
        self        = true;
        all_bodies  = true;
        contact_ids = ids;
        target_ids  = ids;
      }

      bool
      all_bodies_mode() const
      {
        return all_bodies;
      }

      /// The exclusion radius in use (after setup(): an automatic radius
      /// resolved).
      double
      exclusion_radius() const
      {
        return exclusion_radius_;
      }

      /// Current face geometry of every body 2 face (collective).
      std::vector<IndicatorFace<dim>>
      current_faces(const VectorType &u) const;

      /// The point of body 2's contact surface that a node of Gamma_C
      /// lies on or over: what friction measures the node's slip against.
      struct Partner
      {
        int                                 face = -1; // none
        std::array<double, n_face_vertices> shape{};   // vertex weights
        Tensor<1, dim>                      normal;    // body 2's, outward
      };

      /**
       * For every node of Gamma_C (this rank's, nodes() order) at the
       * ghosted state @p u, with @p faces = current_faces(u): the closest
       * point of the faces whose box, grown by one face size, holds the
       * node (2D: on the segment; 3D: on the bilinear face), its vertex
       * weights and body 2's outward unit normal there: the vertex
       * normals (vertex_normals()) interpolated with the weights. A node
       * near no face gets face = -1.
       */
      std::vector<Partner>
      node_partners(const VectorType                      &u,
                    const std::vector<IndicatorFace<dim>> &faces) const;

      /// Body 2's displacement at @p partner when its faces are @p faces
      /// (current_faces() at some state).
      Tensor<1, dim>
      partner_displacement(const std::vector<IndicatorFace<dim>> &faces,
                           const Partner                         &partner) const;

      /// The DoF of component @p c of vertex @p v of body 2's face @p f.
      types::global_dof_index
      face_vertex_dof(const unsigned int f, const unsigned int v, const unsigned int c) const
      {
        return faces2[f].dofs[v * dim + c];
      }

      /**
       * Couplings (node of Gamma_C, body 2 face) that a term beyond the
       * penalty writes into the Hessian (friction): add_sparsity() adds
       * them, and needs_new_pattern() asks for a new pattern when one is
       * missing. Set on this rank's nodes.
       */
      void
      set_node_couplings(std::vector<std::pair<unsigned int, unsigned int>> couplings)
      {
        node_couplings = std::move(couplings);
      }

      /// @p constraints, completed on several ranks with the lines of the
      /// body 2 DoFs that other ranks own (collective).
      const AffineConstraints<double> &
      assembly_constraints(const AffineConstraints<double> &constraints) const;

    private:
      /// Distance to the bounding box of the cells of body 2 (the cells
      /// on the target boundary's side; collective).
      std::function<double(const Point<dim> &)>
      band_distance() const;

      /// Body 2's vertex normals for the faces @p faces, keyed by the
      /// vertex's first DoF: the faces' outward normals (away from the
      /// opposite face) at their centres, weighted by the faces' sizes and
      /// summed at each vertex (not normalised), so that a point's normal
      /// varies continuously along the surface.
      std::map<types::global_dof_index, Tensor<1, dim>>
      vertex_normals(const std::vector<IndicatorFace<dim>> &faces) const;

      /// A point of Gamma_C where Phi is evaluated: x = X + sum_j
      /// shape_j u_j e_{component_j}.
      struct Point1
      {
        std::vector<types::global_dof_index> dofs;
        std::vector<unsigned int>            components;
        std::vector<double>                  shape;
        Point<dim>                           X;
        double                               weight;
        types::material_id                   body = 0; // of its cell
      };

      /// A face of body 2's contact surface: the DoFs of its vertices and
      /// of the opposite face's (vertex by vertex, component by component,
      /// in IndicatorFace's order) and their reference positions.
      struct Face2
      {
        std::array<types::global_dof_index, n_target_dofs> dofs;
        std::array<double, n_target_dofs>                  X;
        double                                             h;
        std::array<double, n_face_vertices> end_stretch; // -1: common
        std::array<bool, n_face_vertices>   free_end{};
        std::array<double, n_face_vertices> ramp{};      // partition shape
        types::material_id                  body = 0;    // of its cell

        template <class Archive>
        void
        serialize(Archive &ar, const unsigned int)
        {
          for (unsigned int k = 0; k < n_target_dofs; ++k)
            ar &dofs[k] & X[k];
          ar &h &body;
        }
      };

      /// Body 1's nodes as evaluation points (node_points), and the
      /// evaluation points of the penalty (points): the nodes, or in the
      /// integral form the Gauss points of the contact faces.
      void
      collect_points();

      /// Body 2's faces on the target boundary into faces2: this rank's,
      /// then every rank's in rank order (collective).
      void
      gather_target_faces();

      /// The free ends of body 2's faces (ends no other face continues)
      /// and the partition shape's ramp at each end.
      void
      mark_face_ends();

      /// Throws InputError if either boundary is empty or both lie on one
      /// body (collective).
      void
      check_boundaries() const;

      /// The smallest and mean size of body 2's faces and the thinnest
      /// layer where Phi > 0.
      void
      measure_faces();

      /// extra_rows: the rows any rank's pairs may write to (collective).
      void
      find_extra_rows(const AffineConstraints<double> &constraints);

      Point<dim>
      position(const Point1 &p, const VectorType &u) const;

      /// Current positions of the owned nodes of Gamma_C.
      std::vector<Point<dim>>
      node_positions(const VectorType &u) const;

      using FaceTree = decltype(pack_rtree(
        std::declval<std::vector<std::pair<BoundingBox<dim>, unsigned int>>>()));

      /// R-tree of the faces' boxes, grown by @p margin face sizes.
      FaceTree
      face_tree(const std::vector<IndicatorFace<dim>> &faces, const double margin) const;

      /// The faces of @p tree whose boxes hold @p x, point @p k of @p list
      /// (points or node_points), into @p hits: the R-tree's query (timed as
      /// search) without the faces the point skips (self-contact, all
      /// bodies).
      void
      candidate_faces(const FaceTree                                         &tree,
                      const Point<dim>                                       &x,
                      const std::vector<Point1>                              &list,
                      const unsigned int                                      k,
                      std::vector<std::pair<BoundingBox<dim>, unsigned int>> &hits) const;

      /// Pairs (point, face) whose face box, grown by @p margin face
      /// sizes, contains the point; with @p positive_only only those
      /// where Phi's face term is > 0.
      std::vector<std::pair<unsigned int, unsigned int>>
      find_pairs(const std::vector<Point1>            &points,
                 const VectorType                     &u,
                 const std::vector<IndicatorFace<dim>> &faces,
                 const double                          margin,
                 const bool                            positive_only) const;

      /// Largest penetration over face size (all ranks) of every point
      /// reported (all) and of the points the penalty acts on (penalised:
      /// the nodes of the nodal form, the Gauss points of the integral
      /// form: mu cannot push out a node between them, e.g. a corner of
      /// body 1).
      struct PenetrationRatios
      {
        double all = 0., penalised = 0.;
      };
      PenetrationRatios
      penetration_ratios(const VectorType &u) const;

      /// Largest penetration over face size of the points @p x, the
      /// current positions of @p list (points or node_points).
      double
      penetration_ratio(const std::vector<Point<dim>>         &x,
                        const std::vector<Point1>             &list,
                        const std::vector<IndicatorFace<dim>> &faces,
                        std::vector<double>                   *depths = nullptr) const;

      /// Self-contact: for every point of points and node_points, the
      /// faces it is not evaluated against (sorted).
      void
      find_excluded_faces();

      /// Whether point @p k of @p list (points or node_points) skips face
      /// @p face (self-contact only).
      bool
      skips(const std::vector<Point1> &list, const unsigned int k, const unsigned int face) const
      {
        if (!self)
          return false;
        if (all_bodies)
          return list[k].body == faces2[face].body;
        const auto &skipped = (&list == &points ? skip_points : skip_nodes)[k];
        return std::binary_search(skipped.begin(), skipped.end(), face);
      }

      std::vector<double>
      node_pressures(const std::vector<double> &forces) const;

      /// Profile of body 2's target nodes (reaction forces, pressure
      /// |f_k| / w_k) as CSV (collective).
      void
      write_target_profile(const std::string         &file,
                           const VectorType          &u,
                           const std::vector<double> &forces) const;

      TwoBodyParameters      prm;
      types::boundary_id     contact_boundary;
      const DoFHandler<dim> &dof_handler;
      const Mapping<dim>    &mapping;
      BoundaryNodes<dim>     boundary;
      /// Body 2's nodes on the target boundary: the reaction of the
      /// penalty term on them (after body 1's in the force record, dim
      /// numbers per node) gives body 2's pressure.
      BoundaryNodes<dim>     target;

      std::vector<Point1> points;     // owned evaluation points
      std::vector<Point1> node_points; // owned nodes as points
      std::vector<Face2>  faces2;     // all of body 2's faces, every rank
      unsigned int        first_owned_face = 0, n_owned_faces = 0;
      double              min_face_size = 0., mean_face_size = 0.;
      double              min_layer = 0.; // thinnest layer where Phi > 0
      IndexSet            relevant, extra_rows;
      /// The hanging-node constraints of the last setup(): the force record
      /// moves what falls on a hanging DoF to the DoFs it follows (the
      /// record's nodes leave hanging nodes out).
      AffineConstraints<double> record_hanging;

      std::set<std::pair<unsigned int, unsigned int>> pattern;
      // set_node_couplings()'s, and those in the sparsity pattern.
      std::vector<std::pair<unsigned int, unsigned int>> node_couplings;
      std::set<std::pair<unsigned int, unsigned int>>    node_pattern;
      mutable PairStatistics                          stats;
      bool                                            convexified = false;
      bool                                            lumped_reaction = false;
      bool                                            self = false;
      bool                                            all_bodies = false;
      /// The contact boundaries and the target boundaries: one each, or
      /// the same set (all bodies).
      std::set<types::boundary_id>                    contact_ids, target_ids;
      double                                          exclusion_radius_ = 0.;
      std::vector<std::vector<unsigned int>>          skip_points, skip_nodes;
      double                                          skipped_per_point = 0.;
      mutable AffineConstraints<double>               merged;
      /// Body 2's side at the last profile written: the reaction on its
      /// target nodes and their largest pressure (for summary.json).
      mutable Tensor<1, dim> target_force;
      mutable double         target_max_pressure = 0.;
    };
  } // namespace Contact
} // namespace Signorini
