// @sect3{The run's driver: MPI when it is needed, and errors under MPI}
//
// Two concerns of a run under mpirun that the rest of the program need
// not know. Starting MPI costs about a second with Open MPI, more than
// solving a modelisation, so a run started alone starts it only when its
// file asks for a solver that needs it. And an error must end every
// process: a process that leaves while the others wait for it in a
// collective call would hang the run for ever, so an error is reported
// through a barrier with a timeout, and a run whose processes do not all
// arrive there is aborted.
#include <ring_contact/base/utilities.h>
#include <ring_contact/driver/mpi_session.h>
#include <ring_contact/linear_algebra/linear_system.h>

#include <chrono>
#include <cstdlib>
#include <iostream>
#include <signal.h>
#include <stdexcept>
#include <thread>

namespace RingContact
{
  namespace Driver
  {
    namespace
    {
      // Whether a process manager (OpenMPI's or MPICH's mpirun, srun)
      // started this process. Asked of the environment, where each
      // manager leaves its variables, because asking MPI would need MPI
      // started: the very cost a serial run avoids.
      bool
      launched_by_mpirun()
      {
        for (const char *variable :
             {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK", "PMI_RANK"})
          if (std::getenv(variable) != nullptr)
            return true;
        return false;
      }
    } // namespace

    MpiSession::MpiSession(int &argc, char **&argv)
        : argc(argc)
        , argv(argv)
    {
      // The 1 is deal.II's thread limit: these problems are too small for
      // threads to pay, and under MPI there is a process per core.
      if (launched_by_mpirun())
        mpi = std::make_unique<dealii::Utilities::MPI::MPI_InitFinalize>(argc,
                                                                         argv,
                                                                         1);
    }

    // MUMPS and the iterative solver work on Trilinos's matrix, and even
    // an empty Trilinos object needs MPI: a run of one process that asks
    // for them starts it now, once its file is read. The run's handlers of
    // SIGINT and SIGTERM (signals.cc), installed before, are kept: deal.II
    // starts PETSc there and removes PETSc's handlers, which set SIGTERM
    // back to its default action, and a SIGTERM then killed a MUMPS run at
    // once, a converged step's row of history.csv not yet written (found by
    // killing Hertz 3D after its first step).
    void
    MpiSession::start_for(const Parameters &parameters)
    {
      if (mpi ||
          (parameters.newton.linear_solver != LinearSolverType::mumps &&
           parameters.newton.linear_solver != LinearSolverType::iterative))
        return;
      struct sigaction interrupt, termination;
      sigaction(SIGINT, nullptr, &interrupt);
      sigaction(SIGTERM, nullptr, &termination);
      mpi = std::make_unique<dealii::Utilities::MPI::MPI_InitFinalize>(argc,
                                                                       argv,
                                                                       1);
      sigaction(SIGINT, &interrupt, nullptr);
      sigaction(SIGTERM, &termination, nullptr);
    }

    // A communicator of its own: on the run's, the barrier could be paired
    // with a collective call of the run that another process is waiting
    // in, a mismatch that MPI leaves undefined.
    // Freed by the destructor, before MPI ends (the session outlives the
    // barrier).
    ErrorBarrier::ErrorBarrier(const MPI_Comm world)
        : world(world)
    {
      if (n_processes(world) > 1)
        MPI_Comm_dup(world, &communicator);
    }

    ErrorBarrier::~ErrorBarrier()
    {
      if (communicator != MPI_COMM_NULL)
        MPI_Comm_free(&communicator);
    }

    // A non-blocking barrier, polled every millisecond, instead of
    // MPI_Barrier: a process that never arrives (it waits elsewhere, or
    // loops) would hold MPI_Barrier for ever, and the run with it.
    bool
    ErrorBarrier::all_processes_arrive(const double seconds) const
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

    // An error that every process met (the parameter file, the mesh) is
    // said once, by process 0, and the run ends with its exit code. One
    // that only some met is said by each of those, naming the process,
    // and MPI_Abort ends the others after ten seconds, rather than leave
    // them waiting.
    int
    ErrorBarrier::fail(const std::string &message, const int exit_code) const
    {
      const unsigned int n = n_processes(world);
      if (n == 1 || all_processes_arrive(10))
        {
          if (this_process(world) == 0)
            std::cerr << "ring_contact: error: " << message << std::endl;
          return exit_code;
        }
      std::cerr << "ring_contact: error (process " << this_process(world)
                << " of " << n << "): " << message << std::endl;
      MPI_Abort(world, exit_code);
      return exit_code;
    }

    // For the files only process 0 writes (the lock, history.csv,
    // verdicts.csv): its failure, a full disk among others, becomes every
    // process's exception with the same message, so that all processes
    // leave the run the same way. Collective: every process must call it,
    // whether or not it has anything to do (a call made on process 0 alone
    // once passed the tests by luck).
    void
    on_process_zero(const MPI_Comm world, const std::function<void()> &f)
    {
      std::string error;
      if (this_process(world) == 0)
        try
          {
            f();
          }
        catch (const std::exception &e)
          {
            error = one_line_message(e);
          }
      if (n_processes(world) > 1)
        error = dealii::Utilities::MPI::broadcast(world, error, 0);
      if (!error.empty())
        throw std::runtime_error(error);
    }
  } // namespace Driver
} // namespace RingContact
