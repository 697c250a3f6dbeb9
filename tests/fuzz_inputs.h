// Fuzz test of the program's input: hundreds of hostile inputs, generated
// from a fixed seed, each run as a child process of the real executable with
// a time limit. Every run must end either with results (exit code 0 or 1
// and the verdict table, or the "could not be solved" line) or with a clean
// error: exit code 1 or 2 and a single line on stderr that starts with
// "ring_contact: error:". Never a signal, a hang, or a multi-line raw
// exception. The output holds only the deterministic counts by outcome;
// the inputs of a failing case are kept in the test's folder
// (fuzz/<case>.prm) with its stdout and stderr.
//
// The corpus: mutated values of every kind of entry (huge, tiny, negative,
// NaN, inf, empty, 1e-320, garbage bytes, very long), broken syntax, include
// loops, deep and missing includes, directories and special files where
// files are expected, the three meshes of the repository (formats 1 and
// 2.2, linear and quadratic) truncated at random points, with changed
// counts, element types, node counts, tags and random bytes, the linear one
// written again by gmsh in formats 4.1 (ASCII and binary) and 2.2 (binary),
// cut and overwritten, and numbers handed to a .geo script.
//
// The corpus is run in two halves, the even cases and the odd ones, by the
// tests fuzz_inputs_1 and fuzz_inputs_2: the whole took 5 minutes on a busy
// machine, and up to the harness's limit of 10 on a busier one.
#ifndef ring_contact_tests_fuzz_inputs_h
#define ring_contact_tests_fuzz_inputs_h

#include <ring_contact/config.h>

#include "tests.h"

#include <fcntl.h>
#include <gmsh.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

using RingContactTests::check;
namespace fs = std::filesystem;

namespace
{
  const std::string source_dir = RING_CONTACT_SOURCE_DIR;
  // A legal input finishes in well under a second; hostile ones must stop
  // at least as fast. 20 s leaves room for a loaded machine.
  constexpr int time_limit_seconds = 20;

  std::mt19937 random_engine(20240917);

  // Deterministic across standard libraries (the distributions are not).
  unsigned int
  random_below(const unsigned int n)
  {
    return n == 0 ? 0 : static_cast<unsigned int>(random_engine() % n);
  }

  std::string
  read_file(const std::string &name)
  {
    std::ifstream      in(name, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  }

  void
  write_file(const std::string &name, const std::string &text)
  {
    std::ofstream out(name, std::ios::binary);
    out << text;
  }

  // A small, fast, legal problem: 12 elements around, one across each
  // ring, two load steps, nothing written but the verdicts.
  const std::string quiet_base =
    "subsection Mesh\n set Elements around = 12\n"
    " set Radial elements outer ring = 1\n"
    " set Radial elements inner ring = 1\nend\n"
    "subsection Load program\n set Ramp steps = 2\n set Rotation steps = 2\n"
    "end\n"
    "subsection Newton\n set Verbose = false\nend\n"
    "subsection Output\n set VTU interval = 0\n set Print timing = false\n"
    " set Print steps = false\n set Write history = false\nend\n"
    "subsection Checks\n set Steps = last\n set Tolerance = 1\nend\n";

  struct Case
  {
    std::string name;
    std::string argument; // what the program is given
  };

  enum class Outcome
  {
    results,     // exit 0/1 with the verdict table or a failed step
    clean_error, // exit 1/2, one "ring_contact: error:" line on stderr
    bad          // anything else
  };

  struct Run
  {
    Outcome     outcome;
    std::string why;
  };

  Run
  run_case(const Case &c)
  {
    const std::string out_name = "fuzz/" + c.name + ".stdout";
    const std::string err_name = "fuzz/" + c.name + ".stderr";
    const pid_t       pid      = fork();
    if (pid == 0)
      {
        const int out =
          open(out_name.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        const int err =
          open(err_name.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        dup2(out, 1);
        dup2(err, 2);
        // A runaway allocation must not take the machine down: 6 GB of
        // address space (not under AddressSanitizer, whose shadow memory
        // reserves terabytes of address space at start: there its own
        // allocator limits stand in).
#ifndef __SANITIZE_ADDRESS__
        const rlimit memory{6ul << 30, 6ul << 30};
        setrlimit(RLIMIT_AS, &memory);
#endif
        execl(RING_CONTACT_EXECUTABLE,
              RING_CONTACT_EXECUTABLE,
              c.argument.c_str(),
              static_cast<char *>(nullptr));
        _exit(127);
      }
    int        status = 0;
    const auto start  = std::chrono::steady_clock::now();
    bool       killed = false;
    while (waitpid(pid, &status, WNOHANG) == 0)
      {
        if (std::chrono::steady_clock::now() - start >
            std::chrono::seconds(time_limit_seconds))
          {
            kill(pid, SIGKILL);
            waitpid(pid, &status, 0);
            killed = true;
            break;
          }
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
      }
    if (killed)
      return {Outcome::bad, "time limit exceeded"};
    if (WIFSIGNALED(status))
      return {Outcome::bad, "signal " + std::to_string(WTERMSIG(status))};
    const int         code = WEXITSTATUS(status);
    const std::string out  = read_file(out_name);
    const std::string err  = read_file(err_name);
    const bool        single =
      !err.empty() && err.back() == '\n' && err.find('\n') == err.size() - 1;
    for (const char ch : err)
      if ((static_cast<unsigned char>(ch) < 0x20 && ch != '\n') || ch == 0x7F)
        return {Outcome::bad, "a control character on stderr"};
    // A refused input exits with 2, a run that could not go on with 3;
    // results with 0 or 1 (the checks' verdict), or 3 when a step could
    // not be solved.
    if ((code == 2 || code == 3) && single &&
        err.compare(0, 20, "ring_contact: error:") == 0)
      return {Outcome::clean_error, ""};
    if (err.empty() &&
        (((code == 0 || code == 1) &&
          out.find("checks pass") != std::string::npos &&
          out.find("could not be solved") == std::string::npos) ||
         (code == 3 && out.find("could not be solved") != std::string::npos)))
      return {Outcome::results, ""};
    return {Outcome::bad,
            "exit code " + std::to_string(code) +
              ", stderr: " + err.substr(0, 300)};
  }

  // --------------------------------------------------------------------
  // The corpus
  // --------------------------------------------------------------------

  std::vector<Case> cases;

  void
  add_prm(const std::string &name, const std::string &text)
  {
    write_file("fuzz/" + name + ".prm", text);
    cases.push_back({name, "fuzz/" + name + ".prm"});
  }

  std::string
  set_entry(const std::string &subsection,
            const std::string &entry,
            const std::string &value)
  {
    return "subsection " + subsection + "\n set " + entry + " = " + value +
           "\nend\n";
  }

  std::string
  garbage(const unsigned int n)
  {
    std::string text;
    for (unsigned int i = 0; i < n; ++i)
      text += static_cast<char>(random_below(256));
    return text;
  }

  void
  value_mutations()
  {
    const std::vector<std::pair<std::string, std::string>> entries = {
      {"Mesh", "Elements around"},
      {"Mesh", "Radial elements outer ring"},
      {"Mesh", "Radial elements inner ring"},
      {"Mesh", "Global refinements"},
      {"Mesh", "Sector elements"},
      {"Mesh", "Outer radius"},
      {"Mesh", "Interface radius"},
      {"Mesh", "Inner radius"},
      {"Mesh", "Mesh source"},
      {"Patch test", "Elements lower block"},
      {"Materials", "Young's modulus outer ring"},
      {"Materials", "Poisson's ratio inner ring"},
      {"Materials", "Material law"},
      {"Finite elements", "Displacement degree outer ring"},
      {"Finite elements", "Multiplier degree"},
      {"Finite elements", "Mapping degree"},
      {"Contact", "Slave boundary"},
      {"Contact", "Master boundary"},
      {"Contact", "Integration schemes"},
      {"Contact", "Complementarity constant"},
      {"Contact", "Probe point"},
      {"Load program", "Program"},
      {"Load program", "Reference pressure"},
      {"Load program", "Ramp steps"},
      {"Load program", "Time step"},
      {"Load program", "Rotation pressure"},
      {"Load program", "Rotation steps"},
      {"Load program", "Rotation in elements"},
      {"Newton", "Maximum iterations"},
      {"Newton", "Tolerance"},
      {"Newton", "Maximum step cuts"},
      {"Output", "VTU interval"},
      {"Output", "VTU subdivisions"},
      {"Checks", "Steps"},
      {"Checks", "Tolerance"},
      {"Checks", "Quantity"}};
    const std::vector<std::string> values = {
      "",           "0",          "-1",
      "1e-320",     "1e999",      "-1e308",
      "nan",        "inf",        "99999999999999999999",
      "2147483648", "4294967297", "10000000",
      "5e9",        "abc",        "1,2,3",
      "{1|2}",      "0x10",       "3 4",
      "1e6, 1e6",   "Gauss 0",    "segment-based 99"};
    // Every entry with a few values chosen at random, plus garbage bytes
    // and a very long value.
    unsigned int n = 0;
    for (const auto &[subsection, entry] : entries)
      {
        for (unsigned int i = 0; i < 2; ++i)
          add_prm("value_" + std::to_string(n++),
                  quiet_base + set_entry(subsection,
                                         entry,
                                         values[random_below(values.size())]));
        std::string bytes = garbage(20);
        for (char &ch : bytes)
          if (ch == '\n' || ch == '#')
            ch = 'x';
        add_prm("value_" + std::to_string(n++),
                quiet_base + set_entry(subsection, entry, bytes));
        if (n % 3 == 0)
          add_prm("value_" + std::to_string(n++),
                  quiet_base +
                    set_entry(subsection, entry, std::string(5000, '7')));
      }
  }

  void
  syntax_mutations()
  {
    const std::vector<std::string> texts = {
      "",
      "subsection Mesh\n",
      "end\n",
      "subsection Mesh\nend\nend\n",
      "subsection No such section\nend\n",
      "set Elements around = 4\n",
      "subsection Mesh\n set Elements around 4\nend\n",
      "subsection Mesh\n set = 4\nend\n",
      "subsection Mesh\n Elements around = 4\nend\n",
      "subsection Mesh\n set Elements around = 4 \\\n",
      "subsection Mesh\n set Elements around = \\\n 4\nend\n",
      "subsection\nend\n",
      "include\n",
      "include \n",
      "subsection Mesh\n subsection Mesh\n end\nend\n",
      "subsection Mesh end\n",
      "SET x = 1\n",
      "subsection Mesh\n set Elements around = 4 # comment\nend\n#\n",
      std::string("subsection Mesh\n set Elements around = 4\0\nend\n", 42),
      std::string(100000, 'x'),
      std::string(2 << 20, '\n'),
    };
    unsigned int n = 0;
    for (const auto &text : texts)
      add_prm("syntax_" + std::to_string(n++), quiet_base + text);
    for (unsigned int i = 0; i < 10; ++i)
      add_prm("syntax_" + std::to_string(n++), garbage(200 + 50 * i));
    // The legal base cut at random points.
    for (unsigned int i = 0; i < 10; ++i)
      add_prm("syntax_" + std::to_string(n++),
              quiet_base.substr(0, random_below(quiet_base.size())));
  }

  void
  include_mutations()
  {
    const std::string folder = fs::absolute("fuzz").string();
    add_prm("include_self",
            "include " + folder + "/include_self.prm\n" + quiet_base);
    write_file("fuzz/include_b.prm", "include " + folder + "/include_a.prm\n");
    add_prm("include_a", "include " + folder + "/include_b.prm\n");
    add_prm("include_relative_self", "include include_relative_self.prm\n");
    // A chain of 30 files: deeper than the cap.
    for (unsigned int i = 0; i < 30; ++i)
      write_file("fuzz/chain_" + std::to_string(i) + ".prm",
                 "include chain_" + std::to_string(i + 1) + ".prm\n");
    write_file("fuzz/chain_30.prm", quiet_base);
    cases.push_back({"include_chain", "fuzz/chain_0.prm"});
    // A legal chain of 5.
    for (unsigned int i = 0; i < 5; ++i)
      write_file("fuzz/short_" + std::to_string(i) + ".prm",
                 "include short_" + std::to_string(i + 1) + ".prm\n");
    write_file("fuzz/short_5.prm", quiet_base);
    cases.push_back({"include_short_chain", "fuzz/short_0.prm"});
    add_prm("include_missing", "include does/not/exist.prm\n" + quiet_base);
    add_prm("include_directory", "include " + folder + "\n" + quiet_base);
    add_prm("include_dev_null", "include /dev/null\n" + quiet_base);
    add_prm("include_dev_zero", "include /dev/zero\n" + quiet_base);
    add_prm("include_binary",
            "include " + std::string(RING_CONTACT_EXECUTABLE) + "\n" +
              quiet_base);
    add_prm("include_inside_subsection",
            "subsection Mesh\ninclude " + folder + "/include_b.prm\nend\n");
    write_file("fuzz/unbalanced.prm", "subsection Mesh\n");
    add_prm("include_unbalanced", "include unbalanced.prm\nend\n");
  }

  void
  file_mutations()
  {
    fs::create_directories("fuzz/a_directory.prm");
    cases.push_back({"prm_directory", "fuzz/a_directory.prm"});
    cases.push_back({"prm_missing", "fuzz/no_such_file.prm"});
    cases.push_back({"prm_dev_null", "/dev/null"});
    cases.push_back({"prm_dev_zero", "/dev/zero"});
    cases.push_back({"prm_empty_name", ""});
    cases.push_back({"prm_binary", RING_CONTACT_EXECUTABLE});
    const std::string gmsh = "subsection Mesh\n set Mesh source = gmsh file\n";
    add_prm("mesh_directory", quiet_base + gmsh + " set Mesh file = .\nend\n");
    add_prm("mesh_dev_zero",
            quiet_base + gmsh + " set Mesh file = /dev/zero\nend\n");
    add_prm("mesh_missing",
            quiet_base + gmsh + " set Mesh file = nothing.msh\nend\n");
    add_prm("mesh_empty_name", quiet_base + gmsh + " set Mesh file =\nend\n");
  }

  // One mesh run: the original's modelisation A with the mesh `file`.
  void
  add_mesh_case(const std::string &name,
                const std::string &text,
                const std::string &degree)
  {
    write_file("fuzz/" + name + ".msh", text);
    add_prm(name,
            quiet_base + "subsection Mesh\n set Mesh source = gmsh file\n" +
              " set Mesh file = " + name +
              ".msh\n set Elements around = 40\nend\n"
              "subsection Finite elements\n"
              " set Displacement degree outer ring = " +
              degree + "\n set Displacement degree inner ring = " + degree +
              "\nend\nsubsection Load program\n set Ramp steps = 1\nend\n");
  }

  std::vector<std::string>
  lines_of(const std::string &text)
  {
    std::vector<std::string> lines;
    std::istringstream       in(text);
    std::string              line;
    while (std::getline(in, line))
      lines.push_back(line);
    return lines;
  }

  std::string
  join(const std::vector<std::string> &lines)
  {
    std::string text;
    for (const auto &line : lines)
      text += line + "\n";
    return text;
  }

  void
  mesh_mutations()
  {
    unsigned int n = 0;
    for (const auto &[file, degree] : {std::make_pair("ssnp152a.msh", "1"),
                                       std::make_pair("rings-40.msh", "1"),
                                       std::make_pair("ssnp152g.msh", "2")})
      {
        const std::string text  = read_file(source_dir + "/meshes/" + file);
        const auto        lines = lines_of(text);
        const auto name = [&]() { return "mesh_" + std::to_string(n++); };
        // The mesh itself: legal.
        add_mesh_case(name(), text, degree);
        // Cut at random points.
        for (unsigned int i = 0; i < 8; ++i)
          add_mesh_case(name(),
                        text.substr(0, random_below(text.size())),
                        degree);
        // Random bytes overwritten.
        for (unsigned int i = 0; i < 6; ++i)
          {
            std::string corrupted = text;
            for (unsigned int j = 0; j < 1 + i; ++j)
              corrupted[random_below(corrupted.size())] =
                static_cast<char>(random_below(256));
            add_mesh_case(name(), corrupted, degree);
          }
        // Counts changed, elements and nodes mutated, line by line.
        std::vector<unsigned int> count_lines, element_lines, node_lines;
        for (unsigned int i = 0; i + 1 < lines.size(); ++i)
          {
            if (lines[i] == "$NOD" || lines[i] == "$Nodes" ||
                lines[i] == "$ELM" || lines[i] == "$Elements")
              count_lines.push_back(i + 1);
          }
        bool in_elements = false, in_nodes = false;
        for (unsigned int i = 0; i < lines.size(); ++i)
          {
            if (lines[i] == "$ELM" || lines[i] == "$Elements")
              {
                in_elements = true;
                ++i;
                continue;
              }
            if (lines[i] == "$NOD" || lines[i] == "$Nodes")
              {
                in_nodes = true;
                ++i;
                continue;
              }
            if (!lines[i].empty() && lines[i][0] == '$')
              in_elements = in_nodes = false;
            else if (in_elements)
              element_lines.push_back(i);
            else if (in_nodes)
              node_lines.push_back(i);
          }
        for (const unsigned int c : count_lines)
          for (const long delta : {-1L, 1L, -1000L, 1000000000000L})
            {
              auto mutated = lines;
              mutated[c]   = std::to_string(std::stol(lines[c]) + delta);
              add_mesh_case(name(), join(mutated), degree);
            }
        const bool format_1 = lines[0] == "$NOD";
        const auto fields   = [](const std::string &line) {
          std::istringstream       in(line);
          std::vector<std::string> f;
          std::string              w;
          while (in >> w)
            f.push_back(w);
          return f;
        };
        const auto unfields = [](const std::vector<std::string> &f) {
          std::string line;
          for (const auto &w : f)
            line += (line.empty() ? "" : " ") + w;
          return line;
        };
        for (unsigned int i = 0; i < 12; ++i)
          {
            auto               mutated = lines;
            const unsigned int at =
              element_lines[random_below(element_lines.size())];
            auto f = fields(lines[at]);
            switch (i % 6)
              {
                case 0: // another element type
                  f[1] = std::vector<std::string>{
                    "2", "16", "99", "15", "1", "3"}[random_below(6)];
                  break;
                case 1: // one node fewer
                  f.pop_back();
                  break;
                case 2: // format 1: the node count; format 2: a tag count
                  if (format_1)
                    f[4] = std::to_string(std::stol(f[4]) - 1);
                  else
                    f[2] = "7";
                  break;
                case 3: // a node that does not exist
                  f.back() = "987654";
                  break;
                case 4: // another physical tag
                  f[2 + !format_1] = "201";
                  break;
                case 5: // the element dropped (count unchanged)
                  f.clear();
                  break;
              }
            if (f.empty())
              mutated.erase(mutated.begin() + at);
            else
              mutated[at] = unfields(f);
            add_mesh_case(name(), join(mutated), degree);
          }
        // A line dropped and the count fixed: a missing boundary segment.
        {
          auto                     mutated = lines;
          std::vector<std::string> kept;
          unsigned int             dropped = 0;
          for (unsigned int i = 0; i < mutated.size(); ++i)
            {
              const bool element =
                std::find(element_lines.begin(), element_lines.end(), i) !=
                element_lines.end();
              if (element && fields(mutated[i])[1] == "1" && dropped < 3 &&
                  random_below(10) == 0)
                {
                  ++dropped;
                  continue;
                }
              kept.push_back(mutated[i]);
            }
          for (auto &line : kept)
            if (&line - &kept[0] > 0 &&
                (kept[&line - &kept[0] - 1] == "$ELM" ||
                 kept[&line - &kept[0] - 1] == "$Elements"))
              line = std::to_string(std::stol(line) - dropped);
          add_mesh_case(name(), join(kept), degree);
        }
        // Nodes: NaN, huge, duplicated, out of plane.
        for (const std::string &replacement : {std::string("nan 0 0"),
                                               std::string("1e999 0 0"),
                                               std::string("0 0 0.5"),
                                               std::string("x y z")})
          {
            auto               mutated = lines;
            const unsigned int at = node_lines[random_below(node_lines.size())];
            mutated[at]           = fields(lines[at])[0] + " " + replacement;
            add_mesh_case(name(), join(mutated), degree);
          }
        {
          auto mutated = lines;
          mutated[node_lines[1]] =
            fields(lines[node_lines[0]])[0] + " 0.5 0.5 0";
          add_mesh_case(name(), join(mutated), degree);
        }
        // One triangle instead of the mesh's elements.
        {
          std::string triangle =
            format_1 ? "$NOD\n3\n1 0 0 0\n2 1 0 0\n3 0 1 0\n$ENDNOD\n$ELM\n1\n"
                       "1 2 100 1 3 1 2 3\n$ENDELM\n" :
                       "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n3\n"
                       "1 0 0 0\n2 1 0 0\n3 0 1 0\n$EndNodes\n$Elements\n1\n"
                       "1 2 2 100 1 1 2 3\n$EndElements\n";
          add_mesh_case(name(), triangle, degree);
        }
      }
  }

  // Write the original's linear mesh again with gmsh itself.
  std::string
  written_by_gmsh(const double version, const bool binary)
  {
    const std::string file = "fuzz/written-" + std::to_string(version) +
                             (binary ? "-binary" : "") + ".msh";
    gmsh::initialize(0, nullptr, false);
    gmsh::option::setNumber("General.Terminal", 0);
    gmsh::open(source_dir + "/meshes/ssnp152a.msh");
    gmsh::option::setNumber("Mesh.MshFileVersion", version);
    gmsh::option::setNumber("Mesh.Binary", binary ? 1 : 0);
    gmsh::write(file);
    gmsh::finalize();
    return read_file(file);
  }

  // The formats gmsh writes and the mutations above do not cover: ASCII
  // 4.1, binary 4.1 and 2.2, cut and overwritten at random; element nodes
  // that gmsh 4.8's ASCII 4.1 reader does not check (-1 crashes it); and
  // the numbers handed to a .geo script.
  void
  gmsh_written_mutations()
  {
    unsigned int n    = 0;
    const auto   name = [&]() { return "written_" + std::to_string(n++); };
    for (const auto &[version, binary] : {std::make_pair(4.1, false),
                                          std::make_pair(4.1, true),
                                          std::make_pair(2.2, true)})
      {
        const std::string text = written_by_gmsh(version, binary);
        add_mesh_case(name(), text, "1");
        for (unsigned int i = 0; i < 6; ++i)
          add_mesh_case(name(), text.substr(0, random_below(text.size())), "1");
        for (unsigned int i = 0; i < 5; ++i)
          {
            std::string corrupted = text;
            for (unsigned int j = 0; j < 1 + i; ++j)
              corrupted[random_below(corrupted.size())] =
                static_cast<char>(random_below(256));
            add_mesh_case(name(), corrupted, "1");
          }
        if (binary)
          continue;
        // A quadrilateral "tag n1 n2 n3 n4" of the element section.
        const auto         lines = lines_of(text);
        const unsigned int elements =
          std::find(lines.begin(), lines.end(), "$Elements") - lines.begin();
        std::vector<unsigned int> quads;
        for (unsigned int i = elements + 2; i < lines.size(); ++i)
          {
            std::istringstream       in(lines[i]);
            std::vector<std::string> f;
            for (std::string w; in >> w;)
              f.push_back(w);
            if (f.size() == 5)
              quads.push_back(i);
          }
        for (const std::string node : {"-1", "0", "987654"})
          {
            auto               mutated = lines;
            const unsigned int at      = quads[random_below(quads.size())];
            const std::size_t  space   = mutated[at].find(' ');
            mutated[at] = mutated[at].substr(0, space) + " " + node +
                          mutated[at].substr(mutated[at].find(' ', space + 1));
            add_mesh_case(name(), join(mutated), "1");
          }
      }
    const std::string geo = "subsection Mesh\n set Mesh source = gmsh file\n"
                            " set Mesh file = " +
                            source_dir + "/meshes/ssnp152.geo\n";
    for (const std::string numbers : {"Ne = 12, Nr1 = 1, Nr2 = 1",
                                      "Ne = 10",
                                      "Ne = abc",
                                      "Ne = 1e-320",
                                      "Ne = 12, Ne = 16",
                                      "1x = 3",
                                      "Nx = 3",
                                      "Ne 12",
                                      ","})
      add_prm(name(),
              quiet_base + geo + " set Geo parameters = " + numbers +
                "\nend\n");
    add_prm(name(),
            quiet_base + "subsection Mesh\n set Geo parameters = Ne = 12\n"
                         "end\n");
  }

  void
  size_and_hang_mutations()
  {
    const std::vector<std::string> texts = {
      set_entry("Mesh", "Elements around", "10000000"),
      set_entry("Mesh", "Radial elements outer ring", "10000000"),
      "subsection Mesh\n set Elements around = 100000\n"
      " set Global refinements = 8\nend\n",
      "subsection Mesh\n set Sector elements = 1\nend\n"
      "subsection Load program\n set Program = rotation\n"
      " set Rotation in elements = 1e6\nend\n",
      "subsection Mesh\n set Sector elements = 1\nend\n"
      "subsection Load program\n set Program = rotation\n"
      " set Rotation in elements = 5e9\nend\n",
      "subsection Load program\n set Program = rotation\n"
      " set Rotation in elements = -1e300\nend\n",
      "subsection Load program\n set Ramp steps = 100000\n"
      " set Time step = 1\nend\n",
      "subsection Mesh\n set Sector elements = 11\nend\n",
      "subsection Contact\n set Probe point = 1e300, 1e300\nend\n",
      "subsection Contact\n set Probe point = 5, 5\nend\n",
      "subsection Checks\n set Steps =\nend\n",
      "subsection Checks\n set Steps = ,\nend\n",
      "subsection Checks\n set Steps = 99\nend\n",
      "subsection Problem\n set Scenario = patch test\nend\n"
      "subsection Patch test\n set Elements lower block = 10000000\nend\n"};
    unsigned int n = 0;
    for (const auto &text : texts)
      add_prm("size_" + std::to_string(n++), quiet_base + text);
    // Every sector of the 12-element rings, ramp and rotation.
    for (unsigned int k = 0; k <= 12; ++k)
      for (const std::string program : {k % 2 == 0 ? "ramp" : "rotation"})
        add_prm("sector_" + program + "_" + std::to_string(k),
                quiet_base + "subsection Mesh\n set Sector elements = " +
                  std::to_string(k) +
                  "\nend\nsubsection Load program\n set Program = " + program +
                  "\n set Rotation in elements = 3\nend\n");
  }
} // namespace

// Generate the whole corpus (the same for both halves: one seed, one
// order) and run the cases whose index is `part` modulo `parts`.
void
run_fuzz(const unsigned int part, const unsigned int parts)
{
  fs::remove_all("fuzz");
  fs::create_directories("fuzz");
  value_mutations();
  syntax_mutations();
  include_mutations();
  file_mutations();
  mesh_mutations();
  gmsh_written_mutations();
  size_and_hang_mutations();

  // This half's cases.
  {
    std::vector<Case> mine;
    for (unsigned int i = 0; i < cases.size(); ++i)
      if (i % parts == part)
        mine.push_back(cases[i]);
    cases = std::move(mine);
  }
  std::map<Outcome, unsigned int> counts;
  std::vector<std::string>        failures;
  // Two children at a time (the machine has two cores).
  std::vector<Run>      runs(cases.size());
  std::atomic<unsigned> next{0};
  const auto            worker = [&]() {
    for (unsigned int i = next++; i < cases.size(); i = next++)
      runs[i] = run_case(cases[i]);
  };
  std::thread first(worker), second(worker);
  first.join();
  second.join();
  for (unsigned int i = 0; i < cases.size(); ++i)
    {
      const Run &run = runs[i];
      ++counts[run.outcome];
      if (run.outcome == Outcome::bad)
        failures.push_back(cases[i].name + ": " + run.why);
      else
        {
          fs::remove("fuzz/" + cases[i].name + ".stdout");
          fs::remove("fuzz/" + cases[i].name + ".stderr");
        }
    }
  auto &out = RingContactTests::deallog_file;
  out << cases.size() << " hostile inputs" << std::endl
      << "ended with results: " << counts[Outcome::results] << std::endl
      << "ended with a one-line error: " << counts[Outcome::clean_error]
      << std::endl
      << "crashed, hung or printed a raw error: " << counts[Outcome::bad]
      << std::endl;
  for (const auto &failure : failures)
    std::cerr << "FUZZ FAILURE " << failure << std::endl;
  check(failures.empty(),
        std::to_string(failures.size()) +
          " inputs crashed, hung or printed a raw error (see stderr and "
          "fuzz/)");
  check(cases.size() * parts >= 300, "at least 300 inputs in all");
}

#endif
