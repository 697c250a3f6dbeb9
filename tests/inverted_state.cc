// A state with inverted elements is never accepted: small strain at
// p = 1e10 Pa on E = 1e9 Pa turns the inner ring inside out (det F < 0 at
// the bulk quadrature points); the step is cut, then the run stops and says
// why, with no converged step.
#include <ring_contact/config.h>
#include <ring_contact/problem/contact_problem.h>

#include "tests.h"

using namespace RingContact;
using RingContactTests::check;

int
main()
{
  {
    std::ofstream prm("inverted.prm");
    prm << "include " << RING_CONTACT_SOURCE_DIR << "/prm/ssnp152a.prm\n"
        << "subsection Materials\n set Kinematics = small strain\nend\n"
        << "subsection Contact\n set Integration schemes = nodal\nend\n"
        << "subsection Load program\n set Reference pressure = 1e10\n"
        << " set Ramp steps = 1\n set Time step = 1.1\nend\n"
        << "subsection Newton\n set Verbose = false\n"
        << " set Maximum step cuts = 2\nend\n"
        << "subsection Output\n set VTU interval = 0\n"
        << " set Print timing = false\n set Write history = false\nend\n";
  }
  Parameters parameters;
  parameters.read("inverted.prm");
  std::ostringstream log;
  ContactProblem problem(parameters,
                             parameters.contact.schemes.front(),
                             log);
  check(!problem.run(), "the run stops");
  check(problem.history().empty(), "no step is accepted");
  check(log.str().find("Newton did not converge after 2 step cuts "
                       "(inverted elements: det F = ") != std::string::npos,
        "the message names the inverted elements: " + log.str());
  RingContactTests::deallog_file
    << "inverted state rejected: the run stops after 2 step cuts with the "
       "message 'inverted elements: det F = ... <= 0 at ... quadrature points'"
    << std::endl;
}
