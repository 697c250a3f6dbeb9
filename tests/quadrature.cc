// The contact quadrature rules on a slave segment (t in [0, 1]): the points
// and weights of each scheme, and the polynomial degree each integrates
// exactly.
#include <ring_contact/base/utilities.h>
#include <ring_contact/contact/contact_surface.h>

#include "tests.h"

#include <cmath>
#include <iomanip>
#include <tuple>
#include <vector>

using namespace RingContact;
using RingContactTests::check;

namespace
{
  // Highest degree d such that t^0 ... t^d are integrated exactly.
  unsigned int
  exactness(const Quadrature<1> &q)
  {
    unsigned int d = 0;
    for (;; ++d)
      {
        double sum = 0;
        for (unsigned int i = 0; i < q.size(); ++i)
          sum += q.weight(i) * std::pow(q.point(i)[0], d);
        if (std::abs(sum - 1.0 / (d + 1)) > 1e-13)
          return d - 1;
      }
  }
} // namespace

int
main()
{
  auto &out = RingContactTests::deallog_file;
  out << std::setprecision(8);

  const auto show = [&](const std::string &text, const unsigned int degree) {
    const IntegrationScheme scheme = IntegrationScheme::parse(text);
    const Quadrature<1>     q      = contact_quadrature(scheme, degree, 1);
    out << std::left << std::setw(16) << scheme.name() << " on Q" << degree
        << ": " << q.size() << " points, exact to degree " << exactness(q)
        << "; points";
    for (unsigned int i = 0; i < q.size(); ++i)
      out << ' ' << q.point(i)[0];
    out << "; weights";
    for (unsigned int i = 0; i < q.size(); ++i)
      out << ' ' << q.weight(i);
    out << std::endl;
    return q;
  };

  // Nodal: at the nodes of the slave segment, trapezoid on Q1 and Simpson
  // on Q2 (the weights that integrate the element's own polynomials, not
  // the equal weights that make the original's quadratic nodal scheme off).
  const auto nodal1 = show("nodal", 1);
  check(nodal1.size() == 2 && std::abs(nodal1.weight(0) - 0.5) < 1e-15,
        "nodal on Q1 is the trapezoidal rule");
  const auto nodal2 = show("nodal", 2);
  check(nodal2.size() == 3 && std::abs(nodal2.weight(1) - 2.0 / 3) < 1e-15,
        "nodal on Q2 is Simpson's rule");

  // The degree is the higher of the slave's and the master's: a linear
  // slave facing a quadratic master is integrated at its vertices and
  // mid-side points (Simpson), where the master's nodes face it. Rules that
  // give some node of a quadratic segment no weight are refused there.
  for (const std::string first_order :
       {"Gauss 1", "segment-based 1", "Newton-Cotes 1"})
    {
      const IntegrationScheme scheme = IntegrationScheme::parse(first_order);
      try
        {
          contact_quadrature(scheme, 2, 1);
          check(false, first_order + " must be refused on a quadratic surface");
        }
      catch (const std::exception &e)
        {
          out << "refused on Q2: " << one_line_message(e) << std::endl;
        }
    }
  // A rule needs at least as many points on a segment as the multiplier has
  // nodes there, on linear surfaces too: one point per segment cannot see a
  // pressure that alternates from node to node (a uniform 1 MPa came out 0,
  // 2, 0, 2 MPa with Gauss 1 on Q1). Two points suffice for a linear
  // multiplier; a quadratic one needs three, so Gauss 2 and Newton-Cotes 1
  // are refused with it.
  for (const auto &[text, multiplier_degree, accepted] :
       std::vector<std::tuple<std::string, unsigned int, bool>>{
         {"Gauss 1", 1, false},
         {"segment-based 1", 1, false},
         {"Gauss 2", 1, true},
         {"Newton-Cotes 1", 1, true},
         {"Gauss 2", 2, false},
         {"segment-based 2", 2, false},
         {"Gauss 3", 2, true},
         {"nodal", 2, true},
         {"Simpson 1", 2, true}})
    {
      const IntegrationScheme scheme = IntegrationScheme::parse(text);
      bool                    taken  = true;
      try
        {
          contact_quadrature(scheme, multiplier_degree, multiplier_degree);
        }
      catch (const std::exception &e)
        {
          taken = false;
          out << "refused with a multiplier of degree " << multiplier_degree
              << ": " << one_line_message(e) << std::endl;
        }
      check(taken == accepted,
            text + (accepted ? " must be accepted" : " must be refused") +
              " with a multiplier of degree " +
              std::to_string(multiplier_degree));
    }

  for (unsigned int n = 2; n <= 10; ++n)
    {
      const auto q = show("Gauss " + std::to_string(n), 1);
      check(q.size() == n && exactness(q) == 2 * n - 1,
            "Gauss n is exact to degree 2n - 1");
    }
  for (unsigned int n = 1; n <= 4; ++n)
    {
      const auto q = show("Simpson " + std::to_string(n), 1);
      check(q.size() == 2 * n + 1 && exactness(q) == 3,
            "composite Simpson: 2n + 1 points, exact to degree 3");
    }
  for (const unsigned int n : {1u, 2u, 4u, 6u})
    {
      const auto q = show("Newton-Cotes " + std::to_string(n), 1);
      check(q.size() == n + 1, "closed Newton-Cotes: n + 1 points");
    }

  // The rule must integrate the surface's shape functions exactly (the
  // contact patch test: a uniform pressure transmitted exactly): on
  // surfaces of degree 1 to 4, every scheme's declared exactness is the
  // measured one, and the rules below the degree are refused with the
  // smallest that fit (a quartic slave with 'segment-based 2' missed the
  // patch test by 3.4 %).
  for (unsigned int degree = 1; degree <= 4; ++degree)
    for (const std::string text : {"nodal",
                                   "Gauss 2",
                                   "Gauss 3",
                                   "segment-based 2",
                                   "segment-based 3",
                                   "Simpson 1",
                                   "Simpson 3",
                                   "Newton-Cotes 1",
                                   "Newton-Cotes 2",
                                   "Newton-Cotes 4",
                                   "Newton-Cotes 6"})
      {
        const IntegrationScheme scheme   = IntegrationScheme::parse(text);
        const unsigned int      declared = exactness_degree(scheme, degree);
        try
          {
            const Quadrature<1> q = contact_quadrature(scheme, degree, 1);
            check(declared >= degree,
                  text + " must be refused on degree " +
                    std::to_string(degree));
            // Segment-based: the declared exactness is that of each piece.
            check(exactness(q) == declared,
                  text + " on degree " + std::to_string(degree) +
                    ": declared exact to " + std::to_string(declared) +
                    ", measured " + std::to_string(exactness(q)));
          }
        catch (const std::exception &e)
          {
            check(declared < degree,
                  text + " must be accepted on degree " +
                    std::to_string(degree) + ": " + e.what());
            if (degree >= 3)
              out << "refused on Q" << degree << ": " << one_line_message(e)
                  << std::endl;
          }
      }

  // Names that are refused, with the reason.
  for (const std::string bad : {"Gauss",
                                "Gauss 0",
                                "Gauss 21",
                                "Lobatto 3",
                                "Newton-Cotes 3",
                                "Gauss 2 3",
                                "nodal 3",
                                "nodal junk",
                                "segment-based x"})
    {
      try
        {
          IntegrationScheme::parse(bad);
          check(false, "'" + bad + "' must be refused");
        }
      catch (const std::exception &e)
        {
          out << "refused: " << e.what() << std::endl;
        }
    }

  // 'segment-based' alone: the points are chosen once the elements are
  // known (ContactParameters::choose_schemes()).
  const IntegrationScheme automatic = IntegrationScheme::parse("segment-based");
  check(automatic.cuts_at_master_kinks() && automatic.n_points == 0,
        "'segment-based' alone waits for its number of points");
}
