#include <signorini/contact/registry.h>
#include <signorini/contact/two_body.h>
#include <signorini/contact/two_pass.h>
#include <signorini/input_error.h>

#include <deal.II/base/geometry_info.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_templates.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/rtree.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace Signorini
{
  namespace Contact
  {

    void
    project_to_positive_semidefinite(FullMatrix<double> &H)
    {
      // LAPACK's dsyev (QR iteration on the tridiagonal form: every
      // eigenpair at once) with its INFO checked. deal.II's
      // compute_eigenvalues_symmetric calls dsyevx, which on failure prints
      // "LAPACK error in syevx" and returns eigenvectors that did not
      // converge (seen on SSNV104's pair Hessians).
      const types::blas_int n = H.m();
      std::vector<double>   a(n * n), lambda(n);
      for (types::blas_int i = 0; i < n; ++i)
        for (types::blas_int j = 0; j < n; ++j)
          {
            a[i + j * n] = 0.5 * (H(i, j) + H(j, i));
            if (!std::isfinite(a[i + j * n]))
              throw std::runtime_error(
                "a pair Hessian to be projected has a non-finite entry (" +
                std::to_string(i) + ", " + std::to_string(j) + ")");
          }
      const char      jobz = 'V', uplo = 'U';
      types::blas_int info = 0, lwork = -1;
      double          size = 0.;
      syev(&jobz, &uplo, &n, a.data(), &n, lambda.data(), &size, &lwork, &info);
      lwork = std::max<types::blas_int>(static_cast<types::blas_int>(size), 3 * n);
      std::vector<double> work(lwork);
      if (info == 0)
        syev(&jobz, &uplo, &n, a.data(), &n, lambda.data(), work.data(), &lwork, &info);
      if (info != 0)
        throw std::runtime_error(
          "LAPACK's symmetric eigensolver (dsyev) failed on a " + std::to_string(n) +
          " x " + std::to_string(n) + " pair Hessian: " +
          (info < 0 ? "argument " + std::to_string(-info) + " is invalid" :
                      std::to_string(info) + " off-diagonal entries of its "
                                             "tridiagonal form did not converge to zero"));
      for (types::blas_int k = 0; k < n; ++k)
        if (!std::isfinite(lambda[k]))
          throw std::runtime_error("LAPACK's symmetric eigensolver (dsyev) returned a "
                                   "non-finite eigenvalue for a pair Hessian");
      H = 0.;
      for (types::blas_int k = 0; k < n; ++k)
        if (lambda[k] > 0.)
          for (types::blas_int i = 0; i < n; ++i)
            for (types::blas_int j = 0; j < n; ++j)
              H(i, j) += lambda[k] * a[i + k * n] * a[j + k * n];
    }

    void
    TwoBodyParameters::declare_parameters(ParameterHandler &prm)
    {
      prm.declare_entry("Target boundary id",
                        "10",
                        Patterns::Integer(0, 255),
                        "The boundary id of body 2's potential contact "
                        "surface, whose indicator function Phi body 1's "
                        "'Contact boundary id' must keep at zero.");
      prm.declare_entry("Contact form",
                        "nodal",
                        Patterns::Selection("nodal|integral"),
                        "nodal: mu sum_i w_i Phi(x_i) over the support points "
                        "of body 1's contact boundary (w_i: tributary "
                        "length/area). integral: mu int_Gamma_C Phi(X + u) "
                        "ds with 'Gauss points per face' points per "
                        "direction on every face (reference configuration); "
                        "it also catches body 2 vertices that poke through "
                        "the middle of a body 1 face.");
      prm.declare_entry("Gauss points per face",
                        "2",
                        Patterns::Integer(1, 10),
                        "K: Gauss points per direction on each face of "
                        "Gamma_C for the integral form.");
      prm.declare_entry("Stretch",
                        "0.12",
                        Patterns::Double(0., 0.5),
                        "s: each face's simplex base is stretched by s times "
                        "its length beyond each end (3D: each triangle is "
                        "scaled by 1 + 2s), so that the simplices of "
                        "neighbouring faces overlap and Phi has no zero line "
                        "under shared vertices [-]; in (0, 0.5).");
      prm.declare_entry("End stretch",
                        "1",
                        Patterns::Double(0., 2.),
                        "The stretch at the free ends of the target surface "
                        "(2D: a vertex of one target face only, e.g. on a "
                        "symmetry line; 3D: the vertices of an edge of one "
                        "target face only), where no neighbouring simplex "
                        "overlaps: with the common stretch, Phi under such a "
                        "vertex is about 25 times weaker than mid-face and "
                        "vanishes below 0.2 of the cell depth [-].");
      prm.declare_entry("Indicator shape",
                        "partition",
                        Patterns::Selection("simplex|partition"),
                        "simplex: the poster's construction, a sum over body "
                        "2's faces of C^2 bumps on stretched simplices; along "
                        "a face it is about 12 times weaker under shared "
                        "vertices than mid-face at the same depth, which "
                        "fails the contact patch test. partition: over each "
                        "face a prism normal to it, g(depth / H) times a "
                        "weight that rises over [-s, s] (s = 'Stretch') at "
                        "each face end shared with a neighbour, so that the "
                        "weights sum to 1, and over [-s_end, 0] at a free "
                        "end ('End stretch'); g(eta) = 64 eta^3 (1 - eta)^3, "
                        "H the apex's height. On a flat surface of equal "
                        "faces Phi depends on the depth only "
                        "(doc/two_bodies.md, 'Contact patch test').");
      prm.declare_entry("Apex depth",
                        "1",
                        Patterns::Double(0., 1.),
                        "Apex rule: the simplex apex lies this fraction of "
                        "the way from the face's centroid to the centroid of "
                        "the cell's opposite face (1: on the opposite face) "
                        "[-]; in (0, 1]. Phi > 0 in a layer this deep.");
      prm.declare_entry("Search margin",
                        "1",
                        Patterns::Double(0.),
                        "The sparsity pattern holds the (point, face) pairs "
                        "whose face box grown by this many face sizes "
                        "contains the point; it is rebuilt when a pair with "
                        "Phi > 0 falls outside [-]; >= 0.");
      prm.declare_entry("Maximum motion",
                        "0.5",
                        Patterns::Double(0.),
                        "A Newton step moves no point of the contact "
                        "boundary and no vertex of body 2's contact faces by "
                        "more than this fraction of the thinnest layer where "
                        "Phi > 0 (a point that crosses the layer in one step "
                        "feels no force) [-]; > 0.");
      prm.declare_entry("Hessian",
                        "adaptive",
                        Patterns::Selection("adaptive|exact|projected"),
                        "The Hessian of each (point, face) term handed to "
                        "Newton. exact: the true second derivative; Phi is "
                        "a bump, so at large mu its negative curvature can "
                        "make the Hessian indefinite, and Newton then falls "
                        "back to diagonal shifts and steepest descent. "
                        "projected: each pair's matrix with its negative "
                        "eigenvalues set to zero (projected Newton): "
                        "positive semidefinite, so the Newton step is a "
                        "descent direction, but convergence near the "
                        "solution is only linear. adaptive: exact, and "
                        "projected for a Newton step whose exact Hessian "
                        "gives no descent direction. The gradient is exact "
                        "in every mode, so the solution is the same.");
      prm.declare_entry("Passes",
                        "one-pass",
                        Patterns::Selection("one-pass|two-pass"),
                        "one-pass: only body 1's contact boundary is kept "
                        "out of body 2 (the poster's evaluation): body 2 "
                        "receives the contact force as point loads at body "
                        "1's nodes, which fails the contact patch test with "
                        "the nodal form. two-pass: body 2's target boundary "
                        "is also kept out of body 1, through body 1's "
                        "indicator function on its contact boundary, in the "
                        "same form; each pass carries half of mu, so that mu "
                        "keeps its meaning (doc/two_bodies.md).");
    }

    void
    TwoBodyParameters::parse_parameters(ParameterHandler &prm)
    {
      target_boundary = prm.get_integer("Target boundary id");
      integral        = (prm.get("Contact form") == "integral");
      gauss_points    = prm.get_integer("Gauss points per face");
      stretch         = prm.get_double("Stretch");
      apex_depth      = prm.get_double("Apex depth");
      search_margin   = prm.get_double("Search margin");
      max_motion      = prm.get_double("Maximum motion");
      end_stretch     = prm.get_double("End stretch");
      shape           = (prm.get("Indicator shape") == "partition" ?
                           IndicatorShape::partition :
                           IndicatorShape::simplex);
      passes = (prm.get("Passes") == "two-pass" ? 2 : 1);
      const std::string hessian = prm.get("Hessian");
      hessian_mode = (hessian == "exact"     ? HessianMode::exact :
                      hessian == "projected" ? HessianMode::projected :
                                               HessianMode::adaptive);
      if (!(max_motion > 0.))
        throw InputError("Contact > Two bodies > Maximum motion",
                         "must be > 0, got " + prm.get("Maximum motion"));
      if (!(stretch > 0.))
        throw InputError("Contact > Two bodies > Stretch",
                         "must be > 0 (with 0 Phi vanishes under the shared "
                         "vertices), got " + prm.get("Stretch"));
      if (!(apex_depth > 0.))
        throw InputError("Contact > Two bodies > Apex depth",
                         "must be > 0, got " + prm.get("Apex depth"));
    }

    namespace
    {
      /// An edge of a body 2 face that no other face shares as a vertex
      /// pair: the face, the edge's first vertex and its ends (reference
      /// configuration).
      template <int dim>
      struct SingleEdge
      {
        unsigned int face, vertex;
        Point<dim>   a, b;
      };

      /// Whether p lies on the segment [a, b] (to round-off of its length).
      template <int dim>
      bool
      on_segment(const Point<dim> &p, const Point<dim> &a, const Point<dim> &b)
      {
        const Tensor<1, dim> ab = b - a;
        const double         l2 = ab.norm_square();
        const double         s  = ((p - a) * ab) / l2;
        if (s < -1e-10 || s > 1. + 1e-10)
          return false;
        return (p - (a + s * ab)).norm_square() <= 1e-20 * l2;
      }

      /// Whether the edge [p, q] is half of the edge [a, b] across a
      /// change of refinement level on a curved surface: it shares an end
      /// with it and its other end is the hanging vertex, which the
      /// manifold put on the surface, off the chord [a, b] by the arc's
      /// sag (3% of |ab| for a face of a quarter of the radius), near its
      /// midpoint.
      template <int dim>
      bool
      half_of(const Point<dim> &p,
              const Point<dim> &q,
              const Point<dim> &a,
              const Point<dim> &b)
      {
        const double     l2   = (b - a).norm_square();
        const Point<dim> mid  = 0.5 * (a + b);
        const auto       same = [l2](const Point<dim> &x, const Point<dim> &y) {
          return (x - y).norm_square() <= 1e-20 * l2;
        };
        const auto near_mid = [&](const Point<dim> &x) {
          return (x - mid).norm_square() <= 0.0625 * l2;
        };
        return ((same(p, a) || same(p, b)) && near_mid(q)) ||
               ((same(q, a) || same(q, b)) && near_mid(p));
      }

      /// For each edge of @p single that another face's edge of @p single
      /// continues (it lies along it, or is half of it across a change of
      /// refinement level): the indices of the edge and of the first such
      /// other edge.
      template <int dim>
      std::vector<std::pair<unsigned int, unsigned int>>
      continued_edges(const std::vector<SingleEdge<dim>> &single)
      {
        std::vector<std::pair<unsigned int, unsigned int>> continued;
        for (unsigned int i = 0; i < single.size(); ++i)
          for (unsigned int j = 0; j < single.size(); ++j)
            {
              const auto &e = single[i];
              const auto &o = single[j];
              if (o.face != e.face &&
                  ((on_segment(e.a, o.a, o.b) && on_segment(e.b, o.a, o.b)) ||
                   (on_segment(o.a, e.a, e.b) && on_segment(o.b, e.a, e.b)) ||
                   half_of(e.a, e.b, o.a, o.b) || half_of(o.a, o.b, e.a, e.b)))
                {
                  continued.emplace_back(i, j);
                  break;
                }
            }
        return continued;
      }
    } // namespace

    template <int dim>
    TwoBodyContact<dim>::TwoBodyContact(const TwoBodyParameters &parameters,
                                        const types::boundary_id contact_boundary,
                                        const DoFHandler<dim>   &dof_handler,
                                        const Mapping<dim>      &mapping)
      : prm(parameters)
      , contact_boundary(contact_boundary)
      , dof_handler(dof_handler)
      , mapping(mapping)
      , boundary(dof_handler, mapping)
      , target(dof_handler, mapping)
      , contact_ids{contact_boundary}
      , target_ids{parameters.target_boundary}
    {}

    template <int dim>
    void
    TwoBodyContact<dim>::setup(const AffineConstraints<double> &hanging_constraints,
                               const AffineConstraints<double> &constraints)
    {
      const MPI_Comm comm = dof_handler.get_communicator();
      relevant            = DoFTools::extract_locally_relevant_dofs(dof_handler);
      record_hanging.clear();
      record_hanging.copy_from(hanging_constraints);
      boundary.setup(contact_ids, hanging_constraints);
      // Self-contact and all bodies: the contact nodes carry every force
      // (no second record of the same nodes).
      target.setup(self ? std::set<types::boundary_id>() : target_ids, hanging_constraints);
      this->nodal_forces.assign((boundary.nodes().size() + target.nodes().size()) * dim,
                                0.);

      collect_points();
      gather_target_faces();
      mark_face_ends();
      check_boundaries();
      measure_faces();
      if (self && !all_bodies)
        {
          // Automatic radius: three of the largest faces, so that a point
          // skips the faces of its own neighbourhood.
          if (!(exclusion_radius_ > 0.))
            {
              double largest = 0.;
              for (const auto &f : faces2)
                largest = std::max(largest, f.h);
              exclusion_radius_ = 3. * largest;
            }
          find_excluded_faces();
          // For summary.json, which one rank writes: no collective there.
          unsigned long long skipped = 0;
          for (const auto &faces : skip_points)
            skipped += faces.size();
          skipped_per_point = static_cast<double>(Utilities::MPI::sum(skipped, comm)) /
                              std::max(1u, Utilities::MPI::sum(static_cast<unsigned int>(
                                                                 points.size()),
                                                               comm));
        }
      find_extra_rows(constraints);

      stats                = PairStatistics();
      stats.target_faces   = faces2.size();
      stats.points         = Utilities::MPI::sum(static_cast<unsigned int>(points.size()), comm);
      pattern.clear();
    }

    template <int dim>
    void
    TwoBodyContact<dim>::collect_points()
    {
      // Body 1's nodes as evaluation points (always: they carry the
      // output), and the Gauss points of the integral form.
      node_points.clear();
      // A node's body: the material of a cell whose contact face holds it
      // (bodies share no vertices).
      std::map<types::global_dof_index, types::material_id> body_of_dof;
      std::vector<types::global_dof_index>                   face_dofs;
      if (all_bodies)
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (!cell->is_artificial())
            for (const auto f : cell->face_indices())
              if (cell->face(f)->at_boundary() &&
                  contact_ids.count(cell->face(f)->boundary_id()) > 0)
                {
                  face_dofs.resize(dof_handler.get_fe().n_dofs_per_face(f));
                  cell->face(f)->get_dof_indices(face_dofs);
                  for (const auto dof : face_dofs)
                    body_of_dof[dof] = cell->material_id();
                }
      for (const auto &n : boundary.nodes())
        {
          Point1 p;
          if (all_bodies)
            {
              const auto it = body_of_dof.find(n.dofs[0]);
              AssertThrow(it != body_of_dof.end(),
                          ExcMessage("a contact node lies on no contact face this rank sees"));
              p.body = it->second;
            }
          for (unsigned int c = 0; c < dim; ++c)
            {
              p.dofs.push_back(n.dofs[c]);
              p.components.push_back(c);
              p.shape.push_back(1.);
            }
          p.X      = n.X;
          p.weight = n.weight;
          node_points.push_back(p);
        }
      if (!prm.integral)
        {
          points = node_points;
          return;
        }
      const auto &fe = dof_handler.get_fe();
      points.clear();
      FEFaceValues<dim> fe_face(mapping, fe, QGauss<dim - 1>(prm.gauss_points),
                                update_values | update_JxW_values |
                                  update_quadrature_points);
      std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const auto f : cell->face_indices())
            if (cell->face(f)->at_boundary() &&
                contact_ids.count(cell->face(f)->boundary_id()) > 0)
              {
                fe_face.reinit(cell, f);
                cell->get_dof_indices(dofs);
                for (unsigned int q = 0; q < fe_face.n_quadrature_points; ++q)
                  {
                    Point1 p;
                    for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
                      if (fe.has_support_on_face(i, f))
                        {
                          p.dofs.push_back(dofs[i]);
                          p.components.push_back(
                            fe.system_to_component_index(i).first);
                          p.shape.push_back(fe_face.shape_value(i, q));
                        }
                    p.X      = fe_face.quadrature_point(q);
                    p.weight = fe_face.JxW(q);
                    p.body   = cell->material_id();
                    points.push_back(p);
                  }
              }
    }

    template <int dim>
    void
    TwoBodyContact<dim>::gather_target_faces()
    {
      const MPI_Comm     comm = dof_handler.get_communicator();
      std::vector<Face2> owned_faces;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const auto f : cell->face_indices())
            if (cell->face(f)->at_boundary() &&
                target_ids.count(cell->face(f)->boundary_id()) > 0)
              {
                // Face vertices in cyclic order, then the opposite face's
                // vertices in the same order (vertex i of face f lies
                // opposite vertex i of the opposite face).
                const unsigned int fo = GeometryInfo<dim>::opposite_face[f];
                const std::array<unsigned int, 4> cyclic = {{0, 1, 3, 2}};
                Face2 face;
                face.h    = cell->face(f)->diameter();
                face.body = cell->material_id();
                for (unsigned int side = 0; side < 2; ++side)
                  for (unsigned int v = 0; v < n_face_vertices; ++v)
                    {
                      const unsigned int lv = (dim == 2 ? v : cyclic[v]);
                      const unsigned int cv = GeometryInfo<dim>::face_to_cell_vertices(
                        side == 0 ? f : fo, lv);
                      for (unsigned int c = 0; c < dim; ++c)
                        {
                          const unsigned int k = (side * n_face_vertices + v) * dim + c;
                          face.dofs[k] = cell->vertex_dof_index(cv, c);
                          face.X[k]    = cell->vertex(cv)[c];
                        }
                    }
                owned_faces.push_back(face);
              }
      const auto all_faces = Utilities::MPI::all_gather(comm, owned_faces);
      faces2.clear();
      const unsigned int rank = Utilities::MPI::this_mpi_process(comm);
      for (unsigned int r = 0; r < all_faces.size(); ++r)
        {
          if (r == rank)
            {
              first_owned_face = faces2.size();
              n_owned_faces    = all_faces[r].size();
            }
          faces2.insert(faces2.end(), all_faces[r].begin(), all_faces[r].end());
        }
    }

    template <int dim>
    void
    TwoBodyContact<dim>::mark_face_ends()
    {
      // Free ends: 2D vertices of one face, 3D vertices of edges of one
      // face (vertices are identified by their first DoF).
      std::map<std::vector<types::global_dof_index>, unsigned int> count;
      auto key = [&](const Face2 &f, const unsigned int v) {
        std::vector<types::global_dof_index> k = {f.dofs[v * dim]};
        if (dim == 3)
          {
            k.push_back(f.dofs[((v + 1) % n_face_vertices) * dim]);
            std::sort(k.begin(), k.end());
          }
        return k;
      };
      // The smallest face at each end (vertex in 2D, edge in 3D).
      std::map<std::vector<types::global_dof_index>, double> smallest;
      for (const auto &f : faces2)
        for (unsigned int v = 0; v < n_face_vertices; ++v)
          {
            const auto k = key(f, v);
            ++count[k];
            const auto [it, first] = smallest.try_emplace(k, f.h);
            if (!first)
              it->second = std::min(it->second, f.h);
          }
      // In 3D an edge of one face is not a free end if it lies along
      // edges of other faces: where the refinement level changes, a
      // coarse face's edge holds two fine faces' edges (with a hanging
      // vertex between them), none of them shared as a vertex pair, yet
      // the surface goes on across them. Such edges overlap another
      // face's edge in the reference configuration.
      std::set<std::pair<unsigned int, unsigned int>> continued;
      if (dim == 3)
        {
          std::vector<SingleEdge<dim>> single;
          for (unsigned int i = 0; i < faces2.size(); ++i)
            for (unsigned int v = 0; v < n_face_vertices; ++v)
              if (count[key(faces2[i], v)] == 1)
                {
                  SingleEdge<dim>    e{i, v, Point<dim>(), Point<dim>()};
                  const unsigned int w = (v + 1) % n_face_vertices;
                  for (unsigned int c = 0; c < dim; ++c)
                    {
                      e.a[c] = faces2[i].X[v * dim + c];
                      e.b[c] = faces2[i].X[w * dim + c];
                    }
                  single.push_back(e);
                }
          for (const auto &[i, j] : continued_edges(single))
            {
              const auto &e = single[i];
              continued.insert({e.face, e.vertex});
              // Across a change of refinement level the neighbour is the
              // other face along the edge.
              const auto k = key(faces2[e.face], e.vertex);
              smallest[k]  = std::min(smallest[k], faces2[single[j].face].h);
            }
        }
      for (unsigned int i = 0; i < faces2.size(); ++i)
        {
          auto &f = faces2[i];
          f.end_stretch.fill(-1.);
          f.free_end.fill(false);
          // The partition shape's ramp at a shared end spans s times the
          // smaller face's size on either side, so that the ramps of
          // faces of different sizes still sum to 1.
          for (unsigned int v = 0; v < n_face_vertices; ++v)
            f.ramp[v] = prm.stretch * std::min(1., smallest[key(f, v)] / f.h);
          for (unsigned int v = 0; v < n_face_vertices; ++v)
            if (count[key(f, v)] == 1 && continued.count({i, v}) == 0)
              {
                f.free_end[v]    = true;
                f.end_stretch[v] = prm.end_stretch;
                if (dim == 3)
                  f.end_stretch[(v + 1) % n_face_vertices] = prm.end_stretch;
              }
        }
    }

    template <int dim>
    void
    TwoBodyContact<dim>::check_boundaries() const
    {
      const MPI_Comm               comm = dof_handler.get_communicator();
      std::set<types::material_id> body1, body2;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const auto f : cell->face_indices())
            if (cell->face(f)->at_boundary())
              {
                if (contact_ids.count(cell->face(f)->boundary_id()) > 0)
                  body1.insert(cell->material_id());
                if (target_ids.count(cell->face(f)->boundary_id()) > 0)
                  body2.insert(cell->material_id());
              }
      std::vector<unsigned int> ids1(body1.begin(), body1.end()),
        ids2(body2.begin(), body2.end());
      std::set<unsigned int> all1, all2;
      for (const auto &part : Utilities::MPI::all_gather(comm, ids1))
        all1.insert(part.begin(), part.end());
      for (const auto &part : Utilities::MPI::all_gather(comm, ids2))
        all2.insert(part.begin(), part.end());
      if (all1.empty())
        throw InputError("Contact > Contact boundary id",
                         "boundary " + std::to_string(contact_boundary) +
                           " does not exist in the mesh");
      if (faces2.empty())
        throw InputError("Contact > Two bodies > Target boundary id",
                         "boundary " + std::to_string(prm.target_boundary) +
                           " does not exist in the mesh");
      if (all_bodies)
        {
          if (all1.size() < 2)
            throw InputError("Contact > Pairs > Contact boundaries",
                             "'Two-body pairs = all' needs contact boundaries on "
                             "at least two bodies; these lie on one");
          return;
        }
      if (self)
        {
          if (contact_boundary != prm.target_boundary)
            throw InputError("Contact > Pairs > Self-contact boundary ids",
                             "self-contact keeps one boundary out of its own "
                             "body: its target must be the same boundary");
          return;
        }
      for (const auto id : all1)
        if (all2.count(id) > 0)
          throw InputError("Contact > Two bodies > Target boundary id",
                           "boundaries " + std::to_string(contact_boundary) +
                             " and " + std::to_string(prm.target_boundary) +
                             " both lie on the body with material id " +
                             std::to_string(id) +
                             ": the contact boundary and the target surface "
                             "must belong to different bodies");
    }

    template <int dim>
    void
    TwoBodyContact<dim>::measure_faces()
    {
      min_face_size  = std::numeric_limits<double>::max();
      mean_face_size = 0.;
      min_layer      = std::numeric_limits<double>::max();
      for (const auto &f : faces2)
        {
          min_face_size = std::min(min_face_size, f.h);
          mean_face_size += f.h / faces2.size();
          // Distance between the face's and the opposite face's centroids.
          Tensor<1, dim> offset;
          for (unsigned int v = 0; v < n_face_vertices; ++v)
            for (unsigned int c = 0; c < dim; ++c)
              offset[c] += (f.X[(n_face_vertices + v) * dim + c] - f.X[v * dim + c]) /
                           n_face_vertices;
          min_layer = std::min(min_layer, prm.apex_depth * offset.norm());
        }
    }

    template <int dim>
    void
    TwoBodyContact<dim>::find_extra_rows(const AffineConstraints<double> &constraints)
    {
      // Rows this rank's pairs may write to: body 2's face DoFs and the
      // DoFs their constraints refer to.
      const MPI_Comm                       comm = dof_handler.get_communicator();
      std::vector<types::global_dof_index> rows;
      for (unsigned int i = first_owned_face; i < first_owned_face + n_owned_faces; ++i)
        for (const auto dof : faces2[i].dofs)
          {
            rows.push_back(dof);
            if (const auto *entries = constraints.get_constraint_entries(dof))
              for (const auto &e : *entries)
                rows.push_back(e.first);
          }
      extra_rows = IndexSet(dof_handler.n_dofs());
      for (const auto &part : Utilities::MPI::all_gather(comm, rows))
        {
          std::vector<types::global_dof_index> sorted(part);
          std::sort(sorted.begin(), sorted.end());
          sorted.erase(std::unique(sorted.begin(), sorted.end()), sorted.end());
          extra_rows.add_indices(sorted.begin(), sorted.end());
        }
      extra_rows.compress();
    }

    template <int dim>
    Point<dim>
    TwoBodyContact<dim>::position(const Point1 &p, const VectorType &u) const
    {
      Point<dim> x = p.X;
      for (unsigned int j = 0; j < p.dofs.size(); ++j)
        x[p.components[j]] += p.shape[j] * u[p.dofs[j]];
      return x;
    }

    template <int dim>
    const AffineConstraints<double> &
    TwoBodyContact<dim>::assembly_constraints(const AffineConstraints<double> &constraints) const
    {
      const MPI_Comm comm = dof_handler.get_communicator();
      if (Utilities::MPI::n_mpi_processes(comm) == 1)
        return constraints;
      // The owner of a body 2 face knows the constraint lines of its DoFs;
      // send them to every rank. A line: index, inhomogeneity, n entries,
      // then (column, value) pairs, all as doubles (DoF indices < 2^53).
      std::vector<double> lines;
      for (unsigned int i = first_owned_face; i < first_owned_face + n_owned_faces; ++i)
        for (const auto dof : faces2[i].dofs)
          if (const auto *entries = constraints.get_constraint_entries(dof))
            {
              lines.push_back(dof);
              lines.push_back(constraints.get_inhomogeneity(dof));
              lines.push_back(entries->size());
              for (const auto &e : *entries)
                {
                  lines.push_back(e.first);
                  lines.push_back(e.second);
                }
            }
      IndexSet local_lines = relevant;
      local_lines.add_indices(extra_rows);
      merged.clear();
      merged.reinit(local_lines);
      merged.merge(constraints,
                   AffineConstraints<double>::MergeConflictBehavior::no_conflicts_allowed,
                   true);
      for (const auto &part : Utilities::MPI::all_gather(comm, lines))
        for (std::size_t k = 0; k < part.size();)
          {
            const auto   dof = static_cast<types::global_dof_index>(part[k]);
            const double b   = part[k + 1];
            const auto   n   = static_cast<std::size_t>(part[k + 2]);
            k += 3;
            const bool known = merged.is_constrained(dof);
            if (!known)
              {
                merged.add_line(dof);
                merged.set_inhomogeneity(dof, b);
              }
            for (std::size_t e = 0; e < n; ++e, k += 2)
              if (!known)
                merged.add_entry(dof, static_cast<types::global_dof_index>(part[k]),
                                 part[k + 1]);
          }
      merged.close();
      return merged;
    }

    template <int dim>
    double
    TwoBodyContact<dim>::add_penalty(const VectorType                &u,
                                     const double                     mu,
                                     const AffineConstraints<double> &constraints,
                                     VectorType                      *rhs,
                                     MatrixType                      *hessian,
                                     std::vector<double>             *forces) const
    {
      const MPI_Comm comm  = dof_handler.get_communicator();
      const auto     faces = current_faces(u);
      const auto     pairs = find_pairs(points, u, faces, 0., false);
      const AffineConstraints<double> &c =
        (rhs || hessian) ? assembly_constraints(constraints) : constraints;
      VectorType force_vector;
      IndexSet   writable;
      if (forces)
        {
          // Body 2's DoFs of a pair may be owned elsewhere (extra_rows).
          IndexSet ghosts = relevant;
          ghosts.add_indices(extra_rows);
          force_vector.reinit(dof_handler.locally_owned_dofs(), ghosts, comm, true);
          writable = ghosts;
          writable.add_indices(dof_handler.locally_owned_dofs());
        }
      // The record's share @p value of DoF @p dof: on the DoFs it follows
      // if it hangs (the nodes of the record are not hanging), so that the
      // record's sums are the forces' (a locally refined target).
      const auto record = [&](const types::global_dof_index dof, const double value) {
        if (record_hanging.is_constrained(dof))
          {
            const auto &entries = *record_hanging.get_constraint_entries(dof);
            bool        known   = true;
            for (const auto &e : entries)
              known = known && writable.is_element(e.first);
            if (known)
              {
                for (const auto &e : entries)
                  force_vector(e.first) += e.second * value;
                return;
              }
          }
        force_vector(dof) += value;
      };

      std::string            projection_failure; // the first on this rank
      constexpr unsigned int n_variables = IndicatorFace<dim>::n_variables;
      Vector<double>         g(n_variables);
      FullMatrix<double>     H(n_variables, n_variables);
      // The local matrices and vectors of the pairs of one evaluation
      // point's group (the points of one face of body 1: they share its
      // DoFs) with one target face are summed before they go into the
      // matrix, one insertion per (face, target face) instead of one per
      // point: in 3D each insertion writes 36 x 36 entries through
      // Epetra's global-to-local lookups. A group of one pair (every pair
      // of the nodal form) is inserted as it is.
      struct Open
      {
        unsigned int                         face;
        std::vector<types::global_dof_index> dofs;
        Vector<double>                       rhs;
        FullMatrix<double>                   matrix;
        unsigned int                         n_pairs;
      };
      std::vector<Open>  open;   // the current group's, by first appearance
      const Point1      *group = nullptr;
      const auto         flush = [&]() {
        for (auto &o : open)
          if (rhs && hessian)
            c.distribute_local_to_global(o.matrix, o.rhs, o.dofs, *hessian, *rhs);
          else if (rhs)
            c.distribute_local_to_global(o.rhs, o.dofs, *rhs);
          else
            c.distribute_local_to_global(o.matrix, o.dofs, *hessian);
        open.clear();
      };
      double value = 0.;
      for (const auto &pair : pairs)
        {
          const Point1             &p    = points[pair.first];
          const IndicatorFace<dim> &face = faces[pair.second];
          const Point<dim>          x    = position(p, u);
          const double phi = face.value(x, prm.stretch, prm.apex_depth);
          if (!(phi > 0.))
            continue;
          const double scale = mu * p.weight;
          value += scale * phi;
          if (!rhs && !hessian && !forces)
            continue;
          face.derivatives(x, prm.stretch, g, H, prm.apex_depth);
          if (hessian && (prm.hessian_mode == TwoBodyParameters::HessianMode::projected ||
                          convexified))
            try
              {
                project_to_positive_semidefinite(H);
              }
            catch (const std::exception &e)
              {
                // Every rank must reach the collective check below.
                if (projection_failure.empty())
                  projection_failure = e.what();
                H = 0.;
              }
          const unsigned int n1 = p.dofs.size();
          const unsigned int n  = n1 + n_target_dofs;
          // Local DoF j -> kernel variable var[j] with factor fac[j].
          std::vector<unsigned int> var(n);
          std::vector<double>       fac(n, 1.);
          for (unsigned int j = 0; j < n1; ++j)
            {
              var[j] = p.components[j];
              fac[j] = p.shape[j];
            }
          for (unsigned int j = 0; j < n_target_dofs; ++j)
            var[n1 + j] = dim + j;
          if (forces)
            {
              for (unsigned int j = 0; j < n1; ++j)
                record(p.dofs[j], -scale * fac[j] * g(var[j]));
              // The reaction on body 2's vertices; lumped, the share of the
              // opposite face's vertices goes to the face's own (the vertex
              // of the same position in the face).
              for (unsigned int j = 0; j < n_target_dofs; ++j)
                record(faces2[pair.second].dofs[lumped_reaction ? j % (n_target_dofs / 2) : j],
                       -scale * g(dim + j));
            }
          if (!rhs && !hessian)
            continue;
          if (group == nullptr || group->dofs != p.dofs)
            {
              flush();
              group = &p;
            }
          auto o = std::find_if(open.begin(), open.end(), [&](const Open &x) {
            return x.face == pair.second;
          });
          if (o == open.end())
            {
              Open fresh;
              fresh.face = pair.second;
              fresh.dofs.assign(p.dofs.begin(), p.dofs.end());
              fresh.dofs.insert(fresh.dofs.end(), faces2[pair.second].dofs.begin(),
                                faces2[pair.second].dofs.end());
              fresh.rhs.reinit(n);
              fresh.matrix.reinit(n, n);
              fresh.n_pairs = 0;
              open.push_back(std::move(fresh));
              o = open.end() - 1;
            }
          // The first pair's values are copied, later ones added.
          const bool first = o->n_pairs++ == 0;
          for (unsigned int i = 0; i < n; ++i)
            {
              const double r = -scale * fac[i] * g(var[i]);
              o->rhs(i)      = first ? r : o->rhs(i) + r;
              for (unsigned int j = 0; j < n; ++j)
                {
                  const double m = scale * fac[i] * fac[j] * H(var[i], var[j]);
                  o->matrix(i, j) = first ? m : o->matrix(i, j) + m;
                }
            }
        }
      flush();
      if (rhs)
        rhs->compress(VectorOperation::add);
      if (hessian)
        hessian->compress(VectorOperation::add);
      if (forces)
        {
          force_vector.compress(VectorOperation::add);
          const std::size_t n1 = nodes().size();
          forces->assign((n1 + target.nodes().size()) * dim, 0.);
          for (unsigned int k = 0; k < n1; ++k)
            for (unsigned int d = 0; d < dim; ++d)
              (*forces)[k * dim + d] = force_vector(nodes()[k].dofs[d]);
          for (unsigned int k = 0; k < target.nodes().size(); ++k)
            for (unsigned int d = 0; d < dim; ++d)
              (*forces)[(n1 + k) * dim + d] = force_vector(target.nodes()[k].dofs[d]);
        }
      stats.last_pairs =
        Utilities::MPI::sum(static_cast<unsigned long long>(pairs.size()), comm);
      stats.max_pairs = std::max(stats.max_pairs, stats.last_pairs);
      // A failed projection is an error on every rank, never a silently
      // wrong Hessian.
      if (Utilities::MPI::logical_or(!projection_failure.empty(), comm))
        for (const auto &reason : Utilities::MPI::all_gather(comm, projection_failure))
          if (!reason.empty())
            throw SolveFailure("two-body contact: " + reason);
      return Utilities::MPI::sum(value, comm);
    }

    template class TwoBodyContact<2>;
    template class TwoBodyContact<3>;

    ModelEntry
    two_body_model()
    {
      ModelEntry entry;
      entry.name = "two bodies";
      entry.help = "two bodies: the boundary 'Contact boundary id' of body 1 must stay out "
                   "of body 2, whose surface is the Two bodies subsection's 'Target "
                   "boundary id' (smooth indicator function, penalty; Method = "
                   "newton-penalty).";
      // The indicator constraint Phi = 0 has a zero gradient on the
      // surface: no node-wise constraints for Ipopt or the interior point
      // method.
      entry.capabilities.node_wise_constraints = false;
      entry.capabilities.bodies                = 2;
      entry.declare_parameters                 = [](ParameterHandler &prm) {
        prm.enter_subsection("Two bodies");
        TwoBodyParameters::declare_parameters(prm);
        prm.leave_subsection();
      };
      entry.parse_parameters = [](ParameterHandler &prm, const unsigned int) {
        TwoBodyParameters parameters;
        prm.enter_subsection("Two bodies");
        parameters.parse_parameters(prm);
        prm.leave_subsection();
        return std::make_shared<const ParsedParameters<TwoBodyParameters>>(
          std::move(parameters));
      };
      entry.boundary_ids = [](const ModelParameters &parameters) {
        return std::vector<NamedBoundaryId>{
          {"Two bodies > Target boundary id",
           parsed<TwoBodyParameters>(parameters).target_boundary}};
      };
      entry.set_create([](const ModelParameters   &parameters,
                          const types::boundary_id boundary_id,
                          const auto              &dof_handler,
                          const auto              &mapping) {
        constexpr int dim = std::decay_t<decltype(dof_handler)>::dimension;
        const auto   &prm = parsed<TwoBodyParameters>(parameters);
        if (prm.passes == 2)
          return std::unique_ptr<Model<dim>>(
            std::make_unique<TwoPassContact<dim>>(prm, boundary_id, dof_handler, mapping));
        return std::unique_ptr<Model<dim>>(
          std::make_unique<TwoBodyContact<dim>>(prm, boundary_id, dof_handler, mapping));
      });
      return entry;
    }
  } // namespace Contact
} // namespace Signorini
