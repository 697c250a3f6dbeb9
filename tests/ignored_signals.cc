// A signal that the program's caller ignores stays ignored for the whole
// run (driver/signals.cc). A script's background job, nohup or a service
// manager starts the program with SIGINT or SIGTERM ignored; the handlers
// are installed only for the signals not ignored, and the first signal
// gives only those back their default action. Before, the first SIGTERM
// reset an ignored SIGINT to its default, and a later SIGINT killed a run
// that was meant to be deaf to it. Each case raises the handled signal in
// this process and reads the dispositions after it.
#include <ring_contact/base/utilities.h>
#include <ring_contact/driver/signals.h>

#include "tests.h"

#include <csignal>

using RingContactTests::check;

namespace
{
  bool
  ignored(const int signal)
  {
    struct sigaction now;
    sigaction(signal, nullptr, &now);
    return now.sa_handler == SIG_IGN;
  }

  // `deaf` ignored by the caller, `heard` not: the first `heard` is
  // recorded as the stop, `deaf` stays ignored (raised, it does nothing).
  void
  first_signal_keeps(const int deaf, const int heard, const std::string &name)
  {
    RingContact::stop_signal = 0;
    std::signal(deaf, SIG_IGN);
    std::signal(heard, SIG_DFL);
    RingContact::Driver::install_signal_handlers(false);
    std::raise(heard);
    check(RingContact::stop_signal.load() == heard,
          name + ": the first signal is recorded as the stop");
    check(ignored(deaf), name + ": the ignored signal is still ignored");
    std::raise(deaf);
    check(!ignored(heard),
          name + ": the heard signal has its default action again");
    RingContactTests::deallog_file
      << name << ": recorded as the stop; the ignored signal stays ignored"
      << std::endl;
  }
} // namespace

int
main()
{
  first_signal_keeps(SIGINT, SIGTERM, "SIGINT ignored, SIGTERM sent");
  first_signal_keeps(SIGTERM, SIGINT, "SIGTERM ignored, SIGINT sent");
}
