// The record of a run and what its exit code says (issue 30):
// - the exit code of each kind of ending: 0 every check passes, 1 a check
//   fails, 2 the input is refused (a missing file, an unknown entry or a
//   value out of range given with --set, a wrong command), 3 a load step
//   cannot be solved (interrupted runs, 130 and 143: test interrupt);
// - --set "Subsection/Entry=value" overrides the file and is recorded;
// - results/<name>/used_parameters.prm runs the same problem again: its
//   history.csv equals the first run's in every column but wall_time, and
//   its verdicts.csv byte for byte;
// - results/<name>/run.log holds what the terminal showed.
#include "run_program.h"

#include <filesystem>
#include <fstream>
#include <sstream>

using RingContactTests::check;

namespace
{
  // history.csv without its wall_time column.
  std::string
  history_without_wall_time(const std::string &filename)
  {
    std::ifstream in(filename);
    std::string   line, out;
    int           skip = -1;
    while (std::getline(in, line))
      {
        std::vector<std::string> fields;
        std::stringstream        row(line);
        for (std::string field; std::getline(row, field, ',');)
          fields.push_back(field);
        if (skip < 0)
          for (unsigned int k = 0; k < fields.size(); ++k)
            if (fields[k] == "wall_time")
              skip = k;
        for (unsigned int k = 0; k < fields.size(); ++k)
          if (static_cast<int>(k) != skip)
            out += fields[k] + ",";
        out += "\n";
      }
    return out;
  }

  RingContactTests::RunResult
  run(const std::vector<std::string> &arguments)
  {
    std::vector<std::string> command = {RING_CONTACT_EXECUTABLE};
    command.insert(command.end(), arguments.begin(), arguments.end());
    return RingContactTests::run_command(command);
  }

  const std::string a = SOURCE_DIR "/../prm/ssnp152a.prm";
} // namespace

int
main()
{
  auto &out = RingContactTests::deallog_file;
  // A rerun of the test starts from nothing (a folder of an earlier run
  // would add the line that says what was removed).
  for (const char *folder : {"pass", "fail", "unsolved", "first", "again"})
    std::filesystem::remove_all(folder);
  const std::vector<std::string> quiet = {"--set",
                                          "Output/VTU interval=0",
                                          "--set",
                                          "Output/Print timing=false"};
  const auto with = [&](std::vector<std::string> arguments) {
    arguments.insert(arguments.begin(), quiet.begin(), quiet.end());
    return run(arguments);
  };

  // Exit codes.
  struct Case
  {
    std::string              name;
    std::vector<std::string> arguments;
    int                      expected;
  };
  const std::vector<Case> cases = {
    {"every check passes", {"--set", "Output/Directory=pass", a}, 0},
    {"a check fails",
     {"--set", "Output/Directory=fail", "--set", "Checks/Tolerance=1e-9", a},
     1},
    {"a missing parameter file", {"no_such_file.prm"}, 2},
    {"an unknown entry given with --set", {"--set", "Newton/Bogus=1", a}, 2},
    {"a value out of range given with --set",
     {"--set", "Mesh/Elements around=2", a},
     2},
    {"--set without Subsection/Entry=value", {"--set", "Tolerance", a}, 2},
    {"an unknown option", {"--bogus", a}, 2},
    {"a step that cannot be solved",
     {"--set",
      "Output/Directory=unsolved",
      "--set",
      "Newton/Maximum iterations=1",
      "--set",
      "Newton/Maximum step cuts=0",
      a},
     3}};
  for (const auto &c : cases)
    {
      const auto result = with(c.arguments);
      out << c.name << ": exit code " << result.exit_code << std::endl;
      check(result.exit_code == c.expected,
            c.name + ": exit code " + std::to_string(result.exit_code) +
              ", expected " + std::to_string(c.expected));
    }
  {
    // The quiet entries are --set 1 and 2.
    const auto result = with({"--set", "Newton/Bogus=1", a});
    check(result.printed("ring_contact: error: --set 3: no entry 'Bogus' in "
                         "subsection 'Newton'"),
          "an error of --set names it");
  }

  // The record: used_parameters.prm holds the overrides, and runs again.
  {
    const auto first = with({"--set",
                             "Output/Directory=first",
                             "--set",
                             "Load program/Ramp steps=7",
                             a});
    check(first.exit_code == 0, "first run");
    const std::string used =
      RingContactTests::file_contents("first/used_parameters.prm");
    check(used.find("  set Ramp steps = 7\n") != std::string::npos &&
            used.find("#   Load program/Ramp steps\n") != std::string::npos,
          "the override is recorded as set on the command line");
    check(RingContactTests::count_rows("first/history.csv") == 2 * 7,
          "the override acts: 7 steps of each of A's two schemes");
    const auto again =
      run({"--set",
           "Output/Directory=" + std::filesystem::current_path().string() +
             "/again",
           "first/used_parameters.prm"});
    check(again.exit_code == 0, "rerun from used_parameters.prm");
    check(history_without_wall_time("first/history.csv") ==
            history_without_wall_time("again/history.csv"),
          "the rerun's history equals the first's (wall_time aside)");
    check(RingContactTests::file_contents("first/verdicts.csv") ==
            RingContactTests::file_contents("again/verdicts.csv"),
          "the rerun's verdicts equal the first's");
    out << "used_parameters.prm: the rerun's history.csv and verdicts.csv "
           "equal the first run's"
        << std::endl;

    // run.log: the terminal's lines, in order.
    std::string terminal;
    for (const auto &line : first.lines)
      terminal += line + "\n";
    check(RingContactTests::file_contents("first/run.log") == terminal,
          "run.log holds what the terminal showed");
    out << "run.log: the terminal's lines, in order" << std::endl;
  }
}
