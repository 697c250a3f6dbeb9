// The contact nodes of a slave surface: the multiplier unknowns numbered
// k = 0, 1, ... along it, each with its reference weight w_k = int Phi_k dS,
// the places where it sits on the segments, its neighbours along the
// surface and, with friction, its tangential-traction unknown. Made once,
// when the contact interface is made (contact_interface.h), and fixed after:
// the active set (active_set.h) and the contact rows index their arrays by
// k, and the postprocessing finds a node's place here instead of searching.
#ifndef ring_contact_contact_multiplier_nodes_h
#define ring_contact_contact_multiplier_nodes_h

#include <deal.II/base/point.h>
#include <deal.II/base/types.h>

#include <ring_contact/contact/contact_surface.h>

#include <array>
#include <map>
#include <utility>
#include <vector>

namespace RingContact
{
  using namespace dealii;

  /// The multiplier nodes of one slave surface, in the order of their
  /// index k.
  struct MultiplierNodes
  {
    /// Number the multiplier nodes of `slave` segment by segment. With
    /// cyclic symmetry, each end-side dof of `twins` is one node with its
    /// image on the start side (the constraints tie the two). With
    /// `friction`, each node's tangential-traction dof is kept at its k.
    MultiplierNodes(
      const ContactSurface                                             &slave,
      const std::map<types::global_dof_index, types::global_dof_index> &twins,
      const bool friction);

    /// The nodes of a slave surface of faces (3D, FaceContact): their
    /// multiplier dofs in the order of k, their weights w_k, and each
    /// face's four nodes k in deal.II's lexicographic order with the nodes'
    /// reference `positions`: the neighbours are the faces' edges, for the
    /// active set's edge extrapolation on a surface. No sites (the faces
    /// know their nodes), no friction.
    MultiplierNodes(const std::vector<types::global_dof_index>     &dofs,
                    const std::vector<double>                      &weights,
                    const std::vector<std::array<unsigned int, 4>> &faces,
                    const std::vector<Point<3>>                    &positions);

    /// The number of contact nodes.
    unsigned int
    size() const
    {
      return dofs.size();
    }

    /// Every multiplier dof on the slave surface, twins included.
    std::vector<types::global_dof_index>
    all_dofs() const;

    /// The tangential-traction dof at a multiplier node (friction), or
    /// invalid.
    types::global_dof_index
    tangential_dof(const types::global_dof_index multiplier_dof) const;

    /// The multiplier dof of each node (a twin's image, never the twin).
    std::vector<types::global_dof_index> dofs;
    /// The index k of every multiplier dof on the surface, twins included.
    std::map<types::global_dof_index, unsigned int> index;
    /// Where each node sits: (slave segment, t), one entry per segment
    /// that shares it (a vertex: two).
    std::map<types::global_dof_index,
             std::vector<std::pair<unsigned int, double>>>
      sites;
    /// w_k = int Phi_k dS over the reference surface.
    std::vector<double> reference_weight;
    /// Friction: the tangential-traction dof of each node (empty without).
    std::vector<types::global_dof_index> tangential_dofs;
    /// The neighbours of each node along the slave surface, each with the
    /// length of the link in the reference configuration (measured on the
    /// segment that joins them: a twin's neighbour across the sector's ends
    /// is a segment away, not a sector).
    std::vector<std::vector<std::pair<unsigned int, double>>> neighbours;

    /// A surface of faces (3D): each node's reference position (empty on a
    /// 2D curve, whose nodes are chains of neighbours).
    std::vector<Point<3>> surface_position;

  private:
    /// The nodes in their order along each segment: consecutive ones are
    /// neighbours (a vertex links the segments that share it, a twin the
    /// sector's two ends).
    void
    link_neighbours(const ContactSurface &slave);
  };
} // namespace RingContact

#endif
