// @sect3{The run's driver: the command line}
//
// ring_contact [--set "Subsection/Entry=value" ...] <file.prm>, or one of
// --help, --version, --print-parameters. The --set entries are applied
// after the file, in their order, with the file's checks (their errors name
// them: "--set 2: ..."), and recorded in results/<name>/used_parameters.prm.
#ifndef ring_contact_driver_command_line_h
#define ring_contact_driver_command_line_h

#include <string>
#include <vector>

namespace RingContact
{
  namespace Driver
  {
    struct CommandLine
    {
      /// Parse the arguments; a flag is answered here (`answered`, with the
      /// exit code: 0, or 2 with the usage on stderr for a wrong command).
      CommandLine(const int argc, char **argv);

      std::string              prm_file;
      std::vector<std::string> overrides;
      bool                     answered  = false;
      int                      exit_code = 0;
    };
  } // namespace Driver
} // namespace RingContact

#endif
