// @sect3{What a scenario with a reference pressure reports}
//
// The rings and the patch test know the exact contact pressure everywhere on
// the slave surface, the rings' closed form and the patch test's uniform p,
// and they report and check the same quantities: the pressure at the probe node
// (node A of the rings) against that reference, the relative L2 error over the
// slave surface, the extreme nodal pressures, and with friction the tangential
// traction at the probe and the number of sliding nodes. They are written once
// here and each scenario passes its reference. A general problem, whose
// references are expressions given per check, has its own quantities
// (scenarios/general/quantities.cc).
#include <ring_contact/scenarios/reference_pressure.h>

#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

namespace RingContact
{
  namespace ReferencePressure
  {
    // @sect4{The columns and the step's line}
    //
    // The scenario's columns of history.csv. 'load_factor' holds the load
    // state's pressure p in Pa (the ramp's p(t), the rotation's constant p),
    // 'rotation' the rotation parameter s in elements; 'analytic' is the
    // reference pressure, and the errors are relative to it.
    std::vector<std::string>
    columns()
    {
      return {"load_factor",
              "rotation",
              "pressure_A",
              "analytic",
              "relative_error",
              "l2_relative_error",
              "pressure_min",
              "pressure_max"};
    }

    // The extremes over every contact node, open ones included: an open
    // node's zero pressure belongs in the spread, which it makes large under
    // a load that should close the whole surface.
    template <int dim>
    std::pair<double, double>
    pressure_extremes(const SolutionState<dim> &state)
    {
      double lowest  = std::numeric_limits<double>::max();
      double highest = -std::numeric_limits<double>::max();
      for (const auto node : state.contact_nodes())
        {
          lowest  = std::min(lowest, state.reported_pressure(node));
          highest = std::max(highest, state.reported_pressure(node));
        }
      return {lowest, highest};
    }

    template <int dim>
    void
    report(const SolutionState<dim> &state,
           const Point<dim>         &probe,
           const double              reference,
           const PressureMeasure     measure,
           std::vector<NamedValue>  &into)
    {
      // The pressure is a nodal unknown, so node A is the contact node nearest
      // to the probe point, over every pair. Its pressure and the extremes are
      // in the measure Contact/Reported pressure chooses (Cauchy or nominal),
      // the same in which the L2 error is taken.
      const double pressure_A =
        state.reported_pressure(state.contact_node_nearest_to(probe));
      const auto [lowest, highest] = pressure_extremes(state);
      // The L2 error over the slave surface of the first pair: the rings and
      // the patch test have one pair. One number serves as the reference along
      // the whole surface because both exact pressures are uniform on it (the
      // rings' does not depend on the angle).
      const double l2 = state.contact_interfaces().front()->l2_relative_error(
        state.get_solution(), reference, measure);
      // The error at A keeps its sign, so that a history shows on which side of
      // the reference the pressure lies; the checks take its magnitude.
      into.insert(into.end(),
                  {{"load_factor", state.load_state()("pressure")},
                   {"rotation", state.load_state()("rotation")},
                   {"pressure_A", pressure_A},
                   {"analytic", reference},
                   {"relative_error", (pressure_A - reference) / reference},
                   {"l2_relative_error", l2},
                   {"pressure_min", lowest},
                   {"pressure_max", highest}});
    }

    // The load p and the rotation s say where the load program is; p_A
    // against the analytic value is what the checks look at. The analytic
    // value is the first column left out of a line that would be too wide
    // (the error says how far p_A is from it).
    std::vector<StepField>
    step_fields(const HistoryRow &row)
    {
      std::vector<StepField> fields = {
        {"p", format_number(row.value("load_factor"), 6), 11},
        {"s", format_number(row.value("rotation"), 3), 5},
        {"p_A", format_number(row.value("pressure_A")), 12},
        {"analytic", format_number(row.value("analytic")), 12, 3}};
      // Errors relative to a zero analytic pressure (an input as soft as
      // E = 1e-300 gives one) have no meaning: said so, not inf or nan.
      const double relative = row.value("relative_error"),
                   l2       = row.value("l2_relative_error");
      const auto percent    = [](const double value) {
        if (!std::isfinite(value))
          return std::string("n/a");
        std::ostringstream text;
        text << std::fixed << std::setprecision(3) << 100 * value << '%';
        return text.str();
      };
      fields.push_back({"error", percent(relative), 8});
      fields.push_back({"L2", percent(l2), 7});
      return fields;
    }

    // A converged state with every node open under a load that closes the
    // contact solves the discrete equations but is not the solution sought:
    // modelisation F at finite strain once converged to such a state (p_A = 0,
    // -100 %), and nothing but its failed checks said so. The warning names the
    // step.
    void
    warn_if_open(std::ostream &out, const HistoryRow &row)
    {
      const double analytic = row.value("analytic");
      if (analytic > 0 && row.active_nodes == 0)
        out << "Warning: step " << row.step
            << ": Newton converged with the contact open at every node, "
               "while the analytic solution is closed contact (pressure "
            << analytic << ")\n";
    }

    // @sect4{The checks}
    //
    // The quantity of Checks/Quantity on the checked steps. The pressure at A
    // is compared relatively with the reference, as the original's TEST_RESU
    // does. The spread and the L2 error are relative to the reference already,
    // so their reference is 0 and their error absolute: the verdict table says
    // which. A checked step the run did not reach fails (for_checked_rows()).
    std::vector<Verdict>
    evaluate_checks(const CheckParameters         &checks,
                    const std::string             &scheme,
                    const std::vector<HistoryRow> &history,
                    const unsigned int             n_steps)
    {
      std::vector<Verdict> verdicts;
      const auto           check_row = [&](const HistoryRow &row) {
        Verdict v;
        v.scheme    = row.scheme;
        v.step      = row.step;
        v.tolerance = checks.tolerance;
        // Against the reference pressure (the rings' closed form): the
        // pressure itself, or the spread and the L2 error relative to it.
        v.source = "closed form";
        if (checks.quantity == CheckedQuantity::pressure_at_A)
          {
            v.quantity  = "pressure at A";
            v.value     = row.value("pressure_A");
            v.reference = row.value("analytic");
            v.error     = row.value("relative_error");
          }
        else if (checks.quantity == CheckedQuantity::pressure_spread)
          {
            v.quantity = "pressure spread";
            v.value = (row.value("pressure_max") - row.value("pressure_min")) /
                      row.value("analytic");
            v.reference = 0;
            v.error     = v.value;
            v.relative  = false;
          }
        else
          {
            v.quantity  = "L2 error of pressure";
            v.value     = row.value("l2_relative_error");
            v.reference = 0;
            v.error     = v.value;
            v.relative  = false;
          }
        v.pass = std::isfinite(v.error) && std::abs(v.error) <= v.tolerance;
        verdicts.push_back(v);
      };
      for_checked_rows(checks.every_step,
                       checks.steps,
                       history,
                       n_steps,
                       check_row,
                       scheme,
                       checks.tolerance,
                       verdicts);
      return verdicts;
    }
  } // namespace ReferencePressure

  // @sect4{With friction}
  //
  // The tangential traction at the probe node is the multiplier's coefficient
  // there, read from the solution: a Cauchy traction on the unit tangent tau
  // = e_z x n of the master's normal (with the dual basis of Gauss and
  // segment-based schemes, its weighted mean about the node), whatever
  // Contact/Reported pressure says of the normal pressure. The sliding nodes
  // are counted over every pair: the state of the stick-slip active set at the
  // converged step.
  namespace Friction
  {
    std::vector<std::string>
    columns()
    {
      return {"tangential_traction_A", "slipping_nodes"};
    }

    template <int dim>
    unsigned int
    n_slipping(const SolutionState<dim> &state)
    {
      unsigned int n = 0;
      for (const ContactInterface<dim> *contact : state.contact_interfaces())
        n += contact->active_set().n_slipping();
      return n;
    }

    template <int dim>
    void
    report(const SolutionState<dim> &state,
           const Point<dim>         &probe,
           std::vector<NamedValue>  &into)
    {
      const auto node = state.contact_node_nearest_to(probe);
      into.insert(into.end(),
                  {{"tangential_traction_A",
                    state.get_solution()(
                      state.contact_of(node).nodes().tangential_dof(node))},
                   {"slipping_nodes", static_cast<double>(n_slipping(state))}});
    }

    std::vector<StepField>
    step_fields(const HistoryRow &row)
    {
      return {{"q_A", format_number(row.value("tangential_traction_A")), 12, 1},
              {"sliding", format_number(row.value("slipping_nodes")), 7, 2}};
    }
  } // namespace Friction


  // @sect4{The scenarios checked against a reference pressure}

  template <int dim>
  std::vector<std::string>
  ReferencePressureScenario<dim>::leading_columns() const
  {
    return ReferencePressure::columns();
  }

  template <int dim>
  std::vector<std::string>
  ReferencePressureScenario<dim>::trailing_columns() const
  {
    if (run_parameters().contact.frictional())
      return Friction::columns();
    return {};
  }

  template <int dim>
  void
  ReferencePressureScenario<dim>::report(const SolutionState<dim> &state,
                                         HistoryRow               &row) const
  {
    const Parameters &parameters = run_parameters();
    const Point<dim>  probe      = reference_entries().template probe_point<dim>();
    ReferencePressure::report(state,
                              probe,
                              reference_pressure(state.load_state()),
                              parameters.contact.reported_pressure,
                              row.leading);
    if (parameters.contact.frictional())
      Friction::report(state, probe, row.trailing);
  }

  template <int dim>
  std::vector<StepField>
  ReferencePressureScenario<dim>::step_fields(const HistoryRow &row) const
  {
    auto fields = ReferencePressure::step_fields(row);
    if (run_parameters().contact.frictional())
      for (auto &field : Friction::step_fields(row))
        fields.push_back(field);
    return fields;
  }

  template <int dim>
  void
  ReferencePressureScenario<dim>::warn(std::ostream     &out,
                                       const HistoryRow &row) const
  {
    ReferencePressure::warn_if_open(out, row);
  }

  template <int dim>
  std::vector<Verdict>
  ReferencePressureScenario<dim>::evaluate_checks(
    const std::string             &scheme,
    const std::vector<HistoryRow> &history) const
  {
    return ReferencePressure::evaluate_checks(reference_entries().checks,
                                              scheme,
                                              history,
                                              this->load_program().n_steps());
  }
  // The scenarios of both dimensions (the patch test has both); the count
  // of sliding nodes for the general problem as well.
  template unsigned int
  Friction::n_slipping(const SolutionState<2> &);
  template class ReferencePressureScenario<2>;
  template class ReferencePressureScenario<3>;
} // namespace RingContact
