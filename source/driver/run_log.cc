// @sect3{The run's driver: the log of the run}
//
// A stream buffer that passes every character on to the terminal's buffer
// and to the log: in memory until a file is attached, then into the file.
// Both streams share one log (the order of their lines is kept), written
// with write(2) on a descriptor opened with O_NOFOLLOW, like every other
// file of the results folder (a symbolic link planted there is refused,
// its target never written).
#include <ring_contact/driver/run_log.h>

#include <fcntl.h>
#include <unistd.h>

#include <iostream>

namespace RingContact
{
  namespace Driver
  {
    namespace
    {
      // The log shared by both streams: its text until a file is attached,
      // and the file's descriptor after.
      struct SharedLog
      {
        std::string pending;
        std::string filename;
        int         descriptor = -1;

        void
        add(const char *text, const std::size_t n)
        {
          if (descriptor < 0)
            {
              pending.append(text, n);
              return;
            }
          // A failed write of the log must not end the run: the results
          // are what matters, the log is their companion.
          std::size_t done = 0;
          while (done < n)
            {
              const ssize_t w = ::write(descriptor, text + done, n - done);
              if (w <= 0)
                return;
              done += static_cast<std::size_t>(w);
            }
        }
      };

      SharedLog *shared_log = nullptr;
    } // namespace

    // Unbuffered: each character goes on at once, so that the terminal
    // sees the lines when the program writes them (main.cc makes stdout
    // line-buffered for pipes), and nothing is lost if the run ends.
    class RunLog::Tee : public std::streambuf
    {
    public:
      Tee(std::streambuf *terminal, SharedLog &log)
          : terminal(terminal)
          , log(log)
      {}

    protected:
      int
      overflow(const int c) override
      {
        if (c == traits_type::eof())
          return traits_type::not_eof(c);
        const char ch = static_cast<char>(c);
        log.add(&ch, 1);
        return terminal->sputc(ch);
      }

      std::streamsize
      xsputn(const char *s, const std::streamsize n) override
      {
        log.add(s, static_cast<std::size_t>(n));
        return terminal->sputn(s, n);
      }

      int
      sync() override
      {
        return terminal->pubsync();
      }

    private:
      std::streambuf *terminal;
      SharedLog      &log;
    };

    RunLog::RunLog()
    {
      shared_log = new SharedLog();
      old_out    = std::cout.rdbuf();
      old_err    = std::cerr.rdbuf();
      out        = std::make_unique<Tee>(old_out, *shared_log);
      err        = std::make_unique<Tee>(old_err, *shared_log);
      std::cout.rdbuf(out.get());
      std::cerr.rdbuf(err.get());
    }

    RunLog::~RunLog()
    {
      std::cout.flush();
      std::cerr.flush();
      std::cout.rdbuf(old_out);
      std::cerr.rdbuf(old_err);
      if (shared_log->descriptor >= 0)
        ::close(shared_log->descriptor);
      delete shared_log;
      shared_log = nullptr;
    }

    void
    RunLog::attach(const std::string &filename)
    {
      if (shared_log == nullptr || shared_log->filename == filename)
        return;
      const int descriptor = ::open(filename.c_str(),
                                    O_WRONLY | O_CREAT | O_TRUNC | O_NOFOLLOW |
                                      O_CLOEXEC,
                                    0644);
      if (descriptor < 0)
        return;
      if (shared_log->descriptor >= 0)
        ::close(shared_log->descriptor);
      shared_log->descriptor = descriptor;
      shared_log->filename   = filename;
      std::string text;
      text.swap(shared_log->pending);
      shared_log->add(text.data(), text.size());
    }
  } // namespace Driver
} // namespace RingContact
