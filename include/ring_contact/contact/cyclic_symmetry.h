// Cyclic symmetry. Where bodies of revolution, their meshes and the imposed
// displacements repeat every element around (2 pi / Ne) — the rings: the
// radial displacement is the same at every angle and the inner boundary
// turns rigidly — the solution repeats too, so a sector of k elements
// gives the whole bodies' solution:
//  - the displacements of its two radial sides are tied by the rotation
//    through the sector angle Phi: u(R(Phi) X) = R(Phi) u(X), and the
//    contact pressure at the slave vertex on the end side equals the one on
//    the start side;
//  - the master surface beyond the sector is the sector's own, turned by
//    +-Phi, +-2 Phi, ...: its rotated copies (ContactSurface) carry the
//    unknowns of the originals, rotated, so that slave points near the
//    sides and slave points that slid past them find their partners. The
//    copies are trimmed so that the master surface covers the circle at
//    most once: where the sector and c whole copies on each side would go
//    further round than the circle, copies would lie on top of the sector
//    and the pairing would meet coincident master segments (Newton failed
//    for k = 21, 23..39 of 40 around). See master_window().
// deal.II's DoFTools::make_periodicity_constraints() matches faces by a
// translation; for a rotation we pair the nodes of the two sides ourselves
// (by their support points) and write the constraints, two entries per
// displacement component.
#ifndef ring_contact_contact_cyclic_symmetry_h
#define ring_contact_contact_cyclic_symmetry_h

#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/hp/mapping_collection.h>
#include <deal.II/lac/affine_constraints.h>

#include <ring_contact/base/components.h>
#include <ring_contact/base/dimension.h>

#include <array>
#include <map>
#include <vector>

namespace RingContact
{
  using namespace dealii;

  namespace CyclicSymmetry
  {
    /// What the contact interface needs to know of a sector (angle 0: the
    /// whole rings).
    struct Sector
    {
      double       angle  = 0; ///< Phi
      unsigned int copies = 0; ///< rotated master copies on each side
      /// The master segments kept, sector-relative: those whose midpoint
      /// lies at an angle in [-window_before, angle + window_after) from
      /// the sector's start side (radians; the copies are trimmed to it).
      double window_before = 0;
      double window_after  = 0;
      /// Multiplier dofs on the end side and their images on the start
      /// side: one contact node.
      std::map<types::global_dof_index, types::global_dof_index>
        multiplier_twins;
    };

    /// The rotated master copies a sector of `sector_elements` elements
    /// (of `elements_around` around, both of the refined mesh) needs for a
    /// rotation of up to `slave_turn` elements: c = 1 + ceil(|s| /
    /// k) copies on each side, trimmed to the window [-w, k + w) with w =
    /// c k, or, where the sector and its copies would go further round than
    /// the circle ((2c + 1) k >= Ne), to a window of exactly the circle,
    /// whose side towards which the slave slides (`slave_turn`:
    /// the slave's motion along the master, signed) gets max(ceil((Ne -
    /// k) / 2), min(Ne - k, ceil(|s|) + 1)) elements and the other side
    /// the rest. Either way no master position appears twice modulo the
    /// circle; the slave nodes stay inside the window as long as k + |s| <
    /// Ne (Parameters refuses the rest, except k = Ne).
    void
    set_master_window(Sector            &sector,
                      const unsigned int sector_elements,
                      const unsigned int elements_around,
                      const double       slave_turn);

    /// A node on the end side of the sector and its image on the start
    /// side: the dofs of the displacement (x, y) and of the multiplier
    /// (invalid where the body has none) at both.
    struct NodePair
    {
      std::array<types::global_dof_index, Components::n_components<dim>> end;
      std::array<types::global_dof_index, Components::n_components<dim>> start;
    };

    /// Pair every node of the end side (boundary `end_side`) with its image
    /// on the start side (`start_side`), turned back through
    /// `sector_angle`. Throws if a node has no image: the two sides must
    /// carry the same nodes.
    std::vector<NodePair>
    find_node_pairs(const DoFHandler<dim>            &dof_handler,
                    const hp::MappingCollection<dim> &mapping,
                    const double                      sector_angle,
                    const types::boundary_id          start_side,
                    const types::boundary_id          end_side);

    /// The multiplier dofs of the pairs: end -> start.
    std::map<types::global_dof_index, types::global_dof_index>
    multiplier_pairs(const std::vector<NodePair> &pairs);

    /// Add u_end = R(Phi) u_start and lambda_end = lambda_start for every
    /// pair whose end dofs are not constrained yet: the corners on r = R1
    /// and r = R3 keep their imposed values (which satisfy the same
    /// relation), and the multiplier off the slave surface stays zero.
    void
    add_constraints(const std::vector<NodePair> &pairs,
                    const double                 sector_angle,
                    AffineConstraints<double>   &constraints);
  } // namespace CyclicSymmetry
} // namespace RingContact

#endif
