// The contact interface: a slave surface that carries the Lagrange multiplier
// (the contact pressure), a master surface that gives the normal, the pairing
// of slave quadrature points with their closest points on the current master
// surface, the unilateral condition and the assembly of the contact terms
// with their exact linearisation (automatic differentiation with Sacado).
//
// Weak form, for every slave quadrature point with weight w and current
// length element ds = |dx_s/dt| w:
//   displacement rows:  - lambda (delta u_s - delta u_m(xi)) . n  ds
//   multiplier row k:   weighted gap  g~_k = sum  Phi_k g ds
// and per multiplier node k the complementarity function
//   C_k = w_k lambda_k - max(0, w_k lambda_k - c g~_k) = 0,
// with w_k = int Phi_k dS (reference); C_k = c g~_k on the active set,
// w_k lambda_k off it. Every row is then a force per unit thickness.
// With small-strain kinematics the contact is geometrically linear too:
// pairing, normal and length element of the reference configuration.
//
// Coulomb friction (mu > 0): a second multiplier, the tangential traction
// lambda_t on the unit tangent tau = e_z x n, adds
//   displacement rows:  + lambda_t (delta u_s - delta u_m(xi)) . tau  ds
// (the master's friction force on the slave, -lambda_t tau, opposes the
// slave's slip when lambda_t has the slip's sign). The slip of a slave
// point in the step is the tangential part of its motion relative to the
// master point it was paired with at the last converged state (xi_n on
// segment m_n, found by projecting the point's old position onto the old
// master), s = tau . [(u_s - u_s,n) - (u_m(xi_n) - u_m,n(xi_n))]: zero in a
// rigid motion of the pair, so objective. Weighted per node,
// s~_k = sum Phi_k s ds, and the node's trial traction
// T_k = w_k lambda_t,k + c s~_k decides its state with the bound
// B_k = mu (w_k lambda_k - c g~_k):
//   open (normal inactive):  w_k lambda_t,k = 0
//   stick (|T_k| <= B_k):    c s~_k = 0
//   slip  (sign s = T_k/|T_k|): w_k lambda_t,k - s mu w_k lambda_k = 0,
// the primal-dual active-set form of Alart and Curnier's
// w lambda_t - proj_[-B, B](T) = 0, each row exactly linearised.
#ifndef ring_contact_contact_contact_interface_h
#define ring_contact_contact_contact_interface_h

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_matrix.h>

#include <ring_contact/contact/contact_surface.h>
#include <ring_contact/contact/cyclic_symmetry.h>
#include <ring_contact/linear_algebra/linear_system.h>

#include <algorithm>
#include <array>
#include <map>
#include <memory>
#include <set>

namespace RingContact
{
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

  class ContactInterface
  {
  public:
    /// `largest_youngs_modulus` sets the automatic complementarity constant
    /// E / h (h: the shortest slave segment) when the parameters give none.
    /// With cyclic symmetry (`sector.angle` > 0) the master surface is
    /// continued by rotated copies, and the two multiplier nodes of a pair
    /// of `sector.multiplier_twins` are one contact node (the end one is
    /// tied to the start one by the constraints).
    ContactInterface(const DoFHandler<2>          &dof_handler,
                     const ContactParameters      &parameters,
                     const IntegrationScheme      &scheme,
                     const unsigned int            slave_mapping_degree,
                     const unsigned int            master_mapping_degree,
                     const double                  largest_youngs_modulus,
                     const bool                    geometrically_linear,
                     const CyclicSymmetry::Sector &sector = {});

    /// How update() pairs the slave points of a point-wise scheme.
    enum class Pairing
    {
      /// Closest-point search (a point with two candidates keeps its last
      /// partner).
      search,
      /// Every point keeps its last partner segment and follows it, onto
      /// its extension if need be: the residual is a smooth function of the
      /// displacement (the line-search trials while the Newton loop holds
      /// the pairing because it cycles, see solve_newton_step()).
      hold,
      /// As `hold`, but a point past its partner's end is held at that
      /// vertex, with the vertex normal, from then on: past a groove's
      /// vertex the extension runs inside the neighbouring segment (the
      /// accepted Newton iterates while the pairing is held).
      hold_within_segments
    };

    /// Pair every slave quadrature point with the current master surface,
    /// compute the weighted gaps and choose the active set from the current
    /// multipliers. Returns the number of nodes whose status changed.
    unsigned int
    update(const Vector<double> &solution,
           const Pairing         pairing = Pairing::search);

    /// The next update() chooses the first active set of a load step (or of
    /// a retry after a cut): nodes that touch close as well (see update()).
    void
    start_step(const Vector<double> &solution)
    {
      first_update_of_step = true;
      pressed_at_step_start =
        std::any_of(multiplier_dof_list.begin(),
                    multiplier_dof_list.end(),
                    [&](const auto dof) { return solution(dof) > 0; });
    }

    /// Whether the step began with no pressure on the pair: a contact zone
    /// that grows from nothing, a point or an initial overlap (see
    /// hold_stick()).
    bool
    zone_grows_from_point() const
    {
      return !pressed_at_step_start;
    }

    /// Friction: whether every closed node sticks, whatever its trial
    /// traction (update_friction()). The Newton loop holds the stick while a
    /// zone that grows from a point finds its width, so that the contact is
    /// piecewise linear meanwhile and its edges can be extrapolated.
    void
    hold_stick(const bool hold)
    {
      stick_held = hold;
    }

    /// Small strain: gaps linear in the displacement.
    bool
    small_strain() const
    {
      return geometrically_linear;
    }

    /// A pair of bodies in finite strain measured as in small strain
    /// (reference pairing, normal and length, gaps linear in the
    /// displacement) while the Newton loop solves a step's problem
    /// linearised at the undeformed state (ContactProblem::linearise()).
    void
    linearise(const bool on)
    {
      geometrically_linear = small_strain_model || on;
    }

    bool
    has_friction() const
    {
      return friction_coefficient > 0;
    }

    /// Whether update() moves the edges of the contact zones by the
    /// extrapolation of their square-root profile (see
    /// extrapolate_zone_edges()). The Newton loop allows it in the first
    /// iterations of a step only, so that the last ones are plain
    /// primal-dual active-set iterations.
    void
    allow_edge_extrapolation(const bool allow)
    {
      edge_extrapolation = allow;
    }

    /// Whether the contact rows are piecewise linear in the unknowns: small
    /// strain (gaps linear in the displacement) and no friction, or friction
    /// with every closed node held in stick (a linear tie). The Newton
    /// iteration is then the primal-dual active-set method for a linear
    /// complementarity problem, which needs no damping.
    bool
    piecewise_linear() const
    {
      return geometrically_linear && (friction_coefficient == 0 || stick_held);
    }

    /// The contact state of every node: closed or open, and with friction
    /// stick (0) or the sense of its slip (+-1).
    struct NodeStates
    {
      std::vector<bool> active;
      std::vector<int>  slip_sign;
    };

    NodeStates
    node_states() const
    {
      return {active, slip_sign};
    }

    /// The number of nodes whose state differs from `before`.
    unsigned int
    n_changed_since(const NodeStates &before) const;

    /// Each node's mean gap g~_k / w_k at the last update() (0 where w_k
    /// is 0).
    std::vector<double>
    mean_gaps() const;

    /// The slave and master segments of every contact point paired at the
    /// last update() (adaptive refinement keeps the master as fine as the
    /// slave where they face each other).
    std::vector<std::pair<unsigned int, unsigned int>>
    paired_segments() const;

    /// True if the current pairs are all inside the last sparsity pattern.
    bool
    sparsity_covers_pairing() const;

    /// The couplings of the current pairs (and their neighbours, so that
    /// small slips do not need a new pattern), one block of unknowns per
    /// slave segment, each sorted: every unknown of a block is coupled with
    /// every other. Known before the sparsity pattern is built, so that
    /// the memory of the system can be estimated first (LinearSystem).
    std::vector<std::vector<types::global_dof_index>>
    coupling_blocks();

    /// Add the contact terms to the tangent matrix and rhs = -residual:
    /// the slave points on this process's cells, and the rows of the open
    /// nodes it owns (see LinearSystem).
    void
    assemble(const Vector<double>            &solution,
             const AffineConstraints<double> &constraints,
             LinearSystem                    &system) const;

    /// Add the contact terms of the residual at `solution` (their values,
    /// unconstrained) to `forces`: in a displacement row, the force of the
    /// other body on this node, with the sign of an internal force. Every
    /// slave point, whatever its process (the same sum on all of them).
    void
    add_forces(const Vector<double> &solution, Vector<double> &forces) const;

    /// The multiplier dofs of the slave surface, one per contact node (with
    /// cyclic symmetry the end side's twin is left out: see
    /// all_multiplier_dofs()).
    const std::vector<types::global_dof_index> &
    multiplier_dofs() const
    {
      return multiplier_dof_list;
    }

    /// Every multiplier dof on the slave surface, twins included.
    std::vector<types::global_dof_index>
    all_multiplier_dofs() const;

    /// Number of active (closed) multiplier nodes.
    unsigned int
    n_active() const;

    /// Whether the multiplier node `dof` (of this interface) is active.
    bool
    is_active(const types::global_dof_index dof) const;

    /// Friction: the converged state of a step (or of its part) becomes the
    /// one the next slips are measured from.
    void
    accept_state(const Vector<double> &solution);

    /// Number of closed nodes that slip (friction).
    unsigned int
    n_slipping() const;

    /// The tangential-traction dof at a multiplier node (friction), or
    /// invalid.
    types::global_dof_index
    tangential_dof(const types::global_dof_index multiplier_dof) const;

    /// Every tangential-traction dof of the slave surface (friction).
    const std::vector<types::global_dof_index> &
    tangential_dofs() const
    {
      return tangential_dof_list;
    }

    /// The multiplier dof at the slave vertex nearest to a reference point
    /// (and, if asked, its distance from the point).
    types::global_dof_index
    multiplier_dof_nearest_to(const Point<2> &point,
                              double         *distance = nullptr) const;

    /// Current over reference length of the slave surface at a multiplier
    /// node (average over the segments that share it): converts the Cauchy
    /// pressure to the nominal one.
    double
    stretch_at(const types::global_dof_index multiplier_dof) const;

    /// The deepest interpenetration of the surfaces at the last update():
    /// the most negative mean gap g~_k / w_k over the multiplier nodes
    /// (a depth >= 0; 0 when none is negative), and that node's position.
    std::pair<double, Point<2>>
    deepest_interpenetration() const;

    /// The length of the shortest slave segment (reference configuration).
    double
    slave_segment_length() const
    {
      return segment_length;
    }

    /// Gap at a multiplier node (its slave point projected on the master).
    double
    gap_at(const types::global_dof_index multiplier_dof,
           const Vector<double>         &solution) const;

    /// sqrt(int (p_h - p_ref)^2) / sqrt(int p_ref^2) over the slave surface,
    /// with p_h the reported (Cauchy or nominal) pressure.
    double
    l2_relative_error(const Vector<double> &solution,
                      const double          reference_pressure,
                      const PressureMeasure measure) const;

    /// The weight a unit pressure on the slave puts on each master node
    /// under this interface's scheme and its last update(): the sum over the
    /// slave points of the node's shape function at the partner times the
    /// point's length element, keyed by the node's x unknown (the load
    /// transfer of the contact patch test, diagnostics/surfaces_at_rest.h).
    std::map<types::global_dof_index, double>
    master_load_weights() const;

    const ContactSurface &
    slave_surface() const
    {
      return slave;
    }
    const ContactSurface &
    master_surface() const
    {
      return master;
    }

  private:
    /// Evaluate the contact element of each slave point (those on cells of
    /// `process`, or all with numbers::invalid_unsigned_int) at `solution`,
    /// with derivatives or without, and hand it and its residual to
    /// `visit(element, residual)`: assemble() and add_forces(). Defined and
    /// used in contact_assembly.cc only.
    template <typename Visitor>
    void
    visit_points(const Vector<double> &solution,
                 const bool            derivatives,
                 const unsigned int    process,
                 const Visitor        &visit) const;

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

    ContactSurface      slave;
    ContactSurface      master;
    const Quadrature<1> quadrature;
    const double        complementarity_constant;
    /// Coulomb's coefficient (0: frictionless).
    const double friction_coefficient;
    /// Small strain: contact geometry (pairing, normal, length) of the
    /// reference configuration, gap linear in the displacement. The
    /// model's, and the one used now (also while a finite-strain step is
    /// solved linearised, see linearise()).
    const bool small_strain_model;
    bool       geometrically_linear;

    /// Fixed rules: every slave quadrature point paired with its closest
    /// master point. Segment-based: each slave segment cut into pieces with
    /// one partner each.
    void
    pair_points(const Vector<double> &solution, const Pairing pairing);
    /// Fill in a contact point from its piece, xi and w: position,
    /// partner (from `project`), gap and length element.
    template <typename Projector>
    void
    complete_point(ContactPoint         &point,
                   const unsigned int    slave_segment,
                   const Vector<double> &solution,
                   const Projector      &project) const;
    void
    pair_pieces(const Vector<double> &solution);
    /// The cuts of a slave segment (parameter, master vertex), sorted.
    std::vector<std::pair<double, unsigned int>>
    piece_cuts(const unsigned int s) const;

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

    /// Friction: each point's old partner, the weighted slips s~_k and the
    /// nodes' stick/slip states. Returns the number of changed states.
    unsigned int
    update_friction(const Vector<double> &solution);
    /// s~_k from the contact elements (contact_assembly.cc).
    void
    compute_weighted_slips(const Vector<double> &solution);

    const bool segment_based;
    /// Friction: the tangential traction in the dual basis of the
    /// multiplier basis (see ConvergedState), wherever the scheme's points
    /// are not the multiplier nodes.
    bool dual_basis = false;

    /// Friction: the nodes whose tangential motion is held alike on both
    /// sides (find_tangential_ties()), found at every assembly.
    mutable std::vector<bool> tied;
    void
    find_tangential_ties(const Vector<double>            &solution,
                         const AffineConstraints<double> &constraints,
                         const MPI_Comm                   communicator) const;

    std::vector<types::global_dof_index>            multiplier_dof_list;
    std::map<types::global_dof_index, unsigned int> multiplier_index;
    /// Where each multiplier node sits: (slave segment, t), one entry per
    /// segment that shares it.
    std::map<types::global_dof_index,
             std::vector<std::pair<unsigned int, double>>>
                        node_sites;
    std::vector<double> reference_weight; ///< w_k = int Phi_k dS
    std::vector<double> weighted_gap;     ///< g~_k
    std::vector<bool>   active;
    double              segment_length; ///< smallest slave segment
    /// Set by start_step(), cleared by the update() that it concerns.
    bool first_update_of_step = false;
    bool edge_extrapolation   = false;
    bool stick_held           = false;
    /// Whether a node carried pressure when the step began (start_step()).
    bool pressed_at_step_start = false;
    /// The multiplier nodes' neighbours along the slave surface, each with
    /// the length of the link in the reference configuration (measured on
    /// the segment that joins them: a twin's neighbour across the sector's
    /// ends is a segment away, not a sector).
    std::vector<std::vector<std::pair<unsigned int, double>>> node_neighbours;

    /// Friction: per node the tangential dof, s~_k and the state (0 stick,
    /// +1 or -1 the sign of the slip); the last converged solution and
    /// surfaces.
    std::vector<types::global_dof_index> tangential_dof_list;
    std::vector<double>                  weighted_slip;
    std::vector<int>                     slip_sign;
    Vector<double>                       converged_solution;
    std::unique_ptr<ContactSurface>      converged_slave, converged_master;

    std::vector<ContactPoint> points;
    /// (slave segment, master segment) pairs in the sparsity pattern.
    std::set<std::pair<unsigned int, unsigned int>> pattern_pairs;
  };
} // namespace RingContact

#endif
