// The surfaces of a 3D gmsh model become the geometry
// (input/model_surfaces.h). First meshes/hertz_3d.geo (OpenCASCADE: a punch
// with a spherical end, cut by the planes x = 0, y = 0, x = s, y = s): its
// sphere is recognised with its centre and radius, its other surfaces flat,
// and after two global refinements every boundary vertex on the sphere is
// on it to 1e-12 of its radius, while those on the four planes stay in
// them to 1e-12: the lines where the sphere meets a plane take the
// circle they lie on (a small circle at x = s, which the sphere's own
// manifold would pull out of the plane). Without the surfaces, the refined
// vertices sit on the coarse facets, 1e-3 off the sphere. Then a script of
// gmsh's built-in kernel: a cylinder of radius 0.5 extruded and turned so
// that its axis is tilted, recognised with that axis, its vertices after
// two refinements on the side and the ends to 1e-12 (faceted: 1e-2 off),
// and a quarter torus (a disc turned about an axis) that is none of the
// shapes and stays faceted. Last, the cylinder's script with
// Mesh.ScalingFactor = 0.001: the cylinder recognised scaled.
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_nothing.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/tria.h>

#include <ring_contact/config.h>
#include <ring_contact/input/gmsh_mesh.h>
#include <ring_contact/input/model_surfaces.h>

#include "tests.h"

#include <cmath>
#include <fstream>
#include <iomanip>

using namespace RingContact;
using RingContactTests::check;

namespace
{
  const char *script = R"(
  // A disc of radius 0.5 in the plane z = 0 about (x0, 0, 0): a square and
// four patches up to the circle, n x n quadrilaterals each.
Macro Disc
  Point(o + 1) = {x0, 0, 0};
  For k In {0 : 3}
    Point(o + 2 + k) = {x0 + 0.5 * Cos(Pi / 4 + k * Pi / 2), 0.5 * Sin(Pi / 4 + k * Pi / 2), 0};
    Point(o + 6 + k) = {x0 + 0.2 * Cos(Pi / 4 + k * Pi / 2), 0.2 * Sin(Pi / 4 + k * Pi / 2), 0};
  EndFor
  For k In {0 : 3}
    Circle(o + 1 + k) = {o + 2 + k, o + 1, o + 2 + (k + 1) % 4};
    Line(o + 5 + k) = {o + 6 + k, o + 6 + (k + 1) % 4};
    Line(o + 9 + k) = {o + 6 + k, o + 2 + k};
  EndFor
  Curve Loop(o + 1) = {o + 5, o + 6, o + 7, o + 8};
  Plane Surface(o + 1) = {o + 1};
  For k In {0 : 3}
    Curve Loop(o + 2 + k) = {o + 9 + k, o + 1 + k, -(o + 9 + (k + 1) % 4), -(o + 5 + k)};
    Plane Surface(o + 2 + k) = {o + 2 + k};
  EndFor
  Transfinite Curve{o + 1 : o + 12} = 4;
  Transfinite Surface{o + 1 : o + 5};
  Recombine Surface{o + 1 : o + 5};
Return

// The cylinder: the disc about the origin turned about the axis
// (1, -1, 0) by 0.7 rad, then extruded to height 1.5 along its normal.
o = 0; x0 = 0; Call Disc;
Rotate {{1, -1, 0}, {0, 0, 0}, 0.7} { Surface{1 : 5}; }
a = 1.5 * Sin(0.7) / Sqrt(2);
cylinder[] = Extrude {-a, -a, 1.5 * Cos(0.7)} { Surface{1 : 5}; Layers{5}; Recombine; };
// The torus: the disc about (2, 0, 0) turned a quarter about the y axis.
o = 1000; x0 = 2; Call Disc;
torus[] = Extrude {{0, 1, 0}, {0, 0, 0}, Pi / 2} { Surface{1001 : 1005}; Layers{6}; Recombine; };
Physical Volume(2) = {cylinder[1], cylinder[7], cylinder[13], cylinder[19], cylinder[25]};
Physical Volume(3) = {torus[1], torus[7], torus[13], torus[19], torus[25]};
Physical Surface(20) = Abs(CombinedBoundary{ Volume{cylinder[1], cylinder[7], cylinder[13], cylinder[19], cylinder[25]}; });
Physical Surface(30) = Abs(CombinedBoundary{ Volume{torus[1], torus[7], torus[13], torus[19], torus[25]}; });
)";

  // The cylinder's axis: e_z turned by 0.7 about (1, -1, 0) / sqrt(2).
  const Tensor<1, 3> cylinder_axis({-std::sin(0.7) / std::sqrt(2.),
                                    -std::sin(0.7) / std::sqrt(2.),
                                    std::cos(0.7)});
  const double       cylinder_height = 1.5;

  // How far a point is from the cylinder: on an end, from its plane (and
  // within the circle); on the side, from the radius.
  double
  off_cylinder(const Point<3> &x)
  {
    const double t       = x * cylinder_axis;
    const double r       = (x - t * cylinder_axis).norm();
    const double off_end = std::min(std::abs(t), std::abs(t - cylinder_height));
    return std::min(std::abs(r - 0.5), std::max(off_end, r - 0.5));
  }

  // The largest of `distance` over the vertices of the boundary faces of
  // id `boundary`.
  template <typename Distance>
  double
  largest(const Triangulation<3>  &triangulation,
          const types::boundary_id boundary,
          const Distance          &distance)
  {
    double largest = 0;
    for (const auto &cell : triangulation.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary() && face->boundary_id() == boundary)
          for (const unsigned int v : face->vertex_indices())
            largest = std::max(largest, distance(face->vertex(v)));
    return largest;
  }

  const char *
  name_of(const Geometry::ModelShape::Kind kind)
  {
    using Kind = Geometry::ModelShape::Kind;
    return kind == Kind::flat     ? "flat" :
           kind == Kind::sphere   ? "sphere" :
           kind == Kind::cylinder ? "cylinder" :
           kind == Kind::circle   ? "circle" :
                                    "other";
  }

  // The shapes found, by kind, and the circles among the curves.
  std::string
  summary(const std::vector<Geometry::ModelShape> &shapes,
          const Geometry::GmshMesh<3>             &mesh)
  {
    std::map<std::string, unsigned int> kinds;
    for (const auto &shape : shapes)
      ++kinds[name_of(shape.kind)];
    std::string text = "surfaces:";
    for (const auto &[kind, count] : kinds)
      text += ' ' + std::to_string(count) + ' ' + kind;
    unsigned int circles = 0;
    for (const auto &[tag, samples] : mesh.curves)
      circles += Geometry::recognise_space_curve(tag, samples).kind ==
                 Geometry::ModelShape::Kind::circle;
    return text + "; curves: " + std::to_string(circles) + " circles of " +
           std::to_string(mesh.curves.size());
  }

  // The punch of meshes/hertz_3d.geo, refined twice, with its surfaces or
  // faceted.
  void
  punch(const bool attach)
  {
    auto             &out = RingContactTests::deallog_file;
    Triangulation<3>  triangulation;
    const std::string file =
      std::string(RING_CONTACT_SOURCE_DIR) + "/meshes/hertz_3d.geo";
    // A coarse mesh of it: 6 x 6 x 4 cells in the punch, 4 x 4 x 4 in the
    // block.
    const auto mesh = Geometry::read_gmsh<3>(
      triangulation,
      file,
      {{"n", 6}, {"nz", 4}, {"rs", 1.2}, {"m", 4}, {"mz", 4}},
      1,
      false);
    const double   R = 1, s = 0.5;
    const Point<3> centre(0, 0, R - 2e-4);
    if (attach)
      {
        const auto shapes =
          Geometry::attach_model_surfaces(triangulation, mesh);
        out << "punch: " << summary(shapes, mesh) << std::endl;
        for (const auto &shape : shapes)
          if (shape.kind == Geometry::ModelShape::Kind::sphere)
            check(shape.centre.distance(centre) < 1e-12 &&
                    std::abs(shape.radius - R) < 1e-12,
                  "the sphere's centre and radius");
      }
    triangulation.refine_global(2);
    const double sphere = largest(triangulation, 10, [&](const Point<3> &x) {
      return std::abs(x.distance(centre) - R);
    });
    double       planes =
      std::max(largest(triangulation,
                       12,
                       [](const Point<3> &x) { return std::abs(x[0]); }),
               largest(triangulation, 13, [](const Point<3> &x) {
                 return std::abs(x[1]);
               }));
    planes =
      std::max(planes, largest(triangulation, 14, [&](const Point<3> &x) {
                 return std::min(std::abs(x[0] - s), std::abs(x[1] - s));
               }));
    out << (attach ? "curved" : "faceted") << ": vertices off the sphere "
        << sphere << ", off the planes " << planes << std::endl;
    check(attach ? sphere < 1e-12 : sphere > 1e-4, "the sphere");
    check(planes < 1e-12, "the planes");
  }

  // The cylinder and the torus, refined twice, with their surfaces or
  // faceted; `scaling` the script's Mesh.ScalingFactor.
  void
  cylinder(const bool attach, const double scaling = 1)
  {
    auto             &out  = RingContactTests::deallog_file;
    const std::string file = "model_surfaces.geo";
    std::ofstream(file) << script << "Mesh.ScalingFactor = " << scaling
                        << ";\n";
    Triangulation<3> triangulation;
    const auto mesh = Geometry::read_gmsh<3>(triangulation, file, {}, 1, false);
    if (attach)
      {
        const auto shapes =
          Geometry::attach_model_surfaces(triangulation, mesh);
        out << "cylinder and torus: " << summary(shapes, mesh) << std::endl;
        // The cylinder's four sides about the tilted axis; and two pieces
        // of the torus's are cylinders too, about the y axis (where the
        // disc's sides parallel to it sweep).
        unsigned int tilted = 0, about_y = 0;
        for (const auto &shape : shapes)
          if (shape.kind == Geometry::ModelShape::Kind::cylinder)
            {
              if (std::abs(std::abs(shape.axis * cylinder_axis) - 1) < 1e-12 &&
                  std::abs(shape.radius - 0.5 * scaling) < 1e-12 * scaling &&
                  cross_product_3d(shape.centre - Point<3>(), cylinder_axis)
                      .norm() < 1e-12 * scaling)
                ++tilted;
              else if (std::abs(std::abs(shape.axis[1]) - 1) < 1e-12)
                ++about_y;
            }
        out << "Mesh.ScalingFactor = " << scaling << ": cylinders of radius "
            << 0.5 * scaling << ": " << tilted << " about the tilted axis, "
            << about_y << " about the y axis" << std::endl;
        check(tilted == 4 && about_y == 2, "the cylinders' axes and radii");
      }
    if (scaling != 1)
      return;
    triangulation.refine_global(2);
    const double off = largest(triangulation, 20, off_cylinder);
    out << (attach ? "curved" : "faceted") << ": vertices off the cylinder "
        << off << std::endl;
    check(attach ? off < 1e-12 : off > 1e-3, "the cylinder");
  }
} // namespace

int
main()
{
  RingContactTests::deallog_file << std::setprecision(3);
  punch(false);
  punch(true);
  cylinder(false);
  cylinder(true);
  cylinder(true, 0.001);
}
