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
  inline std::ofstream deallog_file("output");

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
