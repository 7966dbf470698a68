// The rigid foundation's limit of a line-search trial
// (RigidFoundation::limit_trial, used by Newton's line search):
// - a node free at the current state u whose trial position lies deeper
//   than the deepest penetration at u is lifted to exactly that depth, by
//   its vertical DoF only;
// - nodes in contact at u, and free nodes that stay above that depth, are
//   left as they are;
// - with no node penetrating at u nothing moves and the call says so.
// The trial moves every node down by 0.05 and sideways by a smooth field,
// the foundation is a cylinder (sphere) that the bottom face's middle
// penetrates by 0.02. Counts are global: 1 and 2 ranks print the same.
// On 2 ranks the call is followed, as in Newton's line search, by a
// collective distribute() with constraints (a version that left the ranks
// that lifted nodes in another vector state than the others made
// tests/hertz_rigid_penalty on 2 ranks hang there; this test only ran
// slower with it).

#include <signorini/contact/foundation.h>
#include <signorini/contact/rigid_foundation.h>

#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/numerics/vector_tools.h>

#include <fstream>
#include <iomanip>

using namespace dealii;
using namespace Signorini;

template <int dim>
class Motion : public Function<dim>
{
public:
  Motion()
    : Function<dim>(dim)
  {}
  double
  value(const Point<dim> &p, const unsigned int c) const override
  {
    if (c == dim - 1)
      return -0.05;
    return 0.01 * std::sin(3. * p[0] + c);
  }
};

template <int dim>
void
check(const double radius, std::ostream &out)
{
  const MPI_Comm                            comm = MPI_COMM_WORLD;
  parallel::distributed::Triangulation<dim> tria(comm);
  GridGenerator::subdivided_hyper_cube(tria, dim == 2 ? 16 : 8, 0., 1., true);
  FESystem<dim>   fe(FE_Q<dim>(1), dim);
  MappingQ<dim>   mapping(1);
  DoFHandler<dim> dof(tria);
  dof.distribute_dofs(fe);
  const IndexSet owned    = dof.locally_owned_dofs();
  const IndexSet relevant = DoFTools::extract_locally_relevant_dofs(dof);
  AffineConstraints<double> none(relevant);
  none.close();

  ParameterHandler prm;
  Contact::Foundation<dim>::declare_parameters(prm);
  prm.set("Shape", "circle");
  prm.set("Center", dim == 2 ? "0.5, -1" : "0.5, 0.5, -1");
  prm.set("Radius", std::to_string(radius));
  prm.set("Side", "upper");
  Contact::RigidFoundation<dim> contact(Contact::Foundation<dim>::create(prm, "test"),
                                        dim == 2 ? 2 : 4, dof, mapping);
  contact.setup(none);

  auto ghosted = [&](const VectorType &v) {
    VectorType g(owned, relevant, comm);
    g = v;
    return g;
  };
  const VectorType u(owned, comm); // the reference configuration
  VectorType       before(owned, comm);
  VectorTools::interpolate(mapping, dof, Motion<dim>(), before);
  VectorType after(before);

  // Ghosted copies are made collectively, before the loops over this
  // rank's nodes.
  const VectorType ug = ghosted(u);
  double           depth = 0.;
  for (const auto &node : contact.nodes())
    depth = std::max(depth, contact.evaluate(node, ug).penetration());
  depth = Utilities::MPI::max(depth, comm);

  const bool moved_any = contact.limit_trial(ug, after);
  // As Newton's line search does next: a collective operation that needs
  // every rank to agree on the vector's state (the ranks that lifted
  // nodes and those that did not).
  AffineConstraints<double> top(relevant);
  VectorTools::interpolate_boundary_values(mapping, dof, dim == 2 ? 3 : 5,
                                           Functions::ZeroFunction<dim>(dim), top);
  top.close();
  top.distribute(after);
  const auto   b = ghosted(before), a = ghosted(after);
  unsigned int lifted = 0, kept_in_contact = 0, kept_free = 0, wrong = 0;
  double       worst_gap = 0.;
  for (const auto &node : contact.nodes())
    {
      const bool   in_contact = contact.evaluate(node, ug).g < 0.;
      const double g_before   = contact.evaluate(node, b).g;
      const double g_after    = contact.evaluate(node, a).g;
      bool         same       = true;
      for (unsigned int c = 0; c < dim; ++c)
        same = same && a[node.dofs[c]] == b[node.dofs[c]];
      if (depth > 0. && !in_contact && g_before < -depth)
        {
          // Lifted: the gap is -depth, the horizontal DoFs are untouched.
          for (unsigned int c = 0; c + 1 < dim; ++c)
            wrong += (a[node.dofs[c]] != b[node.dofs[c]]);
          worst_gap = std::max(worst_gap, std::abs(g_after + depth));
          ++lifted;
        }
      else
        {
          wrong += !same;
          ++(in_contact ? kept_in_contact : kept_free);
        }
    }
  lifted          = Utilities::MPI::sum(lifted, comm);
  kept_in_contact = Utilities::MPI::sum(kept_in_contact, comm);
  kept_free       = Utilities::MPI::sum(kept_free, comm);
  wrong           = Utilities::MPI::sum(wrong, comm);
  worst_gap       = Utilities::MPI::max(worst_gap, comm);
  const bool ok   = wrong == 0 && worst_gap < 1e-14 &&
                  moved_any == (lifted > 0);
  out << dim << "D, radius " << radius << ": deepest penetration "
      << std::setprecision(6) << depth << "; " << lifted << " node(s) lifted, "
      << kept_in_contact << " in contact and " << kept_free
      << " free node(s) left alone; reported "
      << (moved_any ? "moved" : "nothing moved") << "; gap of the lifted "
      << "nodes = -depth and nothing else moved: " << (ok ? "ok" : "FAIL")
      << "\n";
  if (!ok)
    std::cerr << "wrong " << wrong << " worst gap error " << worst_gap << "\n";
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream                    out;
  if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    out.open("output");
  check<2>(1.02, out); // the bottom's middle penetrates by 0.02
  check<2>(0.9, out);  // nothing penetrates: nothing moves
  check<3>(1.02, out);
  check<3>(0.9, out);
}
