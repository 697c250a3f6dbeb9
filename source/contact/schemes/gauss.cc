// @sect3{The Gauss schemes}
//
// 'Gauss n': n Gauss points on each slave segment, a fixed rule blind to the
// kinks of the master's shape functions inside the segment once the meshes
// have slid (segment_based.cc puts the same points on pieces cut at them).
#include <deal.II/base/quadrature_lib.h>

#include <ring_contact/contact/contact_quadrature.h>

namespace RingContact
{
  namespace
  {
    // The registration line of the family: Contact/Integration schemes =
    // Gauss n.
    const IntegrationSchemeFamilies::Add registration{IntegrationSchemeFamily{
      "Gauss",
      {},
      "n Gauss points per slave segment (1-20)",
      points_from_to(1, 20),
      "Gauss needs 1 to 20 points",
      {},
      false,
      // One point (Gauss 1) misses the vertex nodes of a quadratic segment
      // and is refused there (contact_quadrature()).
      [](const unsigned int n, unsigned int) -> Quadrature<1> {
        return QGauss<1>(n);
      },
      // n Gauss points: exact to 2 n - 1.
      [](const unsigned int n, unsigned int) { return 2 * n - 1; }}};
  } // namespace
} // namespace RingContact
