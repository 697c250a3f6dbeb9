// A standing probe for surfaces that do not match: the contact patch test
// (the two blocks of prm/two_blocks.prm pressed by a uniform pressure p,
// whose exact contact pressure is p at every node) on random pairs of
// meshes, either block the slave, linear and quadratic elements, every
// scheme. Seeded, so that every run poses the same cases. For each case:
// - with no scheme named (the default, segment-based at the degree the
//   elements need) the pressure is p at every node to 1e-8: the mortar
//   scheme passes the patch test on any pair of meshes;
// - a point-wise scheme (nodal, Gauss 2 and 3, Simpson 1, Newton-Cotes 2)
//   whose pressure departs from p by more than 1e-6 at some node was named
//   before the first step ("does not pass the contact patch test"), and one
//   that was named departs from p: the warning comes exactly where the
//   scheme fails the test, whichever surface is the finer;
// - on matching meshes no point-wise scheme is named (and each passes).
#include <ring_contact/config.h>
#include <ring_contact/problem/contact_problem.h>

#include "tests.h"

#include <cmath>
#include <iomanip>
#include <random>

using namespace RingContact;
using RingContactTests::check;
using RingContactTests::deallog_file;

namespace
{
  std::mt19937_64 generator(20261206);

  unsigned int
  integer(const unsigned int a, const unsigned int b)
  {
    return std::uniform_int_distribution<unsigned int>(a, b)(generator);
  }

  struct Outcome
  {
    bool   warned;
    double swing; // largest |pressure / p - 1| over the slave nodes
  };

  // The patch test with `lower` and `upper` segments along the interface,
  // displacement degree `degree`, the upper block's base the slave unless
  // `swapped`, and `scheme` (empty: the default).
  Outcome
  run(const unsigned int lower,
      const unsigned int upper,
      const unsigned int degree,
      const bool         swapped,
      const std::string &scheme)
  {
    const double p = 1e6; // prm/two_blocks.prm's pressure
    {
      std::ofstream prm("case.prm");
      prm << "include " RING_CONTACT_SOURCE_DIR "/prm/two_blocks.prm\n"
          << "subsection Mesh\n set Mesh file = " RING_CONTACT_SOURCE_DIR
             "/meshes/two_blocks.geo\n set Geo parameters = nl = "
          << lower << ", nu = " << upper << "\nend\n";
      for (const unsigned int body : {1, 2})
        prm << "subsection Body " << body
            << "\n set Displacement degree = " << degree << "\nend\n";
      prm << "subsection Contact\n set Slave boundary = " << (swapped ? 20 : 10)
          << "\n set Master boundary = " << (swapped ? 10 : 20)
          << "\n set Integration schemes = "
          << (scheme.empty() ? "automatic" : scheme) << "\nend\n";
      for (unsigned int k = 1; k <= 4; ++k)
        prm << "subsection Check " << k << "\n set Steps = none\nend\n";
      prm << "subsection Load program\n set Time points = 1\nend\n"
          << "subsection Newton\n set Verbose = false\nend\n"
          << "subsection Output\n set VTU interval = 0\n"
          << " set Print timing = false\n set Write history = false\nend\n";
    }
    Parameters parameters;
    parameters.read("case.prm");
    std::ostringstream  log;
    ContactProblem<dim> problem(parameters,
                                parameters.contact.schemes.front(),
                                log);
    check(problem.run(), "the patch test is solved");
    const auto &row = problem.history().back();
    return {log.str().find("does not pass the contact patch test") !=
              std::string::npos,
            std::max(std::abs(row.value("pressure_min") / p - 1),
                     std::abs(row.value("pressure_max") / p - 1))};
  }
} // namespace

int
main()
{
  auto                          &out       = deallog_file;
  const std::vector<std::string> pointwise = {
    "nodal", "Gauss 2", "Gauss 3", "Simpson 1", "Newton-Cotes 2"};
  unsigned int cases = 0, warned = 0, silent_exact = 0;
  double       default_swing = 0, largest_pointwise_swing = 0;
  for (unsigned int k = 0; k < 14; ++k)
    {
      // Two fixed cases first: quadratic matching meshes, and a slave that
      // halves every master segment (whose nodes include the master's: the
      // point-wise schemes pass there). Then every fourth pair matches, the
      // others at random, either finer.
      const bool         fixed   = k < 2;
      const unsigned int lower   = fixed ? 6 : integer(2, 16);
      const unsigned int upper   = k == 1              ? 12 :
                                   fixed || k % 4 == 0 ? lower :
                                                         integer(2, 16);
      const unsigned int degree  = k == 0 ? 2 : k == 1 ? 1 : integer(1, 2);
      const bool         swapped = !fixed && integer(0, 1) == 1;
      out << "nl = " << lower << ", nu = " << upper << ", Q" << degree
          << ", slave " << (swapped ? "the lower block" : "the upper block")
          << ":";
      // The default: exact.
      const Outcome exact = run(lower, upper, degree, swapped, "");
      check(exact.swing < 1e-8, "the default scheme passes the patch test");
      check(!exact.warned, "the default scheme is never named");
      default_swing = std::max(default_swing, exact.swing);
      for (const std::string &scheme : pointwise)
        {
          const Outcome o = run(lower, upper, degree, swapped, scheme);
          ++cases;
          largest_pointwise_swing = std::max(largest_pointwise_swing, o.swing);
          if (o.swing > 1e-6)
            check(o.warned,
                  scheme + " fails the patch test here and must be named");
          if (o.warned)
            {
              ++warned;
              check(o.swing > 1e-6, scheme + " is named but passes");
            }
          else
            ++silent_exact;
          if (lower == upper)
            check(!o.warned, scheme + " is named on matching meshes");
          out << ' ' << scheme << (o.warned ? " named" : " silent");
        }
      out << std::endl;
    }
  out << cases << " point-wise cases: " << warned << " named, " << silent_exact
      << " silent and exact; the default within 1e-8, "
      << "the point-wise schemes' largest swing "
      << (largest_pointwise_swing > 0.01 ? "above" : "below") << " 1 %"
      << std::endl;
}
