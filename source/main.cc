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
//
// Under MPI (`mpirun -np N ring_contact file.prm`) every process runs the
// problem (see LinearSystem); process 0 alone prints and writes the history
// and verdicts, each process writes its piece of the VTU files. A run
// started without mpirun does not start MPI, unless the file asks for
// MUMPS.
#include <deal.II/base/mpi.h>
#include <deal.II/base/multithread_info.h>

#include <ring_contact/config.h>
#include <ring_contact/linear_system.h>
#include <ring_contact/load_program.h>
#include <ring_contact/output_folder.h>
#include <ring_contact/parameter_file.h>
#include <ring_contact/parameters.h>
#include <ring_contact/postprocessing.h>
#include <ring_contact/ring_contact_problem.h>
#include <ring_contact/utilities.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <map>
#include <memory>
#include <thread>

#include <unistd.h>

namespace
{
  // The handler only records the signal in RingContact::stop_signal (a
  // lock-free atomic: safe in a handler, and two signals handled at once by
  // two threads see each other) and gives SIGINT and SIGTERM back their
  // default action, so that a second signal ends the program at once.
  using RingContact::stop_signal;
  // Whether this process says, when the first signal comes, that it was
  // heard (process 0 only, under MPI).
  std::atomic<bool> announce_stop{true};
  static_assert(std::atomic<bool>::is_always_lock_free);

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
    // At once, not after the step (which may take long): write() is safe
    // in a handler, the streams are not.
    if (announce_stop)
      {
        static const char message[] =
          "\nring_contact: stopping once the results on disk are whole, "
          "after the current step (a second signal stops at once)\n";
        [[maybe_unused]] const auto written =
          ::write(STDERR_FILENO, message, sizeof(message) - 1);
      }
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

  // Whether a process manager (OpenMPI's or MPICH's mpirun, srun) started
  // this process: only then is MPI started before the parameter file is
  // read (starting it alone costs about a second).
  bool
  launched_by_mpirun()
  {
    for (const char *variable :
         {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK", "PMI_RANK"})
      if (std::getenv(variable) != nullptr)
        return true;
    return false;
  }

  // Whether every process reaches this point within `seconds`, on a
  // communicator of its own: an error that every process met (a parameter
  // file or a mesh that all of them read) ends the run cleanly; one that
  // only some met leaves the others waiting in a collective call, and the
  // run must be aborted rather than hang.
  bool
  all_processes_arrive(const MPI_Comm communicator, const double seconds)
  {
    MPI_Request request;
    MPI_Ibarrier(communicator, &request);
    const auto start = std::chrono::steady_clock::now();
    for (int done = 0;;)
      {
        MPI_Test(&request, &done, MPI_STATUS_IGNORE);
        if (done)
          return true;
        if (std::chrono::duration<double>(std::chrono::steady_clock::now() -
                                          start)
              .count() > seconds)
          return false;
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
      }
  }

  // Run `f` on process 0 only (a file of the results folder) and make its
  // failure that of every process: the exception's message is sent to all,
  // and each throws it.
  template <typename Function>
  void
  on_process_zero(const MPI_Comm communicator, const Function &f)
  {
    using namespace RingContact;
    std::string error;
    if (this_process(communicator) == 0)
      try
        {
          f();
        }
      catch (const std::exception &e)
        {
          error = one_line_message(e);
        }
    if (n_processes(communicator) > 1)
      error = dealii::Utilities::MPI::broadcast(communicator, error, 0);
    if (!error.empty())
      throw std::runtime_error(error);
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
  // One thread: the assembly is serial (under MPI, one process per core),
  // and on these small systems the threads that deal.II would start for
  // sorting and output cost more than they save.
  dealii::MultithreadInfo::set_thread_limit(1);
  // The log line by line also into a pipe or a file (`| tee`, a batch
  // system's log): whoever watches sees each step when it is done.
  std::setvbuf(stdout, nullptr, _IOLBF, BUFSIZ);

  const std::string usage = "usage: ring_contact <file.prm>\n"
                            "       mpirun -np N ring_contact <file.prm>\n"
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

  // MPI: started by mpirun, or for MUMPS on one process. Not otherwise:
  // deal.II's serial classes do not need it, and starting it costs more
  // than solving a modelisation.
  std::unique_ptr<dealii::Utilities::MPI::MPI_InitFinalize> mpi;
  if (launched_by_mpirun())
    mpi =
      std::make_unique<dealii::Utilities::MPI::MPI_InitFinalize>(argc, argv, 1);
  install_signal_handlers();
  if (mpi && this_process(MPI_COMM_WORLD) != 0)
    announce_stop = false;

  // Every process reads the file: an error in it is every process's, and
  // process 0 says it.
  Parameters parameters;
  try
    {
      parameters.read(argument);
    }
  catch (const std::exception &e)
    {
      if (this_process(MPI_COMM_WORLD) == 0)
        std::cerr << "ring_contact: error: " << one_line_message(e)
                  << std::endl;
      return 1;
    }
  if (!mpi && (parameters.newton.linear_solver == LinearSolverType::mumps ||
               parameters.newton.linear_solver == LinearSolverType::iterative))
    mpi =
      std::make_unique<dealii::Utilities::MPI::MPI_InitFinalize>(argc, argv, 1);
  const MPI_Comm     world = MPI_COMM_WORLD;
  const unsigned int n     = n_processes(world);
  const bool         root  = this_process(world) == 0;
  // The other processes' log goes nowhere.
  std::ostream  null_stream(nullptr);
  std::ostream &out = root ? std::cout : null_stream;
  // For the error barrier, apart from the run's own communication; freed
  // before MPI ends (declared after `mpi`).
  struct OwnCommunicator
  {
    MPI_Comm communicator = MPI_COMM_NULL;
    ~OwnCommunicator()
    {
      if (communicator != MPI_COMM_NULL)
        MPI_Comm_free(&communicator);
    }
  } error_communicator;
  if (n > 1)
    MPI_Comm_dup(world, &error_communicator.communicator);
  const MPI_Comm errors = error_communicator.communicator;

  // An error: said once and a clean exit when every process met it; said
  // by the process that met it and the run aborted otherwise (the others
  // wait for it in a collective call).
  const auto fail = [&](const std::string &message) {
    if (n == 1 || all_processes_arrive(errors, 10))
      {
        if (root)
          std::cerr << "ring_contact: error: " << message << std::endl;
        return 1;
      }
    std::cerr << "ring_contact: error (process " << this_process(world)
              << " of " << n << "): " << message << std::endl;
    MPI_Abort(world, 1);
    return 1;
  };

  try
    {
      const OutputParameters &output = parameters.output;

      // The output folder, held for the whole run (a run that writes no
      // file leaves the folder alone); process 0 holds it and writes the
      // history and the verdicts.
      const bool writes_files =
        output.write_history || output.vtu_interval > 0;
      std::unique_ptr<OutputFolder> folder;
      std::unique_ptr<HistoryFile>  history_file;
      if (writes_files)
        on_process_zero(world, [&]() {
          folder = std::make_unique<OutputFolder>(output.directory);
        });
      // An earlier run's files go, and the history starts, once the first
      // scheme is set up: a run whose input or mesh fails leaves them.
      bool       folder_ready   = !writes_files;
      const auto prepare_folder = [&]() {
        if (folder_ready)
          return;
        folder_ready = true;
        on_process_zero(world, [&]() {
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
              if (parameters.contact.friction_coefficient > 0)
                for (const char *column :
                     {"tangential_traction_A", "slipping_nodes"})
                  columns.emplace_back(column);
              history_file =
                std::make_unique<HistoryFile>(output.directory + "/history.csv",
                                              columns);
            }
        });
        // Each process writes its piece of the VTU files into the folder.
        if (n > 1)
          MPI_Barrier(world);
      };

      std::vector<Verdict> verdicts;
      bool                 solved  = true;
      const unsigned int   n_steps = LoadProgram(parameters.load).n_steps();
      // A stop asked of any process is a stop of all, after the same step.
      bool stop = false;
      for (const auto &scheme : parameters.contact.schemes)
        {
          if (stop)
            break;
          RingContactProblem problem(parameters, scheme, out, world);
          problem.set_start_observer(prepare_folder);
          problem.set_step_observer([&](const HistoryRow &row) {
            // Every process takes part (process 0's failure is all of
            // theirs): the condition is the same on all of them.
            if (output.write_history)
              on_process_zero(world, [&]() { history_file->append(row); });
            stop = stop_signal != 0;
            if (n > 1)
              stop = dealii::Utilities::MPI::logical_or(stop, world);
            return !stop;
          });
          solved = problem.run() && solved;
          if (n > 1)
            stop = dealii::Utilities::MPI::logical_or(stop_signal != 0, world);
          else
            stop = stop_signal != 0;
          // A scheme stopped by a signal before its last step has no
          // verdicts: its checks are not known.
          const auto &history = problem.history();
          if (stop && (history.empty() || history.back().step < n_steps))
            {
              out << "Stopped after "
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
            on_process_zero(world, [&]() {
              write_verdicts(output.directory + "/verdicts.csv", verdicts);
            });
        }
      if (stop)
        {
          if (!verdicts.empty())
            print_verdicts(out, verdicts);
          out << std::flush;
          // The signal this process received (under mpirun, SIGTERM).
          const int signal =
            stop_signal.load() != 0 ? stop_signal.load() : SIGTERM;
          if (root)
            std::cerr << "ring_contact: interrupted by "
                      << (signal == SIGINT ? "SIGINT" : "SIGTERM")
                      << ": the converged steps' results are complete"
                      << (output.write_history || output.vtu_interval > 0 ?
                            " in " + output.directory :
                            std::string())
                      << std::endl;
          return 128 + signal;
        }
      if (output.print_timing)
        {
          // The largest process's peak memory (what each machine needs).
          const std::size_t peak =
            n > 1 ? dealii::Utilities::MPI::max(peak_memory(), world) :
                    peak_memory();
          out << "Peak memory: " << (peak + (1 << 19)) / (1 << 20) << " MB"
              << (n > 1 ?
                    " (the largest of " + std::to_string(n) + " processes)" :
                    std::string())
              << "\n";
        }
      const bool pass = print_verdicts(out, verdicts);
      if (!solved)
        out << "A load step could not be solved (see above).\n";
      return (pass && solved) ? 0 : 1;
    }
  catch (const RingContact::Interrupted &e)
    {
      // Before the first step: nothing of this run was written, and an
      // earlier run's results are as they were.
      const int signal = stop_signal.load() != 0 ? stop_signal.load() : SIGTERM;
      if (n > 1 && !all_processes_arrive(errors, 10))
        MPI_Abort(world, 128 + signal);
      if (root)
        std::cerr << "ring_contact: interrupted by "
                  << (signal == SIGINT ? "SIGINT" : "SIGTERM") << " "
                  << e.what() << ", before the first step: nothing written"
                  << std::endl;
      return 128 + signal;
    }
  catch (const ParameterError &e)
    {
      // A value found wrong once the mesh is known: its file and line.
      return fail(parameters.located(e));
    }
  catch (const std::bad_alloc &)
    {
      return fail("out of memory (a smaller mesh, or 'Mesh/Sector elements' "
                  "for cyclic symmetry)");
    }
  catch (const std::exception &e)
    {
      return fail(one_line_message(e));
    }
  catch (...)
    {
      return fail("an unknown exception");
    }
}
