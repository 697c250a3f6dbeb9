// The load programs as functions of a pseudo-time t: the steps the user
// asks for, and the load state at any t in between (used when a step is cut
// into smaller increments). A ramp of the pressure, p(t) = p0 10^(t - 1.1)
// at t = k dt (the rings' A, B and H, the patch test); a rotation of s
// elements at a fixed pressure (the rings' C to G); or given pseudo-times,
// in which a general problem's expressions are written.
#ifndef ring_contact_problem_load_program_h
#define ring_contact_problem_load_program_h

#include <ring_contact/input/parameters.h>

#include <map>
#include <string>
#include <vector>

namespace RingContact
{
  /// What is imposed at one instant: the pseudo-time and the load
  /// program's parameters at it, by their names. The rings' ramp and
  /// rotation programs name the pressure p [Pa] "pressure" and the rotation
  /// s [elements turned] "rotation"; the steps program of a general problem
  /// has none (its boundary data are expressions of t). The scenario reads
  /// the parameters its boundary data are written in; the predictor asks
  /// which of them moved (LoadStepper), knowing none by name.
  struct LoadState
  {
    double                        time = 0; ///< the pseudo-time t
    std::map<std::string, double> parameters;

    /// The parameter of a name; 0 in a state without parameters (the
    /// unloaded start the constraints are set up in). A name the program
    /// does not have in a state that has some is a program error, refused.
    double
    operator()(const std::string &name) const;
  };

  class LoadProgram
  {
  public:
    explicit LoadProgram(const LoadParameters &parameters);

    /// Number of steps (step numbers run 1..n_steps()).
    unsigned int
    n_steps() const;

    /// Pseudo-time at the end of step k (k = 0 is the unloaded start).
    double
    time(const unsigned int step) const;

    /// The load at pseudo-time t.
    LoadState
    state(const double t) const;

    /// The load at the end of step k.
    LoadState
    state_at_step(const unsigned int step) const;

  private:
    const LoadParameters parameters;
  };
} // namespace RingContact

#endif
