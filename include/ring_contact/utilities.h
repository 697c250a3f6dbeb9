// Small helpers shared by the program and its tests.
#ifndef ring_contact_utilities_h
#define ring_contact_utilities_h

#include <atomic>
#include <cstddef>
#include <exception>
#include <stdexcept>
#include <string>

namespace RingContact
{
  /// The message of an exception on one line: for deal.II exceptions only the
  /// "additional information" (no stack trace), whitespace collapsed, made
  /// printable and cut to a sane length (see printable()).
  std::string
  one_line_message(const std::exception &e);

  /// `text` safe to show on a terminal in one line: control characters and
  /// bytes that are not UTF-8 become \xHH escapes, and a text longer than
  /// `max_length` characters is cut and ends with "...".
  std::string
  printable(const std::string &text, std::size_t max_length = 60);

  /// The signal (SIGINT or SIGTERM) that asked the run to stop, 0 while none
  /// did: set by the program's handler (main.cc), read between load steps
  /// and wherever the program waits long outside them (gmsh meshing a
  /// script).
  extern std::atomic<int> stop_signal;

  /// Thrown where a stop asked by a signal ends a wait before the first
  /// load step; what() says what was interrupted ("while gmsh meshed ...").
  class Interrupted : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };

  /// The peak resident memory of this process so far (VmHWM), in bytes; 0
  /// where the system does not say.
  std::size_t
  peak_memory();
} // namespace RingContact

#endif
