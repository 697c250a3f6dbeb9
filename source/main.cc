// ring_contact: SSNP152 with deal.II. Usage: ring_contact <file.prm>
//
// Runs the modelisation described by the parameter file once per contact
// integration scheme it lists, writes results/<prm name>/history.csv and
// the VTU/PVD files, prints the verdict table of the checks and exits with
// a non-zero code if a check fails or a step cannot be solved.
//
// Results are never lost or mixed: the run holds its output folder (a second
// run into it is refused) and removes what an earlier run left there;
// history.csv grows by one row per converged step, on disk before the next
// step starts, and verdicts.csv is written as soon as a scheme is done.
// SIGINT or SIGTERM ends the run after the current step's files are
// complete (exit code 130 or 143); a second signal ends it at once.
#include <deal.II/base/multithread_info.h>

#include <ring_contact/config.h>
#include <ring_contact/load_program.h>
#include <ring_contact/output_folder.h>
#include <ring_contact/parameters.h>
#include <ring_contact/postprocessing.h>
#include <ring_contact/ring_contact_problem.h>
#include <ring_contact/utilities.h>

#include <atomic>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <map>
#include <memory>

namespace
{
  // The signal that asked the run to stop, 0 while none did. The handler
  // only records it (a lock-free atomic: safe in a handler, and two signals
  // handled at once by two threads see each other) and gives SIGINT and
  // SIGTERM back their default action, so that a second signal ends the
  // program at once.
  std::atomic<int> stop_signal{0};
  static_assert(std::atomic<int>::is_always_lock_free);

  extern "C" void
  request_stop(const int signal)
  {
    if (stop_signal.exchange(signal) != 0)
      {
        std::signal(signal, SIG_DFL);
        std::raise(signal);
        return;
      }
    std::signal(SIGINT, SIG_DFL);
    std::signal(SIGTERM, SIG_DFL);
  }

  void
  install_signal_handlers()
  {
    struct sigaction action;
    std::memset(&action, 0, sizeof(action));
    action.sa_handler = request_stop;
    sigemptyset(&action.sa_mask);
    // Interrupted system calls (file writes) resume.
    action.sa_flags = SA_RESTART;
    // A signal the caller ignores stays ignored (a shell script's
    // background jobs ignore SIGINT, so that Ctrl-C stops only the script).
    for (const int signal : {SIGINT, SIGTERM})
      {
        struct sigaction inherited;
        sigaction(signal, nullptr, &inherited);
        if (inherited.sa_handler != SIG_IGN)
          sigaction(signal, &action, nullptr);
      }
    // A file size limit (ulimit -f) makes write() fail with EFBIG, reported
    // like a full disk, instead of killing the program.
    std::signal(SIGXFSZ, SIG_IGN);
  }

  // "history.csv, verdicts.csv, 42 .vtu, 4 .pvd"
  std::string
  describe_files(const std::vector<std::string> &names)
  {
    std::map<std::string, unsigned int> by_kind;
    std::string                         text;
    for (const auto &name : names)
      {
        const auto dot = name.rfind('.');
        const bool listed_by_name =
          name == "history.csv" || name == "verdicts.csv";
        if (listed_by_name)
          text += (text.empty() ? "" : ", ") + name;
        else
          ++by_kind[name.front() == '.' ? "temporary" : name.substr(dot)];
      }
    for (const auto &[kind, n] : by_kind)
      text += (text.empty() ? "" : ", ") + std::to_string(n) + " " + kind;
    return text;
  }
} // namespace

int
main(int argc, char **argv)
{
  using namespace RingContact;
  // A serial program: MPI is not initialised (deal.II's serial classes do
  // not need it, and starting it costs more than solving a modelisation),
  // and one thread: the assembly is serial, and on these small systems the
  // threads that deal.II would start for sorting and output cost more than
  // they save.
  dealii::MultithreadInfo::set_thread_limit(1);
  // The log line by line also into a pipe or a file (`| tee`, a batch
  // system's log): whoever watches sees each step when it is done.
  std::setvbuf(stdout, nullptr, _IOLBF, BUFSIZ);

  const std::string usage = "usage: ring_contact <file.prm>\n"
                            "       ring_contact --print-parameters   (all "
                            "entries, defaults, docs)\n"
                            "       ring_contact --version\n";
  if (argc != 2)
    {
      std::cerr << usage;
      return 2;
    }
  const std::string argument = argv[1];
  if (argument == "--help" || argument == "-h")
    {
      std::cout << usage;
      return 0;
    }
  if (argument == "--version")
    {
      std::cout << "ring_contact " RING_CONTACT_VERSION "\n";
      return 0;
    }
  if (argument == "--print-parameters")
    {
      Parameters::print_reference(std::cout, true);
      return 0;
    }

  install_signal_handlers();
  try
    {
      Parameters parameters;
      parameters.read(argument);
      const OutputParameters &output = parameters.output;

      // The output folder, held for the whole run, without an earlier run's
      // files (a run that writes no file leaves the folder alone).
      std::unique_ptr<OutputFolder> folder;
      std::unique_ptr<HistoryFile>  history_file;
      if (output.write_history || output.vtu_interval > 0)
        {
          folder             = std::make_unique<OutputFolder>(output.directory);
          const auto removed = folder->remove_earlier_results();
          if (!removed.empty())
            std::cout << "Removed from " << output.directory << " the "
                      << removed.size() << " files of an earlier run ("
                      << describe_files(removed) << ")\n";
          if (output.write_history)
            {
              std::vector<std::string> columns;
              for (const auto &check : parameters.problem.checks)
                columns.push_back(check.column());
              history_file =
                std::make_unique<HistoryFile>(output.directory + "/history.csv",
                                              columns);
            }
        }

      std::vector<Verdict> verdicts;
      bool                 solved  = true;
      const unsigned int   n_steps = LoadProgram(parameters.load).n_steps();
      for (const auto &scheme : parameters.contact.schemes)
        {
          if (stop_signal != 0)
            break;
          RingContactProblem problem(parameters, scheme, std::cout);
          problem.set_step_observer([&](const HistoryRow &row) {
            if (history_file)
              history_file->append(row);
            return stop_signal == 0;
          });
          solved = problem.run() && solved;
          // A scheme stopped by a signal before its last step has no
          // verdicts: its checks are not known.
          const auto &history = problem.history();
          if (stop_signal != 0 &&
              (history.empty() || history.back().step < n_steps))
            {
              std::cout << "Stopped after "
                        << (history.empty() ?
                              std::string("no converged step") :
                              "step " + std::to_string(history.back().step))
                        << " of scheme " << scheme.name() << '\n';
              break;
            }
          const auto v = parameters.general() ?
                           evaluate_checks(parameters.problem,
                                           scheme.name(),
                                           history,
                                           n_steps) :
                           evaluate_checks(parameters.checks,
                                           scheme.name(),
                                           history,
                                           n_steps);
          verdicts.insert(verdicts.end(), v.begin(), v.end());
          if (output.write_history)
            write_verdicts(output.directory + "/verdicts.csv", verdicts);
        }
      if (stop_signal != 0)
        {
          if (!verdicts.empty())
            print_verdicts(std::cout, verdicts);
          std::cout << std::flush;
          const int signal = stop_signal.load();
          std::cerr << "ring_contact: interrupted by "
                    << (signal == SIGINT ? "SIGINT" : "SIGTERM")
                    << ": the converged steps' results are complete"
                    << (folder ? " in " + output.directory : std::string())
                    << std::endl;
          return 128 + signal;
        }
      const bool pass = print_verdicts(std::cout, verdicts);
      if (!solved)
        std::cout << "A load step could not be solved (see above).\n";
      return (pass && solved) ? 0 : 1;
    }
  catch (const std::bad_alloc &)
    {
      std::cerr << "ring_contact: error: out of memory (a smaller mesh, or "
                   "'Mesh/Sector elements' for cyclic symmetry)"
                << std::endl;
      return 1;
    }
  catch (const std::exception &e)
    {
      std::cerr << "ring_contact: error: " << one_line_message(e) << std::endl;
      return 1;
    }
  catch (...)
    {
      std::cerr << "ring_contact: error: an unknown exception" << std::endl;
      return 1;
    }
}
