// The progress of a run on the terminal: one line per converged step in a
// table whose header names the columns, the time elapsed and an estimate
// of the time left, in at most 132 columns (progress.cc).
#ifndef ring_contact_output_progress_h
#define ring_contact_output_progress_h

#include <chrono>
#include <ostream>
#include <string>
#include <vector>

namespace RingContact
{
  /// The widest line the run prints on its own (a line printer's width;
  /// ParaView, editors and CI logs show it whole).
  constexpr unsigned int max_line_width = 132;

  /// One column of a step's line: its header and its value, already
  /// formatted, and the narrowest the column may be. A line wider than
  /// max_line_width leaves columns out, those of the highest `drop_rank`
  /// first (the last of equal rank first); rank 0 is always shown. What is
  /// left out is in history.csv.
  struct StepField
  {
    std::string  header;
    std::string  value;
    unsigned int min_width = 0;
    unsigned int drop_rank = 0;
  };

  /// A number in `digits` significant digits, as std::ostream's default
  /// format gives it ("91957.91", "1.157389e+06", "nan").
  std::string
  format_number(const double value, const int digits = 7);

  /// A duration for a person: "0.4s", "12s", "2m05s", "1h02m".
  std::string
  format_duration(const double seconds);

  /// `text` broken at spaces into lines of at most `width` characters, the
  /// lines after the first indented by `indent` spaces; each line ends in a
  /// newline.
  std::string
  wrap_text(const std::string &text,
            const unsigned int width  = max_line_width,
            const unsigned int indent = 4);

  /// `entries` side by side, three spaces apart, as many on a line as fit
  /// within `width`; each line ends in a newline ("" for no entries).
  std::string
  side_by_side(const std::vector<std::string> &entries,
               const unsigned int              width = max_line_width);

  /// The clock of a run of several schemes: the time since the run
  /// started, and the time left estimated from the steps solved so far in
  /// the current scheme (each later scheme counted as long as this one).
  class RunProgress
  {
  public:
    explicit RunProgress(const unsigned int n_schemes = 1);

    /// A new scheme starts its steps (its set-up is done): `index` counts
    /// from 0.
    void
    start_scheme(const unsigned int index);

    /// " (2 of 3)" in a run of several schemes, "" in a run of one.
    std::string
    scheme_label() const;

    /// Seconds since the run started.
    double
    elapsed() const;

    /// Seconds left after `step` of `n_steps` of the current scheme.
    double
    remaining(const unsigned int step, const unsigned int n_steps) const;

  private:
    using Clock = std::chrono::steady_clock;
    const unsigned int n_schemes;
    unsigned int       scheme = 0;
    Clock::time_point  run_start, scheme_start;
  };

  /// The step lines of one scheme: the header before the first line (and
  /// again where a value widens its column), the columns that do not fit
  /// within max_line_width left out (and named).
  class StepTable
  {
  public:
    void
    print(std::ostream &out, const std::vector<StepField> &fields);

    /// Whether the header has been printed.
    bool
    started() const
    {
      return !widths.empty();
    }

  private:
    std::string
    line_of(const std::vector<StepField> &fields, const bool headers) const;

    std::vector<unsigned int> widths;
    std::vector<bool>         shown;
  };
} // namespace RingContact

#endif
