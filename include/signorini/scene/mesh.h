#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/grid/tria.h>

#include <string>
#include <vector>

namespace Signorini
{
  using namespace dealii;

  /**
   * The built-in shape of one body, from its "Geometry" subsection. In 2D
   * y is vertical, in 3D z is (the foundation is x_d = psi(x')).
   *
   * Boundary ids (before 'Boundary id offset' is added):
   * - rectangle/box: 0 x = x_min, 1 x = x_max, 2 y = y_min, 3 y = y_max,
   *   4 z = z_min, 5 z = z_max;
   * - quarter disk (2D, the lower right quarter x >= cx, y <= cy): 0 the
   *   arc, 1 the edge x = cx (symmetry), 2 the edge y = cy (flat top);
   * - half disk (2D, the lower half y <= cy): 0 the arc, 1 the flat top
   *   y = cy;
   * - die (a rectangle, in 3D a box, whose bottom is a circular arc, in 3D
   *   a cylindrical surface along y, of height 'Arc sag' through the lower
   *   edges x = x_min and x = x_max): 0 the arc and both sides x = x_min,
   *   x = x_max, 1 the top; in 3D also 2 the end y = y_min, 3 the end
   *   y = y_max;
   * - octant ball (3D, x >= cx, y >= cy, z <= cz): 0 the sphere, 1 the
   *   plane x = cx, 2 the flat top z = cz, 3 the plane y = cy;
   * - quarter ball (3D, x >= cx, z <= cz): 0 the sphere, 1 the plane
   *   x = cx, 2 the flat top z = cz;
   * - hemisphere (3D, z <= cz): 0 the sphere, 1 the flat top z = cz;
   * - with 'Orientation = up' the disks, ball parts and cylinders are
   *   the upper ones (y >= cy in 2D, z >= cz in 3D, the same x (and y)
   *   ranges and ids); their flat face (quarter disk, octant and quarter
   *   ball, quarter cylinder id 2; half disk, hemisphere, half cylinder
   *   id 1) is then the bottom;
   * - quarter cylinder (3D, the quarter disk in the x-z plane extruded
   *   along y over 'Length', centred on cy): 0 the curved surface, 1 the
   *   plane x = cx, 2 the flat top z = cz, 3 the end y = cy - L/2, 4 the
   *   end y = cy + L/2;
   * - half cylinder (3D, the half disk z <= cz extruded likewise): 0 the
   *   curved surface, 1 the flat top, 2 the end y = cy - L/2, 3 the end
   *   y = cy + L/2.
   * The ball parts are one, two or four copies of deal.II's octant
   * (quarter_hyper_ball), so that the lowest point of the ball is a mesh
   * vertex.
   *
   * Placement (the "Placement" subsection): the shape built as above is
   * turned by 'Rotation angle' about the line through the origin along
   * 'Rotation axis' (2D: about z) and then shifted by 'Translation',
   * x -> Q x + t, with its manifolds (a sphere's centre, a cylinder's
   * axis); the boundary ids stay those of the shape.
   */
  struct BodyGeometry
  {
    enum class Shape
    {
      rectangle,
      quarter_disk,
      half_disk,
      die,
      octant_ball,
      quarter_ball,
      hemisphere,
      quarter_cylinder,
      half_cylinder,
      ring,
      half_ring,
      tube,
      half_tube
    };

    /// A quarter or half cylinder, a tube or a half tube: a 2D section
    /// extruded along y over 'Length'.
    bool
    extruded_along_y() const
    {
      return shape == Shape::quarter_cylinder || shape == Shape::half_cylinder ||
             shape == Shape::tube || shape == Shape::half_tube;
    }

    Shape                     shape = Shape::rectangle;
    std::vector<double>       lower_corner;
    std::vector<double>       upper_corner;
    std::vector<unsigned int> subdivisions;
    std::vector<double>       center;
    double                    radius             = 1.;
    double                    inner_radius       = 0.5; // ring, half ring
    double                    length             = 1.;
    double                    arc_sag            = 0.3;
    /// Disks, ball parts, cylinders: the upper part (y >= cy in 2D,
    /// z >= cz in 3D) instead of the lower one.
    bool                      upward             = false;
    unsigned int              boundary_id_offset = 0;
    /// Placement: x -> Q x + t, Q the rotation by rotation_angle (radians,
    /// counter-clockwise seen from the tip of rotation_axis; in 2D about
    /// z) and t the translation (dim entries).
    std::vector<double>       translation;
    std::vector<double>       rotation_axis{0., 0., 1.};
    double                    rotation_angle = 0.;

    /// Whether the placement moves the shape at all.
    bool
    placed() const;

    /// The boundary ids of the built shape in dimension @p dim (the
    /// shape's ids, documented with 'Shape', plus 'Boundary id offset').
    std::vector<unsigned int>
    boundary_ids(const unsigned int dim) const;

    static void
    declare_parameters(ParameterHandler &prm);

    /// @p context is the subsection path used in error messages.
    void
    parse_parameters(ParameterHandler  &prm,
                     const unsigned int dim,
                     const std::string &context);

  private:
    /// The "Placement" subsection, checked against the shape's size.
    void
    parse_placement(ParameterHandler  &prm,
                    const unsigned int dim,
                    const std::string &context);
  };

  /// The "Mesh" subsection: where the scene's coarse mesh comes from.
  struct MeshParameters
  {
    enum class Source
    {
      generated,
      gmsh
    };
    Source       source = Source::generated;
    std::string  gmsh_file;
    unsigned int global_refinements = 0;
    unsigned int        local_refinements = 0;
    /// The centres of the locally refined balls, dim numbers each.
    std::vector<double> local_center;
    unsigned int        local_center_count = 1;
    double              local_radius = 0.;

    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm, const std::string &prm_directory);
  };

  /**
   * Build the coarse scene mesh into @p tria and refine it globally:
   * either one generated coarse mesh per body (cells of body b carry
   * material id @p material_ids[b]; the bodies keep their own vertices,
   * so bodies that touch are not glued together), or a Gmsh file whose
   * physical tags give material and boundary ids. Curved boundaries get
   * a SphericalManifold (a CylindricalManifold for the cylinders and the
   * 3D die; on their faces and, in 3D, their edges) and the cells of the
   * curved body a transfinite interpolation, so refinement follows the
   * geometry. After the
   * global refinements, 'Local refinements' more levels are added to the
   * cells that have a vertex within 'Local refinement radius' of
   * 'Local refinement center' (a contact zone, say); p4est keeps
   * neighbouring levels within one of each other (hanging nodes).
   */
  /// With @p coarse_only: no refinement (the coarse mesh that a
  /// checkpoint's refined mesh is loaded into).
  template <int dim>
  void
  build_scene_mesh(const MeshParameters                      &mesh,
                   const std::vector<BodyGeometry>           &bodies,
                   const std::vector<types::material_id>     &material_ids,
                   parallel::distributed::Triangulation<dim> &tria,
                   const bool                                 coarse_only = false);
} // namespace Signorini
