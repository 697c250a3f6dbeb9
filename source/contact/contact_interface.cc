// @sect3{The contact interface: pairing, weighted gaps, active set}
//
// One contact pair: a slave surface that carries the multipliers and a master
// surface that gives the normal (contact_surface.cc), with the quadrature rule
// of the chosen scheme on the slave (contact_quadrature.cc). Before every
// assembly the Newton loop calls update(): the surfaces move to the current
// iterate, every slave quadrature point is paired with a point of the master,
// the weighted gaps g~_k are summed and each multiplier node is declared closed
// or open (and, with friction, sticking or sliding). The contact element of
// contact_assembly.cc then turns each pair into rows of the Newton system; this
// file also gives what the postprocessing asks of a pair: the node nearest to a
// point, the stretch, the nodal gap and the L2 error of the pressure.
#include <deal.II/base/quadrature_lib.h>

#include <ring_contact/contact/contact_interface.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace RingContact
{
  // @sect4{Construction: the surfaces, the rule and the multiplier nodes}
  //
  // The quadrature rule is chosen for the higher displacement degree of the two
  // surfaces: the same rule integrates the slave's and the master's rows, and a
  // rule that saw only a linear slave's vertices would give a quadratic
  // master's mid-side nodes no contact force (doc/theory.md).
  ContactInterface::ContactInterface(const DoFHandler<2>     &dof_handler,
                                     const ContactParameters &parameters,
                                     const IntegrationScheme &scheme,
                                     const unsigned int slave_mapping_degree,
                                     const unsigned int master_mapping_degree,
                                     const double       largest_youngs_modulus,
                                     const bool         geometrically_linear,
                                     const CyclicSymmetry::Sector &sector)
      : slave(dof_handler, parameters.slave_boundary_id, slave_mapping_degree)
      , master(dof_handler,
               parameters.master_boundary_id,
               master_mapping_degree,
               parameters.smooth_master_normals,
               sector.angle,
               sector.copies,
               sector.window_before,
               sector.window_after)
      , quadrature(
          contact_quadrature(scheme,
                             std::max(slave.displacement_basis().size(),
                                      master.displacement_basis().size()) -
                               1,
                             slave.multiplier_basis().size() - 1))
      // Automatic complementarity constant: E / h of the slave surface, the
      // stiffness of a layer one element thick (closing a gap g against it
      // takes a pressure E g / h). c only chooses the active set (at the
      // solution c g~_k = 0 on the closed nodes and lambda_k = 0 on the open
      // ones, whatever c), but it weighs a gap against a pressure in w lambda -
      // c g~, and with E / h the two terms are of one size.
      , complementarity_constant(parameters.complementarity_constant > 0 ?
                                   parameters.complementarity_constant :
                                   largest_youngs_modulus /
                                     slave.min_segment_length())
      , friction_coefficient(parameters.friction_coefficient)
      , small_strain_model(geometrically_linear)
      , geometrically_linear(geometrically_linear)
      , segment_based(scheme.type == ContactIntegration::segment_based)
  {
    // The multiplier nodes, and w_k = int Phi_k dS with a Gauss rule of
    // n_geometry + n_multiplier points: exact on straight segments, where |X'|
    // is constant; on curved ones |X'| is the square root of a polynomial,
    // integrated to the rule's accuracy. A twin (cyclic symmetry) is the node
    // of its image on the start side.
    // w_k is the reference weight, a constant: the open rows w_k lambda_k = 0
    // and the trial tractions stay linear in the unknowns, and the rows keep
    // their scale however the surface stretches.
    const QGauss<1> exact(slave.geometry_basis().size() +
                          slave.multiplier_basis().size());
    const auto      node_of = [&](const types::global_dof_index dof) {
      const auto twin = sector.multiplier_twins.find(dof);
      return twin == sector.multiplier_twins.end() ? dof : twin->second;
    };
    for (unsigned int s = 0; s < slave.segments().size(); ++s)
      {
        const auto &segment = slave.segments()[s];
        for (unsigned int k = 0; k < segment.multiplier_dofs.size(); ++k)
          {
            const auto dof  = segment.multiplier_dofs[k];
            const auto node = node_of(dof);
            // A node met for the first time gets the next index k; a vertex
            // shared by two segments, or a twin, finds its index there, and its
            // weight is summed over its segments below.
            if (multiplier_index.count(node) == 0)
              {
                multiplier_index[node] = multiplier_dof_list.size();
                multiplier_dof_list.push_back(node);
                reference_weight.push_back(0.0);
                // The tangential dof of the same node at the same index: the
                // friction arrays are indexed by k like the normal ones.
                if (friction_coefficient > 0)
                  {
                    AssertThrow(segment.tangential_dofs.size() ==
                                  segment.multiplier_dofs.size(),
                                ExcInternalError());
                    tangential_dof_list.push_back(segment.tangential_dofs[k]);
                  }
              }
            multiplier_index[dof] = multiplier_index[node];
            // Where each node sits (segment, t), for the postprocessing: the
            // nearest node, the stretch and the nodal gap look it up instead of
            // searching.
            node_sites[node].emplace_back(s, slave.multiplier_nodes()[k]);
          }
        for (unsigned int q = 0; q < exact.size(); ++q)
          {
            std::vector<double> Phi;
            slave.multiplier_basis().evaluate(exact.point(q)[0], Phi);
            const double dS =
              slave.reference_point(s, exact.point(q)[0]).dx.norm() *
              exact.weight(q);
            for (unsigned int k = 0; k < Phi.size(); ++k)
              reference_weight[multiplier_index[segment.multiplier_dofs[k]]] +=
                Phi[k] * dS;
          }
      }
    // The tangential traction's basis (contact_element.h): the dual one,
    // unless the scheme's points are the multiplier nodes themselves (the
    // nodal scheme, whose weights are diagonal: there Psi = Phi).
    if (friction_coefficient > 0)
      {
        const auto &nodes = slave.multiplier_nodes();
        bool at_nodes     = !segment_based && quadrature.size() == nodes.size();
        for (unsigned int q = 0; at_nodes && q < quadrature.size(); ++q)
          at_nodes = std::any_of(nodes.begin(), nodes.end(), [&](double t) {
            return std::abs(t - quadrature.point(q)[0]) < 1e-12;
          });
        dual_basis = !at_nodes;
      }
    // update() decides every node before the first assembly: the initial values
    // only set what the first update() counts as a change.
    weighted_gap.assign(multiplier_dof_list.size(), 0.0);
    segment_length = slave.min_segment_length();
    active.assign(multiplier_dof_list.size(), true);
    weighted_slip.assign(multiplier_dof_list.size(), 0.0);
    slip_sign.assign(multiplier_dof_list.size(), 0);

    // The nodes in their order along the surface: on each segment by their
    // parameter, consecutive ones are neighbours (a vertex links the
    // segments that share it, a twin the sector's two ends).
    node_neighbours.assign(multiplier_dof_list.size(), {});
    std::vector<std::vector<std::pair<double, unsigned int>>> on_segment(
      slave.segments().size());
    for (const auto &[dof, sites] : node_sites)
      for (const auto &[s, t] : sites)
        on_segment[s].emplace_back(t, multiplier_index.at(dof));
    for (unsigned int s = 0; s < on_segment.size(); ++s)
      {
        auto &nodes = on_segment[s];
        std::sort(nodes.begin(), nodes.end());
        for (unsigned int i = 1; i < nodes.size(); ++i)
          {
            const unsigned int a = nodes[i - 1].second, b = nodes[i].second;
            const double       length =
              slave.reference_point(s, nodes[i].first)
                .x.distance(slave.reference_point(s, nodes[i - 1].first).x);
            for (const auto &[from, to] :
                 {std::make_pair(a, b), std::make_pair(b, a)})
              if (from != to && std::none_of(node_neighbours[from].begin(),
                                             node_neighbours[from].end(),
                                             [to = to](const auto &n) {
                                               return n.first == to;
                                             }))
                node_neighbours[from].emplace_back(to, length);
          }
      }
  }

  // @sect4{The update of an iteration}
  //
  // The surfaces to the state of `solution`, the pairing, the weighted gaps and
  // the active set from the current multipliers and gaps (the primal-dual
  // active-set strategy: the max in C_k is decided at the iterate). The number
  // of changes is what the Newton loop needs: an iterate is converged only if
  // no node changed its state.
  unsigned int
  ContactInterface::update(const Vector<double> &solution,
                           const Pairing         pairing)
  {
    // Finite strain: pair and measure in the current configuration. Small
    // strain: pair in the reference configuration, and the gap is the
    // reference gap plus the normal jump of the displacement.
    // The surfaces then keep zero displacement, so that every position, normal
    // and length the contact sees is the reference one.
    if (geometrically_linear)
      {
        const Vector<double> zero(solution.size());
        slave.update(zero);
        master.update(zero);
      }
    else
      {
        slave.update(solution);
        master.update(solution);
      }

    // The pairing held by the Newton loop concerns the fixed rules only:
    // pair_pieces() cuts the slave segments afresh at every update, the cuts
    // moving with both surfaces.
    if (segment_based)
      pair_pieces(solution);
    else
      pair_points(solution, pairing);

    // Weighted gaps and the active set from the current multipliers.
    // In double, the sum that the contact element's multiplier rows evaluate
    // again in AD numbers, c sum Phi_k g ds: here it only chooses the active
    // set.
    std::fill(weighted_gap.begin(), weighted_gap.end(), 0.0);
    for (const auto &point : points)
      {
        const auto         &segment = slave.segments()[point.slave_segment];
        std::vector<double> Phi;
        slave.multiplier_basis().evaluate(point.eta, Phi);
        for (unsigned int k = 0; k < Phi.size(); ++k)
          weighted_gap[multiplier_index[segment.multiplier_dofs[k]]] +=
            Phi[k] * point.projection.gap * point.current_length;
      }
    std::vector<bool>   closed(multiplier_dof_list.size());
    std::vector<double> indicator(multiplier_dof_list.size());
    for (unsigned int k = 0; k < multiplier_dof_list.size(); ++k)
      {
        const double lambda = solution(multiplier_dof_list[k]);
        indicator[k]        = reference_weight[k] * lambda -
                       complementarity_constant * weighted_gap[k];
        // Closed when w lambda - c g~ >= 0; a gap of round-off size (at
        // the start the surfaces touch exactly) counts as closed.
        // The tolerance is a gap of 1e-12 of the shortest slave segment h: on
        // the scale of c g~_k, c w_k 1e-12 h.
        const double round_off = 1e-12 * complementarity_constant *
                                 reference_weight[k] * segment_length;
        closed[k] = reference_weight[k] * lambda -
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
    // load on that node alone inverted the elements around it (Hertz, d0 =
    // 0, h = 0.005: a cut, 10 iterations instead of 3 to 5); a step that
    // starts from a one-node zone (an unloading) may so close a node or two
    // for one iteration. Not when a zone is closed already: a contact zone that
    // grows from step to step is then held, and the band would only close nodes
    // that the load may not reach (with the load's extrapolation, Hertz in 8
    // steps took 20 iterations instead of 17).
    if (first_update_of_step &&
        std::count(closed.begin(), closed.end(), true) <= 1)
      for (unsigned int k = 0; k < multiplier_dof_list.size(); ++k)
        if (solution(multiplier_dof_list[k]) >= 0 &&
            weighted_gap[k] <= 1e-2 * segment_length * reference_weight[k])
          closed[k] = true;
    if (edge_extrapolation && piecewise_linear() && !first_update_of_step)
      extrapolate_zone_edges(active,
                             std::vector<bool>(active.size(), true),
                             indicator,
                             closed);
    unsigned int n_changed = 0;
    for (unsigned int k = 0; k < multiplier_dof_list.size(); ++k)
      {
        if (closed[k] != active[k])
          ++n_changed;
        active[k] = closed[k];
      }
    first_update_of_step = false;
    // A changed friction state counts as a change: Newton stops only when
    // neither the active set nor a state changed.
    return n_changed + update_friction(solution);
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
  // tension halves the excess, and a Hertz cylinder pressed from touching
  // on h = 0.005 took 12 iterations, one or two nodes at a time. Where a
  // zone is too narrow, the gap beyond its edge is negative up to 3/2 of
  // the shortfall (g ~ -sqrt(s) (3 (a - b) / 2 - s), s = x - b), and
  // closing every such node overshoots by half of it.
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
  // zones within them (update_friction(): sticking nodes, indicator B - |T|,
  // walks over the closed nodes only). "Closed" and "open" below read
  // "inside" and "outside".
  void
  ContactInterface::extrapolate_zone_edges(const std::vector<bool>   &inside,
                                           const std::vector<bool>   &linked,
                                           const std::vector<double> &indicator,
                                           std::vector<bool> &closed) const
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
          const auto &links = node_neighbours[current];
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
        if (!inside[e] || node_neighbours[e].size() != 2)
          continue;
        const auto &[a, a_length] = node_neighbours[e][0];
        const auto &[b, b_length] = node_neighbours[e][1];
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
  std::pair<double, Point<2>>
  ContactInterface::deepest_interpenetration() const
  {
    double   depth = 0;
    Point<2> where;
    for (unsigned int k = 0; k < multiplier_dof_list.size(); ++k)
      if (reference_weight[k] > 0 &&
          -weighted_gap[k] / reference_weight[k] > depth)
        {
          depth            = -weighted_gap[k] / reference_weight[k];
          const auto &site = node_sites.at(multiplier_dof_list[k]).front();
          where            = slave.reference_point(site.first, site.second).x;
        }
    return {depth, where};
  }

  // @sect4{Friction: the converged state, the old partners and the states}
  //
  // The slip of a slave point in a step is its motion relative to the master
  // point it was paired with at the last converged state. accept_state() keeps
  // copies of both surfaces in that state, and every update() projects the
  // points' old positions onto the old master. Measured so, rather than by
  // integrating a tangential velocity, the slip is objective (a rigid motion of
  // the pair slips nothing) and the same with every integration scheme.
  void
  ContactInterface::accept_state(const Vector<double> &solution)
  {
    if (friction_coefficient == 0)
      return;
    converged_solution = solution;
    converged_slave    = std::make_unique<ContactSurface>(slave);
    converged_master   = std::make_unique<ContactSurface>(master);
    // Small strain: both at the reference configuration, where the pairing is
    // made.
    const Vector<double> zero(solution.size());
    converged_slave->update(geometrically_linear ? zero : solution);
    converged_master->update(geometrically_linear ? zero : solution);
  }

  unsigned int
  ContactInterface::update_friction(const Vector<double> &solution)
  {
    if (friction_coefficient == 0)
      return 0;
    // Before the first converged state: the reference configuration.
    if (!converged_master)
      accept_state(Vector<double>(solution.size()));
    // Each point's partner at the last converged state: its old position
    // projected onto the old master (small strain: both in the reference
    // configuration, the current pairing itself).
    // The current partner segment is the preferred candidate: where the old
    // position has two valid projections (on a vertex, in a concave corner) it
    // keeps the current one.
    for (auto &point : points)
      point.old_projection =
        geometrically_linear ?
          point.projection :
          converged_master->project(
            converged_slave->current_point(point.slave_segment, point.eta).x,
            point.projection.segment);
    // From the contact element, values only (contact_assembly.cc): the slips
    // need the current tangent, the moving pieces and the old partners exactly
    // as the residual does.
    compute_weighted_slips(solution);

    // The states of the closed nodes from the trial tractions.
    const double        c = complementarity_constant;
    const unsigned int  n = multiplier_dof_list.size();
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
            const double w = reference_weight[k];
            trial[k] =
              w * solution(tangential_dof_list[k]) + c * weighted_slip[k];
            const double bound = friction_coefficient *
                                 std::max(0.0,
                                          w * solution(multiplier_dof_list[k]) -
                                            c * weighted_gap[k]);
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
    // not extrapolated (but in a step from rest, newton.cc; the rule comes
    // after the extrapolation, which reads the plain rule's states), and the
    // nodes a stick zone grows over flipped from one sense to the other at
    // each iteration (a slip of 1e-7 against the sense slid gives a trial of
    // ten times the bound) under a damped line search. Steel on aluminium
    // from touching, Saint Venant-Kirchhoff, mu = 0.2, four steps, nodal /
    // Gauss 2 / segment-based 2: without the rule 33 / 58 / 37 iterations in
    // all at h = 0.01, with it 28 / 28 / 31; 38 / 87 / 66 at h = 0.005, with
    // it 31 / 36 / 48 (the first steps within an iteration of each other).
    // Not at small strain, where the edges are extrapolated: there it made
    // h = 0.0025 in one step take 30 iterations and a cut (Gauss 2,
    // segment-based 2) instead of 10. (The rule reads the states of the last
    // update, so that a second update at the same iterate may change a
    // state again.)
    if (!geometrically_linear && !stick_held)
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

  unsigned int
  ContactInterface::n_changed_since(const NodeStates &before) const
  {
    unsigned int n = 0;
    for (unsigned int k = 0; k < active.size(); ++k)
      n += (k >= before.active.size() || before.active[k] != active[k] ||
            before.slip_sign[k] != slip_sign[k]);
    return n;
  }

  std::vector<double>
  ContactInterface::mean_gaps() const
  {
    std::vector<double> gaps(weighted_gap.size(), 0.0);
    for (unsigned int k = 0; k < gaps.size(); ++k)
      if (reference_weight[k] > 0)
        gaps[k] = weighted_gap[k] / reference_weight[k];
    return gaps;
  }

  unsigned int
  ContactInterface::n_slipping() const
  {
    unsigned int n = 0;
    for (unsigned int k = 0; k < active.size(); ++k)
      n += active[k] && slip_sign[k] != 0;
    return n;
  }

  types::global_dof_index
  ContactInterface::tangential_dof(
    const types::global_dof_index multiplier_dof) const
  {
    if (friction_coefficient == 0)
      return numbers::invalid_dof_index;
    return tangential_dof_list[multiplier_index.at(multiplier_dof)];
  }

  // @sect4{A contact point: its partner, gap and length element}
  //
  // Shared by both pairings: the point's place on its piece, its partner from
  // the projector it is given (a search, a held partner, or the partner of a
  // piece), its gap and its length element.
  template <typename Projector>
  void
  ContactInterface::complete_point(ContactPoint         &point,
                                   const unsigned int    slave_segment,
                                   const Vector<double> &solution,
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
    if (geometrically_linear)
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
  ContactInterface::reference_gap_of(const unsigned int slave_segment,
                                     const double       eta,
                                     const Projection  &projection) const
  {
    const Point<2> Xs = slave.reference_point(slave_segment, eta).x;
    const Point<2> Xm =
      master.reference_point(projection.segment, projection.t).x;
    const double gap = (Xs - Xm) * master.normal(projection);
    return std::abs(gap) <= SurfaceKernel::position_round_off(Xm) ? 0.0 : gap;
  }

  // The gap at the surfaces' current state (small strain: the reference
  // state): the reference part plus the normal jump of the displacement,
  // computed apart so that a displacement below the round-off of the
  // positions is not lost in X + u (see the contact element).
  double
  ContactInterface::gap_of(const unsigned int slave_segment,
                           const double       eta,
                           const Projection  &projection) const
  {
    const Tensor<1, 2> jump =
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
  // or when the line search fails, the Newton loop holds the pairing altogether
  // (Pairing; newton.cc): on a faceted master that turns, the slave points sit
  // in the grooves, where with one normal per point no root exists, and the
  // pairing flipped between two segments at every iteration.
  void
  ContactInterface::pair_points(const Vector<double> &solution,
                                const Pairing         pairing)
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
          const unsigned int index     = new_points.size();
          const unsigned int preferred = index < points.size() ?
                                           points[index].projection.segment :
                                           numbers::invalid_unsigned_int;
          ContactPoint       point;
          point.xi = quadrature.point(q)[0];
          point.w  = quadrature.weight(q);
          complete_point(point, s, solution, [&](const Point<2> &x) {
            if (pairing == Pairing::search ||
                preferred == numbers::invalid_unsigned_int)
              return master.project(x, preferred);
            Projection kept = points[index].projection;
            if (!kept.at_vertex)
              {
                // At an accepted iterate a held partner is followed along its
                // segment, but not past its end onto the extension: with
                // facet normals, past a vertex seen from a groove (a concave
                // corner) the extension runs inside the neighbouring
                // segment's body, and a point pushed along it by the
                // segment's tilted normal converges to a state that
                // penetrates the neighbour (measured: the nodal scheme
                // turned one element per step ended 6.8 % below the same
                // turn in smaller steps). It is held at the vertex instead,
                // with the vertex normal, as project() pairs it. Not within
                // the line search: the switch is a jump of the residual,
                // which would stop the search (measured: nodal, 80 around,
                // failed at step 5 of C's rotation).
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
    points = std::move(new_points);
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
  ContactInterface::pair_pieces(const Vector<double> &solution)
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
            const unsigned int index     = new_points.size();
            const unsigned int preferred = index < points.size() ?
                                             points[index].projection.segment :
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
                complete_point(point, s, solution, [&](const Point<2> &x) {
                  return master.project_onto(x, partner);
                });
                new_points.push_back(point);
              }
          }
      }
    points = std::move(new_points);
  }


  // The cuts of slave segment s, sorted: the parameters eta where the line
  // through a nearby master vertex along its vertex normal crosses the
  // segment, each with that vertex.
  std::vector<std::pair<double, unsigned int>>
  ContactInterface::piece_cuts(const unsigned int s) const
  {
    // Master vertices near the segment: within half its length, and
    // the distance between the surfaces there (the bodies may be apart
    // or overlap by more than a segment: small strain pairs them in
    // the reference configuration, where they need not touch).
    // Half a segment alone missed the cuts of blocks meshed 0.2 apart
    // (uncut pieces, and a pressure 3 % off, silently).
    std::vector<Point<2>> corners;
    double                apart = 0;
    for (const double t : {0.0, 0.5, 1.0})
      {
        corners.push_back(slave.current_point(s, t).x);
        apart = std::max(apart, std::abs(master.project(corners.back()).gap));
      }
    BoundingBox<2> box(corners);
    const double   length = corners.front().distance(corners.back());
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
          const Point<2>     xv = master.current_point(m, end).x;
          const Tensor<1, 2> nv = master.vertex_normal(m, end);
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

  // @sect4{The sparsity pattern of the contact couplings}
  //
  // The tangent's pattern holds, per slave segment, the master segments its
  // points are paired with and their neighbours. A new pattern costs a new
  // symbolic analysis of the factorization, which the direct solvers keep while
  // the pattern does not change; with the neighbours in it, a point that slips
  // to the next segment needs none. After each update() the Newton loop asks
  // whether the pattern still covers the pairs (assembly.cc).
  bool
  ContactInterface::sparsity_covers_pairing() const
  {
    for (const auto &point : points)
      {
        if (pattern_pairs.count(
              {point.slave_segment, point.projection.segment}) == 0)
          return false;
        // Friction: the old partner enters through the slip.
        if (friction_coefficient > 0 &&
            pattern_pairs.count(
              {point.slave_segment, point.old_projection.segment}) == 0)
          return false;
        // The neighbours enter through vertex and smoothed normals.
        for (const unsigned int b :
             master.segments()[point.projection.segment].neighbours)
          if (b != numbers::invalid_unsigned_int &&
              pattern_pairs.count({point.slave_segment, b}) == 0)
            return false;
      }
    return true;
  }

  std::vector<std::vector<types::global_dof_index>>
  ContactInterface::coupling_blocks()
  {
    // Per slave segment, the master segments its points are paired with and
    // their neighbours (which enter through vertex and smoothed normals, and
    // which a slip may reach next): one block couples all their unknowns.
    pattern_pairs.clear();
    for (const auto &point : points)
      {
        pattern_pairs.insert({point.slave_segment, point.projection.segment});
        if (friction_coefficient > 0)
          pattern_pairs.insert(
            {point.slave_segment, point.old_projection.segment});
        for (const unsigned int m :
             master.segments()[point.projection.segment].neighbours)
          if (m != numbers::invalid_unsigned_int)
            pattern_pairs.insert({point.slave_segment, m});
      }
    // One block per slave segment couples its displacements, multipliers and
    // tangential tractions with the displacements of all those master segments.
    std::map<unsigned int, std::vector<types::global_dof_index>> block;
    for (const auto &[s, m] : pattern_pairs)
      {
        auto &dofs = block[s];
        if (dofs.empty())
          for (const auto *list : {&slave.segments()[s].dofs_x,
                                   &slave.segments()[s].dofs_y,
                                   &slave.segments()[s].multiplier_dofs,
                                   &slave.segments()[s].tangential_dofs})
            dofs.insert(dofs.end(), list->begin(), list->end());
        for (const auto *list :
             {&master.segments()[m].dofs_x, &master.segments()[m].dofs_y})
          dofs.insert(dofs.end(), list->begin(), list->end());
      }
    std::vector<std::vector<types::global_dof_index>> blocks;
    for (auto &[s, dofs] : block)
      {
        std::sort(dofs.begin(), dofs.end());
        dofs.erase(std::unique(dofs.begin(), dofs.end()), dofs.end());
        blocks.push_back(std::move(dofs));
      }
    return blocks;
  }

  // @sect4{Small strain: the linear gap}
  //
  // (u_s - u_m) . n0 at a slave point and its partner, the displacement read
  // from the solution: the surfaces hold the reference configuration (update()
  // gave them zero displacement). A rotated copy's displacement is R u of its
  // original's unknowns.
  double
  ContactInterface::linear_gap_increment(const Vector<double> &solution,
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
                                         return Tensor<1, 2>(
                                           {solution(seg.dofs_x[i]),
                                            solution(seg.dofs_y[i])});
                                       });
      return Tensor<1, 2>(seg.rotation * Tensor<1, 2>(u.x));
    };
    const Tensor<1, 2> jump =
      displacement_at(slave, slave_segment, t) -
      displacement_at(master, projection.segment, projection.t);
    // The surfaces hold the reference configuration here.
    return jump * master.normal(projection);
  }

  unsigned int
  ContactInterface::n_active() const
  {
    return std::count(active.begin(), active.end(), true);
  }

  bool
  ContactInterface::is_active(const types::global_dof_index dof) const
  {
    const auto k = multiplier_index.find(dof);
    return k != multiplier_index.end() && active[k->second];
  }

  // @sect4{What the postprocessing asks of a pair}
  //
  // The node nearest to a reference point: the rings' node A is named by its
  // initial position (0.6, 0), a general problem's checks by theirs.
  types::global_dof_index
  ContactInterface::multiplier_dof_nearest_to(const Point<2> &point,
                                              double         *distance) const
  {
    double                  best = std::numeric_limits<double>::max();
    types::global_dof_index dof  = numbers::invalid_dof_index;
    for (unsigned int s = 0; s < slave.segments().size(); ++s)
      for (unsigned int k = 0; k < slave.multiplier_nodes().size(); ++k)
        {
          const double d = point.distance(
            slave.reference_point(s, slave.multiplier_nodes()[k]).x);
          if (d < best)
            {
              best = d;
              dof  = slave.segments()[s].multiplier_dofs[k];
            }
        }
    if (distance)
      *distance = best;
    // The node's own dof (not a cyclic twin).
    return multiplier_dof_list[multiplier_index.at(dof)];
  }

  std::vector<types::global_dof_index>
  ContactInterface::all_multiplier_dofs() const
  {
    std::vector<types::global_dof_index> dofs;
    for (const auto &[dof, k] : multiplier_index)
      dofs.push_back(dof);
    return dofs;
  }

  // The points as paired by the last update(): the master's shape functions
  // at each partner, weighted by the point's length element. A rotated copy
  // of a sector's segment carries the original's unknowns, so its weights
  // land on them.
  std::map<types::global_dof_index, double>
  ContactInterface::master_load_weights() const
  {
    std::map<types::global_dof_index, double> weights;
    std::vector<double> psi(master.displacement_basis().size());
    for (const auto &point : points)
      {
        if (point.projection.segment == numbers::invalid_unsigned_int)
          continue;
        const SurfaceSegment &segment =
          master.segments()[point.projection.segment];
        master.displacement_basis().evaluate(point.projection.t, psi);
        for (unsigned int j = 0; j < psi.size(); ++j)
          weights[segment.dofs_x[j]] += psi[j] * point.current_length;
      }
    return weights;
  }

  // Cauchy to nominal: lambda is a force per current length, the nominal
  // pressure one per reference length, lambda ds / dS. At a vertex the
  // stretches of the two segments differ: the node gets their mean.
  double
  ContactInterface::stretch_at(const types::global_dof_index dof) const
  {
    double      sum   = 0;
    const auto &sites = node_sites.at(dof);
    for (const auto &[s, t] : sites)
      sum += slave.current_point(s, t).dx.norm() /
             slave.reference_point(s, t).dx.norm();
    return sum / sites.size();
  }

  // The nodal gap of the VTU files: the node's slave point projected afresh,
  // with the gap computed as in the pairing.
  double
  ContactInterface::gap_at(const types::global_dof_index dof,
                           const Vector<double>         &solution) const
  {
    const auto [s, t] = node_sites.at(dof).front();
    Projection p      = master.project(slave.current_point(s, t).x);
    p.gap             = gap_of(s, t, p);
    if (geometrically_linear)
      p.gap += linear_gap_increment(solution, s, t, p);
    return p.gap;
  }

  // The relative L2 error of the pressure against a uniform reference
  // (the rings' Lame pressure is the same all round), with a rule of its own
  // (the displacement degree + 3 Gauss points per slave segment) rather than
  // the contact scheme's, so that every scheme is measured alike.
  double
  ContactInterface::l2_relative_error(const Vector<double> &solution,
                                      const double          reference,
                                      const PressureMeasure measure) const
  {
    const QGauss<1>     rule(slave.displacement_basis().size() + 2);
    double              error = 0, norm = 0;
    std::vector<double> Phi;
    for (unsigned int s = 0; s < slave.segments().size(); ++s)
      {
        const auto &segment = slave.segments()[s];
        for (unsigned int q = 0; q < rule.size(); ++q)
          {
            const double t = rule.point(q)[0];
            slave.multiplier_basis().evaluate(t, Phi);
            double lambda = 0;
            for (unsigned int k = 0; k < Phi.size(); ++k)
              lambda += Phi[k] * solution(segment.multiplier_dofs[k]);
            const double ds = slave.current_point(s, t).dx.norm();
            const double dS = slave.reference_point(s, t).dx.norm();
            // Cauchy: lambda over ds; nominal: lambda ds/dS over dS.
            const double pressure =
              measure == PressureMeasure::cauchy ? lambda : lambda * ds / dS;
            const double length =
              (measure == PressureMeasure::cauchy ? ds : dS) * rule.weight(q);
            // Relative to the reference before squaring: pressures of
            // 1e-200 would underflow.
            const double relative = (pressure - reference) / reference;
            error += relative * relative * length;
            norm += length;
          }
      }
    return std::sqrt(error / norm);
  }
  std::vector<std::pair<unsigned int, unsigned int>>
  ContactInterface::paired_segments() const
  {
    std::vector<std::pair<unsigned int, unsigned int>> pairs;
    for (const ContactPoint &point : points)
      if (point.projection.segment != numbers::invalid_unsigned_int)
        pairs.emplace_back(point.slave_segment, point.projection.segment);
    return pairs;
  }
} // namespace RingContact
