// Small helpers shared by the program and its tests.
#ifndef ring_contact_utilities_h
#define ring_contact_utilities_h

#include <exception>
#include <string>

namespace RingContact
{
  /// The message of an exception on one line: for deal.II exceptions only the
  /// "additional information" (no stack trace), whitespace collapsed.
  std::string
  one_line_message(const std::exception &e);
} // namespace RingContact

#endif
