// @sect3{The closed Newton-Cotes schemes}
//
// 'Newton-Cotes n': one closed Newton-Cotes rule of order n on the slave
// segment, n + 1 equally spaced points from end to end. The orders are those
// of the closed rules deal.II has: QTrapezoid, QSimpson, QMilne and QWeddle,
// with 2, 3, 5 and 7 points.
#include <deal.II/base/quadrature_lib.h>

#include <ring_contact/contact/contact_quadrature.h>

namespace RingContact
{
  namespace
  {
    // The registration line of the family: Contact/Integration schemes =
    // Newton-Cotes n.
    const IntegrationSchemeFamilies::Add registration{IntegrationSchemeFamily{
      "Newton-Cotes",
      {},
      "closed Newton-Cotes of order 1, 2, 4 or 6",
      {1, 2, 4, 6},
      "Newton-Cotes order must be 1, 2, 4 or 6",
      {},
      false,
      // The trapezoid (n = 1: its segment ends miss the mid-side nodes of a
      // quadratic segment, refused there by contact_quadrature()), Simpson
      // (2), Milne (4), Weddle (6).
      [](const unsigned int n, unsigned int) -> Quadrature<1> {
        switch (n)
          {
            case 1:
              return QTrapezoid<1>();
            case 2:
              return QSimpson<1>();
            case 4:
              return QMilne<1>();
            default:
              // Only the orders registered above are parsed.
              Assert(n == 6, ExcInternalError());
              return QWeddle<1>();
          }
      },
      // Closed rules: n + 1 points, exact to degree n, n + 1 for even n.
      [](const unsigned int n, unsigned int) {
        return n % 2 == 0 ? n + 1 : n;
      }}};
  } // namespace
} // namespace RingContact
