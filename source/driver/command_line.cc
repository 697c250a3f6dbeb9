// @sect3{The run's driver: the command line}
//
// The arguments of the program (command_line.h). A wrong command is a
// refused input: the usage on stderr and exit code 2, as for a wrong file.
#include <ring_contact/config.h>
#include <ring_contact/driver/command_line.h>
#include <ring_contact/driver/run.h>
#include <ring_contact/input/parameters.h>

#include <iostream>

namespace RingContact
{
  namespace Driver
  {
    namespace
    {
      const std::string usage =
        "usage: ring_contact [--set \"Subsection/Entry=value\" ...] <file.prm>\n"
        "       mpirun -np N ring_contact <file.prm>\n"
        "       ring_contact --print-parameters   (all entries, defaults, docs)\n"
        "       ring_contact --version\n"
        "exit codes: 0 every check passes, 1 a check fails, 2 the input is\n"
        "refused, 3 a step cannot be solved, 130/143 interrupted\n";

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

    CommandLine::CommandLine(const int argc, char **argv)
    {
      if (argc == 2 && answer_flag(argv[1]))
        {
          answered = true;
          return;
        }
      // The file may be named by an empty argument: the reader refuses it
      // with its own message, as any other name of no file.
      bool have_file = false, wrong = false;
      for (int i = 1; i < argc && !wrong; ++i)
        {
          const std::string argument = argv[i];
          if (argument == "--set" && i + 1 < argc)
            overrides.emplace_back(argv[++i]);
          else if (argument.rfind("--set=", 0) == 0)
            overrides.push_back(argument.substr(6));
          else if (!have_file && argument.rfind("-", 0) != 0)
            {
              prm_file  = argument;
              have_file = true;
            }
          else
            // An unknown option, a second file, or --set without its
            // entry.
            wrong = true;
        }
      if (wrong || !have_file)
        {
          std::cerr << usage;
          answered  = true;
          exit_code = ExitCode::input_refused;
        }
    }
  } // namespace Driver
} // namespace RingContact
