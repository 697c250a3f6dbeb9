// @sect3{The load steps}
//
// The step loop of the load program: each step reached from the last
// converged state through increments, each started from a predictor (the
// last increment extrapolated) and solved by the Newton solver
// (newton_solver.h); an increment whose Newton iteration fails is tried
// again from the last converged state if it started from an extrapolated
// one, then halved. After a converged step, adaptive refinement solves it
// again on the refined meshes. The problem is seen through NonlinearProblem
// (nonlinear_problem.h); the load path (the times of the last two converged
// states) is held here.
#ifndef ring_contact_problem_load_stepper_h
#define ring_contact_problem_load_stepper_h

#include <ring_contact/input/parameters.h>
#include <ring_contact/problem/load_program.h>
#include <ring_contact/problem/newton_solver.h>
#include <ring_contact/problem/nonlinear_problem.h>

#include <ostream>
#include <string>

namespace RingContact
{
  class LoadStepper
  {
  public:
    /// The steps of `load_program` on `problem`, with the entries of
    /// subsection Newton (its cuts, its predictor, the Newton solver's);
    /// what happens goes to `log`. The problem starts at rest, t = 0.
    LoadStepper(NonlinearProblem       &problem,
                const LoadProgram      &load_program,
                const NewtonParameters &parameters,
                std::ostream           &log);
    /// The load program is held by reference: not a temporary.
    LoadStepper(NonlinearProblem &,
                const LoadProgram &&,
                const NewtonParameters &,
                std::ostream &) = delete;

    /// Solve step `step` of the load program from the current state (and
    /// again on refined meshes where adaptive refinement is due). False if
    /// it could not be solved: the problem is then at the last converged
    /// state. `iterations` and `cuts` add up the step's Newton iterations
    /// and halvings.
    bool
    solve_step(const unsigned int step,
               unsigned int      &iterations,
               unsigned int      &cuts);

    /// The pseudo-time of the last converged state.
    double
    time() const
    {
      return current_time;
    }

  private:
    /// From the current state to the load state at t_end, the increment
    /// halved while Newton fails; false if it still fails after the cuts.
    bool
    advance_to(const unsigned int step,
               const double       t_end,
               unsigned int      &cuts,
               unsigned int      &iterations);
    /// The predictor of a load step: the factor of the last increment to
    /// extrapolate (0: none).
    double
    extrapolation_factor(const double t_next) const;
    /// The iterate extrapolated by `scale` times the last increment from
    /// `converged`.
    void
    extrapolate(const Vector<double> &converged, const double scale);
    /// The predictor checked against the boundary target (set): returns
    /// the scale kept (`scale`, the linear one, or 0).
    double
    check_predictor(const Vector<double> &converged,
                    const double          linear,
                    const double          scale);
    /// One try of the increment to `t_next` from the predicted iterate: the
    /// boundary target, the predictor's check, the Newton solve. False,
    /// with its reason, if it fails; the boundary increment is dropped
    /// either way.
    bool
    try_increment(const double          t_next,
                  const Vector<double> &converged,
                  const double          linear,
                  double               &scale,
                  unsigned int         &iterations,
                  double               &residual,
                  std::string          &failure);
    /// After a converged step, if refinement is due: 'Adaptive cycles'
    /// times refine and solve the step again. False if a cycle fails.
    bool
    solve_again_on_refined_meshes(const unsigned int step,
                                  unsigned int      &cuts,
                                  unsigned int      &iterations);

    NonlinearProblem      &problem;
    const LoadProgram     &load_program;
    const NewtonParameters parameters;
    std::ostream          &log;
    NewtonSolver           newton;

    /// The pseudo-times of the last converged state and of the one before.
    double previous_time = 0;
    double current_time  = 0;
  };
} // namespace RingContact

#endif
