// Surfaces that interpenetrate before any load are named in the log. H's
// rings with the outer ring Q1 and Mapping degree = 0: the outer (master)
// ring is faceted, the inner (slave) ring curved (Q2 geometry), so the slave
// starts inside the master by the chord's sagitta s = R2 (1 - cos(pi / 40))
// at the middle of each master segment. The slave's multiplier is linear
// (vertex values), and the gap along a segment is parabolic, -s 4 t (1 - t),
// so the mean gap at a node, int Phi_k g / int Phi_k over its two segments,
// is -2/3 s: the warning must say 2/3 s to 1 %. The shipped H (both rings
// curved) and A (both faceted, the meshes matching) start touching: no
// warning. (The Hertz problem's cylinder dips into the block on purpose and
// nothing but the contact holds it: no warning there either, asserted by
// the log of the test hertz.)
#include <ring_contact/config.h>
#include <ring_contact/problem/contact_problem.h>

#include "tests.h"

#include <cmath>

using namespace RingContact;
using RingContactTests::check;
using RingContactTests::deallog_file;

namespace
{
  // The log of the first step of modelisation `letter` with `extra`.
  std::string
  first_step_log(const char letter, const std::string &extra)
  {
    {
      std::ofstream prm("case.prm");
      prm << "include " << RING_CONTACT_SOURCE_DIR << "/prm/ssnp152" << letter
          << ".prm\n"
          << extra << "subsection Contact\n set Integration schemes = nodal\n"
          << "end\nsubsection Load program\n set Ramp steps = 1\nend\n"
          << "subsection Newton\n set Verbose = false\nend\n"
          << "subsection Checks\n set Steps = none\nend\n"
          << "subsection Output\n set VTU interval = 0\n"
          << " set Print timing = false\n set Write history = false\nend\n";
    }
    Parameters parameters;
    parameters.read("case.prm");
    std::ostringstream  log;
    ContactProblem<dim> problem(parameters,
                                parameters.contact.schemes.front(),
                                log);
    problem.run();
    return log.str();
  }

  const std::string warning =
    "Warning: the contact surfaces interpenetrate before any load, by up to ";
} // namespace

int
main()
{
  const std::string mixed =
    first_step_log('h',
                   "subsection Finite elements\n"
                   " set Displacement degree outer ring = 1\n"
                   " set Mapping degree = 0\nend\n");
  const auto at = mixed.find(warning);
  check(at != std::string::npos,
        "a curved slave against a faceted master is named; the log:\n" + mixed);
  const double depth    = std::stod(mixed.substr(at + warning.size()));
  const double sagitta  = 0.6 * (1 - std::cos(M_PI / 40));
  const double expected = 2.0 / 3.0 * sagitta;
  check(std::abs(depth - expected) < 0.01 * expected,
        "the depth is 2/3 of the sagitta (" + std::to_string(depth) +
          " against " + std::to_string(expected) + ")");
  deallog_file << "H, outer ring Q1, Mapping degree = 0: warned, depth "
               << depth << " = 2/3 of the sagitta to 1 %" << std::endl;

  for (const char letter : {'h', 'a'})
    {
      const std::string log = first_step_log(letter, "");
      check(log.find(warning) == std::string::npos,
            std::string("no warning for the shipped ") + letter);
      deallog_file << "shipped " << letter << ": no warning" << std::endl;
    }
}
