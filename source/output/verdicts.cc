// @sect3{Verdicts: the checks of a run}
//
// A run ends by judging itself, as Code_Aster's test cases do with
// TEST_RESU: each checked quantity (the pressure at A against Lame's
// closed form, a general problem's checks against their reference
// expressions) at the steps asked for, against a tolerance. The scenarios
// make the verdicts (scenario.h); this file shows them, as the table the
// run prints and as verdicts.csv for the report's scripts, and the table's
// outcome becomes the run's exit code.
#include <ring_contact/output/output_folder.h>
#include <ring_contact/output/progress.h>
#include <ring_contact/output/verdicts.h>

#include <algorithm>
#include <iomanip>
#include <set>
#include <sstream>

namespace RingContact
{
  // The verdict table, after Code_Aster's TEST_RESU: each check's value,
  // reference, whether the error is relative or absolute, the error and the
  // tolerance in a form that shows small numbers (1.00e-08, not 0.0000 %),
  // the kind of reference, and the verdict. At most 132 columns.
  bool
  print_verdicts(std::ostream &out, const std::vector<Verdict> &verdicts)
  {
    // A file without checks passes (its run succeeds if its steps do), and
    // says so rather than print an empty table.
    if (verdicts.empty())
      {
        out << "\nChecks: none\n";
        return true;
      }
    // The table's cells first, then each column as wide as its widest
    // cell: a quantity as long as "tangential traction at (0.3, 0)" fits
    // within 132 columns beside the rest (fixed widths once pushed such a
    // row to 136). Scheme, quantity and the words left-aligned, numbers
    // right-aligned, two spaces between columns.
    const std::vector<std::string> header = {"scheme",
                                             "quantity",
                                             "step",
                                             "value",
                                             "reference",
                                             "error is",
                                             "error",
                                             "tolerance",
                                             "source",
                                             "verdict"};
    const std::vector<bool>        left   = {
               true, true, false, false, false, true, false, false, true, true};
    std::vector<std::vector<std::string>> rows;
    bool                                  all_pass = true;
    for (const auto &v : verdicts)
      {
        // A step not reached has no value, reference or error: "-".
        // Otherwise seven digits for value and reference, three for error
        // and tolerance, whose sign as a fixed percentage (0.0000 %) flipped
        // with round-off between runs.
        const bool none       = std::isnan(v.value) && std::isnan(v.error);
        const auto scientific = [](const double x) {
          std::ostringstream text;
          text << std::scientific << std::setprecision(2) << x;
          return text.str();
        };
        rows.push_back({v.scheme,
                        v.quantity,
                        std::to_string(v.step),
                        none ? "-" : format_number(v.value),
                        none ? "-" : format_number(v.reference),
                        none ? "" : (v.relative ? "relative" : "absolute"),
                        none ? "-" : scientific(v.error),
                        scientific(v.tolerance),
                        v.source.empty() ? "-" : v.source,
                        v.pass ? "PASS" : "FAIL"});
        all_pass = all_pass && v.pass;
      }
    std::vector<std::size_t> widths;
    for (unsigned int c = 0; c < header.size(); ++c)
      {
        widths.push_back(header[c].size());
        for (const auto &row : rows)
          widths[c] = std::max(widths[c], row[c].size());
      }
    const auto print_row = [&](const std::vector<std::string> &cells) {
      std::string line;
      for (unsigned int c = 0; c < cells.size(); ++c)
        {
          const std::string padding(widths[c] - cells[c].size(), ' ');
          line += (c == 0 ? "" : "  ") +
                  (left[c] ? cells[c] + padding : padding + cells[c]);
        }
      // The last column's padding is not kept.
      out << line.substr(0, line.find_last_not_of(' ') + 1) << '\n';
    };
    out << "\nChecks\n";
    print_row(header);
    for (const auto &row : rows)
      print_row(row);
    unsigned int n_pass = 0;
    for (const auto &v : verdicts)
      n_pass += v.pass;
    out << n_pass << " of " << verdicts.size() << " checks pass\n";
    // A reference expression that gives no number (sqrt(t - 2) at t = 1)
    // fails its check: say so, once per quantity.
    std::set<std::string> said;
    for (const auto &v : verdicts)
      if (!std::isfinite(v.reference) && said.insert(v.quantity).second)
        out << "Note: the reference of '" << v.quantity
            << "' is not a finite number at step " << v.step << " ("
            << (std::isnan(v.reference) ? "nan" :
                v.reference > 0         ? "inf" :
                                          "-inf")
            << "): check its expression\n";
    return all_pass;
  }


  namespace
  {
    // The same fields as the table, at ten digits; a step not reached
    // keeps its nan value and error here, which a CSV reader parses as
    // numbers, where the table shows "-".
    std::string
    verdicts_csv(const std::vector<Verdict> &verdicts)
    {
      // A field with a comma or a quote ("pressure at (0, 0)") in quotes, its
      // quotes doubled (RFC 4180), so that a CSV reader sees one field.
      const auto field = [](const std::string &text) {
        if (text.find_first_of(",\"\n") == std::string::npos)
          return text;
        std::string quoted = "\"";
        for (const char c : text)
          quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
        return quoted + "\"";
      };
      std::ostringstream out;
      out << "scheme,quantity,step,value,reference,error,tolerance,error_is,"
             "reference_is,verdict\n";
      out << std::setprecision(10);
      for (const auto &v : verdicts)
        out << field(v.scheme) << ',' << field(v.quantity) << ',' << v.step
            << ',' << v.value << ',' << v.reference << ',' << v.error << ','
            << v.tolerance << ',' << (v.relative ? "relative" : "absolute")
            << ',' << field(v.source) << ',' << (v.pass ? "PASS" : "FAIL")
            << '\n';
      return out.str();
    }

  } // namespace

  // Written after each scheme with the verdicts of all the schemes done so
  // far, replacing the last file whole: a run stopped in a later scheme
  // keeps the verdicts of the earlier ones.
  void
  write_verdicts(const std::string          &filename,
                 const std::vector<Verdict> &verdicts)
  {
    write_file_atomically(filename, verdicts_csv(verdicts));
  }

} // namespace RingContact
