// @sect3{The semi-smooth Newton solver}
//
// Each load step is solved by a semi-smooth Newton method: pair the slave
// points with the current master surface, choose the active set, assemble,
// solve the linearised system directly, and move along the update as far as
// the residual decreases (line search). It has converged when the active
// set no longer changes and both the force rows and the contact rows are
// below the tolerance relative to their own scales, or at their round-off
// floor (ResidualMeasure): one tolerance fits any material, load and size.
//
// This file only drives: the state it moves is the problem's iterate, and
// the problem pairs, assembles and solves (NonlinearProblem; for the contact
// problem problem/assembly.cc and problem/nonlinear_problem.cc). What it adds
// is the logic that makes the method robust: a convergence test that knows
// what double precision can resolve, a line search against the jumps of a
// faceted master surface, the pairing held when it cycles, and the rejection
// of inverted states; and, at the points of the iteration where they act,
// the strategies for a zone that grows from a point (first_step.cc).
#include <ring_contact/problem/newton_solver.h>

#include <algorithm>
#include <iomanip>

namespace RingContact
{
  // @sect4{Held pairing}
  //
  // After how many iterations of a Newton solve the pairing is held. On a
  // faceted master surface turned by the rotation, every slave point of C
  // with the nodal scheme (80 of 80, step 1) flipped between the two
  // segments of a groove at every iteration. Ordinary steps converge before
  // (doc/validation.md, "Newton"), with a free pairing.
  constexpr unsigned int hold_pairing_after = 4;

  // While the pairing is held, an accepted iterate stops a point that has
  // passed its partner's end at that vertex, with the vertex normal: past
  // a groove's vertex the segment's extension runs inside the neighbouring
  // segment, and holding points there ended a rotation of C (facet normals,
  // nodal scheme, one element per step) low. The line search's trials follow
  // the extension instead (Pairing::hold): the switch to the vertex is a jump
  // of the residual, which stopped the search (C, facet normals, nodal, 80
  // around, failed early in the rotation). Both: doc/validation.md, "The
  // rotation at p = 1e7 Pa".
  Pairing
  NewtonSolver::accepted_pairing() const
  {
    return keep_partners ? Pairing::hold_within_segments : Pairing::search;
  }

  NewtonSolver::NewtonSolver(NonlinearProblem       &problem,
                             const NewtonParameters &parameters,
                             std::ostream           &log)
      : problem(problem)
      , parameters(parameters)
      , log(log)
  {}

  // @sect4{The Newton iteration}
  //
  // Semi-smooth Newton: pair, choose the active set, assemble, solve, and
  // move along the update as far as the residual decreases (line search).
  // Converged when the active set did not change, and both the force rows
  // and the contact rows are below the tolerance relative to their own
  // scales, or at their round-off floor (test_convergence()). A state with
  // an inverted element (det F <= 0) is never accepted.
  //
  // The active-set choice max(0, w_k lambda_k - c g~_k) makes the residual
  // only piecewise smooth; Newton's method on it is the primal-dual
  // active-set method, which is converged only when the set it solved with
  // is the set the new iterate chooses: hence n_changed == 0 in the test.
  bool
  NewtonSolver::solve(unsigned int &iterations, double &final_residual)
  {
    Vector<double> newton_update(problem.iterate().size());
    iterations = 0;
    failure.clear();
    // However the solve ends (converged, failed, or an exception from the
    // assembly), the updates after it choose by the plain rule.
    struct PlainRuleAfter
    {
      NewtonSolver &solver;
      ~PlainRuleAfter()
      {
        solver.finish_solve();
      }
    } plain_rule_after{*this};
    unsigned int n_changed = start_solve();
    // The update that led to the current iterate: none yet, or whether it
    // imposed the boundary increment and the residual it started from.
    bool   updated = false, update_lifted = false;
    double update_from = 0;
    for (unsigned int it = 0;; ++it)
      {
        if (must_stop(it))
          {
            final_residual = std::numeric_limits<double>::infinity();
            return false;
          }
        n_changed += release_held_stick(it);
        ResidualMeasure measure;
        const bool      converged = test_convergence(it, n_changed, measure);
        // One number for the step's report and for the rate of the update
        // that led here: the worse of the two groups.
        final_residual = std::max(measure.force, measure.gap);
        if (updated)
          convergence_record.record(update_lifted,
                                    update_from,
                                    final_residual,
                                    converged);
        if (parameters.verbose)
          print_iteration(it, measure, n_changed);
        // A residual that is not a number would only give an update that is
        // not one: the step fails here, with its reason, and is cut.
        if (!std::isfinite(measure.merit))
          {
            failure = "the residual is not finite";
            return false;
          }
        if (converged)
          return true;
        if (it == parameters.max_iterations)
          {
            failure = "no convergence in " +
                      std::to_string(parameters.max_iterations) +
                      " iterations";
            return false;
          }

        // A slave point in a groove of a faceted master (a master vertex
        // seen from the slave side, where the normal turns by the angle
        // between the segments) has no position with one normal where the
        // residual vanishes: the pairing flips between the two segments at
        // every iteration and Newton cycles. After a few iterations every
        // point keeps its partner (on the segment's extension if need be):
        // the residual is smooth, and the step converges to the state with
        // that pairing. The next step pairs afresh.
        if (it + 1 == hold_pairing_at)
          keep_partners = true;
        first_step.choose_edge_extrapolation(problem, it);

        if (!problem.solve_linear_system(newton_update, failure))
          {
            final_residual = std::numeric_limits<double>::infinity();
            return false;
          }
        ++iterations;
        // The next iterate without its tangent first when it is expected to
        // converge (see ConvergenceRecord): the test of convergence needs
        // only the residual, and after the last update of a step the
        // tangent was thrown away (a large share of the assemblies on A's
        // ramp). The forecast uses this run's own quadratic rate: always
        // assembling the residual first wasted an assembly at every iteration
        // that did not converge (a loss on the rotation modelisations); on A's
        // ramp the forecast skips most of those tangents and wastes none
        // (doc/validation.md, "Time and memory behind the code's choices").
        updated       = true;
        update_lifted = problem.imposing_boundary_increment();
        update_from   = final_residual;
        const auto next =
          convergence_record.expects(update_lifted,
                                     final_residual,
                                     parameters.tolerance) ?
            NonlinearProblem::Assembly::residual :
            NonlinearProblem::Assembly::residual_and_tangent;
        if (!take_update(newton_update, measure, next, n_changed))
          return false;
      }
  }

  // Every load step pairs afresh; the pairing is held only within the step
  // whose Newton iteration cycled. The first update moves the boundary to
  // the new load state. Written straight into the solution, the whole
  // increment sat in the first layer of elements along the boundary; at
  // finite strain with thin layers (F, 160 x 12 per ring, p = 1e7 in one
  // step: about 27 % strain there) Newton went to another solution, the
  // rings apart, p_A = 0. Through the linearised problem the increment
  // spreads over the bodies. No such update when the predictor hit the
  // target already. Then the first step's strategies, where they apply,
  // and the first iterate assembled. Returns its number of changed states.
  unsigned int
  NewtonSolver::start_solve()
  {
    keep_partners = false;
    visited_states.clear();
    stalled_on_kink = false;
    problem.impose_boundary_increment();
    problem.start_contact_step();
    first_step.start(problem);
    hold_pairing_at = hold_pairing_after;
    return problem.assemble_newton_system(
      Pairing::search, NonlinearProblem::Assembly::residual_and_tangent);
  }

  // The plain rule after the solve; a stall concerned this solve's updates.
  void
  NewtonSolver::finish_solve()
  {
    stalled_on_kink = false;
    first_step.finish(problem);
  }

  // Whether the Newton iteration `it` must not go on: a signal ends the
  // step here, not after it (and its cuts): the converged steps are on disk
  // already; an inverted element (det F <= 0 at a quadrature point) makes
  // the material law meaningless, and the step is cut. The assembly does
  // not evaluate the law at such a point but counts it, so that the
  // rejection comes here with the smallest det F in its message.
  bool
  NewtonSolver::must_stop(const unsigned int it)
  {
    if (problem.stop_requested())
      {
        failure = "interrupted by a signal";
        return true;
      }
    if (problem.state_rejected())
      {
        failure = problem.rejection_reason();
        if (parameters.verbose)
          log << "    Newton " << std::setw(2) << it << "  " << failure
              << '\n';
        return true;
      }
    return false;
  }

  std::string
  stop_reason(const NonlinearProblem &problem)
  {
    if (problem.stop_requested())
      return "interrupted by a signal";
    return problem.state_rejected() ? problem.rejection_reason() : "";
  }

  // The held stick released (first_step.cc): the iterate assembled again
  // with the stick and slip states. A frictional step from rest in finite
  // strain (linearised first): the contact zone is found, and the stick and
  // slip states are chosen under the model's laws right away, their edges
  // extrapolated there for as many iterations as a step's first. The
  // linearised stick zone is not the finite-strain one (a = R / 10 strains
  // the bodies by 5 %: steel on aluminium, mu = 0.2, its edge is several nodes
  // further in), and finding it first cost damped iterations, after which the
  // finite-strain iteration moved the edge a node per iteration: on a fine mesh
  // more iterations than the default 12, and cuts (bench/first-step;
  // doc/validation.md, "Curved geometry, ties and touching bodies"). Returns
  // the number of states changed by the new assembly.
  unsigned int
  NewtonSolver::release_held_stick(const unsigned int it)
  {
    if (!first_step.release_stick(problem,
                                  it,
                                  last_closed_changes,
                                  parameters.max_iterations))
      return 0;
    if (!first_step.is_linearised())
      return problem.assemble_newton_system(
        accepted_pairing(), NonlinearProblem::Assembly::residual_and_tangent);
    if (parameters.verbose)
      log << "    the contact zone is found: the model's laws "
             "from here, with the stick and slip states\n";
    const unsigned int n_changed = to_the_model_laws(it);
    first_step.extrapolate_stick_edges_from(it);
    return n_changed;
  }

  // @sect4{The convergence test}
  //
  // An iterate assembled without its tangent: the tangent now, at the same
  // state and pairing, unless the iterate has converged. The update needs
  // it, and so may the test of convergence (the round-off floor of the
  // forces). The iterate before the update that imposes the boundary
  // increment is the last load state's equilibrium, its boundary not yet
  // moved: never converged; nor an iterate under held stick.
  bool
  NewtonSolver::test_convergence(const unsigned int it,
                                 unsigned int      &n_changed,
                                 ResidualMeasure   &measure)
  {
    const double tolerance = parameters.tolerance;
    const bool   lifting   = problem.imposing_boundary_increment();
    measure                = problem.residual_measure();
    if (!problem.assembled_with_tangent() &&
        !(!lifting && n_changed == 0 && measure.converged(tolerance)))
      {
        problem.assemble_system(
          NonlinearProblem::Assembly::residual_and_tangent);
        measure = problem.residual_measure();
      }
    bool converged = !lifting && !first_step.is_holding_stick() &&
                     n_changed == 0 && measure.converged(tolerance);
    // The linearised step has converged: the model's own laws and contact
    // geometry from here, at the same iterate, with the active set the
    // plain rule chooses there (a node or two from the linearised one).
    // Without friction: with it, the switch came at the end of the held
    // stick (release_held_stick()).
    if (converged && first_step.is_linearised())
      {
        if (parameters.verbose)
          log << "    the linearised step has converged: the model's "
                 "laws from here\n";
        // Not converged with an inverted element: the law was not
        // evaluated there.
        n_changed = to_the_model_laws(it);
        measure   = problem.residual_measure();
        converged = n_changed == 0 && !problem.state_rejected() &&
                    measure.converged(tolerance);
      }
    return converged;
  }

  // From a linearised iterate to the model's own laws and contact geometry
  // (FirstStepStrategy::leave_linearisation()), paired afresh in the current
  // configuration (the partners held in the linearised iterations are the
  // reference configuration's), and held again only after as many
  // iterations as at the start. A damped small-strain update's stall
  // (line_search()) says nothing of the next update under the model's laws.
  unsigned int
  NewtonSolver::to_the_model_laws(const unsigned int it)
  {
    first_step.leave_linearisation(problem);
    stalled_on_kink = false;
    keep_partners   = false;
    hold_pairing_at = it + hold_pairing_after;
    return problem.assemble_newton_system(
      Pairing::search, NonlinearProblem::Assembly::residual_and_tangent);
  }

  // One line per Newton iteration (Newton/Verbose). Before the update that
  // moves the boundary, the measures are those of the previous load state
  // (the reactions may be zero): not shown. The line gives each measure
  // beside its floor, so that a stalled step shows whether it is stuck
  // above the arithmetic's limit or merely at it.
  void
  NewtonSolver::print_iteration(const unsigned int     it,
                                const ResidualMeasure &measure,
                                const unsigned int     n_changed) const
  {
    unsigned int n_active = 0, n_nodes = 0;
    for (const auto &pair : problem.contact_pair_states())
      {
        n_active += pair.n_closed;
        n_nodes += pair.n_nodes;
      }
    if (problem.imposing_boundary_increment())
      {
        log << "    Newton " << std::setw(2) << it
            << "  boundary increment imposed on the update  active "
            << n_active << "/" << n_nodes << '\n';
        return;
      }
    log << "    Newton " << std::setw(2) << it << "  relative residual "
        << std::scientific << std::setprecision(3) << measure.force;
    // Converged before the tangent (and the floor) was assembled.
    if (measure.force_floor_known)
      log << " (floor " << measure.force_floor << ")";
    else
      log << " (floor not needed)";
    if (measure.at_rest)
      log << "  gap (nothing has moved yet)";
    else
      log << "  gap " << measure.gap << " (floor " << measure.gap_floor << ")";
    log << std::defaultfloat << "  active " << n_active << "/" << n_nodes
        << "  changed " << n_changed << '\n';
  }

  // @sect4{Taking the update}
  //
  // The Newton update applied, and the next iterate assembled (`next`
  // says whether with its tangent). The update that imposes the boundary
  // increment is taken whole: a fraction of it would leave the boundary
  // short of the load state, and the merit of the state before it does not
  // see the increment. An inverted state is rejected at the next iteration
  // (the load step is then cut). Any other update goes through the line
  // search; where it finds no decrease, the pairing is the suspect and is
  // held, and where it is held already, the step fails (false).
  bool
  NewtonSolver::take_update(const Vector<double>            &newton_update,
                            const ResidualMeasure           &measure,
                            const NonlinearProblem::Assembly next,
                            unsigned int                    &n_changed)
  {
    // The solve leaves the boundary at its target up to round-off; the
    // homogeneous updates after it would keep that error for the whole
    // step, so the imposed values are written again, exactly.
    const auto states_before = problem.contact_node_states();
    if (problem.imposing_boundary_increment())
      {
        problem.iterate() += newton_update;
        problem.set_boundary_at_target();
        n_changed = problem.assemble_newton_system(accepted_pairing(), next);
        last_closed_changes = n_closed_changed_since(states_before);
        return true;
      }
    // The changes are counted from here: each trial of the line search is
    // assembled afresh, and counting against the trial before it said
    // "changed 0" while the active set grew at every iteration (and an iterate
    // could pass as converged with a set it was not solved with).
    double     step_length   = 1;
    const auto count_changes = [&]() {
      n_changed           = n_changed_since(states_before);
      last_closed_changes = n_closed_changed_since(states_before);
    };
    // No decrease along the update: with a free pairing the residual may
    // jump between pairings at every trial, so the pairing is held and the
    // same iterate assembled again, now smooth in the displacement; the
    // next iteration solves from there. With the pairing held already
    // there is nothing left to try, and the step is cut.
    if (!line_search(newton_update, measure, next, n_changed, step_length))
      {
        stalled_on_kink = false; // it concerned the update that failed
        if (keep_partners)
          return false;
        keep_partners = true;
        problem.assemble_newton_system(
          accepted_pairing(), NonlinearProblem::Assembly::residual_and_tangent);
        count_changes();
        if (parameters.verbose)
          log << "      line search failed: pairing held\n";
        return true;
      }
    if (parameters.verbose && step_length < 1)
      log << "      line search: step length " << step_length << '\n';
    // A damped update with friction at small strain that changed no state
    // (see line_search()).
    const auto pairs = problem.contact_pair_states();
    stalled_on_kink =
      step_length < 1 && n_changed_since(states_before) == 0 &&
      std::all_of(pairs.begin(), pairs.end(), [](const auto &pair) {
        return pair.small_strain && pair.friction;
      });
    // The trials followed held partners onto their extensions.
    if (keep_partners)
      problem.assemble_newton_system(accepted_pairing(), next);
    count_changes();
    return true;
  }

  std::vector<int>
  NewtonSolver::state_key() const
  {
    std::vector<int> key;
    for (const auto &states : problem.contact_node_states())
      for (unsigned int k = 0; k < states.active.size(); ++k)
        key.push_back(states.active[k] ? 2 + states.slip_sign[k] : 0);
    return key;
  }

  unsigned int
  NewtonSolver::n_changed_since(const std::vector<NodeStates> &before) const
  {
    const auto   now = problem.contact_node_states();
    unsigned int n   = 0;
    for (unsigned int i = 0; i < now.size(); ++i)
      n += now[i].n_changed_since(before[i]);
    return n;
  }

  unsigned int
  NewtonSolver::n_closed_changed_since(
    const std::vector<NodeStates> &before) const
  {
    const auto   now = problem.contact_node_states();
    unsigned int n   = 0;
    for (unsigned int i = 0; i < now.size(); ++i)
      n += now[i].n_closed_changed_since(before[i]);
    return n;
  }

  // @sect4{The line search}
  //
  // Globalisation of the semi-smooth Newton method: u + a du with a = 1,
  // 1/2, 1/4, ... until the merit |R| (the Euclidean norm of the free rows)
  // decreases by the Armijo fraction, |R(u + a du)| <= (1 - 1e-4 a) |R(u)|,
  // and no element is inverted; the system at the accepted state is left
  // assembled. With faceted master surfaces the residual jumps where a
  // contact point crosses a master vertex (its normal turns by the angle
  // between the segments), and a full step can jump back and forth between
  // two pairings forever; the line search stops on the lower side.
  bool
  NewtonSolver::line_search(const Vector<double>            &newton_update,
                            const ResidualMeasure           &before,
                            const NonlinearProblem::Assembly assembly,
                            unsigned int                    &n_changed,
                            double                          &step_length)
  {
    constexpr unsigned int max_halvings  = 6;
    constexpr double       armijo        = 1e-4;
    Vector<double>        &solution      = problem.iterate();
    const Vector<double>   start         = solution;
    const auto             states_before = problem.contact_node_states();
    visited_states.insert(state_key());
    // Each trial is paired and assembled as an iterate would be (the
    // active set is chosen anew): the merit must be that of the state the
    // loop would continue from. A held pairing follows the segments'
    // extensions here, not stopped at the vertices (see
    // accepted_pairing()).
    for (unsigned int halving = 0;; ++halving)
      {
        solution = start;
        solution.add(step_length, newton_update);
        n_changed = problem.assemble_newton_system(
          keep_partners ? Pairing::hold : Pairing::search, assembly);
        // While the zones' edges move (the first iterations, see
        // FirstStepStrategy::choose_edge_extrapolation()), a whole update
        // that opens or closes nodes is taken whatever its merit: the
        // merit of a state with another active set has other rows (a gap
        // where there was a pressure), and its increase says nothing about
        // the step. Damped, a zone grew slowly from a touching point; whole, it
        // finds its width in a few iterations (doc/validation.md, "Curved
        // geometry, ties and touching bodies"). The line search stays for the
        // rest: a fixed active set, friction's stick and slip, faceted masters.
        if (halving == 0 && first_step.extrapolating_edges() &&
            !problem.state_rejected() &&
            n_closed_changed_since(states_before) > 0)
          return true;
        // Likewise, in any step, right after a damped update that changed
        // no state, one that changes only friction's states (a stall on the
        // kink between stick and slip: the fraction taken keeps the states,
        // and the next update aims at the same states again; the residual
        // halved at each iteration). Never back to states this step has met:
        // the method can cycle (with every such update whole, the second step
        // of the problem above alternated between two sets of closed nodes).
        // The figures: doc/validation.md, "Curved geometry, ties and touching
        // bodies".
        const bool whole_state_change =
          stalled_on_kink && n_closed_changed_since(states_before) == 0;
        if (halving == 0 && whole_state_change && !problem.state_rejected() &&
            n_changed_since(states_before) > 0 &&
            visited_states.insert(state_key()).second)
          return true;
        // A trial with an inverted element is never accepted, whatever its
        // merit: the stress there was not evaluated.
        if (!problem.state_rejected())
          {
            const double    tolerance = parameters.tolerance;
            ResidualMeasure trial     = problem.residual_measure();
            // At the round-off floor the merit is noise: take the step.
            const auto accept = [&]() {
              return trial.merit <= (1 - armijo * step_length) * before.merit ||
                     trial.converged(tolerance) || before.converged(tolerance);
            };
            // The floor of the forces, which needs the tangent, may decide:
            // the trial is assembled again at the same state and pairing,
            // with its tangent, so that the decision is the one a whole
            // assembly would have taken.
            if (!accept() && trial.undecided(tolerance))
              {
                problem.assemble_system(
                  NonlinearProblem::Assembly::residual_and_tangent);
                trial = problem.residual_measure();
              }
            if (accept())
              return true;
          }
        // Down to 1/64 of the update without a decrease: the iterate is
        // restored and the caller decides (hold the pairing, or fail).
        if (halving == max_halvings)
          {
            if (problem.state_rejected())
              return true; // rejected by the Newton loop with its message
            failure  = "the line search found no decrease of the residual";
            solution = start;
            return false;
          }
        step_length /= 2;
      }
  }
} // namespace RingContact
