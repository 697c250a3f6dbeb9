// @sect3{The nodal scheme}
//
// The original's node-to-segment scheme: the contact integrals evaluated at
// the nodes, with the weights that integrate the elements' polynomials. It
// takes no number: its points follow from the surfaces' degree. Exact only
// where the nodes of the two surfaces face each other.
#include <deal.II/base/quadrature_lib.h>

#include <ring_contact/contact/contact_quadrature.h>

#include <algorithm>

namespace RingContact
{
  namespace
  {
    // The registration line of the family: Contact/Integration schemes =
    // nodal.
    const IntegrationSchemeFamilies::Add registration{IntegrationSchemeFamily{
      "nodal",
      {},
      "at the slave nodes",
      {},
      // 'nodal 3' was once run as plain nodal: anything after the word is
      // refused.
      "nodal takes no number or other word (its points are the nodes)",
      {},
      false,
      // At the nodes: trapezoid when both surfaces are linear, Simpson when
      // one is quadratic. A linear slave facing a quadratic master needs the
      // mid-side points too (the degree is the higher of the two surfaces'):
      // with the slave vertices alone the master's mid-side nodes would get
      // no contact force. On cubic and quartic surfaces, Gauss-Lobatto
      // through their 4 or 5 nodes: the nodes of every segment are still
      // quadrature points.
      [](unsigned int, const unsigned int degree) -> Quadrature<1> {
        return QGaussLobatto<1>(degree + 1);
      },
      // Gauss-Lobatto with degree + 1 points: exact to 2 (degree + 1) - 3.
      [](unsigned int, const unsigned int degree) {
        return std::max(1u, 2 * degree - 1);
      }}};
  } // namespace
} // namespace RingContact
