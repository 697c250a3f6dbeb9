// The contact zones' edges extrapolated on a surface of faces
// (ActiveSet on the nodes of a 3D slave surface, surface_zone_edges.cc),
// against the first-order profiles the rule is built on, posed on a flat
// square of 40 x 40 faces with a circular zone whose true radius is a:
// - too wide: the zone closed to radius b > a, the indicator inside it
//   Hertz's profile of a zone too wide, (a^2 + b^2 - 2 r^2) / sqrt(b^2 -
//   r^2) (a line load across the edge: the first-order change of the square
//   root with b), zero at x0 = sqrt((a^2 + b^2) / 2). The plain rule opens
//   the tension band and keeps r < x0 closed; the rule moves the edge in by
//   twice the band's depth, to 2 x0 - b, within a cell of it (the first-order
//   estimate of a);
// - too narrow: the zone closed to radius b < a, the open nodes beyond it
//   penetrating as -sqrt(s) (3 (a - b) / 2 - s), s = r - b, up to 3/2 of the
//   shortfall. The plain rule closes them all; the rule keeps open those
//   beyond 2/3 of the penetration's extent, at a, within a cell;
// - a band of tension one node deep, and a penetration two links deep, are
//   left to the plain rule, as on a curve;
// - the rule acts only where it is allowed (the first iterations of a step).
#include <deal.II/lac/vector.h>

#include <ring_contact/contact/active_set.h>
#include <ring_contact/contact/multiplier_nodes.h>

#include "tests.h"

#include <cmath>
#include <iomanip>

using namespace dealii;
using RingContact::ActiveSet;
using RingContact::MultiplierNodes;
using RingContactTests::check;

namespace
{
  constexpr unsigned int n = 40;      // faces per side of [-1, 1]^2
  constexpr double       h = 2.0 / n; // their size
  constexpr double       c = 1.0;     // the complementarity constant
  constexpr unsigned int m = (n + 1) * (n + 1);

  // The nodes of the square's faces, in deal.II's lexicographic order per
  // face; weights w_k = 1, the dofs the nodes' numbers.
  MultiplierNodes
  square()
  {
    std::vector<types::global_dof_index>     dofs(m);
    std::vector<Point<3>>                    x(m);
    std::vector<std::array<unsigned int, 4>> faces;
    for (unsigned int j = 0; j <= n; ++j)
      for (unsigned int i = 0; i <= n; ++i)
        {
          dofs[j * (n + 1) + i] = j * (n + 1) + i;
          x[j * (n + 1) + i]    = Point<3>(-1 + i * h, -1 + j * h, 0.25);
        }
    for (unsigned int j = 0; j < n; ++j)
      for (unsigned int i = 0; i < n; ++i)
        faces.push_back({{j * (n + 1) + i,
                          j * (n + 1) + i + 1,
                          (j + 1) * (n + 1) + i,
                          (j + 1) * (n + 1) + i + 1}});
    return MultiplierNodes(dofs, std::vector<double>(m, 1.0), faces, x);
  }

  double
  radius(const MultiplierNodes &nodes, const unsigned int k)
  {
    const Point<3> &x = nodes.surface_position[k];
    return std::hypot(x[0], x[1]);
  }

  // A state: the multipliers and the weighted gaps of the nodes, each
  // given as a function of r.
  struct State
  {
    Vector<double>      lambda = Vector<double>(m);
    std::vector<double> gap    = std::vector<double>(m, 0.0);
  };

  // The state of a zone closed to radius b: the multipliers `inside` it,
  // the gaps `outside`, as functions of r.
  template <typename Inside, typename Outside>
  State
  profile(const MultiplierNodes &nodes,
          const double           b,
          const Inside          &inside,
          const Outside         &outside)
  {
    State s;
    for (unsigned int k = 0; k < m; ++k)
      {
        const double r = radius(nodes, k);
        if (r <= b)
          s.lambda(k) = inside(r);
        else
          s.gap[k] = outside(r);
      }
    return s;
  }

  // The zone closed to radius b by the plain rule (pressed inside, a gap
  // outside): the active set the next choice starts from.
  void
  close_disk(ActiveSet &states, const MultiplierNodes &nodes, const double b)
  {
    const State s = profile(
      nodes, b, [](double) { return 1.0; }, [&](double r) { return r - b; });
    states.choose_closed_nodes(s.lambda,
                               s.gap,
                               std::vector<bool>(m, true),
                               true);
  }

  // The largest radius of a closed node, and the smallest of an open node
  // within the square's inscribed disk.
  std::pair<double, double>
  zone_radii(const ActiveSet &states, const MultiplierNodes &nodes)
  {
    double closed = 0, open = 1;
    for (unsigned int k = 0; k < m; ++k)
      if (states.is_closed(k))
        closed = std::max(closed, radius(nodes, k));
      else
        open = std::min(open, radius(nodes, k));
    return {closed, open};
  }

  // Choose from state `s` with the extrapolation allowed or not, from the
  // zone closed to radius b; returns the zone's radii.
  std::pair<double, double>
  choose(const MultiplierNodes &nodes,
         const double           b,
         const State           &s,
         const bool             extrapolate)
  {
    ActiveSet states(nodes, c, 0., h);
    close_disk(states, nodes, b);
    states.allow_edge_extrapolation(extrapolate);
    states.choose_closed_nodes(s.lambda,
                               s.gap,
                               std::vector<bool>(m, true),
                               true);
    return zone_radii(states, nodes);
  }

  // Too wide: closed to b, the true radius a; Hertz's profile of a zone
  // too wide inside (its h^2 keeps the edge node finite), a gap outside.
  State
  too_wide(const MultiplierNodes &nodes, const double a, const double b)
  {
    return profile(
      nodes,
      b,
      [&](double r) {
        return (a * a + b * b - 2 * r * r) / std::sqrt(b * b - r * r + h * h);
      },
      [&](double r) { return (r - b) * (r - b); });
  }

  // Too narrow: closed to b, the true radius a; the master penetrating
  // beyond b up to b + 3 (a - b) / 2.
  State
  too_narrow(const MultiplierNodes &nodes, const double a, const double b)
  {
    return profile(
      nodes,
      b,
      [&](double r) { return std::sqrt(b * b - r * r); },
      [&](double r) { return -std::sqrt(r - b) * (1.5 * (a - b) - (r - b)); });
  }
} // namespace

int
main()
{
  auto &out = RingContactTests::deallog_file;
  out << std::setprecision(4);
  const MultiplierNodes nodes = square();
  unsigned int          links = 0;
  for (const auto &neighbours : nodes.neighbours)
    links += neighbours.size();
  check(links == 2 * 2 * n * (n + 1),
        "each edge of the faces links its two nodes once");
  out << "a square of " << n << " x " << n << " faces: " << m << " nodes, "
      << links / 2 << " links" << std::endl;

  // Too wide, and too wide by a band of one node (a = 0.68, b = 0.7).
  {
    const double a = 0.5, b = 0.8, x0 = std::sqrt((a * a + b * b) / 2);
    const State  s     = too_wide(nodes, a, b);
    const auto   plain = choose(nodes, b, s, false);
    const auto   moved = choose(nodes, b, s, true);
    out << "too wide (a = " << a << ", closed to b = " << b
        << "): plain rule closed to " << plain.first << ", extrapolated to "
        << moved.first << " (2 x0 - b = " << 2 * x0 - b << ")" << std::endl;
    check(plain.first < x0 + 1e-9 && plain.second > x0 - h,
          "the plain rule opens the tension band");
    check(std::abs(moved.first - (2 * x0 - b)) < h &&
            std::abs(moved.second - (2 * x0 - b)) < h,
          "the edge moves in by twice the band's depth, within a cell");
    const double a1 = 0.68, b1 = 0.7;
    const auto   thin = too_wide(nodes, a1, b1);
    check(choose(nodes, b1, thin, true) == choose(nodes, b1, thin, false),
          "a band of one node is left to the plain rule");
    out << "a band of tension one node deep: the plain rule's choice"
        << std::endl;
  }
  // Too narrow, and too narrow by a penetration of two links.
  {
    const double a = 0.5, b = 0.3;
    const State  s     = too_narrow(nodes, a, b);
    const auto   plain = choose(nodes, b, s, false);
    const auto   moved = choose(nodes, b, s, true);
    out << "too narrow (a = " << a << ", closed to b = " << b
        << "): plain rule closed to " << plain.first << ", extrapolated to "
        << moved.first << std::endl;
    check(plain.first > b + 1.5 * (a - b) - h,
          "the plain rule closes every penetrating node");
    check(std::abs(moved.first - a) < h && std::abs(moved.second - a) < h,
          "the edge moves out to 2/3 of the penetration, within a cell");
    const double a1 = 0.33, b1 = 0.3;
    const auto   thin = too_narrow(nodes, a1, b1);
    check(choose(nodes, b1, thin, true) == choose(nodes, b1, thin, false),
          "a penetration two links deep is left to the plain rule");
    out << "a penetration two links deep: the plain rule's choice" << std::endl;
  }
}
