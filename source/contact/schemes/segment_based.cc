// @sect3{The segment-based (mortar) schemes}
//
// 'segment-based n': each slave segment cut where the lines through the
// master vertices along their normals cross it (ContactPairing::
// pair_pieces()), and n Gauss points on each piece. Inside a piece the
// master's shape functions have no kink, so the rule integrates what it sees
// as exactly as on matching meshes: the only family that passes the contact
// patch test on surfaces that do not match, and the default. The contact
// element and the postprocessing ask cuts_at_master_kinks(), not the name.
#include <deal.II/base/quadrature_lib.h>

#include <ring_contact/contact/contact_quadrature.h>

namespace RingContact
{
  namespace
  {
    // The registration line of the family: Contact/Integration schemes =
    // segment-based [n].
    const IntegrationSchemeFamilies::Add registration{IntegrationSchemeFamily{
      "segment-based",
      {},
      "each slave segment cut where the lines through the master vertices "
      "along their normals cross it, n Gauss points on each piece (mortar "
      "integration; without n: the surfaces' displacement degree + 1); it "
      "passes the contact patch test on any meshes",
      points_from_to(1, 20),
      "segment-based needs 1 to 20 Gauss points per piece",
      // Without a number: p + 1 points on each piece, as the bulk's rule
      // has per direction (ContactParameters::choose_schemes() says why).
      [](const unsigned int degree) { return degree + 1; },
      true,
      // The rule on each piece; one point per piece (which on facing meshes
      // is the whole segment) is refused on quadratic surfaces.
      [](const unsigned int n, unsigned int) -> Quadrature<1> {
        return QGauss<1>(n);
      },
      // n Gauss points on each piece: exact to 2 n - 1 there.
      [](const unsigned int n, unsigned int) { return 2 * n - 1; }}};
  } // namespace
} // namespace RingContact
