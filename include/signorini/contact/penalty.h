#pragma once

#include <signorini/contact/boundary_nodes.h>
#include <signorini/problem/energy_functional.h>
#include <signorini/problem/objective.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>

#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace Signorini
{
  namespace Contact
  {
    /**
     * A contact model that enters the energy as a penalty term mu P(U)
     * (C^2 in U): the rigid foundation's mu/3 sum_k w_k <-g_k>^3 or the
     * two-body indicator term mu sum_i w_i Phi(x_i). This is all the
     * penalty continuation needs to know of it.
     */
    template <int dim>
    class PenaltyTerm
    {
    public:
      virtual ~PenaltyTerm() = default;

      /**
       * Add mu P(u) and, if given, minus its gradient to @p rhs and its
       * Hessian to @p hessian (condensed with @p constraints, then
       * compressed: collective). Returns mu P summed over all ranks. If
       * @p forces is given it receives the model's nodal contact forces
       * (the record that measure() and the output read).
       */
      virtual double
      add_penalty(const VectorType                &u,
                  const double                     mu,
                  const AffineConstraints<double> &constraints,
                  VectorType                      *rhs,
                  MatrixType                      *hessian,
                  std::vector<double>             *forces = nullptr) const = 0;

      struct Measure
      {
        double       max_penetration_ratio = 0.; // penetration over h
        unsigned int n_active              = 0;
      };

      /// Largest penetration over the local mesh size, and the number of
      /// active contact nodes, of the state @p u with nodal @p forces.
      virtual Measure
      measure(const VectorType &u, const std::vector<double> &forces) const = 0;

      /**
       * Called before an evaluation with a Hessian at the ghosted @p u:
       * true if the couplings the term needs at @p u are not all in the
       * pairs the matrix's sparsity pattern was built for (collective).
       */
      virtual bool
      needs_new_pattern(const VectorType &u)
      {
        (void)u;
        return false;
      }

      /// The boundary id of Gamma_C.
      virtual types::boundary_id
      contact_boundary_id() const = 0;

      /// The nodes of the contact boundary Gamma_C (this rank's).
      virtual const BoundaryNodes<dim> &
      contact_nodes_on_boundary() const = 0;

      /// Whether the state @p u is one the model can represent (collective).
      virtual bool
      admissible(const VectorType &u) const
      {
        (void)u;
        return true;
      }

      /**
       * Make add_penalty() assemble a positive semidefinite approximation
       * of the Hessian (on) or the exact one (off); returns whether the
       * model has such an approximation and uses it. Default: none.
       */
      virtual bool
      set_convexified(const bool on)
      {
        (void)on;
        return false;
      }

      /// See Objective::limit_trial(). Default: nothing moves.
      virtual bool
      limit_trial(const VectorType &u, VectorType &trial) const
      {
        (void)u;
        (void)trial;
        return false;
      }

      /// Largest step length along the direction @p d (locally owned)
      /// from the ghosted @p u that the model allows (collective).
      virtual double
      max_step(const VectorType &u, const VectorType &d) const
      {
        (void)u;
        (void)d;
        return std::numeric_limits<double>::infinity();
      }
    };

    /**
     * The penalised energy G_mu(U) = E(U) + mu P(U) of formulation.md
     * sections 2 and 4, as a Newton objective. If the contact term asks
     * for a new sparsity pattern before a Hessian is assembled,
     * @p rebuild_pattern is called with the state first (it must
     * re-initialise the matrix that evaluate() receives).
     */
    template <int dim>
    class PenaltyObjective : public Objective
    {
    public:
      using PatternBuilder = std::function<void(const VectorType &)>;

      PenaltyObjective(const EnergyFunctional<dim> &energy,
                       PenaltyTerm<dim>            &contact,
                       const double                 time,
                       const double                 mu,
                       const PatternBuilder        &rebuild_pattern = {})
        : energy(energy)
        , contact(contact)
        , time(time)
        , mu(mu)
        , rebuild_pattern(rebuild_pattern)
      {}

      Evaluation
      evaluate(const VectorType                &u,
               const AffineConstraints<double> &constraints,
               VectorType                      *rhs,
               MatrixType                      *hessian) override;

      /// If set, the contact term's share of evaluate() is timed in its
      /// section "contact" (inside the caller's "assembly").
      TimerOutput *timer = nullptr;

      double
      max_step(const VectorType &u, const VectorType &d) override
      {
        return contact.max_step(u, d);
      }

      bool
      limit_trial(const VectorType &u, VectorType &trial) override
      {
        return contact.limit_trial(u, trial);
      }

      bool
      set_convexified(const bool on) override
      {
        return contact.set_convexified(on);
      }

    private:
      const EnergyFunctional<dim> &energy;
      PenaltyTerm<dim>            &contact;
      const double                 time;
      const double                 mu;
      PatternBuilder               rebuild_pattern;
    };

  } // namespace Contact
} // namespace Signorini
