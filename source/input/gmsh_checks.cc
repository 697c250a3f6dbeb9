// @sect3{Gmsh meshes: what gmsh read, checked}
//
// gmsh gives back what the file says, damaged or not; deal.II builds a
// triangulation from whatever it is handed. Between the two, what a mesh of
// bodies in contact must be: the cells, the nodes, the elements and their
// physical tags (the reading itself is gmsh_file.cc's). In two dimensions the
// cells are quadrilaterals and the boundary is lines; in three the cells are
// hexahedra and the boundary is quadrilaterals. deal.II's hexahedral
// meshes (and p4est's) take no tetrahedra, prisms or pyramids: a model
// meshed with them is refused with the ways gmsh has of making hexahedra.
// Every error is one line that names the file.
#include <ring_contact/base/utilities.h>
#include <ring_contact/input/gmsh_checks.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <stdexcept>

namespace RingContact
{
  namespace Geometry
  {
    void
    refuse_mesh_file(const std::string &filename, const std::string &what)
    {
      throw std::runtime_error("cannot read mesh file '" +
                               printable(filename, 200) + "': " + what);
    }

    namespace
    {
      // The nodes of each accepted element type in dimension dim (0: not
      // accepted). The cells take only their corners, so the 8-node
      // quadrilateral (the original's meshes of E, F and H) is as good as
      // the 9-node one, and the 20-node hexahedron as the 27-node one;
      // points are accepted here and dropped later (a script's geometry
      // points are elements of type 15), and so are the lines of a 3d
      // model (the edges of its surfaces).
      template <int dim>
      unsigned int
      nodes_of_type(const int type)
      {
        switch (type)
          {
            case 1:
              return 2; // 2-node line
            case 3:
              return 4; // 4-node quadrilateral
            case 5:
              return dim == 3 ? 8 : 0; // 8-node hexahedron
            case 8:
              return 3; // 3-node line
            case 10:
              return 9; // 9-node quadrilateral
            case 12:
              return dim == 3 ? 27 : 0; // 27-node hexahedron
            case 15:
              return 1; // point
            case 16:
              return 8; // 8-node quadrilateral
            case 17:
              return dim == 3 ? 20 : 0; // 20-node hexahedron
            default:
              return 0;
          }
      }

      // For the message only: a user whose mesh is made of triangles is
      // told so in words, not by a gmsh type number.
      std::string
      name_of_type(const int type)
      {
        switch (type)
          {
            case 2:
              return "3-node triangle";
            case 4:
              return "4-node tetrahedron";
            case 5:
              return "8-node hexahedron";
            case 6:
              return "6-node prism";
            case 7:
              return "5-node pyramid";
            case 9:
              return "6-node triangle";
            case 11:
              return "10-node tetrahedron";
            case 12:
              return "27-node hexahedron";
            case 13:
              return "18-node prism";
            case 14:
              return "14-node pyramid";
            case 17:
              return "20-node hexahedron";
            case 18:
              return "15-node prism";
            case 19:
              return "13-node pyramid";
            case 20:
            case 21:
              return "higher-order triangle";
            case 29:
            case 30:
            case 31:
              return "higher-order tetrahedron";
            case 36:
            case 37:
              return "higher-order quadrilateral";
            default:
              return "element";
          }
      }

      // What a model of dimension dim must be meshed with, for the message
      // that refuses another element.
      template <int dim>
      std::string
      accepted_elements()
      {
        if (dim == 2)
          return "the bodies must be meshed with quadrilaterals (gmsh types "
                 "3, 10 and 16; in a .geo, 'Recombine Surface' makes them) "
                 "and lines (1 and 8)";
        return "the bodies must be meshed with hexahedra (gmsh types 5, 12 "
               "and 17) and their boundaries with quadrilaterals (3, 10 and "
               "16); in a .geo, transfinite volumes with 'Recombine "
               "Surface' and 'Recombine Volume', 'Extrude' with 'Layers' "
               "and 'Recombine', or 'Mesh.SubdivisionAlgorithm = 2' (gmsh's "
               "all-hexahedral subdivision) make them";
      }

      // @sect4{The cells}
      //
      // No cell repeats a corner, is folded or flat; no edge (in 3d: face)
      // is shared by more than two cells; every boundary element is a side
      // of a cell. Sides are sets of node tags, not of positions: the two
      // copies of a contact interface lie on each other but are different
      // nodes, so their cells share no side.
      using Side = std::vector<std::size_t>;

      // The side of a boundary element, or of a cell through its corners
      // `corners`: its corner node tags, sorted.
      Side
      side_of(const GmshElement &e, const std::vector<unsigned int> &corners)
      {
        Side side;
        for (const unsigned int c : corners)
          side.push_back(e.nodes[c]);
        std::sort(side.begin(), side.end());
        return side;
      }

      [[noreturn]] void
      element_fail(const std::string &filename,
                   const GmshElement &e,
                   const std::string &what)
      {
        refuse_mesh_file(filename,
                         "element " + std::to_string(e.tag) + ": " + what);
      }

      // Whether a corner's cross product or volume `value` keeps the sign of
      // the corners before it (`sign`, 0 before the first, then set): it
      // must be one sign and larger than 1e-12 of its scale, the product of
      // its edges' lengths, so that the test does not depend on the units.
      bool
      keeps_orientation(const double value, const double scale, int &sign)
      {
        const int s = value > 1e-12 * scale  ? 1 :
                      value < -1e-12 * scale ? -1 :
                                               0;
        if (s == 0 || (sign != 0 && s != sign))
          return false;
        sign = s;
        return true;
      }

      // A quadrilateral: gmsh numbers the corners around the cell, and the
      // turns at the four corners must all have one sign. One sign, not a
      // positive one: cells drawn clockwise (a surface whose outline runs
      // clockwise) are reoriented when the triangulation is built. The
      // cross product is compared with 1e-12 of the edge lengths' product,
      // so the test does not depend on the units (keeps_orientation()).
      void
      check_quadrilateral(const GmshMesh<2>            &mesh,
                          const GmshElement            &e,
                          std::map<Side, unsigned int> &side_use)
      {
        const std::set<std::size_t> corners(e.nodes.begin(),
                                            e.nodes.begin() + 4);
        if (corners.size() != 4)
          element_fail(mesh.filename,
                       e,
                       "a quadrilateral that repeats a corner node");
        int sign = 0;
        for (unsigned int i = 0; i < 4; ++i)
          {
            const Point<2> a = mesh.nodes.at(e.nodes[i]);
            const Point<2> b = mesh.nodes.at(e.nodes[(i + 1) % 4]);
            const Point<2> c = mesh.nodes.at(e.nodes[(i + 2) % 4]);
            const double   cross =
              (b[0] - a[0]) * (c[1] - b[1]) - (b[1] - a[1]) * (c[0] - b[0]);
            if (!keeps_orientation(cross,
                                   (b - a).norm() * (c - b).norm(),
                                   sign))
              element_fail(mesh.filename,
                           e,
                           "a quadrilateral that is flat, folded or not "
                           "convex");
          }
        // An edge of three cells is no surface deal.II can build.
        for (unsigned int i = 0; i < 4; ++i)
          if (++side_use[side_of(e, {i, (i + 1) % 4})] > 2)
            element_fail(mesh.filename,
                         e,
                         "an edge shared by more than two quadrilaterals");
      }

      // A hexahedron: gmsh numbers its corners 0-3 around the bottom face
      // and 4-7 above them. At each corner the three edges that leave it,
      // taken in the directions of the cell's axes, must span a volume of
      // one sign at all eight (the trilinear map's Jacobian at the corners;
      // one sign: a cell numbered the other way round is reoriented when the
      // triangulation is built), compared with 1e-12 of the edges' lengths'
      // product. A face of three cells is no body deal.II can build.
      void
      check_hexahedron(const GmshMesh<3>            &mesh,
                       const GmshElement            &e,
                       std::map<Side, unsigned int> &side_use)
      {
        const std::set<std::size_t> corners(e.nodes.begin(),
                                            e.nodes.begin() + 8);
        if (corners.size() != 8)
          element_fail(mesh.filename,
                       e,
                       "a hexahedron that repeats a corner node");
        // gmsh's corner at (i, j, k) of the unit cube, and the neighbour
        // of a corner along each axis.
        const std::array<unsigned int, 8> gmsh_corner = {
          {0, 1, 3, 2, 4, 5, 7, 6}};
        int sign = 0;
        for (unsigned int v = 0; v < 8; ++v)
          {
            const Point<3> &x = mesh.nodes.at(e.nodes[gmsh_corner[v]]);
            Tensor<1, 3>    edge[3];
            double          scale = 1;
            for (unsigned int d = 0; d < 3; ++d)
              {
                const unsigned int w = v ^ (1u << d); // the neighbour
                edge[d] = mesh.nodes.at(e.nodes[gmsh_corner[w]]) - x;
                if (w < v)
                  edge[d] *= -1; // along the axis, not against it
                scale *= edge[d].norm();
              }
            if (!keeps_orientation(cross_product_3d(edge[0], edge[1]) * edge[2],
                                   scale,
                                   sign))
              element_fail(mesh.filename,
                           e,
                           "a hexahedron that is flat, folded or twisted "
                           "(its corners' volumes change sign)");
          }
        // Its six faces, by their corners in gmsh's numbering.
        static const std::vector<std::vector<unsigned int>> faces = {
          {0, 1, 2, 3},
          {4, 5, 6, 7},
          {0, 1, 5, 4},
          {1, 2, 6, 5},
          {2, 3, 7, 6},
          {3, 0, 4, 7}};
        for (const auto &face : faces)
          if (++side_use[side_of(e, face)] > 2)
            element_fail(mesh.filename,
                         e,
                         "a face shared by more than two hexahedra");
      }

      template <int dim>
      void
      check_cells(const GmshMesh<dim> &mesh)
      {
        std::map<Side, unsigned int> side_use;
        bool                         any_cell = false, linear = false;
        for (const auto &e : mesh.elements)
          if (is_cell_type<dim>(e.type))
            {
              any_cell = true;
              linear   = linear || e.type == 3 || e.type == 5;
              if constexpr (dim == 2)
                check_quadrilateral(mesh, e, side_use);
              else
                check_hexahedron(mesh, e, side_use);
            }
        // A mesh of triangles, or of lines only, has no cell this program
        // can use; the message says how gmsh makes quadrilaterals.
        if (!any_cell)
          refuse_mesh_file(
            mesh.filename,
            dim == 2 ? "no quadrilaterals (the bodies are meshed with gmsh "
                       "types 3, 10 or 16; in a .geo, 'Recombine Surface' "
                       "makes them)" :
                       "no hexahedra (" + accepted_elements<dim>() + ")");
        if (linear && mesh.quadratic)
          refuse_mesh_file(mesh.filename,
                           "linear and quadratic elements mixed");
        // A boundary element must lie on the cells it bounds, or the
        // boundary id it carries would be given to no face.
        for (const auto &e : mesh.elements)
          if (is_face_type<dim>(e.type))
            {
              std::vector<unsigned int> corners(corners_of_type(e.type));
              for (unsigned int c = 0; c < corners.size(); ++c)
                corners[c] = c;
              if (side_use.count(side_of(e, corners)) == 0)
                element_fail(mesh.filename,
                             e,
                             std::string(dim == 2 ? "a line" :
                                                    "a quadrilateral") +
                               " (physical tag " + std::to_string(e.physical) +
                               ") that is not " +
                               (dim == 2 ? "an edge of a quadrilateral" :
                                           "a face of a hexahedron"));
            }
      }

      // @sect4{The nodes}
      //
      // The nodes gmsh read: as many as the file declares, each once, with
      // finite coordinates; in 2d in the plane z = 0 (to 1e-10 of the
      // largest coordinate: a mesh drawn in 3D would be silently
      // flattened).
      template <int dim>
      void
      read_nodes(const GmshModel      &model,
                 const DeclaredCounts &declared,
                 GmshMesh<dim>        &mesh)
      {
        const std::string &filename    = mesh.filename;
        const auto        &node_tags   = model.node_tags;
        const auto        &coordinates = model.coordinates;
        // Every declared node must have been read: a shortfall (a node
        // number given twice, say) would otherwise pass unnoticed. A script
        // declares nothing.
        if (!declared.script && node_tags.size() != declared.nodes)
          refuse_mesh_file(filename,
                           "the file declares " +
                             std::to_string(declared.nodes) +
                             " nodes but gmsh read " +
                             std::to_string(node_tags.size()) +
                             " (a node number given twice?)");
        // Two passes: the size of the mesh (its largest coordinate) is
        // known only after every node has been seen, and the plane test is
        // relative to it.
        double largest = 0;
        for (std::size_t i = 0; i < node_tags.size(); ++i)
          {
            const double x = coordinates[3 * i], y = coordinates[3 * i + 1],
                         z = coordinates[3 * i + 2];
            // 1e100 is no coordinate of a body either: a few products of
            // such numbers overflow.
            if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z) ||
                std::abs(x) > 1e100 || std::abs(y) > 1e100 ||
                std::abs(z) > 1e100)
              refuse_mesh_file(filename,
                               "node " + std::to_string(node_tags[i]) +
                                 " has a coordinate that is not a finite "
                                 "number");
            Point<dim> node;
            node[0] = x;
            node[1] = y;
            if constexpr (dim == 3)
              node[2] = z;
            if (!mesh.nodes.emplace(node_tags[i], node).second)
              refuse_mesh_file(filename,
                               "node " + std::to_string(node_tags[i]) +
                                 " is defined twice");
            largest = std::max({largest, std::abs(x), std::abs(y)});
          }
        // Relative to the largest coordinate: a mesh in millimetres and
        // one in metres are judged alike.
        if (dim == 2)
          for (std::size_t i = 0; i < node_tags.size(); ++i)
            if (std::abs(coordinates[3 * i + 2]) > 1e-10 * largest)
              refuse_mesh_file(filename,
                               "node " + std::to_string(node_tags[i]) +
                                 " has z = " +
                                 std::to_string(coordinates[3 * i + 2]) +
                                 ": the mesh must lie in the plane z = 0");
      }

      // @sect4{The elements}
      //
      // The elements of one gmsh entity, which all take its physical tag:
      // the cells and boundary elements of dim only, each element number
      // once, every node they name defined. Points are dropped, and in 3d
      // the lines of no physical group (a 3d model's boundary conditions
      // and contact surfaces are its surfaces: a physical curve is refused).
      template <int dim>
      void
      add_elements(const GmshModel::Entity &entity,
                   const long               physical,
                   const std::string       &filename,
                   std::set<std::size_t>   &element_tags,
                   GmshMesh<dim>           &mesh)
      {
        for (unsigned int t = 0; t < entity.types.size(); ++t)
          {
            const int          type    = entity.types[t];
            const auto        &tags    = entity.element_tags[t];
            const auto        &nodes   = entity.element_nodes[t];
            const unsigned int n_nodes = nodes_of_type<dim>(type);
            if (n_nodes == 0)
              refuse_mesh_file(filename,
                               "element " +
                                 std::to_string(tags.empty() ? 0 : tags[0]) +
                                 " is a " + name_of_type(type) +
                                 " (gmsh type " + std::to_string(type) +
                                 "): " + accepted_elements<dim>());
            const bool edge_of_3d = dim == 3 && (type == 1 || type == 8);
            if (edge_of_3d && physical != 0)
              refuse_mesh_file(filename,
                               "gmsh entity " + std::to_string(entity.tag) +
                                 " (dimension 1) has physical tag " +
                                 std::to_string(physical) +
                                 ": in a 3d model the boundary conditions "
                                 "and contact surfaces are physical surfaces, "
                                 "not curves");
            // gmsh lists the nodes of all elements of a type in one array:
            // its length must fit, or the elements below would be read
            // past its end.
            if (nodes.size() != n_nodes * tags.size())
              refuse_mesh_file(filename,
                               "the answer of gmsh's reader is inconsistent");
            for (std::size_t i = 0; i < tags.size(); ++i)
              {
                // Element tags number the cells (gmsh_mesh.cc takes them in
                // tag order): each must be unique over the whole file,
                // points included.
                if (!element_tags.insert(tags[i]).second)
                  refuse_mesh_file(filename,
                                   "element " + std::to_string(tags[i]) +
                                     " is defined twice");
                if (type == 15 || edge_of_3d)
                  continue; // points, a solid's edges: not part of the mesh
                GmshElement element;
                element.type     = type;
                element.physical = physical;
                element.tag      = tags[i];
                element.entity   = entity.tag;
                element.nodes.assign(nodes.begin() + i * n_nodes,
                                     nodes.begin() + (i + 1) * n_nodes);
                // An element whose node the file does not define would
                // have no vertex for it in the triangulation.
                for (const std::size_t node : element.nodes)
                  if (mesh.nodes.count(node) == 0)
                    refuse_mesh_file(filename,
                                     "element " + std::to_string(element.tag) +
                                       " refers to node " +
                                       std::to_string(node) +
                                       ", which the file does not define");
                // Any second-order element marks the whole mesh quadratic;
                // check_cells() then refuses a Q1 cell beside it.
                if (type == 8 || type == 10 || type == 16 || type == 12 ||
                    type == 17)
                  mesh.quadratic = true;
                mesh.elements.push_back(std::move(element));
              }
          }
      }
    } // namespace

    namespace
    {
      // A model of volumes is three-dimensional: said so in 2d, before its
      // nodes off the plane are.
      void
      refuse_three_dimensional(const GmshModel   &model,
                               const std::string &filename)
      {
        for (const auto &entity : model.entities)
          if (entity.dim == 3 && !entity.types.empty())
            refuse_mesh_file(filename,
                             "the model is three-dimensional (gmsh volume " +
                               std::to_string(entity.tag) +
                               " is meshed): a two-dimensional problem is a "
                               "model of surfaces in the plane z = 0");
      }

      // A mesh file declared its elements: gmsh must have read them all.
      // A script keeps only the entities in physical groups (if it has
      // any), as gmsh does when it saves a mesh: the curves between the
      // patches of a ring and the points of its geometry are not part of
      // the mesh. The count includes the points, as the file's count does.
      // In 3d the volumes' types are checked first: a model of tetrahedra
      // or prisms is told so, not that the first triangle on its boundary
      // is refused.
      template <int dim>
      void
      check_elements_read(const GmshModel      &model,
                          const std::string    &filename,
                          const DeclaredCounts &declared)
      {
        std::size_t n_elements = 0;
        for (const auto &entity : model.entities)
          for (const auto &tags : entity.element_tags)
            n_elements += tags.size();
        if (!declared.script && n_elements != declared.elements)
          refuse_mesh_file(filename,
                           "the file declares " +
                             std::to_string(declared.elements) +
                             " elements but gmsh read " +
                             std::to_string(n_elements));
        if (dim == 3)
          for (const auto &entity : model.entities)
            for (unsigned int t = 0; t < entity.types.size(); ++t)
              if (entity.dim == 3 && nodes_of_type<dim>(entity.types[t]) == 0)
                refuse_mesh_file(
                  filename,
                  "element " +
                    std::to_string(entity.element_tags[t].empty() ?
                                     0 :
                                     entity.element_tags[t][0]) +
                    " is a " + name_of_type(entity.types[t]) + " (gmsh type " +
                    std::to_string(entity.types[t]) +
                    "): " + accepted_elements<dim>());
      }
    } // namespace

    // @sect4{The surfaces of a 3D model}
    //
    // A 3D script's sampled surfaces (model_surfaces.cc recognises them),
    // and the entity of every quadrilateral and line of its surfaces and
    // curves, those of no physical group too: a sphere's faces need their
    // surface whether or not a boundary condition names them.
    namespace
    {
      void
      add_surfaces(const GmshModel &model, GmshMesh<3> &mesh)
      {
        for (const auto &[tag, values] : model.surfaces)
          {
            GmshMesh<3>::Surface surface{tag, {}, {}};
            const std::size_t    n = values.size() / 6;
            for (std::size_t i = 0; i < n; ++i)
              {
                surface.points.emplace_back(values[3 * i],
                                            values[3 * i + 1],
                                            values[3 * i + 2]);
                surface.normals.push_back(
                  Tensor<1, 3>({values[3 * (n + i)],
                                values[3 * (n + i) + 1],
                                values[3 * (n + i) + 2]}));
              }
            mesh.surfaces.push_back(std::move(surface));
          }
        for (const auto &entity : model.entities)
          for (unsigned int t = 0; t < entity.types.size(); ++t)
            {
              const int          type    = entity.types[t];
              const unsigned int n_nodes = nodes_of_type<3>(type);
              if ((entity.dim != 1 && entity.dim != 2) || n_nodes < 2 ||
                  (entity.dim == 2 && !is_face_type<3>(type)))
                continue;
              const unsigned int corners = corners_of_type(type);
              const auto        &nodes   = entity.element_nodes[t];
              for (std::size_t first = 0; first + n_nodes <= nodes.size();
                   first += n_nodes)
                {
                  std::vector<std::size_t> key(nodes.begin() + first,
                                               nodes.begin() + first + corners);
                  std::sort(key.begin(), key.end());
                  mesh.entity_of_element[key] = entity.tag;
                }
            }
      }
    } // namespace

    // @sect4{The mesh}
    //
    // What gmsh read, checked; the elements of each entity take the
    // entity's physical tag. The physical tags become the material ids of
    // the cells (the bodies) and the boundary ids of the boundary elements
    // (supports, loads, contact surfaces).
    template <int dim>
    GmshMesh<dim>
    checked_mesh(const GmshModel      &model,
                 const std::string    &filename,
                 const DeclaredCounts &declared)
    {
      GmshMesh<dim> mesh;
      mesh.filename = filename;
      if (dim == 2)
        refuse_three_dimensional(model, filename);
      read_nodes(model, declared, mesh);
      check_elements_read<dim>(model, filename, declared);
      const bool any_physical = std::any_of(model.entities.begin(),
                                            model.entities.end(),
                                            [](const auto &entity) {
                                              return !entity.physicals.empty();
                                            });

      std::set<std::size_t> element_tags;
      for (const auto &entity : model.entities)
        {
          // gmsh files a format 1 or 2.2 element's physical tag under its
          // elementary entity: two tags on one entity cannot be told
          // apart. Refused as ambiguous rather than one silently chosen.
          // (The other way round, an element with tag 0 on an entity
          // whose other elements carry a tag gets theirs.) Points may
          // belong to several groups: they are dropped anyway.
          if (entity.physicals.size() > 1 && entity.dim > 0)
            refuse_mesh_file(filename,
                             "the elements of gmsh entity " +
                               std::to_string(entity.tag) + " (dimension " +
                               std::to_string(entity.dim) +
                               ") carry physical tags " +
                               std::to_string(entity.physicals[0]) + " and " +
                               std::to_string(entity.physicals[1]) +
                               ": each entity needs one");
          // What gmsh would write to a .msh file from this script: only
          // the entities in physical groups, if there are any.
          if (declared.script && any_physical && entity.physicals.empty())
            continue;
          const long physical =
            entity.physicals.empty() ? 0 : entity.physicals[0];
          // deal.II keeps the largest ids for itself (its invalid ids are
          // the largest values of the id types), and negative tags have
          // no meaning: a bound well inside both.
          if (physical < 0 || physical > 1000000000)
            refuse_mesh_file(filename,
                             "gmsh entity " + std::to_string(entity.tag) +
                               " (dimension " + std::to_string(entity.dim) +
                               ") has physical tag " +
                               std::to_string(physical) +
                               " (physical tags are between 0 and 1e9)");
          add_elements(entity, physical, filename, element_tags, mesh);
        }
      // The order of the file (gmsh gives them by entity and type): the
      // cells are numbered in it, so the same mesh in any format gives
      // the same triangulation.
      std::sort(mesh.elements.begin(),
                mesh.elements.end(),
                [](const GmshElement &a, const GmshElement &b) {
                  return a.tag < b.tag;
                });
      check_cells(mesh);
      for (const auto &[tag, xyz] : model.curves)
        {
          std::vector<Point<dim>> points;
          for (std::size_t i = 0; i + 2 < xyz.size(); i += 3)
            {
              Point<dim> x;
              for (unsigned int d = 0; d < dim; ++d)
                x[d] = xyz[i + d];
              points.push_back(x);
            }
          mesh.curves.emplace_back(tag, std::move(points));
        }
      if constexpr (dim == 3)
        add_surfaces(model, mesh);
      return mesh;
    }

    // The two dimensions of the program (issue 48).
    template GmshMesh<2>
    checked_mesh<2>(const GmshModel &,
                    const std::string &,
                    const DeclaredCounts &);
    template GmshMesh<3>
    checked_mesh<3>(const GmshModel &,
                    const std::string &,
                    const DeclaredCounts &);
  } // namespace Geometry
} // namespace RingContact
