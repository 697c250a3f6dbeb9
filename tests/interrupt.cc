// SIGINT and SIGTERM end a run after the current step's files are complete:
// the real executable (modelisation A, two schemes, a VTU file every step)
// is sent a signal at several points of its run, while it sets up, while it
// writes a step's VTU files (just after the step's line is printed), in the
// first and in the second scheme. Each time: the signal is acknowledged
// when received, the exit code is 128 + the signal, the message says so,
// history.csv has one whole row per step printed, verdicts.csv holds
// exactly the schemes that finished, every .pvd and every .vtu it lists
// read back whole with VTK, and no temporary file is left. A second signal
// ends the run at once; the files on disk are still whole, and the next run
// into the folder removes the leftovers. A signal while gmsh meshes a
// script that never ends stops the run at once.
#include "run_program.h"

#include <chrono>
#include <fstream>
#include <sstream>
#include <thread>

using RingContactTests::check;
using RingContactTests::count_rows;

namespace
{
  // Modelisation A with `steps` ramp steps into the folder `name`.
  std::string
  write_prm(const std::string &name,
            const unsigned int steps  = 21,
            const std::string &solver = "")
  {
    std::ofstream prm(name + ".prm");
    prm << "include " RING_CONTACT_SOURCE_DIR "/prm/ssnp152a.prm\n"
        << "subsection Load program\n set Ramp steps = " << steps << "\nend\n"
        << "subsection Output\n set Directory = " << name
        << "\n set VTU interval = 1\n set Print timing = false\n"
           " set Print steps = true\nend\n"
           "subsection Newton\n set Verbose = false\n"
        << (solver.empty() ? "" : " set Linear solver = " + solver + "\n")
        << "end\n";
    return name + ".prm";
  }

  // The step number of a step line (" 3/100 ..."), 0 for any other line.
  unsigned int
  step_of(const std::string &line)
  {
    return RingContactTests::RunResult::step_of(line);
  }

  // Send `signal` (and `second_signal`, if not 0, right after it) when the
  // run prints step `step` of scheme number `scheme` (1, 2), or, with
  // step = 0, when it starts that scheme; the run's linear `solver` if
  // given (MUMPS starts MPI, and PETSc with it, once the file is read).
  void
  interrupt(const std::string &name,
            const int          signal,
            const unsigned int scheme,
            const unsigned int step,
            const int          second_signal = 0,
            const std::string &solver        = "")
  {
    auto        &out     = RingContactTests::deallog_file;
    unsigned int current = 0;
    bool         sent    = false;
    const auto   result  = RingContactTests::run_program(
      write_prm(name, 21, solver),
      [&](const std::string &line, const pid_t pid) {
        if (line.rfind("Scheme ", 0) == 0)
          ++current;
        if (!sent && current == scheme &&
            (step == 0 ? line.rfind("Scheme ", 0) == 0 : step_of(line) == step))
          {
            ::kill(pid, signal);
            if (second_signal != 0)
              ::kill(pid, second_signal);
            sent = true;
          }
      });
    const std::string what = name + " (" +
                             (signal == SIGINT ? "SIGINT" : "SIGTERM") +
                             (second_signal != 0 ? ", then SIGTERM" : "") + ")";
    check(sent, what + ": the signal was sent");
    const unsigned int steps_printed = result.steps_printed();
    const unsigned int rows          = count_rows(name + "/history.csv");
    const bool         verdicts = std::ifstream(name + "/verdicts.csv").good();
    if (second_signal == 0)
      {
        check(result.exit_code == 128 + signal,
              what + ": exit code " + std::to_string(result.exit_code));
        check(result.printed("stopping once the results on disk are whole"),
              what + ": the signal acknowledged when received");
        check(result.printed(std::string("interrupted by ") +
                             (signal == SIGINT ? "SIGINT" : "SIGTERM")),
              what + ": the message");
        check(rows == steps_printed,
              what + ": " + std::to_string(rows) + " rows for " +
                std::to_string(steps_printed) + " steps printed");
        // verdicts.csv: the finished schemes only (21 checks each).
        unsigned int finished = 0;
        for (const auto &line : result.lines)
          finished += step_of(line) == 21;
        check(verdicts == (finished > 0) &&
                (finished == 0 ||
                 count_rows(name + "/verdicts.csv") == 21 * finished),
              what + ": verdicts.csv of the finished schemes");
        check(RingContactTests::check_results(
                name,
                "--quiet --all-listed --vtu-every-step --rows " +
                  std::to_string(rows)),
              what + ": the files read back whole");
        out << what << ": exit code " << result.exit_code
            << ", history rows = steps printed, verdicts.csv "
            << (verdicts ?
                  "of " + std::to_string(finished) + " finished scheme(s)" :
                  std::string("not written"))
            << ", .pvd and .vtu whole" << std::endl;
      }
    else
      {
        // Killed by the second signal (whichever of the two the kernel
        // delivered second): the rows on disk are whole (the step being
        // written may be missing), a temporary may be left.
        check((result.signal == signal || result.signal == second_signal) &&
                result.exit_code == -1,
              what + ": killed by the second signal; exit code " +
                std::to_string(result.exit_code) + ", signal " +
                std::to_string(result.signal));
        check(rows == steps_printed || rows + 1 == steps_printed,
              what + ": " + std::to_string(rows) + " rows for " +
                std::to_string(steps_printed) + " steps printed");
        check(RingContactTests::check_results(
                name,
                "--quiet --allow-temporaries --rows " + std::to_string(rows)),
              what + ": the files read back whole");
        out << what << ": killed by the second signal, history rows whole, "
            << ".pvd and .vtu whole" << std::endl;

        // The next run into the folder starts clean.
        const auto rerun = RingContactTests::run_program(write_prm(name, 3));
        check(rerun.exit_code == 0, what + ": the rerun succeeds");
        check(rerun.printed("files of an earlier run"),
              what + ": the rerun says it removed the earlier files");
        check(RingContactTests::check_results(
                name, "--quiet --all-listed --vtu-every-step --rows 6"),
              what + ": after the rerun, its files only");
        out << what << ": the rerun removed the earlier files, its own "
            << "read back whole" << std::endl;
      }
  }

  // A signal while gmsh meshes a script that never ends (gmsh itself is
  // deaf to it): once the program has started gmsh (a child process of its
  // own), SIGTERM; the run must stop within seconds, exit code 143, saying
  // what it interrupted (before, only a second signal ended it).
  void
  interrupt_meshing()
  {
    auto &out = RingContactTests::deallog_file;
    std::ofstream("endless.geo") << "For i In {1:1e15}\n  j = i;\nEndFor\n";
    std::ofstream("endless.prm")
      << "include " RING_CONTACT_SOURCE_DIR "/prm/two_blocks.prm\n"
      << "subsection Mesh\n set Mesh file = endless.geo\nend\n"
      << "subsection Output\n set Directory = endless\nend\n";
    std::thread                           signaller;
    std::chrono::steady_clock::time_point sent;
    bool                                  gmsh_started = false;
    const auto result = RingContactTests::run_command(
      {RING_CONTACT_EXECUTABLE, "endless.prm"}, {}, 0, [&](const pid_t pid) {
        signaller = std::thread([&, pid]() {
          // gmsh runs when the program has a child process;
          // at most a minute to get there, then SIGKILL.
          const std::string children = "/proc/" + std::to_string(pid) +
                                       "/task/" + std::to_string(pid) +
                                       "/children";
          for (int i = 0; i < 600 && !gmsh_started; ++i)
            {
              std::string child;
              std::ifstream(children) >> child;
              gmsh_started = !child.empty();
              std::this_thread::sleep_for(std::chrono::milliseconds(100));
            }
          sent = std::chrono::steady_clock::now();
          ::kill(pid, gmsh_started ? SIGTERM : SIGKILL);
          // A run deaf to it is killed after 20 s.
          for (int i = 0; i < 200; ++i)
            {
              std::this_thread::sleep_for(std::chrono::milliseconds(100));
              if (::kill(pid, 0) != 0)
                return;
            }
          ::kill(pid, SIGKILL);
        });
      });
    const auto ended = std::chrono::steady_clock::now();
    signaller.join();
    const double seconds = std::chrono::duration<double>(ended - sent).count();
    check(gmsh_started, "meshing: gmsh started");
    check(result.exit_code == 143,
          "meshing: exit code " + std::to_string(result.exit_code));
    check(result.printed("ring_contact: interrupted by SIGTERM while gmsh "
                         "read or meshed 'endless.geo', before the first "
                         "step: nothing written"),
          "meshing: the message");
    check(seconds < 10, "meshing: stopped within seconds");
    out << "meshing: exit code 143, gmsh stopped, nothing written" << std::endl;
  }
} // namespace

namespace
{
  // A step whose Newton iteration keeps failing is cut again and again
  // (here up to 30 times, each cut a few Newton iterations on a mesh of
  // 15 360 cells): SIGTERM at its first failure must stop the run within
  // seconds, not after the step's every cut (before: about 20 s). The
  // converged steps (none here) are complete, the step is not counted.
  void
  interrupt_step_cuts()
  {
    auto &out = RingContactTests::deallog_file;
    std::ofstream("cuts.prm")
      << "include " RING_CONTACT_SOURCE_DIR "/prm/ssnp152a.prm\n"
      << "subsection Mesh\n set Global refinements = 3\nend\n"
      << "subsection Contact\n set Integration schemes = nodal\nend\n"
      << "subsection Newton\n set Maximum iterations = 1\n"
         " set Maximum step cuts = 30\n set Verbose = false\nend\n"
      << "subsection Output\n set Directory = cuts\n set VTU interval = 0\n"
         " set Print timing = false\nend\n";
    bool                                  sent = false;
    std::chrono::steady_clock::time_point sent_at;
    const auto result = RingContactTests::run_program(
      "cuts.prm", [&](const std::string &line, const pid_t pid) {
        if (!sent && line.find("Newton failed") != std::string::npos)
          {
            sent_at = std::chrono::steady_clock::now();
            ::kill(pid, SIGTERM);
            sent = true;
          }
      });
    const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - sent_at)
        .count();
    check(sent, "step cuts: a step failed and was cut");
    check(result.exit_code == 143,
          "step cuts: exit code " + std::to_string(result.exit_code));
    check(result.printed("Interrupted by a signal in step 1"),
          "step cuts: the message");
    check(result.count("  step 1: Newton failed") <= 2,
          "step cuts: " +
            std::to_string(result.count("  step 1: Newton failed")) +
            " cuts after the signal");
    check(seconds < 5, "step cuts: stopped within seconds");
    check(RingContactTests::count_rows("cuts/history.csv") == 0,
          "step cuts: no row for the step that did not converge");
    out << "step cuts: exit code 143 at the first cut, within seconds"
        << std::endl;
  }
} // namespace

int
main()
{
  interrupt_meshing();
  interrupt_step_cuts();
  interrupt("int_setup", SIGINT, 1, 0);
  interrupt("int_step3", SIGINT, 1, 3);
  interrupt("term_step10", SIGTERM, 1, 10);
  // Starting MPI for MUMPS set SIGTERM back to its default action (deal.II
  // removes PETSc's handlers): the run was killed at once.
  interrupt("term_step10_mumps", SIGTERM, 1, 10, 0, "MUMPS");
  interrupt("term_scheme2", SIGTERM, 2, 0);
  interrupt("int_scheme2_step5", SIGINT, 2, 5);
  interrupt("term_last_step", SIGTERM, 2, 21);
  interrupt("twice", SIGINT, 1, 4, SIGTERM);
}
