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

#include <ring_contact/base/dimension.h>
#include <ring_contact/input/parameters.h>
#include <ring_contact/output/history.h>
#include <ring_contact/output/verdicts.h>
#include <ring_contact/problem/solution_state.h>
#include <ring_contact/scenarios/reference_pressure_entries.h>
#include <ring_contact/scenarios/scenario.h>

#include <ostream>
#include <string>
#include <utility>
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

    /// The lowest and the highest contact pressure over every contact node
    /// of every pair, open nodes included, in the reported measure.
    template <int dim>
    std::pair<double, double>
    pressure_extremes(const SolutionState<dim> &state);

    /// Their values at a state: the pressure at the contact node nearest to
    /// `probe` against `reference` (NaN: none known), reported as
    /// `measure` says.
    template <int dim>
    void
    report(const SolutionState<dim> &state,
           const Point<dim>         &probe,
           const double              reference,
           const PressureMeasure     measure,
           std::vector<NamedValue>  &into);

    /// The rings' columns of the step's line: the load, the rotation, the
    /// pressure at A against the analytic one, the errors.
    std::vector<StepField>
    step_fields(const HistoryRow &row);

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

    /// The number of sliding nodes over every pair.
    template <int dim>
    unsigned int
    n_slipping(const SolutionState<dim> &state);

    /// The tangential traction (Cauchy, the multiplier itself) at the
    /// contact node nearest to `probe`, and the number of sliding nodes.
    template <int dim>
    void
    report(const SolutionState<dim> &state,
           const Point<dim>         &probe,
           std::vector<NamedValue>  &into);

    /// q_A and the number of sliding nodes, left out before the pressure
    /// when the line is too wide.
    std::vector<StepField>
    step_fields(const HistoryRow &row);
  } // namespace Friction

  /// A scenario checked against a reference pressure that it knows
  /// everywhere on its slave surface (the rings' closed form, the patch
  /// test's uniform p). What it reports, prints, warns about and checks is
  /// the same for all of them, around the reference each gives: the
  /// functions of ReferencePressure and, with friction, of Friction.
  template <int dim>
  class ReferencePressureScenario : public Scenario<dim>
  {
  public:
    /// The pressure columns; the friction ones only with friction (a
    /// frictionless history keeps the columns it had before friction).
    std::vector<std::string>
    leading_columns() const override;
    std::vector<std::string>
    trailing_columns() const override;

    void
    report(const SolutionState<dim> &state, HistoryRow &row) const override;

    std::vector<StepField>
    step_fields(const HistoryRow &row) const override;

    /// A converged state with the contact open everywhere, where the
    /// reference has it closed, is another solution of the discrete
    /// problem: said, since nothing else would say it.
    void
    warn(std::ostream &out, const HistoryRow &row) const override;

    /// The checks of subsection Checks against the reference, over the
    /// load program's steps (not the history's: a run that stopped early
    /// fails the checks of the steps it did not reach).
    std::vector<Verdict>
    evaluate_checks(const std::string             &scheme,
                    const std::vector<HistoryRow> &history) const override;

  protected:
    /// The reference pressure at a load state.
    virtual double
    reference_pressure(const LoadState &load) const = 0;

    /// The parameters of the run.
    virtual const Parameters &
    run_parameters() const = 0;

    /// The scenario's ramp, probe and checks.
    virtual const ReferencePressureEntries &
    reference_entries() const = 0;
  };
} // namespace RingContact

#endif
