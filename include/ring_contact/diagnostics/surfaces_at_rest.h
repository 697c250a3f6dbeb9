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
// - A point-wise scheme on surfaces whose nodes do not face each other: it
//   fails the contact patch test there, and the pressure swings from node to
//   node whatever the mesh size.
#ifndef ring_contact_diagnostics_surfaces_at_rest_h
#define ring_contact_diagnostics_surfaces_at_rest_h

#include <deal.II/lac/vector.h>

#include <ring_contact/base/dimension.h>
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
    report_initial_interpenetration(ContactInterface<dim> &contact,
                                    const Vector<double>  &solution,
                                    std::ostream          &log);

    /// Warn in `log` when the discrete contact surfaces are too coarse for
    /// the curves they follow (their manifolds): when the initial gap they
    /// give departs from the gap between the curves by more than 0.1 % of the
    /// median initial gap or interference. Silent unless most nodes start
    /// with gaps of one size (conforming surfaces). True if it warned.
    bool
    report_coarse_geometry(ContactInterface<dim> &contact,
                           const Vector<double>  &solution,
                           std::ostream          &log);

    /// What a uniform pressure on the slave surface gives the master's
    /// nodes under a point-wise scheme, as a ratio to what the mortar
    /// (segment-based) transfer gives them, over the master nodes that the
    /// slave covers whole (the contact patch test; exact: 1).
    struct LoadTransfer
    {
      double       lowest  = 1;           ///< smallest ratio
      double       highest = 1;           ///< largest ratio
      Point<dim>   lowest_at, highest_at; ///< where (reference position)
      unsigned int n_nodes = 0;           ///< master nodes compared
    };

    /// Measure the load transfer of `pointwise` (an interface under a
    /// point-wise scheme) against `mortar` (one of the same pair under
    /// segment-based integration) in the state `solution` (the reference
    /// state), with a unit pressure on every slave node. Both are paired
    /// anew in that state.
    LoadTransfer
    measure_load_transfer(ContactInterface<dim> &pointwise,
                          ContactInterface<dim> &mortar,
                          const Vector<double>  &solution);

    /// The median ratio of a slave segment's length to that of the master
    /// segment facing it, over the slave segments that face the master
    /// (normals opposed) and are nearest to it (within two of their lengths
    /// of the smallest gap); 0 if none faces it. Above 1: the slave is the
    /// coarser surface.
    double
    facing_length_ratio(ContactInterface<dim> &contact,
                        const Vector<double>  &solution);

    /// True if the vertices of each surface of `contact` that face the
    /// other surface land on its vertices in the state `solution` (the
    /// meshes conform along the contact, whatever their degrees).
    bool
    vertices_conform(ContactInterface<dim> &contact,
                     const Vector<double>  &solution);

    /// Warn in `log` when the point-wise `scheme` fails the contact patch
    /// test on the surfaces of a pair (`transfer` departs from 1 by more
    /// than 1e-3) and the surfaces are not `conforming` (vertices_conform():
    /// there a departure is the rule's error on curved segments, which
    /// refinement removes, not a failed patch test), with the measured
    /// figures, what to expect, and the way out; `length_ratio`
    /// (facing_length_ratio()) adds that the slave is the coarser surface.
    /// `slave_id` and `master_id` name the surfaces. True if it warned.
    bool
    report_non_matching(const LoadTransfer      &transfer,
                        const double             length_ratio,
                        const bool               conforming,
                        const IntegrationScheme &scheme,
                        const types::boundary_id slave_id,
                        const types::boundary_id master_id,
                        std::ostream            &log);
  } // namespace Diagnostics
} // namespace RingContact

#endif
