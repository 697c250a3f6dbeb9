// The surfaces and curves of a 3D gmsh model as the bodies' geometry, as
// model_curves.h does for a 2D one: each surface of a script, sampled by
// gmsh's CAD kernel with its normals (gmsh_process.cc), recognised as a
// plane, a sphere or a cylinder, and attached to the boundary faces that
// lie on it as deal.II's SphericalManifold or CylindricalManifold; the
// lines of those faces on a circle of the model get that circle. Refinement
// then puts new vertices on the model's surfaces (a sphere refined stays a
// sphere), and a mapping of degree >= 2 curves the cells beside them.
#ifndef ring_contact_input_model_surfaces_h
#define ring_contact_input_model_surfaces_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/grid/tria.h>

#include <ring_contact/input/gmsh_file.h>

#include <vector>

namespace RingContact
{
  using namespace dealii;

  namespace Geometry
  {
    /// What a surface or a curve of a 3D model is.
    struct ModelShape
    {
      enum class Kind
      {
        flat,     ///< a plane, or a straight line: the default, flat
        sphere,   ///< a piece of a sphere: SphericalManifold
        cylinder, ///< a piece of a circular cylinder: CylindricalManifold
        circle,   ///< an arc of a circle: a CylindricalManifold about the
                  ///< circle's axis
        other     ///< anything else: kept faceted (flat) for now
      };
      int          tag  = 0;
      Kind         kind = Kind::flat;
      Point<3>     centre; ///< of a sphere or circle; a point on an axis
      Tensor<1, 3> axis;   ///< of a cylinder or circle (unit)
      double       radius = 0;
    };

    /// What the points (on a grid of the surface's parameters) and the
    /// unit normals there describe: a plane, a sphere or a circular
    /// cylinder (each to 1e-9 of its size), or another surface.
    ModelShape
    recognise_surface(int                              tag,
                      const std::vector<Point<3>>     &points,
                      const std::vector<Tensor<1, 3>> &normals);

    /// What the points, evenly spaced along a curve, describe: a straight
    /// line, an arc of a circle (to 1e-9 of its radius), or another curve.
    ModelShape
    recognise_space_curve(int tag, const std::vector<Point<3>> &samples);

    /// The surfaces and curves of `mesh` (a 3D script's) attached to
    /// `triangulation` made from it: every boundary face on a sphere or a
    /// cylinder gets its manifold, and so do the face's lines, except a
    /// line on a curve of the model, which gets the curve's (flat for a
    /// straight one, a circle's for an arc). Returns the surfaces found.
    std::vector<ModelShape>
    attach_model_surfaces(Triangulation<3>  &triangulation,
                          const GmshMesh<3> &mesh);
  } // namespace Geometry
} // namespace RingContact

#endif
