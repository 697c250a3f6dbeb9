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
#include <ring_contact/config.h>
#include <ring_contact/driver/mpi_session.h>
#include <ring_contact/driver/run.h>
#include <ring_contact/driver/signals.h>
#include <ring_contact/input/parameters.h>
#include <ring_contact/linear_algebra/linear_system.h>

#include <cstdio>
#include <iostream>
#include <string>

namespace
{
  const std::string usage = "usage: ring_contact <file.prm>\n"
                            "       mpirun -np N ring_contact <file.prm>\n"
                            "       ring_contact --print-parameters   (all "
                            "entries, defaults, docs)\n"
                            "       ring_contact --version\n";

  // --help, --version, --print-parameters: answered at once (true).
  bool
  answer_flag(const std::string &argument)
  {
    if (argument == "--help" || argument == "-h")
      std::cout << usage;
    else if (argument == "--version")
      std::cout << "ring_contact " RING_CONTACT_VERSION "\n";
    else if (argument == "--print-parameters")
      RingContact::Parameters::print_reference(std::cout, true);
    else
      return false;
    return true;
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
  if (argc != 2)
    {
      std::cerr << usage;
      return 2;
    }
  if (answer_flag(argv[1]))
    return 0;

  // MPI when mpirun started the process (before the file is read: every
  // process reads it, and an error in it is every process's).
  Driver::MpiSession mpi(argc, argv);
  Driver::install_signal_handlers(this_process(mpi.world()) == 0);
  Parameters parameters;
  try
    {
      parameters.read(argv[1]);
    }
  catch (const std::exception &e)
    {
      if (this_process(mpi.world()) == 0)
        std::cerr << "ring_contact: error: " << one_line_message(e)
                  << std::endl;
      return 1;
    }
  // Or when the file asks for a solver that needs it, on one process.
  mpi.start_for(parameters);
  return Driver::run(parameters, mpi.world());
}
