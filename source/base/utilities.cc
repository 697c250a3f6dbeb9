// @sect3{Utilities: messages, the stop flag, memory}
//
// Helpers that the program and its tests share. The messages: every error
// the program prints is one line, and a line with nothing in it that can
// harm a terminal, since parameter files and meshes come from users and
// their values are quoted back. The stop flag that the signal handler
// sets and the long waits read. And the memory the process has used and
// may still use, read from /proc, by which a factorization too large for
// the machine is refused before it starts rather than after minutes of
// swapping.
#include <deal.II/base/exceptions.h>

#include <ring_contact/base/utilities.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sstream>

#include <sys/resource.h>

namespace RingContact
{
  // Written by the signal handler, so it must be lock-free: a handler that
  // interrupted a thread holding the atomic's lock would wait for ever.
  std::atomic<int> stop_signal{0};
  static_assert(std::atomic<int>::is_always_lock_free);

  namespace
  {
    // The length of the UTF-8 sequence that starts at `at`, 0 if it is not
    // a valid one. The lead bytes exclude the overlong two-byte forms
    // (0xC0, 0xC1) and code points beyond U+10FFFF (above 0xF4); the
    // continuation bytes must be 10xxxxxx. Overlong three- and four-byte
    // forms and surrogates pass: the aim is a terminal that shows what it
    // is given, not a validator.
    std::size_t
    utf8_length(const std::string &text, const std::size_t at)
    {
      const auto byte = [&](const std::size_t i) {
        return static_cast<unsigned char>(text[i]);
      };
      const unsigned char first = byte(at);
      const std::size_t   n     = (first >= 0xC2 && first <= 0xDF) ? 2 :
                                  (first >= 0xE0 && first <= 0xEF) ? 3 :
                                  (first >= 0xF0 && first <= 0xF4) ? 4 :
                                                                     0;
      // A sequence that the text ends inside is not valid either, and its
      // continuation bytes are not read past the end.
      if (n == 0 || at + n > text.size())
        return 0;
      for (std::size_t i = 1; i < n; ++i)
        if ((byte(at + i) & 0xC0) != 0x80)
          return 0;
      return n;
    }
  } // namespace

  std::string
  printable(const std::string &text, const std::size_t max_length)
  {
    // `shown` counts characters, not bytes: a name in UTF-8 is cut after
    // the same number of letters as one in ASCII, and never inside one.
    std::string result;
    std::size_t shown = 0;
    std::size_t at    = 0;
    while (at < text.size() && shown < max_length)
      {
        const unsigned char c = static_cast<unsigned char>(text[at]);
        if (c >= 0x20 && c < 0x7F)
          {
            result += text[at];
            ++at;
          }
        else if (const std::size_t n = (c >= 0x80) ? utf8_length(text, at) : 0;
                 n > 0)
          {
            result += text.substr(at, n);
            at += n;
          }
        else
          {
            // A control character (an escape sequence can move the cursor
            // or retitle the terminal) or a stray byte: shown as \xHH, so
            // that the message still says what the file holds.
            char escape[8];
            std::snprintf(escape, sizeof(escape), "\\x%02X", c);
            result += escape;
            ++at;
          }
        ++shown;
      }
    // A cut text says that it is cut.
    if (at < text.size())
      result += "...";
    return result;
  }

  std::string
  one_line_message(const std::exception &e)
  {
    // deal.II's what() is a block of several lines with the file, line and
    // function of the assertion and, where available, a stack trace;
    // print_info() gives only the message written for the user.
    std::string text;
    if (const auto *deal_ii = dynamic_cast<const dealii::ExceptionBase *>(&e))
      {
        std::ostringstream out;
        deal_ii->print_info(out);
        text = out.str();
      }
    else
      text = e.what();
    // Collapse all whitespace runs into single spaces.
    std::string line;
    bool        space = false;
    for (const char c : text)
      if (c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' ||
          c == '\f')
        space = !line.empty();
      else
        {
          if (space)
            line += ' ';
          line += c;
          space = false;
        }
    // Messages quote values that were escaped where they were read; this
    // is the last guard against a raw byte reaching the terminal.
    return printable(line, 1000);
  }

  // VmHWM, the high-water mark of the resident set: what the process
  // needed at its worst, printed with the timing of a run.
  // Without /proc (not Linux) it is 0, and the run prints 0 MB rather
  // than fail.
  std::size_t
  peak_memory()
  {
    std::ifstream status("/proc/self/status");
    for (std::string line; std::getline(status, line);)
      if (line.rfind("VmHWM:", 0) == 0)
        {
          std::istringstream in(line.substr(6));
          std::size_t        kilobytes = 0;
          in >> kilobytes;
          return kilobytes * 1024;
        }
    return 0;
  }

  namespace
  {
    // A "Name:   123 kB" line of a /proc file, in bytes (0 if none); /proc's
    // kB are units of 1024 bytes.
    std::size_t
    proc_kilobytes(const std::string &file, const std::string &name)
    {
      std::ifstream in(file);
      for (std::string line; std::getline(in, line);)
        if (line.rfind(name, 0) == 0)
          {
            std::istringstream value(line.substr(name.size()));
            std::size_t        kilobytes = 0;
            value >> kilobytes;
            return kilobytes * 1024;
          }
      return 0;
    }
  } // namespace

  // MemAvailable, not MemFree: the kernel's estimate of what can be given
  // without swapping counts the page cache it would drop. The check it
  // serves (direct_solver.cc) compares UMFPACK's estimate with 90 % of it.
  std::size_t
  available_memory()
  {
    std::size_t available = proc_kilobytes("/proc/meminfo", "MemAvailable:");
    // An address-space limit (ulimit -v, a batch system's) bounds what this
    // process can have: what is left of it.
    struct rlimit limit;
    if (::getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY)
      {
        // VmSize, the address space in use, not the resident set: the limit
        // counts every mapping, touched or not.
        const std::size_t used = proc_kilobytes("/proc/self/status", "VmSize:");
        const std::size_t left =
          limit.rlim_cur > used ?
            static_cast<std::size_t>(limit.rlim_cur) - used :
            0;
        available = available > 0 ? std::min(available, left) : left;
      }
    // Neither known (no /proc, no limit): 0, and the caller's check is
    // not made.
    return available;
  }
} // namespace RingContact
