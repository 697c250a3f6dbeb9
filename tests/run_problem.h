// Shared by the unit tests that run the solver: write a parameter file,
// run its first integration scheme, and return the history (the test stops
// if a step cannot be solved).
#ifndef ring_contact_run_problem_h
#define ring_contact_run_problem_h

#include <ring_contact/ring_contact_problem.h>

#include "tests.h"

namespace RingContactTests
{
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
    std::ostringstream              log;
    RingContact::RingContactProblem problem(parameters,
                                            parameters.contact.schemes.front(),
                                            log);
    check(problem.run(), name + ": every step is solved");
    return problem.history();
  }
} // namespace RingContactTests

#endif
