#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>
#include <deal.II/grid/tria_description.h>

#include <ring_contact/geometry.h>
#include <ring_contact/gmsh_file.h>
#include <ring_contact/utilities.h>

#include <unistd.h>

#include <array>
#include <cmath>
#include <fstream>
#include <iomanip>
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
      // the radial sides of a sector from their angle and the side of the
      // cell (with k = Ne both sides lie on the ray at angle 0).
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
              if (sector && std::abs(center[1]) < tol && center[0] > 0 &&
                  cell->center()[1] > 0)
                face->set_boundary_id(Ids::sector_start);
              else if (sector && std::abs(center * end_normal) < tol &&
                       cell->center() * end_normal < 0)
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
      // Build the triangulation of a checked gmsh mesh. Only the vertices
      // make the cells: the curved geometry comes from the polar manifold,
      // and the mid-side nodes of the circles are checked to lie on it.
      // Vertices are numbered by node tag and cells taken by element tag,
      // the order of the file whatever its format.
      // `on_circles`: the boundary lines lie on circles about the origin
      // (the rings), and a quadratic line's mid-side node must be on its
      // circle; otherwise the geometry is straight-sided, and it must be at
      // the middle of its line (a curved quadratic mesh would otherwise be
      // silently straightened).
      void
      build_triangulation(Triangulation<2> &triangulation,
                          GmshMesh         &mesh,
                          const bool        on_circles)
      {
        std::map<std::size_t, unsigned int> vertex_of_node;
        for (const auto &element : mesh.elements)
          for (unsigned int i = 0;
               i < (element.type == 1 || element.type == 8 ? 2u : 4u);
               ++i)
            vertex_of_node[element.nodes[i]] = 0;
        std::vector<Point<2>> vertices;
        mesh.node_of_vertex.clear();
        for (auto &[node, vertex] : vertex_of_node)
          {
            vertex = vertices.size();
            vertices.push_back(mesh.nodes.at(node));
            mesh.node_of_vertex.push_back(node);
          }
        std::vector<CellData<2>> cells;
        SubCellData              lines;
        for (const auto &element : mesh.elements)
          if (element.type == 3 || element.type == 10 || element.type == 16)
            {
              // gmsh: corners counterclockwise; deal.II: lexicographic.
              const auto &n = element.nodes;
              CellData<2> cell;
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
                  const Point<2> mid   = mesh.nodes.at(n[2]),
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
        // moves against its load). deal.II orders them counterclockwise.
        GridTools::invert_cells_with_negative_measure(vertices, cells);
        GridTools::consistently_order_cells(cells);
        try
          {
            triangulation.create_triangulation(vertices, cells, lines);
          }
        catch (const std::exception &e)
          {
            throw std::runtime_error(
              "mesh file '" + mesh.filename +
              "': deal.II cannot build a mesh of it: " + one_line_message(e));
          }
      }

      // The mesh audit of the boundary: every boundary face of the
      // triangulation must be one line of the file (a face without one is a
      // line the file dropped, or a crack in the mesh, and its boundary
      // condition would silently be missing), that line must carry a
      // physical tag (an untagged line got boundary id 0: a slave line left
      // out of its contact surface, the pressure off by up to 200 % in the
      // patch test), and one only (two lines of two entities on one face,
      // with two tags: one of them silently won). Each error names the
      // file, the entity and the element. (A tagged line that is no edge of
      // a cell, or an inner edge, is refused by the reader and by deal.II.)
      void
      check_boundary_tags(const Triangulation<2> &triangulation,
                          const GmshMesh         &mesh)
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
        const auto near = [](const Point<2> &x) {
          std::ostringstream where;
          where << "(" << x[0] << ", " << x[1] << ")";
          return where.str();
        };
        std::map<Key, std::vector<const GmshElement *>> lines;
        for (const auto &element : mesh.elements)
          if (element.type == 1 || element.type == 8)
            lines[key(element.nodes[0], element.nodes[1])].push_back(&element);
        unsigned int untagged = 0;
        Point<2>     example;
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
                    "mesh file '" + mesh.filename + "': the boundary face "
                    "near " + near(face->center()) + " carries two physical "
                    "tags, " + std::to_string(it->second.front()->physical) +
                    " (" + describe(*it->second.front()) + ") and " +
                    std::to_string(line->physical) + " (" + describe(*line) +
                    "): a face belongs to one boundary");
            }
        if (untagged > 0)
          throw std::runtime_error(
            "mesh file '" + mesh.filename + "': " + std::to_string(untagged) +
            " boundary face(s) carry no physical tag from the file (the "
            "first near " + near(example) +
            "): a boundary line is missing or the mesh has a crack");
      }
    } // namespace

    GmshMesh
    read_gmsh(Triangulation<2>  &triangulation,
              const std::string &filename,
              const GeoNumbers  &geo_numbers,
              const unsigned int element_order,
              const bool         on_circles)
    {
      GmshMesh mesh = read_gmsh_file(filename, geo_numbers, element_order);
      build_triangulation(triangulation, mesh, on_circles);
      return mesh;
    }

    void
    check_size(const std::size_t n_coarse_cells, const Parameters &parameters)
    {
      // Unknowns per cell: two displacement components and, on about half
      // of the cells, the multiplier, each p^2 per cell for degree p.
      unsigned int p = std::max(parameters.finite_elements.degree_outer,
                                parameters.finite_elements.degree_inner);
      if (parameters.general())
        {
          p = 1;
          for (const auto &body : parameters.problem.bodies)
            p = std::max(p, body.degree);
        }
      const double cells = static_cast<double>(n_coarse_cells) *
                           std::pow(4.0, parameters.mesh.global_refinements);
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

    void
    check_bodies(const Triangulation<2> &triangulation,
                 const Parameters       &parameters)
    {
      const std::string name    = "mesh '" + parameters.mesh.mesh_file + "'";
      const auto       &problem = parameters.problem;
      std::map<types::material_id, unsigned int> body_of;
      std::string                                ids;
      for (unsigned int b = 0; b < problem.bodies.size(); ++b)
        {
          body_of[problem.bodies[b].material_id] = b;
          ids += (b == 0 ? "" : ", ") +
                 std::to_string(problem.bodies[b].material_id);
        }

      std::set<types::material_id>                               materials;
      std::map<types::boundary_id, std::set<types::material_id>> bodies_of;
      for (const auto &cell : triangulation.active_cell_iterators())
        {
          materials.insert(cell->material_id());
          if (body_of.count(cell->material_id()) == 0)
            throw std::runtime_error(name + " has cells of physical group " +
                                     std::to_string(cell->material_id()) +
                                     ", which is no body's 'Material id' (" +
                                     ids + ")");
          for (const auto &face : cell->face_iterators())
            if (face->at_boundary())
              bodies_of[face->boundary_id()].insert(cell->material_id());
        }
      for (unsigned int b = 0; b < problem.bodies.size(); ++b)
        if (materials.count(problem.bodies[b].material_id) == 0)
          throw std::runtime_error(
            name + " has no cells of physical group " +
            std::to_string(problem.bodies[b].material_id) + " (Body " +
            std::to_string(b + 1) + "'s 'Material id')");

      const auto require_boundary = [&](const unsigned int id,
                                        const std::string &role) {
        if (bodies_of.count(id) == 0)
          throw std::runtime_error(name + " has no boundary with tag " +
                                   std::to_string(id) + " (" + role + ")");
      };
      for (const auto &condition : problem.boundary_conditions)
        require_boundary(condition.boundary_id, condition.name);
      for (const auto &check : problem.checks)
        if (check.quantity == ProblemQuantity::resultant_force_x ||
            check.quantity == ProblemQuantity::resultant_force_y)
          require_boundary(check.boundary_id, check.name);
      const auto pairs = parameters.contact_pairs();
      for (unsigned int k = 0; k < pairs.size(); ++k)
        {
          const std::string subsection =
            k == 0 ? "Contact" : "Contact pair " + std::to_string(k + 1);
          const auto [slave, master] = pairs[k];
          require_boundary(slave, subsection + "/Slave boundary");
          require_boundary(master, subsection + "/Master boundary");
          for (const auto &[id, role] : {std::make_pair(slave, "slave"),
                                         std::make_pair(master, "master")})
            if (bodies_of.at(id).size() != 1)
              throw std::runtime_error(name + ": the " + role + " surface " +
                                       std::to_string(id) + " of " +
                                       subsection +
                                       " touches two bodies; it must belong "
                                       "to one");
          const auto slave_body  = *bodies_of.at(slave).begin();
          const auto master_body = *bodies_of.at(master).begin();
          if (slave_body == master_body)
            throw std::runtime_error(
              name + ": the slave and master surfaces of " + subsection +
              " belong to the same body (" + std::to_string(slave_body) + ")");
          if (parameters.finite_elements.multiplier_degree >
              problem.bodies[body_of.at(slave_body)].degree)
            throw std::runtime_error(
              "Finite elements/Multiplier degree (" +
              std::to_string(parameters.finite_elements.multiplier_degree) +
              ") exceeds the displacement degree of the slave body of " +
              subsection + " (Body " +
              std::to_string(body_of.at(slave_body) + 1) + ")");
        }
      // The slave surfaces of two pairs share no vertex: a pressure node
      // belongs to one pair.
      std::map<unsigned int, unsigned int> pair_of_vertex;
      for (const auto &cell : triangulation.active_cell_iterators())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary())
            for (unsigned int k = 0; k < pairs.size(); ++k)
              if (face->boundary_id() == pairs[k].first)
                for (const unsigned int v : face->vertex_indices())
                  {
                    const auto [at, inserted] =
                      pair_of_vertex.emplace(face->vertex_index(v), k);
                    if (!inserted && at->second != k)
                      throw std::runtime_error(
                        name + ": the slave surfaces " +
                        std::to_string(pairs[at->second].first) + " and " +
                        std::to_string(pairs[k].first) +
                        " of two contact pairs share the vertex (" +
                        std::to_string(face->vertex(v)[0]) + ", " +
                        std::to_string(face->vertex(v)[1]) +
                        "); a pressure node belongs to one pair");
                  }
    }

    void
    create_mesh(Triangulation<2> &triangulation, const Parameters &parameters)
    {
      const auto &mesh_parameters = parameters.mesh;
      // A general problem: the bodies of a gmsh mesh, straight-sided
      // (FlatManifold), meshed from a script with linear elements (the
      // cells take the vertices only).
      if (parameters.general())
        {
          const GmshMesh mesh = read_gmsh(triangulation,
                                          parameters.mesh.mesh_file,
                                          parameters.mesh.geo_numbers,
                                          1,
                                          false);
          // The audit of the file's tags first: a line it drops leaves a
          // boundary without faces, which check_bodies() would report.
          check_boundary_tags(triangulation, mesh);
          check_bodies(triangulation, parameters);
          check_size(triangulation.n_active_cells(), parameters);
          triangulation.refine_global(parameters.mesh.global_refinements);
          return;
        }
      if (parameters.mesh.source == MeshSource::patch_test)
        {
          check_size(2 * (mesh_parameters.patch_elements_lower +
                          mesh_parameters.patch_elements_upper),
                     parameters);
          make_blocks(triangulation, parameters.mesh);
          triangulation.refine_global(parameters.mesh.global_refinements);
          return;
        }
      if (parameters.mesh.source == MeshSource::generated)
        {
          const std::size_t columns = mesh_parameters.sector_elements > 0 ?
                                        mesh_parameters.sector_elements :
                                        mesh_parameters.elements_around;
          check_size(std::size_t(columns) *
                       (mesh_parameters.radial_elements_outer +
                        mesh_parameters.radial_elements_inner),
                     parameters);
          make_rings(triangulation, parameters.mesh);
          check_rings(triangulation, parameters);
        }
      else
        {
          // A script is meshed with the elements the rings use: linear if
          // both rings are, quadratic otherwise (the cells take only the
          // vertices; quadratic nodes on the circles are checked).
          const auto    &fe = parameters.finite_elements;
          const unsigned order =
            fe.degree_outer == 1 && fe.degree_inner == 1 ? 1 : 2;
          const GmshMesh mesh = read_gmsh(triangulation,
                                          parameters.mesh.mesh_file,
                                          parameters.mesh.geo_numbers,
                                          order);
          check_rings(triangulation, parameters);
          check_boundary_tags(triangulation, mesh);
          check_size(triangulation.n_active_cells(), parameters);
        }

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
      // Each circle is covered once: its faces span the whole turn (the
      // sector angle for a sector), no gap, no overlap.
      std::map<types::boundary_id, double> angle_covered;
      for (const auto &cell : triangulation.active_cell_iterators())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary())
            {
              const Point<2> a = face->vertex(0), b = face->vertex(1);
              angle_covered[face->boundary_id()] +=
                std::abs(std::atan2(a[0] * b[1] - a[1] * b[0], a * b));
            }
      const double full_turn = parameters.mesh.sector_elements > 0 ?
                                 parameters.mesh.sector_angle() :
                                 2 * numbers::PI;
      for (const auto id : {Ids::outer_boundary,
                            Ids::inner_boundary,
                            static_cast<types::boundary_id>(
                              parameters.contact.slave_boundary_id),
                            static_cast<types::boundary_id>(
                              parameters.contact.master_boundary_id)})
        if (angle_covered.count(id) != 0 &&
            std::abs(angle_covered[id] - full_turn) > 1e-6 * full_turn)
          throw std::runtime_error(
            name + ": boundary " + std::to_string(id) + " covers " +
            std::to_string(angle_covered[id] * 180 / numbers::PI) +
            " degrees of its circle instead of " +
            std::to_string(full_turn * 180 / numbers::PI) +
            " (a gap or an overlap)");

      require_boundary(Ids::outer_boundary, "outer boundary r = R1");
      require_boundary(Ids::inner_boundary, "inner boundary r = R3");
      require_boundary(parameters.contact.slave_boundary_id, "slave surface");
      require_boundary(parameters.contact.master_boundary_id, "master surface");
      // Every boundary face belongs to one of the known boundaries.
      std::set<types::boundary_id> known = {
        Ids::outer_boundary,
        Ids::inner_boundary,
        static_cast<types::boundary_id>(parameters.contact.slave_boundary_id),
        static_cast<types::boundary_id>(parameters.contact.master_boundary_id)};
      if (parameters.mesh.sector_elements > 0)
        known.insert({Ids::sector_start, Ids::sector_end});
      for (const auto &[id, rings] : rings_of)
        if (known.count(id) == 0)
          throw std::runtime_error(
            name + " has boundary faces with id " + std::to_string(id) +
            ", which is none of the ring boundaries (200, 500) nor the "
            "slave or master surface (a boundary line missing from a mesh "
            "file leaves id 0)");


      if (*rings_of.at(parameters.contact.slave_boundary_id).begin() ==
          *rings_of.at(parameters.contact.master_boundary_id).begin())
        throw std::runtime_error(name +
                                 ": the slave and master surfaces belong to "
                                 "the same ring");
    }
  } // namespace Geometry
} // namespace RingContact
