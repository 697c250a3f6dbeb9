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
//
// The interface is made of three parts, each a class of its own: the
// pairing of the slave points with the master (contact_pairing.h), the
// active set of closed, sticking and sliding nodes (active_set.h), and this
// class, which owns the surfaces and the multiplier nodes
// (multiplier_nodes.h), moves them to each iterate, and turns the pairs and
// the states into rows of the Newton system (contact_assembly.cc) and into
// what the postprocessing asks of a pair.
#ifndef ring_contact_contact_contact_interface_h
#define ring_contact_contact_contact_interface_h

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_matrix.h>

#include <ring_contact/base/dimension.h>
#include <ring_contact/contact/active_set.h>
#include <ring_contact/contact/contact_pairing.h>
#include <ring_contact/contact/contact_surface.h>
#include <ring_contact/contact/cyclic_symmetry.h>
#include <ring_contact/contact/multiplier_nodes.h>
#include <ring_contact/linear_algebra/linear_system.h>

#include <map>
#include <memory>
#include <set>

namespace RingContact
{
  /// The contact interface of a pair of surfaces in `dim` dimensions: the
  /// class below for dim = 2 (segments of curves); for dim = 3 (bilinear
  /// faces) face_contact_interface.h, with the same vocabulary.
  template <int dim>
  class ContactInterface;

  template <>
  class ContactInterface<2>
  {
  public:
    /// `largest_youngs_modulus` sets the automatic complementarity constant
    /// E / h (h: the shortest slave segment) when the parameters give none.
    /// With cyclic symmetry (`sector.angle` > 0) the master surface is
    /// continued by rotated copies, and the two multiplier nodes of a pair
    /// of `sector.multiplier_twins` are one contact node (the end one is
    /// tied to the start one by the constraints).
    ContactInterface(const DoFHandler<dim>        &dof_handler,
                     const ContactParameters      &parameters,
                     const IntegrationScheme      &scheme,
                     const unsigned int            slave_mapping_degree,
                     const unsigned int            master_mapping_degree,
                     const double                  largest_youngs_modulus,
                     const bool                    geometrically_linear,
                     const CyclicSymmetry::Sector &sector = {});

    ContactInterface(const ContactInterface &) = delete;
    ContactInterface &
    operator=(const ContactInterface &) = delete;

    /// @name An iterate
    /// @{

    /// Move the surfaces to `solution`, pair every slave quadrature point
    /// with the master surface, and choose the active set (and with
    /// friction the stick and slip states) from the current multipliers
    /// and weighted gaps. Returns the number of nodes whose state changed.
    unsigned int
    update(const Vector<double> &solution,
           const Pairing         pairing = Pairing::search);

    /// Friction: the converged state of a step (or of its part) becomes the
    /// one the next slips are measured from.
    void
    accept_state(const Vector<double> &solution);

    /// Small strain: gaps linear in the displacement.
    bool
    small_strain() const
    {
      return geometrically_linear;
    }

    /// A pair of bodies in finite strain measured as in small strain
    /// (reference pairing, normal and length, gaps linear in the
    /// displacement) while the Newton solver solves a step's problem
    /// linearised at the undeformed state (problem/first_step.h).
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

    /// Whether the contact rows are piecewise linear in the unknowns: small
    /// strain (gaps linear in the displacement) and no friction, or friction
    /// with every closed node held in stick (a linear tie). The Newton
    /// iteration is then the primal-dual active-set method for a linear
    /// complementarity problem, which needs no damping.
    bool
    piecewise_linear() const
    {
      return geometrically_linear &&
             (friction_coefficient == 0 || states.holds_stick());
    }
    /// @}

    /// @name The parts: nodes, pairing, active set
    /// @{
    const MultiplierNodes &
    nodes() const
    {
      return multiplier_nodes;
    }
    const ContactPairing &
    pairing() const
    {
      return point_pairing;
    }
    const ActiveSet &
    active_set() const
    {
      return states;
    }
    /// The Newton solver's strategies set the active set's switches
    /// (start of a step, stick held, edges extrapolated).
    ActiveSet &
    active_set()
    {
      return states;
    }
    /// @}

    /// @name The Newton system
    /// @{

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
    /// @}

    /// @name What the postprocessing asks of a pair
    /// @{

    /// The multiplier dof at the slave vertex nearest to a reference point
    /// (and, if asked, its distance from the point).
    types::global_dof_index
    multiplier_dof_nearest_to(const Point<dim> &point,
                              double           *distance = nullptr) const;

    /// Current over reference length of the slave surface at a multiplier
    /// node (average over the segments that share it): converts the Cauchy
    /// pressure to the nominal one.
    double
    stretch_at(const types::global_dof_index multiplier_dof) const;

    /// Gap at a multiplier node (its slave point projected on the master).
    double
    gap_at(const types::global_dof_index multiplier_dof,
           const Vector<double>         &solution) const;

    /// The deepest interpenetration of the surfaces at the last update():
    /// the most negative mean gap g~_k / w_k over the multiplier nodes
    /// (a depth >= 0; 0 when none is negative), and that node's position.
    std::pair<double, Point<dim>>
    deepest_interpenetration() const;

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
    /// @}

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

    /// Friction: s~_k from the contact elements (contact_assembly.cc).
    std::vector<double>
    weighted_slips(const Vector<double> &solution) const;

    /// Friction: the nodes whose tangential motion is held alike on both
    /// sides (find_tangential_ties()), found at every assembly.
    mutable std::vector<bool> tied;
    void
    find_tangential_ties(const Vector<double>            &solution,
                         const AffineConstraints<double> &constraints,
                         const MPI_Comm                   communicator) const;

    ContactSurface slave;
    ContactSurface master;
    const double   complementarity_constant;
    /// Coulomb's coefficient (0: frictionless).
    const double friction_coefficient;
    /// Small strain: contact geometry (pairing, normal, length) of the
    /// reference configuration, gap linear in the displacement. The
    /// model's, and the one used now (also while a finite-strain step is
    /// solved linearised, see linearise()).
    const bool small_strain_model;
    bool       geometrically_linear;
    const bool segment_based;
    /// The length of the shortest slave segment (reference configuration).
    const double segment_length;

    const MultiplierNodes multiplier_nodes;
    ContactPairing        point_pairing;
    ActiveSet             states;
    /// Friction: the tangential traction in the dual basis of the
    /// multiplier basis (see ConvergedState), wherever the scheme's points
    /// are not the multiplier nodes.
    const bool dual_basis;

    /// Friction: the last converged solution and surfaces.
    Vector<double>                  converged_solution;
    std::unique_ptr<ContactSurface> converged_slave, converged_master;

    /// (slave segment, master segment) pairs in the sparsity pattern.
    std::set<std::pair<unsigned int, unsigned int>> pattern_pairs;
  };
} // namespace RingContact

// The 3D interface, ContactInterface<3>.
#include <ring_contact/contact/face_contact_interface.h>

#endif
