// @sect3{The run's driver: MPI}
//
// A run started by mpirun (or srun) starts MPI before reading its file;
// one started alone starts it only if the file asks for a solver that
// needs it (MUMPS, the iterative one): starting MPI costs more than solving
// a modelisation. And an error of one process must not leave the others
// waiting in a collective call: an error every process met (a file or a
// mesh all of them read) ends the run cleanly, one that only some met
// aborts it (ErrorBarrier).
#ifndef ring_contact_driver_mpi_session_h
#define ring_contact_driver_mpi_session_h

#include <deal.II/base/mpi.h>

#include <ring_contact/input/parameters.h>

#include <functional>
#include <memory>
#include <string>

namespace RingContact
{
  namespace Driver
  {
    /// MPI for the run, if it needs it.
    class MpiSession
    {
    public:
      /// Start MPI if a process manager started this process.
      MpiSession(int &argc, char **&argv);

      /// Start MPI now if the parameters ask for a solver that needs it.
      void
      start_for(const Parameters &parameters);

      /// MPI_COMM_WORLD (whether or not MPI runs: one process without).
      MPI_Comm
      world() const
      {
        return MPI_COMM_WORLD;
      }

    private:
      int   &argc;
      char **&argv;
      std::unique_ptr<dealii::Utilities::MPI::MPI_InitFinalize> mpi;
    };

    /// The end of a run by an error: said once and a clean exit code when
    /// every process met it; said by the process that met it and the run
    /// aborted otherwise (the others wait for it in a collective call).
    class ErrorBarrier
    {
    public:
      explicit ErrorBarrier(const MPI_Comm world);
      ~ErrorBarrier();

      /// Say `message` and return `exit_code` (or abort).
      int
      fail(const std::string &message, const int exit_code = 1) const;

      /// Whether every process reaches this point within `seconds`.
      bool
      all_processes_arrive(const double seconds) const;

    private:
      const MPI_Comm world;
      /// A communicator of its own, apart from the run's communication.
      MPI_Comm communicator = MPI_COMM_NULL;
    };

    /// Run `f` on process 0 only (a file of the results folder) and make
    /// its failure that of every process: the exception's message is sent
    /// to all, and each throws it.
    void
    on_process_zero(const MPI_Comm world, const std::function<void()> &f);
  } // namespace Driver
} // namespace RingContact

#endif
