// @sect3{The surfaces of a 3D gmsh model}
//
// A 3D general problem's mesh comes from a gmsh script whose surfaces the
// CAD kernel knows exactly: Hertz's sphere, a shaft's cylinder. The mesh
// alone gives flat quadrilaterals between its vertices, and refinement
// would keep them flat: a sphere refined twice would still be the coarse
// mesh's polyhedron. Here, as model_curves.cc does in 2D, the surfaces
// become the geometry: a sphere or a cylinder (recognised from gmsh's
// samples and normals, to 1e-9 of its size) gets deal.II's own
// SphericalManifold or CylindricalManifold on the boundary faces that lie
// on it, and the faces' lines on a circle of the model (where a sphere
// meets a plane of symmetry, a cylinder its end) that circle, a
// CylindricalManifold about the circle's axis. Other surfaces stay
// faceted: deal.II 9.4 has no manifold that follows a CAD surface without
// OpenCASCADE, and the program has no chart of its own for them yet.
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/grid/manifold_lib.h>
#include <deal.II/grid/tria_accessor.h>
#include <deal.II/grid/tria_iterator.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <ring_contact/input/model_surfaces.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

namespace RingContact
{
  namespace Geometry
  {
    namespace
    {
      // The sphere (in k = 2 dimensions a circle) closest to points q in
      // the algebraic sense, 2 c . q + b = |q|^2 solved by least squares,
      // if every point lies on it to `tolerance` of its radius.
      template <int k>
      std::optional<std::pair<Point<k>, double>>
      fit_sphere(const std::vector<Point<k>> &q, const double tolerance)
      {
        FullMatrix<double> normal(k + 1, k + 1);
        Vector<double>     rhs(k + 1);
        for (const auto &x : q)
          {
            double row[k + 1];
            for (unsigned int d = 0; d < k; ++d)
              row[d] = 2 * x[d];
            row[k] = 1;
            for (unsigned int i = 0; i <= k; ++i)
              {
                for (unsigned int j = 0; j <= k; ++j)
                  normal(i, j) += row[i] * row[j];
                rhs(i) += row[i] * x.norm_square();
              }
          }
        try
          {
            normal.gauss_jordan();
          }
        catch (...)
          {
            return std::nullopt;
          }
        Vector<double> solution(k + 1);
        normal.vmult(solution, rhs);
        Point<k> centre;
        for (unsigned int d = 0; d < k; ++d)
          centre[d] = solution(d);
        double radius = 0;
        for (const auto &x : q)
          radius += centre.distance(x) / q.size();
        if (!std::isfinite(radius) || radius == 0)
          return std::nullopt;
        for (const auto &x : q)
          if (std::abs(centre.distance(x) - radius) > tolerance * radius)
            return std::nullopt;
        return std::make_pair(centre, radius);
      }

      // A unit vector across `a`.
      Tensor<1, 3>
      unit_normal_to(const Tensor<1, 3> &a)
      {
        const Tensor<1, 3> other(
          {std::abs(a[0]) < 0.6 ? 1. : 0., std::abs(a[0]) < 0.6 ? 0. : 1., 0.});
        const Tensor<1, 3> n = cross_product_3d(a, other);
        return n / n.norm();
      }

      // A circular cylinder through points q: its axis first from the
      // normals (they all lie across it: the eigenvector of the least
      // eigenvalue of the sum of n n^T, zero for a cylinder), its centre
      // and radius from the points seen along it (fit_sphere<2>); then
      // Gauss-Newton on the distances to the axis minus the radius, in the
      // axis's two tilts, the centre's two shifts and the radius, which
      // takes the fit to the points' round-off: a CAD kernel's normals
      // may be good to 1e-8 only (gmsh's built-in ruled surfaces), too
      // coarse for the tolerance. Found if every point is then on the
      // cylinder to 1e-9 of its radius.
      struct Cylinder
      {
        Tensor<1, 3> axis;
        Point<3>     centre;
        double       radius;
      };

      std::optional<Cylinder>
      fit_cylinder(const std::vector<Point<3>>     &q,
                   const std::vector<Tensor<1, 3>> &normals,
                   const double                     size)
      {
        SymmetricTensor<2, 3> spread;
        for (const auto &n : normals)
          spread += symmetrize(outer_product(n, n));
        const auto eigen = eigenvectors(spread);
        if (eigen[2].first > 1e-6 * normals.size())
          return std::nullopt;
        Cylinder c{eigen[2].second / eigen[2].second.norm(), Point<3>(), 0};
        // The residuals of the cylinder moved by d (tilts, shifts, radius).
        const auto residuals = [&q](const Cylinder &c, const double *d) {
          const Tensor<1, 3> e1 = unit_normal_to(c.axis),
                             e2 = cross_product_3d(c.axis, e1);
          Tensor<1, 3> axis     = c.axis + d[0] * e1 + d[1] * e2;
          axis /= axis.norm();
          const Point<3> centre = c.centre + d[2] * e1 + d[3] * e2;
          Vector<double> f(q.size());
          for (unsigned int i = 0; i < q.size(); ++i)
            {
              const Tensor<1, 3> x = q[i] - centre;
              f(i) = (x - (x * axis) * axis).norm() - (c.radius + d[4]);
            }
          return f;
        };
        {
          const Tensor<1, 3> e1 = unit_normal_to(c.axis),
                             e2 = cross_product_3d(c.axis, e1);
          std::vector<Point<2>> seen;
          for (const auto &x : q)
            seen.emplace_back(x * e1, x * e2);
          const auto circle = fit_sphere<2>(seen, 1e-3);
          if (!circle)
            return std::nullopt;
          c.centre = Point<3>(circle->first[0] * e1 + circle->first[1] * e2);
          c.radius = circle->second;
        }
        const double zero[5] = {0, 0, 0, 0, 0};
        for (unsigned int iteration = 0; iteration < 10; ++iteration)
          {
            const Vector<double> f = residuals(c, zero);
            FullMatrix<double>   jacobian(q.size(), 5);
            for (unsigned int k = 0; k < 5; ++k)
              {
                double d[5]            = {0, 0, 0, 0, 0};
                d[k]                   = 1e-7 * (k < 2 ? 1 : size);
                const Vector<double> g = residuals(c, d);
                for (unsigned int i = 0; i < q.size(); ++i)
                  jacobian(i, k) = (g(i) - f(i)) / d[k];
              }
            FullMatrix<double> normal(5, 5);
            jacobian.Tmmult(normal, jacobian);
            Vector<double> rhs(5), step(5);
            jacobian.Tvmult(rhs, f);
            try
              {
                normal.gauss_jordan();
              }
            catch (...)
              {
                return std::nullopt;
              }
            normal.vmult(step, rhs);
            const double d[5] = {
              -step(0), -step(1), -step(2), -step(3), -step(4)};
            const Tensor<1, 3> e1 = unit_normal_to(c.axis),
                               e2 = cross_product_3d(c.axis, e1);
            c.axis += d[0] * e1 + d[1] * e2;
            c.axis /= c.axis.norm();
            c.centre += d[2] * e1 + d[3] * e2;
            c.radius += d[4];
            if (step.l2_norm() <= 1e-14 * size)
              break;
          }
        if (residuals(c, zero).linfty_norm() <= 1e-9 * c.radius)
          return c;
        return std::nullopt;
      }


      // The largest distance of the points from the first: the size the
      // tolerances of the tests scale with.
      double
      size_of(const std::vector<Point<3>> &points)
      {
        double size = 0;
        for (const auto &p : points)
          size = std::max(size, p.distance(points.front()));
        return size;
      }
    } // namespace

    // @sect4{Which surface it is}
    //
    // A plane if every normal is the first and every point on the plane
    // through the first; a sphere if every point lies on the best-fitting
    // sphere; a cylinder if the normals all lie across one direction (the
    // axis: the eigenvector of the least eigenvalue of the sum of n n^T,
    // zero for a cylinder) and the points, seen along it, on one circle.
    // Points are taken relative to the first, so that a small surface far
    // from the origin is fitted to its own size.
    ModelShape
    recognise_surface(const int                        tag,
                      const std::vector<Point<3>>     &points,
                      const std::vector<Tensor<1, 3>> &normals)
    {
      ModelShape shape;
      shape.tag  = tag;
      shape.kind = ModelShape::Kind::other;
      if (points.size() < 9 || points.size() != normals.size())
        return shape;
      const double size = size_of(points);
      if (size == 0)
        return shape;
      std::vector<Point<3>> q;
      for (const auto &p : points)
        q.emplace_back(p - points.front());

      // The plane through the points' centroid across their least spread.
      Tensor<1, 3> mean;
      for (const auto &x : q)
        mean += x / static_cast<double>(q.size());
      SymmetricTensor<2, 3> spread;
      for (const auto &x : q)
        spread += symmetrize(outer_product(x - mean, x - mean));
      const Tensor<1, 3> across = eigenvectors(spread)[2].second;
      bool               plane  = true;
      for (const auto &x : q)
        plane = plane && std::abs((x - mean) * across) <= 1e-10 * size;
      if (plane)
        {
          shape.kind = ModelShape::Kind::flat;
          return shape;
        }

      const auto sphere = fit_sphere<3>(q, 1e-9);
      if (sphere && sphere->second <= 1e4 * size)
        {
          shape.kind   = ModelShape::Kind::sphere;
          shape.centre = points.front() + sphere->first;
          shape.radius = sphere->second;
          return shape;
        }

      if (const auto cylinder = fit_cylinder(q, normals, size))
        {
          shape.kind   = ModelShape::Kind::cylinder;
          shape.axis   = cylinder->axis;
          shape.centre = points.front() + cylinder->centre;
          shape.radius = cylinder->radius;
        }
      return shape;
    }

    // @sect4{Which curve it is}
    //
    // A line if every sample lies on the chord of the ends; an arc of a
    // circle if every sample lies in the plane of three of them (a third
    // of the curve apart) and on the circle through them.
    ModelShape
    recognise_space_curve(const int tag, const std::vector<Point<3>> &samples)
    {
      ModelShape shape;
      shape.tag           = tag;
      shape.kind          = ModelShape::Kind::other;
      const std::size_t n = samples.size();
      if (n < 4)
        return shape;
      const double size = size_of(samples);
      if (size == 0)
        return shape;

      const Point<3> &a = samples.front(), &b = samples.back();
      if (a.distance(b) > 1e-12 * size)
        {
          const Tensor<1, 3> d        = (b - a) / (b - a).norm();
          bool               straight = true;
          for (const auto &p : samples)
            straight =
              straight && cross_product_3d(d, p - a).norm() <= 1e-10 * size;
          if (straight)
            {
              shape.kind = ModelShape::Kind::flat;
              return shape;
            }
        }

      const Point<3>    &p = samples[0];
      const Tensor<1, 3> u = samples[n / 3] - p, v = samples[(2 * n) / 3] - p;
      const Tensor<1, 3> w = cross_product_3d(u, v);
      if (w.norm() <= 1e-12 * size * size)
        return shape;
      const Tensor<1, 3> axis = w / w.norm();
      // The circumcentre of the three points.
      const Point<3> centre =
        p + cross_product_3d(u.norm_square() * v - v.norm_square() * u, w) /
              (2 * w.norm_square());
      const double radius = centre.distance(p);
      for (const auto &x : samples)
        if (std::abs((x - p) * axis) > 1e-9 * radius ||
            std::abs(centre.distance(x) - radius) > 1e-9 * radius)
          return shape;
      shape.kind   = ModelShape::Kind::circle;
      shape.centre = centre;
      shape.axis   = axis;
      shape.radius = radius;
      return shape;
    }

    // @sect4{The surfaces on the triangulation}
    //
    // A boundary face is found on its surface through the gmsh
    // quadrilateral it was made of, a line on its curve through the gmsh
    // line: their corner nodes, from the vertices (GmshMesh::node_of_vertex,
    // GmshMesh::entity_of_element). Manifold ids from 1 up are the curved
    // surfaces, then the circles; the cells stay flat, as in 2D.
    std::vector<ModelShape>
    attach_model_surfaces(Triangulation<3>  &triangulation,
                          const GmshMesh<3> &mesh)
    {
      std::vector<ModelShape>           surfaces;
      std::map<int, types::manifold_id> id_of_surface, id_of_curve;
      types::manifold_id                next_id = 1;
      for (const auto &surface : mesh.surfaces)
        {
          surfaces.push_back(
            recognise_surface(surface.tag, surface.points, surface.normals));
          const ModelShape &shape = surfaces.back();
          if (shape.kind == ModelShape::Kind::sphere)
            triangulation.set_manifold(next_id,
                                       SphericalManifold<3>(shape.centre));
          else if (shape.kind == ModelShape::Kind::cylinder)
            triangulation.set_manifold(next_id,
                                       CylindricalManifold<3>(shape.axis,
                                                              shape.centre));
          else
            continue;
          id_of_surface[shape.tag] = next_id++;
        }
      if (id_of_surface.empty())
        return surfaces;

      // The curves: a circle gets its manifold, a straight line stays
      // flat, another curve takes the surface's.
      for (const auto &[tag, samples] : mesh.curves)
        {
          const ModelShape shape = recognise_space_curve(tag, samples);
          if (shape.kind == ModelShape::Kind::circle)
            {
              triangulation.set_manifold(next_id,
                                         CylindricalManifold<3>(shape.axis,
                                                                shape.centre));
              id_of_curve[tag] = next_id++;
            }
          else if (shape.kind == ModelShape::Kind::flat)
            id_of_curve[tag] = numbers::flat_manifold_id;
        }

      const auto entity_of = [&mesh](std::vector<std::size_t> nodes) {
        for (auto &node : nodes)
          node = mesh.node_of_vertex.at(node);
        std::sort(nodes.begin(), nodes.end());
        const auto entity = mesh.entity_of_element.find(nodes);
        return entity == mesh.entity_of_element.end() ? 0 : entity->second;
      };
      for (const auto &cell : triangulation.active_cell_iterators())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary())
            {
              const auto               face = cell->face(f);
              std::vector<std::size_t> vertices;
              for (const unsigned int v : face->vertex_indices())
                vertices.push_back(face->vertex_index(v));
              const auto surface = id_of_surface.find(entity_of(vertices));
              if (surface == id_of_surface.end())
                continue;
              face->set_manifold_id(surface->second);
              for (unsigned int l = 0; l < face->n_lines(); ++l)
                {
                  const auto line  = face->line(l);
                  const auto curve = id_of_curve.find(
                    entity_of({line->vertex_index(0), line->vertex_index(1)}));
                  line->set_manifold_id(curve == id_of_curve.end() ?
                                          surface->second :
                                          curve->second);
                }
            }
      return surfaces;
    }
  } // namespace Geometry
} // namespace RingContact
