// Small helpers shared by the program and its tests.
#ifndef ring_contact_base_utilities_h
#define ring_contact_base_utilities_h

#include <atomic>
#include <cmath>
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

  /// Thrown where a state (a displacement, a position, a residual) is found
  /// not to be a finite number: the load step fails with this message and
  /// is cut, as when its Newton iteration fails, instead of the program
  /// computing on with infinities (or crashing on an index that a NaN
  /// comparison never set).
  class NonFiniteState : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };

  /// The Euclidean norm sqrt(sum x_i^2) of numbers of any magnitude, with
  /// a running scale as LAPACK's dnrm2 computes it: the squares of a
  /// residual of 1e-200 underflow to zero, and those of 1e200 overflow,
  /// while this neither does. NaN if any x_i is NaN.
  class EuclideanNorm
  {
  public:
    void
    add(const double x)
    {
      const double a = std::abs(x);
      if (a == 0)
        return;
      if (a > scale)
        {
          const double ratio = scale / a;
          scaled_sum         = 1 + scaled_sum * ratio * ratio;
          scale              = a;
        }
      else
        {
          const double ratio = a / scale;
          scaled_sum += ratio * ratio;
        }
    }

    double
    value() const
    {
      return scale * std::sqrt(scaled_sum);
    }

  private:
    double scale      = 0;
    double scaled_sum = 1;
  };

  /// Thrown where a converged state fails an invariant that the program
  /// checks (equilibrium.h): its results are not written as converged,
  /// and the run stops with the reason.
  class UntrustedState : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };

  /// The peak resident memory of this process so far (VmHWM), in bytes; 0
  /// where the system does not say.
  std::size_t
  peak_memory();

  /// The memory the system can give without swapping (MemAvailable), in
  /// bytes; 0 where the system does not say.
  std::size_t
  available_memory();

  /// Thrown before a factorization that would need more memory than the
  /// machine has: what() says how much, and the run stops (a step cut
  /// would not help).
  class FactorizationTooLarge : public std::runtime_error
  {
  public:
    FactorizationTooLarge(const std::string &what, const double bytes)
        : std::runtime_error(what)
        , bytes(bytes)
    {}
    const double bytes;
  };
} // namespace RingContact

#endif
