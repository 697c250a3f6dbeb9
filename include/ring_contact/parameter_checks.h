// The value checks shared by every subsection's parse_parameters(): each
// failure is a ParameterError that names the subsection and the entry
// (Parameters::read() adds the file and line that set the value).
#ifndef ring_contact_parameter_checks_h
#define ring_contact_parameter_checks_h

#include <deal.II/base/parameter_handler.h>

#include <array>
#include <string>
#include <utility>
#include <vector>

namespace RingContact
{
  namespace ParameterChecks
  {
    using namespace dealii;

    /// "1e+06", "0.5": a number as the messages show it.
    std::string
    to_text(const double value);

    /// Throw a one-line error that names the entry, when `ok` is false.
    void
    require(const bool         ok,
            const std::string &subsection,
            const std::string &entry,
            const std::string &what);

    /// The value of an entry as a finite double between 1e-300 and 1e300
    /// in magnitude, or 0.
    double
    get_double(ParameterHandler  &prm,
               const std::string &subsection,
               const std::string &entry);

    /// The value of an integer entry, in [lowest, highest].
    unsigned int
    get_count(ParameterHandler  &prm,
              const std::string &subsection,
              const std::string &entry,
              const long         lowest,
              const long         highest);

    /// An entry 'Steps': 'all' (every_step), 'last' (invalid_unsigned_int),
    /// 'none' (empty) or a list of step numbers from 1.
    void
    get_steps(ParameterHandler          &prm,
              const std::string         &subsection,
              const std::string         &entry,
              bool                      &every_step,
              std::vector<unsigned int> &steps);

    /// The items 'name = value, name = value' of an entry (empty: none),
    /// each name given once and made of letters, digits and _, starting
    /// with a letter (`leading_letter`) or with anything but a digit;
    /// `example` and `kind_of_name` make the messages ("e.g. 'Ne = 80'",
    /// "a gmsh variable name"). Returns the names and the values' text.
    std::vector<std::pair<std::string, std::string>>
    get_assignments(const std::string &text,
                    const std::string &subsection,
                    const std::string &entry,
                    const std::string &example,
                    const std::string &kind_of_name,
                    const bool         leading_letter);

    /// An entry of two coordinates 'x, y'.
    std::array<double, 2>
    get_point(ParameterHandler  &prm,
              const std::string &subsection,
              const std::string &entry);
  } // namespace ParameterChecks
} // namespace RingContact

#endif
