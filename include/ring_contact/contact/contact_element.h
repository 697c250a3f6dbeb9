// @sect3{The contact element: its declaration}
//
// The contact element of one slave point and its partner (see
// contact_element.cc for what it computes and why, and contact_assembly.cc
// for the walk over the slave points that uses it). It is a class template
// on the AD number type, instantiated for two static capacities; only the
// contact assembly uses it.
#ifndef ring_contact_contact_contact_element_h
#define ring_contact_contact_contact_element_h

#include <deal.II/differentiation/ad/sacado_number_types.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/vector.h>

#include <ring_contact/base/dimension.h>
#include <ring_contact/contact/contact_pairing.h>
#include <ring_contact/contact/surface_kernel.h>
#include <ring_contact/linear_algebra/linear_system.h>

#include <array>
#include <functional>
#include <map>
#include <vector>

namespace RingContact
{
  /// The contact element, used by contact_assembly.cc only.
  namespace ContactElements
  {
    using namespace dealii;

    // @sect4{AD numbers of a static capacity}
    //
    // The most local unknowns of a contact element: a slave segment's
    // displacements, four master segments' (the partner, its two
    // neighbours, and with friction the old partner), the multipliers and
    // the tangential tractions. AD numbers of a static capacity (their
    // derivatives sized to the element's unknowns at run time) need no
    // allocation: dynamic ones allocate, and made C's assembly slower
    // (bench/alternate --seed; doc/validation.md, "Time and memory behind the
    // code's choices"). The capacity of degree 2 (2 x 3 + 4 x 2 x 3 + 3 + 3 =
    // 36) serves the linear and quadratic surfaces; the elements of cubic and
    // quartic ones (up to 2 x 5 + 4 x 2 x 5 + 5 + 5 = 60) take numbers of that
    // capacity: given to every element, it made the common case slower (the
    // same section).
    constexpr unsigned int small_capacity = 2 * 3 + 4 * 2 * 3 + 3 + 3;
    constexpr unsigned int large_capacity = 2 * 5 + 4 * 2 * 5 + 5 + 5;
    using SmallAD = Sacado::Fad::SLFad<double, small_capacity>;
    using LargeAD = Sacado::Fad::SLFad<double, large_capacity>;

    // Friction: the last converged solution and the surfaces in that state
    // (ContactInterface::accept_state()). The slip of an iterate is its motion
    // relative to that state: the element reads it, but never differentiates
    // it.
    //
    // And the basis of the tangential traction: Psi_k biorthogonal to the
    // multiplier basis Phi_k, int Psi_k Phi_j dS = delta_kj int Phi_k dS on
    // each slave segment (the dual basis of Wohlmuth), wherever the
    // scheme's points are not the multiplier nodes themselves (dual_basis);
    // where they are (the nodal scheme with multipliers of the slave's
    // degree) the weights are diagonal already, and Psi is Phi. See
    // ContactElement::evaluate_slave_point().
    struct ConvergedState
    {
      const Vector<double> &solution;
      const ContactSurface &slave;
      const ContactSurface &master;
      const bool            dual_basis;
    };

    // @sect4{The layout of a contact element}
    //
    // The contact element of one slave point and its partner: the local
    // unknowns as AD variables, then the slave point, the partner and the
    // normal, the residual, and its value and exact derivative scattered into
    // the global system. Each step is a member function, in the order
    // ContactInterface::visit_points() calls them.
    //
    // ElementLayout is the part that does not depend on the number type:
    // which unknowns enter. Local layout: slave u_x, u_y, then u_x, u_y of
    // each master segment whose displacement enters (the partner, and the
    // neighbours that define the normal: at a vertex the other segment
    // there; smoothed normals and segment-based pieces: both neighbours of
    // the partner; with friction the old partner), then the multipliers,
    // then (friction) the tangential tractions.
    // The layout is built first, apart from the element, so that the number of
    // local unknowns is known when the AD type is chosen (visit_points()): the
    // elements of linear and quadratic surfaces fit numbers of capacity 36,
    // those of cubic and quartic ones need 60.
    class ElementLayout
    {
    public:
      ElementLayout(const ContactSurface &slave,
                    const ContactSurface &master,
                    const ContactPoint   &point,
                    const bool            current,
                    const bool            segment_based,
                    const ConvergedState *converged);

      unsigned int
      n_unknowns() const
      {
        return local_dofs.size();
      }

    protected:
      const ContactSurface &slave;
      const ContactSurface &master;
      const ContactPoint   &point;
      const Projection     &projection;
      const SurfaceSegment &s_seg;
      const SurfaceSegment &m_seg;
      /// Finite strain: the current configuration (else the reference
      /// tangent, small strain).
      const bool current;
      const bool smooth;
      const bool segment_based;
      /// Friction: the last converged state (nullptr: frictionless).
      const ConvergedState *converged;

      std::vector<types::global_dof_index> local_dofs;
      std::map<unsigned int, unsigned int> offset_of; // segment -> its u_x
      unsigned int ns = 0, nl = 0, lambda_offset = 0, tangential_offset = 0;
    };

    template <typename AD>
    class ContactElement : public ElementLayout
    {
    public:
      using ADPoint  = SurfaceKernel::CurvePoint<AD>;
      using ADVector = Tensor<1, dim, AD>;

      /// The layout's unknowns must fit the AD numbers' capacity.
      explicit ContactElement(const ElementLayout &layout)
          : ElementLayout(layout)
      {}

      void
      gather_unknowns(const Vector<double> &solution,
                      const bool            derivatives = true);
      void
      evaluate_slave_point();
      void
      evaluate_partner_and_normal();
      AD
      slip() const;
      std::vector<AD>
      residual(
        const double                                        c,
        const std::function<bool(types::global_dof_index)> &active,
        const std::function<int(types::global_dof_index)>  &friction_state,
        const double                                        mu) const;
      /// Phi_k at the slave point (for the weighted slips).
      AD
      multiplier_basis(const unsigned int k) const
      {
        return Phi_eta[k];
      }
      /// Psi_k at the slave point (for the weighted slips s~_k = int Psi_k s
      /// dS).
      AD
      tangential_basis(const unsigned int k) const
      {
        return Psi_eta[k];
      }
      AD
      length_element() const
      {
        return ds;
      }
      void
      scatter(std::vector<AD>                 &residual,
              const AffineConstraints<double> &constraints,
              LinearSystem                    &system);
      /// The residual's values added to `v`, unconstrained.
      void
      add_values(std::vector<AD> &residual, Vector<double> &v);

    private:
      std::array<AD, 2>
      piece_ends();
      ADPoint
      master_point(const unsigned int m, const double t) const;
      ADVector
      scaled_normal(const unsigned int m, const double t) const;
      ADVector
      vertex_normal(const unsigned int end) const;
      void
      turn_copies(std::vector<AD> &v, const bool back) const;

      std::vector<AD> u;

      // The slave point.
      std::vector<double> N, dN, ddN, Phi, dPhi, ddPhi;
      AD                  d_eta, ds, lambda, lambda_t;
      ADPoint             xs;
      /// Its reference position and its displacement, apart (see the gap).
      ADVector        xs_reference, us;
      std::vector<AD> Phi_eta, N_eta;
      /// The tangential traction's basis Psi_k (see evaluate_slave_point()).
      std::vector<AD> Psi_eta;

      // The partner and the normal.
      std::vector<double> Nm, dNm, ddNm;
      AD                  dxi, gap;
      ADVector            normal;
    };
  } // namespace ContactElements
} // namespace RingContact

#endif
