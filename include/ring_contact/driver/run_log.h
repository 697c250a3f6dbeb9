// @sect3{The run's driver: the log of the run}
//
// results/<name>/run.log holds what the terminal showed: the program's
// standard output and its errors, in the order they were written. The
// streams are teed from the start (process 0 only), the text kept in memory
// until the results folder is known and taken (the start of the first step:
// a run refused on its input writes no log over an earlier run's), then
// written there as it comes.
#ifndef ring_contact_driver_run_log_h
#define ring_contact_driver_run_log_h

#include <memory>
#include <streambuf>
#include <string>

namespace RingContact
{
  namespace Driver
  {
    class RunLog
    {
    public:
      /// Tee std::cout and std::cerr (restored by the destructor).
      RunLog();
      ~RunLog();

      /// From now on the log goes to `filename` too (what was written
      /// before first); a second call with the same name does nothing.
      static void
      attach(const std::string &filename);

    private:
      class Tee;
      std::unique_ptr<Tee> out, err;
      std::streambuf      *old_out, *old_err;
    };
  } // namespace Driver
} // namespace RingContact

#endif
