// @sect3{The run's driver: SIGINT and SIGTERM}
//
// A stop asked by Ctrl-C or SIGTERM must not cut a file in half, so the
// handler does nothing but record the signal in stop_signal (utilities.h);
// the run reads the flag between steps, at every Newton iteration and
// while gmsh meshes, and ends where its files are whole. A second signal
// is the user's insistence: it takes the signal's default action and
// kills the process at once.
#include <ring_contact/base/utilities.h>
#include <ring_contact/driver/signals.h>

#include <unistd.h>

#include <atomic>
#include <csignal>
#include <cstring>

namespace RingContact
{
  namespace Driver
  {
    namespace
    {
      // Whether this process says, when the first signal comes, that it
      // was heard (process 0 only, under MPI).
      std::atomic<bool> announce_stop{true};
      static_assert(std::atomic<bool>::is_always_lock_free);

      // Whether the handler was installed for SIGINT and SIGTERM: a signal
      // the caller ignored (a script's background job, nohup, a service
      // manager) is never given its default action, since that would let
      // a later one kill a run that was meant to be deaf to it. The first
      // SIGTERM reset an ignored SIGINT to its default before this was
      // kept.
      std::atomic<bool> handles_interrupt{false}, handles_termination{false};

      // Record the signal; a second one takes the default action at once.
      // Two signals handled at once by two threads see each other.
      // Re-raised with the default action, the process ends as killed by
      // the signal, which is what its parent (a shell, mpirun) expects to
      // see.
      extern "C" void
      request_stop(const int signal)
      {
        if (stop_signal.exchange(signal) != 0)
          {
            std::signal(signal, SIG_DFL);
            std::raise(signal);
            return;
          }
        // Only the signals this handler took over: one ignored by the
        // caller stays ignored.
        if (handles_interrupt)
          std::signal(SIGINT, SIG_DFL);
        if (handles_termination)
          std::signal(SIGTERM, SIG_DFL);
        // At once, not after the step (which may take long): write() is
        // safe in a handler, the streams are not.
        if (announce_stop)
          {
            static const char message[] =
              "\nring_contact: stopping once the results on disk are whole, "
              "after the current step (a second signal stops at once)\n";
            [[maybe_unused]] const auto written =
              ::write(STDERR_FILENO, message, sizeof(message) - 1);
          }
      }
    } // namespace

    void
    install_signal_handlers(const bool announce)
    {
      announce_stop = announce;
      struct sigaction action;
      std::memset(&action, 0, sizeof(action));
      action.sa_handler = request_stop;
      sigemptyset(&action.sa_mask);
      // Interrupted system calls (file writes) resume.
      action.sa_flags = SA_RESTART;
      // A signal the caller ignores is left ignored here: a shell script's
      // background jobs ignore SIGINT, so that Ctrl-C stops only the
      // script.
      for (const int signal : {SIGINT, SIGTERM})
        {
          struct sigaction inherited;
          sigaction(signal, nullptr, &inherited);
          const bool handled = inherited.sa_handler != SIG_IGN;
          (signal == SIGINT ? handles_interrupt : handles_termination) =
            handled;
          if (handled)
            sigaction(signal, &action, nullptr);
        }
      // A file size limit (ulimit -f) would otherwise kill the process
      // with SIGXFSZ in the middle of a write; ignored, write() fails with
      // EFBIG and the run reports it like a full disk, naming the file.
      std::signal(SIGXFSZ, SIG_IGN);
    }

    void
    set_announce_stop(const bool announce)
    {
      announce_stop = announce;
    }

    // SIGTERM when this process saw no signal itself: under MPI a stop
    // asked of another process reaches this one through the collective
    // or of run.cc, and SIGTERM is what mpirun would have sent it.
    int
    stopping_signal()
    {
      return stop_signal.load() != 0 ? stop_signal.load() : SIGTERM;
    }

    std::string
    signal_name(const int signal)
    {
      return signal == SIGINT ? "SIGINT" : "SIGTERM";
    }
  } // namespace Driver
} // namespace RingContact
