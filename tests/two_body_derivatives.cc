// Two-body contact term mu P(U) (nodal and integral forms, 2D and 3D, Q1
// and Q2): its assembled gradient and Hessian, with the coupled blocks
// between body 1's contact DoFs and body 2's cell DoFs, against central
// differences of the value and of the gradient along random directions
// (one of them moving body 2 only). Body 1 (a coarser box) overlaps the
// top layer of body 2's cells, shifted sideways so that the meshes do not
// match; everything is perturbed randomly. A 0.1% Hessian error must be
// rejected. The same for the two-pass evaluation (Passes = two-pass: body
// 2's top nodes against body 1's indicator too), nodal and integral.

#include <signorini/contact/two_body.h>
#include <signorini/contact/two_pass.h>
#include <signorini/scene/mesh.h>

#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>

#include "penalty_fd.h"

#include <fstream>
#include <limits>
#include <memory>
#include <random>
#include <string>

using namespace dealii;
using namespace Signorini;

template <int dim>
void
check(const unsigned int degree,
      const bool         integral,
      std::ostream      &out,
      const unsigned int passes = 1)
{
  const MPI_Comm                            comm = MPI_COMM_WORLD;
  parallel::distributed::Triangulation<dim> tria(comm);
  std::vector<BodyGeometry>                 bodies(2);
  for (unsigned int b = 0; b < 2; ++b)
    {
      bodies[b].lower_corner.assign(dim, 0.);
      bodies[b].upper_corner.assign(dim, 1.);
      bodies[b].subdivisions.assign(dim, b == 0 ? 2 : 3);
    }
  // Body 1 above, its bottom 0.06 inside body 2's top cells (depth 1/3).
  bodies[0].lower_corner[0]     = 0.07;
  bodies[0].upper_corner[0]     = 0.87;
  bodies[0].lower_corner[dim - 1] = 1. - 0.06;
  bodies[0].upper_corner[dim - 1] = 2. - 0.06;
  bodies[1].boundary_id_offset  = 10;
  MeshParameters mesh;
  build_scene_mesh<dim>(mesh, bodies, {0, 1}, tria);

  FESystem<dim>   fe(FE_Q<dim>(degree), dim);
  MappingQ<dim>   mapping(degree);
  DoFHandler<dim> dof(tria);
  dof.distribute_dofs(fe);
  const IndexSet owned    = dof.locally_owned_dofs();
  const IndexSet relevant = DoFTools::extract_locally_relevant_dofs(dof);
  AffineConstraints<double> none(relevant);
  none.close();

  Contact::TwoBodyParameters parameters;
  parameters.target_boundary = 10 + 2 * (dim - 1) + 1; // body 2's top
  parameters.integral        = integral;
  parameters.gauss_points    = 3;
  // the exact Hessian is checked here
  parameters.hessian_mode = Contact::TwoBodyParameters::HessianMode::exact;
  parameters.passes       = passes;
  std::unique_ptr<Contact::Model<dim>> model;
  if (passes == 2)
    model = std::make_unique<Contact::TwoPassContact<dim>>(parameters, 2 * (dim - 1), dof,
                                                           mapping);
  else
    model = std::make_unique<Contact::TwoBodyContact<dim>>(parameters, 2 * (dim - 1), dof,
                                                           mapping);
  Contact::Model<dim> &contact = *model;
  contact.setup(none, none);

  std::mt19937                           rng(11 + degree + dim + integral + 10 * passes);
  std::uniform_real_distribution<double> uniform(-1., 1.);
  auto random_vector = [&](const double amplitude, const bool body2_only) {
    VectorType                           v(owned, comm);
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    for (const auto &cell : dof.active_cell_iterators())
      if (cell->is_locally_owned() && (!body2_only || cell->material_id() == 1))
        {
          cell->get_dof_indices(dofs);
          for (const auto i : dofs)
            if (owned.is_element(i))
              v[i] = amplitude * uniform(rng);
        }
    v.compress(VectorOperation::insert);
    return v;
  };
  auto ghosted = [&](const VectorType &v) {
    VectorType g(owned, relevant, comm);
    g = v;
    return g;
  };
  const VectorType u = random_vector(0.01, false);

  IndexSet writable = relevant;
  contact.add_writable_rows(writable);
  TrilinosWrappers::SparsityPattern sp(owned, owned, writable, comm);
  DoFTools::make_sparsity_pattern(dof, sp, none, false);
  contact.add_sparsity(sp, none, ghosted(u));
  sp.compress();
  MatrixType H;
  H.reinit(sp);
  VectorType          rhs(owned, comm);
  const double        mu = 50.;
  std::vector<double> forces;
  const double value = contact.add_penalty(ghosted(u), mu, none, &rhs, &H, &forces);
  const auto   pairs = *contact.evaluated_pairs();

  const double h = 1e-6;
  auto fd_errors = [&](const MatrixType &matrix, const VectorType &v) {
    return penalty_fd_errors<dim>(contact, mu, none, relevant, u, rhs, matrix, v, h);
  };
  double worst_gradient = 0., worst_hessian = 0.;
  for (unsigned int trial = 0; trial < 4; ++trial)
    {
      const auto e   = fd_errors(H, random_vector(1., trial == 0));
      worst_gradient = std::max(worst_gradient, e.first);
      worst_hessian  = std::max(worst_hessian, e.second);
    }
  // The coupled block: moving body 2 only changes body 1's forces.
  const VectorType v2 = random_vector(1., true);
  VectorType       Hv2(owned, comm);
  H.vmult(Hv2, v2);
  double body1_part = 0.;
  for (const auto &n : contact.contact_nodes_on_boundary().nodes())
    for (unsigned int c = 0; c < dim; ++c)
      body1_part += Hv2[n.dofs[c]] * Hv2[n.dofs[c]];
  body1_part = Utilities::MPI::sum(body1_part, comm);

  const bool ok = value > 0. && pairs > 0 && worst_gradient < 1e-6 &&
                  worst_hessian < 1e-5 && body1_part > 0.;
  out << dim << "D Q" << degree << (integral ? " integral" : " nodal")
      << (passes == 2 ? " two-pass" : "") << ": "
      << (value > 0. ? "penetrating" : "NOT penetrating") << ", "
      << (pairs > 0 ? "pairs evaluated" : "NO pairs")
      << "; gradient vs FD " << (worst_gradient < 1e-6 ? "ok" : "FAIL")
      << ", Hessian vs FD " << (worst_hessian < 1e-5 ? "ok" : "FAIL")
      << ", coupled block " << (body1_part > 0. ? "present" : "MISSING") << "\n";
  if (!ok)
    std::cerr << "errors " << worst_gradient << " " << worst_hessian << "\n";
  if (degree == 1 && !integral && passes == 1)
    {
      H *= 1.001;
      out << dim << "D: a Hessian scaled by 1.001 is "
          << (fd_errors(H, random_vector(1., false)).second >= 1e-5 ? "rejected" :
                                                                    "NOT rejected")
          << "\n";
    }
}

// The projection used by 'Hessian = projected': Q diag(lambda) Q^T must
// become Q diag(max(lambda, 0)) Q^T, and a semidefinite matrix must stay.
void
check_projection(std::ostream &out)
{
  const unsigned int                     n = 10;
  std::mt19937                           rng(5);
  std::uniform_real_distribution<double> uniform(-1., 1.);
  FullMatrix<double>                     Q(n, n);
  for (unsigned int k = 0; k < n; ++k) // Gram-Schmidt on random columns
    {
      Vector<double> q(n);
      for (unsigned int i = 0; i < n; ++i)
        q(i) = uniform(rng);
      for (unsigned int l = 0; l < k; ++l)
        {
          double dot = 0.;
          for (unsigned int i = 0; i < n; ++i)
            dot += q(i) * Q(i, l);
          for (unsigned int i = 0; i < n; ++i)
            q(i) -= dot * Q(i, l);
        }
      q /= q.l2_norm();
      for (unsigned int i = 0; i < n; ++i)
        Q(i, k) = q(i);
    }
  std::vector<double> lambda(n);
  for (unsigned int k = 0; k < n; ++k)
    lambda[k] = (k % 3 == 0 ? -1. : 1.) * (k + 1);
  auto build = [&](const bool clip) {
    FullMatrix<double> A(n, n);
    for (unsigned int k = 0; k < n; ++k)
      for (unsigned int i = 0; i < n; ++i)
        for (unsigned int j = 0; j < n; ++j)
          A(i, j) += (clip ? std::max(lambda[k], 0.) : lambda[k]) * Q(i, k) * Q(j, k);
    return A;
  };
  FullMatrix<double> A = build(false), expected = build(true);
  Contact::project_to_positive_semidefinite(A);
  A.add(-1., expected);
  const double error_indefinite = A.frobenius_norm() / expected.frobenius_norm();
  FullMatrix<double> B = expected;
  Contact::project_to_positive_semidefinite(B);
  B.add(-1., expected);
  const double error_definite = B.frobenius_norm() / expected.frobenius_norm();
  out << "projection: indefinite matrix -> positive part "
      << (error_indefinite < 1e-12 ? "ok" : "FAIL")
      << ", semidefinite matrix unchanged " << (error_definite < 1e-12 ? "ok" : "FAIL")
      << "\n";
  if (error_indefinite >= 1e-12 || error_definite >= 1e-12)
    std::cerr << "projection errors " << error_indefinite << " " << error_definite << "\n";

  // A matrix LAPACK cannot take must end in an error with a reason, never
  // in a silently wrong projection.
  FullMatrix<double> C = expected;
  C(2, 3)              = std::numeric_limits<double>::quiet_NaN();
  std::string reason;
  try
    {
      Contact::project_to_positive_semidefinite(C);
    }
  catch (const std::exception &e)
    {
      reason = e.what();
    }
  out << "projection of a non-finite matrix: "
      << (reason.empty() ? "no error (FAIL)" : "error: " + reason) << "\n";
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream                    out("output");
  check_projection(out);
  for (const bool integral : {false, true})
    {
      check<2>(1, integral, out);
      check<2>(2, integral, out);
      check<3>(1, integral, out);
    }
  for (const bool integral : {false, true})
    {
      check<2>(1, integral, out, 2);
      check<3>(1, integral, out, 2);
    }
}
