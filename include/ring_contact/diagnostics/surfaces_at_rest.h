// @sect3{Diagnostics: the contact surfaces at rest}
//
// Three warnings read off the surfaces before the first step, each a wrong
// result once given without a word:
//
// - Surfaces that interpenetrate before any load. The contact pushes them
//   apart in the first step, a load that the problem does not state (a
//   curved slave against a faceted master starts inside it by up to the
//   sagitta, which is 2 % of the element size at 40 elements around a
//   circle; at E / p = 100 that is several times the pressure sought).
//   Measured by each node's mean gap g~_k / w_k in the reference state; said
//   when deeper than 1e-4 of the slave's shortest segment (round-off of
//   touching surfaces is 1e-16 of it). The caller leaves out the pairs with
//   a body held by the contact only (rigid_body_modes.h): its motion absorbs
//   the overlap, which is then a way to start in contact (the Hertz
//   problem's cylinder).
// - Surfaces too coarse for the curves they follow.
// - A slave coarser than its master under a point-wise scheme.
#ifndef ring_contact_diagnostics_surfaces_at_rest_h
#define ring_contact_diagnostics_surfaces_at_rest_h

#include <deal.II/lac/vector.h>

#include <ring_contact/contact/contact_interface.h>
#include <ring_contact/contact/contact_quadrature.h>

#include <ostream>

namespace RingContact
{
  namespace Diagnostics
  {
    using namespace dealii;

    /// Warn in `log` when the surfaces of `contact` interpenetrate at
    /// `solution` (the reference state); true if it warned.
    bool
    report_initial_interpenetration(ContactInterface     &contact,
                                    const Vector<double> &solution,
                                    std::ostream         &log);

    /// Warn in `log` when the discrete contact surfaces are too coarse for
    /// the curves they follow (their manifolds): when the initial gap they
    /// give departs from the gap between the curves by more than 0.1 % of the
    /// median initial gap or interference. Silent unless most nodes start
    /// with gaps of one size (conforming surfaces). True if it warned.
    bool
    report_coarse_geometry(ContactInterface     &contact,
                           const Vector<double> &solution,
                           std::ostream         &log);

    /// Warn in `log` when `scheme` evaluates the contact at points (nodal,
    /// Gauss, Simpson, Newton-Cotes: not segment-based) and the slave
    /// surface of `contact` is coarser than its master where the two face
    /// each other at `solution` (the reference state): when the median ratio
    /// of a slave segment's length to that of the master segment facing it
    /// exceeds 1.1, over the slave segments that face the master (normals
    /// opposed) and are nearest to it (within two of their lengths of the
    /// smallest gap). `slave_id` and `master_id` name the surfaces in the
    /// message. True if it warned.
    bool
    report_coarse_slave(ContactInterface        &contact,
                        const Vector<double>    &solution,
                        const IntegrationScheme &scheme,
                        const types::boundary_id slave_id,
                        const types::boundary_id master_id,
                        std::ostream            &log);
  } // namespace Diagnostics
} // namespace RingContact

#endif
