#pragma once

// This header holds the parameter struct alone, so that the scene's
// parameters (parameters/scene_parameters.h) include no solver or model.

#include <signorini/contact/foundation.h>
#include <signorini/contact/hertz.h>
#include <signorini/contact/two_body_parameters.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/types.h>

#include <string>
#include <vector>

namespace Signorini
{
  using namespace dealii;

  namespace Contact
  {
    /**
     * The "Contact > Pairs" subsection of 'Type = pairs' (issue 51): several
     * contacts in one scene. Each two-body pair keeps one boundary (its
     * contact boundary, on one body) out of another body (its target
     * boundary), as 'Type = two bodies' does with 'Contact boundary id' and
     * 'Two bodies > Target boundary id'; each foundation boundary keeps one
     * boundary above the rigid foundation of 'Contact > Foundation', in its
     * penalty form. The two-body pairs share the settings of 'Contact > Two
     * bodies' (form, indicator shape, stretch, ...; not its target id).
     * Pair K is the K-th two-body pair of the list, then the self-contact
     * boundaries ('Self-contact boundary ids'), then the foundation
     * boundaries in their order.
     */
    struct PairsParameters
    {
      struct Pair
      {
        types::boundary_id contact = 0;
        types::boundary_id target  = 0;
        /// Self-contact: contact == target ('Self-contact boundary ids').
        bool self = false;
        /// Every body against every other ('Two-body pairs = all', over
        /// 'Contact boundaries'; contact and target: the first of them).
        bool all = false;
      };
      /// 'Two-body pairs'.
      std::vector<Pair> pairs;
      /// 'Contact boundaries' (with 'Two-body pairs = all').
      std::vector<types::boundary_id> contact_boundaries;
      /// 'Two-body pairs = all' (the default) without 'Contact boundaries':
      /// the scene adds the all-bodies pair over the bodies' free surfaces
      /// (Scene::parse_pairs), if two bodies have one.
      bool automatic_all = false;
      /// 'Self-contact exclusion radius' (0: automatic).
      double self_exclusion_radius = 0.;
      /// 'Foundation boundary ids'.
      std::vector<types::boundary_id> foundation_ids;
      /// 'Contact > Two bodies', shared by the pairs (target id unused).
      TwoBodyParameters two_body;
      /// 'Contact > Foundation'.
      FoundationParameters foundation;
      /// 'Pair K > Hertz reference' for each pair (inactive if not given).
      /// Scene::parse_parameters fills a 'Contact modulus' of 0 from the
      /// two bodies of the pair (or the one body against the foundation).
      std::vector<HertzReference> hertz;
      /// The material ids of the scene's bodies, in body order (set by
      /// Scene::parse_parameters): body b + 1 of the per-body resultants.
      std::vector<types::material_id> body_material_ids;

      /// Pairs with a 'Pair K' subsection of their own (Hertz reference).
      static constexpr unsigned int max_described_pairs = 8;

      unsigned int
      n_pairs() const
      {
        return pairs.size() + foundation_ids.size();
      }

      /// Pair @p k (0-based) is against the rigid foundation.
      bool
      is_foundation(const unsigned int k) const
      {
        return k >= pairs.size();
      }

      /// "pair3": the prefix of pair @p k's quantities and columns.
      static std::string
      key(const unsigned int k)
      {
        return "pair" + std::to_string(k + 1);
      }

      /// Declared inside "Contact" (with 'Two bodies' and 'Foundation'
      /// declared by their own models).
      static void
      declare_parameters(ParameterHandler &prm);
      /// prm in "Contact"; throws InputError naming the entry.
      void
      parse_parameters(ParameterHandler &prm, const unsigned int dim);
    };
  } // namespace Contact
} // namespace Signorini
