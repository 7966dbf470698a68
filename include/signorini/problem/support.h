#pragma once

#include <signorini/contact/model.h>
#include <signorini/problem/energy_functional.h>
#include <signorini/scene/scene.h>

namespace Signorini
{
  /**
   * Before the first load step: throws SolveFailure (the run ends with
   * status "failed" and exit 3, at once, with the reason) when a body can
   * move without bound. That is a body whose translation along an axis no
   * Dirichlet condition fixes, which the load at @p end_time pushes along
   * that axis, and which no contact can stop: the scene declares none, or
   * every constrained contact node (a rigid foundation) lies farther than
   * 100 times the scene's size from the foundation. The energy then falls
   * linearly without a minimum; the solvers would regularise an indefinite
   * matrix at every iteration and crawl (a foundation at Height = -1e308
   * kept the sphere in its first load step for minutes).
   *
   * Cheap where it matters: the load is assembled only when a body has a
   * free axis and no reachable contact. Rotations and two-body contact
   * (always taken as reachable) are not checked. Collective.
   */
  template <int dim>
  void
  check_support(const Scene<dim>              &scene,
                const EnergyFunctional<dim>   &energy,
                const Contact::Model<dim>     *contact,
                const double                   end_time);
} // namespace Signorini
