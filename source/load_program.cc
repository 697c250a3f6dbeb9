#include <ring_contact/load_program.h>

#include <algorithm>
#include <cmath>

namespace RingContact
{
  LoadProgram::LoadProgram(const LoadParameters &parameters)
      : parameters(parameters)
  {}

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
    // Rotation: the pseudo-time runs from 0 to 1 over the steps.
    return static_cast<double>(step) / parameters.rotation_steps;
  }

  LoadState
  LoadProgram::state(const double t) const
  {
    if (parameters.program == LoadProgramType::ramp)
      {
        // p(t) = p0 10^(t - 1.1); the first step starts from zero load, so
        // within it (0 < t < dt, only reached when it is cut) p grows
        // linearly to p(dt).
        const double dt = parameters.time_step;
        const double p =
          parameters.reference_pressure * std::pow(10.0, std::max(t, dt) - 1.1);
        return {t < dt ? p * t / dt : p, 0.0, t};
      }
    // Steps: the expressions of the problem take t itself.
    if (parameters.program == LoadProgramType::steps)
      return {0.0, 0.0, t};
    // Rotation: the full pressure from the first step on (reached linearly
    // within the first step if that step has to be cut), s = s_end t.
    const double t1 = time(1);
    const double p  = parameters.rotation_pressure * std::min(1.0, t / t1);
    return {p, parameters.rotation_elements * t, t};
  }

  LoadState
  LoadProgram::state_at_step(const unsigned int step) const
  {
    return state(time(step));
  }
} // namespace RingContact
