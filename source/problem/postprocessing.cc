// @sect3{Postprocessing: what a converged step reports}
//
// After each converged step: the history row (the solver's columns, the
// scenario's quantities, the invariants of equilibrium.h), the step's line
// in the log, and every so many steps the VTU files. Also the diagnostics
// before the first step, and what the scenarios read of the state
// (SolutionState): the contact nodes, the reported pressure, the nodal
// forces.
#include <deal.II/numerics/rtree.h>

#include <ring_contact/base/dimension.h>
#include <ring_contact/base/utilities.h>
#include <ring_contact/contact/surface_arc_length.h>
#include <ring_contact/diagnostics/rigid_body_modes.h>
#include <ring_contact/diagnostics/stiffness_spread.h>
#include <ring_contact/diagnostics/surfaces_at_rest.h>
#include <ring_contact/problem/contact_problem.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <map>
#include <set>
#include <sstream>

namespace RingContact
{
  // @sect4{Before the first step}
  //
  // The boundary data against the mesh, the rigid motions only the contact
  // holds, what the problem is in one line, surfaces that interpenetrate
  // before any load, and every quantity the scenario reports evaluated once
  // at rest. Each check answers a wrong result once given without a word:
  // a load along a direction its own boundary holds (the support took it
  // silently), a body free to slide (the solver returned an arbitrary
  // position and the run ended with exit code 0), surfaces that overlap at
  // rest (H with a Q1 outer ring and Mapping degree = 0, a curved slave
  // against a faceted master, passed 0 of its 63 checks with no word of
  // why), a checked point far from every contact node (the nearest node's
  // value was reported as the pressure there). Now each is an error or a
  // warning before the first step, not after it; and bodies whose
  // stiffnesses are too far apart for double precision (a body 1e-9 thick,
  // Young's moduli 1e9 apart), which failed as a body "free to move
  // rigidly".
  template <int dim>
  void
  ContactProblem<dim>::diagnose_start()
  {
    // At the pseudo-times of every step, since a general problem's boundary
    // data are expressions of t.
    {
      std::vector<double> times;
      for (unsigned int step = 1; step <= load_program.n_steps(); ++step)
        times.push_back(load_program.time(step));
      scenario->check_boundary_data(dof_handler, mapping_collection, times);
    }
    // Notes the bodies that only the contact holds, and throws if a motion
    // is held by nothing: the tangent would be singular along it (in 3D
    // the six modes of each body). The stiffness spread and the surfaces'
    // interpenetration and coarse geometry below are 2D so far.
    held_by_contact =
      Diagnostics::rigid_body_modes(dof_handler,
                                    mapping_collection,
                                    bodies,
                                    imposed_dofs,
                                    normal_target,
                                    normal_component,
                                    contact_interfaces(),
                                    parameters.contact.frictional(),
                                    log);
    // Coulomb friction's discrete problem is proved to have one solution
    // only for small coefficients; past about 1 a second one can appear, as
    // it does in the frictional patch test (tests/friction_two_solutions:
    // its uniform state and one with an end node open both solve it), and
    // Newton's method converges to either without a sign. Said, not refused:
    // the coefficient is the user's, and the answer is often the sought one.
    if (parameters.contact.friction_coefficient > 1)
      log << "Warning: the friction coefficient "
          << parameters.contact.friction_coefficient
          << " is above 1, where Coulomb friction's discrete problem may have "
             "more than one solution (uniqueness is proved for small "
             "coefficients only; Hassani, Hild, Ionescu and Sakki 2003 "
             "compute where it is lost), and Newton's method finds one of "
             "them, not necessarily the one sought: the frictional patch test "
             "at 2 has its uniform state and a second one with an end node "
             "open (doc/validation.md). Check the answer along another path "
             "(more load steps, another mesh).\n";
    // And throws if the bodies' stiffnesses, or a thin body's cells, are
    // too far apart for a solve in double precision.
    if constexpr (dim == 2)
      stiffness_spread = Diagnostics::stiffness_spread(triangulation, bodies);
    log << "Scheme " << scheme.name() << progress->scheme_label() << ": "
        << triangulation.n_active_cells() << " cells, " << dof_handler.n_dofs()
        << " unknowns, " << n_contact_nodes() << " contact pressure nodes, "
        << load_program.n_steps() << " steps\n";
    const auto pairs = parameters.contact_pairs();
    if constexpr (dim == 3)
      for (unsigned int i = 0; i < contacts.size(); ++i)
        report_non_matching_surfaces(i);
    else
      for (unsigned int i = 0; i < contacts.size(); ++i)
        {
          const auto &[slave, master] = pairs[i];
          report_non_matching_surfaces(i);
          // A body of the pair held by the contact only absorbs an overlap
          // by its motion: a way to start in contact (the Hertz problem's
          // cylinder), not said.
          if (held_by_contact.count(body_of_boundary.at(slave)) ||
              held_by_contact.count(body_of_boundary.at(master)))
            continue;
          Diagnostics::report_initial_interpenetration(*contacts[i],
                                                       solution,
                                                       log);
          Diagnostics::report_coarse_geometry(*contacts[i], solution, log);
        }
    // Every quantity the scenario reports, evaluated once at rest and
    // thrown away: a quantity that cannot be evaluated throws now.
    HistoryRow at_rest;
    scenario->report(*this, at_rest);
  }

  namespace
  {
    // The load transfer of a point-wise scheme on 3D surfaces, against
    // segment-based integration, which passes the contact patch test on
    // any meshes: a unit pressure on every slave node, the force it puts
    // on each master vertex under either scheme (the reference
    // configuration), and the extremes of their ratio over the vertices
    // that carry a share. Both 1 where the point-wise scheme passes.
    std::pair<double, double>
    master_load_ratios(ContactInterface<3> &pointwise,
                       ContactInterface<3> &mortar,
                       const unsigned int   n_dofs)
    {
      Vector<double> unit(n_dofs), by_points(n_dofs), by_clips(n_dofs);
      for (const auto dof : pointwise.nodes().dofs)
        unit(dof) = 1;
      pointwise.update(unit);
      mortar.update(unit);
      pointwise.add_forces(unit, by_points);
      mortar.add_forces(unit, by_clips);
      // Per master vertex, the magnitude of its force under either scheme.
      std::map<types::global_dof_index, std::pair<double, double>> at_vertex;
      for (const auto &face : mortar.faces().master_faces())
        for (const auto &node : face.u_dofs)
          {
            double a = 0, b = 0;
            for (const auto dof : node)
              {
                a += by_points(dof) * by_points(dof);
                b += by_clips(dof) * by_clips(dof);
              }
            at_vertex[node[0]] = {std::sqrt(a), std::sqrt(b)};
          }
      double largest = 0;
      for (const auto &[dof, forces] : at_vertex)
        largest = std::max(largest, forces.second);
      double lowest = 1, highest = 1;
      for (const auto &[dof, forces] : at_vertex)
        if (forces.second > 1e-3 * largest)
          {
            lowest  = std::min(lowest, forces.first / forces.second);
            highest = std::max(highest, forces.first / forces.second);
          }
      return {lowest, highest};
    }
  } // namespace


  namespace
  {
    // Whether the two surfaces of a 3D pair conform: each slave face faces
    // one master face vertex to vertex, along the mean normal of the slave
    // faces at each vertex, across a gap or an overlap (2D:
    // Diagnostics::vertices_conform). The point-wise schemes then hand the
    // load on node to node and pass the patch test; their loads may still
    // differ from the clipped ones by the facets' curvature (about 0.1 %
    // on the closing gap's rings: doc/validation.md, "2D by extrusion"),
    // which is not what the warning is about. A slave vertex's partner is
    // its nearest master vertex (deal.II's R-tree of the master vertices),
    // a different one for each.
    bool
    faces_conform(const FaceContact &faces)
    {
      const auto point = [](const FaceClipping::Vector3<double> &v) {
        return Point<3>(v[0], v[1], v[2]);
      };
      // The slave vertices (by their first unknown) with the sum of their
      // faces' unit normals, and the shortest slave edge.
      double edge = std::numeric_limits<double>::max();
      std::map<types::global_dof_index, std::pair<Point<3>, Tensor<1, 3>>>
        slave;
      for (const auto &face : faces.slave_faces())
        {
          const Tensor<1, 3> n = cross_product_3d(point(face.reference[3]) -
                                                    point(face.reference[0]),
                                                  point(face.reference[2]) -
                                                    point(face.reference[1]));
          for (unsigned int v = 0; v < 4; ++v)
            {
              auto &vertex = slave[face.u_dofs[v][0]];
              vertex.first = point(face.reference[v]);
              vertex.second += n / n.norm();
              edge =
                std::min(edge,
                         vertex.first.distance(point(face.reference[v ^ 1])));
            }
        }
      // The master vertices, once each, and the master faces by their
      // vertices in increasing order.
      std::vector<Point<3>>                            master_points;
      std::vector<types::global_dof_index>             master_dofs;
      std::set<types::global_dof_index>                seen;
      std::set<std::array<types::global_dof_index, 4>> master_faces;
      for (const auto &face : faces.master_faces())
        {
          std::array<types::global_dof_index, 4> key;
          for (unsigned int v = 0; v < 4; ++v)
            {
              key[v] = face.u_dofs[v][0];
              if (seen.insert(key[v]).second)
                {
                  master_points.push_back(point(face.reference[v]));
                  master_dofs.push_back(key[v]);
                }
            }
          std::sort(key.begin(), key.end());
          master_faces.insert(key);
        }
      if (master_points.empty())
        return false;
      const auto tree = pack_rtree_of_indices(master_points);

      std::map<types::global_dof_index, types::global_dof_index> partner;
      std::set<types::global_dof_index>                          matched;
      for (const auto &[dof, vertex] : slave)
        {
          std::vector<std::size_t> nearest;
          tree.query(boost::geometry::index::nearest(vertex.first, 1),
                     std::back_inserter(nearest));
          const Tensor<1, 3> n = vertex.second / vertex.second.norm();
          const Tensor<1, 3> d = master_points[nearest[0]] - vertex.first;
          // Across a gap the partner is along the normal; at a free edge
          // the slave faces' mean normal leans by half a facet's angle,
          // hence a tenth of the distance.
          if ((d - (d * n) * n).norm() > 1e-6 * edge + 0.1 * d.norm() ||
              !matched.insert(master_dofs[nearest[0]]).second)
            return false;
          partner[dof] = master_dofs[nearest[0]];
        }
      for (const auto &face : faces.slave_faces())
        {
          std::array<types::global_dof_index, 4> key;
          for (unsigned int v = 0; v < 4; ++v)
            key[v] = partner[face.u_dofs[v][0]];
          std::sort(key.begin(), key.end());
          if (master_faces.count(key) == 0)
            return false;
        }
      return true;
    }
  } // namespace


  // A point-wise scheme (nodal, Gauss, Simpson, Newton-Cotes) on a pair
  // whose surfaces do not match fails the contact patch test there: its load
  // transfer is measured against the mortar one on fresh interfaces of the
  // same pair (the problem's own are left as they are), and a departure is
  // said with its figures (diagnostics/surfaces_at_rest.h).
  template <int dim>
  void
  ContactProblem<dim>::report_non_matching_surfaces(
    const unsigned int pair) const
  {
    if (scheme.cuts_at_master_kinks())
      return;
    if constexpr (dim == 2)
      {
        const auto [slave, master] = parameters.contact_pairs()[pair];
        const bool linear          = contacts[pair]->small_strain();
        const auto pointwise =
          make_contact_interface(slave, master, scheme, linear);
        const auto mortar = make_contact_interface(
          slave, master, IntegrationScheme::parse("segment-based 6"), linear);
        const Diagnostics::LoadTransfer transfer =
          Diagnostics::measure_load_transfer(*pointwise, *mortar, solution);
        Diagnostics::report_non_matching(
          transfer,
          Diagnostics::facing_length_ratio(*pointwise, solution),
          Diagnostics::vertices_conform(*pointwise, solution),
          scheme,
          slave,
          master,
          log);
      }
    else
      {
        // In 3D the master vertices' loads (master_load_ratios()); the
        // same warning, with the figures measured on the 3D patch test.
        // Within 0.2 % is a match: on a faceted curved surface whose
        // vertices face each other across a gap, the point-wise and the
        // segment-based loads differ by about 0.1 % (the curvature's, not
        // the meshes'; doc/validation.md, "2D by extrusion").
        const auto [slave, master] = parameters.contact_pairs()[pair];
        const auto pointwise =
          make_contact_interface(slave, master, scheme, true);
        if (faces_conform(pointwise->faces()))
          return;
        const auto mortar = make_contact_interface(
          slave, master, IntegrationScheme::parse("segment-based"), true);
        const auto [lowest, highest] =
          master_load_ratios(*pointwise, *mortar, dof_handler.n_dofs());
        if (!(std::max(1 - lowest, highest - 1) > 2e-3))
          return;
        log << std::setprecision(3) << "Warning: the " << scheme.name()
            << " scheme does not pass the contact patch test on the pair "
               "slave "
            << slave << " / master " << master
            << ": their nodes do not face each other, and a uniform "
               "pressure on the slave gives the master's vertices from "
            << lowest << " to " << highest
            << " times their share. The pressure will swing from node to "
               "node by an amount that refining both surfaces does not "
               "reduce (on the 3D patch test of doc/validation.md by up to "
               "4 %). Segment-based integration passes the test on any "
               "meshes: name no scheme (the default), or set "
               "Contact/Integration schemes = segment-based.\n"
            << std::setprecision(6);
      }
  }

  // @sect4{The contact nodes}
  //
  // What the scenarios read of the contact, gathered over the pairs: a
  // contact node is a multiplier unknown on a slave surface, and belongs to
  // one pair. The lists leave out the end side's twins of a cyclic sector
  // (one node, two unknowns tied by a constraint), so that counts and
  // extremes see each node once.
  template <int dim>
  std::vector<const ContactInterface<dim> *>
  ContactProblem<dim>::contact_interfaces() const
  {
    std::vector<const ContactInterface<dim> *> interfaces;
    for (const auto &contact : contacts)
      interfaces.push_back(contact.get());
    return interfaces;
  }

  template <int dim>
  std::vector<types::global_dof_index>
  ContactProblem<dim>::contact_nodes() const
  {
    std::vector<types::global_dof_index> nodes;
    for (const auto &contact : contacts)
      nodes.insert(nodes.end(),
                   contact->nodes().dofs.begin(),
                   contact->nodes().dofs.end());
    return nodes;
  }

  template <int dim>
  unsigned int
  ContactProblem<dim>::n_contact_nodes() const
  {
    unsigned int n = 0;
    for (const auto &contact : contacts)
      n += contact->nodes().size();
    return n;
  }

  template <int dim>
  unsigned int
  ContactProblem<dim>::n_active_nodes() const
  {
    unsigned int n = 0;
    for (const auto &contact : contacts)
      n += contact->active_set().n_active();
    return n;
  }

  // The node nearest to a reference point over every pair: how node A of
  // the rings, (R2, 0) on the slave surface, or a general problem's checked
  // point is found. A point farther from every node than a slave segment
  // is refused by the scenario before the first step.
  template <int dim>
  types::global_dof_index
  ContactProblem<dim>::contact_node_nearest_to(const Point<dim> &point) const
  {
    double                  best = std::numeric_limits<double>::infinity();
    types::global_dof_index node = numbers::invalid_dof_index;
    for (const auto &contact : contacts)
      {
        double     distance = 0;
        const auto nearest =
          contact->multiplier_dof_nearest_to(point, &distance);
        if (distance < best)
          {
            best = distance;
            node = nearest;
          }
      }
    return node;
  }

  // The unknown lambda is the Cauchy pressure, force per current length of
  // the slave surface. The nominal pressure is force per reference length,
  // lambda ds / dS: what Code_Aster reports as LAGS_C. At p = 1e7 the
  // interface circle shrinks by about 1 %, and the two differ by as much,
  // as large as the effects being measured: the file says which one to
  // report (Contact/Reported pressure).
  template <int dim>
  double
  ContactProblem<dim>::reported_pressure(
    const types::global_dof_index dof) const
  {
    const double lambda = solution(dof);
    return parameters.contact.reported_pressure == PressureMeasure::cauchy ?
             lambda :
             lambda * contact_of(dof).stretch_at(dof);
  }


  // @sect4{A converged step}
  //
  // The row of the step: the solver's columns, the scenario's quantities,
  // and the invariants; the step's line in the log; a state that fails an
  // invariant is reported, not recorded; then the VTU files.
  template <int dim>
  void
  ContactProblem<dim>::postprocess_step(const unsigned int step,
                                        const unsigned int iterations,
                                        const unsigned int cuts,
                                        const double       wall_time)
  {
    TimerOutput::Scope t(timer, "postprocessing");
    // The solver's columns; the scenario adds its quantities (pressure at
    // a point, errors against its reference, resultants), then the
    // invariants are measured on the same state.
    HistoryRow row;
    row.scheme            = scheme.name();
    row.step              = step;
    row.time              = current_load.time;
    row.newton_iterations = iterations;
    row.step_cuts         = cuts;
    row.active_nodes      = n_active_nodes();
    row.wall_time         = wall_time;
    row.cells             = triangulation.n_active_cells();
    row.unknowns          = dof_handler.n_dofs();
    scenario->report(*this, row);
    // A state that fails an invariant is not recorded: the history and the
    // verdicts keep converged states that can be trusted only. Its line
    // is still printed below, so that the log shows the state that failed.
    const bool balanced = measure_balance_of_forces(row);
    if (balanced)
      history_rows.push_back(row);

    if (parameters.output.print_steps)
      print_step_line(row);
    // The run stops here with the reason (UntrustedState reaches the
    // driver), before the step observer writes the step as converged.
    if (!balanced)
      throw UntrustedState(unbalanced_forces);
    // The scenario's own warning about the step. The rings warn of a step
    // converged with the contact open at every node: another solution of
    // the discrete problem (F at finite strain once gave p_A = 0 so), which
    // the checks fail without saying why.
    scenario->warn(log, row);

    // Every `interval` steps, and the last step whatever the interval.
    const unsigned int interval = parameters.output.vtu_interval;
    if (interval > 0 &&
        (step % interval == 0 || step == load_program.n_steps()))
      output_results(step);
  }

  // The step's line (output/progress.h): where the load program is (step k
  // of N, the pseudo-time), how hard Newton worked (iterations, step cuts),
  // the scenario's quantities (what its checks look at), the invariants
  // (the larger of the equilibrium and the action-reaction errors:
  // equilibrium.h), the time since the run started and a forecast of the
  // time left. The first line of a scheme comes with the table's header,
  // and the scenario's legend of its columns where it has one.
  template <int dim>
  void
  ContactProblem<dim>::print_step_line(const HistoryRow &row)
  {
    const unsigned int n_steps = load_program.n_steps();
    if (!step_table.started())
      log << side_by_side(scenario->step_legend());
    std::vector<StepField> fields = {
      {"step",
       std::to_string(row.step) + "/" + std::to_string(n_steps),
       2 * static_cast<unsigned int>(std::to_string(n_steps).size()) + 1},
      {"t", format_number(row.time, 6), 6},
      {"Newton", std::to_string(row.newton_iterations)},
      {"cuts", std::to_string(row.step_cuts)}};
    for (auto &field : scenario->step_fields(row))
      fields.push_back(std::move(field));
    const double balance =
      std::isnan(row.action_reaction_error) ?
        row.equilibrium_error :
        std::max(row.equilibrium_error, row.action_reaction_error);
    fields.push_back({"balance", format_number(balance, 2), 7});
    fields.push_back({"elapsed", format_duration(progress->elapsed()), 7});
    fields.push_back(
      {"left",
       "~" + format_duration(progress->remaining(row.step, n_steps)),
       7});
    step_table.print(log, fields);
  }

  // The nodal forces of the state (equilibrium.h), from the last assembly.
  // That assembly is the converged iterate's own: the Newton loop stops at
  // the iterate it has just assembled.
  template <int dim>
  NodalForces
  ContactProblem<dim>::nodal_forces() const
  {
    NodalForces forces;
    forces.internal = internal_force;
    forces.applied  = external_force;
    // (Before the first assembly the vectors are empty: deal.II's Debug
    // mode refuses to scale an empty vector.)
    if (forces.applied.size() > 0)
      forces.applied *= -1; // external_force is the loads' part of R
    forces.supported = supported;
    // As the Newton loop's floor of the forces (residual_measure()), with
    // the same factor of ten. From the last assembly with the tangent: the
    // converged iterate's own assembly may have skipped the cell matrices
    // that the bulk's magnitudes come from.
    forces.round_off = tangent_magnitude;
    if (forces.round_off.size() > 0)
      forces.round_off *= 10 * std::numeric_limits<double>::epsilon();
    // Per pair, the contact terms' values before any constraint condenses
    // them: a support whose node lies on a contact surface must not count
    // the contact force there as its reaction. add_forces() walks every
    // slave point, so every process gets the same vector.
    for (const auto &contact : contacts)
      {
        forces.contact.emplace_back(dof_handler.n_dofs());
        contact->add_forces(solution, forces.contact.back());
      }
    // A hanging node's force acts on the nodes it hangs from (adaptive
    // refinement): a support next to one takes its share as reaction.
    if (hanging_node_constraints.n_constraints() > 0)
      {
        for (Vector<double> *f : {&forces.internal, &forces.applied})
          if (f->size() > 0)
            hanging_node_constraints.condense(*f);
        for (auto &f : forces.contact)
          hanging_node_constraints.condense(f);
        if (forces.round_off.size() > 0)
          for (const auto &line : hanging_node_constraints.get_lines())
            {
              for (const auto &[j, c] : line.entries)
                forces.round_off(j) +=
                  std::abs(c) * forces.round_off(line.index);
              forces.round_off(line.index) = 0;
            }
      }
    return forces;
  }

  // The invariants of the converged state (equilibrium.h): each body in
  // equilibrium, and each contact pair's action equal to its reaction, both
  // relative to the forces involved. Recorded in the history; a warning
  // beyond what the Newton tolerance leaves, and false (the state cannot be
  // trusted: its reason in unbalanced_forces) beyond 1e-3.
  template <int dim>
  bool
  ContactProblem<dim>::measure_balance_of_forces(HistoryRow &row)
  {
    const NodalForces forces = nodal_forces();
    // Each pair's two bodies, by the material ids of the cells under its
    // surfaces.
    std::vector<std::pair<types::material_id, types::material_id>> pairs;
    for (unsigned int i = 0; i < contacts.size(); ++i)
      if constexpr (dim == 2)
        pairs.emplace_back(
          contacts[i]->slave_surface().segments().front().cell->material_id(),
          contacts[i]->master_surface().segments().front().cell->material_id());
      else
        pairs.emplace_back(
          body_of_boundary.at(parameters.contact_pairs()[i].first),
          body_of_boundary.at(parameters.contact_pairs()[i].second));
    std::vector<std::pair<types::material_id, std::string>> names;
    for (const Body<dim> &body : bodies)
      names.emplace_back(body.material_id, body.name);
    // A cyclic sector's master copies carry the master's forces turned:
    // their sum is not the slave's.
    const Balance balance =
      measure_balance(dof_handler, forces, names, pairs, cyclic_pairs.empty());
    row.equilibrium_error     = balance.worst_body();
    row.action_reaction_error = balance.worst_pair();

    // A body's balance is the sum of the residual over its free rows, which
    // the Newton tolerance (1e-10 by default, relative to the reactions)
    // keeps well below 1e-6 at a converged state. A pair's balance holds
    // at any state, converged or not: at each slave point
    // the slave's and the master's terms share lambda, n and ds, and each
    // side's shape functions sum to one, so the two forces cancel up to
    // round-off; 1e-8 leaves room for that alone.
    constexpr double   warn_body = 1e-6, warn_pair = 1e-8, fail = 1e-3;
    std::ostringstream what;
    what << std::setprecision(3);
    bool failed = false;
    // A body whose sum is within the round-off of its forces is balanced
    // whatever the ratio says (a body moved rigidly carries round-off
    // only).
    for (unsigned int b = 0; b < balance.bodies.size(); ++b)
      {
        const auto &[name, error] = balance.bodies[b];
        if (!balance.beyond_round_off[b] || error <= warn_body)
          continue;
        what << (what.tellp() > 0 ? "; " : "") << name
             << " is out of equilibrium by " << error
             << " of its forces (applied loads, reactions and contact)";
        failed = failed || !(error <= fail);
      }
    for (unsigned int k = 0; k < balance.pairs.size(); ++k)
      if (!std::isnan(balance.pairs[k]) && !(balance.pairs[k] <= warn_pair))
        what << (what.tellp() > 0 ? "; " : "") << "contact pair " << k + 1
             << "'s forces on its two bodies differ by " << balance.pairs[k]
             << " of their magnitude";
    if (what.tellp() == 0)
      return true;
    const bool trusted = !failed && !(row.action_reaction_error > fail);
    if (trusted)
      {
        log << "Warning: step " << row.step << ": " << what.str() << '\n';
        return true;
      }
    unbalanced_forces = "step " + std::to_string(row.step) + ": " + what.str() +
                        ": the state cannot be trusted";
    return false;
  }

  // @sect4{The VTU files}
  //
  // The bodies (displacement, Cauchy stress tensor, von Mises stress) and
  // the slave surfaces (contact pressure and gap at their nodes), one file
  // per step and a .pvd record of them (VtuWriter).
  template <int dim>
  void
  ContactProblem<dim>::output_results(const unsigned int step)
  {
    TimerOutput::Scope t(timer, "output");
    // Made at the first output, with the scheme's tag in its file names,
    // so that the schemes of one run write side by side. By default each
    // cell is subdivided as often as the highest of the mapping and
    // element degrees: curved edges are shown curved, and a Q2 field is
    // not drawn as bilinear.
    if (!vtu_writer)
      {
        const unsigned int subdivisions =
          parameters.output.vtu_subdivisions > 0 ?
            parameters.output.vtu_subdivisions :
            std::max(parameters.finite_elements.mapping_degree,
                     std::max_element(bodies.begin(),
                                      bodies.end(),
                                      [](const Body<dim> &a,
                                         const Body<dim> &b) {
                                        return a.degree < b.degree;
                                      })
                       ->degree);
        vtu_writer =
          std::make_unique<VtuWriter<dim>>(parameters.output.directory,
                                           scheme.tag(),
                                           subdivisions,
                                           communicator);
      }
    // The gap of each slave node, at the multiplier's place: the surface's
    // file shows the gap beside the pressure, and lambda g = 0 can be seen.
    Vector<double> nodal_gap(dof_handler.n_dofs());
    for (const auto &contact : contacts)
      for (const auto dof : contact->nodes().dofs)
        if constexpr (dim == 2)
          nodal_gap(dof) = contact->gap_at(dof, solution);
        else
          nodal_gap(dof) = contact->gap_at(dof);
    // The faces first: they make the arc length at the first output.
    // (A 3D surface has no arc length.)
    const std::vector<typename VtuWriter<dim>::SlaveFace> slave_faces =
      slave_faces_along_chains();
    std::vector<typename VtuWriter<dim>::SurfaceField> fields = {
      {"gap", nodal_gap}};
    if constexpr (dim == 2)
      fields.push_back({"arc_length", arc_length, arc_length_closed});
    vtu_writer->write(dof_handler,
                      mapping_collection,
                      solution,
                      fields,
                      materials,
                      slave_faces,
                      step,
                      current_load.time);
  }

  // The slave faces for the VTU file, chain after chain in the order the
  // arc length runs along each (surface_arc_length.h), which is the
  // abscissa to plot the pressure and the gap against: a plot over it
  // joins the points in the file's order. The arc length itself is made at
  // the first output (the reference geometry does not change; refinement
  // empties it): at the nodes, and again with the start of each closed
  // chain at the chain's length, for the face that closes it.
  template <int dim>
  std::vector<typename VtuWriter<dim>::SlaveFace>
  ContactProblem<dim>::slave_faces_along_chains()
  {
    // A 3D surface has no chains: its faces in the order of the cells,
    // with no arc length.
    if constexpr (dim == 3)
      {
        std::vector<typename VtuWriter<dim>::SlaveFace> faces;
        for (const auto &[slave, master] : parameters.contact_pairs())
          for (const auto &cell : dof_handler.active_cell_iterators())
            for (const unsigned int f : cell->face_indices())
              if (cell->face(f)->at_boundary() &&
                  cell->face(f)->boundary_id() == slave)
                faces.push_back({cell, f});
        return faces;
      }
    else
      {
        const bool new_arc_length = arc_length.size() != dof_handler.n_dofs();
        if (new_arc_length)
          {
            arc_length.reinit(dof_handler.n_dofs());
            for (const auto &contact : contacts)
              for (const auto &[dof, s] : arc_lengths(contact->slave_surface()))
                arc_length(dof) = s;
            arc_length_closed = arc_length;
          }
        std::vector<typename VtuWriter<dim>::SlaveFace> faces;
        for (const auto &contact : contacts)
          {
            const ContactSurface &surface  = contact->slave_surface();
            const auto           &segments = surface.segments();
            for (const auto &chain : surface_chains(surface))
              for (unsigned int k = 0; k < chain.steps.size(); ++k)
                {
                  const auto &[s, entry]                     = chain.steps[k];
                  const SurfaceSegment              &segment = segments[s];
                  typename VtuWriter<dim>::SlaveFace face;
                  face.cell    = segment.cell;
                  face.face_no = segment.face_no;
                  // The chain enters the segment at its vertex `entry`: the
                  // face is walked backwards if that is its second vertex.
                  face.reversed =
                    segment.cell->face(segment.face_no)->vertex_index(0) !=
                    segment.vertices[entry];
                  face.starts_chain = k == 0;
                  face.closes_chain =
                    chain.closed && k + 1 == chain.steps.size();
                  faces.push_back(face);
                }
            // The start of a closed chain, the node at its first segment's
            // entry: the chain's length on the face that closes it.
            if (new_arc_length)
              for (const auto &chain : surface_chains(surface))
                if (chain.closed)
                  {
                    const auto &[s, entry] = chain.steps.front();
                    const auto &nodes      = surface.multiplier_nodes();
                    for (unsigned int i = 0; i < nodes.size(); ++i)
                      if (nodes[i] == entry)
                        arc_length_closed(segments[s].multiplier_dofs[i]) =
                          chain.length;
                  }
          }
        return faces;
      }
  }


  // This chapter's members for the dimensions the program runs in: the
  // explicit instantiation of the class in a chapter instantiates the
  // members defined here (see contact_problem.cc).
  template class ContactProblem<2>;
  template class ContactProblem<3>;
} // namespace RingContact
