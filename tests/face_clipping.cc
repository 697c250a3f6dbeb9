// The clip of a master face against a slave face (contact/face_clipping.h),
// the geometric core of segment-based integration in 3D, against areas
// known in closed form:
// - a unit square and its copy turned through 45 degrees overlap in a
//   regular octagon of area 2 (sqrt 2 - 1);
// - shifted squares overlap in a rectangle, nested ones in the smaller,
//   squares that only touch or lie apart not at all;
// - the same in any orientation and place in space, with a gap between
//   the faces, from any first vertex and in either order of the vertices;
// - a warped slave face clipped against itself gives the area of its
//   projection, |(x2 - x0) x (x3 - x1)| / 2;
// - a master face at right angles to the slave gives nothing;
// - edges that nearly coincide (a refined gmsh mesh): the clips over a
//   slave face sum to its area.
// Then the derivatives that the AD numbers carry through the clip (of the
// area and of its first moment, which moves with the clip vertices) against
// central finite differences of the double version, on a generic pair:
// faces turned against each other, tilted and warped.
#include <ring_contact/contact/face_clipping.h>

#include "tests.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <string>
#include <utility>
#include <vector>

using namespace RingContact::FaceClipping;
using RingContactTests::check;

namespace
{
  using AD    = Sacado::Fad::DFad<double>;
  using Face  = std::vector<Vector3<double>>;
  using Faces = std::pair<Face, Face>;

  // The square [-a, a]^2 at height z, turned through `angle` about the
  // z axis, shifted by (dx, dy); counter-clockwise seen from +z, or
  // clockwise (a master face, whose normal points down).
  Face
  square(const double a,
         const double angle,
         const double dx,
         const double dy,
         const double z,
         const bool   clockwise)
  {
    Face face;
    for (const auto &[x, y] : std::vector<std::pair<double, double>>{
           {-a, -a}, {a, -a}, {a, a}, {-a, a}})
      face.push_back({{std::cos(angle) * x - std::sin(angle) * y + dx,
                       std::sin(angle) * x + std::cos(angle) * y + dy,
                       z}});
    if (clockwise)
      std::reverse(face.begin(), face.end());
    return face;
  }

  // A rotation about the axis (1, 2, 3) by 0.7 and a translation: a place
  // in space with nothing aligned to the axes.
  Face
  moved(const Face &face)
  {
    const double axis[3] = {1 / std::sqrt(14.),
                            2 / std::sqrt(14.),
                            3 / std::sqrt(14.)};
    const double c = std::cos(0.7), s = std::sin(0.7);
    Face         result;
    for (const auto &x : face)
      {
        const double along = axis[0] * x[0] + axis[1] * x[1] + axis[2] * x[2];
        const double cross[3] = {axis[1] * x[2] - axis[2] * x[1],
                                 axis[2] * x[0] - axis[0] * x[2],
                                 axis[0] * x[1] - axis[1] * x[0]};
        Vector3<double> y;
        for (unsigned int d = 0; d < 3; ++d)
          y[d] = c * x[d] + s * cross[d] + (1 - c) * along * axis[d] +
                 (d == 0 ? 0.3 :
                  d == 1 ? -1.2 :
                           2.5);
        result.push_back(y);
      }
    return result;
  }

  template <typename Number>
  Number
  clip_area(const std::vector<Vector3<Number>> &slave,
            const std::vector<Vector3<Number>> &master)
  {
    const Cell<Number> cell = clip_faces(slave, master);
    Number             area = 0;
    for (const auto &t : cell.triangles)
      area += t.area;
    return area;
  }

  // The area and the first moment of the clip polygon, the integral of x
  // over it (each triangle's area times its centroid, in space).
  template <typename Number>
  std::array<Number, 4>
  area_and_moment(const std::vector<Vector3<Number>> &slave,
                  const std::vector<Vector3<Number>> &master)
  {
    const Cell<Number>    cell   = clip_faces(slave, master);
    std::array<Number, 4> result = {{0, 0, 0, 0}};
    for (const auto &t : cell.triangles)
      {
        Vector2<Number> centroid;
        for (unsigned int d = 0; d < 2; ++d)
          centroid[d] =
            (t.vertices[0][d] + t.vertices[1][d] + t.vertices[2][d]) / 3.;
        const Vector3<Number> x = from_plane(cell.plane, centroid);
        result[0] += t.area;
        for (unsigned int d = 0; d < 3; ++d)
          result[d + 1] += t.area * x[d];
      }
    return result;
  }

  void
  check_area(const std::string &what,
             const Face        &slave,
             const Face        &master,
             const double       exact)
  {
    auto &out = RingContactTests::deallog_file;
    // From every first vertex of each face: the same polygon.
    double worst = 0;
    for (unsigned int i = 0; i < slave.size(); ++i)
      for (unsigned int j = 0; j < master.size(); ++j)
        {
          Face s = slave, m = master;
          std::rotate(s.begin(), s.begin() + i, s.end());
          std::rotate(m.begin(), m.begin() + j, m.end());
          worst = std::max(worst, std::abs(clip_area(s, m) - exact));
        }
    out << what << ": area " << clip_area(slave, master) << ", exact " << exact
        << std::endl;
    check(worst <= 1e-13, what + ": the area to 1e-13 from every vertex");
  }
} // namespace

int
main()
{
  auto &out = RingContactTests::deallog_file;
  out << std::setprecision(10) << std::fixed;

  const double pi      = std::acos(-1.);
  const double octagon = 2 * (std::sqrt(2.) - 1);
  const Face   slave   = square(0.5, 0, 0, 0, 0, false);

  // The closed forms, the faces level and then moved into space (with a
  // gap of 0.01 between them, which the projection closes).
  for (const bool in_space : {false, true})
    {
      const auto place = [&](const Face &f) { return in_space ? moved(f) : f; };
      const std::string where = in_space ? " (in space)" : "";
      check_area("octagon" + where,
                 place(slave),
                 place(square(0.5, pi / 4, 0, 0, 0.01, true)),
                 octagon);
      check_area("shifted" + where,
                 place(slave),
                 place(square(0.5, 0, 0.3, 0.2, 0.01, true)),
                 0.7 * 0.8);
      check_area("master around the slave" + where,
                 place(slave),
                 place(square(1, 0.2, 0.1, 0, 0.01, true)),
                 1);
      check_area("master inside the slave" + where,
                 place(slave),
                 place(square(0.25, 0.3, 0.1, -0.1, 0.01, true)),
                 0.25);
      check_area("touching along an edge" + where,
                 place(slave),
                 place(square(0.5, 0, 1, 0, 0.01, true)),
                 0);
      check_area("apart" + where,
                 place(slave),
                 place(square(0.5, 0, 1.5, 0.2, 0.01, true)),
                 0);
      // The master's vertices in the slave's order: the same polygon.
      check_area("master counter-clockwise" + where,
                 place(slave),
                 place(square(0.5, pi / 4, 0, 0, 0.01, false)),
                 octagon);
    }

  // A warped slave face against itself: the area of its projection on the
  // auxiliary plane, half the length of the cross product of its diagonals.
  {
    Face            warped = {{{0, 0, 0}},
                              {{1.1, 0.1, 0.05}},
                              {{0.9, 1, -0.08}},
                              {{-0.1, 0.8, 0.1}}};
    Vector3<double> d1, d2;
    for (unsigned int d = 0; d < 3; ++d)
      {
        d1[d] = warped[2][d] - warped[0][d];
        d2[d] = warped[3][d] - warped[1][d];
      }
    const Vector3<double> n = cross(d1, d2);
    Face                  reversed(warped.rbegin(), warped.rend());
    check_area("warped face against itself",
               warped,
               reversed,
               std::sqrt(dot(n, n)) / 2);
  }

  // A master face standing at right angles to the slave.
  {
    const Face upright = {{{-0.5, 0, 0}},
                          {{0.5, 0, 0}},
                          {{0.5, 0, 1}},
                          {{-0.5, 0, 1}}};
    check(clip_faces(slave, upright).triangles.empty(),
          "a master face at right angles gives no cell");
    out << "master face at right angles: no cell" << std::endl;
  }

  // Edges that nearly coincide: a slave face of a gmsh mesh refined once
  // (prm/two_blocks_3d.prm) and the master faces under it, their vertices
  // as gmsh's transfinite meshing and deal.II's refinement left them, up
  // to 1e-12 off the lines x = 0.5, y = 0.2 .... The slave face's edge
  // x = 0.5 lies 1e-13 beside the master faces' and crosses it at a tiny
  // angle: a crossing taken where both ends lie outside the edge's line
  // (one within the tolerance) fell far beyond the edge, and the four
  // clips summed to 1.17 times the slave face (the pressure 40 % off at a
  // node). The clips now sum to the slave face to 1e-10.
  {
    const auto corners = [](const std::array<double, 8> &xy) {
      // Given in deal.II's lexicographic order; the clip takes a cycle.
      Face face;
      for (const unsigned int v : {0u, 1u, 3u, 2u})
        face.push_back({{xy[2 * v], xy[2 * v + 1], 0}});
      return face;
    };
    const Face              slave_face = corners({{0.49999999999911304,
                                                   0.12500000000011285,
                                                   0.49999999999953398,
                                                   0.25000000000022571,
                                                   0.62499999999928979,
                                                   0.12500000000001102,
                                                   0.62499999999956313,
                                                   0.25000000000002204}});
    const std::vector<Face> masters    = {corners({{0.49999999999921585,
                                                    0.10000000000009736,
                                                    0.5999999999991894,
                                                    0.10000000000003359,
                                                    0.49999999999947259,
                                                    0.20000000000019472,
                                                    0.59999999999943365,
                                                    0.20000000000006718}}),
                                          corners({{0.49999999999947259,
                                                    0.20000000000019472,
                                                    0.59999999999943365,
                                                    0.20000000000006718,
                                                    0.49999999999972933,
                                                    0.30000000000025689,
                                                    0.5999999999996779,
                                                    0.30000000000005855}}),
                                          corners({{0.5999999999991894,
                                                    0.10000000000003359,
                                                    0.69999999999935725,
                                                    0.099999999999969807,
                                                    0.59999999999943365,
                                                    0.20000000000006718,
                                                    0.6999999999995058,
                                                    0.19999999999993961}}),
                                          corners({{0.59999999999943365,
                                                    0.20000000000006718,
                                                    0.6999999999995058,
                                                    0.19999999999993961,
                                                    0.5999999999996779,
                                                    0.30000000000005855,
                                                    0.69999999999965434,
                                                    0.29999999999986016}})};
    double                  total      = 0;
    for (const Face &master : masters)
      total += clip_area(slave_face, master);
    const double area = 0.125 * 0.125;
    out << "nearly coincident edges: the four clips over the slave face "
        << total / area << std::endl;
    check(std::abs(total - area) <= 1e-10 * area,
          "the clips of nearly coincident edges sum to the slave face");
    // The first clip alone: x in [0.5, 0.6], y in [0.125, 0.2].
    check(std::abs(clip_area(slave_face, masters[0]) - 0.1 * 0.075) <=
            1e-10 * area,
          "the clip along the nearly coincident edge is its rectangle");
  }

  // The derivatives: every coordinate of both faces an independent
  // variable (24), on a generic pair.
  {
    Face s = moved({{{-0.5, -0.5, 0}},
                    {{0.55, -0.45, 0.03}},
                    {{0.5, 0.5, 0}},
                    {{-0.45, 0.52, -0.02}}});
    Face m = moved(square(0.45, 0.3, 0.12, -0.07, 0.02, true));
    std::vector<Vector3<AD>> s_ad(4), m_ad(4);
    for (unsigned int v = 0; v < 4; ++v)
      for (unsigned int d = 0; d < 3; ++d)
        {
          s_ad[v][d] = AD(24, 3 * v + d, s[v][d]);
          m_ad[v][d] = AD(24, 12 + 3 * v + d, m[v][d]);
        }
    const auto   exact   = area_and_moment(s_ad, m_ad);
    const double h       = 1e-6;
    double       worst   = 0;
    double       largest = 0;
    for (unsigned int k = 0; k < 24; ++k)
      {
        Face       sp = s, sm = s, mp = m, mm = m;
        const auto v = (k % 12) / 3, d = k % 3;
        auto      &plus  = k < 12 ? sp[v][d] : mp[v][d];
        auto      &minus = k < 12 ? sm[v][d] : mm[v][d];
        plus += h;
        minus -= h;
        const auto up = area_and_moment(sp, mp), down = area_and_moment(sm, mm);
        for (unsigned int q = 0; q < 4; ++q)
          {
            const double fd = (up[q] - down[q]) / (2 * h);
            worst           = std::max(worst, std::abs(exact[q].dx(k) - fd));
            largest         = std::max(largest, std::abs(fd));
          }
      }
    out << "clip area " << exact[0].val() << " with "
        << clip_faces(s_ad, m_ad).polygon.size() << " vertices" << std::endl;
    check(clip_faces(s_ad, m_ad).polygon.size() >= 6,
          "the generic pair's clip cuts both faces");
    check(largest > 0.1, "the derivatives are not all zero");
    check(worst <= 1e-8 * largest,
          "AD derivatives of the area and first moment equal central "
          "differences to 1e-8");
    out << "AD derivatives of the area and the first moment (24 variables) "
           "against central differences: agree to 1e-8"
        << std::endl;
  }
  return 0;
}
