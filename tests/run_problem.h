// Shared by the unit tests that run the solver: write a parameter file,
// run its first integration scheme, and return the history (the test stops
// if a step cannot be solved).
#ifndef ring_contact_run_problem_h
#define ring_contact_run_problem_h

#include <ring_contact/config.h>
#include <ring_contact/problem/contact_problem.h>

#include "tests.h"

namespace RingContactTests
{
  /// A parameter file that includes modelisation `letter`'s shipped file,
  /// adds `extra` and switches its checks off.
  inline std::string
  modelisation(const char letter, const std::string &extra)
  {
    return std::string("include ") + RING_CONTACT_SOURCE_DIR + "/prm/ssnp152" +
           letter + ".prm\n" + extra +
           "\nsubsection Checks\n set Steps = none\nend\n";
  }

  /// Run the first scheme of the parameters in `prm_text` (written to
  /// `name`.prm), quietly.
  inline std::vector<RingContact::HistoryRow>
  run_problem(const std::string &name, const std::string &prm_text)
  {
    {
      std::ofstream prm(name + ".prm");
      prm << prm_text
          << "\nsubsection Output\n set VTU interval = 0\n"
             " set Print timing = false\n set Write history = false\nend\n"
             "subsection Newton\n set Verbose = false\nend\n";
    }
    RingContact::Parameters parameters;
    parameters.read(name + ".prm");
    std::ostringstream                            log;
    RingContact::ContactProblem<RingContact::dim> problem(
      parameters, parameters.contact.schemes.front(), log);
    check(problem.run(), name + ": every step is solved");
    return problem.history();
  }
} // namespace RingContactTests

#endif
