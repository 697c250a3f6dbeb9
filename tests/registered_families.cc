// The contact integration schemes and the refinement estimators are families
// registered one file per member (base/registry.h): this test lists what
// registered, and checks what the parsing, the documentation and the
// composition of the indicators rely on:
// - every scheme family parses by its word in any case, with each number it
//   admits, and names itself back as it was written; a family that takes no
//   number parses alone; one whose number may be left out parses alone too;
// - exactly one family cuts the slave segments at the master's kinks (the
//   mortar scheme the diagnostics compare the point-wise ones with);
// - every family and every estimator is said in its entry's documentation;
// - every estimator starts from a registered one, down to one that starts
//   from nothing (no cycle).
#include <ring_contact/contact/contact_quadrature.h>
#include <ring_contact/problem/refinement_estimator.h>

#include "tests.h"

#include <algorithm>
#include <cctype>

using namespace RingContact;
using RingContactTests::check;

int
main()
{
  auto &out = RingContactTests::deallog_file;

  const std::string schemes_documentation = integration_schemes_documentation();
  unsigned int      cutting               = 0;
  for (const auto &family : IntegrationSchemeFamilies::members())
    {
      // The admitted numbers, as a range where they are one.
      const auto &points = family.admitted_points;
      std::string admitted;
      if (points.empty())
        admitted = "no number";
      else if (points.back() - points.front() + 1 == points.size())
        admitted = "n from " + std::to_string(points.front()) + " to " +
                   std::to_string(points.back());
      else
        for (const unsigned int n : points)
          admitted += (admitted.empty() ? "n in " : ", ") + std::to_string(n);
      out << "scheme family '" << family.name << "': " << admitted
          << (family.default_points ? ", or none" : "")
          << (family.cuts_at_master_kinks ? ", cuts at the master's kinks" :
                                            ", point-wise")
          << std::endl;
      cutting += family.cuts_at_master_kinks ? 1 : 0;
      check(schemes_documentation.find(family.label() + ": " +
                                       family.documentation) !=
              std::string::npos,
            family.name + " is said in the entry's documentation");
      std::string upper = family.name;
      for (char &c : upper)
        c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
      if (family.admitted_points.empty() || family.default_points)
        check(IntegrationScheme::parse(upper).family == &family,
              family.name + " parses alone, in any case");
      for (const unsigned int n : family.admitted_points)
        {
          const std::string       text = family.name + " " + std::to_string(n);
          const IntegrationScheme scheme = IntegrationScheme::parse(text);
          check(scheme.family == &family && scheme.n_points == n &&
                  scheme.name() == text,
                text + " parses and names itself back");
        }
    }
  check(cutting == 1, "one family cuts at the master's kinks");

  const std::string estimators_documentation =
    refinement_estimators_documentation();
  for (const auto &estimator : RefinementEstimators::members())
    {
      out << "estimator '" << estimator.name << "'";
      // Down the chain: each step registered, and no estimator twice.
      std::vector<std::string> chain = {estimator.name};
      while (!RefinementEstimators::get(chain.back()).starts_from.empty())
        {
          const std::string base =
            RefinementEstimators::get(chain.back()).starts_from;
          check(RefinementEstimators::find(base) != nullptr,
                "'" + base + "' is registered");
          check(std::find(chain.begin(), chain.end(), base) == chain.end(),
                "no cycle through '" + base + "'");
          chain.push_back(base);
          out << " starts from '" << base << "'";
        }
      out << std::endl;
      check(estimators_documentation.find(estimator.name + ": " +
                                          estimator.documentation) !=
              std::string::npos,
            estimator.name + " is said in the entry's documentation");
    }
}
