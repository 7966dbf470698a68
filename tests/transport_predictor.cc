// The transport predictor of steady sliding (Load stepping > Sliding
// direction, TransportPredictor). Two rectangles side by side: the slider
// [-1.5, -0.5] x [0, 1] (its left edge prescribed, moved by (0.75, 0.1) at
// t = 1 from zero) and a block [0, 4] x [0, 1] (cells of 0.25), each with a
// linear displacement field, which Q1 reproduces exactly. Sliding along x,
// so d = (0.75, 0). Expected after apply():
// - the slider's DoFs are its field plus d;
// - a block node with X - d in the block has the block's field at X - d
//   (to 1e-6: the points are moved back by 1e-5 d off the vertices);
// - the three block columns with X - d outside the block keep their values:
//   x = 0.25 and 0.5 land in the gap between the bodies, x = 0 inside the
//   slider, which only the body check rejects;
// - with the block's bottom prescribed as well, two bodies move: the input
//   error names the key.
// Run on 1 and 2 ranks; both print the same.

#include <signorini/input_error.h>
#include <signorini/parameters/scene_parameters.h>
#include <signorini/scene/scene.h>
#include <signorini/solvers/transport_predictor.h>

#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/numerics/vector_tools.h>

#include <cmath>
#include <fstream>
#include <iostream>
#include <set>
#include <string>

using namespace dealii;
using namespace Signorini;

namespace
{
  std::string
  scene_text(const std::string &prescribed)
  {
    return R"(
set Dimension = 2
subsection Body 1
  set Material id = 0
  subsection Geometry
    set Shape        = rectangle
    set Lower corner = -1.5, 0
    set Upper corner = -0.5, 1
    set Subdivisions = 4, 4
  end
  subsection Material
    set Young's modulus = 1
  end
end
subsection Body 2
  set Active      = true
  set Material id = 1
  subsection Geometry
    set Shape        = rectangle
    set Lower corner = 0, 0
    set Upper corner = 4, 1
    set Subdivisions = 16, 4
    set Boundary id offset = 10
  end
  subsection Material
    set Young's modulus = 1
  end
end
subsection Boundary conditions
  set Prescribed boundaries   = )" +
           prescribed + R"(
  set Prescribed displacement = 0.75*t; 0.1*t
end
subsection Load stepping
  set Sliding direction = 2, 0
end
)";
  }

  /// The slider's field (zero on its prescribed left edge) and the block's.
  class Field : public Function<2>
  {
  public:
    Field()
      : Function<2>(2)
    {}
    double
    value(const Point<2> &p, const unsigned int c) const override
    {
      if (p[0] < -0.25)
        return c == 0 ? 0.02 * (p[0] + 1.5) : 0.01 * (p[0] + 1.5);
      return c == 0 ? 0.01 * p[0] + 0.02 * p[1] + 0.003 : -0.015 * p[0] + 0.005 * p[1];
    }
  };

  std::unique_ptr<Scene<2>>
  make_scene(const std::string &prescribed, Parameters::Scene &parameters)
  {
    ParameterHandler prm;
    Parameters::Scene::declare_parameters(prm);
    prm.parse_input_from_string(scene_text(prescribed));
    parameters.parse_parameters(prm, "transport.prm");
    auto scene = std::make_unique<Scene<2>>(parameters, MPI_COMM_WORLD);
    scene->setup_dofs(nullptr);
    VectorTools::interpolate(*scene->mapping, scene->dof_handler, Field(),
                             scene->solution);
    scene->solution_ghosted = scene->solution;
    return scene;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool                       root = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  std::ofstream                    out;
  if (root)
    out.open("output");

  {
    Parameters::Scene parameters;
    auto              scene = make_scene("0: xy", parameters);
    const auto       &e     = parameters.load_stepping.sliding_direction;
    out << "direction (normalised): " << e[0] << " " << e[1] << "\n";
    const TransportPredictor<2> predictor(Tensor<1, 2>({e[0], e[1]}));
    const VectorType            before(scene->solution_ghosted);
    const auto                  result = predictor.apply(*scene, 1.);
    out << "d = " << result.shift << "\n"
        << "block nodes carried: " << result.carried << ", kept: " << result.kept << "\n";

    // Compare every locally owned DoF with the expected value.
    const Field                field;
    const auto                &fe = *scene->fe;
    const Quadrature<2>        support(fe.get_unit_support_points());
    FEValues<2>                fe_values(*scene->mapping, fe, support, update_quadrature_points);
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    double slider_error = 0., carried_error = 0., kept_error = 0.;
    std::set<types::global_dof_index> at_x0;
    for (const auto &cell : scene->dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          cell->get_dof_indices(dofs);
          for (unsigned int i = 0; i < dofs.size(); ++i)
            {
              if (!scene->locally_owned.is_element(dofs[i]))
                continue;
              const unsigned int c     = fe.system_to_component_index(i).first;
              const Point<2>     X     = fe_values.quadrature_point(i);
              const double       value = scene->solution_ghosted[dofs[i]];
              if (cell->material_id() == 0)
                slider_error = std::max(slider_error,
                                        std::abs(value - before[dofs[i]] -
                                                 (c == 0 ? 0.75 : 0.)));
              else if (X[0] > 0.7)
                carried_error =
                  std::max(carried_error,
                           std::abs(value - field.value(Point<2>(X[0] - 0.75, X[1]), c)));
              else
                {
                  kept_error = std::max(kept_error, std::abs(value - before[dofs[i]]));
                  if (X[0] < 0.1 && c == 0)
                    at_x0.insert(dofs[i]);
                }
            }
        }
    slider_error  = Utilities::MPI::max(slider_error, MPI_COMM_WORLD);
    carried_error = Utilities::MPI::max(carried_error, MPI_COMM_WORLD);
    kept_error    = Utilities::MPI::max(kept_error, MPI_COMM_WORLD);
    const unsigned int n_kept_inside_slider =
      Utilities::MPI::sum(static_cast<unsigned int>(at_x0.size()), MPI_COMM_WORLD);
    const auto yes = [](const bool b) { return b ? "yes" : "NO"; };
    out << "slider shifted by d (1e-12): " << yes(slider_error < 1e-12) << "\n"
        << "block nodes with x >= 0.75 take the field at X - d (1e-6): "
        << yes(carried_error < 1e-6) << "\n"
        << "block nodes with x <= 0.5 unchanged: " << yes(kept_error == 0.) << "\n"
        << "nodes at x = 0 (X - d inside the slider) among them: " << n_kept_inside_slider
        << "\n";
    std::cerr << "errors: slider " << slider_error << " carried " << carried_error
              << " kept " << kept_error << "\n";
  }

  // Prescribed boundaries on both bodies.
  try
    {
      Parameters::Scene parameters;
      auto              scene = make_scene("0: xy, 12: xy", parameters);
      const auto       &e     = parameters.load_stepping.sliding_direction;
      const TransportPredictor<2> predictor(Tensor<1, 2>({e[0], e[1]}));
      predictor.apply(*scene, 1.);
      out << "two moving bodies: no error\n";
    }
  catch (const InputError &error)
    {
      out << "two moving bodies: " << error.what() << "\n";
    }
}
