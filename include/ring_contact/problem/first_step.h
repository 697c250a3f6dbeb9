// @sect3{The strategies for a contact zone that grows from a point}
//
// A load step that starts with bodies that touch at a point (or not at all)
// has to find its contact zone: a semi-smooth Newton method moves the zone's
// edge by a node or two per iteration, damped by its line search, and at
// finite strain its first update puts the whole load on the few nodes that
// touch. Four strategies make such a step converge in a few iterations,
// each measured on bench/first-step (doc/validation.md):
// - the linearised start: a finite-strain step from rest solved first with
//   the small-strain laws and contact geometry, where the zone is found;
// - stick holding: with friction, every closed node sticks while the zone
//   finds its width, so that the contact is piecewise linear meanwhile;
// - edge extrapolation: in the first iterations of a step, the edges of the
//   contact and stick zones moved to where the square-root profile of their
//   indicator puts them (contact/active_set.cc);
// - the square-root predictor: the step after one from rest extrapolated as
//   the square root of the load, as such a zone grows.
// The first three steer the Newton solver (newton_solver.h) through the
// contact pairs' switches of NonlinearProblem, and their state is held
// here, not among the finite-element data; the fourth is the load stepper's
// (load_stepper.h).
#ifndef ring_contact_problem_first_step_h
#define ring_contact_problem_first_step_h

#include <ring_contact/problem/nonlinear_problem.h>

namespace RingContact
{
  /// The iterations of a Newton solve whose updates may move the contact
  /// zones' edges by extrapolation; the later ones are plain active-set
  /// iterations.
  constexpr unsigned int extrapolate_edges_until = 8;

  /// The first step's strategies of one Newton solver: which of them is on
  /// in the current solve.
  class FirstStepStrategy
  {
  public:
    /// @name At the start and the end of a Newton solve
    /// @{

    /// After the step's first active set is asked for
    /// (NonlinearProblem::start_contact_step()): the linearised start and
    /// the stick held, where they apply.
    void
    start(NonlinearProblem &problem);

    /// Every update after the solve (a state restored after a failure, the
    /// postprocessing, a refined mesh) chooses by the plain rule, under the
    /// model's laws.
    void
    finish(NonlinearProblem &problem);
    /// @}

    /// @name The linearised start
    /// @{

    /// Whether the step is being solved linearised.
    bool
    is_linearised() const
    {
      return linearised;
    }

    /// From the linearised iterate to the model's laws and contact
    /// geometry, at the same iterate (the contact zones' edges no longer
    /// extrapolated there).
    void
    leave_linearisation(NonlinearProblem &problem);
    /// @}

    /// @name Stick holding
    /// @{

    /// Whether the closed nodes are held in stick.
    bool
    is_holding_stick() const
    {
      return holding_stick;
    }

    /// At iteration `it`, whether the held stick is released now: the
    /// zone has found its width to a node (`closed_changes`, the nodes
    /// that opened or closed in the last update, at most one), or the
    /// iterations for finding it are over. The stick and slip states are
    /// chosen from here (the caller assembles the iterate again).
    bool
    release_stick(NonlinearProblem  &problem,
                  const unsigned int it,
                  const unsigned int closed_changes,
                  const unsigned int max_iterations);

    /// A frictional step from rest in finite strain, switched to the
    /// model's laws at iteration `it` when the stick was released: its
    /// stick zones' edges are extrapolated for as many iterations as a
    /// step's first.
    void
    extrapolate_stick_edges_from(const unsigned int it)
    {
      stick_edges_until = it + extrapolate_edges_until;
    }
    /// @}

    /// @name Edge extrapolation
    /// @{

    /// Which pairs' active sets extrapolate the zones' edges in iteration
    /// `it`.
    void
    choose_edge_extrapolation(NonlinearProblem  &problem,
                              const unsigned int it);

    /// Whether the contact zones' edges move by extrapolation in this
    /// iteration: the line search then takes an update that opens or
    /// closes nodes whole.
    bool
    extrapolating_edges() const
    {
      return moving_contact_edges;
    }
    /// @}

  private:
    /// Whether the step starts from the undeformed state, finite strain,
    /// with every contact zone to be found: its problem linearised there is
    /// the small-strain one, solved first.
    bool
    starts_from_rest_in_finite_strain(NonlinearProblem &problem) const;
    /// The small-strain laws and contact geometry (on), or the model's.
    void
    linearise(NonlinearProblem &problem, const bool on);

    bool linearised    = false;
    bool holding_stick = false;
    /// The contact zones' edges move by extrapolation in this iteration.
    bool moving_contact_edges = false;
    /// The iteration up to which the stick zones' edges are extrapolated
    /// in finite strain (a frictional step from rest).
    unsigned int stick_edges_until = 0;
  };

  /// The square-root predictor: the factor by which a load step
  /// extrapolates the last converged increment, given the load's
  /// extrapolation factor `linear`. After a step from rest in which a
  /// contact zone closed over part of its slave surface the state is scaled
  /// by sqrt(r), r = 1 + linear, not by r; otherwise `linear`.
  double
  square_root_predictor(NonlinearProblem &problem, const double linear);
} // namespace RingContact

#endif
