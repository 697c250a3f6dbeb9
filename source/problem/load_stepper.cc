// @sect3{The load steps: predictor, retries and cuts}
//
// A load step is reached through increments of the pseudo-time. Each one
// starts from a predictor, the last converged increment extrapolated (or,
// after a step from rest that closed part of a contact zone, its square
// root: first_step.cc), and is solved by the Newton solver. An increment
// that fails from an extrapolated state is tried again from the last
// converged state; one that fails from there is halved, at most
// Newton/Maximum step cuts times. Each increment that converges becomes the
// new start, and a halved increment is kept for the rest of the step (it is
// not doubled again). A run ends only when a step still fails after the
// halvings; the steps before it are kept.
#include <ring_contact/base/utilities.h>
#include <ring_contact/output/progress.h>
#include <ring_contact/problem/first_step.h>
#include <ring_contact/problem/load_stepper.h>
#include <ring_contact/scenarios/scenario.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace RingContact
{
  LoadStepper::LoadStepper(NonlinearProblem       &problem,
                           const LoadProgram      &load_program,
                           const NewtonParameters &parameters,
                           std::ostream           &log)
      : problem(problem)
      , load_program(load_program)
      , parameters(parameters)
      , log(log)
      , newton(problem, parameters, log)
  {}

  // @sect4{A step of the load program}
  //
  // Adaptive refinement (the problem's): the step solved again on finer
  // meshes before it is reported.
  bool
  LoadStepper::solve_step(const unsigned int step,
                          unsigned int      &iterations,
                          unsigned int      &cuts)
  {
    if (!advance_to(step, load_program.time(step), cuts, iterations))
      return false;
    return solve_again_on_refined_meshes(step, cuts, iterations);
  }

  // @sect4{The predictor}
  //
  // The predictor of a load step: extrapolate the last increment when it
  // and the next move one and the same of the load program's parameters
  // (LoadState: the rings' pressure only, or their rotation only), in that
  // parameter; when none moves, in the pseudo-time, in which a general
  // problem's boundary data are written (its program has no parameters).
  // The stepper knows no parameter by name: it asks which moved. Returns
  // the factor of the last increment (0: no extrapolation).
  //
  // The increments must be of the same kind because the factor is a ratio
  // of one parameter's increments: the rotation program presses the rings
  // in its first step and turns them after, and its first turn has only a
  // pressure increment behind it, from which no turn can be scaled.
  double
  LoadStepper::extrapolation_factor(const double t_next) const
  {
    // The first step has no increment behind it (both times are 0).
    if (!parameters.extrapolate || !(current_time > previous_time))
      return 0;
    const LoadState next = load_program.state(t_next);
    const LoadState now  = problem.load_state();
    const LoadState prev = load_program.state(previous_time);
    // The parameters that move over the last increment or the next, and
    // the ratio of the next increment to the last of the one that does.
    unsigned int moved  = 0;
    double       factor = 0;
    for (const auto &[name, value] : now.parameters)
      {
        const double last = value - prev(name), coming = next(name) - value;
        if (last != 0 || coming != 0)
          {
            ++moved;
            factor = last != 0 ? coming / last : 0;
          }
      }
    if (moved == 0)
      return (t_next - current_time) / (current_time - previous_time);
    return moved == 1 ? factor : 0;
  }

  void
  LoadStepper::extrapolate(const Vector<double> &converged, const double scale)
  {
    if (scale != 0)
      problem.iterate().add(scale,
                            converged,
                            -scale,
                            problem.increment_start());
  }

  // A load program with a kink in it (pressed, then moved sideways) is not
  // extrapolated across the kink: the predictor would go on pressing. Seen
  // where the imposed displacements are: a cylinder pressed by its top moved
  // down, then sideways in one step, started from a zone pressed on far past
  // the target, and its Newton iteration failed before it was tried again from
  // the converged state (doc/validation.md, "Curved geometry, ties and touching
  // bodies"). The square root moves imposed displacements short of their
  // target: there the linear extrapolation is taken, if it meets the target (a
  // Hertz step driven by its top's displacement keeps its predictor so).
  double
  LoadStepper::check_predictor(const Vector<double> &converged,
                               const double          linear,
                               const double          scale)
  {
    if (scale == 0 || problem.boundary_near_target(converged))
      return scale;
    Vector<double> &solution = problem.iterate();
    solution                 = converged;
    if (scale != linear)
      solution.add(linear, converged, -linear, problem.increment_start());
    const double kept =
      scale != linear && problem.boundary_near_target(converged) ? linear : 0;
    if (kept == 0)
      solution = converged;
    return kept;
  }

  // @sect4{One try of an increment}
  //
  // Boundary data that is not a number (a general problem's expression,
  // e.g. sqrt(0.6 - t)) and a state that is not finite (a diverging
  // iterate) fail this try like a Newton failure: the step is cut, and the
  // converged steps stay. Reported as inverted elements or a bare "not
  // finite", they used to hide their cause. A failure in the first iteration
  // (or an exception) leaves the boundary increment imposed; between Newton
  // solves the updates are homogeneous.
  bool
  LoadStepper::try_increment(const double          t_next,
                             const Vector<double> &converged,
                             const double          linear,
                             double               &scale,
                             unsigned int         &iterations,
                             double               &residual,
                             std::string          &failure)
  {
    bool ok = false;
    try
      {
        problem.apply_boundary_motion(load_program.state(t_next));
        scale = check_predictor(converged, linear, scale);
        ok    = newton.solve(iterations, residual);
        if (!ok)
          failure = newton.failure_reason();
      }
    catch (const BoundaryDataError &e)
      {
        failure = e.what();
      }
    catch (const NonFiniteState &e)
      {
        failure = e.what();
      }
    problem.drop_boundary_increment();
    return ok;
  }

  // @sect4{The increments of a step}
  //
  // From the current state to the load state at t_end, through increments
  // halved while Newton fails (at most Newton/Maximum step cuts times).
  bool
  LoadStepper::advance_to(const unsigned int step,
                          const double       t_end,
                          unsigned int      &cuts,
                          unsigned int      &total_iterations)
  {
    double dt = t_end - current_time;
    // Whether the increment being tried starts from the last converged
    // state itself: after a failure from the extrapolated state, the same
    // increment is tried from there before it is cut.
    bool from_converged = false;
    // Sums of halved increments reach t_end only up to round-off: a
    // relative margin keeps them from adding a sub-increment of 1e-16.
    while (current_time < t_end - 1e-12 * std::abs(t_end))
      {
        const double         t_next    = std::min(current_time + dt, t_end);
        const Vector<double> converged = problem.iterate();
        // Predictor: the extrapolation of the last increment, unless a try
        // from it has just failed.
        const double linear =
          from_converged ? 0.0 : extrapolation_factor(t_next);
        double scale = square_root_predictor(problem, linear);
        extrapolate(converged, scale);
        unsigned int iterations = 0;
        double       residual   = std::numeric_limits<double>::infinity();
        std::string  failure;
        const bool   ok = try_increment(
          t_next, converged, linear, scale, iterations, residual, failure);
        total_iterations += iterations;
        // Converged: the interfaces keep this state as the reference of the
        // next increment's slip (friction), and the state it started from
        // becomes the second point of the next extrapolation.
        if (ok)
          {
            problem.accept_contact_state(problem.iterate());
            problem.increment_start() = converged;
            previous_time             = current_time;
            current_time              = t_next;
            from_converged            = false;
            continue;
          }
        // Failed: back to the last converged state, half the increment.
        // The load state and the pairing go back with it, so that the
        // interfaces (read by the next try and by the output if the run
        // stops here) describe the state that is kept.
        problem.restore_state(converged, load_program.state(current_time));
        if (problem.stop_requested())
          {
            log << "Interrupted by a signal in step " << step
                << ": stopping with the last converged state (t = "
                << current_time << ")\n";
            return false;
          }
        // The extrapolation is a guess: a state off the path (a body held
        // by the contact whose first step removed an initial overlap, not
        // in proportion to the load, was extrapolated apart from it) is
        // not a reason to cut the step.
        if (scale != 0)
          {
            from_converged = true;
            log << wrap_text("  step " + std::to_string(step) +
                             ": Newton failed from the extrapolated state (" +
                             failure +
                             "); trying again from the last converged state");
            continue;
          }
        from_converged = false;
        if (cuts == parameters.max_step_cuts)
          {
            std::ostringstream message;
            message << "Step " << step << ": Newton did not converge after "
                    << cuts << " step cuts (" << failure
                    << "; last relative residual " << residual
                    << " at t = " << t_next << ", increment " << dt
                    << "); stopping with the last converged state (t = "
                    << current_time << ")";
            log << wrap_text(message.str());
            return false;
          }
        ++cuts;
        dt /= 2;
        std::ostringstream message;
        message << "  step " << step << ": Newton failed (" << failure
                << "; relative residual " << residual
                << "), cutting the increment to " << dt;
        log << wrap_text(message.str());
      }
    return true;
  }

  // @sect4{The step solved again on the refined mesh}
  //
  // Called when a step has converged. Each cycle of refinement that is due
  // refines, carries the state over and solves the same load state again
  // from the carried state: the boundary values of the new nodes come in
  // through the first update, as any step's; with friction the slips are
  // measured from the step's start, carried over too. Where that fails (a
  // frictional state carried over can start Newton where it cycles), the
  // increment is solved again on the new mesh from the step's start, with
  // step cuts, as the step was. A cycle that fails even so ends the run
  // with the step unreported: its converged state was on the old mesh,
  // which is gone.
  bool
  LoadStepper::solve_again_on_refined_meshes(const unsigned int step,
                                             unsigned int      &cuts,
                                             unsigned int      &iterations)
  {
    const unsigned int n_cycles = problem.refinement_cycles(step);
    for (unsigned int cycle = 1; cycle <= n_cycles; ++cycle)
      {
        if (!problem.refine_mesh_after_step(step, cycle))
          break;
        problem.accept_contact_state(problem.increment_start());
        // The same load state from the carried state: no predictor.
        unsigned int cycle_iterations = 0;
        double       residual         = 0;
        double       no_predictor     = 0;
        std::string  failure;
        const bool   ok = try_increment(current_time,
                                      problem.iterate(),
                                      0,
                                      no_predictor,
                                      cycle_iterations,
                                      residual,
                                      failure);
        iterations += cycle_iterations;
        if (!ok)
          {
            // From the step's start, carried over, as the step was solved.
            log << wrap_text("  step " + std::to_string(step) +
                             ": Newton failed from the state carried to the "
                             "refined mesh (" +
                             failure +
                             "); solving the step again from its start");
            const double t_end = current_time;
            current_time       = previous_time;
            problem.restore_state(problem.increment_start(),
                                  load_program.state(current_time));
            if (!advance_to(step, t_end, cuts, iterations))
              {
                log << wrap_text("Step " + std::to_string(step) +
                                 ": not solved on the mesh of refinement "
                                 "cycle " +
                                 std::to_string(cycle) +
                                 " (the steps before are kept)");
                return false;
              }
            continue;
          }
        problem.accept_contact_state(problem.iterate());
      }
    return true;
  }
} // namespace RingContact
