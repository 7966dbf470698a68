#pragma once

#include <signorini/scene/scene.h>

#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>

namespace Signorini
{
  /**
   * The start of a load step in steady sliding (Load stepping > Sliding
   * direction, doc/two_bodies.md): one body, the slider, is moved by the
   * prescribed displacements and slides along a unit direction e over the
   * other bodies. Once the sliding is steady, the deformation travels with
   * the slider: one step later, the displacement of every other body at a
   * material point X is the one that was at X - d, with d = (Delta u_D . e) e
   * the step's prescribed motion along e, and the slider's own field is
   * shifted by d. apply() replaces the previous step's state by that one.
   * The step solver then starts from there (the tangent predictor adds the
   * rest of the prescribed increment, its part across e).
   *
   * Without it a step starts with the slider pushed by d into the bulge
   * that the previous step left in front of it. On prm/ironing.prm (d two
   * faces wide) the penalty Newton iteration then spent 20 to 49
   * iterations per sliding step on that start, with convexified contact
   * Hessians and short line-search steps, and round-off decided some of
   * its choices: the iteration count differed between 1 and 2 ranks.
   *
   * - d is the mean, over the locally owned DoFs of the prescribed
   *   boundaries, of (prescribed value at the new time - current value),
   *   per component (a component no prescribed DoF constrains counts 0),
   *   projected on e. Those boundaries must all belong to one body (one
   *   material id): otherwise InputError.
   * - A node of another body whose X - d lies outside that body (the
   *   block's end the slider has left behind, or a point in a different
   *   body) keeps its value. Whether X - d lies in the node's own body is
   *   read off the interpolant of the body's material id (exact inside a
   *   cell, and between two ids on a face two bodies share).
   * - Hanging nodes are made conforming afterwards; the Dirichlet values of
   *   the new time are the step solver's business.
   *
   * Collective over the scene's communicator; one evaluation of the
   * previous field at the shifted support points (RemotePointEvaluation)
   * per load step.
   */
  template <int dim>
  class TransportPredictor
  {
  public:
    /// @p direction need not be normalised; it must not be zero.
    explicit TransportPredictor(const Tensor<1, dim> &direction);

    struct Result
    {
      /// The shift d applied (zero: nothing was done).
      Tensor<1, dim> shift;
      /// Nodes of the other bodies, on all ranks: those given the value at
      /// X - d, and those that kept theirs.
      types::global_dof_index carried = 0, kept = 0;
    };

    /// Carry @p scene's solution along for the load step to @p time (the
    /// solution holds the previous step's state).
    Result
    apply(Scene<dim> &scene, const double time) const;

  private:
    Tensor<1, dim> direction;
  };
} // namespace Signorini
