// Shared by the tests that run the real executable as a user would: start
// it on a parameter file with its output (stdout and stderr) read line by
// line as it comes, so that a test can act at a chosen point of the run
// (send a signal, start a second run), and check the results folder with
// check_results.py (Debian's /usr/bin/python3 with VTK).
#ifndef ring_contact_run_program_h
#define ring_contact_run_program_h

#include <ring_contact/config.h>

#include "tests.h"

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdio>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

namespace RingContactTests
{
  /// A file's whole contents ("" if it cannot be read).
  inline std::string
  file_contents(const std::string &filename)
  {
    std::ifstream      in(filename);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  }

  /// The data rows of a CSV file with a header row.
  inline unsigned int
  count_rows(const std::string &filename)
  {
    std::ifstream in(filename);
    std::string   line;
    unsigned int  n = 0;
    while (std::getline(in, line))
      ++n;
    return n > 0 ? n - 1 : 0;
  }

  /// How a run ended and what it printed.
  struct RunResult
  {
    int                      exit_code = -1; ///< -1 if killed by a signal
    int                      signal    = 0;  ///< the signal that killed it
    std::vector<std::string> lines;
    double                   seconds = 0; ///< wall-clock time of the run
    /// The program's largest resident set [bytes], measured by
    /// run_program_measured() only (0 otherwise).
    double peak_memory = 0;

    /// Number of printed lines that start with `prefix`.
    unsigned int
    count(const std::string &prefix) const
    {
      unsigned int n = 0;
      for (const auto &line : lines)
        n += line.rfind(prefix, 0) == 0;
      return n;
    }

    /// The step k of a step line (" 12/21  0.6  2 ...": the progress
    /// table's first column is k/N), 0 for any other line.
    static unsigned int
    step_of(const std::string &line)
    {
      std::istringstream in(line);
      unsigned int       k = 0, n = 0;
      char               slash = 0;
      if (in >> k >> slash >> n && slash == '/' && n > 0 &&
          (in.peek() == ' ' || in.eof()))
        return k;
      return 0;
    }

    /// Number of step lines printed.
    unsigned int
    steps_printed() const
    {
      unsigned int n = 0;
      for (const auto &line : lines)
        n += step_of(line) > 0;
      return n;
    }

    /// Whether the step line of step k was printed.
    bool
    printed_step(const unsigned int k) const
    {
      for (const auto &line : lines)
        if (step_of(line) == k)
          return true;
      return false;
    }

    /// Whether a printed line contains `text`.
    bool
    printed(const std::string &text) const
    {
      for (const auto &line : lines)
        if (line.find(text) != std::string::npos)
          return true;
      return false;
    }
  };

  /// Run the command `arguments` (the program first); `on_line(line, pid)`
  /// sees every line as it is printed. `file_size_limit` > 0 sets
  /// RLIMIT_FSIZE (bytes) for the run. `on_start(pid)` is called once the
  /// process is started, before its output is read.
  inline RunResult
  run_command(
    const std::vector<std::string>                        &arguments,
    const std::function<void(const std::string &, pid_t)> &on_line         = {},
    const rlim_t                                           file_size_limit = 0,
    const std::function<void(pid_t)>                      &on_start        = {})
  {
    int pipe_ends[2];
    check(::pipe(pipe_ends) == 0, "pipe");
    const auto  start = std::chrono::steady_clock::now();
    const pid_t pid   = ::fork();
    check(pid >= 0, "fork");
    if (pid == 0)
      {
        ::dup2(pipe_ends[1], 1);
        ::dup2(pipe_ends[1], 2);
        ::close(pipe_ends[0]);
        ::close(pipe_ends[1]);
        // The signals as a user's shell gives them (a test run from a
        // script's background job would ignore SIGINT).
        std::signal(SIGINT, SIG_DFL);
        std::signal(SIGTERM, SIG_DFL);
        if (file_size_limit > 0)
          {
            const rlimit limit{file_size_limit, file_size_limit};
            ::setrlimit(RLIMIT_FSIZE, &limit);
          }
        std::vector<char *> argv;
        for (const auto &argument : arguments)
          argv.push_back(const_cast<char *>(argument.c_str()));
        argv.push_back(nullptr);
        ::execv(argv[0], argv.data());
        ::_exit(127);
      }
    ::close(pipe_ends[1]);
    if (on_start)
      on_start(pid);
    RunResult   result;
    FILE       *in = ::fdopen(pipe_ends[0], "r");
    std::string line;
    for (int c; (c = std::fgetc(in)) != EOF;)
      if (c == '\n')
        {
          result.lines.push_back(line);
          if (on_line)
            on_line(line, pid);
          line.clear();
        }
      else
        line += static_cast<char>(c);
    if (!line.empty())
      result.lines.push_back(line);
    std::fclose(in);
    int status = 0;
    ::waitpid(pid, &status, 0);
    result.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
        .count();
    if (WIFEXITED(status))
      result.exit_code = WEXITSTATUS(status);
    else if (WIFSIGNALED(status))
      result.signal = WTERMSIG(status);
    return result;
  }

  /// Run ring_contact on `prm_file` (see run_command()).
  inline RunResult
  run_program(
    const std::string                                     &prm_file,
    const std::function<void(const std::string &, pid_t)> &on_line         = {},
    const rlim_t                                           file_size_limit = 0)
  {
    return run_command({RING_CONTACT_EXECUTABLE, prm_file},
                       on_line,
                       file_size_limit);
  }

  /// Run ring_contact on `prm_file` and measure its peak resident set.
  /// Not from a process forked here: a fork starts with this test's
  /// resident set (the libraries it links, 160 MB and more), and the
  /// kernel's ru_maxrss of the child counts it. A small launcher
  /// (Python, which the tests need anyway) forks the program instead and
  /// writes the program's ru_maxrss to a file; the exit code (or 128 +
  /// the signal) is the program's.
  inline RunResult
  run_program_measured(const std::string &prm_file)
  {
    const std::string peak_file = prm_file + ".peak";
    const std::string launcher =
      "import os, sys\n"
      "pid = os.fork()\n"
      "if pid == 0:\n"
      "    try:\n"
      "        os.execv(sys.argv[2], sys.argv[2:])\n"
      "    finally:\n"
      "        os._exit(127)\n"
      "_, status, usage = os.wait4(pid, 0)\n"
      "with open(sys.argv[1], 'w') as f:\n"
      "    f.write(str(usage.ru_maxrss))\n"
      "sys.exit(os.WEXITSTATUS(status) if os.WIFEXITED(status) else\n"
      "         128 + os.WTERMSIG(status))\n";
    std::remove(peak_file.c_str());
    RunResult         result    = run_command({"/usr/bin/python3",
                                               "-c",
                                               launcher,
                                               peak_file,
                                               RING_CONTACT_EXECUTABLE,
                                               prm_file});
    const std::string kilobytes = file_contents(peak_file);
    check(!kilobytes.empty(), "the launcher's measure in " + peak_file);
    result.peak_memory = 1024.0 * std::stod(kilobytes);
    return result;
  }

  /// Run ring_contact on `prm_file` under mpirun with `n` processes; the
  /// pid that `on_line` sees is mpirun's.
  inline RunResult
  run_mpi_program(
    const unsigned int                                     n,
    const std::string                                     &prm_file,
    const std::function<void(const std::string &, pid_t)> &on_line = {})
  {
    std::vector<std::string> arguments = {RING_CONTACT_MPIEXEC};
    std::istringstream       flags(RING_CONTACT_MPIEXEC_FLAGS);
    for (std::string flag; flags >> flag;)
      arguments.push_back(flag);
    for (const std::string argument : {std::string("-n"),
                                       std::to_string(n),
                                       std::string(RING_CONTACT_EXECUTABLE),
                                       prm_file})
      arguments.push_back(argument);
    return run_command(arguments, on_line);
  }

  /// check_results.py on `folder` with `options`; true if every file reads
  /// back whole. Its report goes to `report` (if given).
  inline bool
  check_results(const std::string &folder,
                const std::string &options,
                std::string       *report = nullptr)
  {
    const std::string command = "/usr/bin/python3 " SOURCE_DIR
                                "/check_results.py " +
                                folder + " " + options + " 2>&1";
    FILE *in = ::popen(command.c_str(), "r");
    check(in != nullptr, "popen " + command);
    std::string text;
    for (int c; (c = std::fgetc(in)) != EOF;)
      text += static_cast<char>(c);
    const int status = ::pclose(in);
    if (report)
      *report = text;
    if (status != 0)
      std::cerr << command << ":\n" << text;
    return status == 0;
  }
} // namespace RingContactTests

#endif
