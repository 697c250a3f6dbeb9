// Bad input gets a one-line error that names the problem and a non-zero
// exit code, never a crash or a silent wrong answer: each case writes a
// parameter file, runs the real executable on it and checks both.
#include <ring_contact/config.h>

#include "tests.h"

#include <sys/wait.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

using RingContactTests::check;

namespace
{
  const std::string source_dir = RING_CONTACT_SOURCE_DIR;

  // Run the program on a parameter file with `text`; return the exit code
  // and the last line it printed.
  std::pair<int, std::string>
  run(const std::string &name, const std::string &text)
  {
    {
      std::ofstream prm(name + ".prm");
      prm << text;
    }
    const std::string command = std::string(RING_CONTACT_EXECUTABLE) + " " +
                                name + ".prm > " + name + ".log 2>&1";
    const int     status = std::system(command.c_str());
    std::ifstream log(name + ".log");
    std::string   line, last;
    while (std::getline(log, line))
      if (!line.empty())
        last = line;
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, last};
  }

  void
  expect_error(const std::string &name,
               const std::string &text,
               const std::string &expected)
  {
    const auto [code, message] = run(name, text);
    auto &out                  = RingContactTests::deallog_file;
    // The message may hold the path of the test's folder: drop it.
    std::string       shown  = message;
    const std::string folder = std::filesystem::current_path().string() + "/";
    for (auto at = shown.find(folder); at != std::string::npos;
         at      = shown.find(folder))
      shown.erase(at, folder.size());
    out << name << ": exit code " << code << ": " << shown << std::endl;
    check(code != 0, name + ": the program must fail");
    check(message.find("error:") != std::string::npos ||
            message.find("stopping") != std::string::npos ||
            message.find("could not be solved") != std::string::npos,
          name + ": a clear error message");
    check(message.find(expected) != std::string::npos,
          name + ": message must mention '" + expected + "', got: " + message);
  }
} // namespace

int
main()
{
  const std::string quiet = "subsection Output\n set VTU interval = 0\n"
                            " set Print timing = false\n"
                            " set Print steps = false\n end\n"
                            "subsection Newton\n set Verbose = false\nend\n";
  expect_error("missing_mesh",
               "subsection Mesh\n set Mesh source = gmsh file\n"
               " set Mesh file = no/such/mesh.msh\nend\n",
               "does not exist");
  expect_error("unknown_key",
               "subsection Materials\n set Young modulus = 1e9\nend\n",
               "Young modulus");
  expect_error("nu_too_large",
               "subsection Materials\n set Poisson's ratio inner ring = "
               "0.5\nend\n",
               "Poisson's ratio inner ring");
  expect_error("negative_youngs_modulus",
               "subsection Materials\n set Young's modulus outer ring = "
               "-1e9\nend\n",
               "Young's modulus outer ring");
  expect_error("zero_youngs_modulus",
               "subsection Materials\n set Young's modulus inner ring = "
               "0\nend\n",
               "must be positive");
  expect_error("inner_radius_too_large",
               "subsection Mesh\n set Inner radius = 0.6\nend\n",
               "R3 < R2");
  expect_error("slave_equals_master",
               "subsection Contact\n set Slave boundary = 300\n"
               " set Master boundary = 300\nend\n",
               "must differ");
  expect_error("no_slave_boundary",
               "subsection Contact\n set Slave boundary = 600\nend\n",
               "no boundary with id 600");
  expect_error("sector_of_a_read_mesh",
               "subsection Mesh\n set Mesh source = gmsh file\n"
               " set Mesh file = " +
                 source_dir +
                 "/meshes/ssnp152a.msh\n set Sector elements = 1\nend\n",
               "Sector elements");
  expect_error("sector_too_wide",
               "subsection Mesh\n set Sector elements = 40\nend\n",
               "smaller than 'Elements around'");
  expect_error("unknown_scheme",
               "subsection Contact\n set Integration schemes = nodal, "
               "Lobatto 3\nend\n",
               "Lobatto 3");

  // A mesh without the slave group (the original mesh less its S2R2
  // segments): the error names the missing boundary.
  {
    std::ifstream            in(source_dir + "/meshes/ssnp152a.msh");
    std::ofstream            out("no_s2r2.msh");
    std::string              line;
    bool                     in_elements = false;
    std::vector<std::string> elements;
    while (std::getline(in, line))
      {
        if (line == "$ELM")
          {
            in_elements = true;
            out << line << '\n';
            std::getline(in, line); // the count, written below
            continue;
          }
        if (line == "$ENDELM")
          {
            out << elements.size() << '\n';
            for (const auto &e : elements)
              out << e << '\n';
            in_elements = false;
          }
        if (in_elements)
          {
            std::istringstream fields(line);
            int                id, type, tag;
            fields >> id >> type >> tag;
            if (tag != 400)
              elements.push_back(line);
            continue;
          }
        out << line << '\n';
      }
  }
  expect_error("mesh_without_slave",
               "subsection Mesh\n set Mesh source = gmsh file\n"
               " set Mesh file = no_s2r2.msh\nend\n",
               "no boundary with id 400");
  expect_error("not_a_mesh",
               "subsection Mesh\n set Mesh source = gmsh file\n"
               " set Mesh file = not_a_mesh.prm\nend\n",
               "cannot read mesh file");
  expect_error("no_prm_file", "include does_not_exist.prm\n", "");

  // Newton that cannot converge (one iteration allowed, an unreachable
  // tolerance): the step is cut and retried, then the run stops with a
  // message and a non-zero exit code.
  expect_error("newton_fails",
               quiet + "subsection Newton\n set Maximum iterations = 1\n"
                       " set Tolerance = 1e-30\n set Maximum step cuts = 2\n"
                       "end\nsubsection Load program\n set Ramp steps = 2\n"
                       "end\n",
               "could not be solved");
}
