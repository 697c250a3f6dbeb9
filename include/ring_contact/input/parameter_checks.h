// How every subsection of the parameter file declares its entries: each
// entry once, with its name, default, pattern, documentation, the variable
// that holds its value and the checks of that value (class Subsection), in
// the idiom of deal.II's ParameterHandler::add_parameter(). A wrong value is
// a ParameterError that names the subsection and the entry; the reader of
// the file (read_parameter_file()) or Parameters::read() adds the file and
// line that set it.
#ifndef ring_contact_input_parameter_checks_h
#define ring_contact_input_parameter_checks_h

#include <deal.II/base/parameter_handler.h>

#include <array>
#include <functional>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace RingContact
{
  namespace ParameterChecks
  {
    using namespace dealii;

    /// The largest boundary or material tag an entry takes (gmsh's tags
    /// are ints; deal.II's ids are unsigned ints).
    constexpr int max_tag = 1000000000;

    /// "1e+06", "0.5": a number as the messages show it.
    std::string
    to_text(const double value);

    /// Throw a one-line error that names the entry, when `ok` is false.
    void
    require(const bool         ok,
            const std::string &subsection,
            const std::string &entry,
            const std::string &what);

    /// A condition on a number, and what the message says when it fails:
    /// "must be positive" (then ", got -1"); a lower bound that the pattern
    /// states (the printed reference shows it).
    struct Condition
    {
      std::function<bool(double)> holds;
      std::string                 what;
      double lowest = std::numeric_limits<double>::lowest();
    };

    /// x > 0.
    Condition
    positive(const std::string &what = "must be positive");

    /// x >= 0, in the pattern.
    Condition
    not_negative();

    /// The entries of one subsection, each declared once: its name, default,
    /// pattern and documentation with the variable it sets. The value is
    /// converted and checked by a deal.II action (ParameterHandler::
    /// add_action()): on the default when the entry is declared, so that
    /// the variable holds the default from then on, and on each value the
    /// file sets, so that a wrong one is reported at its line. Conditions
    /// between entries are checked once the whole file is read.
    class Subsection
    {
    public:
      /// Enter the subsection `name` of `prm`; the destructor leaves it.
      /// `declared`, if given, receives "Subsection/Entry" of every entry
      /// declared (which entries a scenario owns, see Parameters).
      Subsection(ParameterHandler         &prm,
                 const std::string        &name,
                 std::vector<std::string> *declared = nullptr);
      ~Subsection();
      Subsection(const Subsection &) = delete;
      Subsection &
      operator=(const Subsection &) = delete;

      /// A floating-point number: 0 or between 1e-300 and 1e300 in
      /// magnitude (the pattern admits e.g. 1e-320, a denormal), that
      /// satisfies `condition` (none: any).
      void
      add(const std::string &entry,
          double            &variable,
          const std::string &default_value,
          const std::string &documentation,
          const Condition   &condition = {});

      /// An integer in [lowest, highest] (the pattern says so).
      void
      add(const std::string &entry,
          unsigned int      &variable,
          const std::string &default_value,
          const int          lowest,
          const int          highest,
          const std::string &documentation);

      /// true or false.
      void
      add(const std::string &entry,
          bool              &variable,
          const std::string &default_value,
          const std::string &documentation);

      /// Text as it is, or matching `pattern`.
      void
      add(const std::string           &entry,
          std::string                 &variable,
          const std::string           &default_value,
          const std::string           &documentation,
          const Patterns::PatternBase &pattern = Patterns::Anything());

      /// One of the names of `choices` (the pattern is their selection),
      /// stored as its value.
      template <typename T>
      void
      add(const std::string                            &entry,
          T                                            &variable,
          const std::string                            &default_value,
          const std::vector<std::pair<std::string, T>> &choices,
          const std::string                            &documentation)
      {
        std::string names;
        for (const auto &choice : choices)
          names += (names.empty() ? "" : "|") + choice.first;
        add(entry,
            default_value,
            Patterns::Selection(names),
            documentation,
            [&variable, choices](const std::string &text) {
              for (const auto &choice : choices)
                if (choice.first == text)
                  variable = choice.second;
            });
      }

      /// Any other entry: `read` converts the text (which matches
      /// `pattern`) and checks it, throwing a ParameterError (require()).
      void
      add(const std::string                              &entry,
          const std::string                              &default_value,
          const Patterns::PatternBase                    &pattern,
          const std::string                              &documentation,
          const std::function<void(const std::string &)> &read);

      /// The subsection's name, for the messages of require().
      const std::string name;

    private:
      ParameterHandler         &prm;
      std::vector<std::string> *declared;
    };

    /// The value of an entry as a finite double between 1e-300 and 1e300
    /// in magnitude, or 0.
    double
    number_from_text(const std::string &text,
                     const std::string &subsection,
                     const std::string &entry);

    /// An entry 'Steps': 'all' (every_step), 'last' (invalid_unsigned_int),
    /// 'none' (empty) or a list of step numbers from 1.
    void
    steps_from_text(const std::string         &text,
                    const std::string         &subsection,
                    const std::string         &entry,
                    bool                      &every_step,
                    std::vector<unsigned int> &steps);

    /// The items 'name = value, name = value' of an entry (empty: none),
    /// split at the commas outside parentheses, each name given once and made
    /// of letters, digits and _, starting with a letter (`leading_letter`) or
    /// with anything but a digit; `example` and `kind_of_name` make the
    /// messages ("e.g. 'Ne = 80'", "a gmsh variable name"). Returns the names
    /// and the values' text.
    std::vector<std::pair<std::string, std::string>>
    get_assignments(const std::string &text,
                    const std::string &subsection,
                    const std::string &entry,
                    const std::string &example,
                    const std::string &kind_of_name,
                    const bool         leading_letter);

    /// An entry of two or three coordinates 'x, y' or 'x, y, z'.
    std::vector<double>
    coordinates_from_text(const std::string &text,
                          const std::string &subsection,
                          const std::string &entry);

    /// An entry of two coordinates 'x, y'.
    std::array<double, 2>
    point_from_text(const std::string &text,
                    const std::string &subsection,
                    const std::string &entry);
  } // namespace ParameterChecks
} // namespace RingContact

#endif
