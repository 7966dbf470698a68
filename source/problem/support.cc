#include <signorini/input_error.h>
#include <signorini/problem/support.h>

#include <deal.II/base/array_view.h>
#include <deal.II/base/mpi.h>

#include <cmath>
#include <limits>
#include <sstream>
#include <vector>

namespace Signorini
{
  namespace
  {
    // Contact farther than this many scene sizes away stops nothing.
    constexpr double reach = 100.;
    // A net force below this fraction of the load's l1 norm is no push
    // (round-off of a load that balances itself along the axis).
    constexpr double no_push = 1e-8;
  } // namespace

  template <int dim>
  void
  check_support(const Scene<dim>            &scene,
                const EnergyFunctional<dim> &energy,
                const Contact::Model<dim>   *contact,
                const double                 end_time)
  {
    const unsigned int n_bodies = scene.material_ids.size();
    // Calls f(k, dof) for every DoF of this rank's cells, with k = b * dim
    // + d for the DoF's body b and component d.
    const auto for_each_dof = [&](const auto &f) {
      std::vector<types::global_dof_index> dofs(scene.fe->n_dofs_per_cell());
      for (const auto &cell : scene.dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            unsigned int b = 0;
            while (b < n_bodies && scene.material_ids[b] != cell->material_id())
              ++b;
            if (b == n_bodies)
              continue;
            cell->get_dof_indices(dofs);
            for (unsigned int i = 0; i < dofs.size(); ++i)
              f(b * dim + scene.fe->system_to_component_index(i).first, dofs[i]);
          }
    };
    // fixed[b * dim + d]: a Dirichlet condition on body b's component d.
    std::vector<int> fixed(n_bodies * dim, 0);
    for_each_dof([&](const unsigned int k, const types::global_dof_index dof) {
      if (scene.homogeneous_constraints.is_constrained(dof) &&
          !scene.hanging_constraints.is_constrained(dof))
        fixed[k] = 1;
    });
    {
      const std::vector<int> mine = fixed;
      Utilities::MPI::max(make_array_view(mine), scene.comm, make_array_view(fixed));
    }
    bool any_free = false;
    for (const int f : fixed)
      any_free = any_free || f == 0;
    if (!any_free)
      return;

    // The nearest contact, where a rigid foundation's constraints say.
    double distance = std::numeric_limits<double>::infinity();
    if (contact != nullptr)
      {
        const auto *constraints = contact->node_wise_constraints();
        if (constraints == nullptr)
          return; // two bodies: taken as reachable
        for (const auto &node : constraints->contact_nodes_on_boundary().nodes())
          {
            const auto s = constraints->constraint(node, scene.solution_ghosted);
            distance     = std::min(distance, s.g / s.grad.norm());
          }
        distance = Utilities::MPI::min(distance, scene.comm);
        if (distance <= reach * scene.size)
          return;
      }

    // The load at the end time: minus the gradient at the reference state
    // (stress-free), with the hanging nodes condensed (their weights sum
    // to one, so that each axis's sum is kept).
    VectorType zero(scene.locally_owned, scene.locally_relevant, scene.comm);
    VectorType load(scene.locally_owned, scene.comm);
    energy.evaluate(zero, end_time, scene.hanging_constraints, &load, nullptr);
    std::vector<double> net(n_bodies * dim, 0.);
    std::vector<bool>   counted(scene.locally_owned.n_elements(), false);
    for_each_dof([&](const unsigned int k, const types::global_dof_index dof) {
      if (!scene.locally_owned.is_element(dof))
        return;
      const auto index = scene.locally_owned.index_within_set(dof);
      if (!counted[index])
        {
          counted[index] = true;
          net[k] += load[dof];
        }
    });
    {
      const std::vector<double> mine = net;
      Utilities::MPI::sum(make_array_view(mine), scene.comm, make_array_view(net));
    }
    const double norm = load.l1_norm();
    static const char axis[] = {'x', 'y', 'z'};
    for (unsigned int b = 0; b < n_bodies; ++b)
      for (unsigned int d = 0; d < dim; ++d)
        if (fixed[b * dim + d] == 0 && std::abs(net[b * dim + d]) > no_push * norm)
          {
            std::ostringstream msg;
            msg << "Body " << b + 1 << " can move without bound along "
                << (net[b * dim + d] < 0. ? "-" : "+") << axis[d]
                << ": no Dirichlet condition fixes its " << axis[d]
                << " displacement, the load at t = " << end_time
                << " pushes it that way with a net force of "
                << net[b * dim + d] << ", and ";
            if (contact == nullptr)
              msg << "the scene declares no contact to stop it";
            else
              msg << "the nearest contact node lies " << distance
                  << " from the foundation, beyond " << reach
                  << " times the scene's size " << scene.size;
            msg << " (the energy has no minimum: fix the body in "
                << axis[d] << " (Boundary conditions > Fixed boundaries), "
                << "or bring the contact within reach)";
            throw SolveFailure(msg.str());
          }
  }

  template void
  check_support<2>(const Scene<2> &, const EnergyFunctional<2> &,
                   const Contact::Model<2> *, const double);
  template void
  check_support<3>(const Scene<3> &, const EnergyFunctional<3> &,
                   const Contact::Model<3> *, const double);
} // namespace Signorini
