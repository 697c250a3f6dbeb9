// Shared by the tests against the values Code_Aster prints for SSNP152
// (code_aster_comparison: the 2013 files; code_aster_current: the current
// ones): the pressure at node A along a run with the original's contact
// choices, and its comparison with the printed values.
#ifndef ring_contact_tests_code_aster_h
#define ring_contact_tests_code_aster_h

#include "run_problem.h"

#include <cmath>
#include <iostream>
#include <utility>
#include <vector>

namespace RingContactTests
{
  /// The pressure at node A at every step of modelisation `letter` with
  /// the contact integration `scheme` and the original's choices (smoothed
  /// master normals, LISSAGE = OUI; the nominal pressure, its LAGS_C), and
  /// the entries `extra`.
  inline std::vector<double>
  pressures_at_A(const char         letter,
                 const std::string &scheme,
                 const std::string &extra = "")
  {
    const auto history = run_problem(
      "aster",
      modelisation(letter,
                   "subsection Contact\n set Integration schemes = " + scheme +
                     "\n set Smooth master normals = true\n"
                     " set Reported pressure = nominal\nend\n" +
                     extra));
    std::vector<double> p;
    for (const auto &row : history)
      p.push_back(row.value("pressure_A"));
    return p;
  }

  /// Assert that `ours` (one value per step) holds the (step, value) pairs
  /// `printed` by `version` of Code_Aster within `tolerance`.
  inline void
  compare_with_code_aster(
    const std::string                                  &version,
    const std::string                                  &what,
    const std::vector<double>                          &ours,
    const std::vector<std::pair<unsigned int, double>> &printed,
    const double                                        tolerance)
  {
    double largest = 0;
    for (const auto &[step, value] : printed)
      largest = std::max(largest, std::abs(ours.at(step - 1) - value) / value);
    deallog_file << what << ": " << printed.size() << " values of " << version
                 << " reproduced within " << tolerance << ": "
                 << (largest < tolerance ? "yes" : "NO") << std::endl;
    std::cout << what << ": largest relative difference " << largest
              << std::endl;
    check(largest < tolerance,
          what + ": largest relative difference " + std::to_string(largest));
  }
} // namespace RingContactTests

#endif
