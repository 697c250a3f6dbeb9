// A load program: the steps the user asks for, as pseudo-times t, and the
// load state at any t in between (used when a step is cut into smaller
// increments). The scenario makes its program from its own entries (the
// rings' ramp and rotation, the patch test's ramp); the steps program, the
// given pseudo-times in which a general problem's expressions are written,
// is common.
#ifndef ring_contact_problem_load_program_h
#define ring_contact_problem_load_program_h

#include <ring_contact/input/parameters.h>

#include <functional>

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
    /// The program whose step k ends at `times[k - 1]` and whose state at a
    /// pseudo-time t is `state(t)`.
    LoadProgram(const std::vector<double>              &times,
                const std::function<LoadState(double)> &state);

    /// The steps program: the pseudo-times of Load program/Time points (or
    /// its Number of steps), with no parameters (a general problem's
    /// boundary data are expressions of t).
    static LoadProgram
    steps(const LoadParameters &parameters);

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
    std::vector<double>              times;
    std::function<LoadState(double)> state_at;
  };
} // namespace RingContact

#endif
