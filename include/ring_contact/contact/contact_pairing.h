// The pairing of a contact interface: every slave quadrature point with its
// partner on the master surface, at the surfaces' current state. A fixed
// rule (nodal, Gauss, ...) puts the same points on every slave segment and
// projects each onto the master; segment-based integration cuts each slave
// segment into pieces that face one master segment each, and puts the rule
// on the pieces. Each point carries its gap and its length element, which
// the active set (active_set.h) sums into weighted gaps and the contact
// element (contact_element.h) evaluates again with derivatives.
#ifndef ring_contact_contact_contact_pairing_h
#define ring_contact_contact_contact_pairing_h

#include <deal.II/base/quadrature.h>
#include <deal.II/lac/vector.h>

#include <ring_contact/contact/contact_surface.h>

#include <array>
#include <utility>
#include <vector>

namespace RingContact
{
  using namespace dealii;

  /// A slave quadrature point and its partner on the master surface.
  struct ContactPoint
  {
    unsigned int slave_segment;
    double       eta;    ///< parameter of the point on the slave segment
    double       weight; ///< quadrature weight in eta
    Projection   projection;
    double       current_length; ///< ds = |dx_s/deta| weight
    /// Small strain: the gap of the reference configuration, zero where it
    /// is below the round-off of the positions (see complete_point()).
    double reference_gap = 0;
    /// Segment-based integration: the point is eta = eta_a + (eta_b -
    /// eta_a) xi on a piece [eta_a, eta_b] of the slave segment, with the
    /// weight (eta_b - eta_a) w. An end of the piece is either fixed (a
    /// slave vertex: -1) or the crossing of the line through a vertex of the
    /// partner along its normal (0 or 1: which end of the partner), and then
    /// moves with the displacement. Fixed rules: the piece is [0, 1].
    std::array<double, 2> piece     = {{0, 1}};
    std::array<int, 2>    piece_end = {{-1, -1}};
    double                xi        = 0;
    double                w         = 0;
    /// Friction: the partner of the point's position at the last converged
    /// state on the master of that state.
    Projection old_projection;
  };

  /// How the slave points of a point-wise scheme are paired.
  enum class Pairing
  {
    /// Closest-point search (a point with two candidates keeps its last
    /// partner).
    search,
    /// Every point keeps its last partner segment and follows it, onto
    /// its extension if need be: the residual is a smooth function of the
    /// displacement (the line-search trials while the Newton solver holds
    /// the pairing because it cycles, see problem/newton_solver.cc).
    hold,
    /// As `hold`, but a point past its partner's end is held at that
    /// vertex, with the vertex normal, from then on: past a groove's
    /// vertex the extension runs inside the neighbouring segment (the
    /// accepted Newton iterates while the pairing is held).
    hold_within_segments
  };

  class ContactPairing
  {
  public:
    /// The points of `quadrature` on the segments of `slave` (on their
    /// pieces if `segment_based`), paired with `master`. The surfaces are
    /// the contact interface's, moved by it before each pair().
    ContactPairing(const ContactSurface &slave,
                   const ContactSurface &master,
                   const Quadrature<1>  &quadrature,
                   const bool            segment_based);

    ContactPairing(const ContactPairing &) = delete;
    ContactPairing &
    operator=(const ContactPairing &) = delete;

    /// Pair every slave point with the master at the surfaces' state, with
    /// its gap (`linear_gaps`: the reference gap plus the normal jump of
    /// the displacement in `solution`, the surfaces at the reference
    /// configuration) and its length element.
    void
    pair(const Vector<double> &solution,
         const Pairing         pairing,
         const bool            linear_gaps);

    /// Friction: each point's partner at the last converged state, its
    /// position there projected onto the master of that state (with
    /// `linear_gaps` both are the reference configuration, and the partner
    /// is the current one).
    void
    find_old_partners(const ContactSurface &converged_slave,
                      const ContactSurface &converged_master,
                      const bool            linear_gaps);

    /// The slave points of the last pair().
    const std::vector<ContactPoint> &
    points() const
    {
      return contact_points;
    }

    /// The rule on a slave segment (or piece).
    const Quadrature<1> &
    rule() const
    {
      return quadrature;
    }

    /// The slave and master segments of every contact point paired at the
    /// last pair() (adaptive refinement keeps the master as fine as the
    /// slave where they face each other).
    std::vector<std::pair<unsigned int, unsigned int>>
    paired_segments() const;

    /// The gap at the slave point (segment s, parameter t), projected onto
    /// the master afresh and measured as the pairing measures it.
    double
    gap_at(const unsigned int    s,
           const double          t,
           const Vector<double> &solution,
           const bool            linear_gaps) const;

  private:
    /// Fixed rules: every slave quadrature point paired with its closest
    /// master point.
    void
    pair_points(const Vector<double> &solution,
                const Pairing         pairing,
                const bool            linear_gaps);
    /// Segment-based: each slave segment cut into pieces with one partner
    /// each.
    void
    pair_pieces(const Vector<double> &solution, const bool linear_gaps);
    /// The cuts of a slave segment (parameter, master vertex), sorted.
    std::vector<std::pair<double, unsigned int>>
    piece_cuts(const unsigned int s) const;
    /// Fill in a contact point from its piece, xi and w: position,
    /// partner (from `project`), gap and length element.
    template <typename Projector>
    void
    complete_point(ContactPoint         &point,
                   const unsigned int    slave_segment,
                   const Vector<double> &solution,
                   const bool            linear_gaps,
                   const Projector      &project) const;

    /// The normal distance of the reference points of a slave point and its
    /// partner, zero within the round-off of the positions.
    double
    reference_gap_of(const unsigned int slave_segment,
                     const double       eta,
                     const Projection  &projection) const;
    /// The gap at the surfaces' current state: reference_gap_of() plus the
    /// normal jump of the displacement.
    double
    gap_of(const unsigned int slave_segment,
           const double       eta,
           const Projection  &projection) const;
    /// Small strain: (u_s - u_m) . n0 at a slave point and its partner.
    double
    linear_gap_increment(const Vector<double> &solution,
                         const unsigned int    slave_segment,
                         const double          t,
                         const Projection     &projection) const;

    const ContactSurface &slave;
    const ContactSurface &master;
    const Quadrature<1>   quadrature;
    const bool            segment_based;

    std::vector<ContactPoint> contact_points;
  };
} // namespace RingContact

#endif
