// The checks of a run turned into verdicts, after Code_Aster's TEST_RESU:
// each checked value against its reference, within a tolerance, at the
// steps asked for; the verdict table the run prints and verdicts.csv. The
// scenarios make the verdicts from their history (scenario.h); a step the
// run did not reach fails its checks.
#ifndef ring_contact_output_verdicts_h
#define ring_contact_output_verdicts_h

#include <deal.II/base/numbers.h>

#include <ring_contact/output/history.h>

#include <cmath>
#include <ostream>
#include <string>
#include <vector>

namespace RingContact
{
  /// One checked value and its outcome.
  struct Verdict
  {
    std::string  scheme;
    std::string  quantity;
    unsigned int step;
    double       value;
    double       reference;
    double       error; ///< relative or absolute, as `relative` says
    double       tolerance;
    bool         pass;
    /// (value - reference) / |reference|, or value - reference.
    bool relative = true;
    /// Where the reference comes from: "closed form", "Code_Aster",
    /// "publication", "other code", or "" (not said).
    std::string source;
  };

  /// Call `check_row(row)` for the rows a check takes: every row (and a
  /// failing "step not reached" after the last one when the run stopped
  /// before `n_steps`), or the rows of the listed `steps`
  /// (numbers::invalid_unsigned_int: the last, `n_steps`), a listed step
  /// never reached failing.
  template <typename CheckRow>
  void
  for_checked_rows(const bool                       every_step,
                   const std::vector<unsigned int> &steps,
                   const std::vector<HistoryRow>   &history,
                   const unsigned int               n_steps,
                   const CheckRow                  &check_row,
                   const std::string               &scheme,
                   const double                     tolerance,
                   std::vector<Verdict>            &verdicts)
  {
    const auto not_reached = [&](const unsigned int step) {
      verdicts.push_back(Verdict{scheme,
                                 "step not reached",
                                 step,
                                 std::nan(""),
                                 0,
                                 std::nan(""),
                                 tolerance,
                                 false,
                                 true,
                                 ""});
    };
    if (every_step)
      {
        for (const auto &row : history)
          check_row(row);
        if (history.empty() || history.back().step < n_steps)
          not_reached(history.empty() ? 1 : history.back().step + 1);
        return;
      }
    for (const unsigned int step : steps)
      {
        const unsigned int wanted =
          step == dealii::numbers::invalid_unsigned_int ? n_steps : step;
        bool found = false;
        for (const auto &row : history)
          if (row.step == wanted)
            {
              check_row(row);
              found = true;
            }
        if (!found)
          not_reached(wanted);
      }
  }

  /// The verdict table; returns true if every check passes.
  bool
  print_verdicts(std::ostream &out, const std::vector<Verdict> &verdicts);

  /// verdicts.csv: one row per check (scheme, quantity, step, value,
  /// reference, error, tolerance, error_is, reference_is, PASS/FAIL), for
  /// reports; replaced atomically (the old or the new file, whole).
  void
  write_verdicts(const std::string          &filename,
                 const std::vector<Verdict> &verdicts);
} // namespace RingContact

#endif
