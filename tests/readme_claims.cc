// The documents' claims about the output, held against what a run writes
// (issue 30). doc/output.md, the output reference: its table of the VTU
// arrays against the arrays in the files of a ring run and of a general
// problem, its table of history.csv's columns against the headers of four
// runs (the rings and a general problem, each with and without friction),
// its sample of the terminal against the program's first line and table
// header. README.md: its sample's table header too, and its sentence on
// what --version prints. And every line of the terminal within 132
// columns. (doc/parameters.prm against --print-parameters is the test
// parameter_reference.)
#include "run_program.h"

#include <ring_contact/config.h>

#include <algorithm>
#include <array>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <utility>

using RingContactTests::check;

namespace
{
  // The table row of the document `name` (its text `text`) that starts
  // with `start`, whole.
  std::string
  document_row(const std::string &text,
               const std::string &name,
               const std::string &start)
  {
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);)
      {
        const auto first = line.find_first_not_of(' ');
        if (first != std::string::npos &&
            line.compare(first, start.size(), start) == 0)
          return line.substr(first);
      }
    check(false, name + " has a row starting with " + start);
    return "";
  }

  // The names in backquotes in `text`, in order.
  std::vector<std::string>
  quoted_names(const std::string &text)
  {
    std::vector<std::string> names;
    const std::regex         name("`([a-zA-Z0-9_<>.-]+)`");
    for (auto m = std::sregex_iterator(text.begin(), text.end(), name);
         m != std::sregex_iterator();
         ++m)
      names.push_back((*m)[1]);
    return names;
  }

  // The second cell of a table row.
  std::string
  second_cell(const std::string &row)
  {
    const auto first  = row.find('|', 1);
    const auto second = row.find('|', first + 1);
    return row.substr(first + 1, second - first - 1);
  }

  // The names of the data arrays of a section (PointData, CellData) of a
  // .vtu file: deal.II writes the XML tags in plain text.
  std::set<std::string>
  vtu_arrays(const std::string &filename, const std::string &section)
  {
    const std::string     text  = RingContactTests::file_contents(filename);
    const auto            begin = text.find("<" + section);
    const auto            end   = text.find("</" + section + ">");
    std::set<std::string> names;
    if (begin == std::string::npos || end == std::string::npos)
      return names;
    const std::string part = text.substr(begin, end - begin);
    const std::regex  name("Name=\"([^\"]+)\"");
    for (auto m = std::sregex_iterator(part.begin(), part.end(), name);
         m != std::sregex_iterator();
         ++m)
      names.insert((*m)[1]);
    return names;
  }

  std::vector<std::string>
  header_of(const std::string &filename)
  {
    std::ifstream            in(filename);
    std::string              line;
    std::vector<std::string> names;
    std::getline(in, line);
    std::stringstream row(line);
    for (std::string name; std::getline(row, name, ',');)
      names.push_back(name);
    return names;
  }

  std::string
  joined(const std::vector<std::string> &names)
  {
    std::string text;
    for (const auto &name : names)
      text += (text.empty() ? "" : ",") + name;
    return text;
  }

  // A run with VTU files at every step, no timing; its terminal checked
  // for width.
  RingContactTests::RunResult
  run(const std::string              &folder,
      const std::string              &prm,
      const std::vector<std::string> &settings)
  {
    std::vector<std::string> command = {RING_CONTACT_EXECUTABLE,
                                        "--set",
                                        "Output/Directory=" + folder,
                                        "--set",
                                        "Output/VTU interval=1",
                                        "--set",
                                        "Output/Print timing=false"};
    for (const auto &setting : settings)
      {
        command.push_back("--set");
        command.push_back(setting);
      }
    command.push_back(SOURCE_DIR "/../prm/" + prm);
    const auto result = RingContactTests::run_command(command);
    check(result.exit_code == 0, folder + ": the run passes");
    std::size_t widest = 0;
    for (const auto &line : result.lines)
      widest = std::max(widest, line.size());
    check(widest <= 132,
          folder + ": every line within 132 columns (widest " +
            std::to_string(widest) + ")");
    return result;
  }
} // namespace

int
main()
{
  const std::string readme =
    RingContactTests::file_contents(SOURCE_DIR "/../README.md");
  const std::string output =
    RingContactTests::file_contents(SOURCE_DIR "/../doc/output.md");
  const auto output_row = [&](const std::string &start) {
    return document_row(output, "doc/output.md", start);
  };

  // The four runs: the rings with two steps, with and without friction;
  // the two-block problems of the problem language.
  const std::vector<std::string> short_ring = {
    "Load program/Ramp steps=2", "Contact/Integration schemes=nodal"};
  auto friction_ring = short_ring;
  friction_ring.push_back("Contact/Friction coefficient=0.1");
  const auto rings = run("rings", "ssnp152a.prm", short_ring);
  run("rings_friction", "ssnp152a.prm", friction_ring);
  run("general", "two_blocks.prm", {});
  run("general_friction", "two_blocks_friction.prm", {});

  // @sect4{The VTU arrays}
  for (const auto &[files, stem, folder, scheme] :
       std::vector<std::array<std::string, 4>>{
         {"`solution-<scheme>.pvd`", "solution", "rings", "nodal"},
         {"`slave-<scheme>.pvd`", "slave", "rings", "nodal"},
         {"`solution-<scheme>.pvd`", "solution", "general", "segment-based-2"},
         {"`slave-<scheme>.pvd`", "slave", "general", "segment-based-2"}})
    {
      const std::string           row   = second_cell(output_row("| " + files));
      const auto                  names = quoted_names(row);
      const std::set<std::string> claimed(names.begin(), names.end());
      check(row.find("cell data") == std::string::npos,
            "doc/output.md claims no cell data (the material id is written "
            "as point data)");
      const std::string file = folder + "/" + stem + "-" + scheme + "-0001.vtu";
      const auto        point_data = vtu_arrays(file, "PointData");
      check(point_data == claimed,
            file + ": doc/output.md's point data are the file's");
      check(vtu_arrays(file, "CellData").empty(), file + ": no cell data");
    }

  // @sect4{The columns of history.csv}
  //
  // The rows of doc/output.md's table: the rings' list, "the same with X,
  // Y before equilibrium_error", and the general problem's list, in which
  // the check columns stand where the table says "a column per check".
  const auto rings_claim =
    quoted_names(second_cell(output_row("| rings, patch test |")));
  check(header_of("rings/history.csv") == rings_claim,
        "the rings' columns: " + joined(header_of("rings/history.csv")));

  const auto with_friction = [&](std::vector<std::string> columns,
                                 const std::string       &row_start) {
    const auto added = quoted_names(second_cell(output_row(row_start)));
    // doc/output.md: "the same with <added...> before
    // `equilibrium_error`".
    check(added.size() >= 2 && added.back() == "equilibrium_error",
          row_start + " names the columns added and where");
    columns.insert(std::find(columns.begin(),
                             columns.end(),
                             "equilibrium_error"),
                   added.begin(),
                   added.end() - 1);
    return columns;
  };
  check(header_of("rings_friction/history.csv") ==
          with_friction(rings_claim, "| rings, patch test, with friction |"),
        "the rings' columns with friction");

  const std::string general_row =
    second_cell(output_row("| general problem |"));
  const std::string placeholder = "a column per check";
  check(general_row.find(placeholder) != std::string::npos,
        "the general row says where the checks' columns go");
  const auto before =
    quoted_names(general_row.substr(0, general_row.find(placeholder)));
  const auto after         = quoted_names(general_row.substr(
    general_row.find(')', general_row.find(placeholder)) + 1));
  const auto general_claim = [&](const std::string &folder) {
    std::vector<std::string> columns = before;
    for (const auto &name : header_of(folder + "/history.csv"))
      if (std::regex_match(name, std::regex("check_[0-9]+_[a-z_]+")))
        columns.push_back(name);
    columns.insert(columns.end(), after.begin(), after.end());
    return columns;
  };
  check(header_of("general/history.csv") == general_claim("general"),
        "a general problem's columns: " +
          joined(header_of("general/history.csv")));
  check(header_of("general_friction/history.csv") ==
          with_friction(general_claim("general_friction"),
                        "| general problem, with friction |"),
        "a general problem's columns with friction");

  // @sect4{The terminal}
  //
  // doc/output.md's sample shows the first line of a run and the table's
  // header as the program prints them: the same version, the same words,
  // the same columns. The README's shorter sample shows the header too.
  for (const auto &[name, text] :
       std::vector<std::pair<std::string, std::string>>{
         {"doc/output.md", output}, {"README.md", readme}})
    {
      const auto sample_header =
        document_row(text, name, "step       t  Newton");
      bool header_found = false;
      for (const auto &line : rings.lines)
        header_found =
          header_found ||
          (line.find("step       t  Newton") != std::string::npos &&
           line.substr(line.find('s')) == sample_header);
      check(header_found,
            name + ": the sample's table header is the program's");
    }
  check(output.find("ring_contact " RING_CONTACT_VERSION
                    ": prm/ssnp152a.prm") != std::string::npos,
        "doc/output.md's sample shows this version's first line");
  check(rings.lines.front().rfind("ring_contact " RING_CONTACT_VERSION ": ",
                                  0) == 0,
        "the first line names the program and its version");
  check(rings.printed("Done: 2 steps in ") && rings.printed("Results in "),
        "the summary and the results folder at the end");
  // What --version prints, as the README says it: no version number of
  // its own in that sentence (it said 0.10.0 a release after 0.10.0), or
  // this one.
  {
    const auto at = readme.find("`ring_contact --version` prints");
    check(at != std::string::npos, "the README says what --version prints");
    // To the full stop that ends it (a dot before a space or a line's
    // end; a version's dots are neither).
    std::smatch stop;
    std::regex_search(readme.begin() + at,
                      readme.end(),
                      stop,
                      std::regex("\\.\\s"));
    const std::string sentence =
      readme.substr(at, stop.empty() ? std::string::npos : stop.position(0));
    const std::regex version_number("[0-9]+\\.[0-9]+\\.[0-9]+");
    for (std::sregex_iterator
           number(sentence.begin(), sentence.end(), version_number),
         end;
         number != end;
         ++number)
      check(number->str() == RING_CONTACT_VERSION,
            "the README's --version sentence names " + number->str() +
              ", not the version " RING_CONTACT_VERSION);
  }
  // The citation file names the version too (it said 0.10.0 after 0.11.0).
  {
    const std::string citation =
      RingContactTests::file_contents(SOURCE_DIR "/../CITATION.cff");
    check(citation.find("\nversion: " RING_CONTACT_VERSION "\n") !=
            std::string::npos,
          "CITATION.cff names the version " RING_CONTACT_VERSION);
  }

  RingContactTests::deallog_file
    << "doc/output.md: the VTU arrays of the bodies and the slave surfaces, "
       "the columns of history.csv for the rings and a general problem with "
       "and without friction, the sample's first line and table header "
       "hold; README.md: the sample's table header holds, the --version "
       "sentence names no other version; every line within 132 columns"
    << std::endl;
}
