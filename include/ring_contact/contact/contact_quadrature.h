// The contact integration schemes: their names in the parameter file
// ("nodal", "Gauss 3", "Simpson 2", "Newton-Cotes 4", "segment-based 2"),
// and the quadrature rule each puts on a slave segment (for segment-based
// integration: on each piece of it). Each family of schemes (nodal, Gauss,
// Simpson, Newton-Cotes, segment-based) is registered by a file of its own
// in source/contact/schemes/ (base/registry.h): its word, its documentation,
// the numbers of points it admits, its rule and that rule's exactness. The
// checks every rule must pass, the parsing and the names are here, and ask
// the registry.
#ifndef ring_contact_contact_contact_quadrature_h
#define ring_contact_contact_contact_quadrature_h

#include <deal.II/base/quadrature.h>

#include <ring_contact/base/registry.h>

#include <functional>
#include <string>
#include <vector>

namespace RingContact
{
  using namespace dealii;

  /// One family of contact integration schemes, as it registers itself:
  ///   const IntegrationSchemeFamilies::Add registration{
  ///     IntegrationSchemeFamily{...}};
  struct IntegrationSchemeFamily
  {
    /// The word the parameter file writes ("Gauss"; read in any case).
    std::string name;
    /// Words still read for it.
    std::vector<std::string> old_names;
    /// What the scheme is, for Contact/Integration schemes ("n Gauss
    /// points per slave segment (1-20)"; n is its number of points).
    std::string documentation;
    /// The numbers of points n it admits; empty for a family that takes
    /// no number (nodal: its points are the nodes).
    std::vector<unsigned int> admitted_points;
    /// Why a number is refused, said after the scheme's text ("Gauss needs
    /// 1 to 20 points").
    std::string points_refusal;
    /// The n of the word without a number, from the surfaces' displacement
    /// degree, chosen once the elements are known; empty: a number must be
    /// given.
    std::function<unsigned int(unsigned int degree)> default_points;
    /// Whether the slave segments are cut where the master's vertices
    /// project, the rule put on each piece (mortar integration): exact on
    /// surfaces that do not match, where the point-wise schemes are not.
    bool cuts_at_master_kinks;
    /// The rule on a segment or piece (t in [0, 1]) with n points on
    /// surfaces of displacement degree `degree`.
    std::function<Quadrature<1>(unsigned int n, unsigned int degree)> rule;
    /// The highest polynomial degree that rule integrates exactly.
    std::function<unsigned int(unsigned int n, unsigned int degree)>
      exactness_degree;

    /// "Gauss n", "nodal": the name with what follows it in the file.
    std::string
    label() const;
  };

  /// The registered families of schemes, sorted by name.
  using IntegrationSchemeFamilies = Registry<IntegrationSchemeFamily>;

  /// The numbers first, first + 1, ..., last (a family's admitted_points).
  std::vector<unsigned int>
  points_from_to(const unsigned int first, const unsigned int last);

  /// One contact integration scheme as named in the `.prm` file.
  struct IntegrationScheme
  {
    /// Its family's registration (which outlives every scheme).
    const IntegrationSchemeFamily *family = nullptr;
    unsigned int n_points; ///< n (meaning depends on the family; 0 for
                           ///< segment-based until the elements choose it)

    /// "nodal", "Gauss 3", "Simpson 2", "Newton-Cotes 4", "segment-based 3".
    std::string
    name() const;
    /// The name for file names: "nodal", "gauss-3", "segment-based-2".
    std::string
    tag() const;
    /// Whether it cuts the slave segments at the master's kinks
    /// (segment-based): exact where the surfaces do not match.
    bool
    cuts_at_master_kinks() const;
    /// Parse one of the names above; throws with a clear message otherwise.
    static IntegrationScheme
    parse(const std::string &text);
  };

  /// The registered families, for the documentation of Contact/Integration
  /// schemes: those that cut at the master's kinks, then the point-wise
  /// ones ("Gauss n: ...; nodal: ...").
  std::string
  integration_schemes_documentation();

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

  /// The highest polynomial degree the scheme's rule integrates exactly on
  /// a segment (on each piece, for segment-based integration) whose
  /// surfaces are of degree `degree`.
  unsigned int
  exactness_degree(const IntegrationScheme &scheme, const unsigned int degree);
} // namespace RingContact

#endif
