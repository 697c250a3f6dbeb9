// @sect3{The load program}
//
// The load stepper (load_stepper.cc) does not walk through steps but through a
// pseudo-time t: a step ends at time(k), and a step that fails is cut into
// halves, at pseudo-times between two steps. So every program is a
// function of t (the rings' start from zero load at t = 0), and the steps
// are only where the history is recorded. The rings' programs follow the
// validation document (a ramp of the pressure for A, B and H, a rotation
// at full pressure for C to G); a general problem gives its pseudo-times,
// and its boundary data are expressions of t.
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

  LoadProgram::LoadProgram(const LoadParameters &parameters)
      : parameters(parameters)
  {}

  // The ramp's default is the rings' 21 steps, p from 1e5 to 1e7; the
  // rotation's the document's N_t = 100 (its newest published inputs use
  // 10).
  unsigned int
  LoadProgram::n_steps() const
  {
    switch (parameters.program)
      {
        case LoadProgramType::ramp:
          return parameters.ramp_steps;
        case LoadProgramType::rotation:
          return parameters.rotation_steps;
        case LoadProgramType::steps:
          break;
      }
    return parameters.time_points.size();
  }

  double
  LoadProgram::time(const unsigned int step) const
  {
    if (parameters.program == LoadProgramType::ramp)
      return step * parameters.time_step;
    if (parameters.program == LoadProgramType::steps)
      return step == 0 ? 0.0 : parameters.time_points.at(step - 1);
    // Rotation: the pseudo-time runs from 0 to 1 over the steps. Not s
    // itself, so that a program of zero rotation still advances (its
    // pseudo-times would all be zero).
    return static_cast<double>(step) / parameters.rotation_steps;
  }

  LoadState
  LoadProgram::state(const double t) const
  {
    if (parameters.program == LoadProgramType::ramp)
      {
        // p(t) = p0 10^(t - 1.1); the first step starts from zero load, so
        // within it (0 < t < dt, only reached when it is cut) p grows
        // linearly to p(dt). The exponential never reaches zero (it is
        // p0 10^-1.1 at t = 0): without the linear start a cut first step
        // would begin with a jump of the load. At t = k dt with dt = 0.1,
        // p = 10^(5 + (k - 1)/10) Pa for p0 = 1e6: 1e5, 1e6 and 1e7 Pa at
        // steps 1, 11 and 21.
        const double dt = parameters.time_step;
        const double p =
          parameters.reference_pressure * std::pow(10.0, std::max(t, dt) - 1.1);
        return {t, {{"pressure", t < dt ? p * t / dt : p}, {"rotation", 0.0}}};
      }
    // Steps: the expressions of the problem take t itself; no parameter
    // moves, which tells the predictor to extrapolate in t
    // (extrapolation_factor()).
    if (parameters.program == LoadProgramType::steps)
      return {t, {}};
    // Rotation: the full pressure from the first step on (reached linearly
    // within the first step if that step has to be cut), s = s_end t. The
    // document's program: the first step both loads the rings and turns
    // them by s_end / N_t; at s_end = 1 the inner ring has turned through
    // exactly one element when t = 1.
    const double t1 = time(1);
    const double p  = parameters.rotation_pressure * std::min(1.0, t / t1);
    return {t,
            {{"pressure", p}, {"rotation", parameters.rotation_elements * t}}};
  }

  LoadState
  LoadProgram::state_at_step(const unsigned int step) const
  {
    return state(time(step));
  }
} // namespace RingContact
