// @sect3{The progress of a run}
//
// A run of minutes must say where it is, as the tools people use do (a
// solver's status file, a progress bar): which step of how many, how hard
// Newton worked, the quantity the run is checked on, the time spent and
// the time left. One line per converged step, under a header that names
// the columns, at most 132 characters wide: a line that wraps in a
// terminal or a CI log is a line nobody reads. The residual of every
// Newton iteration is detail for whoever studies the convergence
// (Newton/Verbose).
#include <ring_contact/output/progress.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace RingContact
{
  std::string
  format_number(const double value, const int digits)
  {
    std::ostringstream text;
    text << std::setprecision(digits) << value;
    return text.str();
  }

  // Two significant figures below a minute, then minutes and seconds,
  // then hours and minutes: the precision a person plans with.
  std::string
  format_duration(const double seconds)
  {
    if (!std::isfinite(seconds) || seconds < 0)
      return "?";
    std::ostringstream text;
    if (seconds < 10)
      text << std::fixed << std::setprecision(1) << seconds << "s";
    else if (seconds < 60)
      text << std::lround(seconds) << "s";
    else if (seconds < 3600)
      {
        const long s = std::lround(seconds);
        text << s / 60 << "m" << std::setw(2) << std::setfill('0') << s % 60
             << "s";
      }
    else
      {
        const long m = std::lround(seconds / 60);
        text << m / 60 << "h" << std::setw(2) << std::setfill('0') << m % 60
             << "m";
      }
    return text.str();
  }

  // Greedy, word by word; a word longer than the line stays whole.
  std::string
  wrap_text(const std::string &text,
            const unsigned int width,
            const unsigned int indent)
  {
    // The text's own indentation is kept on its first line.
    const auto         first_word = text.find_first_not_of(' ');
    std::istringstream words(text);
    std::string        result, word;
    std::string line(first_word == std::string::npos ? 0 : first_word, ' ');
    bool        line_has_words = false;
    while (words >> word)
      {
        if (line_has_words && line.size() + 1 + word.size() > width)
          {
            result += line + "\n";
            line           = std::string(indent, ' ');
            line_has_words = false;
          }
        if (line_has_words)
          line += ' ';
        line += word;
        line_has_words = true;
      }
    return result + line + "\n";
  }


  // Unlike wrap_text(), an entry is never broken ("check 5: contact
  // half-width" stays whole): the legend of a table's columns.
  std::string
  side_by_side(const std::vector<std::string> &entries,
               const unsigned int              width)
  {
    std::string text, line;
    for (const auto &entry : entries)
      {
        if (!line.empty() && line.size() + 3 + entry.size() > width)
          {
            text += line + '\n';
            line.clear();
          }
        line += (line.empty() ? "" : "   ") + entry;
      }
    return line.empty() ? text : text + line + '\n';
  }


  // @sect4{The clock}
  //
  // The time left is the mean time of the steps solved so far in this
  // scheme times the steps left, and each later scheme as long as this one
  // will be: a forecast, printed with a tilde. Steps of one scheme cost
  // about the same (a ramp, a rotation); where they do not (the ironing's
  // sliding steps take more Newton iterations than its pressing ones), the
  // forecast corrects itself as the steps come.
  RunProgress::RunProgress(const unsigned int n_schemes)
      : n_schemes(n_schemes)
      , run_start(Clock::now())
      , scheme_start(run_start)
  {}

  void
  RunProgress::start_scheme(const unsigned int index)
  {
    scheme       = index;
    scheme_start = Clock::now();
  }

  std::string
  RunProgress::scheme_label() const
  {
    if (n_schemes < 2)
      return "";
    return " (" + std::to_string(scheme + 1) + " of " +
           std::to_string(n_schemes) + ")";
  }

  double
  RunProgress::elapsed() const
  {
    return std::chrono::duration<double>(Clock::now() - run_start).count();
  }

  double
  RunProgress::remaining(const unsigned int step,
                         const unsigned int n_steps) const
  {
    if (step == 0 || n_steps == 0)
      return std::nan("");
    const double spent =
      std::chrono::duration<double>(Clock::now() - scheme_start).count();
    const double per_step = spent / step;
    const double later_schemes =
      n_schemes > scheme + 1 ? double(n_schemes - scheme - 1) : 0.0;
    return per_step * (n_steps - step) + later_schemes * per_step * n_steps;
  }


  // @sect4{The table of steps}
  //
  // The first line of a scheme fixes the columns: their widths (the widest
  // of the header, the first value and the field's minimum), and which of
  // them fit. A later value wider than its column widens it, and the header
  // is printed again above that line (leaving out another column if the
  // line would no longer fit): the columns stay aligned under their
  // headers, as in a solver's status file, and no line passes the width.
  void
  StepTable::print(std::ostream &out, const std::vector<StepField> &fields)
  {
    bool layout = widths.size() != fields.size();
    if (layout)
      {
        widths.clear();
        shown.assign(fields.size(), true);
        for (const auto &field : fields)
          widths.push_back(std::max<unsigned int>(
            field.min_width, static_cast<unsigned int>(field.header.size())));
      }
    for (unsigned int i = 0; i < fields.size(); ++i)
      if (shown[i] && fields[i].value.size() > widths[i])
        {
          widths[i] = fields[i].value.size();
          layout    = true;
        }
    if (layout)
      {
        const auto width_of_line = [&]() {
          unsigned int total = 0, n = 0;
          for (unsigned int i = 0; i < fields.size(); ++i)
            if (shown[i])
              {
                total += widths[i];
                ++n;
              }
          return total + 2 * (n - 1);
        };
        // Columns left out, the highest rank first and the last of a rank
        // first, until the line fits.
        unsigned int highest_rank = 0;
        for (const auto &field : fields)
          highest_rank = std::max(highest_rank, field.drop_rank);
        std::string left_out;
        for (unsigned int rank = highest_rank; rank > 0; --rank)
          for (unsigned int i = fields.size();
               i-- > 0 && width_of_line() > max_line_width;)
            if (shown[i] && fields[i].drop_rank == rank)
              {
                shown[i] = false;
                left_out += (left_out.empty() ? "" : ", ") + fields[i].header;
              }
        if (!left_out.empty())
          out << wrap_text("(not on the step lines, to keep them within " +
                           std::to_string(max_line_width) +
                           " columns: " + left_out + "; all in history.csv)");
        out << line_of(fields, true) << '\n';
      }
    out << line_of(fields, false) << '\n';
  }

  // The shown columns' headers or values, right-aligned in their widths.
  std::string
  StepTable::line_of(const std::vector<StepField> &fields,
                     const bool                    headers) const
  {
    std::string line;
    for (unsigned int i = 0; i < fields.size(); ++i)
      if (shown[i])
        {
          const std::string &text =
            headers ? fields[i].header : fields[i].value;
          line += (line.empty() ? "" : "  ") +
                  std::string(widths[i] -
                                std::min<std::size_t>(widths[i], text.size()),
                              ' ') +
                  text;
        }
    return line;
  }
} // namespace RingContact
