// What the scenarios report of the contact pressure, and the checks of a
// scenario that knows the pressure everywhere on the slave surface (its
// reference pressure: the rings' closed form, the patch test's uniform
// pressure):
// - the pressure at the probe (node A of the rings), the reference, the
//   relative error there, the relative L2 error over the slave surface and
//   the extreme pressures: the rings' columns of history.csv;
// - with friction, the tangential traction at the probe and the number of
//   nodes that slide;
// - the checks of subsection Checks against the reference.
#ifndef ring_contact_scenarios_reference_pressure_h
#define ring_contact_scenarios_reference_pressure_h

#include <deal.II/base/point.h>

#include <ring_contact/input/parameters.h>
#include <ring_contact/output/history.h>
#include <ring_contact/output/verdicts.h>
#include <ring_contact/problem/solution_state.h>

#include <ostream>
#include <string>
#include <vector>

namespace RingContact
{
  namespace ReferencePressure
  {
    using namespace dealii;

    /// load_factor (the load state's pressure), rotation, pressure_A,
    /// analytic, relative_error, l2_relative_error, pressure_min,
    /// pressure_max.
    std::vector<std::string>
    columns();

    /// Their values at a state: the pressure at the contact node nearest to
    /// `probe` against `reference` (NaN: none known), reported as
    /// `measure` says.
    void
    report(const SolutionState     &state,
           const Point<2>          &probe,
           const double             reference,
           const PressureMeasure    measure,
           std::vector<NamedValue> &into);

    /// The rings' part of the step's line: the load, the Newton
    /// iterations, the pressure at A against the analytic one, the errors.
    void
    print_step(std::ostream &out, const HistoryRow &row);

    /// A converged state with every contact node open under a load that
    /// closes the contact (reference pressure > 0) is another solution of
    /// the discrete problem, not the one sought: said, it is otherwise
    /// silent.
    void
    warn_if_open(std::ostream &out, const HistoryRow &row);

    /// The checks of subsection Checks over the history of one scheme of
    /// `n_steps` steps.
    std::vector<Verdict>
    evaluate_checks(const CheckParameters         &checks,
                    const std::string             &scheme,
                    const std::vector<HistoryRow> &history,
                    const unsigned int             n_steps);
  } // namespace ReferencePressure

  namespace Friction
  {
    using namespace dealii;

    /// tangential_traction_A, slipping_nodes.
    std::vector<std::string>
    columns();

    /// The tangential traction (Cauchy, the multiplier itself) at the
    /// contact node nearest to `probe`, and the number of sliding nodes.
    void
    report(const SolutionState     &state,
           const Point<2>          &probe,
           std::vector<NamedValue> &into);

    /// "  q_A ...  sliding n".
    void
    print_step(std::ostream &out, const HistoryRow &row);
  } // namespace Friction
} // namespace RingContact

#endif
