// The two rings as one deal.II triangulation with two disconnected
// components: the interface vertices exist twice, one copy per ring, so the
// rings are separate bodies that only interact through contact.
#ifndef ring_contact_geometry_h
#define ring_contact_geometry_h

#include <deal.II/grid/tria.h>

#include <ring_contact/gmsh_file.h>
#include <ring_contact/parameters.h>

namespace RingContact
{
  using namespace dealii;

  namespace Geometry
  {
    /// Build the structured seed mesh in code: `elements_around` cells around
    /// every circle (first vertex at angle 0), uniform radial spacing,
    /// material ids 100 (outer) / 101 (inner), boundary ids 200/300/400/500.
    void
    make_rings(Triangulation<2> &triangulation, const MeshParameters &mesh);

    /// The contact patch test: two blocks (lower: master, 100; upper:
    /// slave, 101) with non-matching meshes along the interface y = 0;
    /// boundary ids 200 (bottom), 500 (top), 300/400 (interface), 0 (sides).
    void
    make_blocks(Triangulation<2> &triangulation, const MeshParameters &mesh);

    /// Read a gmsh mesh (.msh formats 1, 2.2, 4.1) or mesh a gmsh script
    /// (.geo, with `geo_numbers` and elements of `element_order`) through
    /// gmsh's library, checked (see gmsh_file.h), with the original's
    /// physical tags as material and boundary ids; returns what gmsh read,
    /// for the checks of the boundary tags.
    GmshMesh
    read_gmsh(Triangulation<2>  &triangulation,
              const std::string &filename,
              const GeoNumbers  &geo_numbers   = {},
              unsigned int       element_order = 1,
              bool               on_circles    = true);

    /// Throw a one-line error, before anything large is allocated, if a mesh
    /// of `n_coarse_cells` cells refined as the parameters say would need
    /// more than 80 % of the machine's physical memory (an estimate from
    /// the number of unknowns, including the direct solver's factors).
    void
    check_size(std::size_t n_coarse_cells, const Parameters &parameters);

    /// Make the mesh of the parameters: generate or read it, attach the
    /// polar manifold (refinement and curved mappings follow the circles),
    /// refine, and check it (see check_rings()).
    void
    create_mesh(Triangulation<2> &triangulation, const Parameters &parameters);

    /// Throw a one-line error if the mesh lacks what the problem needs: the
    /// two ring material ids, the boundaries 200 and 500 and the slave and
    /// master boundaries, each slave/master face on the circle r = R2 and in
    /// one ring.
    void
    check_rings(const Triangulation<2> &triangulation,
                const Parameters       &parameters);

    /// The same for a general problem: every cell in one of the two
    /// bodies, each body present, every boundary tag that a condition, a
    /// check or the contact pair names present, the slave and master
    /// surfaces each on one body and not the same one, and the multiplier
    /// degree at most the slave body's.
    void
    check_bodies(const Triangulation<2> &triangulation,
                 const Parameters       &parameters);
  } // namespace Geometry
} // namespace RingContact

#endif
