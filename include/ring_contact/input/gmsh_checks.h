// What gmsh read from a file, checked before deal.II sees it (the second
// half of gmsh_file.h's reading): the nodes, the elements and their
// physical tags, held to what a mesh of bodies in contact must be. Shared
// by gmsh_file.cc, which reads, and gmsh_checks.cc, which checks.
#ifndef ring_contact_input_gmsh_checks_h
#define ring_contact_input_gmsh_checks_h

#include <ring_contact/input/gmsh_file.h>
#include <ring_contact/input/gmsh_process.h>

#include <cstddef>
#include <string>

namespace RingContact
{
  namespace Geometry
  {
    /// Refuse a mesh file: a one-line std::runtime_error that names the
    /// file first (a run reads a parameter file and possibly a mesh, and
    /// the user must know which one is at fault).
    [[noreturn]] void
    refuse_mesh_file(const std::string &filename, const std::string &what);

    /// What a mesh file declares it holds (a script declares nothing):
    /// gmsh must have read exactly that.
    struct DeclaredCounts
    {
      bool        script   = true;
      std::size_t nodes    = 0;
      std::size_t elements = 0;
    };

    /// The mesh of dimension dim that gmsh's `model` of `filename` is,
    /// checked: every declared node and element read, finite nodes (in the
    /// plane z = 0 in 2d), only the element types of dim (quadrilaterals
    /// and lines in 2d, hexahedra and quadrilaterals in 3d; the others
    /// refused naming the remedy), one physical tag per entity, cells that
    /// are not folded, faces of at most two cells, boundary faces on the
    /// cells. Throws refuse_mesh_file()'s error.
    template <int dim>
    GmshMesh<dim>
    checked_mesh(const GmshModel      &model,
                 const std::string    &filename,
                 const DeclaredCounts &declared);
  } // namespace Geometry
} // namespace RingContact

#endif
