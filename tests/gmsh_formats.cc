// The same mesh in every format gmsh writes gives the same rings: the
// original test's linear mesh (format 1) and its quadratic one are written
// by gmsh itself (its API, Mesh.MshFileVersion and Mesh.Binary) in formats
// 1, 2.2 and 4.1, ASCII and binary, and each is read back through the
// program's reader: the same cells (vertices to 1e-15 of R1, material and
// boundary ids), and on the linear one the same pressure at node A after two
// ramp steps of modelisation A. All reads run in this one process, and after
// a file that makes gmsh's reader crash (a node number -1 in an ASCII 4.1
// element) and one it refuses, which each give a one-line error naming the
// file. Last, 8-node quadrilaterals, written by gmsh from meshes/ssnp152.geo,
// give the cells of the 9-node ones.
#include <deal.II/grid/tria.h>

#include <ring_contact/base/utilities.h>
#include <ring_contact/config.h>
#include <ring_contact/input/gmsh_file.h>
#include <ring_contact/input/gmsh_mesh.h>

#include "gmsh_helpers.h"
#include "run_problem.h"

#include <gmsh.h>

#include <cmath>
#include <iomanip>

using namespace RingContact;
using RingContactTests::check;

namespace
{
  const std::string meshes = std::string(RING_CONTACT_SOURCE_DIR) + "/meshes/";

  using Cells = RingContactTests::Cells<2>;

  // The triangulation of a mesh file (a script meshed to `script_order`).
  Cells
  cells_of(const std::string &file, const unsigned int script_order = 1)
  {
    Triangulation<2> triangulation;
    Geometry::read_gmsh(triangulation, file, {}, script_order);
    return RingContactTests::cells_of(triangulation);
  }

  double
  pressure_at_A(const std::string &file)
  {
    const auto history = RingContactTests::run_problem(
      "formats",
      RingContactTests::modelisation(
        'a',
        "subsection Mesh\n set Mesh source = gmsh file\n set Mesh file = " +
          file +
          "\nend\nsubsection Load program\n set Ramp steps = 2\n"
          " set Time step = 1\nend\n"
          "subsection Contact\n set Integration schemes = nodal\nend\n"));
    return history.back().value("pressure_A");
  }

  std::string
  error_of(const std::string &file)
  {
    try
      {
        Triangulation<2> triangulation;
        Geometry::read_gmsh(triangulation, file);
      }
    catch (const std::exception &e)
      {
        return e.what();
      }
    return "";
  }
} // namespace

int
main()
{
  auto &out = RingContactTests::deallog_file;
  out << std::setprecision(7);

  // A file gmsh's reader crashes on, one it refuses, then the good ones.
  {
    RingContactTests::write_with_gmsh(meshes + "ssnp152a.msh",
                                      "crash.msh",
                                      4.1,
                                      false);
    std::ifstream            in("crash.msh");
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);)
      lines.push_back(line);
    // The last element line (a quadrilateral of the inner ring): its first
    // node becomes -1.
    std::string &last = lines[lines.size() - 2];
    last.replace(last.find(' '),
                 last.find(' ', last.find(' ') + 1) - last.find(' '),
                 " -1");
    std::ofstream crash("crash.msh");
    for (const auto &line : lines)
      crash << line << '\n';
    std::ofstream("refused.msh") << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n"
                                    "$Nodes\n1\n1 0 0 0\n$EndNodes\n"
                                    "$Elements\n1\n1 1 2 200 1 1 7\n"
                                    "$EndElements\n";
  }
  for (const std::string file : {"crash.msh", "refused.msh"})
    {
      const std::string message = error_of(file);
      out << file << ": one-line error naming the file: "
          << (!message.empty() && message.find('\n') == std::string::npos &&
                  message.find("'" + file + "'") != std::string::npos ?
                "yes" :
                "NO")
          << std::endl;
      std::cout << message << std::endl;
    }

  for (const std::string original : {"ssnp152a.msh", "ssnp152g.msh"})
    {
      const Cells reference = cells_of(meshes + original);
      out << original << ": " << reference.ids.size() / 5 << " cells"
          << std::endl;
      const bool   linear      = original == "ssnp152a.msh";
      const double p_reference = linear ? pressure_at_A(meshes + original) : 0;
      for (const double version : {1.0, 2.2, 4.1})
        for (const bool binary : {false, true})
          {
            if (binary && version == 1.0)
              continue; // format 1 is text only
            std::ostringstream name;
            name << original.substr(0, 8) << "-" << version
                 << (binary ? "-binary" : "") << ".msh";
            RingContactTests::write_with_gmsh(meshes + original,
                                              name.str(),
                                              version,
                                              binary);
            const Cells cells = cells_of(name.str());
            double      moved = 0;
            check(cells.vertices.size() == reference.vertices.size(),
                  name.str() + ": as many cells as the original");
            for (unsigned int i = 0; i < cells.vertices.size(); ++i)
              moved =
                std::max(moved,
                         cells.vertices[i].distance(reference.vertices[i]));
            const bool same = cells.ids == reference.ids && moved < 1e-15;
            out << "  format " << version << (binary ? " binary" : " ASCII")
                << ": same cells, ids and vertices: " << (same ? "yes" : "NO");
            check(same,
                  name.str() + ": not the original's cells (vertices up to " +
                    std::to_string(moved) + " apart, ids " +
                    (cells.ids == reference.ids ? "equal" : "different") + ")");
            if (linear)
              {
                const double p = pressure_at_A(name.str());
                out << ", p_A " << p;
                check(std::abs(p - p_reference) <= 1e-12 * p_reference,
                      name.str() + ": another pressure at A");
              }
            out << std::endl;
          }
    }

  // 8-node quadrilaterals (the original's E, F and H): the script meshed
  // by gmsh with incomplete second order and written; the same cells as the
  // script meshed by the program with 9-node ones.
  gmsh::initialize(0, nullptr, false);
  gmsh::option::setNumber("General.Terminal", 0);
  gmsh::open(meshes + "ssnp152.geo");
  gmsh::option::setNumber("Mesh.SecondOrderIncomplete", 1);
  gmsh::model::mesh::generate(2);
  gmsh::model::mesh::setOrder(2);
  gmsh::option::setNumber("Mesh.MshFileVersion", 4.1);
  gmsh::write("quad8.msh");
  gmsh::finalize();
  unsigned int n_quad8 = 0;
  for (const auto &element : Geometry::read_gmsh_file<2>("quad8.msh").elements)
    n_quad8 += element.type == 16;
  const Cells quad8 = cells_of("quad8.msh"),
              quad9 = cells_of(meshes + "ssnp152.geo", 2);
  double moved      = quad8.vertices.size() == quad9.vertices.size() ? 0 : 1;
  for (unsigned int i = 0; moved == 0 && i < quad8.vertices.size(); ++i)
    moved = std::max(moved, quad8.vertices[i].distance(quad9.vertices[i]));
  out << "ssnp152.geo with 8-node quadrilaterals: " << n_quad8
      << " of them, the same cells, ids and vertices as with 9-node ones: "
      << (quad8.ids == quad9.ids && moved < 1e-15 ? "yes" : "NO") << std::endl;
  check(n_quad8 == 240 && quad8.ids == quad9.ids && moved < 1e-15,
        "quad8.msh: not the script's cells");
}
