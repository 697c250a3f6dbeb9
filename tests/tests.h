// Shared by the unit tests: deal.II's testing convention is that a test
// writes to the file "output", which the harness compares with
// <test>.output; `check` stops the test with a clear message when a
// condition does not hold.
#ifndef ring_contact_tests_h
#define ring_contact_tests_h

#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

namespace RingContactTests
{
  /// "output"; under mpirun, process 0's only (the others write
  /// output.<process>, which the harness does not compare). Opened before
  /// main() starts MPI, so the process is read from mpirun's environment.
  inline std::string
  output_name()
  {
    for (const char *variable : {"OMPI_COMM_WORLD_RANK", "PMI_RANK"})
      if (const char *rank = std::getenv(variable))
        if (std::string(rank) != "0")
          return "output." + std::string(rank);
    return "output";
  }

  inline std::ofstream deallog_file(output_name());

  inline void
  check(const bool condition, const std::string &what)
  {
    if (!condition)
      {
        deallog_file << "FAILED: " << what << std::endl;
        std::cerr << "FAILED: " << what << std::endl;
        std::exit(1);
      }
  }
} // namespace RingContactTests

#endif
