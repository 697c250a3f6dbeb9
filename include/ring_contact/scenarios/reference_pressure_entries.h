// The entries of the scenarios that know the contact pressure everywhere on
// their slave surface (the rings' closed form, the patch test's uniform
// pressure): the pressure ramp that loads them, the probe whose pressure
// they report (the rings' node A), and the checks against that reference
// (subsection Checks, the original's TEST_RESU). They are these scenarios'
// own entries, declared by each of them in the subsections where a file
// writes them (Load program, Contact, Checks), so that a file of another
// scenario that sets one is refused (input/parameters.h).
#ifndef ring_contact_scenarios_reference_pressure_entries_h
#define ring_contact_scenarios_reference_pressure_entries_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <ring_contact/base/dimension.h>
#include <ring_contact/problem/load_program.h>

#include <string>
#include <utility>
#include <vector>

namespace RingContact
{
  using namespace dealii;

  /// The quantity checked against the reference pressure.
  enum class CheckedQuantity
  {
    pressure_at_A,     ///< contact pressure at the probe node A
    l2_pressure_error, ///< relative L2 error of the pressure on the slave
    pressure_spread    ///< (max - min) / reference over the slave nodes
  };

  /// Subsection Checks: one quantity, the steps it is checked at and the
  /// tolerance.
  struct CheckParameters
  {
    CheckedQuantity           quantity;
    bool                      every_step;
    std::vector<unsigned int> steps; ///< when not every step
    double                    tolerance;

    /// Declare the entries, recorded in `declared`.
    void
    add_parameters(ParameterHandler &prm, std::vector<std::string> &declared);

    /// A checked step beyond the load program's `n_steps` is refused.
    void
    check_steps(const unsigned int n_steps) const;
  };

  /// The ramp of the pressure, p(t) = p0 10^(t - 1.1) at t = k dt
  /// (Load program/Program = ramp).
  struct PressureRamp
  {
    double       reference_pressure; ///< p0
    unsigned int steps;
    double       time_step; ///< dt

    /// The program's value of Load program/Program.
    static constexpr const char *program_name = "ramp";

    /// The program's name and its sentence of Load program/Program.
    static std::pair<std::string, std::string>
    program_choice();

    /// Declare the entries, recorded in `declared`.
    void
    add_parameters(ParameterHandler &prm, std::vector<std::string> &declared);

    /// The last pressure of the ramp a number.
    void
    finish() const;

    /// The load program: the parameters "pressure" and "rotation" (0).
    LoadProgram
    program() const;
  };

  /// The entries of a scenario checked against a reference pressure.
  struct ReferencePressureEntries
  {
    PressureRamp    ramp;
    CheckParameters checks;
    /// Where the reported pressure is taken (the nearest slave node).
    std::vector<double> probe;

    /// The probe as a point of a `spacedim`-dimensional problem: a
    /// ParameterError (Contact/Probe point) if the file gave it with
    /// the other number of coordinates.
    template <int spacedim>
    Point<spacedim>
    probe_point() const;

    /// Declare every entry, recorded in `declared`.
    void
    add_parameters(ParameterHandler &prm, std::vector<std::string> &declared);
  };
} // namespace RingContact

#endif
