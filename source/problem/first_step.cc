// @sect3{The strategies for a contact zone that grows from a point}
//
// Each strategy below answers a failure measured on the first step of a
// press from touching (bench/first-step: steel on aluminium, the Hertz
// problem, whose contact zone grows as the square root of the load), and
// each is switched on only where that situation is: a step from rest, a
// zone that grows from a point, friction at small strain. The Newton solver
// (newton_solver.cc) asks at the points of its iteration where a strategy
// acts; what the strategies change is the contact pairs' active-set
// switches and the material laws, through NonlinearProblem.
#include <deal.II/base/mpi.h>

#include <ring_contact/linear_algebra/linear_system.h>
#include <ring_contact/problem/first_step.h>

#include <algorithm>
#include <cmath>

namespace RingContact
{
  // @sect4{The start and the end of a Newton solve}
  //
  // With friction, a contact zone that grows from a point (the first step
  // of a press) first finds its width with every closed node sticking: the
  // contact is then a linear tie with a moving edge, whose edges the
  // extrapolation finds in a few iterations (small strain). The stick and
  // slip states are chosen once the zone no longer moves. Chosen together
  // from the first iteration, the states flipped in waves over a zone that
  // grew by a node or two per damped iteration: steel on aluminium, mu = 0.2,
  // many iterations and a cut with Gauss 2 (doc/validation.md, "Curved
  // geometry, ties and touching bodies"). The test reads the pairs after the
  // linearised start: a finite-strain pair solved linearised is a small-strain
  // one.
  void
  FirstStepStrategy::start(NonlinearProblem &problem)
  {
    linearise(problem, starts_from_rest_in_finite_strain(problem));
    stick_edges_until = 0;
    const auto pairs = problem.contact_pair_states();
    holding_stick =
      std::any_of(pairs.begin(),
                  pairs.end(),
                  [](const auto &pair) { return pair.friction; }) &&
      std::all_of(pairs.begin(), pairs.end(), [](const auto &pair) {
        return pair.small_strain && pair.zone_grows_from_point;
      });
    problem.hold_stick(holding_stick);
  }

  // The edges' extrapolation belongs to a solve's first iterations: every
  // update after it (a state restored after a failure, the postprocessing,
  // a refined mesh) chooses by the plain rule.
  void
  FirstStepStrategy::finish(NonlinearProblem &problem)
  {
    moving_contact_edges = false;
    holding_stick        = false;
    problem.allow_edge_extrapolation(
      std::vector<bool>(problem.contact_pair_states().size(), false));
    problem.hold_stick(false);
    linearise(problem, false);
  }

  // @sect4{The linearised start}
  //
  // A step that starts from the undeformed state (every unknown zero) with
  // no contact pressure, some body in finite strain: its problem linearised
  // at that state is the small-strain one, with the same Lame constants (the
  // laws agree to first order at F = I) and the contact measured on the
  // reference configuration. That problem is piecewise linear, and the rules
  // that find a contact zone growing from a point in a few iterations (the
  // edges' extrapolation, whole updates that open or close nodes) hold for
  // it. Its solution is the starting iterate of the finite-strain Newton
  // iteration, whose zone is then within a node or two. Solved in finite
  // strain from the start, the first update put the whole load on the two or
  // three nodes that touch, a state far outside the range of the
  // linearisation (a large residual after the update, then damped updates,
  // inverted elements and cuts). Steel on aluminium (Hertz, a = R / 10, the
  // whole load in one step from touching), Saint Venant-Kirchhoff,
  // frictionless: many iterations and cuts before, a few and none now
  // (bench/first-step; doc/validation.md, "Curved geometry, ties and touching
  // bodies").
  bool
  FirstStepStrategy::starts_from_rest_in_finite_strain(
    NonlinearProblem &problem) const
  {
    const auto pairs         = problem.contact_pair_states();
    const bool finite_strain = std::any_of(
      pairs.begin(), pairs.end(), [](const auto &pair) {
        return !pair.small_strain;
      });
    const bool zones_to_find =
      std::all_of(pairs.begin(), pairs.end(), [](const auto &pair) {
        return pair.zone_grows_from_point;
      });
    // With friction too: the small-strain iterations find the zone with
    // every closed node sticking, and the stick and slip states are chosen
    // under the model's laws from there (release_stick()). Steel on
    // aluminium from touching, Saint Venant-Kirchhoff, mu = 0.2 and 0.5,
    // one step at h = 0.01 to 0.0025 and the first of four at h = 0.01 and
    // 0.005: a few iterations and no cut, where the finite-strain iteration
    // from rest took many, with cuts, or failed (bench/first-step;
    // doc/validation.md, "Curved geometry, ties and touching bodies"). Not
    // where the problem says it may not be linearised (a cyclic sector: small
    // strain there solved a sector of 11 of 12 elements, C, Gauss 2, with an
    // inexact tangent, linearly converging, a defect of its own, left open).
    // Every process decides alike (each holds the whole vector, but a decision
    // that differed would leave the others waiting).
    return finite_strain && zones_to_find && problem.may_linearise() &&
           Utilities::MPI::max(problem.iterate().linfty_norm(),
                               problem.get_communicator()) == 0;
  }

  void
  FirstStepStrategy::linearise(NonlinearProblem &problem, const bool on)
  {
    if (on == linearised)
      return;
    problem.linearise(on);
    linearised = on;
  }

  // From a linearised iterate to the model's own laws and contact geometry,
  // at the same iterate. The first assembly there chooses the states by the
  // plain rule (extrapolated across the switch, from the linearised
  // profile, the stick zone's edge went astray: steel on aluminium, mu = 0.2,
  // h = 0.0025, Gauss 2, many iterations and a cut; doc/validation.md, "Curved
  // geometry, ties and touching bodies"). The Newton solver pairs afresh there
  // (NewtonSolver::to_the_model_laws()).
  void
  FirstStepStrategy::leave_linearisation(NonlinearProblem &problem)
  {
    linearise(problem, false);
    moving_contact_edges = false;
    problem.allow_edge_extrapolation(
      std::vector<bool>(problem.contact_pair_states().size(), false));
  }

  // @sect4{Stick holding}
  //
  // The zone has found its width, to a node (or the iterations for finding
  // it are over): the stick and slip states from here on, chosen at this
  // iterate, which the caller assembles again with them. Before the test of
  // convergence: an iterate converged under held stick is not one under
  // friction. Not at the update that imposes the boundary increment, whose
  // iterate is the last load state's. To a node: with segment-based 2 an
  // edge node can open and close in turn under whole updates (steel on
  // aluminium, the first of four steps, h = 0.0025), and waiting for no change
  // held the stick for most of the step's iterations (doc/validation.md,
  // "Curved geometry, ties and touching bodies"). And at the latest halfway
  // through Newton/Maximum iterations, whatever it is set to.
  bool
  FirstStepStrategy::release_stick(NonlinearProblem  &problem,
                                   const unsigned int it,
                                   const unsigned int closed_changes,
                                   const unsigned int max_iterations)
  {
    if (!holding_stick || problem.imposing_boundary_increment() || it == 0 ||
        !(closed_changes <= 1 || it >= extrapolate_edges_until ||
          2 * it >= max_iterations))
      return false;
    holding_stick = false;
    problem.hold_stick(false);
    return true;
  }

  // @sect4{Edge extrapolation}
  //
  // The zones' edges extrapolated in the iterates of the first iterations
  // (see contact/active_set.cc), at small strain: the contact zones' while
  // the contact is piecewise linear (no friction, or every closed node held
  // in stick), and the stick zones' once the stick and slip states are
  // free. Where the contact is piecewise linear, updates that open or close
  // nodes are also taken whole (NewtonSolver::line_search()). Not at finite
  // strain: shallow ironing (friction 0.3, 40 steps) took many more iterations,
  // and cuts (doc/validation.md, "Curved geometry, ties and touching bodies"),
  // its zone moving by a node or two a step on a sliding, turning surface.
  // Except the stick zones' in the first iterations under the model's laws of a
  // frictional step from rest (the contact zone is then in place, from the
  // linearised iterations; the contact zones' edges are never extrapolated at
  // finite strain, where the contact is not piecewise linear).
  void
  FirstStepStrategy::choose_edge_extrapolation(NonlinearProblem  &problem,
                                               const unsigned int it)
  {
    const auto pairs = problem.contact_pair_states();
    const bool move_edges =
      (it < extrapolate_edges_until &&
       std::all_of(pairs.begin(),
                   pairs.end(),
                   [](const auto &pair) { return pair.small_strain; })) ||
      it < stick_edges_until;
    moving_contact_edges =
      move_edges &&
      std::all_of(pairs.begin(), pairs.end(), [](const auto &pair) {
        return pair.piecewise_linear;
      });
    // Per pair: the contact zones' edges only where every pair is
    // piecewise linear (their updates are then taken whole), the stick
    // zones' wherever the states are free.
    std::vector<bool> allow;
    for (const auto &pair : pairs)
      allow.push_back(moving_contact_edges ||
                      (move_edges && !pair.piecewise_linear));
    problem.allow_edge_extrapolation(allow);
  }

  // @sect4{The square-root predictor}
  //
  // After a step from rest in which a contact zone closed over part of its
  // slave surface (some node closed, fewer than half), the state is scaled
  // by sqrt(r), r = 1 + linear the ratio of the loads from rest (when the
  // load is zero at rest), not by r. Such a zone grows as the square root of
  // the load (Hertz; the displacements away from it grow about as the
  // load), and the linear extrapolation, twice the first of equal steps,
  // closed far more nodes than close: the Newton iteration failed from there,
  // and the step was then solved from the first step's state. The square root
  // is a measured choice, not a derived one: steel on aluminium from touching,
  // four steps, h = 0.01 and 0.005, mu = 0, 0.2, 0.5, nodal / Gauss 2 /
  // segment-based 2: the second step takes fewer iterations with it, in finite
  // and in small strain (bench/first-step, its n=4 lines; doc/validation.md,
  // "Curved geometry, ties and touching bodies"). A zone over most of its
  // surface (conforming bodies: the rings, the patch test, a fit) or none
  // (bodies apart) is linear in the load, and keeps the linear extrapolation
  // (exact for the patch test; the rings' ramp took more iterations with the
  // square root). Imposed displacements are not scaled so: the square root
  // moves them short of their target, and the load stepper falls back to
  // the linear extrapolation there (LoadStepper::predict()).
  double
  square_root_predictor(NonlinearProblem &problem, const double linear)
  {
    if (linear == 0)
      return linear;
    // The last converged state is a step from rest: the state its increment
    // started from is the rest state. Every process decides alike.
    const MPI_Comm communicator = problem.get_communicator();
    if (Utilities::MPI::max(problem.increment_start().linfty_norm(),
                            communicator) != 0)
      return linear;
    const auto pairs = problem.contact_pair_states();
    const bool here =
      std::any_of(pairs.begin(), pairs.end(), [](const auto &pair) {
        return pair.n_closed > 0 && 2 * pair.n_closed < pair.n_nodes;
      });
    const bool zone_closed_from_rest =
      n_processes(communicator) > 1 ?
        Utilities::MPI::logical_or(here, communicator) :
        here;
    return zone_closed_from_rest ? std::sqrt(1 + linear) - 1 : linear;
  }
} // namespace RingContact
