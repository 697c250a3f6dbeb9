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
#include <ring_contact/base/dimension.h>
#include <ring_contact/diagnostics/surfaces_at_rest.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_accessor.h>
#include <deal.II/grid/manifold.h>
#include <deal.II/grid/tria_accessor.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <map>
#include <sstream>
#include <vector>

namespace RingContact
{
  namespace Diagnostics
  {
    bool
    report_initial_interpenetration(ContactInterface<dim> &contact,
                                    const Vector<double>  &solution,
                                    std::ostream          &log)
    {
      contact.update(solution);
      const auto [depth, where] = contact.deepest_interpenetration();
      const double h            = contact.slave_surface().min_segment_length();
      if (!(depth > 1e-4 * h))
        return false;
      log << "Warning: the contact surfaces interpenetrate before any "
             "load, by up to "
          << std::setprecision(3) << depth << " at (" << where[0] << ", "
          << where[1] << "), " << 100 * depth / h
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
    // shrink fit of 1e-3 R between straight facets that do not match swung from
    // open nodes to a multiple of the pressure at 40, 80 and 160 segments per
    // quarter alike (doc/validation.md, "Curved geometry, ties and touching
    // bodies"), where the sag is 19 %, 5 % and 1.2 % of the interference: the
    // kinks of the facets, not the sag, make the swing, and refining does not
    // remove it. Curved (Mapping degree = 2), the departure is 1e-6 of it and
    // the swing a few percent.
    bool
    report_coarse_geometry(ContactInterface<dim> &contact,
                           const Vector<double>  &solution,
                           std::ostream          &log)
    {
      contact.update(solution);
      std::vector<double> gaps;
      const double        h = contact.slave_surface().min_segment_length();
      for (const double g : contact.active_set().mean_gaps())
        if (std::abs(g) > 1e-8 * h)
          gaps.push_back(std::abs(g));
      // Most nodes must have a gap, and of one size (conforming surfaces: a
      // fit, a gap that closes): surfaces that start in contact state no
      // gap size, and a body that comes to the other from afar (the
      // shallow ironing's indenter, 0.03 to 1 m away) states none that the
      // pressure depends on.
      if (gaps.empty() ||
          2 * gaps.size() < contact.active_set().mean_gaps().size())
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
        const auto      &segment = surface.segments()[s];
        const auto       face    = segment.cell->face(segment.face_no);
        const Point<dim> on_curve =
          face->get_manifold().get_intermediate_point(face->vertex(0),
                                                      face->vertex(1),
                                                      t);
        return on_curve - surface.reference_point(s, t).x;
      };
      double     worst = 0;
      Point<dim> where;
      for (unsigned int s = 0; s < slave.segments().size(); ++s)
        if (!slave.segments()[s].is_copy)
          for (const double t : {0.25, 0.5, 0.75})
            {
              const Point<dim> x = slave.reference_point(s, t).x;
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

    // @sect4{Surfaces that do not match, under a point-wise scheme}
    //
    // The contact patch test asks that a uniform pressure be passed from one
    // body to the other exactly: every master node must receive the integral
    // of the pressure against its shape function, its share. Segment-based
    // (mortar) integration does so on any pair of meshes, since it cuts the
    // slave segments where the master's shape functions have their kinks. A
    // point-wise scheme samples the master at its points on each slave
    // segment, and where the two surfaces' nodes do not face each other the
    // samples give some master nodes more than their share and others less:
    // the discrete problem then has no uniform solution, and the pressure
    // swings from node to node by an amount that depends on how the meshes
    // fall against each other, not on their size (refining both keeps the
    // ratio, and the swing). This is the node-to-segment method's known
    // limit, kept as it is because the point-wise schemes are the original
    // Code_Aster's, which the rings reproduce; the run says so wherever it
    // applies, with this mesh's own figure.
    //
    // The figure is measured, not estimated: each scheme's pairing of the
    // surfaces at rest gives every master node the weight a unit pressure
    // puts on it (ContactInterface::master_load_weights(), the integral of
    // its shape function over the slave points paired with it), and the
    // point-wise scheme's weights are compared with those of the mortar
    // scheme on the same surfaces (six Gauss points per piece). Weights, not
    // force vectors: on a faceted circle the nodal scheme pushes along the
    // vertex normal where the mortar forces of the two facets add up to
    // cos(theta / 2) of it, a difference of the normal's representation
    // that matching surfaces have too. The nodes compared are those the
    // slave covers whole and faces nearly parallel: the mortar weight within
    // a factor 0.99 to 1.5 of the node's own share (its shape function's
    // integral over the master) times the median of that coverage. Ends of
    // the covered zone, and parts of a curved slave far from the master,
    // are left out. On matching surfaces
    // the two weights agree to round-off, and nothing is said.
    LoadTransfer
    measure_load_transfer(ContactInterface<dim> &pointwise,
                          ContactInterface<dim> &mortar,
                          const Vector<double>  &solution)
    {
      pointwise.update(solution);
      mortar.update(solution);
      const auto sampled = pointwise.master_load_weights();
      const auto exact   = mortar.master_load_weights();

      // Each master node's share: the integral of its shape function over
      // the master surface, in the reference configuration.
      const ContactSurface &master = pointwise.master_surface();
      const QGauss<1>       rule(6);
      std::vector<double>   phi(master.displacement_basis().size());
      std::map<types::global_dof_index, double>     share;
      std::map<types::global_dof_index, Point<dim>> where;
      for (unsigned int s = 0; s < master.segments().size(); ++s)
        {
          const SurfaceSegment &segment = master.segments()[s];
          if (segment.is_copy)
            continue;
          for (unsigned int q = 0; q < rule.size(); ++q)
            {
              const double t = rule.point(q)[0];
              master.displacement_basis().evaluate(t, phi);
              const double ds =
                master.reference_point(s, t).dx.norm() * rule.weight(q);
              for (unsigned int j = 0; j < phi.size(); ++j)
                share[segment.dofs_x[j]] += phi[j] * ds;
            }
          for (unsigned int j = 0; j < phi.size(); ++j)
            where[segment.dofs_x[j]] =
              master.reference_point(s, master.displacement_nodes()[j]).x;
        }

      // The ratio of the two weights at the nodes the slave covers whole:
      // those whose coverage (mortar weight over share) is within 0.99 to
      // 1.5 times the median coverage. The median is 1 on flat surfaces and
      // the ratio of the radii on concentric arcs apart (a slave circle of
      // 0.6 against a master of 0.72 covers each master node's share with
      // 0.83 of it).
      std::vector<double> coverages;
      for (const auto &[node, own_share] : share)
        {
          const auto e = exact.find(node);
          if (e != exact.end() && e->second > 0)
            coverages.push_back(e->second / own_share);
        }
      LoadTransfer transfer;
      if (coverages.empty())
        return transfer;
      std::nth_element(coverages.begin(),
                       coverages.begin() + coverages.size() / 2,
                       coverages.end());
      const double median = coverages[coverages.size() / 2];
      for (const auto &[node, own_share] : share)
        {
          const auto e = exact.find(node);
          if (e == exact.end() || !(e->second >= 0.99 * median * own_share &&
                                    e->second <= 1.5 * median * own_share))
            continue;
          const auto   s = sampled.find(node);
          const double ratio =
            (s == sampled.end() ? 0.0 : s->second) / e->second;
          ++transfer.n_nodes;
          if (ratio < transfer.lowest)
            {
              transfer.lowest    = ratio;
              transfer.lowest_at = where.at(node);
            }
          if (ratio > transfer.highest)
            {
              transfer.highest    = ratio;
              transfer.highest_at = where.at(node);
            }
        }
      return transfer;
    }

    // The slave segments that face the master: their midpoint projects
    // orthogonally onto it, the two normals opposed, and the gap there
    // within two of the segment's lengths of the smallest such gap (the
    // segments that touch first; bodies may start apart, an indenter far
    // above its block, a gap that closes). The ratio is of the segments'
    // lengths, not of their nodes' spacings: a linear slave against a
    // quadratic master of the same segments (modelisations E and F) is
    // sampled at the master's mid-side nodes by the nodal scheme.
    double
    facing_length_ratio(ContactInterface<dim> &contact,
                        const Vector<double>  &solution)
    {
      contact.update(solution);
      const ContactSurface &slave  = contact.slave_surface(),
                           &master = contact.master_surface();
      const auto length            = [](const ContactSurface &surface,
                             const unsigned int    s) {
        return surface.reference_point(s, 0).x.distance(
          surface.reference_point(s, 1).x);
      };
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
            const Tensor<1, dim> n = slave.scaled_normal(s, 0.5);
            if (!(n * master.normal(p) < -0.5 * n.norm()))
              continue;
            facing.push_back({p.gap, h, h / length(master, p.segment)});
          }
      if (facing.empty())
        return 0;
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
      std::sort(ratios.begin(), ratios.end());
      return ratios[ratios.size() / 2];
    }

    // Whether every vertex of each surface that faces the other (normals
    // opposed, an orthogonal projection) lands on a vertex of the other:
    // the meshes conform there, whatever the degrees (a linear slave against
    // a quadratic master of the same segments passes the flat patch test to
    // 1e-12 under the nodal scheme). On such surfaces a point-wise transfer
    // departs from the mortar one only by the error of its rule on curved
    // segments, which refinement removes (modelisations E to H:
    // doc/validation.md, "Right by default on surfaces that do not match"); on
    // surfaces that do not conform the departure stays.
    bool
    vertices_conform(ContactInterface<dim> &contact,
                     const Vector<double>  &solution)
    {
      contact.update(solution);
      const auto lands_on_vertices = [](const ContactSurface &from,
                                        const ContactSurface &onto) {
        for (unsigned int s = 0; s < from.segments().size(); ++s)
          for (const double end : {0., 1.})
            {
              const CurvePoint x = from.current_point(s, end);
              const Projection p = onto.project(x.x);
              if (p.segment == numbers::invalid_unsigned_int || p.clamped ||
                  p.at_vertex)
                continue;
              const Tensor<1, dim> n = from.scaled_normal(s, end);
              if (!(n * onto.normal(p) < -0.5 * n.norm()))
                continue;
              const double h =
                onto.reference_point(p.segment, 0)
                  .x.distance(onto.reference_point(p.segment, 1).x);
              if (std::min(p.t, 1 - p.t) * h > 1e-6 * x.dx.norm())
                return false;
            }
        return true;
      };
      return lands_on_vertices(contact.slave_surface(),
                               contact.master_surface()) &&
             lands_on_vertices(contact.master_surface(),
                               contact.slave_surface());
    }

    // Said before the first step, once per pair, with the figures of this
    // mesh: the run is the user's choice, and the original's schemes stay
    // available, but not without a word. A slave coarser than its master is
    // the worst case (a swing several times larger than the right way
    // round), so it is named apart. The swings quoted are those measured by
    // bench/mesh-ratios and bench/non-matching (doc/validation.md).
    bool
    report_non_matching(const LoadTransfer      &transfer,
                        const double             length_ratio,
                        const bool               conforming,
                        const IntegrationScheme &scheme,
                        const types::boundary_id slave_id,
                        const types::boundary_id master_id,
                        std::ostream            &log)
    {
      const double defect = std::max(1 - transfer.lowest, transfer.highest - 1);
      if (conforming || transfer.n_nodes == 0 || !(defect > 1e-3))
        return false;
      const auto at = [](const Point<dim> &x) {
        std::ostringstream text;
        text << "(" << x[0] << ", " << x[1] << ")";
        return text.str();
      };
      log << std::setprecision(3) << "Warning: the " << scheme.name()
          << " scheme does not pass the contact patch test on the pair slave "
          << slave_id << " / master " << master_id
          << ": their nodes do not face each other, and a uniform pressure "
             "on the slave gives the master's nodes from "
          << transfer.lowest << " to " << transfer.highest
          << " times their share (at " << at(transfer.lowest_at) << " and "
          << at(transfer.highest_at)
          << "). The pressure will swing from node to node by an amount "
             "that refining both surfaces does not reduce: on the problems "
             "measured in doc/validation.md, by up to 18 % with the finer "
             "surface the slave (nodal under a rigid punch; Gauss 3 up to "
             "8 %) and 32 % with the coarser.";
      if (length_ratio > 1.1)
        log << " The slave is the coarser surface here (its segments "
            << length_ratio
            << " times as long as the master's where they face each other): "
               "make the finer surface the slave.";
      log << " Segment-based integration passes the test on any meshes: "
             "name no scheme (the default), or set Contact/Integration "
             "schemes = segment-based.\n"
          << std::setprecision(6);
      return true;
    }

  } // namespace Diagnostics
} // namespace RingContact
