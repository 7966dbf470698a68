#include <signorini/archive_io.h>
#include <signorini/contact/multi_contact.h>
#include <signorini/contact/registry.h>
#include <signorini/input_error.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

// Several contacts in one scene (Contact > Type = pairs): the parameters,
// the composite model over its parts and its registry entry.

namespace Signorini
{
  namespace Contact
  {
    void
    PairsParameters::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Pairs");
      prm.declare_entry("Two-body pairs",
                        "all",
                        Patterns::Anything(),
                        "The two-body contacts of Type = pairs, as "
                        "'contact:target' boundary id pairs separated by "
                        "commas, e.g. '0:10, 10:20': the contact boundary "
                        "(on one body) must stay out of the body whose "
                        "surface is the target boundary, through the "
                        "target's smooth indicator function as with Type = "
                        "two bodies, whose subsection 'Two bodies' gives "
                        "every pair its form and settings (not its target "
                        "id). A boundary may be the target of one pair and "
                        "the contact boundary of another. Pair K is the "
                        "K-th entry. 'all' (the default): every body "
                        "against every other through the surfaces "
                        "'Contact boundaries', as one pair (pair 1) with "
                        "one search over all of them (a point meets the "
                        "faces near it, of any other body: the search "
                        "costs what the contact zones cost, not what the "
                        "pairs of bodies do); its output is per body "
                        "(bodyB_contact_force_*). 'none': no two-body "
                        "pairs (only self-contact and foundation ones).");
      prm.declare_entry("Contact boundaries",
                        "",
                        Patterns::Anything(),
                        "With 'Two-body pairs = all': the boundary ids, "
                        "separated by commas, that may touch another "
                        "body (on two bodies at least; a body may have "
                        "several). Not the loaded, symmetry or clamped "
                        "boundaries. Empty: the free surfaces of the "
                        "built-in shapes, every boundary id of a body "
                        "that no 'Fixed boundaries', 'Prescribed "
                        "boundaries' or 'Traction boundaries' entry names, "
                        "if two bodies or more have one (else no two-body "
                        "pair); a Gmsh mesh must name them. The pair then "
                        "comes first (pair 1), before the pairs whose "
                        "'Pair K' subsections number them from 1.");
      prm.declare_entry("Self-contact boundary ids",
                        "",
                        Patterns::Anything(),
                        "Boundary ids, separated by commas, each kept out "
                        "of its own body (self-contact: a ring or a tube "
                        "crushed until its inner surface folds onto "
                        "itself), through the indicator function of that "
                        "same boundary with the settings of 'Two bodies'; "
                        "a point is not checked against the faces within "
                        "'Self-contact exclusion radius' of it. One more "
                        "pair each, numbered after the two-body pairs and "
                        "before the foundation boundaries; empty: none.");
      prm.declare_entry("Self-contact exclusion radius",
                        "0",
                        Patterns::Double(0.),
                        "[length] A point of a self-contact boundary is "
                        "not checked against a face whose indicator term "
                        "has a vertex (of the face or of the cell's "
                        "opposite face) within this distance of it in the "
                        "reference configuration: its own neighbourhood, "
                        "which it lies on without touching. Must exceed "
                        "the largest face of the boundary and stay below "
                        "the reference distance between the parts of the "
                        "surface that come into contact (a ring's inner "
                        "diameter). 0: three times the largest face.");
      prm.declare_entry("Foundation boundary ids",
                        "",
                        Patterns::Anything(),
                        "Boundary ids, separated by commas, that must stay "
                        "above the rigid foundation of the subsection "
                        "'Foundation' (its penalty form mu/3 sum w <-g>^3, "
                        "one more pair each, numbered after the two-body "
                        "pairs); empty: no foundation.");
      for (unsigned int k = 0; k < max_described_pairs; ++k)
        {
          prm.enter_subsection("Pair " + std::to_string(k + 1));
          prm.enter_subsection("Hertz reference");
          HertzReference::declare_parameters(prm);
          prm.leave_subsection();
          prm.leave_subsection();
        }
      prm.leave_subsection();
    }

    namespace
    {
      /// A boundary id of the list entry @p key ('Contact > Pairs > KEY').
      types::boundary_id
      boundary_id(const std::string &text, const std::string &key)
      {
        char      *end = nullptr;
        const long id  = std::strtol(text.c_str(), &end, 10);
        if (text.empty() || *end != '\0' || id < 0 || id > 255)
          throw InputError("Contact > Pairs > " + key,
                           "'" + text + "' is not a boundary id (0 to 255)");
        return static_cast<types::boundary_id>(id);
      }
    } // namespace

    void
    PairsParameters::parse_parameters(ParameterHandler &prm, const unsigned int dim)
    {
      prm.enter_subsection("Two bodies");
      two_body.parse_parameters(prm);
      prm.leave_subsection();
      prm.enter_subsection("Foundation");
      foundation.parse_parameters(prm, dim, "Contact > Foundation");
      prm.leave_subsection();
      if (two_body.passes != 1)
        throw InputError("Contact > Two bodies > Passes",
                         "Type = pairs evaluates each pair in one pass (not "
                         "yet two-pass): set one-pass");

      prm.enter_subsection("Pairs");
      pairs.clear();
      foundation_ids.clear();
      const std::string pairs_key = "Two-body pairs";
      contact_boundaries.clear();
      const std::string boundaries_key = "Contact boundaries";
      for (const auto &entry : Utilities::split_string_list(prm.get(boundaries_key)))
        {
          const auto id = boundary_id(entry, boundaries_key);
          if (std::find(contact_boundaries.begin(), contact_boundaries.end(), id) !=
              contact_boundaries.end())
            throw InputError("Contact > Pairs > " + boundaries_key,
                             "boundary id " + entry + " is given twice");
          contact_boundaries.push_back(id);
        }
      const std::string listed = Utilities::trim(prm.get(pairs_key));
      const bool        all    = listed == "all";
      automatic_all            = all && contact_boundaries.empty();
      if (!all && !contact_boundaries.empty())
        throw InputError("Contact > Pairs > " + boundaries_key,
                         "'Contact boundaries' goes with 'Two-body pairs = "
                         "all' (a list of pairs names its boundaries)");
      if (all && !automatic_all)
        {
          if (contact_boundaries.size() < 2)
            throw InputError("Contact > Pairs > " + boundaries_key,
                             "'Two-body pairs = all' needs at least two boundary "
                             "ids, on two bodies");
          Pair pair;
          pair.contact = pair.target = contact_boundaries.front();
          pair.all                   = true;
          pairs.push_back(pair);
        }
      for (const auto &entry : all || listed == "none" ?
                                 std::vector<std::string>() :
                                 Utilities::split_string_list(listed))
        {
          const auto ids = Utilities::split_string_list(entry, ':');
          if (ids.size() != 2)
            throw InputError("Contact > Pairs > " + pairs_key,
                             "'" + entry + "' is not a pair 'contact:target'");
          Pair pair;
          pair.contact = boundary_id(ids[0], pairs_key);
          pair.target  = boundary_id(ids[1], pairs_key);
          if (pair.contact == pair.target)
            throw InputError("Contact > Pairs > " + pairs_key,
                             "'" + entry +
                               "': the contact and the target boundary must differ "
                               "(a boundary kept out of its own body is a "
                               "'Self-contact boundary ids' entry)");
          for (const auto &other : pairs)
            if (other.contact == pair.contact && other.target == pair.target)
              throw InputError("Contact > Pairs > " + pairs_key,
                               "the pair '" + entry + "' is given twice");
          pairs.push_back(pair);
        }
      const std::string self_key = "Self-contact boundary ids";
      for (const auto &entry : Utilities::split_string_list(prm.get(self_key)))
        {
          Pair pair;
          pair.contact = pair.target = boundary_id(entry, self_key);
          pair.self                  = true;
          for (const auto &other : pairs)
            if (other.self && other.contact == pair.contact)
              throw InputError("Contact > Pairs > " + self_key,
                               "boundary id " + entry + " is given twice");
          pairs.push_back(pair);
        }
      self_exclusion_radius = prm.get_double("Self-contact exclusion radius");
      const std::string foundation_key = "Foundation boundary ids";
      for (const auto &entry : Utilities::split_string_list(prm.get(foundation_key)))
        {
          const auto id = boundary_id(entry, foundation_key);
          if (std::find(foundation_ids.begin(), foundation_ids.end(), id) !=
              foundation_ids.end())
            throw InputError("Contact > Pairs > " + foundation_key,
                             "boundary id " + entry + " is given twice");
          foundation_ids.push_back(id);
        }
      if (n_pairs() == 0 && !automatic_all)
        throw InputError("Contact > Pairs > " + pairs_key,
                         "Type = pairs needs at least one pair: a two-body "
                         "pair ('none' gives none), a self-contact or a "
                         "foundation boundary id");
      hertz.assign(n_pairs(), HertzReference());
      for (unsigned int k = 0; k < max_described_pairs; ++k)
        {
          const std::string section = "Pair " + std::to_string(k + 1);
          prm.enter_subsection(section);
          prm.enter_subsection("Hertz reference");
          HertzReference h;
          h.parse_parameters(prm);
          prm.leave_subsection();
          prm.leave_subsection();
          if (h.active() && k >= n_pairs())
            throw InputError("Contact > Pairs > " + section + " > Hertz reference",
                             "the scene has " + std::to_string(n_pairs()) +
                               " pair(s), not " + std::to_string(k + 1));
          if (k < n_pairs())
            hertz[k] = h;
        }
      prm.leave_subsection();
    }

    template <int dim>
    MultiContact<dim>::MultiContact(const PairsParameters &parameters,
                                    const DoFHandler<dim> &dof_handler,
                                    const Mapping<dim>    &mapping)
      : prm(parameters)
      , dof_handler(dof_handler)
      , boundary(dof_handler, mapping)
    {
      for (unsigned int k = 0; k < prm.n_pairs(); ++k)
        {
          Part part;
          part.hertz = prm.hertz[k];
          if (prm.is_foundation(k))
            {
              part.contact = prm.foundation_ids[k - prm.pairs.size()];
              part.model   = std::make_unique<RigidFoundation<dim>>(
                Foundation<dim>::create(prm.foundation), part.contact, dof_handler,
                mapping);
            }
          else
            {
              part.contact             = prm.pairs[k].contact;
              part.target              = prm.pairs[k].target;
              TwoBodyParameters pair   = prm.two_body;
              pair.target_boundary     = part.target;
              auto model = std::make_unique<TwoBodyContact<dim>>(pair, part.contact,
                                                                 dof_handler, mapping);
              if (prm.pairs[k].self)
                model->set_self_contact(prm.self_exclusion_radius);
              if (prm.pairs[k].all)
                model->set_all_bodies(std::set<types::boundary_id>(
                  prm.contact_boundaries.begin(), prm.contact_boundaries.end()));
              // The target nodes' record holds the whole reaction: the
              // pair's action and reaction sum to zero.
              model->set_lumped_reaction(true);
              part.two_body = model.get();
              part.model    = std::move(model);
            }
          parts.push_back(std::move(part));
        }
    }

    template <int dim>
    void
    MultiContact<dim>::setup(const AffineConstraints<double> &hanging_constraints,
                             const AffineConstraints<double> &constraints)
    {
      std::set<types::boundary_id> ids;
      std::size_t                  offset = 0;
      for (unsigned int k = 0; k < parts.size(); ++k)
        {
          Part &p = parts[k];
          try
            {
              p.model->setup(hanging_constraints, constraints);
            }
          catch (const InputError &e)
            {
              // The part's message names Type = two bodies' entries.
              throw InputError(prm.is_foundation(k) ?
                                 "Contact > Pairs > Foundation boundary ids" :
                                 "Contact > Pairs > Two-body pairs",
                               "pair " + std::to_string(k + 1) + ": " + e.what());
            }
          p.offset = offset;
          p.size   = p.model->forces().size();
          p.n_contact_entries =
            p.model->contact_nodes_on_boundary().nodes().size() * (p.two_body ? dim : 1);
          offset += p.size;
          ids.insert(p.contact);
          if (p.two_body)
            ids.insert(p.target);
          if (p.two_body && p.two_body->all_bodies_mode())
            ids.insert(prm.contact_boundaries.begin(), prm.contact_boundaries.end());
        }
      const double first = parts.front().model->initial_penalty(1.);
      for (Part &p : parts)
        p.scale = p.model->initial_penalty(1.) / first;

      boundary.setup(ids, hanging_constraints);
      index_of_dof.clear();
      for (unsigned int i = 0; i < boundary.nodes().size(); ++i)
        index_of_dof[boundary.nodes()[i].dofs[0]] = i;

      // Each node's body, from the material id of a cell it lies on.
      std::map<types::global_dof_index, types::material_id> material_of_dof;
      std::vector<types::global_dof_index>                   face_dofs;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const auto f : cell->face_indices())
            if (cell->face(f)->at_boundary() && ids.count(cell->face(f)->boundary_id()))
              {
                face_dofs.resize(dof_handler.get_fe().n_dofs_per_face(f));
                cell->face(f)->get_dof_indices(face_dofs);
                for (const auto dof : face_dofs)
                  material_of_dof[dof] = cell->material_id();
              }
      node_body.assign(boundary.nodes().size(), -1);
      for (unsigned int i = 0; i < boundary.nodes().size(); ++i)
        {
          const auto it = material_of_dof.find(boundary.nodes()[i].dofs[0]);
          if (it == material_of_dof.end())
            continue;
          const auto &bodies = prm.body_material_ids;
          const auto  b      = std::find(bodies.begin(), bodies.end(), it->second);
          if (b != bodies.end())
            node_body[i] = b - bodies.begin();
        }
      this->nodal_forces.assign(offset, 0.);
    }

    template <int dim>
    unsigned int
    MultiContact<dim>::node_index(const types::global_dof_index dof) const
    {
      const auto it = index_of_dof.find(dof);
      AssertThrow(it != index_of_dof.end(),
                  ExcMessage("pairs: a part's node is not among the contact nodes"));
      return it->second;
    }

    template <int dim>
    std::string
    MultiContact<dim>::description() const
    {
      std::ostringstream s;
      s << prm.pairs.size() << " two-body pair(s)";
      for (unsigned int k = 0; k < prm.pairs.size(); ++k)
        {
          s << (k == 0 ? " (" : ", ");
          if (prm.pairs[k].all)
            {
              s << "all bodies:";
              for (const auto id : prm.contact_boundaries)
                s << " " << static_cast<unsigned int>(id);
            }
          else
            s << static_cast<unsigned int>(prm.pairs[k].contact) << ":"
              << static_cast<unsigned int>(prm.pairs[k].target)
              << (prm.pairs[k].self ? " self" : "");
          s << (k + 1 == prm.pairs.size() ? ")" : "");
        }
      if (!prm.pairs.empty())
        s << ", " << (prm.two_body.integral ? "integral" : "nodal") << " form";
      for (unsigned int k = 0; k < prm.foundation_ids.size(); ++k)
        s << (k == 0 ? "; foundation " : ", ")
          << static_cast<unsigned int>(prm.foundation_ids[k]);
      return s.str();
    }

    template <int dim>
    void
    MultiContact<dim>::check_initial_state(const VectorType &u) const
    {
      for (const Part &p : parts)
        p.model->check_initial_state(u);
    }

    template <int dim>
    void
    MultiContact<dim>::add_writable_rows(IndexSet &rows) const
    {
      for (const Part &p : parts)
        p.model->add_writable_rows(rows);
    }

    template <int dim>
    void
    MultiContact<dim>::add_sparsity(TrilinosWrappers::SparsityPattern &sparsity,
                                    const AffineConstraints<double>   &constraints,
                                    const VectorType                  &u)
    {
      for (Part &p : parts)
        p.model->add_sparsity(sparsity, constraints, u);
    }

    template <int dim>
    unsigned int
    MultiContact<dim>::n_global_nodes() const
    {
      unsigned int n = 0;
      for (const Part &p : parts)
        n += p.model->n_global_nodes();
      return n;
    }

    template <int dim>
    double
    MultiContact<dim>::min_mesh_size() const
    {
      double h = std::numeric_limits<double>::max();
      for (const Part &p : parts)
        h = std::min(h, p.model->min_mesh_size());
      return h;
    }

    template <int dim>
    double
    MultiContact<dim>::mean_mesh_size() const
    {
      double sum = 0.;
      for (const Part &p : parts)
        sum += p.model->mean_mesh_size();
      return sum / parts.size();
    }

    template <int dim>
    double
    MultiContact<dim>::initial_penalty(const double c0_E) const
    {
      return parts.front().model->initial_penalty(c0_E);
    }

    template <int dim>
    std::vector<typename Model<dim>::BandSurface>
    MultiContact<dim>::band_surfaces() const
    {
      std::vector<typename Model<dim>::BandSurface> surfaces;
      for (const Part &p : parts)
        for (const auto &surface : p.model->band_surfaces())
          surfaces.push_back(surface);
      return surfaces;
    }

    template <int dim>
    double
    MultiContact<dim>::add_penalty(const VectorType                &u,
                                   const double                     mu,
                                   const AffineConstraints<double> &constraints,
                                   VectorType                      *rhs,
                                   MatrixType                      *hessian,
                                   std::vector<double>             *forces) const
    {
      if (forces)
        forces->assign(this->nodal_forces.size(), 0.);
      double              value = 0.;
      std::vector<double> part_forces;
      for (const Part &p : parts)
        {
          value += p.model->add_penalty(u, p.scale * mu, constraints, rhs, hessian,
                                        forces ? &part_forces : nullptr);
          if (forces)
            {
              AssertThrow(part_forces.size() == p.size, ExcInternalError());
              std::copy(part_forces.begin(), part_forces.end(),
                        forces->begin() + p.offset);
            }
        }
      return value;
    }

    template <int dim>
    typename PenaltyTerm<dim>::Measure
    MultiContact<dim>::measure(const VectorType &u, const std::vector<double> &forces) const
    {
      double worst = 0.;
      for (const Part &p : parts)
        worst = std::max(worst, p.model->measure(u, slice(forces, p)).max_penetration_ratio);
      return {worst, this->n_active(u, forces)};
    }

    template <int dim>
    bool
    MultiContact<dim>::needs_new_pattern(const VectorType &u)
    {
      // Every part is asked on every rank (collective).
      bool any = false;
      for (Part &p : parts)
        any = p.model->needs_new_pattern(u) || any;
      return any;
    }

    template <int dim>
    types::boundary_id
    MultiContact<dim>::contact_boundary_id() const
    {
      return parts.front().contact;
    }

    template <int dim>
    bool
    MultiContact<dim>::admissible(const VectorType &u) const
    {
      bool all = true;
      for (const Part &p : parts)
        all = p.model->admissible(u) && all;
      return all;
    }

    template <int dim>
    bool
    MultiContact<dim>::set_convexified(const bool on)
    {
      bool any = false;
      for (Part &p : parts)
        any = p.model->set_convexified(on) || any;
      return any;
    }

    template <int dim>
    bool
    MultiContact<dim>::limit_trial(const VectorType &u, VectorType &trial) const
    {
      bool any = false;
      for (const Part &p : parts)
        any = p.model->limit_trial(u, trial) || any;
      return any;
    }

    template <int dim>
    double
    MultiContact<dim>::max_step(const VectorType &u, const VectorType &d) const
    {
      double step = std::numeric_limits<double>::infinity();
      for (const Part &p : parts)
        step = std::min(step, p.model->max_step(u, d));
      return step;
    }

    template <int dim>
    double
    MultiContact<dim>::max_penetration_ratio(const VectorType &u) const
    {
      double worst = 0.;
      for (const Part &p : parts)
        worst = std::max(worst, p.model->max_penetration_ratio(u));
      return worst;
    }

    template <int dim>
    std::optional<unsigned long long>
    MultiContact<dim>::evaluated_pairs() const
    {
      std::optional<unsigned long long> total;
      for (const Part &p : parts)
        if (const auto pairs = p.model->evaluated_pairs())
          total = total.value_or(0) + *pairs;
      return total;
    }

    template <int dim>
    std::optional<double>
    MultiContact<dim>::search_seconds() const
    {
      std::optional<double> total;
      for (const Part &p : parts)
        if (const auto seconds = p.model->search_seconds())
          total = total.value_or(0.) + *seconds;
      return total;
    }

    template <int dim>
    std::vector<types::global_dof_index>
    MultiContact<dim>::force_dofs() const
    {
      std::vector<types::global_dof_index> dofs;
      for (const Part &p : parts)
        {
          const auto part = p.model->force_dofs();
          dofs.insert(dofs.end(), part.begin(), part.end());
        }
      return dofs;
    }

    template <int dim>
    void
    MultiContact<dim>::save_state(OutputArchive &archive, MeshState &mesh) const
    {
      // Each part keeps its share of the record as a field of its own: a
      // node can be in two parts (a target in one pair, in contact in the
      // next), and a field holds a DoF once.
      for (const Part &p : parts)
        {
          p.model->set_contact_forces(slice(this->nodal_forces, p));
          p.model->save_state(archive, mesh);
        }
    }

    template <int dim>
    void
    MultiContact<dim>::load_state(InputArchive &archive, MeshState &mesh)
    {
      for (Part &p : parts)
        {
          p.model->load_state(archive, mesh);
          std::copy(p.model->forces().begin(), p.model->forces().end(),
                    this->nodal_forces.begin() + p.offset);
        }
    }

    template <int dim>
    std::vector<typename MultiContact<dim>::NodeSample>
    MultiContact<dim>::node_samples(const VectorType          &u,
                                    const std::vector<double> &forces) const
    {
      return samples_and_pairs(u, forces, nullptr);
    }

    template <int dim>
    void
    MultiContact<dim>::add_output_fields(DataOut<dim>              &data_out,
                                         const VectorType          &u,
                                         const std::vector<double> &forces) const
    {
      ContactSamples<dim>::add_output_fields(data_out, u, forces);
      std::vector<double> pair;
      samples_and_pairs(u, forces, &pair);
      boundary.add_fields(data_out, {"contact_pair"}, {pair});
    }

    template <int dim>
    std::vector<typename MultiContact<dim>::NodeSample>
    MultiContact<dim>::samples_and_pairs(const VectorType          &u,
                                         const std::vector<double> &forces,
                                         std::vector<double>       *pair) const
    {
      std::vector<NodeSample> samples(boundary.nodes().size());
      std::vector<double>     largest(samples.size(), 0.);
      if (pair)
        pair->assign(samples.size(), 0.);
      // Part @p k puts the force @p f on node @p i.
      const auto count = [&](const unsigned int i, const unsigned int k,
                             const Tensor<1, dim> &f) {
        samples[i].force += f;
        if (pair && f.norm() > largest[i])
          {
            largest[i]  = f.norm();
            (*pair)[i] = k + 1;
          }
      };
      for (unsigned int i = 0; i < samples.size(); ++i)
        {
          const auto &n = boundary.nodes()[i];
          samples[i].X  = n.X;
          samples[i].x  = n.X;
          for (unsigned int d = 0; d < dim; ++d)
            samples[i].x[d] += u[n.dofs[d]];
          samples[i].gaps   = {0.};
          samples[i].weight = n.weight;
        }
      for (unsigned int part = 0; part < parts.size(); ++part)
        {
          const Part &p           = parts[part];
          const auto  part_forces = slice(forces, p);
          const auto  contact     = p.model->samples().node_samples(u, part_forces);
          const auto &nodes       = p.model->contact_nodes_on_boundary().nodes();
          for (unsigned int k = 0; k < contact.size(); ++k)
            {
              const unsigned int i = node_index(nodes[k].dofs[0]);
              NodeSample        &s = samples[i];
              count(i, part, contact[k].force);
              // The foundation's first gap is signed (< 0 inside), the
              // pair's a penetration depth (>= 0).
              const double depth =
                p.two_body ? contact[k].gaps[0] : std::max(0., -contact[k].gaps[0]);
              s.gaps[0] = std::max(s.gaps[0], depth);
            }
          if (p.two_body)
            {
              const auto &target = p.two_body->target_nodes().nodes();
              for (unsigned int j = 0; j < target.size(); ++j)
                {
                  Tensor<1, dim> f;
                  for (unsigned int d = 0; d < dim; ++d)
                    f[d] = part_forces[p.n_contact_entries + j * dim + d];
                  count(node_index(target[j].dofs[0]), part, f);
                }
            }
        }
      for (NodeSample &s : samples)
        s.pressure = s.weight > 0. ? s.force.norm() / s.weight : 0.;
      return samples;
    }

    template <int dim>
    std::vector<double>
    MultiContact<dim>::nodal_pressures(const VectorType          &u,
                                       const std::vector<double> &forces) const
    {
      return pressures_of(node_samples(u, forces));
    }

    template <int dim>
    void
    MultiContact<dim>::part_resultants(const Part                &p,
                                       const std::vector<double> &forces,
                                       Tensor<1, dim>            &on_contact,
                                       Tensor<1, dim>            &on_target) const
    {
      on_contact = Tensor<1, dim>();
      on_target  = Tensor<1, dim>();
      if (p.two_body)
        {
          for (std::size_t i = 0; i < p.n_contact_entries; ++i)
            on_contact[i % dim] += forces[p.offset + i];
          for (std::size_t i = p.n_contact_entries; i < p.size; ++i)
            on_target[(i - p.n_contact_entries) % dim] += forces[p.offset + i];
        }
      const MPI_Comm comm = dof_handler.get_communicator();
      for (unsigned int d = 0; d < dim; ++d)
        {
          on_contact[d] = Utilities::MPI::sum(on_contact[d], comm);
          on_target[d]  = Utilities::MPI::sum(on_target[d], comm);
        }
    }

    template <int dim>
    std::vector<std::string>
    MultiContact<dim>::part_columns() const
    {
      std::vector<std::string> columns;
      for (unsigned int k = 0; k < parts.size(); ++k)
        {
          const std::string key = PairsParameters::key(k);
          for (unsigned int d = 0; d < dim; ++d)
            columns.push_back(key + "_contact_force_" + "xyz"[d]);
          if (parts[k].two_body)
            for (unsigned int d = 0; d < dim; ++d)
              columns.push_back(key + "_target_force_" + "xyz"[d]);
          if (parts[k].two_body && parts[k].two_body->self_contact())
            columns.push_back(key + "_self_contact_force");
          columns.push_back(key + "_contact_area");
        }
      for (unsigned int b = 0; b < prm.body_material_ids.size(); ++b)
        for (unsigned int d = 0; d < dim; ++d)
          columns.push_back("body" + std::to_string(b + 1) + "_contact_force_" + "xyz"[d]);
      return columns;
    }

    template <int dim>
    void
    MultiContact<dim>::add_part_quantities(const unsigned int     k,
                                           const VectorType      &u,
                                           const std::string     &profile_file,
                                           std::vector<Quantity> &quantities) const
    {
      const Part        &p       = parts[k];
      const std::string  key     = PairsParameters::key(k);
      const auto         forces  = slice(this->forces(), p);
      const auto        &hertz   = p.hertz;
      const auto         samples = p.model->samples().node_samples(u, forces);
      const auto         state   = p.model->summarize_state(u, samples);
      Tensor<1, dim>     on_contact, on_target;
      part_resultants(p, this->forces(), on_contact, on_target);
      const auto add = [&quantities](const std::string &name, const double value) {
        Quantity q;
        q.name  = name;
        q.value = value;
        quantities.push_back(q);
        return &quantities.back();
      };
      // The foundation's record holds normal forces: its resultant comes
      // from the samples, the pair's from its record.
      const Tensor<1, dim> force = p.two_body ? on_contact : state.total_force;
      for (unsigned int d = 0; d < dim; ++d)
        {
          Quantity *q  = add(key + "_contact_force_" + "xyz"[d], force[d]);
          q->estimable = true;
          q->scale     = force.norm();
          if (d == dim - 1 && hertz.active())
            {
              q->has_reference = true;
              q->reference     = hertz.modelled_fraction * hertz.load();
              q->tolerance     = hertz.tolerance_force;
            }
        }
      if (p.two_body)
        for (unsigned int d = 0; d < dim; ++d)
          {
            Quantity *q  = add(key + "_target_force_" + "xyz"[d], on_target[d]);
            q->estimable = true;
            q->scale     = on_target.norm();
          }
      if (p.two_body && p.two_body->self_contact())
        {
          // The force across the self-contact: every node's force is the
          // sum of what it feels as a point and as a target vertex, so the
          // forces sum to zero and each action-reaction is counted twice.
          double total = 0.;
          for (const auto &sample : samples)
            total += sample.force.norm();
          Quantity *q = add(key + "_self_contact_force",
                            0.5 * Utilities::MPI::sum(total, dof_handler.get_communicator()));
          q->estimable = true;
        }
      // An index, not a pointer: the quantities that follow may move it.
      const std::size_t area = quantities.size();
      add(key + "_contact_area", state.area)->estimable = true;
      add(key + "_active_contact_nodes", state.n_active);
      add(key + "_max_penetration_over_h", state.max_penetration_ratio);
      std::function<double(const Point<dim> &)> reference;
      if (hertz.active())
        {
          const double a                 = hertz.half_width();
          quantities[area].has_reference = true;
          quantities[area].reference =
            hertz.modelled_fraction * (hertz.point_contact() ? numbers::PI * a * a : 2. * a);
          quantities[area].tolerance = hertz.tolerance_area;
          std::vector<std::pair<double, double>> pressure;
          for (const auto &s : p.model->samples().gather_pressure(samples))
            pressure.emplace_back(hertz.distance(s.first), s.second);
          for (Quantity q : hertz.quantities(pressure))
            {
              q.name = key + "_" + q.name;
              quantities.push_back(q);
            }
          reference = [&hertz](const Point<dim> &x) {
            return hertz.pressure(hertz.distance(x));
          };
        }
      const auto dot  = profile_file.rfind(".csv");
      const auto stem = dot == std::string::npos ? profile_file : profile_file.substr(0, dot);
      p.model->samples().write_profile(stem + "_" + key + ".csv", u, forces, samples,
                                       reference);
    }

    template <int dim>
    std::vector<Quantity>
    MultiContact<dim>::part_quantities(const VectorType  &u,
                                       const std::string &profile_file) const
    {
      std::vector<Quantity> quantities;
      for (unsigned int k = 0; k < parts.size(); ++k)
        add_part_quantities(k, u, profile_file, quantities);
      // Per body: every contact force on its nodes.
      const unsigned int          n_bodies = prm.body_material_ids.size();
      std::vector<Tensor<1, dim>> on_body(n_bodies);
      const auto                  samples = node_samples(u, this->forces());
      for (unsigned int i = 0; i < samples.size(); ++i)
        if (node_body[i] >= 0)
          on_body[node_body[i]] += samples[i].force;
      const MPI_Comm comm = dof_handler.get_communicator();
      for (unsigned int b = 0; b < n_bodies; ++b)
        {
          for (unsigned int d = 0; d < dim; ++d)
            on_body[b][d] = Utilities::MPI::sum(on_body[b][d], comm);
          for (unsigned int d = 0; d < dim; ++d)
            {
              Quantity q;
              q.name      = "body" + std::to_string(b + 1) + "_contact_force_" + "xyz"[d];
              q.value     = on_body[b][d];
              q.estimable = true;
              q.scale     = on_body[b].norm();
              quantities.push_back(q);
            }
        }
      return quantities;
    }

    template <int dim>
    void
    MultiContact<dim>::write_summary(Json &block) const
    {
      this->write_common_summary(block, "contacts");
      Json list = Json::array();
      for (unsigned int k = 0; k < parts.size(); ++k)
        {
          const Part &p = parts[k];
          Json        part;
          part["name"] = PairsParameters::key(k);
          p.model->write_summary(part);
          if (p.two_body) // its own description says "body 2"
            part["target"] =
              std::string(p.two_body->all_bodies_mode() ? "every other body, from boundary " :
                          p.two_body->self_contact() ? "its own body (self-contact) through boundary " :
                                                       "the body of boundary ") +
              std::to_string(static_cast<unsigned int>(p.target)) + ", " +
              (prm.two_body.integral ? "integral" : "nodal") + " form";
          part["penalty scale"] = p.scale;
          list.push_back(part);
        }
      block["pairs"] = list;
    }

    template class MultiContact<2>;
    template class MultiContact<3>;

    /// The registry's entry (contact/registry.cc).
    ModelEntry
    pairs_model()
    {
      ModelEntry entry;
      entry.name = "pairs";
      entry.help = "pairs: several contacts in one scene, any number of bodies: the "
                   "two-body pairs and foundation boundaries of the Pairs subsection "
                   "(each pair as with Type = two bodies, the foundation in its "
                   "penalty form; Method = newton-penalty). 'Contact boundary id' "
                   "is not used.";
      entry.capabilities.node_wise_constraints = false;
      entry.capabilities.bodies                = 1;
      entry.capabilities.contact_boundary_id   = false;
      entry.declare_parameters = [](ParameterHandler &prm) {
        PairsParameters::declare_parameters(prm);
      };
      entry.parse_parameters = [](ParameterHandler &prm, const unsigned int dim) {
        PairsParameters parameters;
        parameters.parse_parameters(prm, dim);
        return std::make_shared<const ParsedParameters<PairsParameters>>(
          std::move(parameters));
      };
      entry.boundary_ids = [](const ModelParameters &parameters) {
        const auto                  &p = parsed<PairsParameters>(parameters);
        std::vector<NamedBoundaryId> ids;
        for (const auto id : p.contact_boundaries)
          ids.push_back({"Pairs > Contact boundaries", id});
        for (const auto &pair : p.pairs)
          if (pair.all)
            continue;
          else if (pair.self)
            ids.push_back({"Pairs > Self-contact boundary ids", pair.contact});
          else
            {
              ids.push_back({"Pairs > Two-body pairs", pair.contact});
              ids.push_back({"Pairs > Two-body pairs", pair.target});
            }
        for (const auto id : p.foundation_ids)
          ids.push_back({"Pairs > Foundation boundary ids", id});
        return ids;
      };
      entry.set_create([](const ModelParameters &parameters,
                          const types::boundary_id,
                          const auto &dof_handler,
                          const auto &mapping) {
        constexpr int dim = std::decay_t<decltype(dof_handler)>::dimension;
        return std::unique_ptr<Model<dim>>(std::make_unique<MultiContact<dim>>(
          parsed<PairsParameters>(parameters), dof_handler, mapping));
      });
      return entry;
    }
  } // namespace Contact
} // namespace Signorini
