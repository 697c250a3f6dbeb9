// Gmsh files read through gmsh's own C++ API: meshes (.msh, formats 1, 2.2
// and 4.1, ASCII or binary) and scripts (.geo, meshed when read).
//
// gmsh 4.8's readers trust the file: some damaged files crash them (see
// gmsh_process.h, where gmsh runs), a count lower than the items listed
// silently drops the rest, and a file that is not a mesh is run as a
// script. So a mesh file is first checked here, lightly: the header (it
// starts with $MeshFormat, or $NOD for format 1), the sections closed, and
// in ASCII files the lines of the node and element sections against the
// counts they declare; nodes and elements are parsed by gmsh only. What
// gmsh returns is then checked as the rings need it: the declared counts
// all read, only quadrilaterals and lines (points are ignored), finite
// plane nodes, no folded cell, one physical group per entity. Every error
// is a one-line std::runtime_error that names the file.
#ifndef ring_contact_input_gmsh_file_h
#define ring_contact_input_gmsh_file_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace RingContact
{
  using namespace dealii;

  namespace Geometry
  {
    /// One element of a gmsh mesh.
    struct GmshElement
    {
      int
        type; ///< gmsh type: 1, 3, 8, 10 or 16 (2d); 3, 5, 10, 12, 16, 17 (3d)
      long                     physical;   ///< physical tag (0 if none)
      std::vector<std::size_t> nodes;      ///< node tags, gmsh order
      std::size_t              tag;        ///< gmsh element tag
      int                      entity = 0; ///< its gmsh (elementary) entity
    };

    /// Whether a gmsh element type is a cell in dimension dim: a
    /// quadrilateral of 4, 9 or 8 nodes (types 3, 10, 16) in 2d, a
    /// hexahedron of 8, 27 or 20 nodes (5, 12, 17) in 3d.
    template <int dim>
    bool
    is_cell_type(const int type)
    {
      return dim == 2 ? type == 3 || type == 10 || type == 16 :
                        type == 5 || type == 12 || type == 17;
    }

    /// Whether a gmsh element type is a boundary face in dimension dim: a
    /// line of 2 or 3 nodes (types 1, 8) in 2d, a quadrilateral (3, 10,
    /// 16) in 3d.
    template <int dim>
    bool
    is_face_type(const int type)
    {
      return dim == 2 ? type == 1 || type == 8 : is_cell_type<2>(type);
    }

    /// The corners of an element of a cell or face type (gmsh lists them
    /// first at every order): 2, 4 or 8.
    inline unsigned int
    corners_of_type(const int type)
    {
      return type == 1 || type == 8                ? 2 :
             type == 5 || type == 12 || type == 17 ? 8 :
                                                     4;
    }

    /// A gmsh mesh in dimension dim, checked.
    template <int dim>
    struct GmshMesh
    {
      std::string                       filename;
      std::map<std::size_t, Point<dim>> nodes; ///< by node tag
      /// Cells and boundary faces, by increasing tag (points, and in 3d
      /// the lines of no physical group, are dropped).
      std::vector<GmshElement> elements;
      bool quadratic = false; ///< types 8, 10, 16 (and 12, 17 in 3d)
      /// A script's curves by gmsh tag, sampled evenly in their parameter
      /// (GmshModel::curves; model_curves.h makes them the geometry).
      std::vector<std::pair<int, std::vector<Point<dim>>>> curves;
      /// A 3D script's surfaces by gmsh tag: points on a grid evenly spaced
      /// in their two parameters and the unit normals there
      /// (GmshModel::surfaces; model_surfaces.h makes them the geometry).
      struct Surface
      {
        int                         tag;
        std::vector<Point<dim>>     points;
        std::vector<Tensor<1, dim>> normals;
      };
      std::vector<Surface> surfaces;
      /// In 3d, the gmsh entity of every quadrilateral of the model's
      /// surfaces and every line of its curves, in physical groups or not,
      /// by its corner node tags in increasing order.
      std::map<std::vector<std::size_t>, int> entity_of_element;
      /// The node tag of each vertex of the triangulation built from it
      /// (set by Geometry::read_gmsh()).
      std::vector<std::size_t> node_of_vertex;
    };

    /// Numbers handed to a .geo script, as gmsh's `-setnumber name value`.
    using GeoNumbers = std::vector<std::pair<std::string, double>>;

    /// Read and check a gmsh mesh file of dimension dim, or run a gmsh
    /// script (a file whose name ends in ".geo": gmsh meshes it in the
    /// model's dimension with elements of order `element_order`, and only
    /// the entities in physical groups are kept and the model scaled by its
    /// Mesh.ScalingFactor, as gmsh does when it saves a mesh). Throws a
    /// one-line std::runtime_error.
    template <int dim>
    GmshMesh<dim>
    read_gmsh_file(const std::string &filename,
                   const GeoNumbers  &geo_numbers   = {},
                   unsigned int       element_order = 1);

    /// The dimension of the model of a gmsh file, 2 or 3 (a model with a
    /// volume is three-dimensional): a script is opened without being
    /// meshed. Throws the one-line std::runtime_error of read_gmsh_file().
    unsigned int
    model_dimension(const std::string &filename,
                    const GeoNumbers  &geo_numbers = {});

    /// Whether `filename` names a gmsh script (ends in ".geo").
    bool
    is_geo_file(const std::string &filename);
  } // namespace Geometry
} // namespace RingContact

#endif
