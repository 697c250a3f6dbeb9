// @sect3{Clipping a slave face against a master face (segment-based, 3D)}
//
// The geometric core of segment-based (mortar) integration on surfaces of
// three-dimensional bodies, as 4C, MOOSE and Kratos do it (Puso & Laursen
// 2004; Popp et al. 2010): the slave face and a master face are projected
// onto an auxiliary plane at the slave face (its centre, and its normal by
// Newell's formula), the two projected polygons are clipped
// (Sutherland-Hodgman: the slave polygon cut by each edge of the convex
// master polygon), and the clip polygon is cut into triangles fanned from
// its centroid, on which a triangle rule gives the points that are mapped
// back to both faces. A patch of non-matching faces under a uniform
// pressure is then integrated exactly, which no number of points per face
// achieves without clipping.
//
// Every function is a template on the number type, as the 2D surface kernel
// (surface_kernel.h) is: double for the search, Sacado's AD numbers for the
// contact element, where the clip vertices carry their derivatives with
// respect to the faces' unknowns and the tangent stays exact. The topology
// (which vertex lies inside which edge) is decided on the values only, so
// that both number types take the same branches. The arithmetic is written
// component by component, which Sacado's expression templates take.
#ifndef ring_contact_contact_face_clipping_h
#define ring_contact_contact_face_clipping_h

#include <Sacado.hpp>

#include <array>
#include <cmath>
#include <vector>

namespace RingContact
{
  namespace FaceClipping
  {
    /// A point or vector in space, and in the auxiliary plane.
    template <typename Number>
    using Vector3 = std::array<Number, 3>;
    template <typename Number>
    using Vector2 = std::array<Number, 2>;

    /// The value of a number (itself for double, the value of an AD
    /// number): what the topology is decided on.
    template <typename Number>
    double
    value(const Number &x)
    {
      return Sacado::ScalarValue<Number>::eval(x);
    }

    /// The auxiliary plane of a slave face: its centre (the vertices'
    /// average), unit normal, and two unit in-plane axes e1, e2 with
    /// e1 x e2 = normal.
    template <typename Number>
    struct Plane
    {
      Vector3<Number> centre, normal, e1, e2;
    };

    /// a x b.
    template <typename Number>
    Vector3<Number>
    cross(const Vector3<Number> &a, const Vector3<Number> &b)
    {
      return {{a[1] * b[2] - a[2] * b[1],
               a[2] * b[0] - a[0] * b[2],
               a[0] * b[1] - a[1] * b[0]}};
    }

    /// a . b.
    template <typename Number>
    Number
    dot(const Vector3<Number> &a, const Vector3<Number> &b)
    {
      return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    }

    /// a / |a|.
    template <typename Number>
    Vector3<Number>
    unit(const Vector3<Number> &a)
    {
      using std::sqrt;
      const Number length = sqrt(dot(a, a));
      return {{a[0] / length, a[1] / length, a[2] / length}};
    }

    /// The plane of a face given by its vertices in order (counter-clockwise
    /// seen from the side its normal points to). Newell's normal, the sum of
    /// the edges' cross products, is the face's mean normal whether or not
    /// the vertices lie in one plane (a warped bilinear face). e1 points
    /// from the centre to the first vertex.
    template <typename Number>
    Plane<Number>
    auxiliary_plane(const std::vector<Vector3<Number>> &face)
    {
      Plane<Number>      plane;
      const unsigned int n = face.size();
      for (unsigned int d = 0; d < 3; ++d)
        {
          plane.centre[d] = 0;
          plane.normal[d] = 0;
        }
      for (unsigned int i = 0; i < n; ++i)
        {
          const Vector3<Number> &a = face[i], &b = face[(i + 1) % n];
          plane.normal[0] += (a[1] - b[1]) * (a[2] + b[2]);
          plane.normal[1] += (a[2] - b[2]) * (a[0] + b[0]);
          plane.normal[2] += (a[0] - b[0]) * (a[1] + b[1]);
          for (unsigned int d = 0; d < 3; ++d)
            plane.centre[d] += a[d] / static_cast<double>(n);
        }
      plane.normal = unit(plane.normal);
      // The first vertex's offset from the centre, less its normal part.
      Vector3<Number> r;
      for (unsigned int d = 0; d < 3; ++d)
        r[d] = face[0][d] - plane.centre[d];
      const Number along = dot(r, plane.normal);
      for (unsigned int d = 0; d < 3; ++d)
        r[d] -= along * plane.normal[d];
      plane.e1 = unit(r);
      plane.e2 = cross(plane.normal, plane.e1);
      return plane;
    }

    /// The coordinates in the plane of the projection of x along the
    /// plane's normal.
    template <typename Number>
    Vector2<Number>
    to_plane(const Plane<Number> &plane, const Vector3<Number> &x)
    {
      Vector3<Number> r;
      for (unsigned int d = 0; d < 3; ++d)
        r[d] = x[d] - plane.centre[d];
      return {{dot(r, plane.e1), dot(r, plane.e2)}};
    }

    /// The point of the plane at coordinates p.
    template <typename Number>
    Vector3<Number>
    from_plane(const Plane<Number> &plane, const Vector2<Number> &p)
    {
      Vector3<Number> x;
      for (unsigned int d = 0; d < 3; ++d)
        x[d] = plane.centre[d] + p[0] * plane.e1[d] + p[1] * plane.e2[d];
      return x;
    }

    /// The signed area of a polygon (positive when counter-clockwise).
    template <typename Number>
    Number
    signed_area(const std::vector<Vector2<Number>> &polygon)
    {
      Number             twice = 0;
      const unsigned int n     = polygon.size();
      for (unsigned int i = 0; i < n; ++i)
        {
          const Vector2<Number> &a = polygon[i], &b = polygon[(i + 1) % n];
          twice += a[0] * b[1] - a[1] * b[0];
        }
      return twice / 2.;
    }

    /// The polygon counter-clockwise: a master face seen from the slave
    /// side is clockwise (its normal points the other way).
    template <typename Number>
    std::vector<Vector2<Number>>
    counter_clockwise(std::vector<Vector2<Number>> polygon)
    {
      if (value(signed_area(polygon)) < 0)
        return {polygon.rbegin(), polygon.rend()};
      return polygon;
    }

    /// The part of `subject` inside the convex polygon `window`, both
    /// counter-clockwise (Sutherland-Hodgman). A vertex counts as inside an
    /// edge when it lies on its left or on it, within `tolerance`;
    /// consecutive vertices closer than `tolerance` are merged, so that a
    /// vertex on an edge does not become two. The tolerance matters for
    /// the derivatives: an edge of the subject that lies on a window edge
    /// (the outer edges of two blocks, meshed alike there) has its two
    /// ends at distances of round-off, one a hair outside, and the
    /// crossing between them, t = d_p / (d_p - d_q), would have a
    /// derivative of one over the round-off (measured: tangent entries of
    /// 1e19 in the 3D patch test in finite strain, whose Newton test then
    /// saw only noise); on the edge within the tolerance, both ends are
    /// inside and there is no crossing. The crossing is that of the edge's
    /// own line, kept between p and q: where p lies within the tolerance
    /// outside the line and q beyond it, both are outside the line and its
    /// crossing of the line p-q lies beyond p, far beyond where the two are
    /// nearly parallel (gmsh's transfinite meshes, refined, put vertices
    /// 1e-13 off the edges of the other face: clip areas 35 % too large,
    /// the 3D patch test's pressure 40 % off at a node); the crossing is
    /// then p itself, merged with it.
    template <typename Number>
    std::vector<Vector2<Number>>
    clip(const std::vector<Vector2<Number>> &subject,
         const std::vector<Vector2<Number>> &window,
         const double                        tolerance)
    {
      std::vector<Vector2<Number>> polygon = subject;
      const unsigned int           n       = window.size();
      for (unsigned int e = 0; e < n && !polygon.empty(); ++e)
        {
          const Vector2<Number> &a = window[e], &b = window[(e + 1) % n];
          // The signed distance (times the edge's length) of p from the
          // edge's line: positive on its left, inside.
          const auto side = [&](const Vector2<Number> &p) -> Number {
            return (b[0] - a[0]) * (p[1] - a[1]) -
                   (b[1] - a[1]) * (p[0] - a[0]);
          };
          // The tolerance as a value of side(): a distance times the
          // edge's length.
          const double on_edge =
            -tolerance *
            std::hypot(value(b[0]) - value(a[0]), value(b[1]) - value(a[1]));
          std::vector<Vector2<Number>> kept;
          const unsigned int           m = polygon.size();
          for (unsigned int i = 0; i < m; ++i)
            {
              const Vector2<Number> &p = polygon[i], &q = polygon[(i + 1) % m];
              const Number           dp = side(p), dq = side(q);
              const bool             p_in = value(dp) >= on_edge,
                         q_in             = value(dq) >= on_edge;
              if (p_in)
                kept.push_back(p);
              // The edge p-q crosses the line: the crossing, written in
              // the numbers of both ends and of the window's edge.
              if (p_in != q_in)
                {
                  Number t = dp / (dp - dq);
                  if (value(t) < 0)
                    t = 0;
                  else if (value(t) > 1)
                    t = 1;
                  kept.push_back(
                    {{p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])}});
                }
            }
          polygon.clear();
          for (const auto &p : kept)
            if (polygon.empty() ||
                std::hypot(value(p[0]) - value(polygon.back()[0]),
                           value(p[1]) - value(polygon.back()[1])) > tolerance)
              polygon.push_back(p);
          if (polygon.size() > 1 &&
              std::hypot(value(polygon.front()[0]) - value(polygon.back()[0]),
                         value(polygon.front()[1]) -
                           value(polygon.back()[1])) <= tolerance)
            polygon.pop_back();
        }
      if (polygon.size() < 3)
        polygon.clear();
      return polygon;
    }

    /// A triangle of the clip polygon, counter-clockwise, and its area.
    template <typename Number>
    struct Triangle
    {
      std::array<Vector2<Number>, 3> vertices;
      Number                         area;
    };

    /// The clip polygon cut into triangles fanned from its vertices'
    /// centroid (the polygon is convex: the clip of convex polygons).
    /// Triangles of an area below `smallest` are left out: slivers of
    /// round-off, whose points would carry no weight.
    template <typename Number>
    std::vector<Triangle<Number>>
    triangulate(const std::vector<Vector2<Number>> &polygon,
                const double                        smallest)
    {
      std::vector<Triangle<Number>> triangles;
      const unsigned int            n = polygon.size();
      if (n < 3)
        return triangles;
      Vector2<Number> c = {{0, 0}};
      for (const auto &p : polygon)
        for (unsigned int d = 0; d < 2; ++d)
          c[d] += p[d] / static_cast<double>(n);
      for (unsigned int i = 0; i < n; ++i)
        {
          Triangle<Number> t{{{c, polygon[i], polygon[(i + 1) % n]}}, 0};
          t.area = signed_area(
            std::vector<Vector2<Number>>(t.vertices.begin(), t.vertices.end()));
          if (value(t.area) > smallest)
            triangles.push_back(t);
        }
      return triangles;
    }

    /// What the clip of a master face against a slave face gives: the
    /// auxiliary plane, the clip polygon in its coordinates and the
    /// triangles.
    template <typename Number>
    struct Cell
    {
      Plane<Number>                 plane;
      std::vector<Vector2<Number>>  polygon;
      std::vector<Triangle<Number>> triangles;
    };

    /// Clip a master face against a slave face, each given by its vertices
    /// in order (a bilinear face's four; a quadratic face is first split
    /// into four bilinear ones). Empty when they do not overlap, or when
    /// the master face stands nearly at right angles to the slave face
    /// (|n_s . n_m| < `orthogonal`, where the projection along n_s would
    /// squash it). Lengths are compared relative to the slave face's size,
    /// areas relative to its area (`relative_area`).
    template <typename Number>
    Cell<Number>
    clip_faces(const std::vector<Vector3<Number>> &slave,
               const std::vector<Vector3<Number>> &master,
               const double                        relative_area = 1e-10,
               const double                        orthogonal    = 1e-3)
    {
      Cell<Number> cell;
      cell.plane                       = auxiliary_plane(slave);
      const Plane<Number> master_plane = auxiliary_plane(master);
      if (std::abs(value(dot(cell.plane.normal, master_plane.normal))) <
          orthogonal)
        return cell;
      std::vector<Vector2<Number>> s, m;
      for (const auto &x : slave)
        s.push_back(to_plane(cell.plane, x));
      for (const auto &x : master)
        m.push_back(to_plane(cell.plane, x));
      s                  = counter_clockwise(s);
      m                  = counter_clockwise(m);
      const double area  = std::abs(value(signed_area(s)));
      const double scale = std::sqrt(area);
      cell.polygon       = clip(s, m, 1e-12 * scale);
      cell.triangles     = triangulate(cell.polygon, relative_area * area);
      return cell;
    }
  } // namespace FaceClipping
} // namespace RingContact

#endif
