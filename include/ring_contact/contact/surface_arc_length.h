// The arc length along a slave surface at its multiplier nodes, for plots
// along the interface (surface_arc_length.cc).
#ifndef ring_contact_contact_surface_arc_length_h
#define ring_contact_contact_surface_arc_length_h

#include <deal.II/base/types.h>

#include <ring_contact/contact/contact_surface.h>

#include <map>
#include <utility>
#include <vector>

namespace RingContact
{
  /// A chain of segments of a slave surface, in the order its arc length
  /// runs (arc_lengths()): each segment with the end (0 or 1) at which the
  /// chain enters it. A closed chain ends where it starts; `length` is that
  /// of its reference curve.
  struct SurfaceChain
  {
    std::vector<std::pair<unsigned int, unsigned int>> steps;
    bool                                               closed = false;
    double                                             length = 0;
  };

  /// The chains of `surface`, each walked from its start as arc_lengths()
  /// measures it: the slave surface's VTU file writes its segments in this
  /// order, so that a plot over the arc length joins neighbours.
  std::vector<SurfaceChain>
  surface_chains(const ContactSurface &surface);

  /// The reference arc length at each multiplier node of `surface`,
  /// measured along its reference geometry (curved where the mapping is)
  /// from the start of the chain of segments the node lies on. An open
  /// chain starts at its end of lowest x (of lowest y where the x agree); a
  /// closed one at its vertex of lowest polar angle about its centroid
  /// (node A of the rings), and runs counterclockwise. Each chain of a
  /// surface in several pieces starts from 0; the rotated copies of a
  /// cyclic sector are left out.
  std::map<dealii::types::global_dof_index, double>
  arc_lengths(const ContactSurface &surface);
} // namespace RingContact

#endif
