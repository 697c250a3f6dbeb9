// @sect3{The composite Simpson schemes}
//
// 'Simpson n': Simpson's rule on each of n equal sub-intervals of the slave
// segment, 2 n + 1 points, the inner ends shared. Exact to degree 3 however
// many sub-intervals: enough for surfaces up to cubic.
#include <deal.II/base/quadrature_lib.h>

#include <ring_contact/contact/contact_quadrature.h>

namespace RingContact
{
  namespace
  {
    // The registration line of the family: Contact/Integration schemes =
    // Simpson n.
    const IntegrationSchemeFamilies::Add registration{IntegrationSchemeFamily{
      "Simpson",
      {},
      "composite Simpson with n sub-intervals",
      points_from_to(1, 20),
      "Simpson order must be 1 to 20",
      {},
      false,
      [](const unsigned int n, unsigned int) -> Quadrature<1> {
        return QIterated<1>(QSimpson<1>(), n);
      },
      // Composite Simpson: degree 3 however many sub-intervals.
      [](unsigned int, unsigned int) { return 3u; }}};
  } // namespace
} // namespace RingContact
