// ring_contact: SSNP152 with deal.II. Usage: ring_contact <file.prm>
//
// Runs the modelisation described by the parameter file once per contact
// integration scheme it lists, writes results/<prm name>/history.csv and
// the VTU/PVD files, prints the verdict table of the checks and exits with
// a non-zero code if a check fails or a step cannot be solved.
#include <deal.II/base/multithread_info.h>

#include <ring_contact/parameters.h>
#include <ring_contact/postprocessing.h>
#include <ring_contact/ring_contact_problem.h>
#include <ring_contact/utilities.h>

#include <filesystem>
#include <iostream>

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

  const std::string usage = "usage: ring_contact <file.prm>\n"
                            "       ring_contact --print-parameters   (all "
                            "entries, defaults, docs)\n";
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
  if (argument == "--print-parameters")
    {
      Parameters::print_reference(std::cout, true);
      return 0;
    }

  try
    {
      Parameters parameters;
      parameters.read(argument);
      std::filesystem::create_directories(parameters.output.directory);

      std::vector<HistoryRow> history;
      std::vector<Verdict>    verdicts;
      bool                    solved = true;
      for (const auto &scheme : parameters.contact.schemes)
        {
          RingContactProblem problem(parameters, scheme, std::cout);
          solved = problem.run() && solved;
          history.insert(history.end(),
                         problem.history().begin(),
                         problem.history().end());
          const auto v = evaluate_checks(parameters.checks, problem.history());
          verdicts.insert(verdicts.end(), v.begin(), v.end());
        }
      if (parameters.output.write_history)
        {
          write_history(parameters.output.directory + "/history.csv", history);
          write_verdicts(parameters.output.directory + "/verdicts.csv",
                         verdicts);
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
