// Three-dimensional meshes from gmsh (issue 48, item 3): hexahedra of 8, 27
// and 20 nodes with quadrilaterals on their boundary, read through the same
// reader and checks as the 2d meshes, into a Triangulation<3> whose
// material ids are the physical volumes and boundary ids the physical
// surfaces. Checked:
// - a box extruded from a transfinite, recombined rectangle (4 x 2 x 2
//   hexahedra): its cells, its volume 1 to round-off, every cell of
//   positive measure, the boundary faces of each physical surface counted;
// - the same box meshed at order 2 and written by gmsh to .msh files of
//   formats 2.2 and 4.1 (at order 1 and 2): the same cells;
// - two boxes stacked with non-matching faces (the upper moved by 0.5 in
//   x, meshed 3 x 2 on the lower's 4 x 2): two material ids, the faces of
//   the contact surfaces on both sides, and the three nodes where the
//   two meshes meet at the same position kept as two vertices each;
// - gmsh's all-hexahedral subdivision of a tetrahedral mesh (the remedy the
//   refusal names): hexahedra, the volume kept;
// - refused, each with one line that names the file: tetrahedra and prisms
//   (with the remedies), a physical curve, a boundary surface without a
//   physical tag (the audit), a folded hexahedron and one that repeats a
//   corner (hand-written files), a quadratic face whose mid-edge node is
//   off its edge, a 3d model read as 2d, and a 3d mesh too large for the
//   machine.
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>

#include <ring_contact/input/gmsh_file.h>
#include <ring_contact/input/gmsh_mesh.h>

#include "gmsh_helpers.h"
#include "tests.h"

#include <gmsh.h>

#include <array>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <map>
#include <sstream>
#include <vector>

using namespace RingContact;
using RingContactTests::check;

namespace
{
  // The rectangle [0, 2] x [0, 1] at height z0, meshed n_x x 2 and extruded
  // through `height` in `layers` layers: a box of hexahedra (recombined),
  // or of prisms or tetrahedra. Its volume is physical `volume`, its
  // bottom, top and sides `surface`, + 1 and + 2.
  std::string
  box(const double       z0,
      const double       height,
      const unsigned int n_x,
      const int          volume,
      const int          surface,
      const std::string &kind   = "hexahedra",
      const int          offset = 0)
  {
    const std::string  o = std::to_string(offset);
    std::ostringstream s;
    // The upper of two boxes (offset > 0) is moved by 0.5 in x: gmsh's
    // built-in kernel merges geometry points that coincide, and two bodies
    // must not share any (their mesh nodes at x = 0.5 coincide).
    const double x0 = offset > 0 ? 0.5 : 0;
    s << "Point(" << o << "+1) = {" << x0 << ", 0, " << z0 << "};\n"
      << "Point(" << o << "+2) = {" << x0 + 2 << ", 0, " << z0 << "};\n"
      << "Point(" << o << "+3) = {" << x0 + 2 << ", 1, " << z0 << "};\n"
      << "Point(" << o << "+4) = {" << x0 << ", 1, " << z0 << "};\n"
      << "Line(" << o << "+1) = {" << o << "+1, " << o << "+2};\n"
      << "Line(" << o << "+2) = {" << o << "+2, " << o << "+3};\n"
      << "Line(" << o << "+3) = {" << o << "+3, " << o << "+4};\n"
      << "Line(" << o << "+4) = {" << o << "+4, " << o << "+1};\n"
      << "Curve Loop(" << o << "+1) = {" << o << "+1, " << o << "+2, " << o
      << "+3, " << o << "+4};\n"
      << "Plane Surface(" << o << "+1) = {" << o << "+1};\n";
    if (kind != "tetrahedra")
      s << "Transfinite Curve{" << o << "+1, " << o << "+3} = " << n_x + 1
        << ";\nTransfinite Curve{" << o << "+2, " << o
        << "+4} = 3;\nTransfinite Surface{" << o << "+1};\n";
    if (kind == "hexahedra")
      s << "Recombine Surface{" << o << "+1};\n";
    s << "out" << o << "[] = Extrude {0, 0, " << height << "} { Surface{" << o
      << "+1}; ";
    if (kind != "tetrahedra")
      s << "Layers{2}; Recombine; ";
    s << "};\n"
      << "Physical Volume(" << volume << ") = {out" << o << "[1]};\n"
      << "Physical Surface(" << surface << ") = {" << o << "+1};\n"
      << "Physical Surface(" << surface + 1 << ") = {out" << o << "[0]};\n"
      << "Physical Surface(" << surface + 2 << ") = {out" << o << "[2], out"
      << o << "[3], out" << o << "[4], out" << o << "[5]};\n";
    return s.str();
  }

  void
  write(const std::string &name, const std::string &text)
  {
    std::ofstream(name) << text;
  }

  // Read a 3d mesh with its audit; the error's text, or "".
  std::string
  error_of(const std::string &file, const unsigned int order = 1)
  {
    try
      {
        Triangulation<3> triangulation;
        const auto       mesh =
          Geometry::read_gmsh(triangulation, file, {}, order, false);
        Geometry::check_boundary_tags(triangulation, mesh);
      }
    catch (const std::exception &e)
      {
        return e.what();
      }
    return "";
  }

  // The boundary faces of each boundary id.
  std::map<unsigned int, unsigned int>
  faces_by_id(const Triangulation<3> &triangulation)
  {
    std::map<unsigned int, unsigned int> count;
    for (const auto &face : triangulation.active_face_iterators())
      if (face->at_boundary())
        ++count[face->boundary_id()];
    return count;
  }
} // namespace

int
main()
{
  auto &out = RingContactTests::deallog_file;
  out << std::setprecision(6);

  // The box, at order 1 and 2, and as .msh files of formats 2.2 and 4.1.
  write("box.geo", box(0, 0.5, 4, 1, 10));
  Triangulation<3> box_cells;
  {
    const auto mesh = Geometry::read_gmsh(box_cells, "box.geo", {}, 1, false);
    Geometry::check_boundary_tags(box_cells, mesh);
    const double volume   = GridTools::volume(box_cells);
    double       smallest = 1;
    for (const auto &cell : box_cells.active_cell_iterators())
      smallest = std::min(smallest, cell->measure());
    const auto faces = faces_by_id(box_cells);
    out << "box.geo: " << box_cells.n_active_cells() << " hexahedra, "
        << box_cells.n_vertices() << " vertices, material id "
        << box_cells.begin_active()->material_id() << ", volume - 1 "
        << (std::abs(volume - 1) < 1e-14 ? "< 1e-14" : "FAILS")
        << ", smallest cell " << smallest << "; boundary faces: bottom "
        << faces.at(10) << ", top " << faces.at(11) << ", sides "
        << faces.at(12) << std::endl;
    check(box_cells.n_active_cells() == 16 && box_cells.n_vertices() == 45,
          "the box has 4 x 2 x 2 hexahedra");
    check(std::abs(volume - 1) < 1e-14 && smallest > 0,
          "the box's volume, every cell positive");
    check(faces.size() == 3 && faces.at(10) == 8 && faces.at(11) == 8 &&
            faces.at(12) == 24,
          "the boundary faces of each physical surface");
  }
  const auto reference = RingContactTests::cells_of(box_cells);
  for (const auto &[file, order] :
       std::vector<std::pair<std::string, int>>{{"box.geo", 2},
                                                {"box22.msh", 1},
                                                {"box41.msh", 1},
                                                {"box22_q.msh", 2},
                                                {"box41_q.msh", 2}})
    {
      if (file != "box.geo")
        RingContactTests::write_with_gmsh("box.geo",
                                          file,
                                          file.find("22") != std::string::npos ?
                                            2.2 :
                                            4.1,
                                          false,
                                          order);
      Triangulation<3> triangulation;
      const auto       mesh =
        Geometry::read_gmsh(triangulation, file, {}, order, false);
      Geometry::check_boundary_tags(triangulation, mesh);
      const auto cells = RingContactTests::cells_of(triangulation);
      double moved = cells.vertices.size() == reference.vertices.size() ? 0 : 1;
      for (unsigned int i = 0; moved == 0 && i < cells.vertices.size(); ++i)
        moved =
          std::max(moved, cells.vertices[i].distance(reference.vertices[i]));
      const bool same = moved < 1e-15 && cells.ids == reference.ids;
      out << file << " (order " << order << ", "
          << (mesh.quadratic ? "quadratic" : "linear") << "): the same cells "
          << (same ? "yes" : "NO") << std::endl;
      check(same, file + " gives the box's cells");
      check(mesh.quadratic == (order == 2), file + ": its order");
    }

  // Two boxes stacked, their faces not matching (4 x 2 below, 3 x 2 above).
  write("stacked.geo",
        box(0, 0.5, 4, 1, 10) + box(0.5, 0.5, 3, 2, 20, "hexahedra", 100));
  {
    Triangulation<3> triangulation;
    const auto       mesh =
      Geometry::read_gmsh(triangulation, "stacked.geo", {}, 1, false);
    Geometry::check_boundary_tags(triangulation, mesh);
    std::map<unsigned int, unsigned int> cells;
    for (const auto &cell : triangulation.active_cell_iterators())
      ++cells[cell->material_id()];
    const auto faces = faces_by_id(triangulation);
    out << "stacked.geo: " << cells[1] << " + " << cells[2] << " hexahedra, "
        << triangulation.n_vertices() << " vertices; the lower top "
        << faces.at(11) << " faces, the upper bottom " << faces.at(20)
        << ", volume " << GridTools::volume(triangulation) << std::endl;
    // Positions held by two vertices: the lower top's nodes at x = 0.5
    // and the upper bottom's at y = 0, 0.5, 1.
    std::map<std::array<long, 3>, unsigned int> at;
    for (const Point<3> &x : triangulation.get_vertices())
      ++at[{{std::lround(x[0] * 1e9),
             std::lround(x[1] * 1e9),
             std::lround(x[2] * 1e9)}}];
    unsigned int shared = 0;
    for (const auto &[position, count] : at)
      shared += count == 2 ? 1 : 0;
    out << "stacked.geo: " << shared
        << " positions held by a vertex of each body" << std::endl;
    check(cells.size() == 2 && cells[1] == 16 && cells[2] == 12 &&
            triangulation.n_vertices() == 45 + 36 && shared == 3,
          "two bodies, their coinciding nodes not merged");
    check(faces.at(11) == 8 && faces.at(20) == 6,
          "the faces of both contact surfaces");
  }

  // gmsh's all-hexahedral subdivision of a tetrahedral mesh.
  write("subdivided.geo",
        "Mesh.SubdivisionAlgorithm = 2;\nMesh.MeshSizeMax = 0.4;\n" +
          box(0, 0.5, 4, 1, 10, "tetrahedra"));
  {
    Triangulation<3> triangulation;
    const auto       mesh =
      Geometry::read_gmsh(triangulation, "subdivided.geo", {}, 1, false);
    Geometry::check_boundary_tags(triangulation, mesh);
    double smallest = 1;
    for (const auto &cell : triangulation.active_cell_iterators())
      smallest = std::min(smallest, cell->measure());
    const double volume = GridTools::volume(triangulation);
    out
      << "subdivided.geo (Mesh.SubdivisionAlgorithm = 2): hexahedra, volume - "
         "1 "
      << (std::abs(volume - 1) < 1e-12 ? "< 1e-12" : "FAILS")
      << ", every cell positive " << (smallest > 0 ? "yes" : "NO") << std::endl;
    check(std::abs(volume - 1) < 1e-12 && smallest > 0,
          "the subdivided box's volume");
  }

  // Refused, each with one line.
  const auto refused = [&](const std::string &file,
                           const std::string &expected,
                           const unsigned int order = 1) {
    const std::string error = error_of(file, order);
    out << file << ": " << error << std::endl;
    check(error.find(file) != std::string::npos &&
            error.find(expected) != std::string::npos &&
            error.find('\n') == std::string::npos,
          file + " is refused in one line naming it: " + expected);
  };
  write("tetrahedra.geo", box(0, 0.5, 4, 1, 10, "tetrahedra"));
  refused("tetrahedra.geo", "Mesh.SubdivisionAlgorithm = 2");
  write("prisms.geo", box(0, 0.5, 4, 1, 10, "prisms"));
  refused("prisms.geo", "6-node prism");
  write("curve.geo", box(0, 0.5, 4, 1, 10) + "Physical Curve(99) = {1};\n");
  refused("curve.geo", "not curves");
  {
    std::string text = box(0, 0.5, 4, 1, 10);
    text             = text.substr(0, text.find("Physical Surface(12)"));
    write("untagged.geo", text);
    refused("untagged.geo", "24 boundary face(s) carry no physical tag");
  }
  // Hand-written: one hexahedron of the unit cube, folded (its top face's
  // last two corners swapped) or with a corner twice.
  const auto one_hexahedron = [&](const std::string &file,
                                  const std::string &corners) {
    std::ostringstream s;
    s << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n8\n";
    for (unsigned int v = 0; v < 8; ++v)
      s << v + 1 << " " << ((v == 1 || v == 2 || v == 5 || v == 6) ? 1 : 0)
        << " " << ((v == 2 || v == 3 || v == 6 || v == 7) ? 1 : 0) << " "
        << (v >= 4 ? 1 : 0) << "\n";
    // A boundary quadrilateral on the top as well: gmsh drops the nodes
    // no element names, and every node must be read.
    s << "$EndNodes\n$Elements\n2\n1 5 2 1 1 " << corners
      << "\n2 3 2 2 2 5 6 7 8\n$EndElements\n";
    write(file, s.str());
  };
  one_hexahedron("folded.msh", "1 2 3 4 5 6 8 7");
  refused("folded.msh", "folded or twisted");
  one_hexahedron("repeated.msh", "1 2 3 4 5 6 7 7");
  refused("repeated.msh", "repeats a corner node");
  // A quadratic box whose first boundary quadrilateral's first mid-edge
  // node is moved off its edge (in the file: it moves for its hexahedron
  // too).
  {
    std::ifstream            in("box22_q.msh");
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);)
      lines.push_back(line);
    std::string node;
    for (const std::string &line : lines)
      {
        std::istringstream fields(line);
        std::string        tag, type, n_tags;
        fields >> tag >> type >> n_tags;
        if (type == "10" && node.empty() && fields)
          {
            std::string skip;
            for (int t = 0; t < std::stoi(n_tags) + 4; ++t)
              fields >> skip;
            fields >> node; // the fifth node: the first mid-edge
          }
      }
    bool in_nodes = false;
    for (std::string &line : lines)
      {
        if (line == "$Nodes")
          in_nodes = true;
        if (line == "$EndNodes")
          in_nodes = false;
        if (in_nodes && line.rfind(node + " ", 0) == 0)
          {
            std::istringstream fields(line);
            std::string        tag;
            double             x, y, z;
            fields >> tag >> x >> y >> z;
            std::ostringstream moved;
            moved << std::setprecision(17) << tag << " " << x << " " << y << " "
                  << z + 0.01;
            line = moved.str();
          }
      }
    std::ofstream file("off_edge.msh");
    for (const std::string &line : lines)
      file << line << "\n";
  }
  refused("off_edge.msh", "not at the middle of its edge", 2);
  // A 3d model read as 2d.
  {
    std::string error;
    try
      {
        Triangulation<2> triangulation;
        Geometry::read_gmsh(triangulation, "box.geo", {}, 1, false);
      }
    catch (const std::exception &e)
      {
        error = e.what();
      }
    out << "box.geo read as 2d: " << error << std::endl;
    check(error.find("three-dimensional") != std::string::npos,
          "a 3d model read as 2d is refused");
  }
  // A 3d mesh too large: 16 cells refined 8 times at degree 2.
  {
    std::string error;
    try
      {
        Geometry::check_size<3>(16, 2, 8);
      }
    catch (const std::exception &e)
      {
        error = e.what();
      }
    out << "16 hexahedra refined 8 times at degree 2: "
        << error.substr(0, error.find(" would need")) << std::endl;
    check(error.find("too large") != std::string::npos,
          "a 3d mesh too large is refused");
    Geometry::check_size<3>(16, 2, 2); // 1024 cells: no error
  }
  return 0;
}
