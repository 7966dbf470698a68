// Finite-difference checks of the rigid-foundation contact derivatives:
// (1) every foundation shape's psi', psi'' against central differences, in
//     2D and 3D, also beyond the circle's Taylor continuation point, and
//     the extrapolated derivatives of an expression against the exact ones;
// (2) the constraint g_k(U) = x_d - psi(x'): its gradient and Hessian with
//     respect to the node's displacement, for a curved foundation;
// (3) the assembled penalty term mu/3 sum w_k <-g_k>^3: minus gradient and
//     Hessian-vector products against differences of the value/gradient.
// A corrupted derivative must be reported (the checker can fail).

#include <signorini/contact/foundation.h>
#include <signorini/contact/rigid_foundation.h>

#include <deal.II/base/mpi.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include "penalty_fd.h"

#include <fstream>
#include <random>

using namespace dealii;
using namespace Signorini;

template <int dim>
std::unique_ptr<Contact::Foundation<dim>>
make(const std::vector<std::pair<std::string, std::string>> &entries)
{
  ParameterHandler prm;
  Contact::Foundation<dim>::declare_parameters(prm);
  for (const auto &e : entries)
    prm.set(e.first, e.second);
  return Contact::Foundation<dim>::create(prm, "test");
}

// Largest relative error of psi' and psi'' against central differences.
template <int dim>
std::pair<double, double>
fd_error(const Contact::Foundation<dim> &f, const Point<dim> &x)
{
  const double h = 1e-5;
  const auto   v = f.evaluate(x);
  double       eg = 0., eh = 0.;
  for (unsigned int i = 0; i + 1 < dim; ++i)
    {
      Point<dim> xp = x, xm = x;
      xp[i] += h;
      xm[i] -= h;
      const auto   vp = f.evaluate(xp), vm = f.evaluate(xm);
      const double g  = (vp.psi - vm.psi) / (2 * h);
      eg = std::max(eg, std::abs(g - v.gradient[i]) / (1. + std::abs(g)));
      for (unsigned int j = 0; j + 1 < dim; ++j)
        {
          const double hj = (vp.gradient[j] - vm.gradient[j]) / (2 * h);
          eh = std::max(eh, std::abs(hj - v.hessian[j][i]) / (1. + std::abs(hj)));
        }
    }
  return {eg, eh};
}

template <int dim>
void
check_shapes(std::ostream &out)
{
  const std::string c = (dim == 2 ? "0.3, 2" : "0.3, 0, 2");
  std::vector<std::pair<std::string, std::vector<std::pair<std::string, std::string>>>>
    shapes = {
      {"plane", {{"Shape", "plane"}, {"Height", "0.2"}, {"Slope", "0.1, -0.3"}}},
      {"circle lower",
       {{"Shape", "circle"}, {"Center", c}, {"Radius", "2"}, {"Side", "lower"}}},
      {"circle upper",
       {{"Shape", "circle"}, {"Center", c}, {"Radius", "2"}, {"Side", "upper"}}},
      {"sine",
       {{"Shape", "sine"}, {"Mean height", "0.1"}, {"Amplitude", "0.05"},
        {"Wavelength", "0.7"}, {"Phase", "0.3"}}},
      {"expression with derivatives",
       {{"Shape", "expression"},
        {"Function", dim == 2 ? "a*x^2 + sin(x)" : "a*x^2 + sin(x*y)"},
        {"Gradient", dim == 2 ? "2*a*x + cos(x)" : "2*a*x + y*cos(x*y); x*cos(x*y)"},
        {"Hessian",
         dim == 2 ? "2*a - sin(x)" :
                    "2*a - y*y*sin(x*y); cos(x*y) - x*y*sin(x*y); "
                    "cos(x*y) - x*y*sin(x*y); -x*x*sin(x*y)"},
        {"Function constants", "a=0.4"}}}};
  std::mt19937                           rng(11 + dim);
  std::uniform_real_distribution<double> uniform(-1., 1.);
  for (const auto &shape : shapes)
    {
      const auto f = make<dim>(shape.second);
      double     eg = 0., eh = 0.;
      // Random points, and points beyond 0.99 R for the circles.
      for (unsigned int k = 0; k < 20; ++k)
        {
          Point<dim> x;
          for (unsigned int d = 0; d < dim; ++d)
            x[d] = (k < 16 ? 1. : 3.) * uniform(rng);
          const auto e = fd_error(*f, x);
          eg           = std::max(eg, e.first);
          eh           = std::max(eh, e.second);
        }
      out << dim << "D " << shape.first << ": psi' vs FD "
          << (eg < 1e-7 ? "ok" : "FAIL") << ", psi'' vs FD "
          << (eh < 1e-6 ? "ok" : "FAIL") << "\n";
      if (eg >= 1e-7 || eh >= 1e-6)
        std::cerr << shape.first << " errors " << eg << " " << eh << "\n";
    }

  // Extrapolated derivatives of the same expression, against the exact.
  auto exact = make<dim>(shapes.back().second);
  auto extrapolated_entries = shapes.back().second;
  extrapolated_entries[2].second = "";
  extrapolated_entries[3].second = "";
  auto   extrapolated = make<dim>(extrapolated_entries);
  double eg = 0., eh = 0.;
  for (unsigned int k = 0; k < 20; ++k)
    {
      Point<dim> x;
      for (unsigned int d = 0; d < dim; ++d)
        x[d] = uniform(rng);
      const auto a = exact->evaluate(x), b = extrapolated->evaluate(x);
      eg = std::max(eg, (a.gradient - b.gradient).norm());
      eh = std::max(eh, (a.hessian - b.hessian).norm());
    }
  out << dim << "D expression, extrapolated derivatives: psi' error < 1e-9 "
      << (eg < 1e-9 ? "ok" : "FAIL") << ", psi'' error < 1e-6 "
      << (eh < 1e-6 ? "ok" : "FAIL") << "\n";
  if (eg >= 1e-9 || eh >= 1e-6)
    std::cerr << "extrapolation errors " << eg << " " << eh << "\n";
}

template <int dim>
void
check_constraints(const unsigned int degree, std::ostream &out)
{
  const MPI_Comm                            comm = MPI_COMM_WORLD;
  parallel::distributed::Triangulation<dim> tria(comm);
  GridGenerator::subdivided_hyper_cube(tria, 3, 0., 1., true);
  FESystem<dim>   fe(FE_Q<dim>(degree), dim);
  MappingQ<dim>   mapping(degree);
  DoFHandler<dim> dof(tria);
  dof.distribute_dofs(fe);
  const IndexSet owned    = dof.locally_owned_dofs();
  const IndexSet relevant = DoFTools::extract_locally_relevant_dofs(dof);
  AffineConstraints<double> none(relevant);
  none.close();

  // A rigid cylinder under the bottom face (id 2 in 2D, 4 in 3D), which
  // the bottom penetrates in its middle.
  const std::string center = (dim == 2 ? "0.5, -1" : "0.5, 0, -1");
  Contact::RigidFoundation<dim> contact(
    make<dim>({{"Shape", "circle"}, {"Center", center}, {"Radius", "1.1"},
               {"Side", "upper"}}),
    dim == 2 ? 2 : 4, dof, mapping);
  contact.setup(none);

  std::mt19937                           rng(5 + degree + dim);
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
  const VectorType u = random_vector(0.03);

  // (2) g_k: gradient and Hessian w.r.t. the node's displacement.
  const double h = 1e-6;
  double       eg = 0., eh = 0.;
  for (const auto &node : contact.nodes())
    {
      const auto s = contact.evaluate(node, ghosted(u));
      for (unsigned int c = 0; c < dim; ++c)
        {
          VectorType up(u), um(u);
          up[node.dofs[c]] += h;
          um[node.dofs[c]] -= h;
          const auto sp = contact.evaluate(node, ghosted(up));
          const auto sm = contact.evaluate(node, ghosted(um));
          eg = std::max(eg, std::abs((sp.g - sm.g) / (2 * h) - s.grad[c]));
          for (unsigned int d = 0; d < dim; ++d)
            eh = std::max(eh, std::abs((sp.grad[d] - sm.grad[d]) / (2 * h) -
                                       s.hess[d][c]));
        }
    }

  // (3) the assembled penalty term.
  TrilinosWrappers::SparsityPattern sp(owned, owned, relevant, comm);
  DoFTools::make_sparsity_pattern(dof, sp, none, false);
  sp.compress();
  MatrixType H;
  H.reinit(sp);
  VectorType   rhs(owned, comm);
  const double mu = 50.;
  std::vector<double> forces;
  contact.add_penalty(ghosted(u), mu, none, &rhs, &H, &forces);
  unsigned int pressed = 0;
  for (const double f : forces)
    pressed += (f > 0.);
  // Relative error of H v against differences of minus the gradient, and
  // of the directional derivative against differences of the value.
  auto fd_errors = [&](const MatrixType &matrix, const VectorType &v) {
    return penalty_fd_errors<dim>(contact, mu, none, relevant, u, rhs, matrix, v, h);
  };
  double worst_gradient = 0., worst_hessian = 0.;
  for (unsigned int trial = 0; trial < 3; ++trial)
    {
      const auto e   = fd_errors(H, random_vector(1.));
      worst_gradient = std::max(worst_gradient, e.first);
      worst_hessian  = std::max(worst_hessian, e.second);
    }
  const bool ok = eg < 1e-8 && eh < 1e-7 && worst_gradient < 1e-6 &&
                  worst_hessian < 1e-5 && pressed > 0;
  out << dim << "D Q" << degree << ": " << contact.n_global_nodes()
      << " contact nodes, " << (pressed > 0 ? "some" : "NO")
      << " penetrating; grad g vs FD " << (eg < 1e-8 ? "ok" : "FAIL")
      << ", hess g vs FD " << (eh < 1e-7 ? "ok" : "FAIL")
      << ", penalty gradient vs FD " << (worst_gradient < 1e-6 ? "ok" : "FAIL")
      << ", penalty Hessian vs FD " << (worst_hessian < 1e-5 ? "ok" : "FAIL")
      << "\n";
  if (!ok)
    std::cerr << "errors " << eg << " " << eh << " " << worst_gradient << " "
              << worst_hessian << "\n";

  // The check must be able to fail: a 0.1% error in the Hessian is caught.
  if (degree == 1)
    {
      H *= 1.001;
      out << dim << "D: a Hessian scaled by 1.001 is "
          << (fd_errors(H, random_vector(1.)).second >= 1e-5 ? "rejected" :
                                                               "NOT rejected")
          << "\n";
    }
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream                    out("output");
  check_shapes<2>(out);
  check_shapes<3>(out);
  check_constraints<2>(1, out);
  check_constraints<2>(2, out);
  check_constraints<3>(1, out);
  check_constraints<3>(2, out);
}
