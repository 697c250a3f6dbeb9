// The active set of a contact interface: which contact nodes are closed,
// and with friction which of them stick and which slide (and which way).
// At every iterate the contact interface (contact_interface.h) sums the
// pairing's points into weighted gaps here and asks for the states: the
// primal-dual active-set choice of the semi-smooth Newton method, the max
// in C_k = w_k lambda_k - max(0, w_k lambda_k - c g~_k) and the Coulomb
// projection decided at the iterate. The states then fix which row each
// node gets in the Newton system (contact_assembly.cc).
//
// The Newton solver's strategies for a zone that grows from a point
// (problem/first_step.h) steer the choice through a few switches: the start
// of a load step, the stick held, the zones' edges extrapolated.
#ifndef ring_contact_contact_active_set_h
#define ring_contact_contact_active_set_h

#include <deal.II/lac/vector.h>

#include <ring_contact/contact/contact_pairing.h>
#include <ring_contact/contact/multiplier_nodes.h>

#include <algorithm>
#include <vector>

namespace RingContact
{
  using namespace dealii;

  /// The contact state of every node of a pair: closed or open, and with
  /// friction stick (0) or the sense of its slip (+-1).
  struct NodeStates
  {
    std::vector<bool> active;
    std::vector<int>  slip_sign;

    /// The number of nodes whose state (closed, stick, slip and its sense)
    /// differs from `before`.
    unsigned int
    n_changed_since(const NodeStates &before) const;

    /// The number of nodes that opened or closed since `before`
    /// (friction's states aside).
    unsigned int
    n_closed_changed_since(const NodeStates &before) const;
  };

  class ActiveSet
  {
  public:
    /// The states of the nodes of `nodes`, chosen with the complementarity
    /// constant c and Coulomb's coefficient (0: frictionless);
    /// `segment_length` is the shortest slave segment, the scale of the
    /// gaps counted as touching.
    ActiveSet(const MultiplierNodes &nodes,
              const double           complementarity_constant,
              const double           friction_coefficient,
              const double           segment_length);

    ActiveSet(const ActiveSet &) = delete;
    ActiveSet &
    operator=(const ActiveSet &) = delete;

    /// @name The choice at an iterate (ContactInterface::update())
    /// @{

    /// The closed nodes from the multipliers of `solution` and the weighted
    /// gaps of the `points` paired on `slave`; the zones' edges
    /// extrapolated where allowed and the contact is `piecewise_linear`.
    /// Returns the number of nodes that opened or closed.
    unsigned int
    choose_closed_nodes(const Vector<double>            &solution,
                        const ContactSurface            &slave,
                        const std::vector<ContactPoint> &points,
                        const bool                       piecewise_linear);

    /// The same choice from weighted gaps g~_k summed by the caller (the
    /// faces of a 3D surface, FaceContact); a node that no master face
    /// covers (`covered[k]` false: its gap row would be empty) stays open.
    unsigned int
    choose_closed_nodes(const Vector<double>      &solution,
                        const std::vector<double> &weighted_gaps,
                        const std::vector<bool>   &covered,
                        const bool                 piecewise_linear);

    /// Friction: the stick and slip states of the closed nodes from their
    /// trial tractions, with the weighted slips s~_k (`weighted_slip`) of
    /// the contact element; `linear_gaps`: small strain. Returns the
    /// number of nodes whose state changed.
    unsigned int
    choose_friction_states(const Vector<double>      &solution,
                           const std::vector<double> &weighted_slip,
                           const bool                 linear_gaps);
    /// @}

    /// @name What the Newton solver's strategies set and read
    /// @{

    /// The next choice is the first of a load step (or of a retry after a
    /// cut): nodes that touch close as well (choose_closed_nodes()).
    void
    start_step(const Vector<double> &solution)
    {
      first_update_of_step = true;
      pressed_at_step_start =
        std::any_of(nodes.dofs.begin(), nodes.dofs.end(), [&](const auto dof) {
          return solution(dof) > 0;
        });
    }

    /// Whether the step began with no pressure on the pair: a contact zone
    /// that grows from nothing, a point or an initial overlap.
    bool
    zone_grows_from_point() const
    {
      return !pressed_at_step_start;
    }

    /// Friction: whether every closed node sticks, whatever its trial
    /// traction. Held while a zone that grows from a point finds its width,
    /// so that the contact is piecewise linear meanwhile and its edges can
    /// be extrapolated.
    void
    hold_stick(const bool hold)
    {
      stick_held = hold;
    }
    bool
    holds_stick() const
    {
      return stick_held;
    }

    /// Whether the choice moves the edges of the zones by the extrapolation
    /// of their square-root profile (extrapolate_zone_edges()). Allowed in
    /// the first iterations of a step only, so that the last ones are plain
    /// primal-dual active-set iterations.
    void
    allow_edge_extrapolation(const bool allow)
    {
      edge_extrapolation = allow;
    }

    NodeStates
    node_states() const
    {
      return {active, slip_sign};
    }
    /// @}

    /// @name The states, for the contact rows and the postprocessing
    /// @{

    /// Whether node k is closed, and its friction state (0 stick, +-1 the
    /// sense of its slip).
    bool
    is_closed(const unsigned int k) const
    {
      return active[k];
    }
    int
    friction_state(const unsigned int k) const
    {
      return slip_sign[k];
    }

    /// Whether the multiplier node `dof` (of this pair) is closed.
    bool
    is_active(const types::global_dof_index dof) const;

    /// Number of closed nodes, and of those that slip (friction).
    unsigned int
    n_active() const;
    unsigned int
    n_slipping() const;

    /// Each node's mean gap g~_k / w_k at the last choice (0 where w_k is
    /// 0).
    std::vector<double>
    mean_gaps() const;
    /// @}

  private:
    /// The primal-dual choice from `weighted_gap`, nodes not `covered` (if
    /// given) kept open: the two choose_closed_nodes().
    unsigned int
    choose_from_weighted_gaps(const Vector<double>    &solution,
                              const std::vector<bool> *covered,
                              const bool               piecewise_linear);

    /// The weighted gaps g~_k = sum Phi_k g ds over the paired `points`.
    void
    sum_weighted_gaps(const ContactSurface            &slave,
                      const std::vector<ContactPoint> &points);

    /// The primal-dual choice `closed`, with the edges of each zone of
    /// nodes `inside` (the current choice) moved to where the square-root
    /// profile of the indicator puts them (see the definition); the walks
    /// along the surface go through `linked` nodes only. For the contact
    /// zones the indicator is w_k lambda_k - c g~_k; for the stick zones the
    /// room B_k - |T_k| to the Coulomb bound.
    void
    extrapolate_zone_edges(const std::vector<bool>   &inside,
                           const std::vector<bool>   &linked,
                           const std::vector<double> &indicator,
                           std::vector<bool>         &closed) const;

    /// extrapolate_zone_edges() on a slave surface of faces (3D), for the
    /// contact zones: a zone's edge is a curve, the distances along the
    /// surface are those to the zone's outermost closed nodes
    /// (surface_zone_edges.cc).
    void
    extrapolate_surface_zone_edges(const std::vector<bool>   &inside,
                                   const std::vector<double> &indicator,
                                   std::vector<bool>         &closed) const;

    const MultiplierNodes &nodes;
    const double           complementarity_constant;
    const double           friction_coefficient;
    const double           segment_length;

    std::vector<double> weighted_gap; ///< g~_k
    std::vector<bool>   active;
    /// Friction: per node 0 stick, +1 or -1 the sign of the slip.
    std::vector<int> slip_sign;
    /// Set by start_step(), cleared by the choice that it concerns.
    bool first_update_of_step = false;
    bool edge_extrapolation   = false;
    bool stick_held           = false;
    /// Whether a node carried pressure when the step began (start_step()).
    bool pressed_at_step_start = false;
  };
} // namespace RingContact

#endif
