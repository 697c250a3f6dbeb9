// @sect3{The contact integration schemes}
//
// Where the contact integrals are evaluated on each slave segment decides much
// of what the method is worth. The nodal rule is the original's node-to-segment
// scheme when both surfaces are linear; Gauss, Simpson and Newton-Cotes rules
// are fixed rules on the whole slave segment, blind to the kinks of the
// master's shape functions inside it once the meshes have slid; segment-based
// integration puts Gauss points on pieces cut at those kinks (the mortar
// integration, ContactPairing::pair_pieces()). Each family registers itself in
// a file of its own (source/contact/schemes/): its word, its documentation, the
// numbers of points it admits, its rule and that rule's exactness. This file
// holds what is common to them: the schemes' names as the parameter file and
// the report write them, the tags of their output files, the parsing, and the
// refusals of the rules that would make the method first order, leave the
// pressure undetermined or fail the contact patch test, whatever the family.
// doc/theory.md measures the consequences.
#include <deal.II/base/exceptions.h>

#include <ring_contact/contact/contact_quadrature.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace RingContact
{
  namespace
  {
    std::string
    lower_case(std::string text)
    {
      for (char &c : text)
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      return text;
    }

    // The family of a word, in any case, or of one of its old names;
    // nullptr if none.
    const IntegrationSchemeFamily *
    find_family(const std::string &word)
    {
      const std::string lower = lower_case(word);
      for (const auto &family : IntegrationSchemeFamilies::members())
        {
          if (lower_case(family.name) == lower)
            return &family;
          for (const std::string &old_name : family.old_names)
            if (lower_case(old_name) == lower)
              return &family;
        }
      return nullptr;
    }

    // The families for the message that refuses an unknown word: "Gauss n,
    // ..., nodal, segment-based [n]" (the brackets: the number may be left
    // out).
    std::string
    known_families()
    {
      std::string known;
      for (const auto &family : IntegrationSchemeFamilies::members())
        known += (known.empty() ? "" : ", ") + family.name +
                 (family.admitted_points.empty() ? "" :
                  family.default_points          ? " [n]" :
                                                   " n");
      return known;
    }
  } // namespace

  std::string
  IntegrationSchemeFamily::label() const
  {
    return name + (admitted_points.empty() ? "" : " n");
  }

  std::vector<unsigned int>
  points_from_to(const unsigned int first, const unsigned int last)
  {
    std::vector<unsigned int> points;
    for (unsigned int n = first; n <= last; ++n)
      points.push_back(n);
    return points;
  }

  // The name as the parameter file writes it and the report prints it: the
  // family's word, and its number of points if it takes one.
  std::string
  IntegrationScheme::name() const
  {
    return family->name + (family->admitted_points.empty() ?
                             std::string() :
                             " " + std::to_string(n_points));
  }

  std::string
  IntegrationScheme::tag() const
  {
    // The name in lower case, a hyphen for the space: "gauss-3".
    // The tag names the scheme's VTU files (VtuWriter), which then carry no
    // space.
    std::string tag = lower_case(name());
    std::replace(tag.begin(), tag.end(), ' ', '-');
    return tag;
  }

  bool
  IntegrationScheme::cuts_at_master_kinks() const
  {
    return family->cuts_at_master_kinks;
  }

  // Parsed strictly (the word in any case, then one number and nothing after
  // it), so that a mistyped scheme is a one-line error that quotes it, never
  // another scheme run in its place.
  IntegrationScheme
  IntegrationScheme::parse(const std::string &text)
  {
    std::istringstream in(text);
    std::string        word, rest;
    in >> word;
    const IntegrationSchemeFamily *family = find_family(word);
    // A family that takes no number (nodal: its points follow from the
    // surfaces' degree) refuses anything after its word ('nodal 3' is not a
    // nodal scheme with 3 points, and was once run as plain nodal).
    if (family != nullptr && family->admitted_points.empty())
      {
        if (in >> rest)
          throw std::runtime_error("contact integration scheme '" + text +
                                   "': " + family->points_refusal);
        return {family, 0};
      }
    // The word alone, of a family that can choose its number (segment-based:
    // the points its surfaces need, chosen once the elements are known,
    // ContactParameters::choose_schemes()): 0 until then.
    if (family != nullptr && family->default_points && !(in >> rest))
      return {family, 0};
    in.clear();
    in.str(text);
    in >> word;
    int n = -1;
    if (!(in >> n))
      throw std::runtime_error("contact integration scheme '" + text +
                               "' needs a number of points, e.g. 'Gauss 2'");
    if (in >> rest)
      throw std::runtime_error("contact integration scheme '" + text +
                               "' has trailing text '" + rest + "'");
    if (family == nullptr)
      throw std::runtime_error("unknown contact integration scheme '" + text +
                               "' (known: " + known_families() + ")");
    const auto &admitted = family->admitted_points;
    if (n < 0 ||
        std::find(admitted.begin(), admitted.end(), n) == admitted.end())
      throw std::runtime_error("contact integration scheme '" + text +
                               "': " + family->points_refusal);
    return {family, static_cast<unsigned int>(n)};
  }

  // The families as the entry's documentation says them: first those that
  // cut at the master's kinks, exact on any meshes, each a sentence; then the
  // point-wise ones in one sentence.
  std::string
  integration_schemes_documentation()
  {
    std::string cutting, pointwise;
    for (const auto &family : IntegrationSchemeFamilies::members())
      if (family.cuts_at_master_kinks)
        cutting += family.label() + ": " + family.documentation + ". ";
      else
        pointwise += (pointwise.empty() ? "" : "; ") + family.label() + ": " +
                     family.documentation;
    return cutting +
           "The point-wise schemes, exact only where the surfaces' nodes "
           "face each other: " +
           pointwise + ".";
  }

  // The highest degree of the polynomials the rule integrates exactly on a
  // segment (or piece), as the family declares it (tests/quadrature measures
  // it). It decides whether a scheme passes the contact patch test on
  // surfaces of a given degree, see contact_quadrature().
  unsigned int
  exactness_degree(const IntegrationScheme &scheme, const unsigned int degree)
  {
    return scheme.family->exactness_degree(scheme.n_points, degree);
  }

  namespace
  {
    // @sect4{The refusals every rule must pass}

    // A quadratic segment's vertex functions vanish at its midpoint and its
    // mid-side function at its ends: a single point (Gauss 1, or one per
    // piece, which on facing meshes is the whole segment) or the ends alone
    // (trapezoid) give some of its nodes no contact force and leave their
    // displacement out of the weighted gaps, an error of the order of h in
    // the pressure (see theory.md).
    // Measured on the rings with one quadratic surface, each of these rules
    // converged at first order in the mesh size (doc/validation.md, "Element
    // mixes").
    // Degree 2 only: on cubic and quartic surfaces these rules fail the
    // exactness test, which says so in its own words.
    void
    refuse_first_order(const IntegrationScheme &scheme,
                       const Quadrature<1>     &rule,
                       const unsigned int       degree)
    {
      if (degree != 2)
        return;
      // The shape functions of the vertices, (1 - t)(1 - 2 t) and
      // t (2 t - 1), and of the mid-side node, 4 t (1 - t), at each point.
      bool first_vertex = false, second_vertex = false, mid_side = false;
      for (const auto &point : rule.get_points())
        {
          const double t = point[0];
          first_vertex |= std::abs((1 - t) * (1 - 2 * t)) > 1e-12;
          second_vertex |= std::abs(t * (2 * t - 1)) > 1e-12;
          mid_side |= std::abs(t * (1 - t)) > 1e-12;
        }
      const std::string reason =
        !mid_side        ? "its segment ends miss the mid-side nodes" :
        rule.size() == 1 ? "its one point per segment misses the vertex "
                           "nodes" :
                           "its points miss a vertex node";
      AssertThrow(first_vertex && second_vertex && mid_side,
                  ExcMessage("contact integration scheme '" + scheme.name() +
                             "' is first order on a quadratic contact "
                             "surface (" +
                             reason +
                             "); use nodal, Gauss 2 or more, Simpson, "
                             "Newton-Cotes 2 or more, or segment-based 2 or "
                             "more"));
    }

    // The multiplier has q + 1 nodes on a segment. A rule with fewer points
    // on a segment (or, segment-based, on a piece, which on facing meshes is
    // the whole segment) leaves a pressure that vanishes at all its points,
    // and so exerts no force and meets no gap: with Gauss 1 on linear
    // surfaces the pressure alternating from node to node, which the solver
    // then adds in any amount. The Gauss-Lobatto rule of the nodal scheme,
    // Simpson and the Newton-Cotes rules of order q or more have enough
    // points.
    void
    require_points_for_multiplier(const IntegrationScheme &scheme,
                                  const unsigned int       points_per_segment,
                                  const unsigned int       multiplier_degree)
    {
      if (points_per_segment < multiplier_degree + 1)
        throw std::runtime_error(
          "contact integration scheme '" + scheme.name() + "' has " +
          std::to_string(points_per_segment) + " point" +
          (points_per_segment == 1 ? "" : "s") +
          " on a slave segment, fewer than the " +
          std::to_string(multiplier_degree + 1) +
          " nodes of the contact pressure there (Multiplier degree " +
          std::to_string(multiplier_degree) +
          "): a pressure that vanishes at its points (alternating from node "
          "to node) is invisible to it, and the pressure is not unique; use "
          "segment-based (the default) or Gauss " +
          std::to_string(multiplier_degree + 1) + " or more");
    }

    // More generally, the contact patch test (a uniform pressure across
    // flat surfaces transmitted exactly) needs the nodal forces int lambda
    // phi_i ds of a constant pressure exact: the rule must integrate the
    // surface's shape functions, polynomials of its degree, exactly. A
    // quartic slave with 'segment-based 2' (exact to degree 3) missed the
    // patch test (doc/validation.md, "Figures that were in the code's
    // comments").
    void
    require_exactness(const IntegrationScheme &scheme,
                      const unsigned int       degree)
    {
      const unsigned int exactness = exactness_degree(scheme, degree);
      if (exactness >= degree)
        return;
      // The smallest rules that fit, for the message: n Gauss points are
      // exact to 2 n - 1, so n >= (degree + 1) / 2.
      const unsigned int gauss_points = (degree + 2) / 2;
      throw std::runtime_error(
        "contact integration scheme '" + scheme.name() +
        "' integrates polynomials up to degree " + std::to_string(exactness) +
        " exactly, less than the degree " + std::to_string(degree) +
        " of the contact surfaces' shape functions: a uniform pressure "
        "would not be transmitted exactly (the contact patch test fails); "
        "use segment-based (without a number: " +
        std::to_string(degree + 1) +
        " points, the default), or on surfaces whose nodes face each "
        "other nodal, Gauss " +
        std::to_string(gauss_points) + " or more" +
        (degree <= 3 ? std::string(", Simpson") : std::string()) +
        ", or Newton-Cotes " +
        (degree <= 3 ? "2" :
         degree <= 5 ? "4" :
                       "6") +
        " or more");
    }
  } // namespace

  // @sect4{The rule of a scheme}
  //
  // `degree` is the higher displacement degree of the two surfaces
  // (ContactInterface's constructor): the same points integrate the slave's
  // rows, the master's rows and the master's part of the weighted gaps, so the
  // rule must see the nodes of the finer of the two surfaces, not only the
  // slave's. A linear slave facing a quadratic master integrated at the slave
  // vertices alone left the master's mid-side nodes without contact force and
  // the pressure low, first order (doc/validation.md, "Element mixes").
  //
  // The family gives the rule, on [0, 1], the parameter of a segment or of a
  // piece (the contact element turns its weights into lengths, ds = |x_s'|
  // (eta_b - eta_a) w); the refusals, in the order of their gravity, are the
  // same for every family.
  Quadrature<1>
  contact_quadrature(const IntegrationScheme &scheme,
                     const unsigned int       degree,
                     const unsigned int       multiplier_degree)
  {
    const Quadrature<1> rule = scheme.family->rule(scheme.n_points, degree);
    refuse_first_order(scheme, rule, degree);
    require_points_for_multiplier(scheme, rule.size(), multiplier_degree);
    require_exactness(scheme, degree);
    return rule;
  }
} // namespace RingContact
