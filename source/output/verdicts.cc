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
#include <ring_contact/output/verdicts.h>

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
    // Fixed widths: scheme and quantity left-aligned, numbers
    // right-aligned, so that the columns of a long table line up.
    bool all_pass = true;
    out << "\nChecks\n"
        << std::left << std::setw(18) << "scheme" << std::setw(22) << "quantity"
        << std::right << std::setw(5) << "step" << std::setw(15) << "value"
        << std::setw(15) << "reference"
        << "  " << std::left << std::setw(8) << "error is" << std::right
        << std::setw(11) << "error" << std::setw(11) << "tolerance"
        << "  " << std::left << std::setw(13) << "reference is"
        << "verdict\n";
    for (const auto &v : verdicts)
      {
        // A step not reached has no value, reference or error: "-".
        // Otherwise seven digits for value and reference, three for error
        // and tolerance, whose sign as a fixed percentage (0.0000 %) flipped
        // with round-off between runs.
        const bool none = std::isnan(v.value) && std::isnan(v.error);
        out << std::left << std::setw(18) << v.scheme << std::setw(22)
            << v.quantity << std::right << std::setw(5) << v.step
            << std::setprecision(7) << std::setw(15);
        if (none)
          out << "-" << std::setw(15) << "-"
              << "  " << std::left << std::setw(8) << "" << std::right
              << std::setw(11) << "-";
        else
          out << v.value << std::setw(15) << v.reference << "  " << std::left
              << std::setw(8) << (v.relative ? "relative" : "absolute")
              << std::right << std::scientific << std::setprecision(2)
              << std::setw(11) << v.error;
        out << std::scientific << std::setprecision(2) << std::setw(11)
            << v.tolerance << std::defaultfloat << "  " << std::left
            << std::setw(13) << (v.source.empty() ? "-" : v.source)
            << (v.pass ? "PASS" : "FAIL") << std::right << '\n';
        all_pass = all_pass && v.pass;
      }
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
