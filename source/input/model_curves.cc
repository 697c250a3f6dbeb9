// @sect3{The curves of a gmsh model}
//
// A general problem's mesh comes from a gmsh script whose curves the CAD
// kernel knows exactly: a shrink fit's arcs, a cylinder's surface. The mesh
// alone gives straight-sided cells between its vertices, and a disc in a
// ring meshed with 40 against 57 segments per quarter then had a pressure that
// swung wildly around the circle (doc/validation.md, "Curved geometry, ties and
// touching bodies"). Here the curves become the
// geometry, the way the rings have theirs: deal.II manifolds on the
// boundary faces. A circle (recognised from gmsh's samples, to 1e-9 of its
// radius) gets deal.II's own PolarManifold about its centre; any other
// curve a chart that interpolates gmsh's samples. The cells keep deal.II's
// flat manifold: a mapping of degree >= 2 places its inner points by a
// transfinite blend of the cell's boundary points (MappingQ's own), and a
// refined cell's centre is averaged from its vertices and its new edge
// points, which lie on the curve. deal.II's TransfiniteInterpolationManifold
// on the cells beside a curve (step-65) was tried and dropped: its inverse
// map failed during refinement on a coarse mesh of a closed ellipse
// (semi-axes 1 and 0.5, cells of 0.4: ExcTransformationFailed), and a
// domain's area, the boundary's business alone, is the same either way.
#include <deal.II/grid/manifold_lib.h>
#include <deal.II/grid/tria_accessor.h>
#include <deal.II/grid/tria_iterator.h>

#include <ring_contact/base/dimension.h>
#include <ring_contact/input/model_curves.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

namespace RingContact
{
  namespace Geometry
  {
    // @sect4{Which curve it is}
    //
    // A line if every sample lies on the chord of the ends (to round-off of
    // the curve's size), a circle if every sample lies on the circle through
    // three of them. The tolerances are far below any mesh's chord sag and
    // far above gmsh's evaluation round-off.
    ModelCurve
    recognise_curve(const int tag, const std::vector<Point<dim>> &samples)
    {
      ModelCurve curve;
      curve.tag           = tag;
      curve.samples       = samples;
      const std::size_t n = samples.size();
      if (n < 4)
        return curve;
      double size = 0;
      for (const auto &p : samples)
        size = std::max(size, p.distance(samples.front()));
      if (size == 0)
        return curve;

      // Straight: every sample on the line through the ends.
      const Point<dim> &a = samples.front(), &b = samples.back();
      if (a.distance(b) > 1e-12 * size)
        {
          const Tensor<1, dim> d        = (b - a) / (b - a).norm();
          bool                 straight = true;
          for (const auto &p : samples)
            straight = straight &&
                       std::abs(cross_product_2d(d) * (p - a)) <= 1e-10 * size;
          if (straight)
            return curve;
        }

      // A circle through three samples a third of the curve apart (a
      // closed curve has its ends on each other).
      const Point<dim> &p = samples[0], &q = samples[n / 3],
                       &r = samples[(2 * n) / 3];
      const double d =
        2 * ((q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]));
      if (std::abs(d) > 1e-14 * size * size)
        {
          const double qq = (q - p).norm_square(), rr = (r - p).norm_square();
          const Point<dim> centre(
            p[0] + ((r[1] - p[1]) * qq - (q[1] - p[1]) * rr) / d,
            p[1] + ((q[0] - p[0]) * rr - (r[0] - p[0]) * qq) / d);
          const double radius = centre.distance(p);
          bool         circle = true;
          for (const auto &x : samples)
            circle =
              circle && std::abs(centre.distance(x) - radius) <= 1e-9 * radius;
          if (circle)
            {
              curve.kind   = ModelCurve::Kind::circle;
              curve.centre = centre;
              curve.radius = radius;
              return curve;
            }
        }
      curve.kind = ModelCurve::Kind::sampled;
      return curve;
    }

    // @sect4{A curve known by its samples}
    //
    // A closed curve (its ends on each other) is periodic in the chart, so
    // that a point near the seam averages across it.
    namespace
    {
      bool
      is_closed(const std::vector<Point<dim>> &samples)
      {
        return samples.front().distance(samples.back()) <=
               1e-12 * samples.front().distance(samples[samples.size() / 2]);
      }
    } // namespace

    SampledCurveManifold::SampledCurveManifold(
      const std::vector<Point<dim>> &samples)
        : ChartManifold<2, 2, 1>(is_closed(samples) ? Tensor<1, 1>({1.0}) :
                                                      Tensor<1, 1>())
        , samples(samples)
        , closed(is_closed(samples))
    {}

    std::unique_ptr<Manifold<dim, dim>>
    SampledCurveManifold::clone() const
    {
      return std::make_unique<SampledCurveManifold>(samples);
    }

    // The interval of t (wrapped on a closed curve, the end intervals
    // extended on an open one) and the local coordinate in it.
    std::pair<unsigned int, double>
    SampledCurveManifold::locate(double t) const
    {
      const unsigned int n_intervals = samples.size() - 1;
      if (closed)
        t -= std::floor(t);
      const double       x = t * n_intervals;
      const unsigned int i = static_cast<unsigned int>(
        std::clamp(std::floor(x), 0.0, n_intervals - 1.0));
      return {i, x - i};
    }

    // Catmull-Rom: the tangent at a sample from its two neighbours (per unit
    // of the sample index), one-sided at the ends of an open curve.
    Tensor<1, dim>
    SampledCurveManifold::tangent_at_sample(const unsigned int i) const
    {
      const unsigned int last = samples.size() - 1;
      if (closed && (i == 0 || i == last))
        return 0.5 * (samples[1] - samples[last - 1]);
      if (i == 0)
        return samples[1] - samples[0];
      if (i == last)
        return samples[last] - samples[last - 1];
      return 0.5 * (samples[i + 1] - samples[i - 1]);
    }

    Point<dim>
    SampledCurveManifold::push_forward(const Point<1> &chart_point) const
    {
      const auto [i, s] = locate(chart_point[0]);
      const double s2 = s * s, s3 = s2 * s;
      const double h00 = 2 * s3 - 3 * s2 + 1, h10 = s3 - 2 * s2 + s,
                   h01 = -2 * s3 + 3 * s2, h11 = s3 - s2;
      return Point<dim>(h00 * samples[i] + h10 * tangent_at_sample(i) +
                        h01 * samples[i + 1] + h11 * tangent_at_sample(i + 1));
    }

    DerivativeForm<1, dim - 1, dim>
    SampledCurveManifold::push_forward_gradient(
      const Point<1> &chart_point) const
    {
      const auto [i, s] = locate(chart_point[0]);
      const double s2   = s * s;
      const double d00 = 6 * s2 - 6 * s, d10 = 3 * s2 - 4 * s + 1,
                   d01 = -6 * s2 + 6 * s, d11 = 3 * s2 - 2 * s;
      const Tensor<1, dim> dx_ds =
        d00 * samples[i] + d10 * tangent_at_sample(i) + d01 * samples[i + 1] +
        d11 * tangent_at_sample(i + 1);
      DerivativeForm<1, dim - 1, dim> gradient;
      for (unsigned int d = 0; d < dim; ++d)
        gradient[d][0] = dx_ds[d] * (samples.size() - 1.0);
      return gradient;
    }

    // The chart point of a point on (or near) the curve: the nearest sample,
    // the closer of the two chords beside it, then Newton on
    // (x(t) - p) . x'(t) = 0.
    Point<1>
    SampledCurveManifold::pull_back(const Point<dim> &space_point) const
    {
      const unsigned int n_intervals = samples.size() - 1;
      unsigned int       nearest     = 0;
      for (unsigned int i = 1; i < samples.size(); ++i)
        if (samples[i].distance(space_point) <
            samples[nearest].distance(space_point))
          nearest = i;
      double best_t        = nearest,
             best_distance = samples[nearest].distance(space_point);
      for (const int side : {-1, 0})
        {
          const int i = static_cast<int>(nearest) + side;
          if (i < 0 || i >= static_cast<int>(n_intervals))
            continue;
          const Tensor<1, dim> chord = samples[i + 1] - samples[i];
          const double         s =
            std::clamp((space_point - samples[i]) * chord / chord.norm_square(),
                       0.0,
                       1.0);
          const double distance =
            (samples[i] + s * chord).distance(space_point);
          if (distance < best_distance)
            {
              best_distance = distance;
              best_t        = i + s;
            }
        }
      double t = best_t / n_intervals;
      for (unsigned int it = 0; it < 4; ++it)
        {
          const Point<dim>     x = push_forward(Point<1>(t));
          const auto           g = push_forward_gradient(Point<1>(t));
          const Tensor<1, dim> dx({g[0][0], g[1][0]});
          const double         f  = (x - space_point) * dx;
          const double         df = dx.norm_square();
          if (df == 0)
            break;
          t -= f / df;
        }
      return Point<1>(t);
    }

    // @sect4{The curves on the triangulation}
    //
    // A boundary face is found on its curve through the gmsh line it was made
    // of: the line's two end nodes, from the face's two vertices
    // (GmshMesh::node_of_vertex). Manifold ids from 1 up are the curves; the
    // cells stay flat (see the top of the file).
    std::vector<ModelCurve>
    attach_model_curves(Triangulation<dim>  &triangulation,
                        const GmshMesh<dim> &mesh)
    {
      std::vector<ModelCurve>           curves;
      std::map<int, types::manifold_id> id_of_entity;
      for (const auto &[tag, samples] : mesh.curves)
        {
          curves.push_back(recognise_curve(tag, samples));
          const ModelCurve &curve = curves.back();
          if (curve.kind == ModelCurve::Kind::straight)
            continue;
          const types::manifold_id id = 1 + id_of_entity.size();
          id_of_entity[tag]           = id;
          if (curve.kind == ModelCurve::Kind::circle)
            triangulation.set_manifold(id, PolarManifold<dim>(curve.centre));
          else
            triangulation.set_manifold(id, SampledCurveManifold(curve.samples));
        }
      if (id_of_entity.empty())
        return curves;

      // The gmsh line of each pair of end nodes, and its entity.
      std::map<std::pair<std::size_t, std::size_t>, int> entity_of_line;
      for (const auto &element : mesh.elements)
        if (element.type == 1 || element.type == 8)
          entity_of_line[std::minmax(element.nodes[0], element.nodes[1])] =
            element.entity;

      for (const auto &cell : triangulation.active_cell_iterators())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary())
            {
              const auto face = cell->face(f);
              const auto line = entity_of_line.find(
                std::minmax(mesh.node_of_vertex.at(face->vertex_index(0)),
                            mesh.node_of_vertex.at(face->vertex_index(1))));
              if (line == entity_of_line.end())
                continue;
              const auto curve = id_of_entity.find(line->second);
              if (curve != id_of_entity.end())
                face->set_manifold_id(curve->second);
            }
      return curves;
    }
  } // namespace Geometry
} // namespace RingContact
