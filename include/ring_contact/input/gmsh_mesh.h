// Meshes from gmsh for every scenario: a gmsh file (or script) read and
// checked (gmsh_file.h) made into a deal.II triangulation with the file's
// physical tags as material and boundary ids, the audit of those tags, and
// a size check before anything large is allocated.
#ifndef ring_contact_input_gmsh_mesh_h
#define ring_contact_input_gmsh_mesh_h

#include <deal.II/grid/tria.h>

#include <ring_contact/input/gmsh_file.h>

#include <cstddef>
#include <string>

namespace RingContact
{
  using namespace dealii;

  namespace Geometry
  {
    /// Read a gmsh mesh (.msh formats 1, 2.2, 4.1) or mesh a gmsh script
    /// (.geo, with `geo_numbers` and elements of `element_order`) through
    /// gmsh's library, checked (see gmsh_file.h and gmsh_checks.h), with its
    /// physical tags as material and boundary ids (in 3d: hexahedra, their
    /// boundary quadrilaterals); returns what gmsh read, for the audit of
    /// the boundary tags. `on_circles`: the boundary lines lie on circles
    /// about the origin (a quadratic line's mid-side node must be on its
    /// circle); otherwise the geometry is straight-sided and a mid-side
    /// node must be at the middle of its line.
    template <int dim>
    GmshMesh<dim>
    read_gmsh(Triangulation<dim> &triangulation,
              const std::string  &filename,
              const GeoNumbers   &geo_numbers   = {},
              unsigned int        element_order = 1,
              bool                on_circles    = true);

    /// The audit of the boundary tags: every boundary face is one boundary
    /// element of the file (a line in 2d, a quadrilateral in 3d) with one
    /// physical tag. Throws a one-line error that names the file, the gmsh
    /// entity and the element.
    template <int dim>
    void
    check_boundary_tags(const Triangulation<dim> &triangulation,
                        const GmshMesh<dim>      &mesh);

    /// Throw a one-line error, before anything large is allocated, if a mesh
    /// of `n_coarse_cells` cells of displacement degree up to `degree`,
    /// refined `global_refinements` times, would need more than 80 % of the
    /// machine's physical memory (an estimate from the number of unknowns,
    /// including the direct solver's factors).
    template <int dim>
    void
    check_size(const std::size_t  n_coarse_cells,
               const unsigned int degree,
               const unsigned int global_refinements);
  } // namespace Geometry
} // namespace RingContact

#endif
