// @sect3{The edges of contact zones on a surface}
//
// The rule of active_set.cc's extrapolate_zone_edges(), on a slave surface
// of faces (3D). On a curve a zone's edge is a node, and the rule walks
// from it along the chain of nodes; on a surface the edge is a curve, and
// there is no chain to walk. The rule itself is the same: it is the
// first-order profile of the indicator w lambda - c g~ across an edge
// (near an edge the bodies are locally in plane strain whatever their
// shapes), so it holds along each line across the edge.
//
// A node's distance from the edge is its distance, in the reference
// configuration, to the nearest of the zone's outermost closed nodes (the
// closed nodes with an open neighbour: on a curve, the end node e from
// which the walks measure). Where the indicator changes sign along an edge
// of a face, the zero between its two nodes is a point of the surface at a
// distance from the zone's edge; the rule's new edge lies along the line
// across the edge through that point:
// - too wide: a node in tension (beyond the outermost closed nodes, in the
//   zone's outer half) next to a pressed one farther in puts the zero at
//   distance z from the edge, and the edge moves in by twice that: every
//   closed node nearer the edge than 2 z, and within 2 z of the zero (on
//   the line across the edge, not across the zone), opens;
// - too narrow: open nodes that penetrate, reached from the zone through
//   penetrating nodes three or more links deep, put the zero of the
//   penetration at distance z; the nodes beyond 2/3 of it that the plain
//   rule closes stay open (the first link out closes whatever the extent).
// Measured: Hertz's sphere from touching (doc/validation.md, "Hertz's
// sphere in 3D").
#include <deal.II/numerics/rtree.h>

#include <ring_contact/contact/active_set.h>

#include <algorithm>
#include <deque>
#include <limits>

namespace RingContact
{
  namespace
  {
    using Links = std::vector<std::vector<std::pair<unsigned int, double>>>;

    /// Where the indicator is zero on a link of the surface: its position
    /// and its distance from the zone's edge.
    struct Zero
    {
      Point<3> position;
      double   distance;
    };

    // The zero of the indicator v between nodes i and j (of opposite
    // signs), interpolated linearly on the link, as in the walks of 2D.
    Zero
    zero_between(const unsigned int           i,
                 const unsigned int           j,
                 const std::vector<Point<3>> &x,
                 const std::vector<double>   &v,
                 const std::vector<double>   &distance)
    {
      const double theta = std::clamp(v[i] / (v[i] - v[j]), 0.0, 1.0);
      return {x[i] + theta * (x[j] - x[i]),
              distance[i] + theta * (distance[j] - distance[i])};
    }

    // Every node's distance to the nearest of the nodes `from`, through a
    // tree of their positions.
    std::vector<double>
    distance_to(const std::vector<Point<3>>     &x,
                const std::vector<unsigned int> &from)
    {
      std::vector<Point<3>> points;
      for (const unsigned int k : from)
        points.push_back(x[k]);
      const auto          tree = pack_rtree_of_indices(points);
      std::vector<double> distance(x.size());
      for (unsigned int k = 0; k < x.size(); ++k)
        {
          std::vector<unsigned int> nearest;
          tree.query(boost::geometry::index::nearest(x[k], 1),
                     std::back_inserter(nearest));
          distance[k] = x[k].distance(points[nearest[0]]);
        }
      return distance;
    }

    // The number of links from the nodes `from` (0) to each node reached
    // through nodes where `pass` holds (breadth first); unsigned(-1) where
    // none reaches.
    template <typename Pass>
    std::vector<unsigned int>
    links_from(const Links                     &links,
               const std::vector<unsigned int> &from,
               const Pass                      &pass)
    {
      std::vector<unsigned int> hops(links.size(),
                                     numbers::invalid_unsigned_int);
      std::deque<unsigned int>  queue;
      for (const unsigned int k : from)
        {
          hops[k] = 0;
          queue.push_back(k);
        }
      while (!queue.empty())
        {
          const unsigned int k = queue.front();
          queue.pop_front();
          for (const auto &[j, length] : links[k])
            if (hops[j] == numbers::invalid_unsigned_int && pass(j))
              {
                hops[j] = hops[k] + 1;
                queue.push_back(j);
              }
        }
      return hops;
    }

    // Each node's zone: the connected sets of nodes `inside` (a number per
    // zone, invalid outside), by breadth-first searches from each node not
    // yet reached.
    std::vector<unsigned int>
    zones_of(const Links &links, const std::vector<bool> &inside)
    {
      std::vector<unsigned int> zone(links.size(),
                                     numbers::invalid_unsigned_int);
      unsigned int              n_zones = 0;
      for (unsigned int k = 0; k < links.size(); ++k)
        if (inside[k] && zone[k] == numbers::invalid_unsigned_int)
          {
            const auto hops = links_from(links, {k}, [&](const unsigned int j) {
              return inside[j];
            });
            for (unsigned int j = 0; j < links.size(); ++j)
              if (hops[j] != numbers::invalid_unsigned_int)
                zone[j] = n_zones;
            ++n_zones;
          }
      return zone;
    }
  } // namespace

  void
  ActiveSet::extrapolate_surface_zone_edges(
    const std::vector<bool>   &inside,
    const std::vector<double> &indicator,
    std::vector<bool>         &closed) const
  {
    const auto        &x     = nodes.surface_position;
    const auto        &links = nodes.neighbours;
    const unsigned int n     = inside.size();
    // The zones' outermost closed nodes, and every node's distance to them.
    std::vector<unsigned int> rim;
    for (unsigned int k = 0; k < n; ++k)
      if (inside[k] &&
          std::any_of(links[k].begin(), links[k].end(), [&](const auto &j) {
            return !inside[j.first];
          }))
        rim.push_back(k);
    if (rim.empty())
      return;
    const auto        distance = distance_to(x, rim);
    std::vector<bool> result   = closed;

    // Too wide. A zone's outer half: nearer its edge than its deepest node
    // (on a curve, the half of the walk from the end node).
    const auto          zone = zones_of(links, inside);
    std::vector<double> deepest;
    for (unsigned int k = 0; k < n; ++k)
      if (inside[k])
        {
          deepest.resize(std::max<std::size_t>(deepest.size(), zone[k] + 1));
          deepest[zone[k]] = std::max(deepest[zone[k]], distance[k]);
        }
    for (unsigned int t = 0; t < n; ++t)
      {
        if (!inside[t] || closed[t] || distance[t] == 0 ||
            distance[t] >= deepest[zone[t]])
          continue;
        for (const auto &[p, length] : links[t])
          {
            if (!inside[p] || indicator[p] <= 0 || distance[p] <= distance[t])
              continue;
            const Zero   zero = zero_between(t, p, x, indicator, distance);
            const double edge = 2 * zero.distance;
            for (unsigned int k = 0; k < n; ++k)
              if (zone[k] == zone[t] && distance[k] < edge &&
                  distance[k] < deepest[zone[k]] &&
                  x[k].distance(zero.position) <= edge)
                result[k] = false;
          }
      }

    // Too narrow: the open nodes that the plain rule closes, reached from a
    // zone through such nodes, and the links where their penetration ends.
    std::vector<unsigned int> first_out;
    for (unsigned int k = 0; k < n; ++k)
      if (!inside[k] && closed[k] &&
          std::any_of(links[k].begin(), links[k].end(), [&](const auto &j) {
            return inside[j.first];
          }))
        first_out.push_back(k);
    const auto hops = links_from(links, first_out, [&](const unsigned int j) {
      return !inside[j] && closed[j];
    });
    for (unsigned int q = 0; q < n; ++q)
      {
        if (hops[q] == numbers::invalid_unsigned_int || hops[q] < 2)
          continue;
        for (const auto &[r, length] : links[q])
          {
            if (inside[r] || closed[r] || distance[r] <= distance[q])
              continue;
            const Zero zero = zero_between(q, r, x, indicator, distance);
            for (unsigned int k = 0; k < n; ++k)
              if (hops[k] != numbers::invalid_unsigned_int && hops[k] >= 1 &&
                  distance[k] > 2. / 3. * zero.distance &&
                  x[k].distance(zero.position) <= zero.distance)
                result[k] = false;
          }
      }
    closed = result;
  }
} // namespace RingContact
