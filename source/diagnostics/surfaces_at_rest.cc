// @sect3{Diagnostics: the contact surfaces at rest}
//
// Warnings, not errors (surfaces_at_rest.h says when and why), each read off
// the surfaces in the reference state, before the first step.
//
// First, surfaces that interpenetrate: an overlap at rest is pushed out
// elastically in the first step, a load the problem does not state. The
// depth is each node's mean gap g~_k / w_k, so a curved slave against a
// faceted master reports 2/3 of the sagitta (the mean of a parabolic gap
// under a linear multiplier), not its maximum. It was added when
// modelisation H with a Q1 outer ring and Mapping degree = 0 failed all 63
// of its checks without a word. update() pairs the surfaces at `solution`,
// the unloaded state, before the depth is read.
#include <ring_contact/diagnostics/surfaces_at_rest.h>

#include <deal.II/dofs/dof_accessor.h>
#include <deal.II/grid/manifold.h>
#include <deal.II/grid/tria_accessor.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <vector>

namespace RingContact
{
  namespace Diagnostics
  {
    bool
    report_initial_interpenetration(ContactInterface     &contact,
                                    const Vector<double> &solution,
                                    std::ostream         &log)
    {
      contact.update(solution);
      const auto [depth, where] = contact.deepest_interpenetration();
      if (!(depth > 1e-4 * contact.slave_segment_length()))
        return false;
      log << "Warning: the contact surfaces interpenetrate before any "
             "load, by up to "
          << std::setprecision(3) << depth << " at (" << where[0] << ", "
          << where[1] << "), " << 100 * depth / contact.slave_segment_length()
          << " % of the slave's shortest segment: the contact pushes them "
             "apart in the first step, a load the problem does not state. "
             "A curved slave against a faceted master does this (Mapping "
             "degree = 0 with mixed element degrees: Mapping degree = 1 "
             "makes both faceted), as do bodies that overlap in the mesh.\n"
          << std::setprecision(6);
      return true;
    }

    // @sect4{A mesh too coarse for its geometry}
    //
    // The error of the initial gap that the discrete surfaces make: at three
    // points of every slave segment, the slave's departure from its curve
    // (the face's manifold: the gmsh model's circle, the rings' polar
    // manifold) minus the master's at the partner, along the master's
    // normal. A faceted arc (Mapping degree = 1) departs by its chord sag,
    // h^2 / 8 R; a quadratic mapping by O(h^4 / R^3). Matching facets make
    // the same error on both sides, and it cancels. Compared with the
    // median size of the initial mean gaps g~_k / w_k, the gap or the
    // interference the problem states, where the surfaces conform (most
    // gaps within a factor 2 of each other). The threshold is low, 0.1 %: a
    // shrink fit of 1e-3 R between straight facets that do not match swung
    // from -100 % (nodes open) to +200 % at 40, 80 and 160 segments per
    // quarter alike, where the sag is 19 %, 5 % and 1.2 % of the
    // interference: the kinks of the facets, not the sag, make the swing,
    // and refining does not remove it. Curved (Mapping degree = 2), the
    // departure is 1e-6 of it and the swing a few percent.
    bool
    report_coarse_geometry(ContactInterface     &contact,
                           const Vector<double> &solution,
                           std::ostream         &log)
    {
      contact.update(solution);
      std::vector<double> gaps;
      const double        h = contact.slave_segment_length();
      for (const double g : contact.mean_gaps())
        if (std::abs(g) > 1e-8 * h)
          gaps.push_back(std::abs(g));
      // Most nodes must have a gap, and of one size (conforming surfaces: a
      // fit, a gap that closes): surfaces that start in contact state no
      // gap size, and a body that comes to the other from afar (the
      // shallow ironing's indenter, 0.03 to 1 m away) states none that the
      // pressure depends on.
      if (gaps.empty() || 2 * gaps.size() < contact.mean_gaps().size())
        return false;
      std::sort(gaps.begin(), gaps.end());
      const double gap = gaps[gaps.size() / 2];
      if (gaps[(9 * gaps.size()) / 10] > 2 * gaps[gaps.size() / 10])
        return false;

      const ContactSurface &slave  = contact.slave_surface(),
                           &master = contact.master_surface();
      const auto departure         = [](const ContactSurface &surface,
                                const unsigned int    s,
                                const double          t) {
        const auto    &segment = surface.segments()[s];
        const auto     face    = segment.cell->face(segment.face_no);
        const Point<2> on_curve =
          face->get_manifold().get_intermediate_point(face->vertex(0),
                                                      face->vertex(1),
                                                      t);
        return on_curve - surface.reference_point(s, t).x;
      };
      double   worst = 0;
      Point<2> where;
      for (unsigned int s = 0; s < slave.segments().size(); ++s)
        if (!slave.segments()[s].is_copy)
          for (const double t : {0.25, 0.5, 0.75})
            {
              const Point<2>   x = slave.reference_point(s, t).x;
              const Projection p = master.project(x);
              if (p.clamped)
                continue;
              const double error =
                (departure(slave, s, t) - departure(master, p.segment, p.t)) *
                master.normal(p);
              if (std::abs(error) > worst)
                {
                  worst = std::abs(error);
                  where = x;
                }
            }
      if (!(worst > 1e-3 * gap))
        return false;
      log << "Warning: the contact surfaces are too coarse for their "
             "curves: at ("
          << std::setprecision(3) << where[0] << ", " << where[1]
          << ") the gap they give departs by " << worst
          << " from the gap between the curves, " << 100 * worst / gap
          << " % of the typical initial gap or interference (" << gap
          << "). Between facets that do not match, the pressure then "
             "swings from facet to facet, and refining does not remove it "
             "(a shrink fit: -100 % to +200 % at any mesh); Mapping degree "
             "= 2 curves the surfaces.\n"
          << std::setprecision(6);
      return true;
    }

    // @sect4{A slave coarser than its master, under a point-wise scheme}
    //
    // A point-wise scheme samples the master at a few points of each slave
    // segment; where a slave segment spans more than one master segment, the
    // master's kinks between those points are held by no constraint, and the
    // pressure swings from node to node whatever the mesh size. Measured on
    // the shrink fit of prm/shrink_fit.prm with its surfaces' roles swapped
    // (the 40 segments per quarter the slave, the 57 the master; curved,
    // Q1): nodal -23 % to +20 %, Gauss 2 -5 % to +6 %, segment-based 2
    // within 0.13 %; the right way round -3.8 % to +1.6 %, -1.4 % to +1.3 %
    // and 0.2 %. At a ratio of 1.125 (40 against 45) nodal already swings by
    // -8.8 %. The ratio is of the segments' lengths, not of their nodes'
    // spacings: a linear slave against a quadratic master of the same
    // segments (modelisations E and F) is sampled at the master's mid-side
    // nodes by the nodal scheme, and is the LBB-stable choice of the
    // multiplier.
    bool
    report_coarse_slave(ContactInterface        &contact,
                        const Vector<double>    &solution,
                        const IntegrationScheme &scheme,
                        const types::boundary_id slave_id,
                        const types::boundary_id master_id,
                        std::ostream            &log)
    {
      if (scheme.type == ContactIntegration::segment_based)
        return false;
      contact.update(solution);
      const ContactSurface &slave  = contact.slave_surface(),
                           &master = contact.master_surface();
      const auto length            = [](const ContactSurface &surface,
                             const unsigned int    s) {
        return surface.reference_point(s, 0).x.distance(
          surface.reference_point(s, 1).x);
      };
      // The slave segments that face the master: their midpoint projects
      // orthogonally onto it, the two normals opposed, and the gap there
      // within two of the segment's lengths of the smallest such gap (the
      // segments that touch first; bodies may start apart, an indenter far
      // above its block, a gap that closes).
      struct Facing
      {
        double gap, length, ratio;
      };
      std::vector<Facing> facing;
      for (unsigned int s = 0; s < slave.segments().size(); ++s)
        if (!slave.segments()[s].is_copy)
          {
            const double     h = length(slave, s);
            const Projection p =
              master.project(slave.reference_point(s, 0.5).x);
            if (p.segment == numbers::invalid_unsigned_int || p.clamped)
              continue;
            const Tensor<1, 2> n = slave.scaled_normal(s, 0.5);
            if (!(n * master.normal(p) < -0.5 * n.norm()))
              continue;
            facing.push_back({p.gap, h, h / length(master, p.segment)});
          }
      if (facing.empty())
        return false;
      const double closest =
        std::min_element(facing.begin(),
                         facing.end(),
                         [](const Facing &a, const Facing &b) {
                           return a.gap < b.gap;
                         })
          ->gap;
      std::vector<double> ratios;
      for (const Facing &f : facing)
        if (f.gap <= closest + 2 * f.length)
          ratios.push_back(f.ratio);
      if (ratios.empty())
        return false;
      std::sort(ratios.begin(), ratios.end());
      const double ratio = ratios[ratios.size() / 2];
      if (!(ratio > 1.1))
        return false;
      log << "Warning: the slave surface (boundary " << slave_id
          << ") is coarser than its master (boundary " << master_id
          << ") where they face each other: its segments are "
          << std::setprecision(3) << ratio
          << " times as long as the master's (median). The " << scheme.name()
          << " scheme holds the master only at its points on each slave "
             "segment, so the pressure swings from node to node, and "
             "refining both does not remove it (a shrink fit, its slave 1.4 "
             "times as long: nodal -23 % to +20 % with Q1 elements, Gauss 2 "
             "+-6 % with Q1 or Q2): make the finer surface the slave, or use "
             "segment-based integration.\n"
          << std::setprecision(6);
      return true;
    }

  } // namespace Diagnostics
} // namespace RingContact
