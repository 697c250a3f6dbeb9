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

#include <ring_contact/base/dimension.h>

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
      int                      type;       ///< gmsh type: 1, 3, 8, 10 or 16
      long                     physical;   ///< physical tag (0 if none)
      std::vector<std::size_t> nodes;      ///< node tags, gmsh order
      std::size_t              tag;        ///< gmsh element tag
      int                      entity = 0; ///< its gmsh (elementary) entity
    };

    struct GmshMesh
    {
      std::string                       filename;
      std::map<std::size_t, Point<dim>> nodes; ///< by node tag
      /// Lines and quadrilaterals, by increasing tag (points are dropped).
      std::vector<GmshElement> elements;
      bool                     quadratic = false; ///< types 8, 10 or 16
      /// A script's curves by gmsh tag, sampled evenly in their parameter
      /// (GmshModel::curves; model_curves.h makes them the geometry).
      std::vector<std::pair<int, std::vector<Point<dim>>>> curves;
      /// The node tag of each vertex of the triangulation built from it
      /// (set by Geometry::read_gmsh()).
      std::vector<std::size_t> node_of_vertex;
    };

    /// Numbers handed to a .geo script, as gmsh's `-setnumber name value`.
    using GeoNumbers = std::vector<std::pair<std::string, double>>;

    /// Read and check a gmsh mesh file, or run a gmsh script (a file whose
    /// name ends in ".geo": gmsh meshes it in 2d with elements of order
    /// `element_order`, and only the entities in physical groups are kept
    /// and the model scaled by its Mesh.ScalingFactor, as gmsh does when it
    /// saves a mesh). Throws a one-line
    /// std::runtime_error.
    GmshMesh
    read_gmsh_file(const std::string &filename,
                   const GeoNumbers  &geo_numbers   = {},
                   unsigned int       element_order = 1);

    /// Whether `filename` names a gmsh script (ends in ".geo").
    bool
    is_geo_file(const std::string &filename);
  } // namespace Geometry
} // namespace RingContact

#endif
