// @sect3{Checked entries of the parameter file}
//
// The checked declaration of entries (parameter_checks.h): conversion of each
// value with its checks, and the parsers of the entries that hold more than one
// value (steps, assignments, points).
//
// deal.II's ParameterHandler::add_parameter() also binds an entry to a
// variable, but its conversion knows only the pattern: deal.II met 1e-320 (a
// denormal, which Patterns::Double accepts) with its raw exception text, and it
// has no place for a condition such as 'positive' with a message of the
// program's own. Subsection keeps its idiom, one statement per entry and the
// variable set by an action, and adds the checks. Every failure is a
// ParameterError that names subsection and entry in one line; the reader of the
// file, or Parameters::read(), adds the file and line that set the value.
#include <deal.II/base/numbers.h>
#include <deal.II/base/utilities.h>

#include <ring_contact/base/dimension.h>
#include <ring_contact/base/utilities.h>
#include <ring_contact/input/parameter_checks.h>
#include <ring_contact/input/parameter_file.h>

#include <cctype>
#include <cmath>
#include <sstream>

namespace RingContact
{
  namespace ParameterChecks
  {
    // @sect4{Messages and conditions}
    //
    // A number in a message as a stream writes it, six significant digits:
    // '1e+06', '0.5', short and close enough to find the value in the file.
    std::string
    to_text(const double value)
    {
      std::ostringstream out;
      out << value;
      return out.str();
    }

    // Throw a one-line error that names the entry, when `ok` is false
    // (Parameters::read() adds the file and line that set the value). The
    // message starts with the entry, and the caller's `what` ('must be
    // positive', 'names a file that does not exist') continues the sentence.
    void
    require(const bool         ok,
            const std::string &subsection,
            const std::string &entry,
            const std::string &what)
    {
      if (!ok)
        throw ParameterError(subsection,
                             entry,
                             "parameter '" + entry + "' in subsection '" +
                               subsection + "' " + what);
    }

    // x > 0 cannot be a bound of Patterns::Double, whose bounds are inclusive:
    // it is a condition, checked by the action with the value in the message.
    Condition
    positive(const std::string &what)
    {
      return {[](const double x) { return x > 0; }, what};
    }

    // x >= 0 can: the pattern's lower bound 0 refuses a negative value before
    // the action runs and shows the range in the reference, so the condition
    // needs no test of its own.
    Condition
    not_negative()
    {
      return {nullptr, "", 0};
    }

    // The value of an entry as a finite double. The pattern has accepted
    // the text, but e.g. 1e-320 (a denormal) or 1e999 still cannot be
    // converted by deal.II: say so, naming the entry and the value. The limits
    // keep every input a normal double with all its digits (a denormal has lost
    // some) and well away from overflow in the first products it enters.
    double
    number_from_text(const std::string &text,
                     const std::string &subsection,
                     const std::string &entry)
    {
      double value = 0;
      bool   ok    = true;
      try
        {
          // string_to_double() throws on text it cannot read whole; the catch
          // gives that the same message as a value out of range.
          value = Utilities::string_to_double(text);
        }
      catch (...)
        {
          ok = false;
        }
      require(ok && std::isfinite(value) &&
                (value == 0 ||
                 (std::abs(value) >= 1e-300 && std::abs(value) <= 1e300)),
              subsection,
              entry,
              "has the value '" + printable(text) +
                "', which is not a usable number (a floating-point number "
                "between 1e-300 and 1e300 in magnitude, or 0)");
      return value;
    }

    // @sect4{One statement per entry}
    //
    // The subsection is entered for the lifetime of the object: the entries
    // added meanwhile are declared in it, and the destructor leaves it on every
    // way out of an add_parameters() function.
    Subsection::Subsection(ParameterHandler         &prm,
                           const std::string        &name,
                           std::vector<std::string> *declared)
        : name(name)
        , prm(prm)
        , declared(declared)
    {
      prm.enter_subsection(name);
    }

    Subsection::~Subsection()
    {
      prm.leave_subsection();
    }

    void
    Subsection::add(const std::string           &entry,
                    const std::string           &default_value,
                    const Patterns::PatternBase &pattern,
                    const std::string           &documentation,
                    const std::function<void(const std::string &)> &read)
    {
      prm.declare_entry(entry, default_value, pattern, documentation);
      // Run on the default now, and on every value the file sets. deal.II
      // checks a value against the pattern before the action runs; the action
      // converts it, checks it and stores it, and what it throws stops the
      // reading at that line, which the reader reports with the file's name and
      // the line's number. Running on the default means the variable holds a
      // valid value from its declaration on, whether the file sets the entry or
      // not.
      prm.add_action(entry, read);
      // A scenario's own entries are recorded (Parameters::readers), so that a
      // file that chooses another scenario and sets them is refused.
      if (declared != nullptr)
        declared->push_back(name + "/" + entry);
    }

    void
    Subsection::add(const std::string &entry,
                    double            &variable,
                    const std::string &default_value,
                    const std::string &documentation,
                    const Condition   &condition)
    {
      // The action runs while the file is read, after this Subsection is gone:
      // it holds copies of the names and the condition, and a reference only to
      // the variable, a member of the Parameters that outlives the handler. The
      // pattern carries only the condition's lower bound, which the reference
      // shows; the action refuses what the pattern lets through but is no
      // usable number, and what fails the condition, with the value.
      const std::string section = name;
      add(entry,
          default_value,
          Patterns::Double(condition.lowest),
          documentation,
          [&variable, section, entry, condition](const std::string &text) {
            const double value = number_from_text(text, section, entry);
            require(!condition.holds || condition.holds(value),
                    section,
                    entry,
                    condition.what + ", got " + to_text(value));
            variable = value;
          });
    }

    void
    Subsection::add(const std::string &entry,
                    unsigned int      &variable,
                    const std::string &default_value,
                    const int          lowest,
                    const int          highest,
                    const std::string &documentation)
    {
      // The range is the pattern's: deal.II refuses a value outside it (a
      // negative one too) before the action, whose conversion then cannot fail,
      // and the reference prints the range.
      add(entry,
          default_value,
          Patterns::Integer(lowest, highest),
          documentation,
          [&variable](const std::string &text) {
            variable = Utilities::string_to_int(text);
          });
    }

    void
    Subsection::add(const std::string &entry,
                    bool              &variable,
                    const std::string &default_value,
                    const std::string &documentation)
    {
      // Patterns::Bool is the selection 'true|false': the action sees one of
      // the two words ('yes' cannot pass the pattern).
      add(entry,
          default_value,
          Patterns::Bool(),
          documentation,
          [&variable](const std::string &text) {
            variable = (text == "true" || text == "yes");
          });
    }

    void
    Subsection::add(const std::string           &entry,
                    std::string                 &variable,
                    const std::string           &default_value,
                    const std::string           &documentation,
                    const Patterns::PatternBase &pattern)
    {
      // Stored as written: what the text must be is checked by whoever reads it
      // (Mesh file by MeshParameters::finish(), Problem/Scenario by its
      // Selection of the registered names).
      add(entry,
          default_value,
          pattern,
          documentation,
          [&variable](const std::string &text) { variable = text; });
    }

    // @sect4{Entries of several values}
    //
    // 'name = value' lists ('Geo parameters', Problem/Constants), lists of
    // steps and points: each item checked on its own, and the message quotes
    // the item at fault rather than the whole line.
    namespace
    {
      // The items of a list separated by commas, each trimmed, split only
      // at the commas outside parentheses: min(a, b) and atan2(y, x) are
      // one value. Otherwise as deal.II's split_string_list(), which was
      // used before and split them: a last empty item (a trailing comma)
      // is dropped. A parenthesis that is never closed keeps the rest of
      // the text in its item, whose value then fails its own check with
      // the parser's reason; one closed too often counts as none.
      std::vector<std::string>
      split_at_top_level_commas(const std::string &text)
      {
        std::vector<std::string> items;
        std::string              item;
        unsigned int             depth = 0;
        for (const char c : text)
          {
            if (c == '(')
              ++depth;
            else if (c == ')' && depth > 0)
              --depth;
            if (c == ',' && depth == 0)
              {
                items.push_back(Utilities::trim(item));
                item.clear();
              }
            else
              item += c;
          }
        items.push_back(Utilities::trim(item));
        if (items.size() > 1 && items.back().empty())
          items.pop_back();
        return items;
      }
    } // namespace

    std::vector<std::pair<std::string, std::string>>
    get_assignments(const std::string &text,
                    const std::string &subsection,
                    const std::string &entry,
                    const std::string &example,
                    const std::string &kind_of_name,
                    const bool         leading_letter)
    {
      std::vector<std::pair<std::string, std::string>> items;
      // An empty entry assigns nothing: the script's own values, no constants.
      if (Utilities::trim(text).empty())
        return items;
      const auto fail = [&](const std::string &what) {
        require(false, subsection, entry, what);
      };
      // Items are split at the commas outside parentheses: a value may be
      // an expression of a function of two arguments.
      for (const std::string &item : split_at_top_level_commas(text))
        {
          const std::size_t equal = item.find('=');
          if (equal == std::string::npos)
            fail("holds '" + printable(item) + "', not 'name = value' (e.g. '" +
                 example + "')");
          const std::string   name  = Utilities::trim(item.substr(0, equal));
          const std::string   value = Utilities::trim(item.substr(equal + 1));
          const unsigned char first =
            name.empty() ? '0' : static_cast<unsigned char>(name[0]);
          // gmsh's variable names may start with _, the constants of a general
          // problem must start with a letter; neither may start with a digit.
          bool identifier = leading_letter ? std::isalpha(first) != 0 :
                                             std::isdigit(first) == 0;
          for (const char c : name)
            identifier =
              identifier &&
              (std::isalnum(static_cast<unsigned char>(c)) || c == '_');
          if (!identifier)
            fail("holds the name '" + printable(name) + "', which is not " +
                 kind_of_name);
          // A name given twice is refused, rather than the later value silently
          // winning.
          for (const auto &earlier : items)
            if (earlier.first == name)
              fail("gives '" + name + "' twice");
          // The value is returned as text: what it must be (a number for gmsh,
          // an expression of the constants before it) is the caller's to check.
          items.emplace_back(name, value);
        }
      return items;
    }

    // 'last' is stored as invalid_unsigned_int: the number of steps is the load
    // program's, not known here, and for_checked_rows() (output/verdicts.h)
    // takes it as the last one.
    void
    steps_from_text(const std::string         &text,
                    const std::string         &subsection,
                    const std::string         &entry,
                    bool                      &every_step,
                    std::vector<unsigned int> &steps)
    {
      const std::string steps_text = Utilities::trim(text);
      require(!steps_text.empty(),
              subsection,
              entry,
              "is empty: give 'all', 'last', 'none' (no checks) or step "
              "numbers");
      every_step = (steps_text == "all");
      steps.clear();
      if (steps_text == "last")
        steps.push_back(numbers::invalid_unsigned_int);
      else if (!every_step && steps_text != "none")
        {
          for (const auto &s : Utilities::split_string_list(steps_text))
            {
              // A signed number, so that '-1' is refused by the range instead
              // of wrapping round to a large unsigned step; 100000 is the most
              // steps a load program has (LoadParameters::max_steps).
              long n = 0;
              try
                {
                  n = Utilities::string_to_int(s);
                }
              catch (...)
                {
                  n = 0;
                }
              require(n >= 1 && n <= 100000,
                      subsection,
                      entry,
                      "must be 'all', 'last', 'none' or step numbers from 1 "
                      "to 100000, got '" +
                        printable(s) + "'");
              steps.push_back(n);
            }
          // A guard: split_string_list() gives at least one item for a text
          // that is not empty, and an empty item ("1,,2", " , ") is already
          // refused above as no step number, so a list that selects nothing
          // cannot reach here.
          require(!steps.empty(),
                  subsection,
                  entry,
                  "selects no step: give 'all', 'last', 'none' (no checks) "
                  "or step numbers");
        }
    }

    // Two or three finite coordinates below 1e300 in magnitude (a point of
    // either dimension; the scenario checks the count against its own).
    std::vector<double>
    coordinates_from_text(const std::string &text,
                          const std::string &subsection,
                          const std::string &entry)
    {
      const auto          items = Utilities::split_string_list(text);
      std::vector<double> point;
      for (const auto &item : items)
        {
          double value = std::nan("");
          try
            {
              value = Utilities::string_to_double(item);
            }
          catch (...)
            {}
          point.push_back(value);
        }
      require((point.size() == 2 || point.size() == 3) &&
                std::all_of(point.begin(),
                            point.end(),
                            [](const double x) {
                              return std::isfinite(x) && std::abs(x) < 1e300;
                            }),
              subsection,
              entry,
              "must be two or three finite coordinates 'x, y' or 'x, y, z', "
              "got '" +
                printable(text) + "'");
      return point;
    }

    // Two finite coordinates below 1e300 in magnitude. The count is checked
    // here too, for the callers whose pattern does not say it.
    std::array<double, 2>
    point_from_text(const std::string &text,
                    const std::string &subsection,
                    const std::string &entry)
    {
      const auto            xy = Utilities::split_string_list(text);
      std::array<double, 2> point;
      for (unsigned int d = 0; d < dim; ++d)
        {
          double value = 0;
          try
            {
              value = xy.size() == 2 ? Utilities::string_to_double(xy.at(d)) :
                                       std::nan("");
            }
          catch (...)
            {
              value = std::nan("");
            }
          require(std::isfinite(value) && std::abs(value) < 1e300,
                  subsection,
                  entry,
                  "must be two finite coordinates 'x, y', got '" +
                    printable(text) + "'");
          point[d] = value;
        }
      return point;
    }
  } // namespace ParameterChecks
} // namespace RingContact
