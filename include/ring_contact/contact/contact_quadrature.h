// The contact integration schemes: their names in the parameter file
// ("nodal", "Gauss 3", "Simpson 2", "Newton-Cotes 4", "segment-based 2"),
// and the quadrature rule each puts on a slave segment (for segment-based
// integration: on each piece of it). One file, so that a new scheme is one
// enum value, its name and its rule.
#ifndef ring_contact_contact_contact_quadrature_h
#define ring_contact_contact_contact_quadrature_h

#include <deal.II/base/quadrature.h>

#include <string>

namespace RingContact
{
  using namespace dealii;

  /// Where the contact integrals are evaluated on each slave segment.
  enum class ContactIntegration
  {
    nodal,   ///< at the slave nodes (Gauss-Lobatto, the original's default)
    gauss,   ///< n Gauss points per slave segment
    simpson, ///< composite Simpson rule of order n (n sub-intervals)
    newton_cotes, ///< closed Newton-Cotes rule with n+1 points (n = 1,2,4,6)
    segment_based ///< slave segments cut where the master vertices project,
                  ///< n Gauss points on each piece (mortar integration)
  };

  /// One contact integration scheme as named in the `.prm` file.
  struct IntegrationScheme
  {
    ContactIntegration type;
    unsigned int       n_points; ///< n (meaning depends on the type; 0 for
                                 ///< segment-based until the elements
                                 ///< choose it)

    /// "nodal", "Gauss 3", "Simpson 2", "Newton-Cotes 4", "segment-based 3".
    std::string
    name() const;
    /// The name for file names: "nodal", "gauss-3", "segment-based-2".
    std::string
    tag() const;
    /// Parse one of the names above; throws with a clear message otherwise.
    static IntegrationScheme
    parse(const std::string &text);
  };

  /// The quadrature rule on a slave segment (t in [0, 1]) of a scheme.
  /// `degree` is the higher of the displacement degrees of the slave and
  /// master surfaces: "nodal" is Gauss-Lobatto through the nodes of a
  /// segment of that degree, i.e. the slave nodes, and also the mid-side
  /// points when the master is quadratic (where they face its mid-side
  /// nodes); see theory.md. Throws, with the reason, for the rules that
  /// leave some nodes of a quadratic surface without weight (first order):
  /// one point per segment or piece, and the trapezoid rule.
  /// Also throws for a rule that does not integrate the shape functions of
  /// a surface of that degree exactly (see exactness_degree()).
  /// Throws too for a rule with fewer points on a segment than the
  /// multiplier of degree `multiplier_degree` has nodes there: a pressure
  /// vanishing at every point would be free.
  Quadrature<1>
  contact_quadrature(const IntegrationScheme &scheme,
                     const unsigned int       degree,
                     const unsigned int       multiplier_degree);

  /// Throw, with the reason, when the scheme's rule has fewer points on a
  /// slave segment (on surfaces of displacement degree `degree`) than the
  /// multiplier of degree `multiplier_degree` has nodes there.
  void
  require_points_for_multiplier(const IntegrationScheme &scheme,
                                const unsigned int       degree,
                                const unsigned int       multiplier_degree);

  /// The highest polynomial degree the scheme's rule integrates exactly on
  /// a segment (on each piece, for segment-based integration) whose
  /// surfaces are of degree `degree`.
  unsigned int
  exactness_degree(const IntegrationScheme &scheme, const unsigned int degree);
} // namespace RingContact

#endif
