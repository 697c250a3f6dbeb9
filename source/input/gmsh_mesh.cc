// @sect3{Meshes from gmsh}
//
// Meshes from gmsh for every scenario: the checked file (gmsh_file.h) made into
// a deal.II triangulation, the audit of its boundary tags, and a size check
// before anything large is allocated. The rings read the original's meshes or a
// script of them with their physical tags; a general problem's bodies, supports
// and contact surfaces are its model's physical groups. Both go through here,
// so a file is held to the same rules whichever scenario reads it; each
// scenario then checks what it needs of the mesh (ring_mesh.cc,
// general/mesh_checks.cc).
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria_description.h>

#include <ring_contact/base/dimension.h>
#include <ring_contact/base/utilities.h>
#include <ring_contact/input/gmsh_mesh.h>

#include <unistd.h>

#include <array>
#include <cmath>
#include <iomanip>
#include <map>
#include <set>
#include <sstream>

namespace RingContact
{
  namespace Geometry
  {
    namespace
    {
      // @sect4{The triangulation of a gmsh mesh}
      //
      // Build the triangulation of a checked gmsh mesh. Only the vertices make
      // the cells: the geometry between them is the scenario's (the rings'
      // polar manifold, a general problem's straight sides), and the mid-side
      // nodes are checked against it.
      // Vertices are numbered by node tag and cells taken by element tag,
      // the order of the file whatever its format.
      // `on_circles`: the boundary lines lie on circles about the origin
      // (the rings), and a quadratic line's mid-side node must be on its
      // circle; otherwise the geometry is straight-sided, and it must be at
      // the middle of its line (a curved quadratic mesh would otherwise be
      // silently straightened).
      void
      build_triangulation(Triangulation<dim> &triangulation,
                          GmshMesh           &mesh,
                          const bool          on_circles)
      {
        // The corner nodes become the vertices: gmsh lists an element's corners
        // first at every order, the first two nodes of a line and the first
        // four of a quadrilateral. `node_of_vertex` keeps the way back from
        // vertex to node tag, which the audit of the tags needs. Nothing merges
        // nodes that lie on each other: the two copies of a contact interface
        // stay two bodies' nodes, as the file has them.
        std::map<std::size_t, unsigned int> vertex_of_node;
        for (const auto &element : mesh.elements)
          for (unsigned int i = 0;
               i < (element.type == 1 || element.type == 8 ? 2u : 4u);
               ++i)
            vertex_of_node[element.nodes[i]] = 0;
        std::vector<Point<dim>> vertices;
        mesh.node_of_vertex.clear();
        for (auto &[node, vertex] : vertex_of_node)
          {
            vertex = vertices.size();
            vertices.push_back(mesh.nodes.at(node));
            mesh.node_of_vertex.push_back(node);
          }
        std::vector<CellData<dim>> cells;
        SubCellData                lines;
        for (const auto &element : mesh.elements)
          // Quadrilaterals of 4, 9 and 8 nodes (gmsh types 3, 10, 16) are cells
          // of their physical group's material id; lines of 2 and 3 nodes
          // (types 1, 8) are boundary lines with theirs as boundary id.
          // gmsh_file.cc has refused every other type already.
          if (element.type == 3 || element.type == 10 || element.type == 16)
            {
              // gmsh: corners counterclockwise; deal.II: lexicographic.
              const auto   &n = element.nodes;
              CellData<dim> cell;
              cell.vertices    = {vertex_of_node.at(n[0]),
                                  vertex_of_node.at(n[1]),
                                  vertex_of_node.at(n[3]),
                                  vertex_of_node.at(n[2])};
              cell.material_id = element.physical;
              cells.push_back(cell);
            }
          else
            {
              const auto &n = element.nodes;
              CellData<1> segment;
              segment.vertices    = {vertex_of_node.at(n[0]),
                                     vertex_of_node.at(n[1])};
              segment.boundary_id = element.physical;
              lines.boundary_lines.push_back(segment);
              if (element.type == 8)
                {
                  const Point<dim> mid   = mesh.nodes.at(n[2]),
                                   end   = mesh.nodes.at(n[0]),
                                   other = mesh.nodes.at(n[1]);
                  if (!on_circles && mid.distance(0.5 * (end + other)) >
                                       1e-8 * end.distance(other))
                    throw std::runtime_error(
                      "mesh file '" + mesh.filename + "', element " +
                      std::to_string(element.tag) +
                      ": the mid-side node of a boundary line is not at its "
                      "middle; the geometry of a general problem is taken "
                      "from the vertices (straight sides), so a curved "
                      "quadratic mesh is refused: give a linear mesh, as "
                      "fine as the geometry needs");
                  if (on_circles &&
                      std::abs(mid.norm() - end.norm()) > 1e-8 * end.norm())
                    throw std::runtime_error(
                      "mesh file '" + mesh.filename + "', element " +
                      std::to_string(element.tag) +
                      ": the mid-side node of a boundary line is not on the "
                      "circle of its end nodes");
                }
            }
        // gmsh numbers a quadrilateral's corners in the sense of its
        // surface's curve loop: a clockwise loop gives cells of negative
        // measure, whose stiffness would have the wrong sign (the body
        // moves against its load). deal.II orders them counterclockwise. Cell
        // by cell: invert_all_negative_measure_cells() would throw on a model
        // whose surfaces run in both senses, which is a valid model. Then the
        // edges are oriented alike from both of their cells, which deal.II
        // requires and gmsh's numbering does not ensure.
        GridTools::invert_cells_with_negative_measure(vertices, cells);
        GridTools::consistently_order_cells(cells);
        try
          {
            triangulation.create_triangulation(vertices, cells, lines);
          }
        // deal.II's exception text spans several lines with its own source
        // location; the program's errors are one line that names the file.
        catch (const std::exception &e)
          {
            throw std::runtime_error(
              "mesh file '" + mesh.filename +
              "': deal.II cannot build a mesh of it: " + one_line_message(e));
          }
      }

    } // namespace

    // @sect4{The audit of the boundary tags}
    //
    // The mesh audit of the boundary: every boundary face of the
    // triangulation must be one line of the file (a face without one is a
    // line the file dropped, or a crack in the mesh, and its boundary
    // condition would silently be missing), that line must carry a
    // physical tag (an untagged line got boundary id 0: a slave line left
    // out of its contact surface, the pressure far off in the patch test:
    // doc/validation.md, "Figures that were in the code's comments"), and one
    // only (two lines of two entities on one face, with two tags: one of them
    // silently won). Each error names the file, the entity and the element. (A
    // tagged line that is no edge of a cell, or an inner edge, is refused by
    // the reader and by deal.II.)
    void
    check_boundary_tags(const Triangulation<dim> &triangulation,
                        const GmshMesh           &mesh)
    {
      // A line and a face are the same when they join the same two
      // nodes: by node, not by position (the two copies of a contact
      // interface's line lie on each other).
      using Key      = std::pair<std::size_t, std::size_t>;
      const auto key = [](const std::size_t a, const std::size_t b) {
        return std::make_pair(std::min(a, b), std::max(a, b));
      };
      const auto face_key = [&](const auto &face) {
        return key(mesh.node_of_vertex.at(face->vertex_index(0)),
                   mesh.node_of_vertex.at(face->vertex_index(1)));
      };
      const auto describe = [&](const GmshElement &e) {
        return "element " + std::to_string(e.tag) + " (gmsh entity " +
               std::to_string(e.entity) + ")";
      };
      const auto near = [](const Point<dim> &x) {
        std::ostringstream where;
        where << "(" << x[0] << ", " << x[1] << ")";
        return where.str();
      };
      std::map<Key, std::vector<const GmshElement *>> lines;
      for (const auto &element : mesh.elements)
        if (element.type == 1 || element.type == 8)
          lines[key(element.nodes[0], element.nodes[1])].push_back(&element);
      // Faces without a line are counted, not thrown at the first: the message
      // says how many there are and where the first is, which tells a whole
      // boundary that the file lacks from a crack of a few faces.
      unsigned int untagged = 0;
      Point<dim>   example;
      for (const auto &face : triangulation.active_face_iterators())
        if (face->at_boundary())
          {
            const Key  k  = face_key(face);
            const auto it = lines.find(k);
            if (it == lines.end())
              {
                if (untagged == 0)
                  example = face->center();
                ++untagged;
                continue;
              }
            for (const GmshElement *line : it->second)
              if (line->physical == 0)
                throw std::runtime_error(
                  "mesh file '" + mesh.filename + "': the boundary line " +
                  describe(*line) + " near " + near(face->center()) +
                  " has no physical tag: give its curve a 'Physical "
                  "Curve', or every boundary line of a body one");
            for (const GmshElement *line : it->second)
              if (line->physical != it->second.front()->physical)
                throw std::runtime_error(
                  "mesh file '" + mesh.filename +
                  "': the boundary face "
                  "near " +
                  near(face->center()) +
                  " carries two physical "
                  "tags, " +
                  std::to_string(it->second.front()->physical) + " (" +
                  describe(*it->second.front()) + ") and " +
                  std::to_string(line->physical) + " (" + describe(*line) +
                  "): a face belongs to one boundary");
          }
      if (untagged > 0)
        throw std::runtime_error(
          "mesh file '" + mesh.filename + "': " + std::to_string(untagged) +
          " boundary face(s) carry no physical tag from the file (the "
          "first near " +
          near(example) +
          "): a boundary line is missing or the mesh has a crack");
    }

    // @sect4{Reading, and the size check}
    //
    // read_gmsh_file() runs gmsh's library in a child process and checks what
    // it read (gmsh_file.cc, gmsh_process.cc); here it only becomes cells.
    GmshMesh
    read_gmsh(Triangulation<dim> &triangulation,
              const std::string  &filename,
              const GeoNumbers   &geo_numbers,
              const unsigned int  element_order,
              const bool          on_circles)
    {
      GmshMesh mesh = read_gmsh_file(filename, geo_numbers, element_order);
      build_triangulation(triangulation, mesh, on_circles);
      return mesh;
    }

    // Called before the coarse mesh is refined and before any unknown is
    // numbered: 'Elements around' or 'Global refinements' set beyond what the
    // machine holds is refused at once, with what it would need, instead of
    // the run swapping or being killed midway.
    void
    check_size(const std::size_t  n_coarse_cells,
               const unsigned int degree,
               const unsigned int global_refinements)
    {
      // Unknowns per cell: two displacement components, p^2 each for degree p,
      // and one p^2 more for the multipliers. That is generous: the multipliers
      // live only on the layer of slave cells along the contact surface (they
      // covered the whole slave body, about half the cells, when this estimate
      // was made).
      const unsigned int p = std::max(1u, degree);
      const double       cells =
        static_cast<double>(n_coarse_cells) * std::pow(4.0, global_refinements);
      const double unknowns = cells * 3 * p * p;
      // Bytes per unknown: the matrix, the vectors, the mesh and the direct
      // solver's factors. A deliberately generous round figure, not a
      // measurement: it only has to stop runs that cannot fit long before
      // they allocate (the 1e6-around input wanted ~24 GB).
      const double bytes_per_unknown = 4000;
      const double needed            = unknowns * bytes_per_unknown;
      const double available =
        static_cast<double>(sysconf(_SC_PHYS_PAGES)) * sysconf(_SC_PAGE_SIZE);
      if (needed > 0.8 * available)
        {
          std::ostringstream message;
          message << "the mesh is too large for this machine: about "
                  << std::setprecision(3) << cells << " cells and " << unknowns
                  << " unknowns would need about " << needed / 1e9
                  << " GB, more than 80 % of the " << available / 1e9
                  << " GB of memory (subsection 'Mesh': fewer elements or "
                     "refinements, or 'Sector elements' for cyclic symmetry)";
          throw std::runtime_error(message.str());
        }
    }

  } // namespace Geometry
} // namespace RingContact
