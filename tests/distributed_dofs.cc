// DoFs of the built-in 3D bodies on a distributed mesh with hanging nodes
// (3 global and 4 local refinement levels, vector Q1): the number of DoFs
// is the one the same mesh has on one rank, and every DoF a rank owns lies
// on some locally owned cell of some rank. deal.II 9.4's DoF distribution
// broke both for the octant ball on 2 ranks (24 of 31590 DoFs on no cell)
// until the coarse cells were put in standard orientation
// (GridTools::consistently_order_cells in build_scene_mesh). Run on 1 and
// 2 ranks; both print the same.

#include <signorini/scene/mesh.h>
#include <signorini/scene/scene.h>

#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>

#include <fstream>
#include <string>
#include <vector>

using namespace dealii;
using namespace Signorini;

namespace
{
  /// Number of DoFs, and the number of owned DoFs on no cell (all ranks).
  std::pair<types::global_dof_index, unsigned int>
  distribute(const BodyGeometry &body, const MPI_Comm comm)
  {
    MeshParameters mesh;
    mesh.global_refinements = 3;
    mesh.local_refinements  = 4;
    mesh.local_center       = {0., 0., 0.};
    mesh.local_radius       = 0.11;
    parallel::distributed::Triangulation<3> tria(comm);
    build_scene_mesh<3>(mesh, {body}, {0}, tria);
    const FESystem<3> fe(FE_Q<3>(1), 3);
    DoFHandler<3>     dof_handler(tria);
    dof_handler.distribute_dofs(fe);
    return {dof_handler.n_dofs(), n_dofs_on_no_cell(dof_handler)};
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                   comm = MPI_COMM_WORLD;
  std::ofstream                    out;
  if (Utilities::MPI::this_mpi_process(comm) == 0)
    out.open("output");

  using Shape = BodyGeometry::Shape;
  struct Case
  {
    std::string name;
    Shape       shape;
    bool        upward;
  };
  const std::vector<Case> cases = {{"octant ball", Shape::octant_ball, false},
                                   {"octant ball, up", Shape::octant_ball, true},
                                   {"quarter ball", Shape::quarter_ball, false},
                                   {"hemisphere", Shape::hemisphere, false},
                                   {"quarter cylinder", Shape::quarter_cylinder, false},
                                   {"die", Shape::die, false}};
  for (const auto &c : cases)
    {
      BodyGeometry body;
      body.shape  = c.shape;
      body.upward = c.upward;
      body.radius = 1.;
      body.length = 1.;
      if (c.shape == Shape::die)
        {
          body.lower_corner = {-0.5, 0., 0.};
          body.upper_corner = {0.5, 1., 1.};
          body.subdivisions = {2, 2, 2};
        }
      else
        body.center = {0., 0., c.upward ? -1. : 1.};
      const auto here   = distribute(body, comm);
      const auto single = distribute(body, MPI_COMM_SELF);
      if (out.is_open())
        out << c.name << ": DoFs as on one rank: "
            << (here.first == single.first ? "yes" : "NO")
            << ", every DoF on a cell: " << (here.second == 0 ? "yes" : "NO") << "\n";
    }
}
