#include <signorini/input_error.h>
#include <signorini/scene/mesh.h>
#include <signorini/parameters/lists.h>

#include <deal.II/base/utilities.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>
#include <deal.II/grid/tria_description.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <memory>
#include <sstream>
#include <thread>
#include <vector>

namespace Signorini
{

  namespace
  {
    // A coarse mesh lives on every rank (p4est): beyond this it is a
    // typing error, not a scene.
    constexpr double max_coarse_cells = 1e7;

    std::string
    format_count(const double n)
    {
      std::ostringstream s;
      s << std::setprecision(3) << n;
      return s.str();
    }

    /**
     * Throw an InputError when refining @p coarse_cells cells @p global
     * times would need more memory than this machine (or, on several
     * ranks, the nodes they run on) has. The estimate is a low bound (the
     * mesh, DoF handler, vectors and the Q1 Hessian take about 2 kB per 2D
     * cell and 10 kB per 3D cell), so that only scenes that cannot run
     * are refused, and before any allocation fails.
     */
    void
    check_refined_size(const double coarse_cells, const unsigned int dim,
                       const unsigned int global, const MPI_Comm comm)
    {
      const double cells = coarse_cells * std::pow(2., double(dim * global));
      const double bytes = cells * (dim == 2 ? 2e3 : 1e4);
      double       memory = 0.; // bytes of this node
      std::ifstream meminfo("/proc/meminfo");
      for (std::string key; meminfo >> key;)
        {
          double kb = 0.;
          meminfo >> kb;
          if (key == "MemTotal:")
            memory = kb * 1024.;
          meminfo.ignore(256, '\n');
        }
      if (!(memory > 0.))
        return;
      const double cores = std::max(1u, std::thread::hardware_concurrency());
      const double nodes =
        std::max(1., Utilities::MPI::n_mpi_processes(comm) / cores);
      if (bytes > memory * nodes || cells > 4e9)
        throw InputError("Mesh > Global refinements",
                         std::to_string(global) + " refinements of " +
                           format_count(coarse_cells) + " coarse cells make " +
                           format_count(cells) + " cells, which need at least " +
                           format_count(bytes / 1e9) + " GB; this machine has " +
                           format_count(memory * nodes / 1e9) + " GB");
    }

    /**
     * GridIn accepts a cell that names one vertex twice, or whose corners
     * coincide: the solve then fails far from the cause. Refuse them with
     * the cell's number (cells counted from 1 in the order of the file's
     * elements of the mesh's dimension) and its vertices.
     */
    template <int dim>
    void
    check_cells(const Triangulation<dim> &tria, const std::string &file)
    {
      const double size = GridTools::diameter(tria);
      for (const auto &cell : tria.active_cell_iterators())
        {
          std::vector<unsigned int> sorted;
          for (const auto v : cell->vertex_indices())
            sorted.push_back(cell->vertex_index(v));
          std::sort(sorted.begin(), sorted.end());
          const bool repeated =
            std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end();
          double shortest = std::numeric_limits<double>::max();
          for (const auto v : cell->vertex_indices())
            for (unsigned int w = v + 1; w < cell->n_vertices(); ++w)
              shortest = std::min(shortest, cell->vertex(v).distance(cell->vertex(w)));
          const bool coincide = !(shortest > 1e-12 * size);
          if (repeated || coincide || !(std::abs(cell->measure()) > 0.))
            {
              std::ostringstream msg;
              msg << "cell " << cell->index() + 1 << " is degenerate ("
                  << (repeated ? "it names a vertex twice" :
                      coincide ? "two of its corners coincide" :
                                 "its measure is zero")
                  << "); its vertices:";
              for (const auto v : cell->vertex_indices())
                msg << " (" << cell->vertex(v) << ")";
              throw InputError(file, msg.str());
            }
        }
    }

    /**
     * The parts of an ASCII Gmsh file that GridIn::read_msh trusts without
     * checking: the $MeshFormat line, and the count lines after $Nodes and
     * $Elements, whose layout depends on the format version (4.x: four
     * numbers; 2.x: one). A 4.1 header over a 2.2 body makes read_msh
     * write out of bounds.
     */
    void
    check_gmsh_layout(std::istream &in, const std::string &file)
    {
      std::string  line;
      unsigned int number  = 0;
      double       version = -1.;
      auto         next    = [&]() {
        ++number;
        return static_cast<bool>(std::getline(in, line));
      };
      auto where = [&]() { return file + ":" + std::to_string(number); };
      auto words = [](const std::string &text) {
        std::istringstream  stream(text);
        std::vector<double> values;
        for (std::string w; stream >> w;)
          {
            char        *end   = nullptr;
            const double value = std::strtod(w.c_str(), &end);
            if (end == w.c_str() || *end != '\0')
              return std::vector<double>(); // not all numbers
            values.push_back(value);
          }
        return values;
      };
      if (!next())
        throw InputError(where(), "the mesh file is empty");
      if (!line.empty() && line.back() == '\r')
        line.pop_back();
      if (line != "$MeshFormat")
        throw InputError(where(), "not an ASCII Gmsh file: it must start with "
                                  "$MeshFormat");
      if (!next())
        throw InputError(where(), "the file ends inside $MeshFormat");
      const auto format = words(line);
      if (format.size() != 3)
        throw InputError(where(), "expected 'version file-type data-size' "
                                  "after $MeshFormat");
      version = format[0];
      if (format[1] != 0.)
        throw InputError(where(), "binary Gmsh files are not supported: "
                                  "save the mesh in ASCII format");
      if (!(version >= 2. && version < 5.))
        throw InputError(where(), "Gmsh format version " +
                                    std::to_string(version) +
                                    " is not supported (2.x or 4.x)");
      const std::size_t expected = (version >= 4. ? 4 : 1);
      while (next())
        {
          if (!line.empty() && line.back() == '\r')
            line.pop_back();
          if (line != "$Nodes" && line != "$Elements")
            continue;
          const std::string section = line;
          if (!next())
            throw InputError(where(), "the file ends after " + section);
          if (words(line).size() != expected)
            throw InputError(where(),
                             "after " + section + " a format " +
                               (expected == 4 ? std::string("4.x") :
                                                std::string("2.x")) +
                               " file has a line of " + std::to_string(expected) +
                               " number(s); does the body match the "
                               "$MeshFormat version?");
        }
    }
  } // namespace
  void
  BodyGeometry::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Shape",
                      "rectangle",
                      Patterns::Selection("rectangle|quarter disk|half disk|die"),
                      "Built-in shape of the body (used when Mesh > Source = "
                      "generated). rectangle: a rectangle (2D) or box (3D) "
                      "with boundary ids 0/1 at x min/max, 2/3 at y min/max, "
                      "4/5 at z min/max. quarter disk (2D): the lower right "
                      "quarter {x >= cx, y <= cy} of the disk, ids 0 arc, "
                      "1 edge x = cx, 2 edge y = cy. half disk (2D): the "
                      "lower half {y <= cy}, ids 0 arc, 1 flat top. The "
                      "lowest point of a disk of center (0, R) touches y = 0 "
                      "at the origin. die (2D): the rectangle between the "
                      "two corners whose bottom edge is replaced by a "
                      "circular arc of height 'Arc sag' through the two "
                      "lower corners; its lowest point is the middle of "
                      "the lower edge. ids 0 the arc and both sides (the "
                      "surface that can touch), 1 the top.");
    prm.declare_entry("Lower corner",
                      "0, 0, 0",
                      Patterns::List(Patterns::Double(), 2, 3),
                      "Rectangle/box: lower corner [length], dim entries "
                      "(extra entries are ignored).");
    prm.declare_entry("Upper corner",
                      "1, 1, 1",
                      Patterns::List(Patterns::Double(), 2, 3),
                      "Rectangle/box: upper corner [length].");
    prm.declare_entry("Subdivisions",
                      "1, 1, 1",
                      Patterns::List(Patterns::Integer(1), 2, 3),
                      "Rectangle/box: number of coarse cells per direction.");
    prm.declare_entry("Center",
                      "0, 1, 0",
                      Patterns::List(Patterns::Double(), 2, 3),
                      "Disks: center of the full disk [length].");
    prm.declare_entry("Radius", "1", Patterns::Double(), "Disks: radius [length], > 0.");
    prm.declare_entry("Arc sag",
                      "0.3",
                      Patterns::Double(),
                      "Die: height of the circular arc at the bottom "
                      "[length], > 0 and below the die's height; the "
                      "radius is (w^2/4 + s^2)/(2 s) for width w and sag s.");
    prm.declare_entry("Boundary id offset",
                      "0",
                      Patterns::Integer(0, 200),
                      "Added to every boundary id of this body, so that two "
                      "bodies of one scene get distinct ids (e.g. 10 for the "
                      "second body).");
  }

  void
  BodyGeometry::parse_parameters(ParameterHandler  &prm,
                                 const unsigned int dim,
                                 const std::string &context)
  {
    const std::string s = prm.get("Shape");
    shape = (s == "rectangle"    ? Shape::rectangle :
             s == "quarter disk" ? Shape::quarter_disk :
             s == "die"          ? Shape::die :
                                   Shape::half_disk);
    lower_corner       = get_list<double>(prm, "Lower corner", dim, context);
    upper_corner       = get_list<double>(prm, "Upper corner", dim, context);
    subdivisions       = get_list<unsigned int>(prm, "Subdivisions", dim, context);
    center             = get_list<double>(prm, "Center", dim, context);
    radius             = prm.get_double("Radius");
    boundary_id_offset = prm.get_integer("Boundary id offset");
    arc_sag            = prm.get_double("Arc sag");

    {
      double coarse_cells = 1.;
      for (const unsigned int n : subdivisions)
        coarse_cells *= n;
      if (coarse_cells > max_coarse_cells)
        throw InputError(context + " > Subdivisions",
                         "'" + prm.get("Subdivisions") + "' makes " +
                           format_count(coarse_cells) +
                           " coarse cells; at most " +
                           format_count(max_coarse_cells) +
                           " (refine with Mesh > Global refinements instead)");
    }
    if (shape == Shape::rectangle || shape == Shape::die)
      for (unsigned int d = 0; d < dim; ++d)
        if (!(upper_corner[d] > lower_corner[d]))
          throw InputError(context + " > Upper corner",
                           "must be above 'Lower corner' in every "
                           "direction, got lower = '" +
                             prm.get("Lower corner") + "', upper = '" +
                             prm.get("Upper corner") + "'");
    if (shape == Shape::die)
      {
        if (dim != 2)
          throw InputError(context + " > Shape",
                           "'die' is a 2D shape; in 3D use a Gmsh mesh");
        if (!(arc_sag > 0.) || !(arc_sag < upper_corner[1] - lower_corner[1]))
          throw InputError(context + " > Arc sag",
                           "must be > 0 and below the die's height " +
                             std::to_string(upper_corner[1] - lower_corner[1]) +
                             ", got " + prm.get("Arc sag"));
      }
    else if (shape != Shape::rectangle)
      {
        if (dim != 2)
          throw InputError(context + " > Shape",
                           "'" + s + "' is a 2D shape; in 3D use a "
                           "rectangle or a Gmsh mesh");
        if (!(radius > 0.))
          throw InputError(context + " > Radius",
                           "must be > 0, got " + prm.get("Radius"));
      }
  }

  void
  MeshParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Source",
                      "generated",
                      Patterns::Selection("generated|gmsh"),
                      "generated: each body builds its own coarse mesh from "
                      "its Geometry subsection. gmsh: one Gmsh file holds "
                      "every body; its physical tags give the material ids "
                      "(which select the bodies) and the boundary ids.");
    prm.declare_entry("Gmsh file",
                      "",
                      Patterns::Anything(),
                      "Gmsh .msh file (relative paths are relative to the "
                      "parameter file).");
    prm.declare_entry("Global refinements",
                      "0",
                      Patterns::Integer(0, 20),
                      "Number of uniform refinements of the coarse mesh.");
    prm.declare_entry("Local refinements",
                      "0",
                      Patterns::Integer(0, 20),
                      "Extra refinement levels, after the global ones, for "
                      "the cells with a vertex inside the ball given by the "
                      "two entries below (e.g. around the expected contact "
                      "zone). The transition is graded with hanging nodes.");
    prm.declare_entry("Local refinement center",
                      "0, 0",
                      Patterns::List(Patterns::Double(), 2, 3),
                      "Center of the locally refined ball [length], dim "
                      "coordinates.");
    prm.declare_entry("Local refinement radius",
                      "0",
                      Patterns::Double(0.),
                      "Radius of the locally refined ball [length].");
  }

  void
  MeshParameters::parse_parameters(ParameterHandler  &prm,
                                   const std::string &prm_directory)
  {
    source = (prm.get("Source") == "gmsh" ? Source::gmsh : Source::generated);
    gmsh_file = prm.get("Gmsh file");
    if (source == Source::gmsh)
      {
        if (gmsh_file.empty())
          throw InputError("Mesh > Gmsh file",
                           "is empty, but Mesh > Source = gmsh");
        if (gmsh_file[0] != '/' && !prm_directory.empty())
          gmsh_file = prm_directory + "/" + gmsh_file;
      }
    global_refinements = prm.get_integer("Global refinements");
    local_refinements  = prm.get_integer("Local refinements");
    local_center.clear();
    for (const auto &v :
         Utilities::split_string_list(prm.get("Local refinement center")))
      local_center.push_back(Utilities::string_to_double(v));
    local_radius = prm.get_double("Local refinement radius");
    if (local_refinements > 0 && !(local_radius > 0.))
      throw InputError("Mesh > Local refinement radius",
                       "must be > 0 when Local refinements > 0");
  }

  namespace
  {
    /// A manifold to attach to the final mesh.
    template <int dim>
    struct ManifoldSpec
    {
      types::manifold_id id;
      bool               transfinite;
      Point<dim>         center;
    };

    template <int dim>
    Point<dim>
    to_point(const std::vector<double> &v)
    {
      Point<dim> p;
      for (unsigned int d = 0; d < dim; ++d)
        p[d] = v[d];
      return p;
    }

    /**
     * Build one body's coarse mesh. Disks are generated around the origin
     * as the upper right quarter/right half that deal.II provides, rotated
     * by -90 degrees (x, y) -> (y, -x) (a rotation keeps the cells
     * positively oriented, a reflection would not), and shifted to the
     * center.
     */
    template <int dim>
    void
    build_body(const BodyGeometry             &g,
               const types::material_id        material_id,
               const unsigned int              body_index,
               Triangulation<dim>             &tria,
               std::vector<ManifoldSpec<dim>> &manifolds)
    {
      if (g.shape == BodyGeometry::Shape::rectangle)
        {
          GridGenerator::subdivided_hyper_rectangle(tria,
                                                    g.subdivisions,
                                                    to_point<dim>(g.lower_corner),
                                                    to_point<dim>(g.upper_corner),
                                                    /*colorize=*/true);
          tria.reset_all_manifolds();
          for (const auto &cell : tria.active_cell_iterators())
            cell->set_all_manifold_ids(numbers::flat_manifold_id);
        }
      else if (g.shape == BodyGeometry::Shape::die)
        {
          // A subdivided rectangle whose vertices are moved vertically so
          // that its bottom row lies on the arc and the rows above are
          // spread evenly between the arc and the top; the arc faces get a
          // SphericalManifold and the cells a transfinite interpolation,
          // so that refinement follows the arc.
          Assert(dim == 2, ExcInternalError());
          const Point<dim> lower = to_point<dim>(g.lower_corner);
          const Point<dim> upper = to_point<dim>(g.upper_corner);
          GridGenerator::subdivided_hyper_rectangle(tria, g.subdivisions, lower, upper,
                                                    /*colorize=*/true);
          tria.reset_all_manifolds();
          const double half_width = 0.5 * (upper[0] - lower[0]);
          const double radius =
            (half_width * half_width + g.arc_sag * g.arc_sag) / (2. * g.arc_sag);
          Point<dim> center;
          center[0] = 0.5 * (lower[0] + upper[0]);
          center[1] = lower[1] + radius;
          const double height = upper[1] - lower[1];
          GridTools::transform(
            [&](const Point<dim> &p) {
              const double dx     = p[0] - center[0];
              const double bottom = center[1] - std::sqrt(radius * radius - dx * dx);
              Point<dim>   q      = p;
              q[1] = bottom + (p[1] - lower[1]) / height * (upper[1] - bottom);
              return q;
            },
            tria);
          const types::manifold_id arc_id         = 2 * body_index;
          const types::manifold_id transfinite_id = 2 * body_index + 1;
          for (const auto &cell : tria.active_cell_iterators())
            {
              cell->set_all_manifold_ids(transfinite_id);
              for (const auto &face : cell->face_iterators())
                if (face->at_boundary())
                  {
                    // colorize: 0/1 the sides, 2 the bottom, 3 the top.
                    if (face->boundary_id() == 2)
                      face->set_manifold_id(arc_id);
                    else
                      face->set_manifold_id(numbers::flat_manifold_id);
                    face->set_boundary_id(face->boundary_id() == 3 ? 1 : 0);
                  }
            }
          manifolds.push_back({arc_id, false, center});
          manifolds.push_back({transfinite_id, true, center});
        }
      else
        {
          Assert(dim == 2, ExcInternalError());
          const Point<dim> origin;
          if (g.shape == BodyGeometry::Shape::quarter_disk)
            GridGenerator::quarter_hyper_ball(tria, origin, g.radius);
          else
            GridGenerator::half_hyper_ball(tria, origin, g.radius);
          tria.reset_all_manifolds();
          const Point<dim> center = to_point<dim>(g.center);
          GridTools::transform(
            [&](const Point<dim> &p) {
              Point<dim> q = center;
              q[0] += p[1];
              q[1] -= p[0];
              return q;
            },
            tria);

          const types::manifold_id arc_id         = 2 * body_index;
          const types::manifold_id transfinite_id = 2 * body_index + 1;
          const double             tol            = 1e-8 * g.radius;
          for (const auto &cell : tria.active_cell_iterators())
            {
              cell->set_all_manifold_ids(transfinite_id);
              for (const auto &face : cell->face_iterators())
                if (face->at_boundary())
                  {
                    // A straight edge through the center has both its
                    // vertices on the line; an arc face does not (its
                    // midpoint may lie on x = cx, its vertices do not).
                    auto on_line = [&](const unsigned int d) {
                      return std::abs(face->vertex(0)[d] - center[d]) < tol &&
                             std::abs(face->vertex(1)[d] - center[d]) < tol;
                    };
                    if (on_line(1))
                      face->set_boundary_id(
                        g.shape == BodyGeometry::Shape::quarter_disk ? 2 : 1);
                    else if (on_line(0))
                      face->set_boundary_id(1);
                    else
                      {
                        face->set_boundary_id(0);
                        face->set_manifold_id(arc_id);
                      }
                  }
            }
          manifolds.push_back({arc_id, false, center});
          manifolds.push_back({transfinite_id, true, center});
        }

      for (const auto &cell : tria.active_cell_iterators())
        {
          cell->set_material_id(material_id);
          for (const auto &face : cell->face_iterators())
            if (face->at_boundary())
              face->set_boundary_id(face->boundary_id() + g.boundary_id_offset);
        }
    }

    /**
     * Put the coarse cells of every part into @p result, keeping each
     * part's vertices separate (no vertex merging), with material,
     * boundary and manifold ids.
     */
    template <int dim>
    void
    combine(const std::vector<std::unique_ptr<Triangulation<dim>>> &parts,
            Triangulation<dim>                                     &result)
    {
      std::vector<Point<dim>>    vertices;
      std::vector<CellData<dim>> cells;
      SubCellData                subcells;
      for (const auto &part : parts)
        {
          const unsigned int offset = vertices.size();
          const auto        &v      = part->get_vertices();
          vertices.insert(vertices.end(), v.begin(), v.end());
          for (const auto &cell : part->active_cell_iterators())
            {
              CellData<dim> c;
              for (unsigned int i = 0; i < cell->n_vertices(); ++i)
                c.vertices[i] = offset + cell->vertex_index(i);
              c.material_id = cell->material_id();
              c.manifold_id = cell->manifold_id();
              cells.push_back(c);
              for (const auto &face : cell->face_iterators())
                if (face->at_boundary() ||
                    face->manifold_id() != numbers::flat_manifold_id)
                  {
                    CellData<dim - 1> f;
                    for (unsigned int i = 0; i < face->n_vertices(); ++i)
                      f.vertices[i] = offset + face->vertex_index(i);
                    f.boundary_id = face->at_boundary() ?
                                      face->boundary_id() :
                                      numbers::internal_face_boundary_id;
                    f.manifold_id = face->manifold_id();
                    if constexpr (dim == 2)
                      subcells.boundary_lines.push_back(f);
                    else
                      subcells.boundary_quads.push_back(f);
                  }
            }
        }
      GridTools::delete_unused_vertices(vertices, cells, subcells);
      result.create_triangulation(vertices, cells, subcells);
    }
  } // namespace

  template <int dim>
  void
  build_scene_mesh(const MeshParameters                      &mesh,
                   const std::vector<BodyGeometry>           &bodies,
                   const std::vector<types::material_id>     &material_ids,
                   parallel::distributed::Triangulation<dim> &tria,
                   const bool                                 coarse_only)
  {
    std::vector<ManifoldSpec<dim>> manifolds;
    if (mesh.source == MeshParameters::Source::gmsh)
      {
        if (std::filesystem::is_directory(mesh.gmsh_file))
          throw InputError("Mesh > Gmsh file",
                           "'" + mesh.gmsh_file + "' is a directory, not a mesh file");
        std::ifstream in(mesh.gmsh_file);
        if (!in)
          throw InputError("Mesh > Gmsh file",
                           "cannot open '" + mesh.gmsh_file + "'");
        if (in.peek() == std::ifstream::traits_type::eof())
          throw InputError(mesh.gmsh_file, "the mesh file is empty");
        check_gmsh_layout(in, mesh.gmsh_file);
        in.clear();
        in.seekg(0);
        Triangulation<dim> serial;
        GridIn<dim>        grid_in(serial);
        try
          {
            grid_in.read_msh(in);
          }
        catch (const std::exception &e)
          {
            throw InputError(mesh.gmsh_file,
                             std::string("cannot read the Gmsh mesh: ") +
                               essential_message(e.what()));
          }
        if (serial.n_active_cells() == 0)
          throw InputError(mesh.gmsh_file, "the mesh has no cells");
        check_cells(serial, mesh.gmsh_file);
        tria.copy_triangulation(serial);
      }
    else
      {
        std::vector<std::unique_ptr<Triangulation<dim>>> parts;
        for (unsigned int b = 0; b < bodies.size(); ++b)
          {
            parts.push_back(std::make_unique<Triangulation<dim>>());
            build_body(bodies[b], material_ids[b], b, *parts.back(), manifolds);
          }
        combine(parts, tria);
      }

    for (const auto &m : manifolds)
      if (m.transfinite)
        {
          TransfiniteInterpolationManifold<dim> transfinite;
          transfinite.initialize(tria);
          tria.set_manifold(m.id, transfinite);
        }
      else
        tria.set_manifold(m.id, SphericalManifold<dim>(m.center));

    if (coarse_only)
      return;
    check_refined_size(tria.n_global_active_cells(), dim,
                       mesh.global_refinements, tria.get_communicator());
    tria.refine_global(mesh.global_refinements);

    if (mesh.local_refinements > 0)
      {
        if (mesh.local_center.size() != dim)
          throw InputError("Mesh > Local refinement center",
                           "needs " + std::to_string(dim) + " coordinates");
        Point<dim> center;
        for (unsigned int d = 0; d < dim; ++d)
          center[d] = mesh.local_center[d];
        for (unsigned int r = 0; r < mesh.local_refinements; ++r)
          {
            for (const auto &cell : tria.active_cell_iterators())
              if (cell->is_locally_owned())
                for (const auto v : cell->vertex_indices())
                  if (cell->vertex(v).distance(center) <= mesh.local_radius)
                    {
                      cell->set_refine_flag();
                      break;
                    }
            tria.execute_coarsening_and_refinement();
          }
      }
  }

  template void
  build_scene_mesh<2>(const MeshParameters &,
                      const std::vector<BodyGeometry> &,
                      const std::vector<types::material_id> &,
                      parallel::distributed::Triangulation<2> &,
                      const bool);
  template void
  build_scene_mesh<3>(const MeshParameters &,
                      const std::vector<BodyGeometry> &,
                      const std::vector<types::material_id> &,
                      parallel::distributed::Triangulation<3> &,
                      const bool);
} // namespace Signorini
