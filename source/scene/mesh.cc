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

    /// The first @p dim entries of @p x, comma-separated.
    std::string
    format_point(const std::vector<double> &x, const unsigned int dim)
    {
      std::string text;
      for (unsigned int d = 0; d < dim && d < x.size(); ++d)
        text += (d > 0 ? ", " : "") + format_count(x[d]);
      return text;
    }

    // The lengths a mesh can hold: a cell refined 30 times from a body of
    // size in [1e-30, 1e30] keeps its Jacobian and the normal equations of
    // its mapping (products of up to six lengths in 3D) within double's
    // range; 1e308 overflowed them and 1e-300 underflowed them (deal.II's
    // mapping then stopped the run: "Matrix of normal equations not
    // positive definite"). And a body's size must be told apart from its
    // position: below 1e-9 of its coordinates its vertices would coincide
    // after refinement.
    constexpr double min_length         = 1e-30;
    constexpr double max_length         = 1e30;
    constexpr double min_size_over_place = 1e-9;

    /// InputError naming @p key unless @p size fits a mesh placed at
    /// coordinates of magnitude up to @p place.
    void
    check_size(const double size, const double place, const std::string &key,
               const std::string &value)
    {
      if (!(std::abs(place) <= max_length))
        throw InputError(key, "'" + value + "' places the body beyond 1e30 "
                              "(a mesh's coordinates must lie within +-1e30)");
      if (!(size >= min_length && size <= max_length))
        throw InputError(key, "'" + value + "' gives a size of " +
                                format_count(size) +
                                "; a mesh holds sizes in [1e-30, 1e30]");
      if (!(size >= min_size_over_place * std::abs(place)))
        throw InputError(key, "'" + value + "' gives a size of " +
                                format_count(size) + " at coordinates of " +
                                format_count(place) +
                                ": below 1e-9 of them the mesh's vertices "
                                "could not be told apart");
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
      // The smallest node decides, the same way on every rank (each rank
      // reads its own node).
      memory = Utilities::MPI::min(memory, comm);
      if (!(memory > 0.))
        return;
      const double cores = Utilities::MPI::min(
        double(std::max(1u, std::thread::hardware_concurrency())), comm);
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
      for (const auto &vertex : tria.get_vertices())
        for (unsigned int d = 0; d < dim; ++d)
          if (!(std::abs(vertex[d]) <= max_length))
            {
              std::ostringstream msg;
              msg << "the vertex (" << vertex
                  << ") lies beyond 1e30: a mesh's coordinates must lie "
                     "within +-1e30";
              throw InputError(file, msg.str());
            }
      if (!(size >= min_length))
        throw InputError(file, "the mesh's size is " + format_count(size) +
                                 "; a mesh holds sizes in [1e-30, 1e30]");
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
                      Patterns::Selection("rectangle|quarter disk|half disk|die|"
                                          "octant ball|quarter ball|hemisphere|"
                                          "quarter cylinder|half cylinder|ring|half ring|"
                                          "tube|half tube"),
                      "Built-in shape of the body (used when Mesh > Source = "
                      "generated). y is vertical in 2D, z in 3D. "
                      "rectangle: a rectangle (2D) or box (3D) "
                      "with boundary ids 0/1 at x min/max, 2/3 at y min/max, "
                      "4/5 at z min/max. quarter disk (2D): the lower right "
                      "quarter {x >= cx, y <= cy} of the disk, ids 0 arc, "
                      "1 edge x = cx, 2 edge y = cy. half disk (2D): the "
                      "lower half {y <= cy}, ids 0 arc, 1 flat top. The "
                      "lowest point of a disk of center (0, R) touches y = 0 "
                      "at the origin. die: the rectangle (3D: box) between "
                      "the two corners whose bottom is replaced by a "
                      "circular arc (3D: a cylindrical surface along y) of "
                      "height 'Arc sag' through the lower edges x = x min "
                      "and x = x max; its lowest points are at the middle "
                      "of x. ids 0 the arc and both sides x = x min, x max "
                      "(the surface that can touch), 1 the top, in 3D 2/3 "
                      "the ends y min/max. octant ball (3D): {x >= cx, "
                      "y >= cy, z <= cz} of the ball, ids 0 sphere, 1 plane "
                      "x = cx, 2 flat top z = cz, 3 plane y = cy. quarter "
                      "ball (3D): {x >= cx, z <= cz}, ids 0 sphere, 1 plane "
                      "x = cx, 2 flat top. hemisphere (3D): {z <= cz}, ids "
                      "0 sphere, 1 flat top. A ball of center (0, 0, R) "
                      "touches z = 0 at the origin, which is a mesh vertex. "
                      "quarter cylinder (3D): the quarter disk {x >= cx, "
                      "z <= cz} of the x-z plane extruded along y over "
                      "'Length' (y in [cy - L/2, cy + L/2]), ids 0 curved "
                      "surface, 1 plane x = cx, 2 flat top z = cz, 3/4 the "
                      "ends y min/max. half cylinder (3D): the half disk "
                      "{z <= cz} extruded likewise, ids 0 curved surface, "
                      "1 flat top, 2/3 the ends y min/max. ring (2D): the "
                      "annulus 'Inner radius' <= |x - c| <= 'Radius' "
                      "around the Center, ids 0 inner circle, 1 outer "
                      "circle. half ring (2D): its right half {x >= cx}, "
                      "ids 0 inner arc, 1 outer arc, 2 the two straight "
                      "edges on x = cx. tube (3D): the ring's annulus in "
                      "the x-z plane extruded along y over 'Length' (y in "
                      "[cy - L/2, cy + L/2]), ids 0 inner surface, 1 outer "
                      "surface, 2/3 the ends y min/max. half tube (3D): its "
                      "half {x >= cx}, ids 0 inner, 1 outer, 2 the cut "
                      "plane x = cx, 3/4 the ends y min/max. Curved surfaces "
                      "carry a spherical or cylindrical manifold: refined "
                      "vertices lie on the exact surface.");
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
                      "Disks, ball parts and cylinders: center of the full "
                      "disk or ball [length], dim entries (3 for a ball part "
                      "or a cylinder; a cylinder's axis is the line through "
                      "it parallel to y).");
    prm.declare_entry("Radius", "1", Patterns::Double(),
                      "Disks, ball parts and cylinders: radius [length], > 0.");
    prm.declare_entry("Inner radius", "0.5", Patterns::Double(),
                      "Ring and half ring: radius of the inner circle "
                      "[length], > 0 and below 'Radius' (the outer one).");
    prm.declare_entry("Length",
                      "1",
                      Patterns::Double(),
                      "Quarter and half cylinder (3D): length along the axis "
                      "(parallel to y, centred on the Center's y) [length], "
                      "> 0. The coarse mesh has about one cell per half "
                      "radius along the axis.");
    prm.declare_entry("Arc sag",
                      "0.3",
                      Patterns::Double(),
                      "Die: height of the circular arc at the bottom "
                      "[length], > 0 and below the die's height (along y in "
                      "2D, z in 3D); the "
                      "radius is (w^2/4 + s^2)/(2 s) for width w and sag s.");
    prm.declare_entry("Orientation",
                      "down",
                      Patterns::Selection("down|up"),
                      "Disks (2D), ball parts and cylinders (3D): down: "
                      "the lower part {y <= cy} (2D) or {z <= cz} (3D), "
                      "its flat face the top; up: the upper part "
                      "{y >= cy} or {z >= cz}, the same x (and in 3D y) "
                      "ranges and boundary ids, its flat face the bottom "
                      "(e.g. the lower of two cylinders or balls pressed "
                      "together; its highest point is a mesh vertex). "
                      "Rectangle and die: must be down.");
    prm.declare_entry("Boundary id offset",
                      "0",
                      Patterns::Integer(0, 200),
                      "Added to every boundary id of this body, so that two "
                      "bodies of one scene get distinct ids (e.g. 10 for the "
                      "second body).");
    prm.enter_subsection("Placement");
    prm.declare_entry("Rotation angle",
                      "0",
                      Patterns::Double(),
                      "[degrees] The shape, built as its entries above say, "
                      "is turned by this angle about the line through the "
                      "origin along 'Rotation axis' (2D: about z, "
                      "counter-clockwise in the x-y plane; 3D: "
                      "counter-clockwise seen from the axis' tip), then "
                      "shifted by 'Translation': x -> Q x + t. Its "
                      "manifolds (a sphere's centre, a cylinder's axis) "
                      "move with it; its boundary ids stay those of the "
                      "shape. To turn a body about its own centre, build "
                      "it around the origin and translate it. Generated "
                      "meshes only (a Gmsh file is used as it is).");
    prm.declare_entry("Rotation axis",
                      "0, 0, 1",
                      Patterns::List(Patterns::Double(), 3, 3),
                      "3D: direction of the rotation axis (any length > "
                      "0). 2D: ignored (the axis is z).");
    prm.declare_entry("Translation",
                      "0, 0, 0",
                      Patterns::List(Patterns::Double(), 2, 3),
                      "[length] Added to every point of the shape after "
                      "the rotation, dim entries (extra entries are "
                      "ignored).");
    prm.leave_subsection();
  }

  bool
  BodyGeometry::placed() const
  {
    bool moved = rotation_angle != 0.;
    for (const double t : translation)
      moved = moved || t != 0.;
    return moved;
  }

  std::vector<unsigned int>
  BodyGeometry::boundary_ids(const unsigned int dim) const
  {
    // The ids 'Shape' documents (and build_body() sets): 0 .. n - 1.
    unsigned int n = 0;
    switch (shape)
      {
        case Shape::rectangle:
          n = 2 * dim;
          break;
        case Shape::quarter_disk:
        case Shape::quarter_ball:
          n = 3;
          break;
        case Shape::half_disk:
        case Shape::hemisphere:
          n = 2;
          break;
        case Shape::die:
          n = (dim == 3 ? 4 : 2);
          break;
        case Shape::octant_ball:
        case Shape::half_cylinder:
          n = 4;
          break;
        case Shape::quarter_cylinder:
          n = 5;
          break;
        case Shape::ring:
          n = 2;
          break;
        case Shape::half_ring:
          n = 3;
          break;
        case Shape::tube:
          n = 4;
          break;
        case Shape::half_tube:
          n = 5;
          break;
      }
    std::vector<unsigned int> ids;
    for (unsigned int i = 0; i < n; ++i)
      ids.push_back(i + boundary_id_offset);
    return ids;
  }

  void
  BodyGeometry::parse_parameters(ParameterHandler  &prm,
                                 const unsigned int dim,
                                 const std::string &context)
  {
    const std::string s = prm.get("Shape");
    shape = (s == "rectangle"        ? Shape::rectangle :
             s == "quarter disk"     ? Shape::quarter_disk :
             s == "die"              ? Shape::die :
             s == "octant ball"      ? Shape::octant_ball :
             s == "quarter ball"     ? Shape::quarter_ball :
             s == "hemisphere"       ? Shape::hemisphere :
             s == "quarter cylinder" ? Shape::quarter_cylinder :
             s == "half cylinder"    ? Shape::half_cylinder :
             s == "ring"             ? Shape::ring :
             s == "half ring"        ? Shape::half_ring :
             s == "tube"             ? Shape::tube :
             s == "half tube"        ? Shape::half_tube :
                                       Shape::half_disk);
    lower_corner       = get_list<double>(prm, "Lower corner", dim, context);
    upper_corner       = get_list<double>(prm, "Upper corner", dim, context);
    subdivisions       = get_list<unsigned int>(prm, "Subdivisions", dim, context);
    center             = get_list<double>(prm, "Center", dim, context);
    radius             = prm.get_double("Radius");
    length             = prm.get_double("Length");
    boundary_id_offset = prm.get_integer("Boundary id offset");
    arc_sag            = prm.get_double("Arc sag");
    upward             = (prm.get("Orientation") == "up");
    inner_radius       = prm.get_double("Inner radius");
    const bool ring = shape == Shape::ring || shape == Shape::half_ring ||
                      shape == Shape::tube || shape == Shape::half_tube;
    if (upward && (shape == Shape::rectangle || shape == Shape::die || ring))
      throw InputError(context + " > Orientation",
                       "'up' applies to the disks, ball parts and "
                       "cylinders, not to '" + s + "'");

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
    const bool only_2d = shape == Shape::quarter_disk || shape == Shape::half_disk ||
                         shape == Shape::ring || shape == Shape::half_ring;
    const bool only_3d = !only_2d && shape != Shape::rectangle &&
                         shape != Shape::die;
    if (only_2d && dim != 2)
      throw InputError(context + " > Shape",
                       "'" + s + "' is a 2D shape; in 3D use a ball part "
                       "(octant ball, quarter ball, hemisphere), a "
                       "quarter or half cylinder or a (half) tube");
    if (only_3d && dim != 3)
      throw InputError(context + " > Shape",
                       "'" + s + "' is a 3D shape; in 2D use a quarter disk, "
                       "a half disk or a (half) ring");
    if (shape == Shape::die)
      {
        const double height = upper_corner[dim - 1] - lower_corner[dim - 1];
        if (!(arc_sag > 0.) || !(arc_sag < height))
          throw InputError(context + " > Arc sag",
                           "must be > 0 and below the die's height " +
                             format_count(height) + ", got " +
                             prm.get("Arc sag"));
      }
    else if (shape != Shape::rectangle)
      {
        if (!(radius > 0.) || !std::isfinite(radius))
          throw InputError(context + " > Radius",
                           "must be > 0, got " + prm.get("Radius"));
        if (ring && !(inner_radius > 0. && inner_radius < radius &&
                      inner_radius >= min_size_over_place * radius))
          throw InputError(context + " > Inner radius",
                           "must be > 0 and below 'Radius' (" + prm.get("Radius") +
                             "), got " + prm.get("Inner radius"));
        if (extruded_along_y())
          {
            if (!(length > 0.) || !std::isfinite(length))
              throw InputError(context + " > Length",
                               "must be > 0, got " + prm.get("Length"));
            if (length / radius > max_coarse_cells / 4.)
              throw InputError(context + " > Length",
                               "'" + prm.get("Length") + "' is " +
                                 format_count(length / radius) +
                                 " radii: the coarse mesh would have more "
                                 "than " + format_count(max_coarse_cells) +
                                 " cells");
          }
      }
    // Sizes and places a mesh can hold (after the checks above, whose
    // messages say more where they apply).
    if (shape == Shape::rectangle || shape == Shape::die)
      for (unsigned int d = 0; d < dim; ++d)
        check_size(upper_corner[d] - lower_corner[d],
                   std::max(std::abs(lower_corner[d]), std::abs(upper_corner[d])),
                   context + " > Upper corner",
                   format_point(lower_corner, dim) + "' to '" +
                     format_point(upper_corner, dim));
    else
      {
        double place = 0.;
        for (unsigned int d = 0; d < dim; ++d)
          place = std::max(place, std::abs(center[d]));
        if (!(place <= max_length))
          throw InputError(context + " > Center",
                           "'" + prm.get("Center") +
                             "': a mesh's coordinates must lie within +-1e30");
        check_size(radius, place, context + " > Radius", prm.get("Radius"));
        if (extruded_along_y())
          check_size(length, place, context + " > Length", prm.get("Length"));
      }
    parse_placement(prm, dim, context);
  }

  void
  BodyGeometry::parse_placement(ParameterHandler  &prm,
                                const unsigned int dim,
                                const std::string &context)
  {
    const std::string where = context + " > Placement";
    prm.enter_subsection("Placement");
    const double degrees = prm.get_double("Rotation angle");
    if (!std::isfinite(degrees))
      throw InputError(where + " > Rotation angle",
                       "must be a finite number, got " + prm.get("Rotation angle"));
    rotation_angle = degrees * numbers::PI / 180.;
    rotation_axis  = get_list<double>(prm, "Rotation axis", 3, where);
    translation    = get_list<double>(prm, "Translation", dim, where);
    const std::string translation_text = prm.get("Translation");
    prm.leave_subsection();
    const double axis_length =
      std::sqrt(rotation_axis[0] * rotation_axis[0] + rotation_axis[1] * rotation_axis[1] +
                rotation_axis[2] * rotation_axis[2]);
    if (dim == 3 && rotation_angle != 0. && !(axis_length > 0.))
      throw InputError(where + " > Rotation axis",
                       "must not be zero when 'Rotation angle' is not 0");
    if (dim == 3 && axis_length > 0.)
      for (double &x : rotation_axis)
        x /= axis_length;
    if (!placed())
      return;
    // The shape's size and the largest coordinate it can reach once placed
    // (a rotation about the origin keeps the distance from it), as the
    // checks above ask of an unplaced shape.
    double size = 0., place = 0.;
    if (shape == Shape::rectangle || shape == Shape::die)
      {
        size = std::numeric_limits<double>::max();
        for (unsigned int d = 0; d < dim; ++d)
          {
            size  = std::min(size, upper_corner[d] - lower_corner[d]);
            place = std::max({place, std::abs(lower_corner[d]), std::abs(upper_corner[d])});
          }
      }
    else
      {
        const bool cylinder = extruded_along_y();
        size = cylinder ? std::min(radius, length) : radius;
        for (unsigned int d = 0; d < dim; ++d)
          place = std::max(place, std::abs(center[d]) + radius +
                                    (cylinder ? 0.5 * length : 0.));
      }
    double shift = 0.;
    for (unsigned int d = 0; d < dim; ++d)
      shift = std::max(shift, std::abs(translation[d]));
    const double reach = std::sqrt(double(dim)) * place + shift;
    if (!(reach <= max_length))
      throw InputError(where + " > Translation",
                       "'" + translation_text + "' places the body beyond 1e30 "
                       "(a mesh's coordinates must lie within +-1e30)");
    if (!(size >= min_size_over_place * reach))
      throw InputError(where + " > Translation",
                       "'" + translation_text + "' moves a body of size " +
                         format_count(size) + " to coordinates of up to " +
                         format_count(reach) +
                         ": below 1e-9 of them the mesh's vertices could "
                         "not be told apart");
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
                      Patterns::Anything(),
                      "Center of the locally refined ball [length], dim "
                      "coordinates; several balls (the contact zones of a "
                      "scene with several contact pairs) as points "
                      "separated by ';', e.g. '0, 0; 0, 2; 0, 4'.");
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
    local_center_count = 0;
    for (const auto &point :
         Utilities::split_string_list(prm.get("Local refinement center"), ';'))
      {
        const auto coordinates = Utilities::split_string_list(point);
        if (coordinates.size() < 2 || coordinates.size() > 3)
          throw InputError("Mesh > Local refinement center",
                           "each point needs 2 or 3 coordinates, got '" + point + "'");
        for (const auto &v : coordinates)
          {
            char        *end   = nullptr;
            const double value = std::strtod(v.c_str(), &end);
            if (v.empty() || *end != '\0' || !std::isfinite(value))
              throw InputError("Mesh > Local refinement center",
                               "'" + v + "' is not a finite number");
            local_center.push_back(value);
          }
        ++local_center_count;
      }
    if (local_center_count == 0)
      throw InputError("Mesh > Local refinement center", "needs at least one point");
    local_radius = prm.get_double("Local refinement radius");
    if (local_refinements > 0 && !(local_radius > 0.))
      throw InputError("Mesh > Local refinement radius",
                       "must be > 0 when Local refinements > 0");
  }

  namespace
  {
    template <int dim>
    Tensor<1, dim>
    unit_vector(const unsigned int direction)
    {
      Tensor<1, dim> e;
      e[direction] = 1.;
      return e;
    }

    /// A manifold to attach to the final mesh.
    template <int dim>
    struct ManifoldSpec
    {
      enum class Kind
      {
        spherical,   // SphericalManifold around center
        cylindrical, // CylindricalManifold, axis along y through center
        transfinite
      };
      types::manifold_id id;
      Kind               kind;
      Point<dim>         center;
      /// The cylinder's axis: along y unless the body was turned.
      Tensor<1, dim>     axis = unit_vector<dim>(1);
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

    template <int dim>
    void
    build_body(const BodyGeometry             &g,
               const types::material_id        material_id,
               const unsigned int              body_index,
               Triangulation<dim>             &tria,
               std::vector<ManifoldSpec<dim>> &manifolds);

    /// The boundary faces of a generated body whose vertices all lie on the
    /// plane x_axis = value get the boundary id @p id.
    struct PlanarPart
    {
      unsigned int       axis;
      double             value;
      types::boundary_id id;
    };

    /**
     * Boundary and manifold ids of a curved 3D body: a cell with a boundary
     * face on one of @p planes gets the flat manifold (on the cell, its
     * faces and edges), every other cell the transfinite one. (With the
     * transfinite manifold on a cell whose face is flat, deal.II 9.4's
     * degree 2 mapping of the parent and the vertices of its children do
     * not agree on that face: after Kelly's indicator refined rim cells of
     * hertz_sphere's loaded flat top, the applied load was 2.3e-4 below
     * P/4; with flat cells 1.6e-7, doc/accuracy-cost.md.) A boundary face
     * on one of @p planes gets that
     * plane's id and the flat manifold (on the face and its edges); every
     * other boundary face is the curved surface: id 0 and @p curved_id on
     * the face and its edges. The curved faces come last, so that an edge
     * shared by a plane and the curved surface (the rim of a flat top)
     * follows the curve.
     */
    void
    assign_curved_ids(Triangulation<3>              &tria,
                      const std::vector<PlanarPart> &planes,
                      const double                   tol,
                      const types::manifold_id       curved_id,
                      const types::manifold_id       transfinite_id)
    {
      const auto on_a_plane = [&](const Triangulation<3>::face_iterator &face) {
        for (const auto &plane : planes)
          {
            bool on_plane = true;
            for (const auto v : face->vertex_indices())
              on_plane = on_plane && std::abs(face->vertex(v)[plane.axis] - plane.value) < tol;
            if (on_plane)
              return &plane;
          }
        return static_cast<const PlanarPart *>(nullptr);
      };
      for (const auto &cell : tria.active_cell_iterators())
        {
          bool touches_plane = false;
          for (const auto &face : cell->face_iterators())
            touches_plane = touches_plane || (face->at_boundary() && on_a_plane(face));
          cell->set_all_manifold_ids(touches_plane ? numbers::flat_manifold_id :
                                                    transfinite_id);
        }
      std::vector<Triangulation<3>::face_iterator> curved;
      for (const auto &cell : tria.active_cell_iterators())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary())
            {
              if (const PlanarPart *plane = on_a_plane(face))
                {
                  face->set_boundary_id(plane->id);
                  face->set_all_manifold_ids(numbers::flat_manifold_id);
                }
              else
                {
                  face->set_boundary_id(0);
                  curved.push_back(face);
                }
            }
      for (const auto &face : curved)
        face->set_all_manifold_ids(curved_id);
    }

    /**
     * A ball part (3D): deal.II's octant {x, y, z >= 0} of the ball around
     * the origin (quarter_hyper_ball); the quarter {y >= 0, z >= 0} and the
     * half {z >= 0} are two and four copies of it turned about z by
     * multiples of 90 degrees (vertices merged). The rotation
     * (x, y, z) -> (y, x, -z) turns them into the lower parts named in
     * BodyGeometry, which are then shifted to the center.
     */
    void
    build_ball_part(const BodyGeometry           &g,
                    const unsigned int            body_index,
                    Triangulation<3>             &tria,
                    std::vector<ManifoldSpec<3>> &manifolds)
    {
      using Shape                 = BodyGeometry::Shape;
      const unsigned int copies   = (g.shape == Shape::octant_ball  ? 1 :
                                     g.shape == Shape::quarter_ball ? 2 :
                                                                      4);
      std::vector<std::unique_ptr<Triangulation<3>>> parts;
      for (unsigned int k = 0; k < copies; ++k)
        {
          parts.push_back(std::make_unique<Triangulation<3>>());
          GridGenerator::quarter_hyper_ball(*parts.back(), Point<3>(), g.radius);
          // k quarter turns about z: (x, y) -> (-y, x), exact in floating point.
          GridTools::transform(
            [k](const Point<3> &p) {
              Point<3> q = p;
              for (unsigned int turn = 0; turn < k; ++turn)
                q = Point<3>(-q[1], q[0], q[2]);
              return q;
            },
            *parts.back());
        }
      if (copies == 1)
        tria.copy_triangulation(*parts[0]);
      else
        {
          std::vector<const Triangulation<3> *> pointers;
          for (const auto &part : parts)
            pointers.push_back(part.get());
          GridGenerator::merge_triangulations(pointers, tria, 1e-10 * g.radius);
        }
      tria.reset_all_manifolds();
      const Point<3> center(g.center[0], g.center[1], g.center[2]);
      // Before this, the octant is {x, y, z >= 0}, the quarter ball
      // {y, z >= 0}, the hemisphere {z >= 0}. Down: the half turn about the
      // line x = y, z = 0. Up: the octant and the hemisphere as they are,
      // the quarter ball turned by -90 degrees about z into {x, z >= 0}.
      if (!g.upward)
        GridTools::transform(
          [&](const Point<3> &p) { return center + Point<3>(p[1], p[0], -p[2]); }, tria);
      else if (g.shape == Shape::quarter_ball)
        GridTools::transform(
          [&](const Point<3> &p) { return center + Point<3>(p[1], -p[0], p[2]); }, tria);
      else
        GridTools::transform([&](const Point<3> &p) { return center + p; }, tria);

      std::vector<PlanarPart> planes;
      if (g.shape == Shape::hemisphere)
        planes.push_back({2, center[2], 1});
      else
        {
          planes.push_back({0, center[0], 1});
          planes.push_back({2, center[2], 2});
        }
      if (g.shape == Shape::octant_ball)
        planes.push_back({1, center[1], 3});
      const types::manifold_id sphere_id      = 2 * body_index;
      const types::manifold_id transfinite_id = 2 * body_index + 1;
      assign_curved_ids(tria, planes, 1e-8 * g.radius, sphere_id, transfinite_id);
      manifolds.push_back({sphere_id, ManifoldSpec<3>::Kind::spherical, center});
      manifolds.push_back({transfinite_id, ManifoldSpec<3>::Kind::transfinite, center});
    }

    /**
     * A 3D body that is a 2D section extruded along y: the quarter or half
     * cylinder (section: the quarter or half disk) and the 3D die (section:
     * the 2D die). The section is built in the x-z plane as the 2D shape in
     * (x, y), extruded over the length, and turned by the rotation
     * (x, y, z) -> (x, y_max - z, y) about x, which takes the section's
     * vertical y to z. The curved surface gets a CylindricalManifold along
     * y through the section's arc center.
     */
    void
    build_extruded(const BodyGeometry           &g,
                   const unsigned int            body_index,
                   Triangulation<3>             &tria,
                   std::vector<ManifoldSpec<3>> &manifolds)
    {
      using Shape          = BodyGeometry::Shape;
      BodyGeometry section = g;
      section.boundary_id_offset = 0;
      double       y_min = 0., y_max = 0., size = 0.;
      unsigned int slices = 1;
      if (g.shape == Shape::die)
        {
          section.lower_corner = {g.lower_corner[0], g.lower_corner[2]};
          section.upper_corner = {g.upper_corner[0], g.upper_corner[2]};
          section.subdivisions = {g.subdivisions[0], g.subdivisions[2]};
          y_min                = g.lower_corner[1];
          y_max                = g.upper_corner[1];
          slices               = g.subdivisions[1];
          for (unsigned int d = 0; d < 3; ++d)
            size = std::max(size, g.upper_corner[d] - g.lower_corner[d]);
        }
      else
        {
          section.shape =
            (g.shape == Shape::quarter_cylinder ? Shape::quarter_disk : Shape::half_disk);
          section.center = {g.center[0], g.center[2]};
          y_min          = g.center[1] - 0.5 * g.length;
          y_max          = g.center[1] + 0.5 * g.length;
          // About one coarse cell per half radius along the axis, as in
          // the section.
          slices = std::max(1l, std::lround(g.length / (0.5 * g.radius)));
          size   = std::max(g.radius, g.length);
        }
      Triangulation<2>             flat;
      std::vector<ManifoldSpec<2>> section_manifolds;
      build_body<2>(section, 0, 0, flat, section_manifolds);
      const Point<2> arc_center = section_manifolds.front().center;
      // extrude_triangulation() takes the number of vertex layers, one
      // more than the cell layers asked for.
      GridGenerator::extrude_triangulation(flat, slices + 1, y_max - y_min, tria);
      tria.reset_all_manifolds();
      GridTools::transform(
        [y_max](const Point<3> &p) { return Point<3>(p[0], y_max - p[2], p[1]); },
        tria);

      // Then the ends y_min, y_max get the next two ids.
      std::vector<PlanarPart> planes;
      types::boundary_id      next = 2;
      if (g.shape == Shape::die)
        {
          planes.push_back({2, g.upper_corner[2], 1});
          planes.push_back({0, g.lower_corner[0], 0});
          planes.push_back({0, g.upper_corner[0], 0});
        }
      else if (g.shape == Shape::quarter_cylinder)
        {
          planes.push_back({0, g.center[0], 1});
          planes.push_back({2, g.center[2], 2});
          next = 3;
        }
      else
        planes.push_back({2, g.center[2], 1});
      planes.push_back({1, y_min, next});
      planes.push_back({1, y_max, types::boundary_id(next + 1)});
      const types::manifold_id curved_id      = 2 * body_index;
      const types::manifold_id transfinite_id = 2 * body_index + 1;
      assign_curved_ids(tria, planes, 1e-8 * size, curved_id, transfinite_id);
      const Point<3> axis_point(arc_center[0], 0., arc_center[1]);
      manifolds.push_back({curved_id, ManifoldSpec<3>::Kind::cylindrical, axis_point});
      manifolds.push_back({transfinite_id, ManifoldSpec<3>::Kind::transfinite, axis_point});
    }

    /**
     * A tube or half tube: the ring or half ring in the x-z plane (built as
     * in 2D), extruded along y over the length and turned so that y is the
     * axis, with one CylindricalManifold on every cell (the cut plane and
     * the ends keep their angle or their y under it). Ids by position:
     * 0 inner, 1 outer surface, (half tube: 2 the cut plane x = cx,) then
     * the ends y min, y max.
     */
    void
    build_tube(const BodyGeometry           &g,
               const unsigned int            body_index,
               Triangulation<3>             &tria,
               std::vector<ManifoldSpec<3>> &manifolds)
    {
      using Shape                = BodyGeometry::Shape;
      const bool   half          = g.shape == Shape::half_tube;
      BodyGeometry section       = g;
      section.boundary_id_offset = 0;
      section.shape              = half ? Shape::half_ring : Shape::ring;
      section.center             = {g.center[0], g.center[2]};
      const double y_min         = g.center[1] - 0.5 * g.length;
      const double y_max         = g.center[1] + 0.5 * g.length;
      const double wall          = g.radius - g.inner_radius;
      // About square coarse cells along the axis, as across the wall.
      const unsigned int slices  = std::max(1l, std::lround(g.length / wall));
      Triangulation<2>             flat;
      std::vector<ManifoldSpec<2>> section_manifolds;
      build_body<2>(section, 0, 0, flat, section_manifolds);
      GridGenerator::extrude_triangulation(flat, slices + 1, g.length, tria);
      tria.reset_all_manifolds();
      // (x, y, z) of the extrusion -> (x, y_max - z, y): the section's y
      // becomes z and the extrusion runs along y (a rotation: the cells
      // keep their orientation).
      GridTools::transform(
        [y_max](const Point<3> &p) { return Point<3>(p[0], y_max - p[2], p[1]); },
        tria);
      const Point<3>           axis_point(g.center[0], 0., g.center[2]);
      const types::manifold_id tube_id = 2 * body_index;
      const double             tol     = 1e-8 * std::max(g.radius, g.length);
      const auto radius_of = [&](const Point<3> &p) {
        return std::hypot(p[0] - g.center[0], p[2] - g.center[2]);
      };
      for (const auto &cell : tria.active_cell_iterators())
        {
          cell->set_all_manifold_ids(tube_id);
          for (const auto &face : cell->face_iterators())
            if (face->at_boundary())
              {
                bool inner = true, outer = true, cut = true, low = true, high = true;
                for (const auto v : face->vertex_indices())
                  {
                    const Point<3> p = face->vertex(v);
                    inner = inner && std::abs(radius_of(p) - g.inner_radius) < tol;
                    outer = outer && std::abs(radius_of(p) - g.radius) < tol;
                    cut   = cut && std::abs(p[0] - g.center[0]) < tol;
                    low   = low && std::abs(p[1] - y_min) < tol;
                    high  = high && std::abs(p[1] - y_max) < tol;
                  }
                const types::boundary_id ends = half ? 3 : 2;
                face->set_boundary_id(inner ? 0 :
                                      outer ? 1 :
                                      low   ? ends :
                                      high  ? ends + 1 :
                                      cut   ? 2 :
                                              numbers::invalid_boundary_id);
                Assert(inner || outer || cut || low || high, ExcInternalError());
              }
        }
      manifolds.push_back({tube_id, ManifoldSpec<3>::Kind::cylindrical, axis_point});
    }

    template <int dim>
    void
    build_curved_3d(const BodyGeometry             &g,
                    const unsigned int              body_index,
                    Triangulation<dim>             &tria,
                    std::vector<ManifoldSpec<dim>> &manifolds)
    {
      if constexpr (dim == 3)
        {
          using Shape = BodyGeometry::Shape;
          if (g.shape == Shape::octant_ball || g.shape == Shape::quarter_ball ||
              g.shape == Shape::hemisphere)
            build_ball_part(g, body_index, tria, manifolds);
          else if (g.shape == Shape::tube || g.shape == Shape::half_tube)
            build_tube(g, body_index, tria, manifolds);
          else
            build_extruded(g, body_index, tria, manifolds);
        }
      else
        {
          (void)g;
          (void)body_index;
          (void)tria;
          (void)manifolds;
          Assert(false, ExcInternalError());
        }
    }

    /**
     * Build one body's coarse mesh (the 3D curved shapes: above). Disks are generated around the origin
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
      if (dim == 3 && g.shape != BodyGeometry::Shape::rectangle)
        build_curved_3d(g, body_index, tria, manifolds);
      else if (g.shape == BodyGeometry::Shape::rectangle)
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
          manifolds.push_back({arc_id, ManifoldSpec<dim>::Kind::spherical, center});
          manifolds.push_back(
            {transfinite_id, ManifoldSpec<dim>::Kind::transfinite, center});
        }
      else if (g.shape == BodyGeometry::Shape::ring ||
               g.shape == BodyGeometry::Shape::half_ring)
        {
          // The annulus in polar cells: about square cells around the
          // half circumference (the full ring has twice the half ring's
          // cells, so that the two meshes are the same on x >= cx).
          Assert(dim == 2, ExcInternalError());
          const Point<dim>   center = to_point<dim>(g.center);
          const unsigned int half_cells = static_cast<unsigned int>(std::ceil(
            0.5 * numbers::PI * (g.radius + g.inner_radius) / (g.radius - g.inner_radius)));
          if (g.shape == BodyGeometry::Shape::ring)
            GridGenerator::hyper_shell(tria, center, g.inner_radius, g.radius,
                                       2 * std::max(half_cells, 2u));
          else
            GridGenerator::half_hyper_shell(tria, center, g.inner_radius, g.radius,
                                            std::max(half_cells, 2u));
          tria.reset_all_manifolds();
          const types::manifold_id polar_id = 2 * body_index;
          const double             tol      = 1e-8 * g.radius;
          for (const auto &cell : tria.active_cell_iterators())
            {
              cell->set_all_manifold_ids(polar_id);
              for (const auto &face : cell->face_iterators())
                if (face->at_boundary())
                  {
                    auto on_circle = [&](const double r) {
                      return std::abs(face->vertex(0).distance(center) - r) < tol &&
                             std::abs(face->vertex(1).distance(center) - r) < tol;
                    };
                    if (on_circle(g.inner_radius))
                      face->set_boundary_id(0);
                    else if (on_circle(g.radius))
                      face->set_boundary_id(1);
                    else
                      {
                        face->set_boundary_id(2);
                        face->set_manifold_id(numbers::flat_manifold_id);
                      }
                  }
            }
          manifolds.push_back({polar_id, ManifoldSpec<dim>::Kind::spherical, center});
        }
      else
        {
          Assert(dim == 2, ExcInternalError());
          const Point<dim> origin;
          const bool       quarter = (g.shape == BodyGeometry::Shape::quarter_disk);
          if (quarter)
            GridGenerator::quarter_hyper_ball(tria, origin, g.radius);
          else
            GridGenerator::half_hyper_ball(tria, origin, g.radius);
          tria.reset_all_manifolds();
          const Point<dim> center = to_point<dim>(g.center);
          // Down: turned by -90 degrees, (x, y) -> (y, -x). Up: the
          // quarter as it is, the half turned by +90 degrees,
          // (x, y) -> (-y, x), into {y >= 0}.
          GridTools::transform(
            [&](const Point<dim> &p) {
              Point<dim> q = center;
              if (!g.upward)
                {
                  q[0] += p[1];
                  q[1] -= p[0];
                }
              else if (quarter)
                q += p;
              else
                {
                  q[0] -= p[1];
                  q[1] += p[0];
                }
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
          manifolds.push_back({arc_id, ManifoldSpec<dim>::Kind::spherical, center});
          manifolds.push_back(
            {transfinite_id, ManifoldSpec<dim>::Kind::transfinite, center});
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
     * The placement of @p g, x -> Q x + t (BodyGeometry), applied to the
     * built body @p tria and to its manifolds, @p manifolds[first] on:
     * centres and axis points move as points, a cylinder's axis direction
     * turns. Q by Rodrigues' formula about the unit axis k,
     * Q v = v cos(a) + (k x v) sin(a) + k (k . v)(1 - cos(a)); in 2D k = z.
     */
    template <int dim>
    void
    place_body(const BodyGeometry             &g,
               Triangulation<dim>             &tria,
               std::vector<ManifoldSpec<dim>> &manifolds,
               const std::size_t               first)
    {
      if (!g.placed())
        return;
      const double c = std::cos(g.rotation_angle), s = std::sin(g.rotation_angle);
      const auto   turn = [&](const Tensor<1, dim> &v) {
        Tensor<1, dim> q;
        if constexpr (dim == 2)
          {
            q[0] = c * v[0] - s * v[1];
            q[1] = s * v[0] + c * v[1];
          }
        else
          {
            Tensor<1, 3> k;
            for (unsigned int d = 0; d < 3; ++d)
              k[d] = g.rotation_axis[d];
            q = v * c + cross_product_3d(k, v) * s + k * ((k * v) * (1. - c));
          }
        return q;
      };
      Tensor<1, dim> shift;
      for (unsigned int d = 0; d < dim; ++d)
        shift[d] = g.translation[d];
      const auto place = [&](const Point<dim> &p) {
        return Point<dim>(turn(p) + shift);
      };
      GridTools::transform(place, tria);
      for (std::size_t m = first; m < manifolds.size(); ++m)
        {
          manifolds[m].center = place(manifolds[m].center);
          manifolds[m].axis   = turn(manifolds[m].axis);
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
          if constexpr (dim == 3)
            part->clear_user_flags_line();
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
              // In 3D the edges carry their own manifold ids (the rim of
              // a flat top follows the curved surface): each edge once.
              if constexpr (dim == 3)
                for (unsigned int l = 0; l < cell->n_lines(); ++l)
                  {
                    const auto line = cell->line(l);
                    if (line->manifold_id() == numbers::flat_manifold_id ||
                        line->user_flag_set())
                      continue;
                    line->set_user_flag();
                    CellData<1> e;
                    e.vertices[0] = offset + line->vertex_index(0);
                    e.vertices[1] = offset + line->vertex_index(1);
                    e.boundary_id = line->at_boundary() ?
                                      line->boundary_id() :
                                      numbers::internal_face_boundary_id;
                    e.manifold_id = line->manifold_id();
                    subcells.boundary_lines.push_back(e);
                  }
            }
        }
      GridTools::delete_unused_vertices(vertices, cells, subcells);
      // Lines in standard orientation: on several ranks deal.II 9.4's DoF
      // distribution left DoFs of hanging vertices on no cell for the
      // octant ball, whose coarse cells (deal.II's octant, turned) have
      // lines in both orientations.
      GridTools::consistently_order_cells(cells);
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
            const std::size_t first = manifolds.size();
            build_body(bodies[b], material_ids[b], b, *parts.back(), manifolds);
            place_body(bodies[b], *parts.back(), manifolds, first);
          }
        combine(parts, tria);
      }

    for (const auto &m : manifolds)
      if (m.kind == ManifoldSpec<dim>::Kind::transfinite)
        {
          TransfiniteInterpolationManifold<dim> transfinite;
          transfinite.initialize(tria);
          tria.set_manifold(m.id, transfinite);
        }
      else if (m.kind == ManifoldSpec<dim>::Kind::spherical)
        tria.set_manifold(m.id, SphericalManifold<dim>(m.center));
      else if constexpr (dim == 3)
        tria.set_manifold(m.id, CylindricalManifold<dim>(m.axis, m.center));

    if (coarse_only)
      return;
    check_refined_size(tria.n_global_active_cells(), dim,
                       mesh.global_refinements, tria.get_communicator());
    tria.refine_global(mesh.global_refinements);

    if (mesh.local_refinements > 0)
      {
        if (mesh.local_center.size() != dim * mesh.local_center_count)
          throw InputError("Mesh > Local refinement center",
                           "needs " + std::to_string(dim) + " coordinates" +
                             (mesh.local_center_count > 1 ? " per point" : ""));
        std::vector<Point<dim>> centers(mesh.local_center_count);
        for (unsigned int p = 0; p < centers.size(); ++p)
          for (unsigned int d = 0; d < dim; ++d)
            centers[p][d] = mesh.local_center[p * dim + d];
        const auto inside = [&](const Point<dim> &x) {
          for (const auto &center : centers)
            if (x.distance(center) <= mesh.local_radius)
              return true;
          return false;
        };
        for (unsigned int r = 0; r < mesh.local_refinements; ++r)
          {
            for (const auto &cell : tria.active_cell_iterators())
              if (cell->is_locally_owned())
                for (const auto v : cell->vertex_indices())
                  if (inside(cell->vertex(v)))
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
