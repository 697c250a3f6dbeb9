// A strict reader of gmsh ASCII mesh files (format 1 and 2.2) for the rings:
// every section count must match the lines up to its end marker, every
// element must have the node count of its type, only the types the rings
// use are accepted (lines and quadrilaterals, linear or quadratic, and
// points), every node an element names must exist, coordinates must be
// finite and planar, no cell may repeat a corner or be folded. A file that
// passes is safe to hand to deal.II's GridIn or to build a triangulation
// from (geometry.cc); a file that does not gives a one-line error that
// names the file, the line and what is wrong.
#ifndef ring_contact_gmsh_file_h
#define ring_contact_gmsh_file_h

#include <deal.II/base/point.h>

#include <map>
#include <string>
#include <vector>

namespace RingContact
{
  using namespace dealii;

  namespace Geometry
  {
    /// One element of a gmsh file.
    struct GmshElement
    {
      int               type;     ///< gmsh type: 1, 3, 8, 10 or 15
      long              physical; ///< physical tag (0 if none)
      std::vector<long> nodes;    ///< node ids, gmsh order
      unsigned int      line;     ///< line in the file
    };

    struct GmshMesh
    {
      std::string              filename;
      std::string              text; ///< the file's content
      std::map<long, Point<2>> nodes;
      std::vector<GmshElement> elements;
      bool                     quadratic = false; ///< types 8 or 10
    };

    /// Read and check a gmsh file; throws a one-line std::runtime_error.
    GmshMesh
    read_gmsh_file(const std::string &filename);
  } // namespace Geometry
} // namespace RingContact

#endif
