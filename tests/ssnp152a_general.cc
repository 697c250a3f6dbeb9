// The problem language poses SSNP152 as the code does: modelisation A
// written as a general problem (prm/ssnp152a_general.prm: Lamé's radial
// displacements as polar expressions of t, the analytic sigma_n as the
// checks' reference) and the SSNP152 scenario (prm/ssnp152a.prm) on the
// same mesh (meshes/ssnp152.geo, 48 around) give the same pressure at node
// A at every step of the ramp, with both schemes, to 1e-9, and both pass
// their 2 % checks.
#include "run_program.h"

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

using RingContactTests::check;

namespace
{
  // history.csv: (scheme, step) -> the column `name` (the scenario's
  // pressure_A, the general problem's first check, the pressure at A).
  std::map<std::pair<std::string, int>, double>
  pressures(const std::string &filename, const std::string &name)
  {
    std::ifstream                                 in(filename);
    std::string                                   line;
    std::map<std::pair<std::string, int>, double> p;
    const auto split = [](const std::string &text) {
      std::vector<std::string> fields;
      std::stringstream        row(text);
      for (std::string field; std::getline(row, field, ',');)
        fields.push_back(field);
      return fields;
    };
    std::getline(in, line);
    const auto   header = split(line);
    unsigned int column = 0;
    while (column < header.size() && header[column] != name)
      ++column;
    check(column < header.size(), filename + " has a column " + name);
    while (std::getline(in, line))
      {
        const auto fields = split(line);
        p[{fields.at(0), std::stoi(fields.at(1))}] =
          std::stod(fields.at(column));
      }
    return p;
  }

  std::string
  quiet(const std::string &folder)
  {
    return "subsection Output\n set VTU interval = 0\n set Print timing = "
           "false\n set Print steps = false\n set Directory = " +
           folder + "\nend\nsubsection Newton\n set Verbose = false\nend\n";
  }
} // namespace

int
main()
{
  {
    std::ofstream prm("scenario.prm");
    prm << "include " SOURCE_DIR "/../prm/ssnp152a.prm\n"
        << "subsection Mesh\n set Mesh source = gmsh file\n"
           " set Mesh file = " SOURCE_DIR "/../meshes/ssnp152.geo\n"
           " set Geo parameters = Ne = 48, Nr1 = 3, Nr2 = 3\nend\n"
        << quiet("results_scenario");
  }
  {
    std::ofstream prm("general.prm");
    prm << "include " SOURCE_DIR "/../prm/ssnp152a_general.prm\n"
        << "subsection Mesh\n set Mesh file = " SOURCE_DIR
           "/../meshes/ssnp152.geo\nend\n"
        << quiet("results_general");
  }
  const auto scenario = RingContactTests::run_program("scenario.prm");
  const auto general  = RingContactTests::run_program("general.prm");
  check(scenario.exit_code == 0 && scenario.printed("42 of 42 checks pass"),
        "the SSNP152 scenario passes its checks");
  check(general.exit_code == 0 && general.printed("42 of 42 checks pass"),
        "the general problem passes its checks");
  const auto a = pressures("results_scenario/history.csv", "pressure_A");
  const auto b =
    pressures("results_general/history.csv", "check_1_contact_pressure");
  check(a.size() == 42 && b.size() == 42, "21 steps of two schemes each");
  double largest = 0;
  for (const auto &[key, value] : a)
    largest = std::max(largest, std::abs(b.at(key) - value) / value);
  check(largest < 1e-9,
        "the same pressure at A: largest relative difference " +
          std::to_string(largest));
  RingContactTests::deallog_file
    << "SSNP152 A as a scenario and in the problem language: 42 of 42 checks "
       "pass in both, the same pressure at A at every step to 1e-9"
    << std::endl;
}
