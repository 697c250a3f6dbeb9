#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>
#include <deal.II/grid/tria_description.h>

#include <ring_contact/geometry.h>

#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

namespace RingContact
{
  namespace Geometry
  {
    void
    make_rings(Triangulation<2> &triangulation, const MeshParameters &mesh)
    {
      // The whole rings, or (cyclic symmetry) a sector of `sector_elements`
      // columns from angle 0, whose two radial sides are boundaries.
      const unsigned int n_around  = mesh.elements_around;
      const bool         sector    = mesh.sector_elements > 0;
      const unsigned int n_columns = sector ? mesh.sector_elements : n_around;
      const unsigned int n_vertices_around = sector ? n_columns + 1 : n_around;
      std::vector<Point<2>>    vertices;
      std::vector<CellData<2>> cells;

      // One ring between radii r_in and r_out with n_radial cells across.
      // Cell (i, j): angular index i, radial index j. The local x axis runs
      // radially and y along the circle, so that every cell has a positive
      // Jacobian.
      const auto add_ring = [&](const double       r_in,
                                const double       r_out,
                                const unsigned int n_radial,
                                const unsigned int material_id) {
        const unsigned int offset = vertices.size();
        for (unsigned int j = 0; j <= n_radial; ++j)
          for (unsigned int i = 0; i < n_vertices_around; ++i)
            {
              const double r   = r_in + (r_out - r_in) * j / n_radial;
              const double phi = 2 * numbers::PI * i / n_around;
              vertices.emplace_back(r * std::cos(phi), r * std::sin(phi));
            }
        const auto v = [&](const unsigned int i, const unsigned int j) {
          return offset + j * n_vertices_around + (i % n_vertices_around);
        };
        for (unsigned int j = 0; j < n_radial; ++j)
          for (unsigned int i = 0; i < n_columns; ++i)
            {
              CellData<2> cell;
              cell.vertices    = {v(i, j),
                                  v(i, j + 1),
                                  v(i + 1, j),
                                  v(i + 1, j + 1)};
              cell.material_id = material_id;
              cells.push_back(cell);
            }
      };
      add_ring(mesh.interface_radius,
               mesh.outer_radius,
               mesh.radial_elements_outer,
               Ids::outer_ring);
      add_ring(mesh.inner_radius,
               mesh.interface_radius,
               mesh.radial_elements_inner,
               Ids::inner_ring);

      triangulation.create_triangulation(vertices, cells, SubCellData());

      // Boundary ids from the circle a face lies on and the ring it bounds;
      // the radial sides of a sector from their angle.
      const double       tol          = 1e-8 * mesh.outer_radius;
      const double       sector_angle = mesh.sector_angle();
      const Tensor<1, 2> end_normal(
        {-std::sin(sector_angle), std::cos(sector_angle)});
      for (const auto &cell : triangulation.active_cell_iterators())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary())
            {
              const bool     outer  = cell->material_id() == Ids::outer_ring;
              const Point<2> center = face->center();
              if (sector && std::abs(center[1]) < tol && center[0] > 0)
                face->set_boundary_id(Ids::sector_start);
              else if (sector && std::abs(center * end_normal) < tol)
                face->set_boundary_id(Ids::sector_end);
              else
                {
                  // The mean radius of the end points (the center of a
                  // straight face lies inside the circle).
                  const double r_face =
                    0.5 * (face->vertex(0).norm() + face->vertex(1).norm());
                  if (std::abs(r_face - mesh.outer_radius) < tol)
                    face->set_boundary_id(Ids::outer_boundary);
                  else if (std::abs(r_face - mesh.inner_radius) < tol)
                    face->set_boundary_id(Ids::inner_boundary);
                  else
                    face->set_boundary_id(outer ? Ids::outer_ring_contact :
                                                  Ids::inner_ring_contact);
                }
            }
    }

    void
    make_blocks(Triangulation<2> &triangulation, const MeshParameters &mesh)
    {
      // Lower block [0, 1] x [-0.5, 0] (master body, material 100), upper
      // block [0, 1] x [0, 0.5] (slave body, 101), two layers of cells each,
      // different numbers of cells along the interface: non-matching.
      std::vector<Point<2>>    vertices;
      std::vector<CellData<2>> cells;
      const auto               add_block = [&](const double       y0,
                                 const unsigned int nx,
                                 const unsigned int material_id) {
        const unsigned int offset = vertices.size(), ny = 2;
        for (unsigned int j = 0; j <= ny; ++j)
          for (unsigned int i = 0; i <= nx; ++i)
            vertices.emplace_back(1.0 * i / nx, y0 + 0.5 * j / ny);
        for (unsigned int j = 0; j < ny; ++j)
          for (unsigned int i = 0; i < nx; ++i)
            {
              CellData<2> cell;
              const auto  v = [&](const unsigned int a, const unsigned int b) {
                return offset + b * (nx + 1) + a;
              };
              cell.vertices    = {v(i, j),
                                  v(i + 1, j),
                                  v(i, j + 1),
                                  v(i + 1, j + 1)};
              cell.material_id = material_id;
              cells.push_back(cell);
            }
      };
      add_block(-0.5, mesh.patch_elements_lower, Ids::outer_ring);
      add_block(0.0, mesh.patch_elements_upper, Ids::inner_ring);
      triangulation.create_triangulation(vertices, cells, SubCellData());
      for (const auto &cell : triangulation.active_cell_iterators())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary())
            {
              const double y     = face->center()[1];
              const bool   lower = cell->material_id() == Ids::outer_ring;
              if (std::abs(y + 0.5) < 1e-12)
                face->set_boundary_id(Ids::outer_boundary);
              else if (std::abs(y - 0.5) < 1e-12)
                face->set_boundary_id(Ids::inner_boundary);
              else if (std::abs(y) < 1e-12)
                face->set_boundary_id(lower ? Ids::outer_ring_contact :
                                              Ids::inner_ring_contact);
              else
                face->set_boundary_id(0); // free sides
            }
    }

    namespace
    {
      // A reader for gmsh ASCII files (format 1 and 2.2) with linear or
      // quadratic quadrilaterals and lines (gmsh types 3/10 and 1/8), for
      // the meshes deal.II's GridIn does not take (9-node quadrilaterals).
      // Only the vertices make the triangulation: the curved geometry comes
      // from the polar manifold, and the mid-side nodes of the circles are
      // checked to lie on it.
      void
      read_gmsh_by_hand(Triangulation<2>  &triangulation,
                        std::istream      &in,
                        const std::string &filename)
      {
        const auto fail = [&](const std::string &what) {
          throw std::runtime_error("cannot read mesh file '" + filename +
                                   "': " + what);
        };
        std::string line;
        bool        format_1 = false;
        while (std::getline(in, line) && line != "$NOD" && line != "$Nodes")
          ;
        format_1 = (line == "$NOD");
        if (line != "$NOD" && line != "$Nodes")
          fail("no node section");
        std::size_t n_nodes = 0;
        in >> n_nodes;
        std::map<long, Point<2>> nodes;
        for (std::size_t i = 0; i < n_nodes; ++i)
          {
            long   id;
            double x, y, z;
            if (!(in >> id >> x >> y >> z))
              fail("bad node line");
            nodes[id] = Point<2>(x, y);
          }
        while (std::getline(in, line) && line != "$ELM" && line != "$Elements")
          ;
        std::size_t n_elements = 0;
        in >> n_elements;

        std::vector<Point<2>>    vertices;
        std::map<long, unsigned> vertex_of_node;
        const auto               vertex = [&](const long node) {
          const auto it = vertex_of_node.find(node);
          if (it != vertex_of_node.end())
            return it->second;
          if (nodes.count(node) == 0)
            fail("element refers to unknown node " + std::to_string(node));
          vertex_of_node[node] = vertices.size();
          vertices.push_back(nodes[node]);
          return static_cast<unsigned>(vertices.size() - 1);
        };
        std::vector<CellData<2>>                   cells;
        SubCellData                                lines;
        std::vector<std::pair<Point<2>, Point<2>>> mid_side; // mid, end
        for (std::size_t e = 0; e < n_elements; ++e)
          {
            long id, type, physical = 0, tag;
            in >> id >> type;
            std::size_t n_element_nodes = 0;
            if (format_1)
              in >> physical >> tag >> n_element_nodes;
            else
              {
                long n_tags;
                in >> n_tags;
                for (long t = 0; t < n_tags; ++t)
                  {
                    in >> tag;
                    if (t == 0)
                      physical = tag;
                  }
                n_element_nodes = type == 1  ? 2 :
                                  type == 8  ? 3 :
                                  type == 3  ? 4 :
                                  type == 10 ? 9 :
                                  type == 15 ? 1 :
                                               0;
              }
            std::vector<long> element_nodes(n_element_nodes);
            for (auto &n : element_nodes)
              in >> n;
            if (!in)
              fail("bad element line");
            if (type == 3 || type == 10)
              {
                // gmsh: corners counterclockwise; deal.II: lexicographic.
                CellData<2> cell;
                cell.vertices    = {vertex(element_nodes[0]),
                                    vertex(element_nodes[1]),
                                    vertex(element_nodes[3]),
                                    vertex(element_nodes[2])};
                cell.material_id = physical;
                cells.push_back(cell);
              }
            else if (type == 1 || type == 8)
              {
                CellData<1> segment;
                segment.vertices    = {vertex(element_nodes[0]),
                                       vertex(element_nodes[1])};
                segment.boundary_id = physical;
                lines.boundary_lines.push_back(segment);
                if (type == 8)
                  mid_side.emplace_back(nodes[element_nodes[2]],
                                        nodes[element_nodes[0]]);
              }
            else if (type != 15)
              fail("element type " + std::to_string(type) +
                   " (only quadrilaterals and lines)");
          }
        if (cells.empty())
          fail("no quadrilaterals");
        // The mid-side nodes of the boundary lines lie on the circles, as
        // the polar manifold puts them.
        for (const auto &[mid, end] : mid_side)
          if (std::abs(mid.norm() - end.norm()) > 1e-8 * end.norm())
            fail("a mid-side node of a boundary line is not on the circle of "
                 "its end nodes");
        GridTools::consistently_order_cells(cells);
        triangulation.create_triangulation(vertices, cells, lines);
      }
    } // namespace

    void
    read_gmsh(Triangulation<2> &triangulation, const std::string &filename)
    {
      std::ifstream in(filename);
      if (!in)
        throw std::runtime_error("cannot open mesh file '" + filename + "'");
      // Quadratic elements (gmsh types 8 and 10) go to our own reader; the
      // others to deal.II's, which keeps the duplicated interface nodes:
      // the two rings stay two bodies.
      std::stringstream buffer;
      buffer << in.rdbuf();
      const std::string text      = buffer.str();
      bool              quadratic = false;
      {
        std::istringstream lines(text);
        std::string        line;
        bool               in_elements = false;
        while (std::getline(lines, line))
          {
            if (line == "$ELM" || line == "$Elements")
              {
                in_elements = true;
                std::getline(lines, line);
                continue;
              }
            if (line == "$ENDELM" || line == "$EndElements")
              break;
            if (in_elements)
              {
                std::istringstream fields(line);
                long               id, type;
                fields >> id >> type;
                if (type == 8 || type == 10)
                  {
                    quadratic = true;
                    break;
                  }
              }
          }
      }
      std::istringstream stream(text);
      if (quadratic)
        {
          read_gmsh_by_hand(triangulation, stream, filename);
          return;
        }
      GridIn<2> grid_in(triangulation);
      try
        {
          grid_in.read_msh(stream);
        }
      catch (const std::exception &e)
        {
          throw std::runtime_error("cannot read mesh file '" + filename +
                                   "' as a gmsh mesh (format 1 or 2.2)");
        }
    }

    void
    create_mesh(Triangulation<2> &triangulation, const Parameters &parameters)
    {
      if (parameters.mesh.source == MeshSource::patch_test)
        {
          make_blocks(triangulation, parameters.mesh);
          triangulation.refine_global(parameters.mesh.global_refinements);
          return;
        }
      if (parameters.mesh.source == MeshSource::generated)
        make_rings(triangulation, parameters.mesh);
      else
        read_gmsh(triangulation, parameters.mesh.mesh_file);

      check_rings(triangulation, parameters);

      // Every cell, face and edge lives on the polar manifold: refinement
      // puts new vertices on the circles, and a mapping of degree >= 2
      // makes the element edges arcs.
      triangulation.set_all_manifold_ids(0);
      triangulation.set_manifold(0, PolarManifold<2>(Point<2>()));
      triangulation.refine_global(parameters.mesh.global_refinements);
    }

    void
    check_rings(const Triangulation<2> &triangulation,
                const Parameters       &parameters)
    {
      const std::string name = parameters.mesh.source == MeshSource::generated ?
                                 std::string("the generated mesh") :
                                 "mesh '" + parameters.mesh.mesh_file + "'";

      std::set<types::material_id>                               materials;
      std::map<types::boundary_id, std::set<types::material_id>> rings_of;
      std::map<types::boundary_id, double> worst_radius_error;
      for (const auto &cell : triangulation.active_cell_iterators())
        {
          materials.insert(cell->material_id());
          for (const auto &face : cell->face_iterators())
            if (face->at_boundary())
              {
                const auto id = face->boundary_id();
                rings_of[id].insert(cell->material_id());
                double expected = parameters.mesh.interface_radius;
                if (id == Ids::outer_boundary)
                  expected = parameters.mesh.outer_radius;
                else if (id == Ids::inner_boundary)
                  expected = parameters.mesh.inner_radius;
                for (unsigned int v = 0; v < 2; ++v)
                  worst_radius_error[id] =
                    std::max(worst_radius_error[id],
                             std::abs(face->vertex(v).norm() - expected));
              }
        }
      for (const unsigned int m : {Ids::outer_ring, Ids::inner_ring})
        if (materials.count(m) == 0)
          throw std::runtime_error(name + " has no cells with material id " +
                                   std::to_string(m) +
                                   " (100: outer ring, 101: inner ring)");

      const auto require_boundary = [&](const unsigned int id,
                                        const std::string &role) {
        if (rings_of.count(id) == 0)
          throw std::runtime_error(name + " has no boundary with id " +
                                   std::to_string(id) + " (the " + role + ")");
        if (rings_of.at(id).size() != 1)
          throw std::runtime_error(name + ": boundary " + std::to_string(id) +
                                   " (the " + role +
                                   ") touches both rings; it must belong to "
                                   "one");
        if (worst_radius_error.at(id) > 1e-6 * parameters.mesh.outer_radius)
          throw std::runtime_error(
            name + ": boundary " + std::to_string(id) + " (the " + role +
            ") is not on its circle; its vertices are up to " +
            std::to_string(worst_radius_error.at(id)) +
            " m off (check the radii in subsection 'Mesh')");
      };
      require_boundary(Ids::outer_boundary, "outer boundary r = R1");
      require_boundary(Ids::inner_boundary, "inner boundary r = R3");
      require_boundary(parameters.contact.slave_boundary_id, "slave surface");
      require_boundary(parameters.contact.master_boundary_id, "master surface");
      if (*rings_of.at(parameters.contact.slave_boundary_id).begin() ==
          *rings_of.at(parameters.contact.master_boundary_id).begin())
        throw std::runtime_error(name +
                                 ": the slave and master surfaces belong to "
                                 "the same ring");
    }
  } // namespace Geometry
} // namespace RingContact
