// @sect3{The contact interface in three dimensions}
//
// ContactInterface<3>: what ContactProblem<3> holds per contact pair, with
// the vocabulary of the 2D ContactInterface (contact_interface.h) so that
// the problem's chapters are written once for both dimensions. Its parts:
// - FaceContact (face_contact.h): the bilinear faces of the two surfaces,
//   their pairs, the weighted gaps and the pairs' rows in AD numbers;
// - MultiplierNodes and ActiveSet, the 2D classes: the slave vertices'
//   pressure unknowns with their weights w_k, and the primal-dual choice of
//   the closed nodes (with its round-off tolerance and its touching start),
//   from the faces' weighted gaps.
// Frictionless: friction in 3D is refused before a problem is made.
#ifndef ring_contact_contact_face_contact_interface_h
#define ring_contact_contact_face_contact_interface_h

#include <deal.II/base/point.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/vector.h>

#include <ring_contact/contact/active_set.h>
#include <ring_contact/contact/contact_pairing.h>
#include <ring_contact/contact/contact_quadrature.h>
#include <ring_contact/contact/face_contact.h>
#include <ring_contact/contact/multiplier_nodes.h>
#include <ring_contact/input/parameters.h>
#include <ring_contact/linear_algebra/linear_system.h>

#include <memory>
#include <set>
#include <utility>
#include <vector>

namespace RingContact
{
  template <int dim>
  class ContactInterface;

  template <>
  class ContactInterface<3>
  {
  public:
    /// The faces of `parameters`' slave and master boundary tags, the
    /// contact integrated by `scheme` (segment-based, nodal or Gauss n:
    /// n x n points per slave face). `largest_youngs_modulus` sets the
    /// complementarity constant E / h (h: the shortest slave face edge)
    /// when the parameters give none. `mapping` (the bodies' mappings by
    /// active finite element index) places the nodes of quadratic faces
    /// (FaceContact).
    ContactInterface(const DoFHandler<3>            &dof_handler,
                     const ContactParameters        &parameters,
                     const IntegrationScheme        &scheme,
                     const double                    largest_youngs_modulus,
                     const bool                      geometrically_linear,
                     const hp::MappingCollection<3> *mapping = nullptr);

    ContactInterface(const ContactInterface &) = delete;
    ContactInterface &
    operator=(const ContactInterface &) = delete;

    /// @name An iterate (as in 2D)
    /// @{

    /// Pair the faces at `solution` and choose the active set from the
    /// weighted gaps and the multipliers. Returns the number of nodes that
    /// opened or closed. The faces are paired again whatever `pairing`
    /// asks: in 3D the pairs are a function of the positions alone.
    unsigned int
    update(const Vector<double> &solution,
           const Pairing         pairing = Pairing::search);

    /// Frictionless: nothing is carried from a converged state.
    void
    accept_state(const Vector<double> &)
    {}

    bool
    small_strain() const
    {
      return small_strain_model;
    }
    void
    linearise(const bool on);
    bool
    has_friction() const
    {
      return false;
    }
    /// Small strain: the rows are piecewise linear in the unknowns.
    bool
    piecewise_linear() const
    {
      return geometrically_linear;
    }
    /// @}

    /// @name The parts
    /// @{
    const MultiplierNodes &
    nodes() const
    {
      return *multiplier_nodes;
    }
    const ActiveSet &
    active_set() const
    {
      return *states;
    }
    ActiveSet &
    active_set()
    {
      return *states;
    }
    const FaceContact &
    faces() const
    {
      return face_contact;
    }
    /// @}

    /// @name The Newton system (as in 2D)
    /// @{
    bool
    sparsity_covers_pairing() const;
    std::vector<std::vector<types::global_dof_index>>
    coupling_blocks();
    void
    assemble(const Vector<double>            &solution,
             const AffineConstraints<double> &constraints,
             LinearSystem                    &system) const;
    void
    add_forces(const Vector<double> &solution, Vector<double> &forces) const;
    /// @}

    /// @name What the postprocessing asks of a pair
    /// @{

    /// The multiplier dof at the slave vertex nearest to a reference point
    /// (and, if asked, its distance from the point).
    types::global_dof_index
    multiplier_dof_nearest_to(const Point<3> &point,
                              double         *distance = nullptr) const;

    /// Current over reference area of the slave surface at a multiplier
    /// node at the last update() (the mean over the faces around it, at
    /// the node): converts the Cauchy pressure to the nominal one.
    double
    stretch_at(const types::global_dof_index multiplier_dof) const;

    /// The mean gap g~_k / w_k at a multiplier node at the last update()
    /// (in 2D the gap of the node's own projection; on faces the weighted
    /// gap is what the contact measures).
    double
    gap_at(const types::global_dof_index multiplier_dof) const;

    /// sqrt(int (p_h - p_ref)^2) / sqrt(int p_ref^2) over the slave
    /// surface at `solution`, p_h the multiplier interpolated on the faces:
    /// Cauchy (over the current surface) or nominal (lambda dA / dA_0 over
    /// the reference one), as in 2D.
    double
    l2_relative_error(const Vector<double> &solution,
                      const double          reference_pressure,
                      const PressureMeasure measure) const;

    /// The most negative mean gap over the nodes at the last update() (a
    /// depth >= 0) and that node's reference position.
    std::pair<double, Point<3>>
    deepest_interpenetration() const;

    /// A slave face as the postprocessing sees it: the multiplier dofs and
    /// the reference positions of its four vertices, in deal.II's
    /// lexicographic order (its edges 0-1, 2-3, 0-2 and 1-3).
    struct SlaveFace
    {
      std::array<types::global_dof_index, 4> multipliers;
      std::array<Point<3>, 4>                X;
    };
    /// Every slave face of the pair.
    std::vector<SlaveFace>
    slave_faces() const;

    /// The reference position of multiplier node k.
    const Point<3> &
    node_position(const unsigned int k) const
    {
      return multiplier_nodes->surface_position[k];
    }
    /// @}

  private:
    /// The stretches of the nodes at `solution` (stretch_at()).
    void
    measure_stretches(const Vector<double> &solution);

    /// Whether each node is closed (the ActiveSet's choice, for FaceContact).
    std::vector<bool>
    closed_nodes() const;

    /// The shortest slave face edge (reference configuration).
    const double edge_length;
    const double complementarity_constant;
    const bool   small_strain_model;
    bool         geometrically_linear;
    FaceContact  face_contact;
    /// Each node's stretch at the last update() (stretch_at()).
    std::vector<double>                    stretches;
    std::unique_ptr<const MultiplierNodes> multiplier_nodes;
    std::unique_ptr<ActiveSet>             states;
    /// (slave face, master face) pairs in the sparsity pattern.
    std::set<std::pair<unsigned int, unsigned int>> pattern_pairs;
  };
} // namespace RingContact

#endif
