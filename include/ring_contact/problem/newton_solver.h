// @sect3{The semi-smooth Newton solver}
//
// The Newton iteration of one load step (or of a part of it): pair the
// contact points, choose the active set, assemble, solve, and move along
// the update as far as the residual decreases. The problem is seen through
// NonlinearProblem (nonlinear_problem.h); what makes the method robust on
// contact is held here: the convergence test that knows the round-off
// floors, the line search against the jumps of a faceted master, the
// pairing held when it cycles, the rejection of inverted states, and the
// first step's strategies (first_step.h). The load steps, their predictor
// and their cuts are the load stepper's (load_stepper.h).
#ifndef ring_contact_problem_newton_solver_h
#define ring_contact_problem_newton_solver_h

#include <ring_contact/input/parameters.h>
#include <ring_contact/problem/first_step.h>
#include <ring_contact/problem/nonlinear_problem.h>

#include <cmath>
#include <limits>
#include <ostream>
#include <set>
#include <string>
#include <vector>

namespace RingContact
{
  /// Why a Newton iteration at the state last assembled must not go on: a
  /// signal asked the run to stop, or the state is rejected (inverted
  /// elements); "" if it goes on.
  std::string
  stop_reason(const NonlinearProblem &problem);

  class NewtonSolver
  {
  public:
    /// A solver of `problem` with the entries of subsection Newton; each
    /// iteration's line goes to `log` with Newton/Verbose. One solver
    /// serves the whole run: it keeps the run's record of convergence.
    NewtonSolver(NonlinearProblem       &problem,
                 const NewtonParameters &parameters,
                 std::ostream           &log);

    /// Solve the problem at its load state from the current iterate, the
    /// first update imposing the boundary increment. `iterations` counts
    /// the updates solved, `final_residual` is the last iterate's relative
    /// residual (both as far as the solve went, also when it throws).
    /// False when the iteration fails (failure_reason()).
    bool
    solve(unsigned int &iterations, double &final_residual);

    /// Why the last solve failed.
    const std::string &
    failure_reason() const
    {
      return failure;
    }

  private:
    /// @name The iteration (newton_solver.cc)
    /// @{
    unsigned int
    start_solve();
    void
    finish_solve();
    bool
    must_stop(const unsigned int it);
    unsigned int
    release_held_stick(const unsigned int it);
    bool
    test_convergence(const unsigned int it,
                     unsigned int      &n_changed,
                     ResidualMeasure   &measure);
    unsigned int
    to_the_model_laws(const unsigned int it);
    Pairing
    accepted_pairing() const;
    void
    print_iteration(const unsigned int     it,
                    const ResidualMeasure &measure,
                    const unsigned int     n_changed) const;
    /// @}

    /// @name Taking the update (newton_solver.cc)
    /// @{
    bool
    take_update(const Vector<double>             &newton_update,
                const ResidualMeasure            &measure,
                const NonlinearProblem::Assembly  next,
                unsigned int                     &n_changed);
    bool
    line_search(const Vector<double>            &newton_update,
                const ResidualMeasure           &before,
                const NonlinearProblem::Assembly assembly,
                unsigned int                    &n_changed,
                double                          &step_length);
    /// The states of every contact node of every pair as one key: 0 open;
    /// 1, 2, 3 closed and sliding backwards, sticking, sliding forwards.
    std::vector<int>
    state_key() const;
    /// The contact nodes whose state differs from `before` (the changes
    /// of an iterate are counted against the iterate it came from, not
    /// against the last line-search trial), and those that opened or
    /// closed.
    unsigned int
    n_changed_since(const std::vector<NodeStates> &before) const;
    unsigned int
    n_closed_changed_since(const std::vector<NodeStates> &before) const;
    /// @}

    NonlinearProblem      &problem;
    const NewtonParameters parameters;
    std::ostream          &log;

    /// The strategies for a zone that grows from a point.
    FirstStepStrategy first_step;

    /// Why the last solve stopped without converging.
    std::string failure;
    /// The contact points keep their partners (pairing cycles), and the
    /// iteration from which they will.
    bool         keep_partners   = false;
    unsigned int hold_pairing_at = 0;
    /// Whether the last update was damped and changed no state (friction
    /// at small strain: the next update is taken whole if it changes
    /// friction's states only), and the states this step's iterates have
    /// met, to which no whole update goes back.
    bool                       stalled_on_kink = false;
    std::set<std::vector<int>> visited_states;
    /// The nodes that opened or closed in the last update taken.
    unsigned int last_closed_changes = 0;

    /// Whether the iterate after a Newton update is expected to converge,
    /// from this run's record. Such an iterate is assembled without its
    /// tangent first: the test of convergence does not need it, and after
    /// the last update of a load step it would not be used. One that does
    /// not converge needs it for its own update, and is assembled again.
    struct ConvergenceRecord
    {
      /// Whether the last update that imposed a boundary increment led to
      /// a converged iterate.
      bool lifting_converged = false;
      /// r_k+1 / r_k^2 of the last other update, r the relative residual
      /// (the larger of the force and gap measures): Newton's quadratic
      /// rate, from which the next residual is forecast. None (infinite)
      /// before the first.
      double rate = std::numeric_limits<double>::infinity();

      bool
      expects(const bool   lifting,
              const double residual,
              const double tolerance) const
      {
        return lifting ? lifting_converged :
                         rate * residual * residual <= tolerance;
      }
      void
      record(const bool   lifting,
             const double from,
             const double to,
             const bool   converged)
      {
        if (lifting)
          lifting_converged = converged;
        else if (from > 0 && std::isfinite(from) && std::isfinite(to))
          rate = to / (from * from);
      }
    } convergence_record;
  };
} // namespace RingContact

#endif
