// @sect3{The entries of a scenario with a reference pressure}
//
// The rings and the patch test are loaded by the same ramp, report the
// pressure at the same kind of probe and are checked the same way: their
// entries are declared here once, and each of the two scenarios declares
// them as its own (a file of a general problem that sets one is refused,
// naming who reads it). Both declare the same entries with the same
// defaults and documentation: deal.II takes an entry declared twice, and
// each declaration's action sets its own scenario's member. How an entry is
// declared, checked and documented is told at the top of
// input/parameters.cc.
#include <ring_contact/base/utilities.h>
#include <ring_contact/input/parameter_checks.h>
#include <ring_contact/scenarios/reference_pressure_entries.h>

#include <deal.II/base/numbers.h>

#include <algorithm>
#include <cmath>

namespace RingContact
{
  using namespace ParameterChecks;

  // @sect4{Subsection Checks}
  //
  // The original's TEST_RESU: one quantity, the steps it is checked at and
  // the tolerance. A general problem has its own checks ('Check 1' to '12').

  void
  CheckParameters::add_parameters(ParameterHandler         &prm,
                                  std::vector<std::string> &declared)
  {
    Subsection s(prm, "Checks", &declared);
    // The pressure at A is the original's check. The spread is the patch
    // test's: its exact pressure is uniform, so the spread is zero in any
    // kinematics, where the value p itself is exact in small strain only.
    s.add("Quantity",
          quantity,
          "pressure at A",
          {{"pressure at A", CheckedQuantity::pressure_at_A},
           {"L2 error of pressure", CheckedQuantity::l2_pressure_error},
           {"pressure spread", CheckedQuantity::pressure_spread}},
          "The checked value (the original's TEST_RESU): the "
          "contact pressure at node A against the analytic "
          "pressure, the relative L2 error of the pressure "
          "over the slave surface (reference 0), or the spread "
          "(largest - smallest nodal pressure) / analytic "
          "pressure (reference 0).");
    s.add("Steps",
          "all",
          Patterns::Anything(),
          "'all', 'last', 'none', or a comma-separated list of "
          "step numbers (1-based).",
          [this](const std::string &text) {
            steps_from_text(text, "Checks", "Steps", every_step, steps);
          });
    // 2 %, the document's tolerance for the ramps; the rotation files set 4 %.
    s.add("Tolerance",
          tolerance,
          "0.02",
          "Largest admitted relative error (0.02 = 2 %).",
          not_negative());
  }

  // A checked step beyond the last one of the load program is a typo, refused
  // here by its line rather than failed as 'not reached' after the run.
  // (invalid_unsigned_int stands for Steps = last, always reached.)
  void
  CheckParameters::check_steps(const unsigned int n_steps) const
  {
    for (const unsigned int step : steps)
      require(step == numbers::invalid_unsigned_int || step <= n_steps,
              "Checks",
              "Steps",
              "names step " + std::to_string(step) +
                ", but the load program has " + std::to_string(n_steps) +
                " steps");
  }

  // @sect4{The ramp}
  //
  // The rings' ramp (A, B, H), which the patch test takes too:
  // p = p0 10^(t - 1.1) at the times t = k dt, by default dt = 0.1,
  // k = 1..21, that is 1e5 Pa at step 1, p0 = 1e6 Pa at step 11 and 1e7 Pa
  // at step 21. The rings are elastic, so each step is an independent
  // problem at its own load: the ramp maps the error over two decades of
  // load.

  std::pair<std::string, std::string>
  PressureRamp::program_choice()
  {
    return {program_name,
            "the pressure p(t) = p0 10^(t - 1.1) at t = k dt (the rings' A, B, "
            "H, the patch test)"};
  }

  void
  PressureRamp::add_parameters(ParameterHandler         &prm,
                               std::vector<std::string> &declared)
  {
    Subsection s(prm, "Load program", &declared);
    s.add("Reference pressure",
          reference_pressure,
          "1e6",
          "p0 [Pa] of the ramp (p = p0 at t = 1.1).",
          positive());
    s.add("Ramp steps",
          steps,
          "21",
          1,
          LoadParameters::max_steps,
          "Number of steps of the ramp.");
    s.add("Time step",
          time_step,
          "0.1",
          "dt of the ramp [pseudo-time].",
          positive());
  }

  // The last pressure of the ramp, p0 10^(n dt - 1.1), must be a number.
  // Named: the pressure itself when it is beyond reason on its own (over
  // 1e99 Pa), else the time step that ramps it too far. The test is written
  // in logarithms, so that it cannot overflow itself.
  void
  PressureRamp::finish() const
  {
    require(std::log10(reference_pressure) + steps * time_step - 1.1 < 100,
            "Load program",
            reference_pressure >= 1e99 ? "Reference pressure" : "Time step",
            "makes the last pressure of the ramp, p0 10^(n dt - 1.1), "
            "exceed 1e100 Pa (p0 = " +
              to_text(reference_pressure) + " Pa, n = " +
              std::to_string(steps) + ", dt = " + to_text(time_step) + ")");
  }

  // p(t) = p0 10^(t - 1.1); the first step starts from zero load, so within
  // it (0 < t < dt, only reached when it is cut) p grows linearly to p(dt).
  // The exponential never reaches zero (it is p0 10^-1.1 at t = 0): without
  // the linear start a cut first step would begin with a jump of the load.
  // The rotation is named, and 0: the rings read it in either program.
  LoadProgram
  PressureRamp::program() const
  {
    std::vector<double> times;
    for (unsigned int step = 1; step <= steps; ++step)
      times.push_back(step * time_step);
    const double p0 = reference_pressure, dt = time_step;
    return LoadProgram(times, [p0, dt](const double t) {
      const double p = p0 * std::pow(10.0, std::max(t, dt) - 1.1);
      return LoadState{t,
                       {{"pressure", t < dt ? p * t / dt : p},
                        {"rotation", 0.0}}};
    });
  }

  // @sect4{The probe and the whole}

  void
  ReferencePressureEntries::add_parameters(ParameterHandler         &prm,
                                           std::vector<std::string> &declared)
  {
    ramp.add_parameters(prm, declared);
    checks.add_parameters(prm, declared);
    // (0.6, 0) is node A of the seed rings, and also lies on the patch
    // test's interface. The rings replace it by (R2, 0) when the file does
    // not set the entry, and each scenario checks that the point is near its
    // slave surface, since the nearest slave node is used whatever the
    // distance.
    Subsection s(prm, "Contact", &declared);
    s.add("Probe point",
          "0.6, 0",
          Patterns::List(Patterns::Double(), 2, 3),
          "Reference position [m] of the probe, the slave node "
          "whose pressure is reported (the nearest slave node is "
          "used): x, y in 2D, x, y, z in 3D. Not set: node A at (R2, 0) "
          "for any interface radius; the centre of the 3D patch test's "
          "interface. "
          "The rings and the patch test only: a general problem reports "
          "the quantities of its Check subsections.",
          [this](const std::string &text) {
            probe = coordinates_from_text(text, "Contact", "Probe point");
          });
  }

  template <int spacedim>
  Point<spacedim>
  ReferencePressureEntries::probe_point() const
  {
    require(probe.size() == spacedim,
            "Contact",
            "Probe point",
            "has " + std::to_string(probe.size()) +
              " coordinates: a point of a " + std::to_string(spacedim) +
              "D problem has " + std::to_string(spacedim) + " (" +
              (spacedim == 2 ? "x, y" : "x, y, z") + ")");
    Point<spacedim> x;
    for (unsigned int d = 0; d < spacedim; ++d)
      x[d] = probe[d];
    return x;
  }

  template Point<2>
  ReferencePressureEntries::probe_point<2>() const;
  template Point<3>
  ReferencePressureEntries::probe_point<3>() const;
} // namespace RingContact
