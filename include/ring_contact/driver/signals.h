// @sect3{The run's driver: signals}
//
// Ctrl-C (SIGINT) or SIGTERM ends a run after the current step's files are
// complete, or at once while it meshes or between Newton iterations (the
// stop flag, stop_signal of utilities.h, is read there); a second signal
// ends it at once. The handler only records the signal (a lock-free atomic:
// safe in a handler) and gives SIGINT and SIGTERM back their default action,
// each only if the caller did not ignore it (an ignored one stays ignored).
#ifndef ring_contact_driver_signals_h
#define ring_contact_driver_signals_h

#include <string>

namespace RingContact
{
  namespace Driver
  {
    /// Install the handlers of SIGINT and SIGTERM (a signal the caller
    /// ignores stays ignored: a shell script's background jobs ignore
    /// SIGINT), and ignore SIGXFSZ (a file size limit makes write() fail
    /// with EFBIG, reported like a full disk). `announce`: say at once,
    /// when the first signal comes, that it was heard (process 0 only).
    void
    install_signal_handlers(const bool announce);

    /// Whether this process should say, when a signal comes, that it was
    /// heard (process 0 only, under MPI).
    void
    set_announce_stop(const bool announce);

    /// The signal that stopped the run, or SIGTERM (what mpirun sends).
    int
    stopping_signal();

    /// "SIGINT" or "SIGTERM".
    std::string
    signal_name(const int signal);
  } // namespace Driver
} // namespace RingContact

#endif
