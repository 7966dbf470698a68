// Micro-benchmark of the energy assembly (EnergyFunctional::evaluate) on one
// thread: the wall and CPU time of one evaluation of E alone, of E and its gradient, and
// of E, gradient and Hessian, per DoF, on a 2D and a 3D Q1 mesh of the unit
// square/cube under a smooth finite deformation, for the first example of
// every registered material law. Not a test: it prints timings.
//
//   build/benchmarks/assembly [2D cells per side] [3D cells per side]
//                             [repetitions] [hessian]
//
// (defaults 256, 32 and 5: 132 098 and 107 811 DoFs; 0 cells skips that
// dimension; "hessian" times only the Hessian evaluations, for a profiler). Each figure is the
// median over the repetitions. Built by the optional target
// `assembly-benchmark` (cmake --build build --target assembly-benchmark).

#include <signorini/material/interface.h>
#include <signorini/material/registry.h>
#include <signorini/problem/energy_functional.h>
#include <signorini/scene/boundary_conditions.h>

#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/multithread_info.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <deal.II/numerics/vector_tools.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

using namespace dealii;
using namespace Signorini;

namespace
{
  /// A smooth deformation with stretch, shear and some rotation (J > 0).
  template <int dim>
  class Deformation : public Function<dim>
  {
  public:
    Deformation()
      : Function<dim>(dim)
    {}
    double
    value(const Point<dim> &p, const unsigned int c) const override
    {
      const double x = p[0], y = p[1], z = (dim == 3 ? p[2] : 0.);
      switch (c)
        {
          case 0:
            return 0.10 * x + 0.05 * std::sin(2. * y) + 0.02 * z * y;
          case 1:
            return -0.08 * y + 0.06 * x * x + 0.03 * z;
          default:
            return 0.05 * z - 0.04 * x * y;
        }
    }
  };

  double
  thread_cpu_seconds()
  {
    timespec t;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
  }

  double
  median(std::vector<double> v)
  {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
  }

  template <int dim>
  void
  run(const unsigned int cells_per_side,
      const unsigned int repetitions,
      const bool         hessian_only)
  {
    const MPI_Comm                            comm = MPI_COMM_WORLD;
    parallel::distributed::Triangulation<dim> tria(comm);
    GridGenerator::subdivided_hyper_cube(tria, cells_per_side, 0., 1.);
    FESystem<dim>   fe(FE_Q<dim>(1), dim);
    MappingQ<dim>   mapping(1);
    DoFHandler<dim> dof(tria);
    dof.distribute_dofs(fe);
    const IndexSet owned    = dof.locally_owned_dofs();
    const IndexSet relevant = DoFTools::extract_locally_relevant_dofs(dof);

    ParameterHandler prm;
    BoundaryConditions<dim>::declare_parameters(prm);
    BoundaryConditions<dim> bc;
    bc.parse_parameters(prm, {0});

    AffineConstraints<double> none(relevant);
    none.close();
    TrilinosWrappers::SparsityPattern sp(owned, owned, relevant, comm);
    DoFTools::make_sparsity_pattern(dof, sp, none, false);
    sp.compress();
    MatrixType H;
    H.reinit(sp);
    VectorType rhs(owned, comm);
    VectorType u(owned, comm);
    VectorTools::interpolate(mapping, dof, Deformation<dim>(), u);
    VectorType ghosted(owned, relevant, comm);
    ghosted = u;

    for (const Material::LawEntry &law : Material::registered_laws())
      {
        ParameterHandler mprm;
        Material::declare_parameters(mprm);
        mprm.set("Model", law.name);
        for (const auto &[key, value] : law.examples.front().settings)
          mprm.set(key, value);
        const auto material = Material::create(mprm, "benchmark");
        const std::map<types::material_id, const Material::Interface *>
          materials = {{0, material.get()}};
        EnergyFunctional<dim> energy(dof, mapping, materials, bc);

        // Wall and CPU time of this thread, median over the repetitions,
        // in microseconds per DoF.
        auto time = [&](VectorType *r, MatrixType *h) {
          std::vector<double> wall, cpu;
          for (unsigned int k = 0; k < repetitions; ++k)
            {
              const double c0    = thread_cpu_seconds();
              const auto   start = std::chrono::steady_clock::now();
              const auto   e     = energy.evaluate(ghosted, 0., none, r, h);
              const auto   stop  = std::chrono::steady_clock::now();
              const double c1    = thread_cpu_seconds();
              AssertThrow(e.admissible, ExcMessage("inadmissible state"));
              wall.push_back(
                std::chrono::duration<double>(stop - start).count());
              cpu.push_back(c1 - c0);
            }
          return std::make_pair(1e6 * median(wall) / dof.n_dofs(),
                                1e6 * median(cpu) / dof.n_dofs());
        };
        const std::pair<double, double> skipped(0., 0.);
        const auto value = hessian_only ? skipped : time(nullptr, nullptr);
        const auto gradient = hessian_only ? skipped : time(&rhs, nullptr);
        const auto hessian  = time(&rhs, &H);
        std::cout << dim << "D Q1  " << std::setw(7) << dof.n_dofs() << "  "
                  << std::left << std::setw(24) << law.name << std::right
                  << std::fixed << std::setprecision(3);
        for (const auto &t : {value, gradient, hessian})
          std::cout << std::setw(8) << t.first << std::setw(7) << t.second;
        std::cout << std::endl;
      }
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  MultithreadInfo::set_thread_limit(1);
  const unsigned int n2 = argc > 1 ? std::stoi(argv[1]) : 256;
  const unsigned int n3 = argc > 2 ? std::stoi(argv[2]) : 32;
  const unsigned int reps = argc > 3 ? std::stoi(argv[3]) : 5;
  // A fourth argument "hessian" times the Hessian evaluations only (for a
  // profiler); the other columns then print 0.
  const bool hessian_only = argc > 4 && std::string(argv[4]) == "hessian";
  std::cout << "one thread; microseconds per DoF per evaluation, wall and "
               "thread CPU time (median of "
            << reps << ")\n"
            << "                                            value"
               "          gradient       Hessian\n"
            << "mesh     DoFs  law                       wall    cpu"
               "    wall    cpu    wall    cpu\n";
  if (n2 > 0)
    run<2>(n2, reps, hessian_only);
  if (n3 > 0)
    run<3>(n3, reps, hessian_only);
}
