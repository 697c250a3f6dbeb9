// The real executable under mpirun -np 2, as a user runs it:
// - A with a VTU file every step: exit code 0, the log and the verdict
//   table printed once (by process 0), history.csv the same as the serial
//   run's (within 1e-9), and every .pvd, .pvtu and piece read
//   back whole with VTK (the pieces make the 240 cells of the rings);
// - mpirun sent SIGINT while C runs (it sends the processes SIGTERM): they
//   stop together after a step, and every file is whole;
// - errors every process meets (a missing mesh file) or that only process 0
//   can meet (the results folder held by another run) end the run with one
//   error line and exit code 1, not an MPI abort;
// - a traction that stops being a number on the faces of one process's
//   cells: the step fails on both processes, is cut, and the run stops with
//   the condition named (no process left waiting).
#include "run_program.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

using RingContactTests::check;
using RingContactTests::count_rows;

namespace
{
  auto &out = RingContactTests::deallog_file;

  // Whether two history files hold the same steps and, but for the wall
  // time of each step (the last column), the same numbers within 1e-9 of
  // max(1, |value|) (pressures in Pa, relative errors as fractions).
  bool
  same_history(const std::string &a, const std::string &b)
  {
    std::istringstream in_a(RingContactTests::file_contents(a)),
      in_b(RingContactTests::file_contents(b));
    std::string  line_a, line_b;
    unsigned int lines = 0;
    // The column of the wall time, which differs: from the header.
    unsigned int wall_time = 0;
    {
      std::istringstream header(RingContactTests::file_contents(a));
      std::string        first, name;
      std::getline(header, first);
      std::istringstream names(first);
      for (unsigned int k = 0; std::getline(names, name, ','); ++k)
        if (name == "wall_time")
          wall_time = k;
    }
    while (std::getline(in_a, line_a))
      {
        if (!std::getline(in_b, line_b))
          return false;
        std::istringstream fields_a(line_a), fields_b(line_b);
        std::string        field_a, field_b;
        std::vector<std::pair<std::string, std::string>> fields;
        while (std::getline(fields_a, field_a, ','))
          {
            if (!std::getline(fields_b, field_b, ','))
              return false;
            fields.emplace_back(field_a, field_b);
          }
        for (unsigned int k = 0; k < fields.size(); ++k)
          {
            if (k == wall_time && lines > 0)
              continue;
            const auto &[x, y] = fields[k];
            char        *end_x, *end_y;
            const double u       = std::strtod(x.c_str(), &end_x);
            const double v       = std::strtod(y.c_str(), &end_y);
            const bool   numbers = *end_x == '\0' && *end_y == '\0';
            if (numbers ? std::abs(u - v) > 1e-9 * std::max(1.0, std::abs(u)) :
                          x != y)
              return false;
          }
        ++lines;
      }
    return lines > 1 && !std::getline(in_b, line_b);
  }

  std::string
  write_prm(const std::string &name,
            const std::string &include,
            const std::string &extra)
  {
    std::ofstream prm(name + ".prm");
    prm << "include " RING_CONTACT_SOURCE_DIR "/prm/" << include << "\n"
        << "subsection Output\n set Directory = " << name
        << "\n set Print timing = false\nend\n"
           "subsection Newton\n set Verbose = false\nend\n"
        << extra;
    return name + ".prm";
  }

  // The program's error lines (mpirun adds its own lines when a process
  // ends with an error code).
  std::vector<std::string>
  error_lines(const RingContactTests::RunResult &result)
  {
    std::vector<std::string> errors;
    for (const auto &line : result.lines)
      if (line.find("ring_contact: error") != std::string::npos)
        errors.push_back(line);
    return errors;
  }
} // namespace

int
main()
{
  // A, VTU every step, against the serial run.
  {
    const std::string vtu = "subsection Output\n set VTU interval = 1\nend\n";
    const auto        parallel = RingContactTests::run_mpi_program(
      2, write_prm("a_mpi", "ssnp152a.prm", vtu));
    const auto serial =
      RingContactTests::run_program(write_prm("a_serial", "ssnp152a.prm", ""));
    const bool same = same_history("a_mpi/history.csv", "a_serial/history.csv");
    const bool files_whole = RingContactTests::check_results(
      "a_mpi", "--vtu-every-step --all-listed --bulk-cells 240 --quiet");
    out << "A on 2 processes: exit code " << parallel.exit_code
        << ", verdict tables printed " << parallel.count("42 of 42 checks pass")
        << ", history.csv " << (same ? "the same as" : "DIFFERENT from")
        << " the serial run's, the VTU files (.pvtu and pieces) "
        << (files_whole ? "whole" : "NOT WHOLE") << std::endl;
    check(parallel.exit_code == 0 && serial.exit_code == 0,
          "A runs on 2 processes");
    check(parallel.count("42 of 42 checks pass") == 1,
          "process 0 alone prints");
    check(parallel.count("Scheme nodal") == 1, "process 0 alone logs");
    check(same, "the history of 2 processes is the serial one");
    check(files_whole, "the VTU files read back whole");
  }

  // SIGINT to mpirun during C.
  {
    bool       sent   = false;
    const auto result = RingContactTests::run_mpi_program(
      2,
      write_prm("c_interrupted",
                "ssnp152c.prm",
                "subsection Output\n set VTU interval = 1\nend\n"),
      [&](const std::string &line, const pid_t pid) {
        if (!sent && RingContactTests::RunResult::step_of(line) == 10)
          {
            ::kill(pid, SIGINT);
            sent = true;
          }
      });
    const unsigned int rows = count_rows("c_interrupted/history.csv");
    const bool         whole =
      RingContactTests::check_results("c_interrupted",
                                      "--vtu-every-step --all-listed --quiet");
    out << "C on 2 processes, SIGINT to mpirun at step 10: stopped "
        << (result.exit_code != 0 && rows >= 10 && rows < 100 ? "after a step" :
                                                                "WRONGLY")
        << ", the files " << (whole ? "whole" : "NOT WHOLE") << std::endl;
    check(sent && result.exit_code != 0 && rows >= 10 && rows < 100,
          "C stops when mpirun is interrupted");
    check(whole, "the interrupted run's files are whole");
  }

  // An error of every process: one line, exit code 1.
  {
    const auto result = RingContactTests::run_mpi_program(
      2,
      write_prm("missing_mesh",
                "ssnp152a.prm",
                "subsection Mesh\n set Mesh source = gmsh file\n"
                " set Mesh file = no_such_file.msh\nend\n"));
    const auto errors = error_lines(result).size();
    out << "missing mesh file on 2 processes: exit code " << result.exit_code
        << ", " << errors << " error line, MPI abort: "
        << (result.printed("MPI_ABORT") ? "yes" : "no") << std::endl;
    check(result.exit_code == 2 && errors == 1 && !result.printed("MPI_ABORT"),
          "a missing mesh file is one error line");
  }

  // The results folder held by another run (here, this test): only process
  // 0 takes it, and both processes end.
  {
    const std::string prm = write_prm("held", "ssnp152a.prm", "");
    ::mkdir("held", 0755);
    const int lock = ::open("held/.ring_contact.lock", O_RDWR | O_CREAT, 0644);
    check(lock >= 0 && ::flock(lock, LOCK_EX | LOCK_NB) == 0, "lock held");
    const auto result = RingContactTests::run_mpi_program(2, prm);
    ::close(lock);
    const auto errors = error_lines(result);
    out << "results folder held by another run, 2 processes: exit code "
        << result.exit_code << ", " << errors.size() << " error line, steps "
        << "solved " << result.steps_printed()
        << ", MPI abort: " << (result.printed("MPI_ABORT") ? "yes" : "no")
        << std::endl;
    check(result.exit_code == 2 && result.steps_printed() == 0 &&
            errors.size() == 1 &&
            errors[0].find("in use by another run") != std::string::npos &&
            !result.printed("MPI_ABORT"),
          "a held folder is refused on every process");
  }

  // A traction that is not a number from t = 0.6 on.
  {
    const auto result = RingContactTests::run_mpi_program(
      2,
      write_prm("traction_not_finite",
                "two_blocks.prm",
                "subsection Mesh\n set Mesh file = " RING_CONTACT_SOURCE_DIR
                "/meshes/two_blocks.geo\nend\n"
                "subsection Output\n set VTU interval = 0\nend\n"
                "subsection Boundary condition 1\n"
                " set Value = 0; -p * t * sqrt(0.6 - t) / sqrt(0.1)\nend\n"));
    const bool named = result.printed(
      "Boundary condition 1 (traction on boundary 11): its value is not a "
      "finite number");
    const bool stopped = result.printed("Step 2: Newton did not converge");
    out << "traction not finite on 2 processes: exit code " << result.exit_code
        << ", the condition named: " << (named ? "yes" : "no")
        << ", step 2 stopped: " << (stopped ? "yes" : "no") << std::endl;
    check(result.exit_code == 3 && named && stopped,
          "a failing load stops both processes");
  }
}
