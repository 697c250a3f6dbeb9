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
      // @sect4{The mid-side nodes of a quadratic boundary}
      //
      // The cells take their corners only: the geometry between them is the
      // scenario's (the rings' polar manifold, a general problem's straight
      // sides), and the mid-side nodes of a quadratic boundary element are
      // checked against it. `on_circles` (the rings, 2d): a line's mid-side
      // node must be on the circle of its ends; otherwise it must be at the
      // middle of its line, and in 3d each mid-edge node of a quadrilateral
      // at the middle of its edge (a curved quadratic mesh would otherwise
      // be silently straightened).
      template <int dim>
      void
      check_mid_side_nodes(const GmshMesh<dim> &mesh,
                           const GmshElement   &element,
                           const bool           on_circles)
      {
        const auto &n    = element.nodes;
        const auto  fail = [&](const std::string &what) {
          throw std::runtime_error("mesh file '" + mesh.filename +
                                   "', element " + std::to_string(element.tag) +
                                   ": " + what);
        };
        const std::string straight =
          "the geometry of a general problem is taken from the vertices "
          "(straight sides), so a curved quadratic mesh is refused: give a "
          "linear mesh, as fine as the geometry needs";
        if (dim == 2 && element.type == 8)
          {
            const Point<dim> mid   = mesh.nodes.at(n[2]),
                             end   = mesh.nodes.at(n[0]),
                             other = mesh.nodes.at(n[1]);
            if (!on_circles &&
                mid.distance(0.5 * (end + other)) > 1e-8 * end.distance(other))
              fail("the mid-side node of a boundary line is not at its "
                   "middle; " +
                   straight);
            if (on_circles &&
                std::abs(mid.norm() - end.norm()) > 1e-8 * end.norm())
              fail("the mid-side node of a boundary line is not on the "
                   "circle of its end nodes");
          }
        if (dim == 3 && (element.type == 10 || element.type == 16))
          for (unsigned int e = 0; e < 4; ++e)
            {
              const Point<dim> mid   = mesh.nodes.at(n[4 + e]),
                               end   = mesh.nodes.at(n[e]),
                               other = mesh.nodes.at(n[(e + 1) % 4]);
              if (mid.distance(0.5 * (end + other)) >
                  1e-8 * end.distance(other))
                fail("a mid-edge node of a boundary quadrilateral is not at "
                     "the middle of its edge; " +
                     straight);
            }
        // The centre node of a 9-node quadrilateral: at the mean of its
        // corners (a bulged face would be flattened too).
        if (dim == 3 && element.type == 10)
          {
            Point<dim> centre;
            for (unsigned int c = 0; c < 4; ++c)
              centre += 0.25 * mesh.nodes.at(n[c]);
            const double size =
              mesh.nodes.at(n[0]).distance(mesh.nodes.at(n[2]));
            if (mesh.nodes.at(n[8]).distance(centre) > 1e-8 * size)
              fail("the centre node of a boundary quadrilateral is not at the "
                   "mean of its corners; " +
                   straight);
          }
      }

      // @sect4{The triangulation of a gmsh mesh}
      //
      // Build the triangulation of a checked gmsh mesh. Only the vertices make
      // the cells, and the mid-side nodes are checked (above). Vertices are
      // numbered by node tag and cells taken by element tag, the order of
      // the file whatever its format.
      template <int dim>
      void
      build_triangulation(Triangulation<dim> &triangulation,
                          GmshMesh<dim>      &mesh,
                          const bool          on_circles)
      {
        // The corner nodes become the vertices: gmsh lists an element's corners
        // first at every order, the first two nodes of a line, the first
        // four of a quadrilateral and the first eight of a hexahedron.
        // `node_of_vertex` keeps the way back from vertex to node tag, which
        // the audit of the tags needs. Nothing merges nodes that lie on each
        // other: the two copies of a contact interface stay two bodies'
        // nodes, as the file has them.
        std::map<std::size_t, unsigned int> vertex_of_node;
        for (const auto &element : mesh.elements)
          for (unsigned int i = 0; i < corners_of_type(element.type); ++i)
            vertex_of_node[element.nodes[i]] = 0;
        std::vector<Point<dim>> vertices;
        mesh.node_of_vertex.clear();
        for (auto &[node, vertex] : vertex_of_node)
          {
            vertex = vertices.size();
            vertices.push_back(mesh.nodes.at(node));
            mesh.node_of_vertex.push_back(node);
          }
        // gmsh numbers the corners of a quadrilateral counterclockwise and
        // those of a hexahedron counterclockwise below, then above; deal.II
        // lexicographically.
        const auto lexicographic = [&](const GmshElement &element) {
          const unsigned int        n = corners_of_type(element.type);
          std::vector<unsigned int> v(n);
          for (unsigned int i = 0; i < n; ++i)
            v[i] = vertex_of_node.at(
              element.nodes[n == 2 ? i : (i ^ ((i >> 1) & 1))]);
          return v;
        };
        std::vector<CellData<dim>> cells;
        SubCellData                sides;
        for (const auto &element : mesh.elements)
          // Cells (quadrilaterals in 2d, hexahedra in 3d) take their
          // physical group's material id; boundary elements (lines in 2d,
          // quadrilaterals in 3d) theirs as boundary id. gmsh_checks.cc has
          // refused every other type already.
          if (is_cell_type<dim>(element.type))
            {
              CellData<dim> cell;
              cell.vertices    = lexicographic(element);
              cell.material_id = element.physical;
              cells.push_back(cell);
            }
          else
            {
              CellData<dim - 1> side;
              side.vertices    = lexicographic(element);
              side.boundary_id = element.physical;
              if constexpr (dim == 2)
                sides.boundary_lines.push_back(side);
              else
                sides.boundary_quads.push_back(side);
              check_mid_side_nodes(mesh, element, on_circles);
            }
        // gmsh numbers a quadrilateral's corners in the sense of its
        // surface's curve loop: a clockwise loop gives cells of negative
        // measure, whose stiffness would have the wrong sign (the body
        // moves against its load). deal.II orders them counterclockwise. Cell
        // by cell: invert_all_negative_measure_cells() would throw on a model
        // whose surfaces run in both senses, which is a valid model. Then the
        // edges are oriented alike from both of their cells, which deal.II
        // requires and gmsh's numbering does not ensure (in 3d a mesh whose
        // faces cannot be oriented alike is refused there).
        try
          {
            GridTools::invert_cells_with_negative_measure(vertices, cells);
            GridTools::consistently_order_cells(cells);
            triangulation.create_triangulation(vertices, cells, sides);
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
    template <int dim>
    void
    check_boundary_tags(const Triangulation<dim> &triangulation,
                        const GmshMesh<dim>      &mesh)
    {
      // A boundary element and a face are the same when they join the same
      // nodes: by node, not by position (the two copies of a contact
      // interface's line lie on each other). The key is the sorted corner
      // node tags.
      using Key           = std::vector<std::size_t>;
      const auto face_key = [&](const auto &face) {
        Key k;
        for (const unsigned int v : face->vertex_indices())
          k.push_back(mesh.node_of_vertex.at(face->vertex_index(v)));
        std::sort(k.begin(), k.end());
        return k;
      };
      const auto element_key = [](const GmshElement &e) {
        Key k(e.nodes.begin(), e.nodes.begin() + corners_of_type(e.type));
        std::sort(k.begin(), k.end());
        return k;
      };
      const auto describe = [&](const GmshElement &e) {
        return "element " + std::to_string(e.tag) + " (gmsh entity " +
               std::to_string(e.entity) + ")";
      };
      const auto near = [](const Point<dim> &x) {
        std::ostringstream where;
        where << "(" << x[0];
        for (unsigned int d = 1; d < dim; ++d)
          where << ", " << x[d];
        where << ")";
        return where.str();
      };
      // What the file's boundary elements are called in the messages.
      const std::string side_name = dim == 2 ? "line" : "quadrilateral";
      std::map<Key, std::vector<const GmshElement *>> lines;
      for (const auto &element : mesh.elements)
        if (is_face_type<dim>(element.type))
          lines[element_key(element)].push_back(&element);
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
                  "mesh file '" + mesh.filename + "': the boundary " +
                  side_name + " " + describe(*line) + " near " +
                  near(face->center()) +
                  (dim == 2 ? " has no physical tag: give its curve a "
                              "'Physical Curve', or every boundary line of a "
                              "body one" :
                              " has no physical tag: give its surface a "
                              "'Physical Surface', or every boundary surface "
                              "of a body one"));
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
          near(example) + "): a boundary " + side_name +
          " is missing or the mesh has a crack");
    }

    // @sect4{Reading, and the size check}
    //
    // read_gmsh_file() runs gmsh's library in a child process and checks what
    // it read (gmsh_file.cc, gmsh_process.cc); here it only becomes cells.
    template <int dim>
    GmshMesh<dim>
    read_gmsh(Triangulation<dim> &triangulation,
              const std::string  &filename,
              const GeoNumbers   &geo_numbers,
              const unsigned int  element_order,
              const bool          on_circles)
    {
      GmshMesh<dim> mesh =
        read_gmsh_file<dim>(filename, geo_numbers, element_order);
      build_triangulation(triangulation, mesh, on_circles);
      return mesh;
    }

    // Called before the coarse mesh is refined and before any unknown is
    // numbered: 'Elements around' or 'Global refinements' set beyond what the
    // machine holds is refused at once, with what it would need, instead of
    // the run swapping or being killed midway.
    template <int dim>
    void
    check_size(const std::size_t  n_coarse_cells,
               const unsigned int degree,
               const unsigned int global_refinements)
    {
      // Unknowns per cell: dim displacement components, p^dim each for
      // degree p, and one p^dim more for the multipliers. That is generous:
      // the multipliers live only on the layer of slave cells along the
      // contact surface (they covered the whole slave body, about half the
      // cells, when this estimate was made).
      const unsigned int p     = std::max(1u, degree);
      const double       cells = static_cast<double>(n_coarse_cells) *
                           std::pow(dim == 2 ? 4.0 : 8.0, global_refinements);
      const double unknowns = cells * (dim + 1) * std::pow(p, dim);
      // Bytes per unknown: the matrix, the vectors, the mesh and the direct
      // solver's factors. A deliberately generous round figure, not a
      // measurement: it only has to stop runs that cannot fit long before
      // they allocate (the 1e6-around input wanted ~24 GB). In 3d a
      // direct solver's fill grows faster than the unknowns, and a row of
      // the matrix holds several times a 2d row's entries: the figure is
      // larger by the ratio of the two fills at 1e5 unknowns.
      const double bytes_per_unknown = dim == 2 ? 4000 : 30000;
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

    // The two dimensions of the program (issue 48).
    template GmshMesh<2>
    read_gmsh(Triangulation<2> &,
              const std::string &,
              const GeoNumbers &,
              unsigned int,
              bool);
    template GmshMesh<3>
    read_gmsh(Triangulation<3> &,
              const std::string &,
              const GeoNumbers &,
              unsigned int,
              bool);
    template void
    check_boundary_tags(const Triangulation<2> &, const GmshMesh<2> &);
    template void
    check_boundary_tags(const Triangulation<3> &, const GmshMesh<3> &);
    template void
    check_size<2>(std::size_t, unsigned int, unsigned int);
    template void
    check_size<3>(std::size_t, unsigned int, unsigned int);
  } // namespace Geometry
} // namespace RingContact
