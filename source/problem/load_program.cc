// @sect3{The load program}
//
// The load stepper (load_stepper.cc) does not walk through steps but through a
// pseudo-time t: a step ends at time(k), and a step that fails is cut into
// halves, at pseudo-times between two steps. So every program is a
// function of t (every program starts from zero load at t = 0), and the
// steps are only where the history is recorded. The scenarios make their
// programs (the rings' ramp and rotation follow the validation document);
// a general problem gives its pseudo-times, and its boundary data are
// expressions of t.
#include <ring_contact/problem/load_program.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace RingContact
{
  double
  LoadState::operator()(const std::string &name) const
  {
    if (parameters.empty())
      return 0;
    const auto found = parameters.find(name);
    if (found == parameters.end())
      throw std::logic_error("the load program has no parameter '" + name +
                             "'");
    return found->second;
  }

  LoadProgram::LoadProgram(const std::vector<double>              &times,
                           const std::function<LoadState(double)> &state)
      : times(times)
      , state_at(state)
  {}

  // Steps: the expressions of the problem take t itself; no parameter
  // moves, which tells the predictor to extrapolate in t
  // (extrapolation_factor()).
  LoadProgram
  LoadProgram::steps(const LoadParameters &parameters)
  {
    return LoadProgram(parameters.time_points, [](const double t) {
      return LoadState{t, {}};
    });
  }

  unsigned int
  LoadProgram::n_steps() const
  {
    return times.size();
  }

  double
  LoadProgram::time(const unsigned int step) const
  {
    return step == 0 ? 0.0 : times.at(step - 1);
  }

  LoadState
  LoadProgram::state(const double t) const
  {
    return state_at(t);
  }

  LoadState
  LoadProgram::state_at_step(const unsigned int step) const
  {
    return state(time(step));
  }
} // namespace RingContact
