// @sect3{The run's driver: the schemes, the results folder, the verdicts}
//
// A run solves the problem of its parameter file once per contact
// integration scheme it lists, writes results/<prm name>/history.csv and
// the VTU/PVD files, prints the verdict table of the checks and ends with
// an exit code that says how it went.
//
// Results are never lost or mixed: the run holds its output folder (a
// second run into it is refused) and removes what an earlier run left
// there only once its input and mesh are found good; history.csv grows by
// one row per converged step, on disk before the next step starts, and
// verdicts.csv is written as soon as a scheme is done. SIGINT or SIGTERM
// ends the run after the current step's files are complete (exit code 130
// or 143); a second signal ends it at once.
//
// Under MPI (mpirun -np N ring_contact file.prm) every process runs the
// problem (see LinearSystem); process 0 alone prints and writes the history
// and verdicts, each process writes its piece of the VTU files.
#ifndef ring_contact_driver_run_h
#define ring_contact_driver_run_h

#include <deal.II/base/mpi.h>

#include <ring_contact/input/parameters.h>

namespace RingContact
{
  namespace Driver
  {
    /// The program's exit codes (doc/output.md lists them); an interrupted run
    /// ends with 128 + the signal (130 for SIGINT, 143 for SIGTERM).
    namespace ExitCode
    {
      /// Every step solved and every check passed.
      constexpr int success = 0;
      /// Every step solved, a check failed.
      constexpr int check_failed = 1;
      /// The input refused: the command line, the parameter file, the
      /// mesh, or a problem the program cannot pose (before any step).
      constexpr int input_refused = 2;
      /// A load step could not be solved, or the run could not go on.
      constexpr int step_failed = 3;
    } // namespace ExitCode

    /// Run every scheme of the parameters; the exit code of the program.
    int
    run(const Parameters &parameters, const MPI_Comm world);
  } // namespace Driver
} // namespace RingContact

#endif
