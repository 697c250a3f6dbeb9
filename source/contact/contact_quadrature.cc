// @sect3{The contact integration schemes}
//
// Where the contact integrals are evaluated on each slave segment decides much
// of what the method is worth. The nodal rule is the original's node-to-segment
// scheme when both surfaces are linear; Gauss, Simpson and Newton-Cotes rules
// are fixed rules on the whole slave segment, blind to the kinks of the
// master's shape functions inside it once the meshes have slid; segment-based
// integration puts Gauss points on pieces cut at those kinks (the mortar
// integration, ContactPairing::pair_pieces()). This file holds the schemes'
// names as the parameter file and the report write them, the tags of their
// output files, and the rule each puts on a segment or piece, with the refusals
// of the rules that would make the method first order or fail the contact patch
// test. doc/theory.md measures the consequences.
#include <deal.II/base/exceptions.h>
#include <deal.II/base/quadrature_lib.h>

#include <ring_contact/contact/contact_quadrature.h>

#include <algorithm>
#include <cctype>
#include <sstream>
#include <stdexcept>

namespace RingContact
{
  // The name as the parameter file writes it and the report prints it.
  std::string
  IntegrationScheme::name() const
  {
    switch (type)
      {
        case ContactIntegration::nodal:
          return "nodal";
        case ContactIntegration::gauss:
          return "Gauss " + std::to_string(n_points);
        case ContactIntegration::simpson:
          return "Simpson " + std::to_string(n_points);
        case ContactIntegration::newton_cotes:
          return "Newton-Cotes " + std::to_string(n_points);
        case ContactIntegration::segment_based:
          return "segment-based " + std::to_string(n_points);
      }
    return "";
  }

  std::string
  IntegrationScheme::tag() const
  {
    // The name in lower case, a hyphen for the space: "gauss-3".
    // The tag names the scheme's VTU files (VtuWriter), which then carry no
    // space.
    std::string tag = name();
    for (char &c : tag)
      c = c == ' ' ?
            '-' :
            static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return tag;
  }

  // Parsed strictly (the word in any case, then one number and nothing after
  // it), so that a mistyped scheme is a one-line error that quotes it, never
  // another scheme run in its place.
  IntegrationScheme
  IntegrationScheme::parse(const std::string &text)
  {
    std::istringstream in(text);
    std::string        word;
    in >> word;
    std::string lower = word;
    for (char &c : lower)
      c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    IntegrationScheme scheme{ContactIntegration::nodal, 0};
    int               n = -1;
    std::string       rest;
    // nodal takes no number: its points follow from the surfaces' degree.
    // Anything after it is refused ('nodal 3' is not a nodal scheme with 3
    // points, and was once run as plain nodal).
    if (lower == "nodal")
      {
        if (in >> rest)
          throw std::runtime_error("contact integration scheme '" + text +
                                   "': nodal takes no number or other "
                                   "word (its points are the nodes)");
        return scheme;
      }
    // segment-based alone: the points its surfaces need, chosen once the
    // elements are known (ContactParameters::choose_schemes()); 0 until then.
    if (lower == "segment-based" && !(in >> rest))
      {
        scheme.type = ContactIntegration::segment_based;
        return scheme;
      }
    in.clear();
    in.str(text);
    in >> word;
    if (!(in >> n))
      throw std::runtime_error("contact integration scheme '" + text +
                               "' needs a number of points, e.g. 'Gauss 2'");
    if (in >> rest)
      throw std::runtime_error("contact integration scheme '" + text +
                               "' has trailing text '" + rest + "'");
    if (lower == "gauss")
      {
        scheme.type = ContactIntegration::gauss;
        if (n < 1 || n > 20)
          throw std::runtime_error("contact integration scheme '" + text +
                                   "': Gauss needs 1 to 20 points");
      }
    else if (lower == "simpson")
      {
        scheme.type = ContactIntegration::simpson;
        if (n < 1 || n > 20)
          throw std::runtime_error("contact integration scheme '" + text +
                                   "': Simpson order must be 1 to 20");
      }
    else if (lower == "newton-cotes")
      {
        scheme.type = ContactIntegration::newton_cotes;
        // The closed rules deal.II has: QTrapezoid, QSimpson, QMilne and
        // QWeddle, with 2, 3, 5 and 7 points.
        if (n != 1 && n != 2 && n != 4 && n != 6)
          throw std::runtime_error("contact integration scheme '" + text +
                                   "': Newton-Cotes order must be 1, 2, 4 "
                                   "or 6");
      }
    else if (lower == "segment-based")
      {
        scheme.type = ContactIntegration::segment_based;
        if (n < 1 || n > 20)
          throw std::runtime_error("contact integration scheme '" + text +
                                   "': segment-based needs 1 to 20 Gauss "
                                   "points per piece");
      }
    else
      throw std::runtime_error(
        "unknown contact integration scheme '" + text +
        "' (known: nodal, Gauss n, Simpson n, Newton-Cotes n, "
        "segment-based [n])");
    scheme.n_points = static_cast<unsigned int>(n);
    return scheme;
  }

  // The highest degree of the polynomials the rule integrates exactly on a
  // segment (or piece). It decides whether a scheme passes the contact patch
  // test on surfaces of a given degree, see contact_quadrature().
  unsigned int
  exactness_degree(const IntegrationScheme &scheme, const unsigned int degree)
  {
    switch (scheme.type)
      {
        case ContactIntegration::nodal:
          // Gauss-Lobatto with degree + 1 points: exact to 2 (degree + 1) - 3.
          return std::max(1u, 2 * degree - 1);
        case ContactIntegration::gauss:
        case ContactIntegration::segment_based:
          // n Gauss points: exact to 2 n - 1.
          return 2 * scheme.n_points - 1;
        case ContactIntegration::simpson:
          // Composite Simpson: degree 3 however many sub-intervals.
          return 3;
        case ContactIntegration::newton_cotes:
          // Closed rules: n + 1 points, exact to degree n, n + 1 for even n.
          return scheme.n_points % 2 == 0 ? scheme.n_points + 1 :
                                            scheme.n_points;
      }
    return 0;
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
                                const unsigned int       degree,
                                const unsigned int       multiplier_degree)
  {
    const unsigned int points_per_segment =
      (scheme.type == ContactIntegration::gauss ||
       scheme.type == ContactIntegration::segment_based) ?
        scheme.n_points :
      scheme.type == ContactIntegration::newton_cotes ? scheme.n_points + 1 :
      scheme.type == ContactIntegration::simpson ? 2 * scheme.n_points + 1 :
                                                   degree + 1;
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

  // @sect4{The rule of a scheme}
  //
  // `degree` is the higher displacement degree of the two surfaces
  // (ContactInterface's constructor): the same points integrate the slave's
  // rows, the master's rows and the master's part of the weighted gaps, so the
  // rule must see the nodes of the finer of the two surfaces, not only the
  // slave's. A linear slave facing a quadratic master integrated at the slave
  // vertices alone left the master's mid-side nodes without contact force and
  // the pressure low, first order (doc/validation.md, "Element mixes").
  Quadrature<1>
  contact_quadrature(const IntegrationScheme &scheme,
                     const unsigned int       degree,
                     const unsigned int       multiplier_degree)
  {
    // A quadratic segment's vertex functions vanish at its midpoint and its
    // mid-side function at its ends: a single point (Gauss 1, or one per
    // piece, which on facing meshes is the whole segment) or the ends alone
    // (trapezoid) give some of its nodes no contact force and leave their
    // displacement out of the weighted gaps, an error of the order of h in
    // the pressure (see theory.md).
    // Measured on the rings with one quadratic surface, each of these rules
    // converged at first order in the mesh size (doc/validation.md, "Element
    // mixes").
    const bool one_point = (scheme.type == ContactIntegration::gauss ||
                            scheme.type == ContactIntegration::segment_based) &&
                           scheme.n_points == 1;
    const bool ends_only =
      scheme.type == ContactIntegration::newton_cotes && scheme.n_points == 1;
    // Degree 2 only: on cubic and quartic surfaces these rules fail the
    // exactness test below, which says so in its own words.
    AssertThrow(degree != 2 || !(one_point || ends_only),
                ExcMessage("contact integration scheme '" + scheme.name() +
                           "' is first order on a quadratic contact surface "
                           "(" +
                           (one_point ? "its one point per segment misses "
                                        "the vertex nodes" :
                                        "its segment ends miss the mid-side "
                                        "nodes") +
                           "); use nodal, Gauss 2 or more, Simpson, "
                           "Newton-Cotes 2 or more, or segment-based 2 or "
                           "more"));
    require_points_for_multiplier(scheme, degree, multiplier_degree);
    // More generally, the contact patch test (a uniform pressure across
    // flat surfaces transmitted exactly) needs the nodal forces int lambda
    // phi_i ds of a constant pressure exact: the rule must integrate the
    // surface's shape functions, polynomials of its degree, exactly. A
    // quartic slave with 'segment-based 2' (exact to degree 3) missed the patch
    // test (doc/validation.md, "Figures that were in the code's comments").
    const unsigned int exactness = exactness_degree(scheme, degree);
    if (exactness < degree)
      {
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
    // The rules are on [0, 1], the parameter of a segment or of a piece; the
    // contact element turns their weights into lengths, ds = |x_s'| (eta_b -
    // eta_a) w.
    switch (scheme.type)
      {
        case ContactIntegration::nodal:
          // At the nodes, with the weights that integrate the elements'
          // polynomials: trapezoid when both surfaces are linear, Simpson
          // when one is quadratic. A linear slave facing a quadratic master
          // needs the mid-side points too: with the slave vertices alone the
          // master's mid-side nodes would get no contact force.
          // On cubic and quartic surfaces, Gauss-Lobatto through their 4 or 5
          // nodes: the nodes of every segment are still quadrature points.
          return QGaussLobatto<1>(degree + 1);
        case ContactIntegration::gauss:
        case ContactIntegration::segment_based: // the rule on each piece
          return QGauss<1>(scheme.n_points);
        case ContactIntegration::simpson:
          // n sub-intervals: 2 n + 1 points, the inner ends shared.
          return QIterated<1>(QSimpson<1>(), scheme.n_points);
        case ContactIntegration::newton_cotes:
          // n sub-intervals of one closed rule on the segment: the trapezoid (n
          // = 1, refused above on quadratic surfaces), Simpson (2), Milne (4),
          // Weddle (6).
          switch (scheme.n_points)
            {
              case 1:
                return QTrapezoid<1>();
              case 2:
                return QSimpson<1>();
              case 4:
                return QMilne<1>();
              case 6:
                return QWeddle<1>();
            }
      }
    // Unreachable: parse() admits no other scheme or number.
    AssertThrow(false, ExcMessage("unknown contact integration scheme"));
    return Quadrature<1>();
  }
} // namespace RingContact
