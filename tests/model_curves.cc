// The curves of a gmsh model become the geometry (input/model_curves.h): a
// script with a quarter circle of radius 2 about (1, 1), an ellipse arc of
// semi-axes 3 and 1.5 and straight lines is read, its curves recognised
// (the circle with its centre and radius to 1e-12, the ellipse as a
// sampled curve, the lines straight), and after three global refinements
// every boundary vertex on the circle is on it to 1e-12 of the radius and
// every one on the ellipse on it to 1e-9 (gmsh's 513 samples, interpolated
// by cubic Hermite: the error is O(h^4) in their spacing). Without the
// curves, the refined vertices sit on the chords, 4e-3 and 8e-3 off. A mapping
// of degree 2 then gives the disc's quarter an area within 1e-8 of pi and the
// ellipse's within 1e-8 of 9 pi / 8 (straight-sided: 3e-3 and 2e-3 off).
// Last, closed curves (OpenCASCADE's whole disc and whole ellipse, each one
// curve whose ends meet): the ellipse's chart is periodic, and refinement
// across its seam keeps the vertices on it (a transfinite interpolation of
// the cells beside the curves once failed here while refining).
// And the first script with Mesh.ScalingFactor = 0.001, which gmsh applies
// when it saves a mesh: every vertex is the unscaled one times 0.001, the
// circle has its centre and radius scaled, and the refined vertices stay
// on it (the factor was ignored: the mesh a thousand times too large).
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_nothing.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/tria.h>

#include <ring_contact/config.h>
#include <ring_contact/input/gmsh_mesh.h>
#include <ring_contact/input/model_curves.h>

#include "tests.h"

#include <cmath>
#include <fstream>
#include <iomanip>

using namespace RingContact;
using RingContactTests::check;

namespace
{
  // Body 1: the quarter disc of radius 2 about (1, 1), x >= 1, y >= 1.
  // Body 2: the quarter ellipse x^2 / 9 + y^2 / 2.25 <= 1 moved to x >= 4,
  // centre (4, 0). Tags: 10 the circle, 20 the ellipse, 11-12 and 21-22
  // the straight sides.
  const char *closed = R"(
SetFactory("OpenCASCADE");
Disk(1) = {0, 0, 0, 1};
Disk(2) = {3, 0, 0, 1, 0.5};
Mesh.RecombineAll = 1; Mesh.Algorithm = 6; Mesh.SubdivisionAlgorithm = 1;
Mesh.MeshSizeMax = 0.4;
Physical Surface(1) = {1}; Physical Surface(2) = {2};
Physical Curve(10) = {1}; Physical Curve(20) = {2};
)";

  const char *script = R"(
Point(1) = {1, 1, 0}; Point(2) = {3, 1, 0}; Point(3) = {1, 3, 0};
Line(1) = {1, 2}; Circle(2) = {2, 1, 3}; Line(3) = {3, 1};
Curve Loop(1) = {1, 2, 3}; Plane Surface(1) = {1};
Point(4) = {4, 0, 0}; Point(5) = {7, 0, 0}; Point(6) = {4, 1.5, 0};
Line(4) = {4, 5}; Ellipse(5) = {5, 4, 5, 6}; Line(6) = {6, 4};
Curve Loop(2) = {4, 5, 6}; Plane Surface(2) = {2};
Mesh.RecombineAll = 1; Mesh.Algorithm = 6; Mesh.SubdivisionAlgorithm = 1;
Mesh.MeshSizeMax = 0.6;
Physical Surface(1) = {1}; Physical Surface(2) = {2};
Physical Curve(10) = {2}; Physical Curve(11) = {1}; Physical Curve(12) = {3};
Physical Curve(20) = {5}; Physical Curve(21) = {4}; Physical Curve(22) = {6};
)";

  // The largest distance of a boundary vertex of `id` from its exact curve.
  template <typename Distance>
  double
  worst(const Triangulation<2>  &triangulation,
        const types::boundary_id id,
        const Distance          &distance)
  {
    double d = 0;
    for (const auto &face : triangulation.active_face_iterators())
      if (face->at_boundary() && face->boundary_id() == id)
        for (const unsigned int v : {0u, 1u})
          d = std::max(d, distance(face->vertex(v)));
    return d;
  }

  double
  area(const Triangulation<2>  &triangulation,
       const types::material_id body,
       const unsigned int       degree)
  {
    const MappingQ<2> mapping(degree);
    FE_Nothing<2>     fe;
    const QGauss<2>   quadrature(degree + 2);
    FEValues<2>       fe_values(mapping, fe, quadrature, update_JxW_values);
    double            a = 0;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->material_id() == body)
        {
          fe_values.reinit(cell);
          for (unsigned int q = 0; q < quadrature.size(); ++q)
            a += fe_values.JxW(q);
        }
    return a;
  }
} // namespace

int
main()
{
  auto &out = RingContactTests::deallog_file;
  out << std::setprecision(3);
  std::ofstream("curves.geo") << script;

  const auto on_circle = [](const Point<2> &x) {
    return std::abs(x.distance(Point<2>(1, 1)) - 2);
  };
  const auto on_ellipse = [](const Point<2> &x) {
    // The distance to first order: |F| / |grad F|, F = x^2/9 + y^2/2.25 - 1.
    const double X = x[0] - 4, Y = x[1];
    const double F = X * X / 9 + Y * Y / 2.25 - 1;
    return std::abs(F) / std::hypot(2 * X / 9, 2 * Y / 2.25);
  };

  for (const bool curved : {false, true})
    {
      Triangulation<2>            triangulation;
      const Geometry::GmshMesh<2> mesh =
        Geometry::read_gmsh(triangulation, "curves.geo", {}, 1, false);
      if (curved)
        {
          const auto curves =
            Geometry::attach_model_curves(triangulation, mesh);
          unsigned int n_circles = 0, n_sampled = 0, n_straight = 0;
          for (const auto &c : curves)
            {
              if (c.kind == Geometry::ModelCurve::Kind::circle)
                {
                  ++n_circles;
                  check(c.centre.distance(Point<2>(1, 1)) < 1e-12 &&
                          std::abs(c.radius - 2) < 1e-12,
                        "the circle's centre and radius");
                }
              n_sampled += c.kind == Geometry::ModelCurve::Kind::sampled;
              n_straight += c.kind == Geometry::ModelCurve::Kind::straight;
            }
          out << "curves: " << n_circles << " circle, " << n_sampled
              << " other, " << n_straight << " straight" << std::endl;
          check(n_circles == 1 && n_sampled == 1 && n_straight == 4,
                "one circle, one other curve, four lines");
        }
      triangulation.refine_global(3);
      const double circle  = worst(triangulation, 10, on_circle),
                   ellipse = worst(triangulation, 20, on_ellipse);
      const double disc    = area(triangulation, 1, curved ? 2 : 1),
                   quad    = area(triangulation, 2, curved ? 2 : 1);
      out << (curved ? "curved:   " : "straight: ")
          << "vertices off the circle " << (circle < 1e-12 ? 0 : circle)
          << ", off the ellipse " << (ellipse < 1e-9 ? 0 : ellipse)
          << "; area errors " << std::abs(disc - M_PI) / M_PI << " and "
          << std::abs(quad - 9 * M_PI / 8) / (9 * M_PI / 8) << std::endl;
      if (curved)
        {
          check(circle < 1e-12, "refined vertices on the circle");
          check(ellipse < 1e-9, "refined vertices on the ellipse");
          check(std::abs(disc - M_PI) < 1e-8 * M_PI, "the disc's area");
          check(std::abs(quad - 9 * M_PI / 8) < 1e-8 * 9 * M_PI / 8,
                "the ellipse's area");
        }
      else
        check(circle > 1e-3 && ellipse > 1e-3,
              "straight-sided, the refined vertices are on the chords");
    }

  std::ofstream("closed.geo") << closed;
  Triangulation<2>            triangulation;
  const Geometry::GmshMesh<2> mesh =
    Geometry::read_gmsh(triangulation, "closed.geo", {}, 1, false);
  Geometry::attach_model_curves(triangulation, mesh);
  triangulation.refine_global(3);
  const double circle  = worst(triangulation, 10, [](const Point<2> &x) {
    return std::abs(x.norm() - 1);
  });
  const double ellipse = worst(triangulation, 20, [](const Point<2> &x) {
    const double X = x[0] - 3, Y = x[1];
    const double F = X * X + Y * Y / 0.25 - 1;
    return std::abs(F) / std::hypot(2 * X, 2 * Y / 0.25);
  });
  out << "closed curves: vertices off the circle "
      << (circle < 1e-12 ? 0 : circle) << ", off the ellipse "
      << (ellipse < 1e-9 ? 0 : ellipse) << std::endl;
  check(circle < 1e-12, "refined vertices on the whole circle");
  check(ellipse < 1e-9, "refined vertices on the whole ellipse");

  // The script drawn in millimetres, say: Mesh.ScalingFactor = 0.001.
  {
    std::ofstream("scaled.geo") << "Mesh.ScalingFactor = 0.001;\n" << script;
    Triangulation<2> unscaled, scaled;
    Geometry::read_gmsh(unscaled, "curves.geo", {}, 1, false);
    const Geometry::GmshMesh<2> mesh =
      Geometry::read_gmsh(scaled, "scaled.geo", {}, 1, false);
    double worst_vertex = 0;
    for (unsigned int v = 0; v < scaled.n_vertices(); ++v)
      worst_vertex = std::max(worst_vertex,
                              scaled.get_vertices()[v].distance(
                                0.001 * unscaled.get_vertices()[v]));
    out << "Mesh.ScalingFactor = 0.001: " << scaled.n_vertices()
        << " vertices, the unscaled ones times 0.001 to "
        << (worst_vertex < 1e-18 ? 0 : worst_vertex) << std::endl;
    check(scaled.n_vertices() == unscaled.n_vertices() && worst_vertex < 1e-18,
          "the scaled vertices are the unscaled ones times 0.001");
    bool circle_scaled = false;
    for (const auto &c : Geometry::attach_model_curves(scaled, mesh))
      if (c.kind == Geometry::ModelCurve::Kind::circle)
        circle_scaled = c.centre.distance(Point<2>(1e-3, 1e-3)) < 1e-15 &&
                        std::abs(c.radius - 2e-3) < 1e-15;
    check(circle_scaled, "the scaled circle's centre and radius");
    scaled.refine_global(3);
    const double off = worst(scaled, 10, [](const Point<2> &x) {
      return std::abs(x.distance(Point<2>(1e-3, 1e-3)) - 2e-3);
    });
    out << "Mesh.ScalingFactor = 0.001: the circle about (0.001, 0.001) of "
           "radius 0.002, refined vertices off it "
        << (off < 1e-15 ? 0 : off) << std::endl;
    check(off < 1e-15, "refined vertices on the scaled circle");
  }
}
