// @sect3{The pairing: slave points and their partners}
//
// Before every assembly the contact interface moves its surfaces to the
// current iterate and asks for the pairing (contact_interface.cc): every
// slave quadrature point is paired with a point of the master surface, with
// its gap and its length element. The fixed rules project each point; the
// segment-based scheme first cuts the slave segments where the master's
// shape functions have kinks. Which partner a point gets is a discrete
// choice that Newton's method cannot see, so the Newton solver may hold it
// (Pairing).
#include <deal.II/base/bounding_box.h>

#include <ring_contact/base/dimension.h>
#include <ring_contact/contact/contact_pairing.h>

#include <algorithm>
#include <cmath>

namespace RingContact
{
  ContactPairing::ContactPairing(const ContactSurface &slave,
                                 const ContactSurface &master,
                                 const Quadrature<1>  &quadrature,
                                 const bool            segment_based)
      : slave(slave)
      , master(master)
      , quadrature(quadrature)
      , segment_based(segment_based)
  {}

  // The pairing held by the Newton solver concerns the fixed rules only:
  // pair_pieces() cuts the slave segments afresh at every update, the cuts
  // moving with both surfaces.
  void
  ContactPairing::pair(const Vector<double> &solution,
                       const Pairing         pairing,
                       const bool            linear_gaps)
  {
    if (segment_based)
      pair_pieces(solution, linear_gaps);
    else
      pair_points(solution, pairing, linear_gaps);
  }

  // @sect4{A contact point: its partner, gap and length element}
  //
  // Shared by both pairings: the point's place on its piece, its partner from
  // the projector it is given (a search, a held partner, or the partner of a
  // piece), its gap and its length element.
  template <typename Projector>
  void
  ContactPairing::complete_point(ContactPoint         &point,
                                 const unsigned int    slave_segment,
                                 const Vector<double> &solution,
                                 const bool            linear_gaps,
                                 const Projector      &project) const
  {
    // The point on its piece [eta_a, eta_b] ([0, 1] for fixed rules), its
    // partner, its gap and its length element.
    point.slave_segment  = slave_segment;
    const double length  = point.piece[1] - point.piece[0];
    point.eta            = point.piece[0] + length * point.xi;
    point.weight         = length * point.w;
    const CurvePoint x   = slave.current_point(slave_segment, point.eta);
    point.projection     = project(x.x);
    point.current_length = x.dx.norm() * point.weight;
    // The projection's own gap, from positions X + u, is replaced by the
    // reference part plus the normal jump of the displacement (gap_of()): the
    // gap the weighted gaps and the active set see is the one the contact
    // element computes.
    point.projection.gap = gap_of(slave_segment, point.eta, point.projection);
    point.reference_gap =
      reference_gap_of(slave_segment, point.eta, point.projection);
    // Small strain: the surfaces hold the reference configuration, so gap_of()
    // gave the reference gap alone, and the displacement enters linearly along
    // the reference normal, g = g0 + (u_s - u_m) . n0.
    if (linear_gaps)
      point.projection.gap += linear_gap_increment(solution,
                                                   slave_segment,
                                                   point.eta,
                                                   point.projection);
  }

  // The normal distance of the reference points of a slave point and its
  // partner, zero where it is within the round-off of the positions (64 eps
  // |X|: a slave Gauss point and its projection on a facing segment of a
  // node-matching mesh are some 1e-17 m apart by round-off alone). Left as it
  // is, that round-off would be a gap of its own: negligible against
  // displacements of 1e-3 m, but nearly two hundred orders of magnitude above
  // the displacements of a load of 1e-200 Pa (1e-209 m on the rings), which the
  // test tiny_scales solves as it solves a load of 1e6.
  double
  ContactPairing::reference_gap_of(const unsigned int slave_segment,
                                   const double       eta,
                                   const Projection  &projection) const
  {
    const Point<dim> Xs = slave.reference_point(slave_segment, eta).x;
    const Point<dim> Xm =
      master.reference_point(projection.segment, projection.t).x;
    const double gap = (Xs - Xm) * master.normal(projection);
    return std::abs(gap) <= SurfaceKernel::position_round_off(Xm) ? 0.0 : gap;
  }

  // The gap at the surfaces' current state (small strain: the reference
  // state): the reference part plus the normal jump of the displacement,
  // computed apart so that a displacement below the round-off of the
  // positions is not lost in X + u (see the contact element).
  double
  ContactPairing::gap_of(const unsigned int slave_segment,
                         const double       eta,
                         const Projection  &projection) const
  {
    const Tensor<1, dim> jump =
      slave.displacement_at(slave_segment, eta) -
      master.displacement_at(projection.segment, projection.t);
    return reference_gap_of(slave_segment, eta, projection) +
           jump * master.normal(projection);
  }

  // @sect4{Pairing the points of a fixed rule}
  //
  // Every slave quadrature point is projected onto the current master surface.
  // Which partner a point gets is a discrete choice that Newton's method cannot
  // see: a point that changes partners between two iterations changes its
  // residual by a jump. So a point keeps its partner while its projection stays
  // on it (project()'s preferred segment), and after four iterations of a step,
  // or when the line search fails, the Newton solver holds the pairing
  // altogether (Pairing; newton_solver.cc): on a faceted master that turns, the
  // slave points sit in the grooves, where with one normal per point no root
  // exists, and the pairing flipped between two segments at every iteration.
  void
  ContactPairing::pair_points(const Vector<double> &solution,
                              const Pairing         pairing,
                              const bool            linear_gaps)
  {
    // Every slave quadrature point with its closest master point; a point
    // keeps its previous partner while its projection stays on it.
    std::vector<ContactPoint> new_points;
    new_points.reserve(slave.segments().size() * quadrature.size());
    for (unsigned int s = 0; s < slave.segments().size(); ++s)
      for (unsigned int q = 0; q < quadrature.size(); ++q)
        {
          // Fixed rules put the same points on every segment in the same order:
          // the point at `index` is the one at that index in the last pairing,
          // and its partner there is the preferred one.
          const unsigned int index = new_points.size();
          const unsigned int preferred =
            index < contact_points.size() ?
              contact_points[index].projection.segment :
              numbers::invalid_unsigned_int;
          ContactPoint point;
          point.xi = quadrature.point(q)[0];
          point.w  = quadrature.weight(q);
          complete_point(
            point, s, solution, linear_gaps, [&](const Point<dim> &x) {
              if (pairing == Pairing::search ||
                  preferred == numbers::invalid_unsigned_int)
                return master.project(x, preferred);
              Projection kept = contact_points[index].projection;
              if (!kept.at_vertex)
                {
                  // At an accepted iterate a held partner is followed along its
                  // segment, but not past its end onto the extension: with
                  // facet normals, past a vertex seen from a groove (a concave
                  // corner) the extension runs inside the neighbouring
                  // segment's body, and a point pushed along it by the
                  // segment's tilted normal converges to a state that
                  // penetrates the neighbour (measured: the nodal scheme turned
                  // one element per step ended below the same turn in smaller
                  // steps). It is held at the vertex instead, with the vertex
                  // normal, as project() pairs it. Not within the line search:
                  // the switch is a jump of the residual, which would stop the
                  // search (measured: nodal, 80 around, failed early in C's
                  // rotation). Both: doc/validation.md, "The rotation at
                  // p = 1e7 Pa".
                  const Projection p = master.project_onto(x, preferred);
                  if (pairing == Pairing::hold || master.smooths_normals() ||
                      (p.t >= 0 && p.t <= 1))
                    return p;
                  return master.project_onto_vertex(x,
                                                    preferred,
                                                    p.t < 0 ? 0 : 1);
                }
              kept.gap = (x - master.current_point(kept.segment, kept.t).x) *
                         master.normal(kept);
              return kept;
            });
          new_points.push_back(point);
        }
    contact_points = std::move(new_points);
  }

  // @sect4{Segment-based integration: the pieces}
  //
  // When the meshes have slid, the master's shape functions have kinks inside a
  // slave segment, where its partner changes, and no fixed rule integrates
  // across them exactly: the pressure of the fixed rules fluctuates as the
  // rings turn. Cut at the kinks, each piece is smooth, and n Gauss points
  // integrate it to the rule's order. The cuts are where the slave crosses the
  // line through a master vertex along its vertex normal, which is where a
  // slave point's partner passes from one master segment to the next.
  void
  ContactPairing::pair_pieces(const Vector<double> &solution,
                              const bool            linear_gaps)
  {
    // Segment-based (mortar) integration: cut each slave segment where the
    // line through a master vertex along the vertex normal crosses it. On
    // each piece the partner is one master segment, the integrand is
    // smooth, and Gauss points integrate it to the accuracy of the rule.
    std::vector<ContactPoint> new_points;
    for (unsigned int s = 0; s < slave.segments().size(); ++s)
      {
        const std::vector<std::pair<double, unsigned int>> cuts = piece_cuts(s);

        // The pieces, the partner of each (from its midpoint), and the
        // Gauss points on it.
        // The pieces between consecutive cuts; a piece of no length (two cuts
        // at one place) carries no point.
        std::vector<std::pair<double, unsigned int>> ends = {
          {0.0, numbers::invalid_unsigned_int}};
        ends.insert(ends.end(), cuts.begin(), cuts.end());
        ends.emplace_back(1.0, numbers::invalid_unsigned_int);
        for (unsigned int i = 0; i + 1 < ends.size(); ++i)
          {
            const double eta_a = ends[i].first, eta_b = ends[i + 1].first;
            if (eta_b - eta_a < 1e-12)
              continue;
            const unsigned int index = new_points.size();
            const unsigned int preferred =
              index < contact_points.size() ?
                contact_points[index].projection.segment :
                numbers::invalid_unsigned_int;
            // The partner from the piece's midpoint: no vertex-normal line
            // crosses the inside of a piece, so the whole piece faces one
            // master segment, and the midpoint is away from the ends, where two
            // segments compete.
            const Projection middle =
              master.project(slave.current_point(s, 0.5 * (eta_a + eta_b)).x,
                             preferred);
            const unsigned int partner = middle.segment;
            const auto        &m_seg   = master.segments()[partner];
            // Which end of the partner made each cut: that end moves with the
            // partner's vertex normal in the contact element (piece_ends()); a
            // slave vertex stays fixed (-1).
            std::array<int, 2> piece_end;
            for (unsigned int side = 0; side < 2; ++side)
              {
                const unsigned int v = ends[i + side].second;
                piece_end[side]      = v == m_seg.vertices[0] ? 0 :
                                       v == m_seg.vertices[1] ? 1 :
                                                                -1;
              }
            for (unsigned int q = 0; q < quadrature.size(); ++q)
              {
                ContactPoint point;
                point.piece     = {{eta_a, eta_b}};
                point.piece_end = piece_end;
                point.xi        = quadrature.point(q)[0];
                point.w         = quadrature.weight(q);
                // Every point of the piece is projected onto that partner, not
                // searched: at the ends of the piece the projection falls on
                // the partner's end to round-off, where a search could pick the
                // neighbour.
                complete_point(
                  point, s, solution, linear_gaps, [&](const Point<dim> &x) {
                    return master.project_onto(x, partner);
                  });
                new_points.push_back(point);
              }
          }
      }
    contact_points = std::move(new_points);
  }


  // The cuts of slave segment s, sorted: the parameters eta where the line
  // through a nearby master vertex along its vertex normal crosses the
  // segment, each with that vertex.
  std::vector<std::pair<double, unsigned int>>
  ContactPairing::piece_cuts(const unsigned int s) const
  {
    // Master vertices near the segment: within half its length, and
    // the distance between the surfaces there (the bodies may be apart
    // or overlap by more than a segment: small strain pairs them in
    // the reference configuration, where they need not touch).
    // Half a segment alone missed the cuts of blocks meshed 0.2 apart (uncut
    // pieces, and a pressure off, silently: doc/validation.md, "Figures that
    // were in the code's comments").
    std::vector<Point<dim>> corners;
    double                  apart = 0;
    for (const double t : {0.0, 0.5, 1.0})
      {
        corners.push_back(slave.current_point(s, t).x);
        apart = std::max(apart, std::abs(master.project(corners.back()).gap));
      }
    BoundingBox<dim> box(corners);
    const double     length = corners.front().distance(corners.back());
    box.extend(0.5 * length + apart);

    // Crossings eta of h(eta) = (x_s(eta) - x_v) x n_v = 0.
    std::vector<std::pair<double, unsigned int>> cuts; // eta, vertex
    std::set<unsigned int>                       seen;
    for (const unsigned int m : master.segments_near(box))
      for (unsigned int end = 0; end < 2; ++end)
        {
          const unsigned int v = master.segments()[m].vertices[end];
          if (!seen.insert(v).second)
            continue;
          const Point<dim>     xv = master.current_point(m, end).x;
          const Tensor<1, dim> nv = master.vertex_normal(m, end);
          // Newton's method from the middle of the segment: h is linear in
          // eta on a straight slave segment (one step), and a polynomial of
          // the segment's degree on a curved one. A zero slope (the segment
          // along the normal line) has no crossing.
          double eta = 0.5;
          for (unsigned int it = 0; it < 20; ++it)
            {
              const CurvePoint p = slave.current_point(s, eta);
              const auto [h, slope] =
                SurfaceKernel::piece_end_residual(p.x - xv, p.dx, nv);
              if (slope == 0)
                break;
              const double d = -h / slope;
              eta += d;
              if (std::abs(d) < 1e-15)
                break;
            }
          // A cut counts inside the segment only (a crossing at a slave
          // vertex cuts nothing), and within reach of the vertex that made
          // it: the normal line is infinite, and only near its vertex does
          // it mark a kink of the master that faces this segment.
          if (std::isfinite(eta) && eta > 1e-10 && eta < 1 - 1e-10 &&
              slave.current_point(s, eta).x.distance(xv) < length + 2 * apart)
            cuts.emplace_back(eta, v);
        }
    std::sort(cuts.begin(), cuts.end());
    return cuts;
  }

  // @sect4{Small strain: the linear gap}
  //
  // (u_s - u_m) . n0 at a slave point and its partner, the displacement read
  // from the solution: the surfaces hold the reference configuration (update()
  // gave them zero displacement). A rotated copy's displacement is R u of its
  // original's unknowns.
  double
  ContactPairing::linear_gap_increment(const Vector<double> &solution,
                                       const unsigned int    slave_segment,
                                       const double          t,
                                       const Projection     &projection) const
  {
    const auto displacement_at = [&](const ContactSurface &surface,
                                     const unsigned int    segment,
                                     const double          t) {
      std::vector<double> N;
      surface.displacement_basis().evaluate(t, N);
      const auto &seg = surface.segments()[segment];
      CurvePoint  u; // the displacement alone
      SurfaceKernel::add_interpolation(u,
                                       N.size(),
                                       N.data(),
                                       (double *)nullptr,
                                       (double *)nullptr,
                                       [&](const unsigned int i) {
                                         return Tensor<1, dim>(
                                           {solution(seg.dofs_x[i]),
                                            solution(seg.dofs_y[i])});
                                       });
      return Tensor<1, dim>(seg.rotation * Tensor<1, dim>(u.x));
    };
    const Tensor<1, dim> jump =
      displacement_at(slave, slave_segment, t) -
      displacement_at(master, projection.segment, projection.t);
    // The surfaces hold the reference configuration here.
    return jump * master.normal(projection);
  }

  // @sect4{Friction: the old partners}
  //
  // The slip of a slave point in a step is its motion relative to the
  // master point it was paired with at the last converged state: its old
  // position projected onto the old master (the contact interface keeps both
  // surfaces in that state, ContactInterface::accept_state()). The current
  // partner segment is the preferred candidate: where the old position has
  // two valid projections (on a vertex, in a concave corner) it keeps the
  // current one. Small strain: both in the reference configuration, the
  // current pairing itself.
  void
  ContactPairing::find_old_partners(const ContactSurface &converged_slave,
                                    const ContactSurface &converged_master,
                                    const bool            linear_gaps)
  {
    for (auto &point : contact_points)
      point.old_projection =
        linear_gaps ?
          point.projection :
          converged_master.project(
            converged_slave.current_point(point.slave_segment, point.eta).x,
            point.projection.segment);
  }

  // @sect4{What the interface asks of the pairs}
  //
  // The nodal gap of the VTU files: the node's slave point projected afresh,
  // with the gap computed as in the pairing.
  double
  ContactPairing::gap_at(const unsigned int    s,
                         const double          t,
                         const Vector<double> &solution,
                         const bool            linear_gaps) const
  {
    Projection p = master.project(slave.current_point(s, t).x);
    p.gap        = gap_of(s, t, p);
    if (linear_gaps)
      p.gap += linear_gap_increment(solution, s, t, p);
    return p.gap;
  }

  // The pairs of segments that face each other, for adaptive refinement.
  std::vector<std::pair<unsigned int, unsigned int>>
  ContactPairing::paired_segments() const
  {
    std::vector<std::pair<unsigned int, unsigned int>> pairs;
    for (const ContactPoint &point : contact_points)
      if (point.projection.segment != numbers::invalid_unsigned_int)
        pairs.emplace_back(point.slave_segment, point.projection.segment);
    return pairs;
  }
} // namespace RingContact
