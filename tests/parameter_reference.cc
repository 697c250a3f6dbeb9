// doc/parameters.prm, the parameter reference the documents point to, is
// what `ring_contact --print-parameters` prints: every entry, its default
// and its documentation, line for line. (It drifted by four lines once.)
// Regenerate it with `build/ring_contact --print-parameters >
// doc/parameters.prm`.
#include "run_program.h"

#include <fstream>

using RingContactTests::check;

int
main()
{
  const auto printed =
    RingContactTests::run_command({RING_CONTACT_EXECUTABLE,
                                   "--print-parameters"});
  check(printed.exit_code == 0, "--print-parameters runs");
  std::ifstream            in(SOURCE_DIR "/../doc/parameters.prm");
  std::vector<std::string> documented;
  for (std::string line; std::getline(in, line);)
    documented.push_back(line);
  unsigned int first_difference = 0;
  while (first_difference < documented.size() &&
         first_difference < printed.lines.size() &&
         documented[first_difference] == printed.lines[first_difference])
    ++first_difference;
  check(documented.size() == printed.lines.size() &&
          first_difference == documented.size(),
        "doc/parameters.prm differs from --print-parameters from line " +
          std::to_string(first_difference + 1));
  RingContactTests::deallog_file
    << "doc/parameters.prm: the " << documented.size()
    << " lines of --print-parameters" << std::endl;
}
