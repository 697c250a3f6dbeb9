// @sect3{Diagnostics: stiffnesses too far apart for double precision}
//
// A cell's stiffness per unit thickness is its Young's modulus times the
// ratio of its length to its thickness (a cell 1e8 times longer than thick
// is 1e8 times stiffer across than a square one). Where the cells'
// stiffnesses differ by a factor S, the forces of the stiffest cells,
// computed from displacements set by the softest, carry a round-off of
// about eps S of the load: bodies of very different Young's moduli, or a
// body very thin against its cells' length, exhaust double precision, and the
// direct solve's residual, a few times eps S (measured: doc/validation.md,
// "Stiffnesses too far apart for double precision"), exceeds its bound.
// Said before the first step (refused past eps S = 1e-7, S = 4.5e8), and
// named when a solve fails, instead of a body free to move rigidly.
#ifndef ring_contact_diagnostics_stiffness_spread_h
#define ring_contact_diagnostics_stiffness_spread_h

#include <deal.II/grid/tria.h>

#include <ring_contact/base/dimension.h>
#include <ring_contact/scenarios/scenario.h>

#include <string>
#include <vector>

namespace RingContact
{
  namespace Diagnostics
  {
    using namespace dealii;

    /// The spread of the cells' stiffnesses, max(E a) / min(E) over the
    /// cells, a a cell's length over its thickness (its longest edge
    /// squared over its area).
    struct StiffnessSpread
    {
      double factor = 1;
      /// What makes it: the stiffest cell's body, E and a, and the
      /// softest body (empty for a factor of 1).
      std::string causes;

      /// Whether round-off (eps times the factor) reaches `fraction` of the
      /// forces.
      bool
      exceeds(const double fraction) const;

      /// "the cells' stiffnesses differ by a factor 8.6e+08 (...)".
      std::string
      describe() const;

      /// What a singular tangent (a solve that fails) suggests: a body free
      /// to move rigidly, and first this spread where it is within a
      /// factor 100 of what double precision can solve.
      std::string
      singular_tangent_advice() const;
    };

    /// The spread of `triangulation`'s cells, each of the body of its
    /// material id. Throws a one-line error when it exceeds what double
    /// precision can solve (eps S > 1e-7).
    StiffnessSpread
    stiffness_spread(const Triangulation<dim>     &triangulation,
                     const std::vector<Body<dim>> &bodies);
  } // namespace Diagnostics
} // namespace RingContact

#endif
