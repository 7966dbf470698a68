#pragma once

#include <signorini/archive.h>
#include <signorini/contact/anderson.h>
#include <signorini/contact/boundary_nodes.h>
#include <signorini/contact/friction_law.h>
#include <signorini/contact/friction_parameters.h>
#include <signorini/mesh_state.h>
#include <signorini/problem/objective.h>
#include <signorini/types.h>

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/numerics/data_out.h>

#include <memory>
#include <string>
#include <vector>

namespace Signorini
{
  namespace Contact
  {
    template <int dim>
    class Model;
    template <int dim>
    class RigidFoundation;

    /**
     * Quasi-static Coulomb friction as a term of its own (doc/friction.md):
     * the incremental dissipation potential sum_p D_p(s_p(U)) of the
     * contact points, with the normal force lambda_p and the tangent basis
     * T_p lagged, and the slip s_p measured from the state u_n at the
     * start of the load step. A solver adds it to the energy it minimises
     * (FrictionObjective), and the step's outer loop re-lags it from the
     * contact model's force record until the normal forces settle
     * (StepSolver::solve_step).
     *
     * It is built only when Contact > Friction > Coefficient > 0
     * (create_friction_term), so a frictionless scene pays nothing.
     */
    template <int dim>
    class FrictionTerm
    {
    public:
      explicit FrictionTerm(const FrictionParameters &parameters)
        : parameters(parameters)
      {}
      virtual ~FrictionTerm() = default;

      /**
       * Start the load step to the load time @p time at the converged
       * ghosted state @p u: it becomes the reference u_n of the slip, and
       * the lag is taken from the model's force record (that of the last
       * converged step) at @p u, extrapolated linearly in the load time
       * from the last two converged steps (step_done()) when there are two.
       */
      virtual void
      start_step(const VectorType &u, const double time) = 0;

      /// The load step to @p time converged: its lagged normal forces
      /// become the history start_step() extrapolates from.
      virtual void
      step_done(const double time) = 0;

      /**
       * Add D at the ghosted state @p u: minus its gradient into @p rhs
       * and its Hessian into @p hessian (either may be null), condensed
       * with @p constraints (the caller has zeroed them; this adds and
       * compresses). Returns D summed over the ranks (collective).
       */
      virtual double
      add(const VectorType                &u,
          const AffineConstraints<double> &constraints,
          VectorType                      *rhs,
          MatrixType                      *hessian) const = 0;

      /**
       * Re-lag lambda and T from the model's force record at the ghosted
       * state @p u (after a converged solve). Returns the relative change
       * of the normal forces, max_p |lambda_new - lambda_old| over the
       * largest normal force now or at the last converged step (0 if no
       * point carries a force; collective).
       */
      virtual double
      update(const VectorType &u) = 0;

      /**
       * The friction forces that the lagged normal forces allow,
       * (sum_p (mu lambda_p)^2)^(1/2), summed over the ranks when lambda
       * last changed. FrictionObjective adds it to the energy's force
       * scale: the solvers' tolerances are relative to that scale, and
       * near the end of an unloading the elastic forces vanish while the
       * friction forces of the lag still act.
       */
      virtual double
      force_scale() const = 0;

      /// The friction state of one contact point, for output.
      struct PointSample
      {
        Point<dim>     X;            // reference position
        double         weight = 0.;  // tributary weight (area; length in 2D)
        double         normal_force = 0.; // lambda_p, lagged
        Tensor<1, dim> force;        // friction force on body 1 (or the body)
        Tensor<1, dim> slip;         // slip increment of the step, T s
        FrictionStatus status = FrictionStatus::open;
        double         dissipation = 0.; // mu lambda |s| of the step
      };

      /// One sample per locally owned contact point at the ghosted @p u.
      virtual std::vector<PointSample>
      point_samples(const VectorType &u) const = 0;

      /// The points' summed state.
      struct Totals
      {
        Tensor<1, dim> force;           // friction force on body 1
        double         dissipation = 0.; // of the step
        unsigned int   n_stick = 0;
        unsigned int   n_slip  = 0;
      };

      /// The contact nodes the points live on (for the VTU fields).
      virtual const BoundaryNodes<dim> &
      boundary() const = 0;

      /// The VTU fields: friction_traction_x.. (force over weight),
      /// friction_slip_x.. (the step's slip increment) and friction_status
      /// (0 open, 1 stick, 2 slip) on the contact nodes.
      void
      add_output_fields(DataOut<dim> &data_out, const VectorType &u) const;

      /// The names of a point's output columns (the VTU fields and the
      /// profile's columns), in the order of profile_values().
      static std::vector<std::string>
      column_names();

      /// column_names() as a CSV header, and a point's values.
      static std::string
      profile_header();
      static std::vector<double>
      profile_values(const PointSample &p);

      const FrictionParameters &
      friction_parameters() const
      {
        return parameters;
      }

      /**
       * Save what the next load step needs beyond the model's force
       * record (which the model saves): the history of step_done(), as
       * fields on the contact nodes into @p mesh and its load times into
       * @p archive; load_state() reads it back on the restarted run's mesh
       * (any number of ranks), so that a restart takes the same path.
       */
      virtual void
      save_state(OutputArchive &archive, MeshState &mesh) const = 0;
      virtual void
      load_state(InputArchive &archive, MeshState &mesh) = 0;

      /**
       * Forget the load path: the history of step_done(), the lag and the
       * slip's reference, as in a term just built. A refinement cycle with
       * friction runs the load path again from rest on its new mesh
       * (Simulator::refinement_cycles()), whose contact nodes are not the
       * old mesh's.
       */
      virtual void
      reset() = 0;

    protected:
      const FrictionParameters parameters;
    };

    /**
     * Friction at the nodes of a contact boundary: node k carries the
     * lagged normal force lambda_k, the tangent basis T_k and its own
     * slip length, and its slip is s_k = T_k^T du_k with du_k the step's
     * relative displacement increment, a linear combination of DoF values
     * (coupling()). What is common to every such term lives here: the
     * extrapolation of lambda from the last two converged steps
     * (start_step()), the Anderson-accelerated outer loop (update(),
     * AndersonMixing of depth 5), the open threshold (below 1e-6 of the
     * largest lambda), the assembly of sum_k D_k and the checkpointed
     * history. A derived class says where lambda, T and du come from.
     */
    template <int dim>
    class NodeFriction : public FrictionTerm<dim>
    {
    public:
      void
      start_step(const VectorType &u, const double time) override;

      void
      step_done(const double time) override;

      double
      add(const VectorType                &u,
          const AffineConstraints<double> &constraints,
          VectorType                      *rhs,
          MatrixType                      *hessian) const override;

      double
      update(const VectorType &u) override;

      double
      force_scale() const override
      {
        return scale;
      }

      std::vector<typename FrictionTerm<dim>::PointSample>
      point_samples(const VectorType &u) const override;

      void
      save_state(OutputArchive &archive, MeshState &mesh) const override;
      void
      load_state(InputArchive &archive, MeshState &mesh) override;

      void
      reset() override;

    protected:
      NodeFriction(const FrictionParameters &parameters, const MPI_Comm comm);

      /// How node k's relative increment du_k depends on the DoFs:
      /// du_k[components[j]] = sum_j factors[j] u[dofs[j]] + const.
      struct Coupling
      {
        std::vector<types::global_dof_index> dofs;
        std::vector<unsigned int>            components;
        std::vector<double>                  factors;
      };

      /**
       * The normal force and the tangent basis of every node (this
       * rank's, in boundary() order) at the ghosted state @p u, from the
       * contact model's force record (collective).
       */
      virtual void
      lag(const VectorType               &u,
          std::vector<double>            &normal_forces,
          std::vector<TangentBasis<dim>> &bases) = 0;

      /// Keep what the slip is measured against beyond the nodes' own
      /// displacements (which this class keeps): the partner's state at
      /// the step's start @p u (collective; nothing by default).
      virtual void
      set_partner_reference(const VectorType &u)
      {
        (void)u;
      }

      /**
       * Subtract from each node's displacement increment @p du (since the
       * step's start, at the ghosted @p u) that of its partner, and say in
       * @p has which nodes have one (collective). By default the partner
       * is fixed: every node has one and du stays.
       */
      virtual void
      subtract_partners(const VectorType            &u,
                        std::vector<Tensor<1, dim>> &du,
                        std::vector<bool>           &has) const
      {
        (void)u;
        (void)du;
        has.assign(du.size(), true);
      }

      /// Append node k's partner's DoFs to its coupling @p c, which holds
      /// the node's own (called only for nodes with a partner; nothing by
      /// default).
      virtual void
      add_partner_coupling(const unsigned int k, Coupling &c) const
      {
        (void)k;
        (void)c;
      }

      /// The constraints to condense node terms with (collective; by
      /// default @p constraints).
      virtual const AffineConstraints<double> &
      condensation(const AffineConstraints<double> &constraints) const
      {
        return constraints;
      }

      /// One DoF per node (this rank's) to keep the history on in a
      /// checkpoint.
      virtual std::vector<types::global_dof_index>
      history_dofs() const = 0;

    private:
      /// lambda and T of every node at @p u (lag() and the open threshold).
      void
      lag_all(const VectorType &u);

      /// force_scale() of the present lambda (collective).
      void
      refresh_scale();

      /// The relative increment du_k of every node at the ghosted @p u:
      /// its own since the step's start, minus its partner's (has[k]:
      /// whether it has one; collective).
      std::vector<Tensor<1, dim>>
      increments(const VectorType &u, std::vector<bool> &has) const;

      /// Node k's coupling: its own DoFs, then its partner's.
      void
      coupling(const unsigned int k, Coupling &c) const;

      std::vector<Tensor<1, dim>>      reference; // u_n at the nodes
      std::vector<double>              lambda;
      AndersonMixing                   mixing; // of lambda over the outer loop
      double                           last_change = 0.; // update()'s last
      double                           scale       = 0.; // force_scale()
      // The lagged forces of the last two converged steps and their load
      // times (oldest first), for start_step()'s extrapolation.
      std::vector<std::vector<double>> history;
      std::vector<double>              history_times;
      std::vector<TangentBasis<dim>>   basis;
      std::vector<FrictionLaw<dim>>    laws; // one slip length per node
      bool                             started = false; // start_step() seen
    };

    /**
     * Friction against the rigid foundation, node by node: at node k the
     * slip is s_k = T_k^T (u_k - u_n,k), the normal is grad g_k/|grad g_k|
     * and lambda_k = F_k |grad g_k| with F_k the model's force record
     * (the interior point multiplier or the penalty force), so lambda_k is
     * the node's normal contact force. Its term lives in the node's own
     * dim x dim block: no new sparsity.
     */
    template <int dim>
    class RigidFriction : public NodeFriction<dim>
    {
    public:
      RigidFriction(const FrictionParameters &parameters,
                    const RigidFoundation<dim> &foundation);

      const BoundaryNodes<dim> &
      boundary() const override;

    protected:
      void
      lag(const VectorType               &u,
          std::vector<double>            &normal_forces,
          std::vector<TangentBasis<dim>> &bases) override;

      std::vector<types::global_dof_index>
      history_dofs() const override;

    private:
      const RigidFoundation<dim> &foundation;
    };

    /**
     * The friction term of the scene's contact model, or null when the
     * coefficient is 0. Throws an InputError naming Contact > Friction >
     * Coefficient for a model it cannot act on yet.
     */
    template <int dim>
    std::unique_ptr<FrictionTerm<dim>>
    create_friction_term(const FrictionParameters &parameters, Model<dim> &model);

    /**
     * An objective plus the friction term: what a step solver minimises
     * when the scene has friction. Everything but the evaluation (the line
     * search's safeguards) is the wrapped objective's.
     */
    template <int dim>
    class FrictionObjective : public Objective
    {
    public:
      FrictionObjective(Objective &inner, const FrictionTerm<dim> *friction)
        : inner(inner)
        , friction(friction)
      {}

      Evaluation
      evaluate(const VectorType                &u,
               const AffineConstraints<double> &constraints,
               VectorType                      *rhs,
               MatrixType                      *hessian) override;

      double
      max_step(const VectorType &u, const VectorType &d) override
      {
        return inner.max_step(u, d);
      }

      bool
      limit_trial(const VectorType &u, VectorType &trial) override
      {
        return inner.limit_trial(u, trial);
      }

      bool
      set_convexified(const bool on) override
      {
        return inner.set_convexified(on);
      }

    private:
      Objective               &inner;
      const FrictionTerm<dim> *friction;
    };
  } // namespace Contact
} // namespace Signorini
