// The built-in body shapes: areas and boundary lengths (per boundary id)
// of the quarter and half disks after refinement, which checks the curved
// manifolds and the boundary ids documented in mesh.h (also the upper
// ones, Orientation = up); and two-body scenes whose bodies touch at one
// point (a half disk on a block, a quarter disk on an upper quarter disk):
// their vertices must stay separate. Placement (a rotation about the
// origin, then a translation): a half disk in 2D, a quarter cylinder and
// an octant ball in 3D, with their manifolds.
// In 3D the same for the ball parts (octant, quarter, hemisphere; also
// turned up: Orientation = up), the
// quarter and half cylinders (also turned up) and the die: volume and the area of each
// boundary id against the exact values (computed with a degree 3 mapping,
// which follows the manifolds), the vertices of the curved surface on the
// sphere or cylinder to round-off after refinement (and those of each
// plane on it), the lowest point of a ball a vertex, a two-body 3D scene,
// and a small hexahedral Gmsh file. And the octant ball's flat top area
// with a degree 2 mapping after a local refinement of its rim cells.
// BodyGeometry::boundary_ids() (which body carries a boundary, for a
// pair's Hertz modulus) against the ids of every shape's built mesh.

#include <signorini/scene/mesh.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_nothing.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>

using namespace dealii;
using namespace Signorini;

namespace
{
  /// Whether BodyGeometry::boundary_ids() of the shape @p name (default
  /// entries, id offset 7) lists the ids its built mesh has.
  template <int dim>
  bool
  listed_ids_are_built(const std::string &name)
  {
    ParameterHandler prm;
    BodyGeometry::declare_parameters(prm);
    prm.set("Shape", name);
    prm.set("Boundary id offset", "7");
    BodyGeometry g;
    g.parse_parameters(prm, dim, "Body 1 > Geometry");
    MeshParameters                            mesh;
    parallel::distributed::Triangulation<dim> tria(MPI_COMM_WORLD);
    build_scene_mesh<dim>(mesh, {g}, {0}, tria, true);
    std::vector<unsigned int> built;
    for (const auto id : tria.get_boundary_ids())
      built.push_back(id);
    std::sort(built.begin(), built.end());
    return built == g.boundary_ids(dim);
  }

  BodyGeometry
  disk(const BodyGeometry::Shape shape, const unsigned int offset = 0)
  {
    BodyGeometry g;
    g.shape              = shape;
    g.center             = {0., 1.};
    g.radius             = 1.;
    g.boundary_id_offset = offset;
    return g;
  }

  template <int dim>
  void
  measure(const parallel::distributed::Triangulation<dim> &tria,
          const std::map<types::boundary_id, double>      &expected_lengths,
          const double                                     expected_area,
          const std::string                               &label,
          std::ostream                                    &out,
          const double                                     tolerance = 1e-5)
  {
    MappingQ<dim>       mapping(dim == 2 ? 2 : 3);
    FE_Q<dim>           fe(1);
    QGauss<dim>         q(4);
    QGauss<dim - 1>     qf(4);
    FEValues<dim>       fv(mapping, fe, q, update_JxW_values);
    FEFaceValues<dim>   ff(mapping, fe, qf, update_JxW_values);
    double              area = 0.;
    std::map<types::boundary_id, double> lengths;
    for (const auto &cell : tria.active_cell_iterators())
      {
        fv.reinit(cell);
        for (unsigned int i = 0; i < q.size(); ++i)
          area += fv.JxW(i);
        for (const auto f : cell->face_indices())
          if (cell->face(f)->at_boundary())
            {
              ff.reinit(cell, f);
              for (unsigned int i = 0; i < qf.size(); ++i)
                lengths[cell->face(f)->boundary_id()] += ff.JxW(i);
            }
      }
    const char *measure_name = (dim == 2 ? "area" : "volume");
    const char *part_name    = (dim == 2 ? "lengths" : "areas");
    const bool  area_ok      = std::abs(area - expected_area) < tolerance;
    out << label << ": " << measure_name << " " << (area_ok ? "ok" : "FAIL");
    bool ids_ok = lengths.size() == expected_lengths.size();
    for (const auto &l : expected_lengths)
      ids_ok = ids_ok && lengths.count(l.first) &&
               std::abs(lengths[l.first] - l.second) < tolerance;
    out << ", boundary ids and " << part_name << " " << (ids_ok ? "ok" : "FAIL") << "\n";
    if (!ids_ok || !area_ok)
      {
        std::cerr << label << " " << measure_name << " " << area << " (expected "
                  << expected_area << ")\n";
        for (const auto &l : lengths)
          std::cerr << "  id " << int(l.first) << " " << l.second << "\n";
      }
  }

  /**
   * The largest distance, relative to @p scale, of a vertex of a boundary
   * face with id @p id from the surface given by @p distance (zero on it).
   */
  template <typename Distance>
  double
  off_surface(const parallel::distributed::Triangulation<3> &tria,
              const types::boundary_id                       id,
              const Distance                                &distance)
  {
    double worst = 0.;
    for (const auto &cell : tria.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary() && face->boundary_id() == id)
          for (const auto v : face->vertex_indices())
            worst = std::max(worst, std::abs(distance(face->vertex(v))));
    return worst;
  }

  void
  surface_check(const std::string &label, const double worst, std::ostream &out)
  {
    out << label << (worst < 1e-13 ? ": on it to round-off" : ": FAIL") << "\n";
    if (!(worst < 1e-13))
      std::cerr << label << ": " << worst << "\n";
  }

  BodyGeometry
  ball(const BodyGeometry::Shape shape, const Point<3> &c, const double r)
  {
    BodyGeometry g;
    g.shape  = shape;
    g.center = {c[0], c[1], c[2]};
    g.radius = r;
    return g;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream                    out("output");
  MeshParameters                   mesh;
  mesh.global_refinements = 4;
  const double pi         = numbers::PI;
  {
    parallel::distributed::Triangulation<2> tria(MPI_COMM_WORLD);
    build_scene_mesh<2>(mesh, {disk(BodyGeometry::Shape::quarter_disk)}, {0}, tria);
    measure(tria, {{0, pi / 2}, {1, 1.}, {2, 1.}}, pi / 4, "quarter disk", out);
  }
  {
    parallel::distributed::Triangulation<2> tria(MPI_COMM_WORLD);
    build_scene_mesh<2>(mesh, {disk(BodyGeometry::Shape::half_disk)}, {0}, tria);
    measure(tria, {{0, pi}, {1, 2.}}, pi / 2, "half disk", out);
  }
  {
    // A half disk (material 1, ids + 10) resting on a block (material 0):
    // they touch at the origin.
    BodyGeometry block;
    block.lower_corner = {-2., -1.};
    block.upper_corner = {2., 0.};
    block.subdivisions = {4, 1};
    parallel::distributed::Triangulation<2> tria(MPI_COMM_WORLD);
    build_scene_mesh<2>(mesh, {block, disk(BodyGeometry::Shape::half_disk, 10)},
                        {0, 1}, tria);
    unsigned int at_origin = 0;
    for (const auto &v : tria.get_vertices())
      at_origin += (v.norm() < 1e-12);
    std::map<types::material_id, unsigned int> cells;
    for (const auto &cell : tria.active_cell_iterators())
      ++cells[cell->material_id()];
    out << "two bodies: vertices at the contact point " << at_origin
        << " (kept apart), cells per material id: 0 -> " << cells[0]
        << ", 1 -> " << cells[1] << "\n";
    measure(tria, {{0, 1.}, {1, 1.}, {2, 4.}, {3, 4.}, {10, pi}, {11, 2.}},
            4. + pi / 2, "block + half disk", out);
  }
  // Orientation = up (2D): the upper quarter {x >= cx, y >= cy} and half
  // {y >= cy}, the same ids and lengths, the arc's vertices on the circle,
  // the highest point a vertex.
  for (const auto shape : {BodyGeometry::Shape::quarter_disk, BodyGeometry::Shape::half_disk})
    {
      const bool   quarter = shape == BodyGeometry::Shape::quarter_disk;
      const std::string name = quarter ? "quarter disk up" : "half disk up";
      BodyGeometry g = disk(shape);
      g.center       = {0.3, -0.2};
      g.radius       = 0.8;
      g.upward       = true;
      const double rr = g.radius, cx = g.center[0], cy = g.center[1];
      parallel::distributed::Triangulation<2> tria(MPI_COMM_WORLD);
      build_scene_mesh<2>(mesh, {g}, {0}, tria);
      if (quarter)
        measure(tria, {{0, pi * rr / 2}, {1, rr}, {2, rr}}, pi * rr * rr / 4, name, out);
      else
        measure(tria, {{0, pi * rr}, {1, 2 * rr}}, pi * rr * rr / 2, name, out);
      double below = 0., off_circle = 0.;
      bool   highest = false;
      for (const auto &cell : tria.active_cell_iterators())
        for (const auto &face : cell->face_iterators())
          for (const auto v : face->vertex_indices())
            {
              const Point<2> x = face->vertex(v);
              below = std::max(below, cy - x[1]);
              if (quarter)
                below = std::max(below, cx - x[0]);
              highest = highest || x.distance(Point<2>(cx, cy + rr)) < 1e-14;
              if (face->at_boundary() && face->boundary_id() == 0)
                off_circle =
                  std::max(off_circle, std::abs(x.distance(Point<2>(cx, cy)) - rr) / rr);
            }
      out << name << ": on its side: " << (below < 1e-12 ? "yes" : "NO")
          << ", arc vertices on the circle: " << (off_circle < 1e-13 ? "yes" : "NO")
          << ", the highest point is a vertex: " << (highest ? "yes" : "NO") << "\n";
    }
  {
    // Placement (2D): the lower half disk around the origin, turned by 180
    // degrees and shifted to (0.3, -0.2), is the upper half disk there.
    BodyGeometry g   = disk(BodyGeometry::Shape::half_disk);
    g.center         = {0., 0.};
    g.radius         = 0.8;
    g.rotation_angle = pi;
    g.translation    = {0.3, -0.2};
    parallel::distributed::Triangulation<2> tria(MPI_COMM_WORLD);
    build_scene_mesh<2>(mesh, {g}, {0}, tria);
    measure(tria, {{0, pi * 0.8}, {1, 1.6}}, pi * 0.32, "half disk placed", out);
    double below = 0., off_circle = 0.;
    bool   highest = false;
    for (const auto &cell : tria.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        for (const auto v : face->vertex_indices())
          {
            const Point<2> x = face->vertex(v);
            below   = std::max(below, -0.2 - x[1]);
            highest = highest || x.distance(Point<2>(0.3, 0.6)) < 1e-14;
            if (face->at_boundary() && face->boundary_id() == 0)
              off_circle = std::max(off_circle, std::abs(x.distance(Point<2>(0.3, -0.2)) - 0.8));
          }
    // After the turn by pi the flat face's refined vertices (placed by the
    // cells' transfinite interpolation) lie up to 6e-12 below y = -0.2.
    std::cerr << "half disk placed: below " << below << "\n";
    out << "half disk placed: above y = -0.2 (to 1e-10): " << (below < 1e-10 ? "yes" : "NO")
        << ", arc vertices on the circle: " << (off_circle < 1e-13 ? "yes" : "NO")
        << ", the highest point is a vertex: " << (highest ? "yes" : "NO") << "\n";
  }
  {
    // Two curved bodies: a quarter disk (R = 1, center (0, 1)) on an upper
    // quarter disk (R = 2, center (0, -2), ids + 10); they touch at the
    // origin.
    BodyGeometry upper = disk(BodyGeometry::Shape::quarter_disk);
    BodyGeometry lower = disk(BodyGeometry::Shape::quarter_disk, 10);
    lower.center       = {0., -2.};
    lower.radius       = 2.;
    lower.upward       = true;
    parallel::distributed::Triangulation<2> tria(MPI_COMM_WORLD);
    build_scene_mesh<2>(mesh, {upper, lower}, {0, 1}, tria);
    unsigned int at_origin = 0;
    for (const auto &v : tria.get_vertices())
      at_origin += (v.norm() < 1e-12);
    out << "two disks: vertices at the contact point " << at_origin << " (kept apart)\n";
    measure(tria, {{0, pi / 2}, {1, 1.}, {2, 1.}, {10, pi}, {11, 2.}, {12, 2.}},
            pi / 4 + pi, "quarter disk + quarter disk up", out);
  }

  // 3D. A ball of radius 0.8 around c = (0.3, -0.2, 1.1), 3 global
  // refinements.
  const Point<3> c(0.3, -0.2, 1.1);
  const double   r = 0.8, r2 = r * r, volume = 4. / 3. * pi * r2 * r;
  auto sphere       = [&](const Point<3> &x) { return (x.distance(c) - r) / r; };
  mesh.global_refinements = 3;
  {
    parallel::distributed::Triangulation<3> tria(MPI_COMM_WORLD);
    build_scene_mesh<3>(mesh, {ball(BodyGeometry::Shape::octant_ball, c, r)}, {0}, tria);
    measure(tria, {{0, pi * r2 / 2}, {1, pi * r2 / 4}, {2, pi * r2 / 4}, {3, pi * r2 / 4}},
            volume / 8, "octant ball", out);
    surface_check("octant ball: vertices of the sphere (id 0)",
                  off_surface(tria, 0, sphere), out);
    surface_check("octant ball: vertices of the planes x = cx, top, y = cy",
                  std::max({off_surface(tria, 1, [&](const Point<3> &x) { return x[0] - c[0]; }),
                            off_surface(tria, 2, [&](const Point<3> &x) { return x[2] - c[2]; }),
                            off_surface(tria, 3, [&](const Point<3> &x) { return x[1] - c[1]; })}),
                  out);
    bool lowest = false;
    for (const auto &v : tria.get_vertices())
      lowest = lowest || v.distance(Point<3>(c[0], c[1], c[2] - r)) < 1e-14;
    out << "octant ball: the lowest point is a vertex: " << (lowest ? "yes" : "NO") << "\n";
  }
  {
    // The flat top's area with the program's degree 2 mapping before and
    // after one local refinement of the cells at its rim, as Kelly's
    // indicator refines them in a refinement cycle (a transfinite cell
    // manifold on those cells once put it 1.9e-3 off, and the applied load
    // with it).
    MeshParameters coarse   = mesh;
    coarse.global_refinements = 2;
    parallel::distributed::Triangulation<3> tria(MPI_COMM_WORLD);
    build_scene_mesh<3>(coarse, {ball(BodyGeometry::Shape::octant_ball, c, r)}, {0}, tria);
    const auto top_area = [&]() {
      MappingQ<3>       mapping(2);
      FE_Q<3>           fe(1);
      QGauss<2>         qf(4);
      FEFaceValues<3>   ff(mapping, fe, qf, update_JxW_values);
      double            area = 0.;
      for (const auto &cell : tria.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const auto f : cell->face_indices())
            if (cell->face(f)->at_boundary() && cell->face(f)->boundary_id() == 2)
              {
                ff.reinit(cell, f);
                for (unsigned int q = 0; q < qf.size(); ++q)
                  area += ff.JxW(q);
              }
      return Utilities::MPI::sum(area, MPI_COMM_WORLD);
    };
    const double before = top_area();
    unsigned int flagged = 0;
    for (const auto &cell : tria.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const auto f : cell->face_indices())
          if (cell->face(f)->at_boundary() && cell->face(f)->boundary_id() == 2 &&
              (cell->face(f)->center() - c).norm() > 0.8 * r)
            {
              cell->set_refine_flag();
              ++flagged;
              break;
            }
    tria.execute_coarsening_and_refinement();
    const double after = top_area(), exact = pi * r2 / 4;
    out << "octant ball: the flat top's area (degree 2 mapping) after refining "
        << (Utilities::MPI::sum(flagged, MPI_COMM_WORLD) > 0 ? "its rim cells" : "NOTHING")
        << " within 1e-5 of the exact one and of the area before: "
        << (std::abs(after - exact) < 1e-5 * exact && std::abs(after - before) < 1e-5 * exact ?
              "yes" :
              "NO")
        << "\n";
  }
  {
    parallel::distributed::Triangulation<3> tria(MPI_COMM_WORLD);
    build_scene_mesh<3>(mesh, {ball(BodyGeometry::Shape::quarter_ball, c, r)}, {0}, tria);
    measure(tria, {{0, pi * r2}, {1, pi * r2 / 2}, {2, pi * r2 / 2}}, volume / 4,
            "quarter ball", out);
    surface_check("quarter ball: vertices of the sphere (id 0)", off_surface(tria, 0, sphere),
                  out);
  }
  {
    parallel::distributed::Triangulation<3> tria(MPI_COMM_WORLD);
    build_scene_mesh<3>(mesh, {ball(BodyGeometry::Shape::hemisphere, c, r)}, {0}, tria);
    measure(tria, {{0, 2 * pi * r2}, {1, pi * r2}}, volume / 2, "hemisphere", out);
    surface_check("hemisphere: vertices of the sphere (id 0)", off_surface(tria, 0, sphere),
                  out);
  }
  // Orientation = up: the upper parts, the same ids and areas, on the side
  // z >= cz (x >= cx for the octant and the quarter, y >= cy for the
  // octant), the highest point a vertex.
  for (const auto shape : {BodyGeometry::Shape::octant_ball, BodyGeometry::Shape::quarter_ball,
                           BodyGeometry::Shape::hemisphere})
    {
      using Shape = BodyGeometry::Shape;
      const std::string name = (shape == Shape::octant_ball  ? "octant ball" :
                                shape == Shape::quarter_ball ? "quarter ball" :
                                                               "hemisphere");
      BodyGeometry g = ball(shape, c, r);
      g.upward       = true;
      parallel::distributed::Triangulation<3> tria(MPI_COMM_WORLD);
      build_scene_mesh<3>(mesh, {g}, {0}, tria);
      const double n = (shape == Shape::octant_ball ? 8. : shape == Shape::quarter_ball ? 4. : 2.);
      std::map<types::boundary_id, double> areas{{0, 4 * pi * r2 / n}};
      if (shape == Shape::hemisphere)
        areas[1] = pi * r2;
      else
        {
          areas[1] = pi * r2 * 4. / n / 2.;
          areas[2] = pi * r2 * 4. / n / 2.;
        }
      if (shape == Shape::octant_ball)
        areas[3] = pi * r2 / 4;
      measure(tria, areas, volume / n, name + " up", out);
      surface_check(name + " up: vertices of the sphere (id 0)", off_surface(tria, 0, sphere),
                    out);
      bool   highest = false;
      double below   = 0.;
      for (const auto &v : tria.get_vertices())
        {
          highest = highest || v.distance(Point<3>(c[0], c[1], c[2] + r)) < 1e-14;
          below   = std::max(below, c[2] - v[2]);
          if (shape != Shape::hemisphere)
            below = std::max(below, c[0] - v[0]);
          if (shape == Shape::octant_ball)
            below = std::max(below, c[1] - v[1]);
        }
      out << name << " up: on its side of the planes: " << (below < 1e-12 ? "yes" : "NO")
          << ", the highest point is a vertex: " << (highest ? "yes" : "NO") << "\n";
    }
  // Cylinders of radius 0.8 and length 2.5 along y through c.
  const double length = 2.5;
  auto cylinder = [&](const Point<3> &x) {
    return (std::hypot(x[0] - c[0], x[2] - c[2]) - r) / r;
  };
  mesh.global_refinements = 2;
  for (const auto shape :
       {BodyGeometry::Shape::quarter_cylinder, BodyGeometry::Shape::half_cylinder})
    {
      const bool quarter = shape == BodyGeometry::Shape::quarter_cylinder;
      BodyGeometry g     = ball(shape, c, r);
      g.length           = length;
      parallel::distributed::Triangulation<3> tria(MPI_COMM_WORLD);
      build_scene_mesh<3>(mesh, {g}, {0}, tria);
      const double section = pi * r2 / (quarter ? 4 : 2);
      const std::string label = quarter ? "quarter cylinder" : "half cylinder";
      if (quarter)
        measure(tria, {{0, pi * r / 2 * length}, {1, r * length}, {2, r * length},
                       {3, section}, {4, section}},
                section * length, label, out);
      else
        measure(tria, {{0, pi * r * length}, {1, 2 * r * length}, {2, section}, {3, section}},
                section * length, label, out);
      surface_check(label + ": vertices of the curved surface (id 0)",
                    off_surface(tria, 0, cylinder), out);
      // Orientation = up: the upper part {z >= cz}, the same ids and
      // areas.
      g.upward = true;
      parallel::distributed::Triangulation<3> up(MPI_COMM_WORLD);
      build_scene_mesh<3>(mesh, {g}, {0}, up);
      if (quarter)
        measure(up, {{0, pi * r / 2 * length}, {1, r * length}, {2, r * length},
                     {3, section}, {4, section}},
                section * length, label + " up", out);
      else
        measure(up, {{0, pi * r * length}, {1, 2 * r * length}, {2, section}, {3, section}},
                section * length, label + " up", out);
      surface_check(label + " up: vertices of the curved surface (id 0)",
                    off_surface(up, 0, cylinder), out);
      double below = 0.;
      for (const auto &v : up.get_vertices())
        below = std::max({below, c[2] - v[2], quarter ? c[0] - v[0] : 0.});
      out << label << " up: on its side of the planes: " << (below < 1e-12 ? "yes" : "NO")
          << "\n";
    }
  // Placement: a quarter cylinder built around the origin, turned by 90
  // degrees about z (its axis from y to -x) and shifted to c; an octant
  // ball turned by 120 degrees about (1, 1, 1) and shifted to c. The same
  // ids and areas, and the refined vertices on the placed surface: the
  // cylinder's manifold axis turns with it.
  {
    BodyGeometry g = ball(BodyGeometry::Shape::quarter_cylinder, Point<3>(), r);
    g.length         = length;
    g.rotation_angle = pi / 2;
    g.rotation_axis  = {0., 0., 1.};
    g.translation    = {c[0], c[1], c[2]};
    parallel::distributed::Triangulation<3> tria(MPI_COMM_WORLD);
    build_scene_mesh<3>(mesh, {g}, {0}, tria);
    const double section = pi * r2 / 4;
    measure(tria, {{0, pi * r / 2 * length}, {1, r * length}, {2, r * length},
                   {3, section}, {4, section}},
            section * length, "quarter cylinder placed", out);
    surface_check("quarter cylinder placed: vertices of the curved surface (id 0) on the "
                  "cylinder along x through c",
                  off_surface(tria, 0, [&](const Point<3> &x) {
                    return (std::hypot(x[1] - c[1], x[2] - c[2]) - r) / r;
                  }),
                  out);
  }
  {
    BodyGeometry g = ball(BodyGeometry::Shape::octant_ball, Point<3>(), r);
    g.rotation_angle = 2 * pi / 3;
    g.rotation_axis  = {1. / std::sqrt(3.), 1. / std::sqrt(3.), 1. / std::sqrt(3.)};
    g.translation    = {c[0], c[1], c[2]};
    parallel::distributed::Triangulation<3> tria(MPI_COMM_WORLD);
    build_scene_mesh<3>(mesh, {g}, {0}, tria);
    measure(tria, {{0, pi * r2 / 2}, {1, pi * r2 / 4}, {2, pi * r2 / 4}, {3, pi * r2 / 4}},
            volume / 8, "octant ball placed", out);
    surface_check("octant ball placed: vertices of the sphere (id 0)",
                  off_surface(tria, 0, sphere), out);
  }
  {
    // A 3D die 1.2 wide (x), 2 long (y), 1 high (z), sag 0.3.
    BodyGeometry g;
    g.shape        = BodyGeometry::Shape::die;
    g.lower_corner = {-0.6, -1., 0.};
    g.upper_corner = {0.6, 1., 1.};
    g.subdivisions = {4, 3, 2};
    g.arc_sag      = 0.3;
    const double w = 1.2, h = 1., s = 0.3, l = 2.;
    const double R     = (w * w / 4 + s * s) / (2 * s);
    const double angle = 2 * std::asin(w / (2 * R));
    const double segment = 0.5 * R * R * (angle - std::sin(angle)); // between chord and arc
    const double section = w * (h - s) + segment;
    parallel::distributed::Triangulation<3> tria(MPI_COMM_WORLD);
    build_scene_mesh<3>(mesh, {g}, {0}, tria);
    measure(tria, {{0, (R * angle + 2 * (h - s)) * l}, {1, w * l}, {2, section}, {3, section}},
            section * l, "die (3D)", out);
    // Subdivisions 4, 3, 2: 3 cell layers along y (the extrusion used to
    // give one fewer), each a copy of the 4 x 2 section.
    parallel::distributed::Triangulation<3> coarse(MPI_COMM_WORLD);
    build_scene_mesh<3>(mesh, {g}, {0}, coarse, true);
    out << "die (3D): coarse cells = 4 x 3 x 2: "
        << (coarse.n_global_active_cells() == 24 ? "yes" : "NO") << "\n";
    const Point<3> axis(0., 0., R);
    surface_check("die (3D): vertices of the arc and sides (id 0) on the arc or a side",
                  off_surface(tria, 0, [&](const Point<3> &x) {
                    return std::min({std::abs(std::hypot(x[0] - axis[0], x[2] - axis[2]) - R),
                                     std::abs(x[0] + 0.6), std::abs(x[0] - 0.6)});
                  }),
                  out);
  }
  {
    // An octant ball of radius 1 (material 1, ids + 10) resting on a box
    // (material 0): they touch at the origin.
    BodyGeometry block;
    block.lower_corner = {-1., -1., -1.};
    block.upper_corner = {1., 1., 0.};
    block.subdivisions = {2, 2, 1};
    BodyGeometry b       = ball(BodyGeometry::Shape::octant_ball, Point<3>(0, 0, 1), 1.);
    b.boundary_id_offset = 10;
    mesh.global_refinements = 2;
    parallel::distributed::Triangulation<3> tria(MPI_COMM_WORLD);
    build_scene_mesh<3>(mesh, {block, b}, {0, 1}, tria);
    unsigned int at_origin = 0;
    for (const auto &v : tria.get_vertices())
      at_origin += (v.norm() < 1e-12);
    std::map<types::material_id, unsigned int> cells;
    for (const auto &cell : tria.active_cell_iterators())
      ++cells[cell->material_id()];
    out << "two bodies (3D): vertices at the contact point " << at_origin
        << " (kept apart), cells per material id: 0 -> " << cells[0] << ", 1 -> "
        << cells[1] << "\n";
    measure(tria, {{0, 2.}, {1, 2.}, {2, 2.}, {3, 2.}, {4, 4.}, {5, 4.},
                   {10, pi / 2}, {11, pi / 4}, {12, pi / 4}, {13, pi / 4}},
            4. + pi / 6, "box + octant ball", out);
  }
  {
    std::string wrong;
    for (const std::string shape : {"rectangle", "quarter disk", "half disk", "die"})
      if (!listed_ids_are_built<2>(shape))
        wrong += " " + shape + " (2D)";
    for (const std::string shape : {"rectangle", "die", "octant ball", "quarter ball",
                                    "hemisphere", "quarter cylinder", "half cylinder"})
      if (!listed_ids_are_built<3>(shape))
        wrong += " " + shape + " (3D)";
    out << "boundary_ids() lists the built ids of every shape: "
        << (wrong.empty() ? "yes" : "NO:" + wrong) << "\n";
  }
  {
    // A small hexahedral Gmsh file: the unit cube in 2 x 2 x 2 cells,
    // faces tagged 10/11 (x = 0/1), 12/13 (y), 14/15 (z), cells 5.
    MeshParameters gmsh;
    gmsh.source             = MeshParameters::Source::gmsh;
    gmsh.gmsh_file          = std::string(SIGNORINI_SOURCE_DIR) + "/tests/data/cube_2x2x2.msh";
    gmsh.global_refinements = 1;
    parallel::distributed::Triangulation<3> tria(MPI_COMM_WORLD);
    build_scene_mesh<3>(gmsh, {}, {}, tria);
    bool material = true;
    for (const auto &cell : tria.active_cell_iterators())
      material = material && cell->material_id() == 5;
    out << "Gmsh hexahedra: " << tria.n_global_active_cells()
        << " cells after one refinement, material id 5: " << (material ? "yes" : "NO") << "\n";
    measure(tria, {{10, 1.}, {11, 1.}, {12, 1.}, {13, 1.}, {14, 1.}, {15, 1.}}, 1.,
            "Gmsh hexahedra", out);
  }
}
