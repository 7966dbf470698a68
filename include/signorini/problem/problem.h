#pragma once

#include <signorini/contact/friction_term.h>
#include <signorini/contact/model.h>
#include <signorini/problem/energy_functional.h>
#include <signorini/problem/incompressibility.h>
#include <signorini/parameters/scene_parameters.h>
#include <signorini/scene/scene.h>

#include <memory>
#include <set>

namespace Signorini
{
  /**
   * The minimisation problem of a scene, which is all a step solver sees:
   * the total potential energy (value, gradient, Hessian), an optional
   * contact model (a penalty term and, where it has them, node-wise
   * inequality constraints) and optional equality constraints (J = 1 per
   * cell of the incompressible bodies).
   */
  template <int dim>
  struct Problem
  {
    Problem(const Parameters::Scene &parameters, Scene<dim> &scene);

    /// Rebuild what depends on the DoFs (after Scene::setup_dofs()).
    void
    setup_constraints();

    Scene<dim>                             &scene;
    std::unique_ptr<EnergyFunctional<dim>>  energy;
    std::unique_ptr<Contact::Model<dim>>    contact; // null: no contact
    /// Coulomb friction of the contact (null: frictionless), made by
    /// setup_constraints() once the contact model has its nodes.
    std::unique_ptr<Contact::FrictionTerm<dim>> friction;
    Contact::FrictionParameters                 friction_parameters;
    std::unique_ptr<Incompressibility<dim>> incompressibility;
    std::set<types::material_id>            incompressible_ids;
  };
} // namespace Signorini
