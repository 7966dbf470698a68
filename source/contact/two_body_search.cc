#include <signorini/contact/two_body.h>
#include <signorini/input_error.h>

#include <deal.II/base/geometry_info.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/rtree.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <set>

// TwoBodyContact: geometric search (the current target faces, their R-tree,
// the point-face pairs, the sparsity couplings) and the safeguards built on
// it (admissibility, step limit, penetration).

namespace Signorini
{
  namespace Contact
  {
    namespace bgi = boost::geometry::index;

    namespace
    {
      /// Adds the wall time of its scope to @p total (the search's share of
      /// the contact terms, for summary.json).
      struct SearchClock
      {
        explicit SearchClock(double &total)
          : total(total)
          , start(std::chrono::steady_clock::now())
        {}
        ~SearchClock()
        {
          total += std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
                     .count();
        }
        double                                            &total;
        const std::chrono::steady_clock::time_point start;
      };
    } // namespace

    template <int dim>
    std::vector<IndicatorFace<dim>>
    TwoBodyContact<dim>::current_faces(const VectorType &u) const
    {
      const SearchClock   clock(stats.search_seconds);
      const MPI_Comm      comm = dof_handler.get_communicator();
      std::vector<double> local;
      local.reserve(n_owned_faces * n_target_dofs);
      for (unsigned int i = first_owned_face; i < first_owned_face + n_owned_faces; ++i)
        for (unsigned int k = 0; k < n_target_dofs; ++k)
          local.push_back(faces2[i].X[k] + u[faces2[i].dofs[k]]);
      std::vector<double> all;
      if (Utilities::MPI::n_mpi_processes(comm) == 1)
        all = std::move(local);
      else
        for (const auto &part : Utilities::MPI::all_gather(comm, local))
          all.insert(all.end(), part.begin(), part.end());
      std::vector<IndicatorFace<dim>> faces(faces2.size());
      for (unsigned int i = 0; i < faces.size(); ++i)
        {
          faces[i].end_stretch = faces2[i].end_stretch;
          faces[i].free_end    = faces2[i].free_end;
          faces[i].ramp        = faces2[i].ramp;
          faces[i].shape       = prm.shape;
        }
      for (unsigned int i = 0; i < faces.size(); ++i)
        for (unsigned int v = 0; v < n_face_vertices; ++v)
          for (unsigned int c = 0; c < dim; ++c)
            {
              faces[i].face[v][c] = all[i * n_target_dofs + v * dim + c];
              faces[i].opposite[v][c] =
                all[i * n_target_dofs + (n_face_vertices + v) * dim + c];
            }
      return faces;
    }

    template <int dim>
    typename TwoBodyContact<dim>::FaceTree
    TwoBodyContact<dim>::face_tree(const std::vector<IndicatorFace<dim>> &faces,
                                   const double                           margin) const
    {
      const SearchClock clock(stats.search_seconds);
      std::vector<std::pair<BoundingBox<dim>, unsigned int>> boxes;
      boxes.reserve(faces.size());
      for (unsigned int i = 0; i < faces.size(); ++i)
        {
          BoundingBox<dim> box = faces[i].bounding_box(prm.stretch, prm.apex_depth);
          if (margin > 0.)
            box.extend(margin * faces2[i].h);
          boxes.emplace_back(box, i);
        }
      return pack_rtree(boxes);
    }

    template <int dim>
    std::vector<Point<dim>>
    TwoBodyContact<dim>::node_positions(const VectorType &u) const
    {
      std::vector<Point<dim>> x;
      x.reserve(node_points.size());
      for (const auto &p : node_points)
        x.push_back(position(p, u));
      return x;
    }

    template <int dim>
    void
    TwoBodyContact<dim>::candidate_faces(
      const FaceTree                                         &tree,
      const Point<dim>                                       &x,
      const std::vector<Point1>                              &list,
      const unsigned int                                      k,
      std::vector<std::pair<BoundingBox<dim>, unsigned int>> &hits) const
    {
      hits.clear();
      {
        const SearchClock clock(stats.search_seconds);
        tree.query(bgi::intersects(x), std::back_inserter(hits));
      }
      if (self)
        hits.erase(std::remove_if(hits.begin(), hits.end(),
                                  [&](const auto &hit) { return skips(list, k, hit.second); }),
                   hits.end());
    }

    template <int dim>
    std::vector<std::pair<unsigned int, unsigned int>>
    TwoBodyContact<dim>::find_pairs(const std::vector<Point1>             &pts,
                                    const VectorType                      &u,
                                    const std::vector<IndicatorFace<dim>> &faces,
                                    const double                           margin,
                                    const bool positive_only) const
    {
      const auto tree = face_tree(faces, margin);
      std::vector<std::pair<unsigned int, unsigned int>>     pairs;
      std::vector<std::pair<BoundingBox<dim>, unsigned int>> hits;
      for (unsigned int k = 0; k < pts.size(); ++k)
        {
          const Point<dim> x = position(pts[k], u);
          candidate_faces(tree, x, pts, k, hits);
          for (const auto &hit : hits)
            if (!positive_only || faces[hit.second].value(x, prm.stretch, prm.apex_depth) > 0.)
              pairs.emplace_back(k, hit.second);
        }
      return pairs;
    }

    namespace
    {
      /// The closest point of the face @p face to @p x: its vertex weights
      /// and body 2's outward normal there. Returns the distance.
      double
      closest_point(const IndicatorFace<2> &face,
                    const Point<2>         &x,
                    std::array<double, 2>  &shape,
                    Tensor<1, 2>           &normal)
      {
        const Tensor<1, 2> e  = face.face[1] - face.face[0];
        const double       t  = std::clamp((x - face.face[0]) * e / e.norm_square(), 0., 1.);
        shape                 = {{1. - t, t}};
        normal                = Tensor<1, 2>({-e[1], e[0]}) / e.norm();
        return (x - (face.face[0] + t * e)).norm();
      }

      double
      closest_point(const IndicatorFace<3> &face,
                    const Point<3>         &x,
                    std::array<double, 4>  &shape,
                    Tensor<1, 3>           &normal)
      {
        // The bilinear face X(a, b) through the cyclic vertices Q0..Q3;
        // Gauss-Newton on |X - x|^2 with (a, b) kept in the unit square.
        const auto &Q = face.face;
        double      a = 0.5, b = 0.5;
        Tensor<1, 3> Xa, Xb;
        for (unsigned int it = 0; it < 8; ++it)
          {
            const Point<3> X = (1 - a) * (1 - b) * Q[0] + a * (1 - b) * Q[1] +
                               a * b * Q[2] + (1 - a) * b * Q[3];
            Xa = (1 - b) * (Q[1] - Q[0]) + b * (Q[2] - Q[3]);
            Xb = (1 - a) * (Q[3] - Q[0]) + a * (Q[2] - Q[1]);
            const Tensor<1, 3> r   = x - X;
            const double       A11 = Xa * Xa, A12 = Xa * Xb, A22 = Xb * Xb;
            const double       det = A11 * A22 - A12 * A12;
            if (!(det > 0.))
              break;
            const double da = (A22 * (Xa * r) - A12 * (Xb * r)) / det;
            const double db = (A11 * (Xb * r) - A12 * (Xa * r)) / det;
            a               = std::clamp(a + da, 0., 1.);
            b               = std::clamp(b + db, 0., 1.);
            if (std::abs(da) + std::abs(db) < 1e-12)
              break;
          }
        shape = {{(1 - a) * (1 - b), a * (1 - b), a * b, (1 - a) * b}};
        Xa    = (1 - b) * (Q[1] - Q[0]) + b * (Q[2] - Q[3]);
        Xb    = (1 - a) * (Q[3] - Q[0]) + a * (Q[2] - Q[1]);
        normal = cross_product_3d(Xa, Xb);
        normal /= normal.norm();
        Point<3> X;
        for (unsigned int v = 0; v < 4; ++v)
          X += shape[v] * Q[v];
        return (x - X).norm();
      }
    } // namespace

    template <int dim>
    std::vector<typename TwoBodyContact<dim>::Partner>
    TwoBodyContact<dim>::node_partners(const VectorType                      &u,
                                       const std::vector<IndicatorFace<dim>> &faces) const
    {
      const auto vertex_normals = this->vertex_normals(faces);
      const auto tree = face_tree(faces, 1.);
      std::vector<Partner>                                   partners(node_points.size());
      std::vector<std::pair<BoundingBox<dim>, unsigned int>> hits;
      for (unsigned int k = 0; k < node_points.size(); ++k)
        {
          const Point<dim> x = position(node_points[k], u);
          candidate_faces(tree, x, node_points, k, hits);
          double best = std::numeric_limits<double>::infinity();
          for (const auto &hit : hits)
            {
              Partner        p;
              Tensor<1, dim> face_normal;
              const double   d = closest_point(faces[hit.second], x, p.shape, face_normal);
              if (d < best)
                {
                  best   = d;
                  p.face = hit.second;
                  partners[k] = p;
                }
            }
          // The normal interpolated from the vertex normals.
          Partner &p = partners[k];
          if (p.face >= 0)
            {
              for (unsigned int v = 0; v < n_face_vertices; ++v)
                p.normal += p.shape[v] * vertex_normals.at(faces2[p.face].dofs[v * dim]);
              p.normal /= p.normal.norm();
            }
        }
      return partners;
    }

    template <int dim>
    std::map<types::global_dof_index, Tensor<1, dim>>
    TwoBodyContact<dim>::vertex_normals(const std::vector<IndicatorFace<dim>> &faces) const
    {
      // (Continuous normals: a node over a vertex would otherwise take one
      // face's normal or the other's from one outer iteration to the next.)
      std::map<types::global_dof_index, Tensor<1, dim>> vertex_normals;
      for (unsigned int f = 0; f < faces.size(); ++f)
        {
          std::array<double, n_face_vertices> shape;
          Tensor<1, dim>                      n;
          Point<dim>                          centre;
          for (unsigned int v = 0; v < n_face_vertices; ++v)
            centre += faces[f].face[v] / static_cast<double>(n_face_vertices);
          closest_point(faces[f], centre, shape, n);
          Tensor<1, dim> inward;
          for (unsigned int v = 0; v < n_face_vertices; ++v)
            inward += faces[f].opposite[v] - faces[f].face[v];
          if (n * inward > 0.)
            n = -n;
          for (unsigned int v = 0; v < n_face_vertices; ++v)
            vertex_normals[faces2[f].dofs[v * dim]] += faces2[f].h * n;
        }
      return vertex_normals;
    }

    template <int dim>
    Tensor<1, dim>
    TwoBodyContact<dim>::partner_displacement(const std::vector<IndicatorFace<dim>> &faces,
                                              const Partner &partner) const
    {
      Tensor<1, dim> d;
      if (partner.face < 0)
        return d;
      const auto &reference = faces2[partner.face].X;
      const auto &current   = faces[partner.face].face;
      for (unsigned int v = 0; v < n_face_vertices; ++v)
        for (unsigned int c = 0; c < dim; ++c)
          d[c] += partner.shape[v] * (current[v][c] - reference[v * dim + c]);
      return d;
    }

    template <int dim>
    void
    TwoBodyContact<dim>::add_sparsity(TrilinosWrappers::SparsityPattern &sparsity,
                                      const AffineConstraints<double>   &constraints,
                                      const VectorType                  &u)
    {
      const auto faces = current_faces(u);
      const auto pairs = find_pairs(points, u, faces, prm.search_margin, false);
      const AffineConstraints<double> &c = assembly_constraints(constraints);
      pattern.clear();
      std::vector<types::global_dof_index> dofs;
      for (const auto &pair : pairs)
        {
          pattern.insert(pair);
          const Point1 &p = points[pair.first];
          dofs.assign(p.dofs.begin(), p.dofs.end());
          dofs.insert(dofs.end(), faces2[pair.second].dofs.begin(),
                      faces2[pair.second].dofs.end());
          c.add_entries_local_to_global(dofs, sparsity, false);
        }
      node_pattern.clear();
      for (const auto &coupling : node_couplings)
        {
          node_pattern.insert(coupling);
          dofs.assign(nodes()[coupling.first].dofs.begin(),
                      nodes()[coupling.first].dofs.end());
          dofs.insert(dofs.end(), faces2[coupling.second].dofs.begin(),
                      faces2[coupling.second].dofs.begin() + n_face_vertices * dim);
          c.add_entries_local_to_global(dofs, sparsity, false);
        }
      stats.pattern_pairs = Utilities::MPI::sum(
        static_cast<unsigned long long>(pattern.size()), dof_handler.get_communicator());
      ++stats.pattern_builds;
    }

    template <int dim>
    bool
    TwoBodyContact<dim>::needs_new_pattern(const VectorType &u)
    {
      const auto faces = current_faces(u);
      bool       missing = false;
      for (const auto &pair : find_pairs(points, u, faces, 0., true))
        if (pattern.count(pair) == 0)
          {
            missing = true;
            break;
          }
      for (const auto &coupling : node_couplings)
        if (node_pattern.count(coupling) == 0)
          missing = true;
      return Utilities::MPI::logical_or(missing, dof_handler.get_communicator());
    }

    template <int dim>
    bool
    TwoBodyContact<dim>::admissible(const VectorType &u) const
    {
      const auto faces = current_faces(u);
      const auto tree = face_tree(faces, 0.);
      std::vector<std::pair<BoundingBox<dim>, unsigned int>> hits;
      bool                                                   ok = true;
      std::vector<double> values; // Phi of each hit face term
      for (const auto *list : {&node_points, &points})
        for (unsigned int k = 0; k < list->size(); ++k)
          {
            const Point<dim> x = position((*list)[k], u);
            candidate_faces(tree, x, *list, k, hits);
            // The crest is judged along the inward direction of the face of
            // the point's cell that it lies below, the nearest one where a
            // cell has several faces on the target (a corner of the
            // target surface: the die's arc meeting its side).
            bool           inside = false;
            double         phi    = 0.;
            double         nearest = std::numeric_limits<double>::infinity();
            Tensor<1, dim> inward;
            values.clear();
            for (const auto &hit : hits)
              {
                const auto &face = faces[hit.second];
                if (face.in_cell(x))
                  {
                    const double d  = face.depth(x, prm.stretch, prm.apex_depth);
                    const double by = (d >= 0. ? d : std::numeric_limits<double>::max());
                    if (!inside || by < nearest)
                      {
                        inward = Tensor<1, dim>();
                        for (unsigned int v = 0; v < n_face_vertices; ++v)
                          inward += face.opposite[v] - face.face[v];
                        nearest = by;
                      }
                    inside = true;
                  }
                values.push_back(face.value(x, prm.stretch, prm.apex_depth));
                phi += values.back();
              }
            if (!inside)
              continue;
            if (!(phi > 0.))
              {
                ok = false;
                break;
              }
            // Past the crest of Phi, the penalty force -mu grad Phi pushes
            // the point deeper (it would tunnel through the layer as mu
            // grows): such a state is not one the model represents.
            Tensor<1, dim> gradient;
            for (unsigned int k = 0; k < hits.size(); ++k)
              if (values[k] > 0.)
                gradient += faces[hits[k].second].point_gradient(x, prm.stretch, prm.apex_depth);
            if (gradient * inward < 0.)
              {
                ok = false;
                break;
              }
          }
      return !Utilities::MPI::logical_or(!ok, dof_handler.get_communicator());
    }

    template <int dim>
    double
    TwoBodyContact<dim>::max_step(const VectorType &u, const VectorType &d) const
    {
      VectorType direction;
      direction.reinit(u, true);
      direction = d;
      double largest = 0.;
      for (const auto &p : points)
        {
          Tensor<1, dim> motion;
          for (unsigned int j = 0; j < p.dofs.size(); ++j)
            motion[p.components[j]] += p.shape[j] * direction[p.dofs[j]];
          largest = std::max(largest, motion.norm());
        }
      for (unsigned int i = first_owned_face; i < first_owned_face + n_owned_faces; ++i)
        for (unsigned int v = 0; v < 2 * n_face_vertices; ++v)
          {
            Tensor<1, dim> motion;
            for (unsigned int c = 0; c < dim; ++c)
              motion[c] = direction[faces2[i].dofs[v * dim + c]];
            largest = std::max(largest, motion.norm());
          }
      largest = Utilities::MPI::max(largest, dof_handler.get_communicator());
      const double allowed = prm.max_motion * min_layer;
      return largest > allowed ? allowed / largest :
                                 std::numeric_limits<double>::infinity();
    }

    template <int dim>
    double
    TwoBodyContact<dim>::penetration_ratio(const std::vector<Point<dim>>         &x,
                                           const std::vector<Point1>             &list,
                                           const std::vector<IndicatorFace<dim>> &faces,
                                           std::vector<double> *depths) const
    {
      const auto tree = face_tree(faces, 0.);
      double     worst = 0.;
      std::vector<std::pair<BoundingBox<dim>, unsigned int>> hits;
      if (depths)
        depths->assign(x.size(), 0.);
      for (unsigned int k = 0; k < x.size(); ++k)
        {
          candidate_faces(tree, x[k], list, k, hits);
          // A point penetrates only inside one of the target's cells (its
          // depth is still the smallest below any face that sees it): the
          // layer of a face reaches past the face's ends (its ramp or its
          // stretched simplices), which at a convex corner of the target
          // surface lies outside the body; there Phi -> 0 as mu grows and
          // the depth below the face's line would never fall.
          double depth = -1., h = 1.;
          bool   inside = false;
          for (const auto &hit : hits)
            {
              const auto  &face = faces[hit.second];
              const double d    = face.depth(x[k], prm.stretch, prm.apex_depth);
              if (d >= 0. && (depth < 0. || d < depth))
                {
                  depth = d;
                  h     = faces2[hit.second].h;
                }
              inside = inside || face.in_cell(x[k]);
            }
          if (depth > 0. && inside)
            {
              worst = std::max(worst, depth / h);
              if (depths)
                (*depths)[k] = depth;
            }
        }
      return worst;
    }

    template <int dim>
    void
    TwoBodyContact<dim>::find_excluded_faces()
    {
      skip_points.clear();
      skip_nodes.clear();
      if (!self)
        return;
      // The boxes of the face terms' vertices in the reference
      // configuration, grown by the radius: a point inside a box may lie
      // within the radius of one of its vertices.
      std::vector<std::pair<BoundingBox<dim>, unsigned int>> boxes;
      for (unsigned int i = 0; i < faces2.size(); ++i)
        {
          std::vector<Point<dim>> vertices(2 * n_face_vertices);
          for (unsigned int v = 0; v < 2 * n_face_vertices; ++v)
            for (unsigned int c = 0; c < dim; ++c)
              vertices[v][c] = faces2[i].X[v * dim + c];
          BoundingBox<dim> box(vertices);
          box.extend(exclusion_radius_);
          boxes.emplace_back(box, i);
        }
      const auto tree = pack_rtree(boxes);
      std::vector<std::pair<BoundingBox<dim>, unsigned int>> hits;
      for (auto [list, skip] : {std::make_pair(&points, &skip_points),
                                std::make_pair(&node_points, &skip_nodes)})
        {
          skip->assign(list->size(), {});
          for (unsigned int k = 0; k < list->size(); ++k)
            {
              const Point<dim> &X = (*list)[k].X;
              hits.clear();
              tree.query(bgi::intersects(X), std::back_inserter(hits));
              for (const auto &hit : hits)
                {
                  const auto &f = faces2[hit.second];
                  for (unsigned int v = 0; v < 2 * n_face_vertices; ++v)
                    {
                      double d2 = 0.;
                      for (unsigned int c = 0; c < dim; ++c)
                        d2 += (f.X[v * dim + c] - X[c]) * (f.X[v * dim + c] - X[c]);
                      if (d2 < exclusion_radius_ * exclusion_radius_)
                        {
                          (*skip)[k].push_back(hit.second);
                          break;
                        }
                    }
                }
              std::sort((*skip)[k].begin(), (*skip)[k].end());
            }
        }
    }

    template <int dim>
    std::function<double(const Point<dim> &)>
    TwoBodyContact<dim>::band_distance() const
    {
      const MPI_Comm comm = dof_handler.get_communicator();
      const auto    &tria = dof_handler.get_triangulation();
      // Body 2: the material ids of the cells on the target boundary.
      std::vector<unsigned int> local_ids;
      for (const auto &cell : tria.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const auto f : cell->face_indices())
            if (cell->face(f)->at_boundary() &&
                target_ids.count(cell->face(f)->boundary_id()) > 0)
              local_ids.push_back(cell->material_id());
      std::set<unsigned int> body2;
      for (const auto &ids : Utilities::MPI::all_gather(comm, local_ids))
        body2.insert(ids.begin(), ids.end());
      Point<dim> lo, hi;
      for (unsigned int d = 0; d < dim; ++d)
        {
          lo[d] = std::numeric_limits<double>::max();
          hi[d] = -lo[d];
        }
      for (const auto &cell : tria.active_cell_iterators())
        if (cell->is_locally_owned() && body2.count(cell->material_id()) > 0)
          for (const auto v : cell->vertex_indices())
            for (unsigned int d = 0; d < dim; ++d)
              {
                lo[d] = std::min(lo[d], cell->vertex(v)[d]);
                hi[d] = std::max(hi[d], cell->vertex(v)[d]);
              }
      for (unsigned int d = 0; d < dim; ++d)
        {
          lo[d] = Utilities::MPI::min(lo[d], comm);
          hi[d] = Utilities::MPI::max(hi[d], comm);
        }
      return [lo, hi](const Point<dim> &X) {
        double d2 = 0.;
        for (unsigned int d = 0; d < dim; ++d)
          {
            const double out = std::max({lo[d] - X[d], X[d] - hi[d], 0.});
            d2 += out * out;
          }
        return std::sqrt(d2);
      };
    }

    // Instantiations of the member functions defined in this file.
    template std::vector<IndicatorFace<2>> TwoBodyContact<2>::current_faces(const VectorType &u) const;
    template std::vector<IndicatorFace<3>> TwoBodyContact<3>::current_faces(const VectorType &u) const;
    template typename TwoBodyContact<2>::FaceTree TwoBodyContact<2>::face_tree(const std::vector<IndicatorFace<2>> &faces, const double margin) const;
    template typename TwoBodyContact<3>::FaceTree TwoBodyContact<3>::face_tree(const std::vector<IndicatorFace<3>> &faces, const double margin) const;
    template std::vector<Point<2>> TwoBodyContact<2>::node_positions(const VectorType &u) const;
    template std::vector<Point<3>> TwoBodyContact<3>::node_positions(const VectorType &u) const;
    template std::vector<std::pair<unsigned int, unsigned int>> TwoBodyContact<2>::find_pairs(const std::vector<Point1> &pts, const VectorType &u, const std::vector<IndicatorFace<2>> &faces, const double margin, const bool positive_only) const;
    template std::vector<std::pair<unsigned int, unsigned int>> TwoBodyContact<3>::find_pairs(const std::vector<Point1> &pts, const VectorType &u, const std::vector<IndicatorFace<3>> &faces, const double margin, const bool positive_only) const;
    template void TwoBodyContact<2>::add_sparsity(TrilinosWrappers::SparsityPattern &sparsity, const AffineConstraints<double> &constraints, const VectorType &u);
    template void TwoBodyContact<3>::add_sparsity(TrilinosWrappers::SparsityPattern &sparsity, const AffineConstraints<double> &constraints, const VectorType &u);
    template bool TwoBodyContact<2>::needs_new_pattern(const VectorType &u);
    template bool TwoBodyContact<3>::needs_new_pattern(const VectorType &u);
    template std::vector<typename TwoBodyContact<2>::Partner> TwoBodyContact<2>::node_partners(const VectorType &u, const std::vector<IndicatorFace<2>> &faces) const;
    template std::vector<typename TwoBodyContact<3>::Partner> TwoBodyContact<3>::node_partners(const VectorType &u, const std::vector<IndicatorFace<3>> &faces) const;
    template Tensor<1, 2> TwoBodyContact<2>::partner_displacement(const std::vector<IndicatorFace<2>> &faces, const Partner &partner) const;
    template Tensor<1, 3> TwoBodyContact<3>::partner_displacement(const std::vector<IndicatorFace<3>> &faces, const Partner &partner) const;
    template bool TwoBodyContact<2>::admissible(const VectorType &u) const;
    template bool TwoBodyContact<3>::admissible(const VectorType &u) const;
    template double TwoBodyContact<2>::max_step(const VectorType &u, const VectorType &d) const;
    template double TwoBodyContact<3>::max_step(const VectorType &u, const VectorType &d) const;
    template double TwoBodyContact<2>::penetration_ratio(const std::vector<Point<2>> &x, const std::vector<Point1> &list, const std::vector<IndicatorFace<2>> &faces, std::vector<double> *depths) const;
    template double TwoBodyContact<3>::penetration_ratio(const std::vector<Point<3>> &x, const std::vector<Point1> &list, const std::vector<IndicatorFace<3>> &faces, std::vector<double> *depths) const;
    template void TwoBodyContact<2>::find_excluded_faces();
    template void TwoBodyContact<3>::find_excluded_faces();
    template std::function<double(const Point<2> &)> TwoBodyContact<2>::band_distance() const;
    template std::function<double(const Point<3> &)> TwoBodyContact<3>::band_distance() const;
  } // namespace Contact
} // namespace Signorini
