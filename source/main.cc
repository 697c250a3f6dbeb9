// @sect3{The main function}
//
// ring_contact: elastic bodies in contact with deal.II, and the rings of
// Code_Aster's validation case of doc/intro.md. Usage: ring_contact
// <file.prm>.
//
// As a deal.II tutorial's main(): read the parameters, then run; the run
// (driver/run.h) solves the problem once per contact integration scheme of
// the file, writes the results and ends with an exit code that says how
// it went. Under MPI, mpirun -np N ring_contact <file.prm>.
#include <deal.II/base/multithread_info.h>

#include <ring_contact/base/utilities.h>
#include <ring_contact/driver/command_line.h>
#include <ring_contact/driver/mpi_session.h>
#include <ring_contact/driver/run.h>
#include <ring_contact/driver/run_log.h>
#include <ring_contact/driver/signals.h>
#include <ring_contact/input/parameters.h>
#include <ring_contact/linear_algebra/linear_system.h>

#include <cstdio>
#include <iostream>
#include <string>


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
  // --help, --version, --print-parameters, or the file and the entries
  // the command line sets over it.
  const Driver::CommandLine command_line(argc, argv);
  if (command_line.answered)
    return command_line.exit_code;

  // MPI when mpirun started the process (before the file is read: every
  // process reads it, and an error in it is every process's).
  Driver::MpiSession mpi(argc, argv);
  Driver::install_signal_handlers(this_process(mpi.world()) == 0);
  // What the terminal shows goes to results/<name>/run.log too.
  const Driver::RunLog log;
  Parameters           parameters;
  try
    {
      parameters.read(command_line.prm_file, command_line.overrides);
    }
  catch (const std::exception &e)
    {
      if (this_process(mpi.world()) == 0)
        std::cerr << "ring_contact: error: " << one_line_message(e)
                  << std::endl;
      return Driver::ExitCode::input_refused;
    }
  // Or when the file asks for a solver that needs it, on one process.
  mpi.start_for(parameters);
  return Driver::run(parameters, mpi.world());
}
