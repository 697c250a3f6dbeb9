// The load stepper, the Newton solver and the first step's strategies on a
// problem of one unknown (problem/nonlinear_problem.h): what each is for,
// checked where it can be seen in isolation.
// - The line search: atan(u - 10) = 0 from u = 0, where Newton's method
//   alone overshoots further at every update (|u - 10| > 1.39), converges
//   with damped updates.
// - The step cuts: a problem that rejects any load increment above 0.3 (as
//   inverted elements reject a state) reaches t = 1 in increments of 0.25:
//   two halvings, and the halved increment kept for the rest of the step.
// - The square-root predictor: u^2 + u = t + sqrt(t), whose solution sqrt(t)
//   grows as a Hertz zone does, after a step from rest in which a zone
//   closed over part of its surface (3 nodes of 10) starts its second step
//   at the solution (no update); with a zone over most of its surface (6 of
//   10) the linear extrapolation is kept, and Newton needs updates.
// - Stick holding: with friction, a zone that grows from a point (1, 4, 6,
//   7, 7 closed nodes after each update) holds every closed node in stick
//   until its last update closed at most one node; no iterate is converged
//   before, even where the residual is zero.
#include <ring_contact/problem/load_stepper.h>
#include <ring_contact/problem/newton_solver.h>

#include <cmath>
#include <functional>
#include <limits>
#include <sstream>

#include "tests.h"

using namespace RingContact;
using RingContactTests::check;

namespace
{
  // One unknown u with the residual R(u, t) and its derivative, and, if
  // asked, one contact pair whose closed nodes follow a script over the
  // Newton updates of a solve. No boundary motion, one process.
  class ToyProblem : public NonlinearProblem
  {
  public:
    std::function<double(double, double)> residual, derivative;
    /// A load increment from the last converged state above this is
    /// rejected, as a state with inverted elements.
    double largest_increment = std::numeric_limits<double>::infinity();
    /// The contact pair (none if `pairs` is empty) and the number of its
    /// closed nodes after each update of a solve (the last repeated).
    std::vector<ContactPairState> pairs;
    std::vector<unsigned int>     closed_after_update;
    /// What the strategies did: the iterate at the start of each solve, the
    /// updates of each solve at which the stick was held and released.
    std::vector<double> solve_starts;
    std::vector<int>    stick_held_at, stick_released_at;
    unsigned int        updates = 0;

    ToyProblem()
        : u(1)
        , u_start(1)
    {}

    Vector<double> &
    iterate() override
    {
      return u;
    }
    Vector<double> &
    increment_start() override
    {
      return u_start;
    }
    const LoadState &
    load_state() const override
    {
      return load;
    }
    void
    restore_state(const Vector<double> &state, const LoadState &l) override
    {
      u    = state;
      load = l;
    }
    void
    accept_contact_state(const Vector<double> &) override
    {
      converged_time = load.time;
    }

    void
    apply_boundary_motion(const LoadState &l) override
    {
      load = l;
    }
    bool
    impose_boundary_increment() override
    {
      solve_starts.push_back(u(0));
      updates = 0;
      return false;
    }
    bool
    imposing_boundary_increment() const override
    {
      return false;
    }
    void
    set_boundary_at_target() override
    {}
    void
    drop_boundary_increment() override
    {}
    bool
    boundary_near_target(const Vector<double> &) const override
    {
      return true;
    }

    unsigned int
    assemble_newton_system(const Pairing, const Assembly what) override
    {
      assemble_system(what);
      if (pairs.empty() || closed_after_update.empty())
        return 0;
      const NodeStates   before = states;
      const unsigned int closed = closed_after_update[std::min<std::size_t>(
        updates, closed_after_update.size() - 1)];
      for (unsigned int k = 0; k < states.active.size(); ++k)
        states.active[k] = k < closed;
      pairs[0].n_closed = closed;
      return states.n_changed_since(before);
    }
    void
    assemble_system(const Assembly what) override
    {
      tangent = what == Assembly::residual_and_tangent;
      r       = residual(u(0), load.time);
      dr      = derivative(u(0), load.time);
    }
    bool
    assembled_with_tangent() const override
    {
      return tangent;
    }
    ResidualMeasure
    residual_measure() const override
    {
      ResidualMeasure measure;
      measure.force             = std::abs(r);
      measure.merit             = std::abs(r);
      measure.force_floor_known = tangent;
      return measure;
    }
    bool
    state_rejected() const override
    {
      return load.time - converged_time > largest_increment;
    }
    std::string
    rejection_reason() const override
    {
      return "the load increment is too large for the toy";
    }
    bool
    solve_linear_system(Vector<double> &update, std::string &) override
    {
      update(0) = -r / dr;
      ++updates;
      return true;
    }

    std::vector<ContactPairState>
    contact_pair_states() const override
    {
      return pairs;
    }
    std::vector<NodeStates>
    contact_node_states() const override
    {
      if (pairs.empty())
        return {};
      return {states};
    }
    void
    start_contact_step() override
    {}
    void
    hold_stick(const bool hold) override
    {
      if (pairs.empty() || !pairs[0].friction ||
          hold == pairs[0].piecewise_linear)
        return;
      // Friction at small strain: piecewise linear while the stick is held.
      pairs[0].piecewise_linear = hold;
      (hold ? stick_held_at : stick_released_at).push_back(updates);
    }
    void
    allow_edge_extrapolation(const std::vector<bool> &allow) override
    {
      check(allow.size() == pairs.size(), "one switch per pair");
    }
    bool
    may_linearise() const override
    {
      return false;
    }
    void
    linearise(const bool) override
    {}

    unsigned int
    refinement_cycles(const unsigned int) override
    {
      return 0;
    }
    bool
    refine_mesh_after_step(const unsigned int, const unsigned int) override
    {
      return false;
    }
    MPI_Comm
    get_communicator() const override
    {
      return MPI_COMM_SELF;
    }
    bool
    stop_requested() const override
    {
      return false;
    }

    /// One contact pair of 10 nodes, all open.
    void
    add_pair(const bool friction, const unsigned int n_closed)
    {
      ContactPairState pair;
      pair.small_strain          = true;
      pair.friction              = friction;
      pair.zone_grows_from_point = true;
      pair.piecewise_linear      = !friction;
      pair.n_closed              = n_closed;
      pair.n_nodes               = 10;
      pairs                      = {pair};
      states.active.assign(10, false);
      states.slip_sign.assign(10, 0);
      for (unsigned int k = 0; k < n_closed; ++k)
        states.active[k] = true;
    }

  private:
    Vector<double> u, u_start;
    LoadState      load{};
    double         converged_time = 0;
    bool           tangent        = false;
    double         r = 0, dr = 0;
    NodeStates     states;
  };

  NewtonParameters
  newton_parameters(const bool extrapolate)
  {
    NewtonParameters parameters{};
    parameters.max_iterations   = 50;
    parameters.tolerance        = 1e-10;
    parameters.max_step_cuts    = 5;
    parameters.extrapolate      = extrapolate;
    parameters.verbose          = false;
    parameters.linear_solver    = LinearSolverType::automatic;
    parameters.linear_tolerance = 1e-8;
    return parameters;
  }

  /// The pseudo-times 1, 2, ... n.
  LoadProgram
  steps(const unsigned int n)
  {
    LoadParameters parameters{};
    parameters.program = "steps";
    for (unsigned int k = 1; k <= n; ++k)
      parameters.time_points.push_back(k);
    parameters.number_of_steps = n;
    return LoadProgram::steps(parameters);
  }
} // namespace

int
main()
{
  auto &out = RingContactTests::deallog_file;

  // The line search. Plain Newton on atan(x) = 0 from x = -10: x_k+1 =
  // x_k - (1 + x_k^2) atan(x_k), further out at every update
  // (138.6, -2.99e4, 1.40e9).
  {
    double x = -10;
    for (unsigned int k = 0; k < 3; ++k)
      x -= (1 + x * x) * std::atan(x);
    check(std::abs(x) > 1e9, "plain Newton diverges");
    ToyProblem toy;
    toy.residual   = [](double u, double t) { return std::atan(u - 10 * t); };
    toy.derivative = [](double u, double t) {
      return 1 / (1 + (u - 10 * t) * (u - 10 * t));
    };
    std::ostringstream log;
    const LoadProgram  program = steps(1);
    LoadStepper        stepper(toy, program, newton_parameters(false), log);
    unsigned int       iterations = 0, cuts = 0;
    check(stepper.solve_step(1, iterations, cuts), "the line search converges");
    check(std::abs(toy.iterate()(0) - 10) < 1e-8 && cuts == 0,
          "at the solution, no cut");
    out << "line search: atan(u - 10) = 0 from u = 0 converged in "
        << iterations << " iterations (plain Newton: |u - 10| = " << std::abs(x)
        << " after 3)" << std::endl;
  }

  // The step cuts: 1 -> 0.5 -> 0.25, then four increments of 0.25.
  {
    ToyProblem toy;
    toy.residual          = [](double u, double t) { return u - t; };
    toy.derivative        = [](double, double) { return 1.0; };
    toy.largest_increment = 0.3;
    std::ostringstream log;
    const LoadProgram  program = steps(1);
    LoadStepper        stepper(toy, program, newton_parameters(false), log);
    unsigned int       iterations = 0, cuts = 0;
    check(stepper.solve_step(1, iterations, cuts), "the cut step converges");
    check(cuts == 2 && toy.solve_starts.size() == 6 && toy.iterate()(0) == 1 &&
            stepper.time() == 1,
          "two cuts, two failed tries and four increments of 0.25");
    out << "step cuts: " << cuts << " cuts, " << toy.solve_starts.size()
        << " Newton solves, " << iterations << " iterations; increments from";
    for (const double start : toy.solve_starts)
      out << ' ' << start;
    out << std::endl << log.str();
  }

  // The square-root predictor against the linear one, on the second step.
  for (const unsigned int closed : {3u, 6u})
    {
      ToyProblem toy;
      toy.residual = [](double u, double t) {
        return u * std::abs(u) + u - t - std::sqrt(t);
      };
      toy.derivative = [](double u, double) { return 2 * std::abs(u) + 1; };
      toy.add_pair(false, closed);
      std::ostringstream log;
      const LoadProgram  program = steps(2);
      LoadStepper        stepper(toy, program, newton_parameters(true), log);
      unsigned int       first = 0, second = 0, cuts = 0;
      check(stepper.solve_step(1, first, cuts) &&
              stepper.solve_step(2, second, cuts),
            "both steps converge");
      const double predicted = toy.solve_starts.back();
      check(closed == 3 ?
              std::abs(predicted - std::sqrt(2.0)) < 1e-14 && second == 0 :
              predicted == 2 && second > 0,
            "the predictor of the second step");
      out << "predictor after a step from rest, " << closed
          << " of 10 nodes closed: the second step starts at u = " << predicted
          << " (solution " << std::sqrt(2.0) << "), " << second << " iterations"
          << std::endl;
    }

  // Stick holding in a frictional zone that grows from a point.
  {
    ToyProblem toy;
    toy.residual            = [](double u, double t) { return u - t; };
    toy.derivative          = [](double, double) { return 1.0; };
    toy.closed_after_update = {1, 4, 6, 7, 7};
    toy.add_pair(true, 0);
    NewtonSolver newton(toy, newton_parameters(false), std::cerr);
    toy.apply_boundary_motion({1, {}});
    unsigned int iterations = 0;
    double       residual   = 0;
    check(newton.solve(iterations, residual), "the held step converges");
    check(toy.stick_held_at == std::vector<int>{0} &&
            toy.stick_released_at.size() == 1 &&
            toy.stick_released_at[0] == 3 && iterations == 4,
          "the stick is held until the zone grew by one node, then released");
    out << "stick holding: held from the start, released after update "
        << toy.stick_released_at[0]
        << " (the zone closed 1, 4, 6, 7 nodes; the residual was zero after "
           "update 1), converged in "
        << iterations << " iterations" << std::endl;
  }
}
