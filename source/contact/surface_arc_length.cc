// @sect3{Arc length along a slave surface}
//
// A contact pressure is read along the interface: plotted against a
// coordinate that runs along it, not against x or y, which fold a curved
// surface onto itself. The slave surface's VTU files carry this arc
// length (`arc_length`), so that ParaView's *Plot Data* (or a script)
// draws p(s) directly. The segments of a surface know their neighbours
// (ContactSurface::find_neighbours()); the chains are walked from a
// start that a user can predict, and each node gets the length of the
// reference curve from that start.
#include <deal.II/base/quadrature_lib.h>

#include <ring_contact/base/dimension.h>
#include <ring_contact/contact/surface_arc_length.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace RingContact
{
  namespace
  {
    // A segment of a chain and the end (0 or 1) at which the walk enters
    // it.
    using Step = std::pair<unsigned int, unsigned int>;

    // The length of the reference curve of a segment between the
    // parameters a < b: Gauss with 8 points, exact for the straight and the
    // quadratic geometries and far below plotting accuracy for the others.
    double
    curve_length(const ContactSurface &surface,
                 const unsigned int    segment,
                 const double          a,
                 const double          b)
    {
      static const QGauss<1> gauss(8);
      double                 length = 0;
      for (unsigned int q = 0; q < gauss.size(); ++q)
        length +=
          surface.reference_point(segment, a + (b - a) * gauss.point(q)[0])
            .dx.norm() *
          gauss.weight(q) * (b - a);
      return length;
    }

    // The position of the vertex at which a step enters its segment.
    Point<dim>
    entry_point(const ContactSurface &surface, const Step &step)
    {
      return surface.reference_point(step.first, step.second).x;
    }

    // The chain that contains `start`, entered at `end`: followed through
    // the neighbours until an open end, a rotated copy or the start again.
    std::vector<Step>
    walk(const ContactSurface &surface,
         const unsigned int    start,
         const unsigned int    end,
         std::vector<bool>    &visited)
    {
      const auto       &segments = surface.segments();
      std::vector<Step> chain;
      Step              step = {start, end};
      while (true)
        {
          visited[step.first] = true;
          chain.push_back(step);
          const auto        &segment = segments[step.first];
          const unsigned int exit    = 1 - step.second;
          const unsigned int next    = segment.neighbours[exit];
          if (next == numbers::invalid_unsigned_int || segments[next].is_copy ||
              visited[next])
            return chain;
          step = {next, static_cast<unsigned int>(segment.neighbour_t[exit])};
        }
    }

    // The same chain walked the other way.
    std::vector<Step>
    reversed(const std::vector<Step> &chain)
    {
      std::vector<Step> other;
      for (auto s = chain.rbegin(); s != chain.rend(); ++s)
        other.emplace_back(s->first, 1 - s->second);
      return other;
    }

    // An open chain starts at its end of lowest x, then lowest y.
    std::vector<Step>
    oriented_open(const ContactSurface &surface, const std::vector<Step> &chain)
    {
      const Point<dim> first     = entry_point(surface, chain.front());
      const auto      &last_step = chain.back();
      const Point<dim> last =
        surface.reference_point(last_step.first, 1 - last_step.second).x;
      const bool reverse =
        last[0] < first[0] || (last[0] == first[0] && last[1] < first[1]);
      return reverse ? reversed(chain) : chain;
    }

    // A closed chain runs counterclockwise (positive signed area) from its
    // vertex of lowest polar angle in [0, 2 pi) about its centroid.
    std::vector<Step>
    oriented_closed(const ContactSurface &surface, std::vector<Step> chain)
    {
      std::vector<Point<dim>> vertices;
      for (const auto &step : chain)
        vertices.push_back(entry_point(surface, step));
      double area = 0;
      for (unsigned int i = 0; i < vertices.size(); ++i)
        {
          const Point<dim> &p = vertices[i];
          const Point<dim> &q = vertices[(i + 1) % vertices.size()];
          area += p[0] * q[1] - q[0] * p[1];
        }
      if (area < 0)
        chain = reversed(chain);
      Point<dim> centre;
      for (const auto &step : chain)
        centre += entry_point(surface, step) / double(chain.size());
      const auto angle = [&](const Step &step) {
        const Tensor<1, dim> r = entry_point(surface, step) - centre;
        // A vertex on the positive x axis through the centre (node A of
        // the rings) is the start, whatever the round-off of the centre.
        const double a = std::atan2(r[1], r[0]);
        return a < -1e-9 ? a + 2 * numbers::PI : std::max(a, 0.0);
      };
      const auto first = std::min_element(chain.begin(),
                                          chain.end(),
                                          [&](const Step &a, const Step &b) {
                                            return angle(a) < angle(b);
                                          });
      std::rotate(chain.begin(), first, chain.end());
      return chain;
    }
  } // namespace


  // The chains one after the other: those with an open end first, each
  // walked whole from it, then the closed ones. The rotated copies of a
  // cyclic sector are left out, and end the chains they border: their
  // unknowns are the sector's own, and the VTU file holds the faces of the
  // mesh only.
  std::vector<SurfaceChain>
  surface_chains(const ContactSurface &surface)
  {
    const auto               &segments = surface.segments();
    std::vector<SurfaceChain> chains;
    std::vector<bool>         visited(segments.size(), false);
    const auto open_at = [&](const unsigned int s, const unsigned int e) {
      const unsigned int n = segments[s].neighbours[e];
      return n == numbers::invalid_unsigned_int || segments[n].is_copy;
    };
    while (true)
      {
        // An unvisited segment at an open end first: its chain is walked
        // whole from there. Only closed chains are left after those.
        unsigned int start = numbers::invalid_unsigned_int, end = 0;
        bool         open = false;
        for (unsigned int s = 0; s < segments.size() && !open; ++s)
          if (!visited[s] && !segments[s].is_copy)
            for (unsigned int e = 0; e < 2 && !open; ++e)
              if (open_at(s, e) || start == numbers::invalid_unsigned_int)
                {
                  start = s;
                  end   = e;
                  open  = open_at(s, e);
                }
        if (start == numbers::invalid_unsigned_int)
          break;
        // Oriented as a user predicts it (oriented_open(), oriented_closed()),
        // and measured along the reference curve, which the chain's last
        // face of a closed surface runs to in the VTU file.
        SurfaceChain chain;
        chain.closed = !open;
        chain.steps =
          open ? oriented_open(surface, walk(surface, start, end, visited)) :
                 oriented_closed(surface, walk(surface, start, end, visited));
        for (const auto &step : chain.steps)
          chain.length += curve_length(surface, step.first, 0, 1);
        chains.push_back(std::move(chain));
      }
    return chains;
  }

  // The arc length of each multiplier node along its chain. The nodes of
  // a quadratic multiplier (three a segment) are measured to their own
  // parameter on the segment, not interpolated, so that a curved segment's
  // middle node lies at the true length.
  std::map<types::global_dof_index, double>
  arc_lengths(const ContactSurface &surface)
  {
    const auto                &segments = surface.segments();
    const std::vector<double> &nodes    = surface.multiplier_nodes();
    std::map<types::global_dof_index, double> lengths;
    for (const auto &chain : surface_chains(surface))
      {
        // Each node: the length up to its segment's entry, plus the length
        // within the segment from the entry to the node. A vertex shared by
        // two segments gets the same value from both, but for the start of
        // a closed chain, which keeps its 0.
        double before = 0;
        for (const auto &[s, entry] : chain.steps)
          {
            const auto &dofs = segments[s].multiplier_dofs;
            for (unsigned int i = 0; i < dofs.size(); ++i)
              {
                const double t      = nodes[i];
                const double within = entry == 0 ?
                                        curve_length(surface, s, 0, t) :
                                        curve_length(surface, s, t, 1);
                lengths.emplace(dofs[i], before + within);
              }
            before += curve_length(surface, s, 0, 1);
          }
      }
    return lengths;
  }
} // namespace RingContact
