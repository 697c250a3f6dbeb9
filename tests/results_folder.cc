// One run per results folder, nothing left of an earlier run, nothing lost
// when a write fails. The real executable (modelisation A):
// - lock: a second run into the folder of a live run (400 steps: it lives
//   while the second starts) is refused with a message naming the folder
//   and the first run's pid; the first run is then stopped (SIGTERM) and
//   its files read back whole;
// - rerun: a shorter run with one scheme into the folder of a longer run
//   with two removes the earlier history, verdicts, VTU and PVD files (and
//   says so) but no other file;
// - failed start: a run whose mesh lacks the contact boundary it names
//   fails before its first step and leaves the earlier run's files whole;
// - foreign files: a folder no run has used, holding a 'history.csv' of
//   the user's, is refused and the file left untouched;
// - a file size limit (RLIMIT_FSIZE, as a full disk: write() fails) hit by
//   history.csv, then by a VTU file: a one-line error naming the file, exit
//   code 1, every row before it whole, no temporary file left.
#include "run_program.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

using RingContactTests::check;
using RingContactTests::count_rows;

namespace
{
  std::string
  write_prm(const std::string &name,
            const unsigned int steps,
            const std::string &schemes,
            const unsigned int vtu_interval)
  {
    std::ofstream prm(name + ".prm");
    prm << "include " RING_CONTACT_SOURCE_DIR "/prm/ssnp152a.prm\n"
        << "subsection Load program\n set Ramp steps = "
        << steps
        // A long run stays on A's ramp (p up to 1e7): beyond it the pressure
        // grows tenfold every 10 steps and Newton fails near step 38.
        << (steps > 21 ? "\n set Time step = " + std::to_string(2.1 / steps) :
                         std::string())
        << "\nend\n"
        << "subsection Contact\n set Integration schemes = " << schemes
        << "\nend\n"
        << "subsection Output\n set Directory = results_" << name
        << "\n set VTU interval = " << vtu_interval
        << "\n set Print timing = false\n set Print steps = true\nend\n"
           "subsection Newton\n set Verbose = false\nend\n";
    return name + ".prm";
  }

  unsigned int
  count_files(const std::string &folder, const std::string &extension)
  {
    unsigned int n = 0;
    for (const auto &entry : std::filesystem::directory_iterator(folder))
      n += entry.path().extension() == extension;
    return n;
  }

  std::string
  last_line(const RingContactTests::RunResult &result)
  {
    return result.lines.empty() ? std::string() : result.lines.back();
  }

  void
  lock()
  {
    auto                       &out = RingContactTests::deallog_file;
    RingContactTests::RunResult second;
    pid_t                       first_pid = 0;
    const auto                  first     = RingContactTests::run_program(
      write_prm("lock", 400, "nodal, Gauss 3", 1),
      [&](const std::string &line, const pid_t pid) {
        if (RingContactTests::RunResult::step_of(line) > 0 && first_pid == 0)
          {
            first_pid = pid;
            second = RingContactTests::run_program("lock.prm");
            ::kill(pid, SIGTERM);
          }
      });
    const std::string message = last_line(second);
    check(second.exit_code == 2,
          "lock: the second run fails, exit code " +
            std::to_string(second.exit_code));
    check(message.find("'results_lock'") != std::string::npos &&
            message.find("pid " + std::to_string(first_pid)) !=
              std::string::npos,
          "lock: the message names the folder and the pid: " + message);
    check(second.steps_printed() == 0, "lock: the second run solved nothing");
    check(first.exit_code == 143,
          "lock: the first run stopped by SIGTERM, exit code " +
            std::to_string(first.exit_code));
    const unsigned int rows = count_rows("results_lock/history.csv");
    check(rows == first.steps_printed(),
          "lock: the first run's rows: " + std::to_string(rows) + " rows for " +
            std::to_string(first.steps_printed()) + " steps printed");
    check(RingContactTests::check_results(
            "results_lock",
            "--quiet --all-listed --vtu-every-step --rows " +
              std::to_string(rows)),
          "lock: the first run's files read back whole");
    std::string shown = message;
    shown.replace(shown.find(std::to_string(first_pid)),
                  std::to_string(first_pid).size(),
                  "<pid>");
    out << "lock: second run refused: " << shown << std::endl;
    out << "lock: first run's files whole after SIGTERM" << std::endl;
  }

  void
  rerun()
  {
    auto      &out = RingContactTests::deallog_file;
    const auto first =
      RingContactTests::run_program(write_prm("rerun", 6, "nodal, Gauss 3", 1));
    check(first.exit_code == 0, "rerun: the first run");
    check(count_rows("results_rerun/history.csv") == 12 &&
            count_files("results_rerun", ".vtu") == 28 &&
            count_files("results_rerun", ".pvd") == 4,
          "rerun: the first run's files");
    // 6 steps and step 0, bulk and surface, two schemes: 28 VTU files.
    // Files this program does not write stay.
    std::ofstream("results_rerun/notes.txt") << "mine\n";
    std::ofstream("results_rerun/mesh.vtu") << "mine\n";
    const auto second =
      RingContactTests::run_program(write_prm("rerun", 3, "nodal", 1));
    check(second.exit_code == 0, "rerun: the second run");
    const auto removal = std::find_if(second.lines.begin(),
                                      second.lines.end(),
                                      [](const std::string &line) {
                                        return line.rfind("Removed", 0) == 0;
                                      });
    check(removal != second.lines.end() &&
            removal->find("the 36 files of an earlier run") !=
              std::string::npos,
          "rerun: the second run says what it removed");
    out << "rerun: " << *removal << std::endl;
    check(count_rows("results_rerun/history.csv") == 3 &&
            count_rows("results_rerun/verdicts.csv") == 3 &&
            count_files("results_rerun", ".vtu") == 2 * (3 + 1) + 1 &&
            count_files("results_rerun", ".pvd") == 2,
          "rerun: only the second run's files");
    check(std::filesystem::exists("results_rerun/notes.txt") &&
            std::filesystem::exists("results_rerun/mesh.vtu"),
          "rerun: other files stay");
    std::filesystem::remove("results_rerun/mesh.vtu");
    check(RingContactTests::check_results(
            "results_rerun", "--quiet --all-listed --vtu-every-step --rows 3"),
          "rerun: the second run's files read back whole");
    out << "rerun: 3 rows, 8 VTU files (step 0 too), 2 PVD files; other "
           "files kept"
        << std::endl;
  }

  // A run whose input fails before its first step (a contact boundary the
  // mesh does not have) leaves the earlier run's files as they were.
  void
  failed_start()
  {
    auto             &out = RingContactTests::deallog_file;
    const std::string prm = write_prm("rerun", 3, "nodal", 1);
    std::ofstream(prm, std::ios::app)
      << "subsection Contact\n set Slave boundary = 999\nend\n";
    const auto result = RingContactTests::run_program(prm);
    check(result.exit_code == 2,
          "failed start: exit code " + std::to_string(result.exit_code));
    check(!result.printed("earlier run"), "failed start: nothing said removed");
    check(count_rows("results_rerun/history.csv") == 3 &&
            count_files("results_rerun", ".vtu") == 2 * (3 + 1) &&
            count_files("results_rerun", ".pvd") == 2,
          "failed start: the earlier run's files are all there");
    check(RingContactTests::check_results(
            "results_rerun", "--quiet --all-listed --vtu-every-step --rows 3"),
          "failed start: the earlier run's files read back whole");
    out << "failed start: " << last_line(result) << std::endl;
    out << "failed start: the earlier run's 3 rows, 8 VTU and 2 PVD files "
           "kept whole"
        << std::endl;
  }

  // A folder no run of this program has used, holding a file with the name
  // of one of its results: refused before anything is written, the file
  // untouched, no lock file left (which would mark the folder as used).
  void
  foreign_files()
  {
    auto &out = RingContactTests::deallog_file;
    std::filesystem::create_directories("results_foreign");
    std::ofstream("results_foreign/history.csv") << "my,own,data\n";
    const auto result =
      RingContactTests::run_program(write_prm("foreign", 3, "nodal", 0));
    const std::string message = last_line(result);
    check(result.exit_code == 2,
          "foreign: exit code " + std::to_string(result.exit_code));
    check(message.find("'results_foreign'") != std::string::npos &&
            message.find("'history.csv'") != std::string::npos,
          "foreign: the message names the folder and the file: " + message);
    std::ifstream     in("results_foreign/history.csv");
    std::stringstream contents;
    contents << in.rdbuf();
    check(contents.str() == "my,own,data\n", "foreign: the file is untouched");
    check(!std::filesystem::exists("results_foreign/.ring_contact.lock"),
          "foreign: no lock file left");
    out << "foreign: " << message << std::endl;
  }

  void
  file_size_limit(const std::string &name,
                  const unsigned int vtu_interval,
                  const rlim_t       limit,
                  const std::string &expected_file)
  {
    auto      &out = RingContactTests::deallog_file;
    const auto result =
      RingContactTests::run_program(write_prm(name, 21, "nodal", vtu_interval),
                                    {},
                                    limit);
    const std::string message = last_line(result);
    check(result.exit_code == 3,
          name + ": exit code " + std::to_string(result.exit_code));
    check(message.rfind("ring_contact: error: cannot write '", 0) == 0 &&
            message.find(expected_file) != std::string::npos,
          name + ": the message names the file: " + message);
    const std::string  folder        = "results_" + name;
    const unsigned int steps_printed = result.steps_printed();
    const unsigned int rows          = count_rows(folder + "/history.csv");
    // The step whose file could not be written is printed, not recorded.
    check(steps_printed >= 1 && rows + 1 == steps_printed,
          name + ": " + std::to_string(rows) + " rows for " +
            std::to_string(steps_printed) + " steps printed");
    check(RingContactTests::check_results(folder,
                                          "--quiet --all-listed --rows " +
                                            std::to_string(rows)),
          name + ": the files before read back whole");
    out << name << ": " << message << std::endl;
    out << name << ": history.csv whole, one row per step before it"
        << std::endl;
  }
} // namespace

namespace
{
  // A symbolic link planted under the lock file's name: refused, its
  // target untouched (the lock was opened through it and the pid written
  // into the target).
  void
  planted_lock_link()
  {
    auto &out = RingContactTests::deallog_file;
    std::filesystem::remove_all("results_link");
    std::filesystem::create_directories("results_link");
    std::ofstream("victim.txt") << "precious\n";
    std::filesystem::create_symlink(std::filesystem::absolute("victim.txt"),
                                    "results_link/.ring_contact.lock");
    const auto result =
      RingContactTests::run_program(write_prm("link", 3, "nodal", 0));
    const std::string message = last_line(result);
    check(result.exit_code == 2,
          "planted link: exit code " + std::to_string(result.exit_code));
    check(message.find("is a symbolic link") != std::string::npos,
          "planted link: the message says so: " + message);
    std::ifstream     in("victim.txt");
    std::stringstream contents;
    contents << in.rdbuf();
    check(contents.str() == "precious\n",
          "planted link: the link's target is untouched");
    out << "planted link: " << message << std::endl;
  }
} // namespace

int
main()
{
  lock();
  rerun();
  failed_start();
  foreign_files();
  planted_lock_link();
  // used_parameters.prm (about 2.6 kB) and about five rows of history.csv
  // fit in 3000 bytes.
  file_size_limit("fsize_history",
                  0,
                  3000,
                  "results_fsize_history/history.csv");
  // A VTU file does not fit in 8000 bytes.
  file_size_limit("fsize_vtu", 1, 8000, "solution-nodal-0001.vtu");
}
