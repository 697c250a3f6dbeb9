// @sect3{The active set: closed nodes, stick and slip}
//
// The semi-smooth Newton method decides the max of the complementarity
// function and the Coulomb projection at each iterate: per node, closed or
// open, and with friction sticking or sliding. That choice is made here,
// from the weighted gaps of the pairing's points and the multipliers of the
// iterate. The number of nodes whose state changed goes back to the Newton
// solver, which accepts an iterate only when no state changes. Beyond the
// plain primal-dual choice, this file holds what makes it fast where a
// contact zone grows from a point: the touching nodes closed at a step's
// start, and the zones' edges extrapolated from the square-root profile of
// the indicator near an edge, in the first iterations of a step.
#include <ring_contact/contact/active_set.h>

#include <algorithm>
#include <cmath>

namespace RingContact
{
  unsigned int
  NodeStates::n_changed_since(const NodeStates &before) const
  {
    unsigned int n = 0;
    for (unsigned int k = 0; k < active.size(); ++k)
      n += (k >= before.active.size() || before.active[k] != active[k] ||
            before.slip_sign[k] != slip_sign[k]);
    return n;
  }

  unsigned int
  NodeStates::n_closed_changed_since(const NodeStates &before) const
  {
    unsigned int n = 0;
    for (unsigned int k = 0; k < active.size(); ++k)
      n += k >= before.active.size() || active[k] != before.active[k];
    return n;
  }

  // The contact interface's update() decides every node before the first
  // assembly: the initial values only set what the first choice counts as a
  // change.
  ActiveSet::ActiveSet(const MultiplierNodes &nodes,
                       const double           complementarity_constant,
                       const double           friction_coefficient,
                       const double           segment_length)
      : nodes(nodes)
      , complementarity_constant(complementarity_constant)
      , friction_coefficient(friction_coefficient)
      , segment_length(segment_length)
      , weighted_gap(nodes.size(), 0.0)
      , active(nodes.size(), true)
      , slip_sign(nodes.size(), 0)
  {}

  // @sect4{The closed nodes}
  //
  // The weighted gaps, in double: the sum that the contact element's
  // multiplier rows evaluate again in AD numbers, c sum Phi_k g ds; here it
  // only chooses the active set.
  void
  ActiveSet::sum_weighted_gaps(const ContactSurface            &slave,
                               const std::vector<ContactPoint> &points)
  {
    std::fill(weighted_gap.begin(), weighted_gap.end(), 0.0);
    for (const auto &point : points)
      {
        const auto         &segment = slave.segments()[point.slave_segment];
        std::vector<double> Phi;
        slave.multiplier_basis().evaluate(point.eta, Phi);
        for (unsigned int k = 0; k < Phi.size(); ++k)
          weighted_gap[nodes.index.at(segment.multiplier_dofs[k])] +=
            Phi[k] * point.projection.gap * point.current_length;
      }
  }

  // The active set from the current multipliers and gaps (the primal-dual
  // active-set strategy: the max in C_k is decided at the iterate).
  unsigned int
  ActiveSet::choose_closed_nodes(const Vector<double>            &solution,
                                 const ContactSurface            &slave,
                                 const std::vector<ContactPoint> &points,
                                 const bool piecewise_linear)
  {
    sum_weighted_gaps(slave, points);
    return choose_from_weighted_gaps(solution, nullptr, piecewise_linear);
  }

  unsigned int
  ActiveSet::choose_closed_nodes(const Vector<double>      &solution,
                                 const std::vector<double> &weighted_gaps,
                                 const std::vector<bool>   &covered,
                                 const bool                 piecewise_linear)
  {
    AssertDimension(weighted_gaps.size(), nodes.size());
    AssertDimension(covered.size(), nodes.size());
    weighted_gap = weighted_gaps;
    return choose_from_weighted_gaps(solution, &covered, piecewise_linear);
  }

  unsigned int
  ActiveSet::choose_from_weighted_gaps(const Vector<double>    &solution,
                                       const std::vector<bool> *covered,
                                       const bool piecewise_linear)
  {
    std::vector<bool>   closed(nodes.dofs.size());
    std::vector<double> indicator(nodes.dofs.size());
    for (unsigned int k = 0; k < nodes.dofs.size(); ++k)
      {
        const double lambda = solution(nodes.dofs[k]);
        indicator[k]        = nodes.reference_weight[k] * lambda -
                       complementarity_constant * weighted_gap[k];
        // Closed when w lambda - c g~ >= 0; a gap of round-off size (at
        // the start the surfaces touch exactly) counts as closed.
        // The tolerance is a gap of 1e-12 of the shortest slave segment h: on
        // the scale of c g~_k, c w_k 1e-12 h.
        const double round_off = 1e-12 * complementarity_constant *
                                 nodes.reference_weight[k] * segment_length;
        closed[k] = nodes.reference_weight[k] * lambda -
                      complementarity_constant * weighted_gap[k] >=
                    -round_off;
      }
    // Bodies that touch at the start (a cylinder on a block, no overlap):
    // the node at the touching point has a mean gap of h^2 / 12 R, not zero,
    // on both sides of it the gap grows, and with every node open a body
    // held only by the contact has a singular tangent (measured: Hertz with
    // d0 = 0, Gauss 2 and segment-based 2 failed after five cuts). When a
    // step would start with at most one node of the pair closed, its first
    // active set closes the nodes whose mean gap g~_k / w_k is within 1 % of
    // the shortest slave segment and that carry no tension. Once only: the
    // next update opens those that the solve puts in tension. One node: the
    // nodal scheme's gap at the touching point is zero itself, and the whole
    // load on that node alone inverted the elements around it (Hertz, d0 = 0: a
    // cut, and more iterations); a step that starts from a one-node zone (an
    // unloading) may so close a node or two for one iteration. Not when a zone
    // is closed already: a contact zone that grows from step to step is then
    // held, and the band would only close nodes that the load may not reach
    // (with the load's extrapolation, Hertz in 8 steps took more iterations).
    // The figures: doc/validation.md, "Curved geometry, ties and touching
    // bodies".
    if (first_update_of_step &&
        std::count(closed.begin(), closed.end(), true) <= 1)
      for (unsigned int k = 0; k < nodes.dofs.size(); ++k)
        if (solution(nodes.dofs[k]) >= 0 &&
            weighted_gap[k] <=
              1e-2 * segment_length * nodes.reference_weight[k])
          closed[k] = true;
    if (covered != nullptr)
      for (unsigned int k = 0; k < nodes.dofs.size(); ++k)
        closed[k] = closed[k] && (*covered)[k];
    // On a curve the walks along chains of nodes; on a surface of faces
    // (3D) the same rule in distances (surface_zone_edges.cc).
    if (edge_extrapolation && piecewise_linear && !first_update_of_step)
      {
        if (nodes.surface_position.empty())
          extrapolate_zone_edges(active,
                                 std::vector<bool>(active.size(), true),
                                 indicator,
                                 closed);
        else
          extrapolate_surface_zone_edges(active, indicator, closed);
      }
    unsigned int n_changed = 0;
    for (unsigned int k = 0; k < nodes.dofs.size(); ++k)
      {
        if (closed[k] != active[k])
          ++n_changed;
        active[k] = closed[k];
      }
    first_update_of_step = false;
    return n_changed;
  }

  // @sect4{Friction: stick and slip}
  //
  // The states of the closed nodes from the trial tractions, with the
  // weighted slips s~_k of the contact element (the contact interface
  // measures them, from the old partners of the pairing).
  unsigned int
  ActiveSet::choose_friction_states(const Vector<double>      &solution,
                                    const std::vector<double> &weighted_slip,
                                    const bool                 linear_gaps)
  {
    // The states of the closed nodes from the trial tractions.
    const double        c = complementarity_constant;
    const unsigned int  n = nodes.dofs.size();
    std::vector<int>    state(n, 0);
    std::vector<double> trial(n, 0.0), room(n, 0.0);
    for (unsigned int k = 0; k < n; ++k)
      {
        // T_k is the tangential traction the node would carry if it stuck (the
        // trial state of a return map), B_k the Coulomb bound, mu times the
        // normal part of C_k and zero on an opening node. Stick where |T_k| <=
        // B_k, else slide in the direction of T_k: the active-set choice of
        // Alart and Curnier's projection, proj_[-B, B](T), evaluated at the
        // iterate.
        if (active[k] && !stick_held)
          {
            const double w = nodes.reference_weight[k];
            trial[k] =
              w * solution(nodes.tangential_dofs[k]) + c * weighted_slip[k];
            const double bound =
              friction_coefficient *
              std::max(0.0, w * solution(nodes.dofs[k]) - c * weighted_gap[k]);
            room[k] = bound - std::abs(trial[k]);
            // A sliding node at the bound stays sliding: at the start of
            // a step (s~ = 0) a node that slid has |T| = B to round-off,
            // and round-off must not decide its state (under MPI it took
            // another Newton iteration than one process).
            const double margin = 1e-9 * bound;
            if (slip_sign[k] != 0 && slip_sign[k] * trial[k] >= bound - margin)
              state[k] = slip_sign[k];
            else if (std::abs(trial[k]) > bound + margin)
              state[k] = trial[k] > 0 ? 1 : -1;
          }
      }
    // The edges of the stick zones move as the contact zones' do: within a
    // stick zone the room B - |T| to the bound has the square-root profile
    // of a pressure near its edge, and beyond it, in the slip zone, -c |s~|
    // the profile of a gap (Cattaneo and Mindlin's traction is the
    // difference of two Hertz profiles, mu (p(a) - p(c))). A stick zone
    // that grows or shrinks by one or two nodes per iteration is moved to
    // its extrapolated edge (extrapolate_zone_edges(), over the closed
    // nodes), in the same first iterations of a step.
    if (edge_extrapolation && !stick_held)
      {
        std::vector<bool> sticking(n), stick(n);
        for (unsigned int k = 0; k < n; ++k)
          {
            sticking[k] = active[k] && slip_sign[k] == 0;
            stick[k]    = active[k] && state[k] == 0;
          }
        const std::vector<bool> plain = stick;
        extrapolate_zone_edges(sticking, active, room, stick);
        for (unsigned int k = 0; k < n; ++k)
          if (stick[k] != plain[k])
            // Left sliding, a node keeps its sense; a stick node beyond
            // the extrapolated edge slides in the sense of its trial.
            state[k] = stick[k]          ? 0 :
                       slip_sign[k] != 0 ? slip_sign[k] :
                       trial[k] >= 0     ? 1 :
                                           -1;
      }
    // At finite strain a sliding node whose new state is sliding the other
    // way sticks first: it slides the other way only if its trial is still
    // beyond the bound at the next update. There the stick zones' edges are
    // not extrapolated (but in a step from rest, problem/first_step.cc; the
    // rule comes after the extrapolation, which reads the plain rule's states),
    // and the nodes a stick zone grows over flipped from one sense to the other
    // at each iteration (a slip of 1e-7 against the sense slid gives a trial of
    // ten times the bound) under a damped line search. Steel on aluminium from
    // touching, Saint Venant-Kirchhoff, mu = 0.2, four steps: fewer iterations
    // in all with the rule, for nodal, Gauss 2 and segment-based 2 alike, the
    // first steps within an iteration of each other (doc/validation.md, "Curved
    // geometry, ties and touching bodies"). Not at small strain, where the
    // edges are extrapolated: there it made a step on a fine mesh take many
    // more iterations and a cut (Gauss 2, segment-based 2). (The rule reads the
    // states of the last update, so that a second update at the same iterate
    // may change a state again.)
    if (!linear_gaps && !stick_held)
      for (unsigned int k = 0; k < n; ++k)
        if (active[k] && slip_sign[k] != 0 && state[k] == -slip_sign[k])
          state[k] = 0;
    unsigned int n_changed = 0;
    for (unsigned int k = 0; k < n; ++k)
      {
        if (state[k] != slip_sign[k])
          ++n_changed;
        slip_sign[k] = state[k];
      }
    return n_changed;
  }

  // @sect4{The edges of the contact zones}
  //
  // The primal-dual active-set method moves the edge of a contact zone
  // slowly on fine meshes. Where a zone is too wide, the closed nodes beyond
  // the true edge are pulled rather than pressed, but only over the outer
  // half of the excess: near an edge the pressure of a zone of half-width b
  // around a true edge at a behaves as (b - x - (b - a) / 2) / sqrt(b - x)
  // (the first-order change of the square-root profile with b, e.g. Hertz's
  // p ~ (a^2 + b^2 - 2 x^2) / sqrt(b^2 - x^2)), so releasing the nodes in
  // tension halves the excess, and a Hertz cylinder pressed from touching took
  // many iterations, one or two nodes at a time (doc/validation.md, "Curved
  // geometry, ties and touching bodies"). Where a zone is too narrow, the gap
  // beyond its edge is negative up to 3/2 of the shortfall
  // (g ~ -sqrt(s) (3 (a - b) / 2 - s), s = x - b), and closing every such node
  // overshoots by half of it.
  //
  // Both are the first-order profile near an edge, whatever the bodies'
  // shapes: the edge moves to twice the extent of the tension inside it, or
  // to 2/3 of the extent of the penetration outside it, each extent the
  // zero of w lambda - c g~ interpolated between the nodes. Only where the
  // change spans several nodes (tension past the end node, three or more
  // nodes penetrating; a smaller change is left to the plain rule, whose
  // step is then as good), and only in the first iterations of a step
  // (allow_edge_extrapolation()). The choice changes a node wherever the
  // plain rule would: an iterate passes as converged only if the plain
  // rule, too, moves no node.
  //
  // Written for any zone of nodes `inside` a set: the contact zones (closed
  // nodes, indicator w lambda - c g~, walks over all nodes), and the stick
  // zones within them (choose_friction_states(): sticking nodes, indicator B -
  // |T|, walks over the closed nodes only). "Closed" and "open" below read
  // "inside" and "outside".
  void
  ActiveSet::extrapolate_zone_edges(const std::vector<bool>   &inside,
                                    const std::vector<bool>   &linked,
                                    const std::vector<double> &indicator,
                                    std::vector<bool>         &closed) const
  {
    const unsigned int n      = inside.size();
    std::vector<bool>  result = closed;
    // The walk from node `from` through its neighbour `first` and on, while
    // `keep` holds: the nodes and their distances along the surface from
    // `from`. It stops where the surface ends or branches.
    const auto walk = [&](const unsigned int from,
                          const unsigned int first,
                          const double       first_length,
                          const auto        &keep) {
      std::vector<std::pair<unsigned int, double>> path;
      unsigned int previous = from, current = first;
      double       distance = first_length;
      while (path.size() < n && linked[current] && keep(current))
        {
          path.emplace_back(current, distance);
          const auto &links = nodes.neighbours[current];
          if (links.size() != 2)
            break;
          const auto &next = links[0].first == previous ? links[1] : links[0];
          previous         = current;
          current          = next.first;
          distance += next.second;
        }
      return path;
    };
    // Where the indicator crosses zero between two nodes of a path, as a
    // distance.
    const auto zero_between = [&](const std::pair<unsigned int, double> &a,
                                  const std::pair<unsigned int, double> &b) {
      const double va = indicator[a.first], vb = indicator[b.first];
      return a.second + (b.second - a.second) * va / (va - vb);
    };
    for (unsigned int e = 0; e < n; ++e)
      {
        // An end of a zone: closed, one closed neighbour and one open one (a
        // zone that reaches the end of the surface has no edge there).
        if (!inside[e] || nodes.neighbours[e].size() != 2)
          continue;
        const auto &[a, a_length] = nodes.neighbours[e][0];
        const auto &[b, b_length] = nodes.neighbours[e][1];
        if (inside[a] == inside[b])
          continue;
        const auto inner =
          inside[a] ? std::make_pair(a, a_length) : std::make_pair(b, b_length);
        const auto outer =
          inside[a] ? std::make_pair(b, b_length) : std::make_pair(a, a_length);

        // Too wide: the innermost node in tension within the zone's outer
        // half, past the end node, and the zero between it and the next
        // node inwards, which must be pressed (else the zero is not
        // bracketed, and the end is left to the plain rule). The plain rule
        // opens the nodes in tension; this opens more, never fewer.
        auto zone =
          walk(e, inner.first, inner.second, [&](const unsigned int j) {
            return inside[j];
          });
        zone.insert(zone.begin(), {e, 0.0});
        int tension = -1;
        for (unsigned int i = 0; 2 * i + 1 < zone.size(); ++i)
          if (!closed[zone[i].first])
            tension = i;
        if (tension >= 1 && indicator[zone[tension + 1].first] > 0)
          {
            const double edge =
              2 * zero_between(zone[tension], zone[tension + 1]);
            for (unsigned int i = 0; 2 * i + 1 < zone.size(); ++i)
              if (zone[i].second < edge)
                result[zone[i].first] = false;
          }

        // Too narrow: the open nodes beyond the edge that penetrate, up to
        // the first that does not (a walk that meets another zone first is
        // left alone). The first of them closes whatever the extent: an
        // iterate whose plain choice closes a node must not come out
        // unchanged, or it could pass as converged with a node inside the
        // master (its row w lambda = 0 does not see the gap).
        const auto beyond =
          walk(e, outer.first, outer.second, [&](const unsigned int j) {
            return !inside[j];
          });
        unsigned int penetrating = 0;
        while (penetrating < beyond.size() && closed[beyond[penetrating].first])
          ++penetrating;
        if (penetrating >= 3 && penetrating < beyond.size())
          {
            const double extent =
              zero_between(beyond[penetrating - 1], beyond[penetrating]);
            for (unsigned int i = 1; i < penetrating; ++i)
              if (beyond[i].second > 2. / 3. * extent)
                result[beyond[i].first] = false;
          }
      }
    closed = result;
  }

  // The deepest mean gap g~_k / w_k below zero, for the warning before any load
  // (diagnostics/surfaces_at_rest.cc): a curved slave facing a faceted
  // master overlaps it by 2/3 of the sagitta in g~_k / w_k, and modelisation H
  // so set up once gave 0 of 63 checks with no word of why. The test w_k > 0
  // guards the division.

  // @sect4{What the states say}
  unsigned int
  ActiveSet::n_active() const
  {
    return std::count(active.begin(), active.end(), true);
  }

  bool
  ActiveSet::is_active(const types::global_dof_index dof) const
  {
    const auto k = nodes.index.find(dof);
    return k != nodes.index.end() && active[k->second];
  }

  unsigned int
  ActiveSet::n_slipping() const
  {
    unsigned int n = 0;
    for (unsigned int k = 0; k < active.size(); ++k)
      n += active[k] && slip_sign[k] != 0;
    return n;
  }

  std::vector<double>
  ActiveSet::mean_gaps() const
  {
    std::vector<double> gaps(weighted_gap.size(), 0.0);
    for (unsigned int k = 0; k < gaps.size(); ++k)
      if (nodes.reference_weight[k] > 0)
        gaps[k] = weighted_gap[k] / nodes.reference_weight[k];
    return gaps;
  }
} // namespace RingContact
