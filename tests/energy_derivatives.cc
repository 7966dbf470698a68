// Finite-difference check of the assembled total potential energy: the
// gradient against central differences of E along random directions, and
// the Hessian times a direction against central differences of the
// gradient, for Q1 and Q2, 2D and 3D, with a traction and a body force
// that depend on position and time, on a mildly distorted mesh. The same
// for the augmented Lagrangian of the J = 1 constraints that the interior
// point method minimises (IncompressibilityLagrangian: the energy plus
// sum_K y_K c_K + rho_K/2 c_K^2, random multipliers and weights).

#include <signorini/scene/boundary_conditions.h>
#include <signorini/problem/energy_functional.h>
#include <signorini/problem/incompressibility_lagrangian.h>
#include <signorini/material/invariant_based.h>
#include <signorini/material/laws.h>

#include <deal.II/base/mpi.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <fstream>
#include <random>
#include <utility>
#include <vector>

using namespace dealii;
using namespace Signorini;

template <int dim>
void
check(const unsigned int degree, std::ostream &out)
{
  const MPI_Comm                            comm = MPI_COMM_WORLD;
  parallel::distributed::Triangulation<dim> tria(comm);
  GridGenerator::subdivided_hyper_cube(tria, 2, 0., 1., true);
  GridTools::distort_random(0.1, tria, false, 7);
  for (const auto &cell : tria.active_cell_iterators())
    cell->set_material_id(0);
  FESystem<dim>   fe(FE_Q<dim>(degree), dim);
  MappingQ<dim>   mapping(degree);
  DoFHandler<dim> dof(tria);
  dof.distribute_dofs(fe);
  const IndexSet owned    = dof.locally_owned_dofs();
  const IndexSet relevant = DoFTools::extract_locally_relevant_dofs(dof);

  Material::InvariantLaw<Material::ElasHyperLaw> material(
    Material::ElasHyperLaw{0.709, 2.3456, 0.456, 30., true});
  std::map<types::material_id, const Material::Interface *> materials = {
    {0, &material}};

  ParameterHandler prm;
  BoundaryConditions<dim>::declare_parameters(prm);
  prm.set("Traction boundaries", "1, 3");
  prm.set("Traction", dim == 2 ? "0.1*x; -0.2+y*t" : "0.1*x; -0.2+y*t; 0.05*z");
  prm.set("Body force", dim == 2 ? "0.3; -0.1*x" : "0.3; -0.1*x; 0.2*y");
  prm.set("Fixed boundaries", "0: x");
  BoundaryConditions<dim> bc;
  bc.parse_parameters(prm, {0, 1, 2, 3, 4, 5});

  EnergyFunctional<dim>     energy(dof, mapping, materials, bc);
  AffineConstraints<double> none(relevant);
  none.close();

  TrilinosWrappers::SparsityPattern sp(owned, owned, relevant, comm);
  DoFTools::make_sparsity_pattern(dof, sp, none, false);
  sp.compress();
  MatrixType H;
  H.reinit(sp);

  std::mt19937                           rng(3 + degree + dim);
  std::uniform_real_distribution<double> uniform(-1., 1.);
  auto random_vector = [&](const double amplitude) {
    VectorType v(owned, comm);
    for (const auto i : owned)
      v[i] = amplitude * uniform(rng);
    v.compress(VectorOperation::insert);
    return v;
  };
  auto ghosted = [&](const VectorType &v) {
    VectorType g(owned, relevant, comm);
    g = v;
    return g;
  };

  const double     t = 0.7;
  const VectorType u = random_vector(0.05);
  VectorType       rhs(owned, comm);

  // Largest relative errors of the gradient and of the Hessian times a
  // direction of @p objective at u against central differences.
  auto fd_check = [&](Objective &objective) {
    const Evaluation e = objective.evaluate(ghosted(u), none, &rhs, &H);
    AssertThrow(e.admissible, ExcInternalError());
    double       worst_gradient = 0., worst_hessian = 0.;
    const double h = 1e-6;
    for (unsigned int trial = 0; trial < 3; ++trial)
      {
        const VectorType v = random_vector(1.);
        VectorType       up(u), um(u);
        up.add(h, v);
        um.add(-h, v);
        VectorType       rp(owned, comm), rm(owned, comm);
        const Evaluation ep = objective.evaluate(ghosted(up), none, &rp, nullptr);
        const Evaluation em = objective.evaluate(ghosted(um), none, &rm, nullptr);

        const double directional = -(rhs * v);
        const double fd          = (ep.value - em.value) / (2 * h);
        worst_gradient =
          std::max(worst_gradient, std::abs(fd - directional) / std::abs(directional));

        VectorType Hv(owned, comm);
        H.vmult(Hv, v);
        VectorType fd_Hv(rm); // -(g(u+hv) - g(u-hv)) / 2h = (rm - rp)/2h... with rhs = -g
        fd_Hv.add(-1., rp);
        fd_Hv /= (2 * h);
        VectorType diff(Hv);
        diff -= fd_Hv;
        worst_hessian = std::max(worst_hessian, diff.l2_norm() / Hv.l2_norm());
      }
    return std::make_pair(worst_gradient, worst_hessian);
  };

  EnergyObjective<dim> objective(energy, t);
  const auto [worst_gradient, worst_hessian] = fd_check(objective);
  out << dim << "D Q" << degree << " (" << dof.n_dofs() << " dofs): gradient vs FD "
      << (worst_gradient < 1e-7 ? "ok" : "FAIL") << ", Hessian vs FD "
      << (worst_hessian < 1e-6 ? "ok" : "FAIL") << ", Hessian symmetric ";
  // Symmetry: v.H w == w.H v
  const VectorType v = random_vector(1.), w = random_vector(1.);
  VectorType       Hv(owned, comm), Hw(owned, comm);
  H.vmult(Hv, v);
  H.vmult(Hw, w);
  out << (std::abs(w * Hv - v * Hw) < 1e-10 * std::abs(w * Hv) ? "ok" : "FAIL");
  // Entry by entry, to the last bit (one rank, no constraints: every cell
  // adds its local matrix, which must be exactly symmetric).
  bool exact = true;
  for (auto entry = H.begin(); entry != H.end(); ++entry)
    exact = exact && entry->value() == H.el(entry->column(), entry->row());
  out << ", exactly " << (exact ? "ok" : "FAIL") << "\n";
  if (worst_gradient >= 1e-7 || worst_hessian >= 1e-6)
    std::cerr << "errors " << worst_gradient << " " << worst_hessian << "\n";

  // The augmented Lagrangian of J = 1 per cell, multipliers and weights of
  // the size of the energy's terms.
  Incompressibility<dim> incompressibility(dof, mapping, {0});
  const unsigned int     n_cells = incompressibility.cells().size();
  std::vector<double>    y(n_cells), rho(n_cells);
  for (unsigned int k = 0; k < n_cells; ++k)
    {
      y[k]   = uniform(rng);
      rho[k] = 10. * (1.5 + uniform(rng));
    }
  IncompressibilityLagrangian<dim> lagrangian(objective, incompressibility, y, rho);
  const auto [lagrangian_gradient, lagrangian_hessian] = fd_check(lagrangian);
  out << dim << "D Q" << degree << " augmented Lagrangian of J = 1: gradient vs FD "
      << (lagrangian_gradient < 1e-7 ? "ok" : "FAIL") << ", Hessian vs FD "
      << (lagrangian_hessian < 1e-6 ? "ok" : "FAIL") << "\n";
  std::cerr << dim << "D Q" << degree << " augmented Lagrangian: errors "
            << lagrangian_gradient << " " << lagrangian_hessian << "\n";
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream                    out("output");
  check<2>(1, out);
  check<2>(2, out);
  check<3>(1, out);
  check<3>(2, out);
}
