// The whole Hertz load (prm/hertz.prm: a cylinder on a block, a = R / 10) in
// one step from bodies that touch, on a fine mesh (h = 0.005, 41 of 121
// contact nodes closed at the end), with every scheme, without friction: the
// contact zone grows from the touching point to its width within the step.
// The plain primal-dual active-set method moved the zone's edge by a few
// nodes per iteration (a line search of steps 1/16 to 1/2 while it grew,
// then one or two nodes released per iteration); a steel cylinder on
// aluminium so took 12 iterations at h = 0.005, 28 to 33 and a step cut at
// h = 0.0025. With the edges extrapolated
// (ContactInterface::extrapolate_zone_edges()) and the whole update taken
// while they move: 3 to 5 iterations here, no cut, from an exact touch (d0
// = 0) and from the shipped overlap (d0 = 2e-4) alike; the test allows 6.
// And the answer is Hertz's (the checks of prm/hertz.prm: p0 within 1.5 %,
// a within 5 %, the reaction equal to the load).
#include <ring_contact/config.h>
#include <ring_contact/problem/contact_problem.h>

#include "tests.h"

using namespace RingContact;
using RingContactTests::check;

int
main()
{
  auto &out = RingContactTests::deallog_file;
  for (const std::string touch : {"d0 = 0", "d0 = 2e-4"})
    for (const std::string scheme : {"nodal", "Gauss 2", "segment-based 2"})
      {
        {
          std::ofstream prm("one_step.prm");
          prm << "include " RING_CONTACT_SOURCE_DIR "/prm/hertz.prm\n"
              << "subsection Mesh\n set Mesh file = " RING_CONTACT_SOURCE_DIR
                 "/meshes/hertz.geo\n set Geo parameters = h = 0.005, "
              << touch << "\nend\n"
              << "subsection Contact\n set Integration schemes = " << scheme
              << "\nend\n"
              << "subsection Load program\n set Number of steps = 1\nend\n"
              << "subsection Newton\n set Verbose = false\nend\n"
              << "subsection Output\n set VTU interval = 0\n"
                 " set Print timing = false\n set Write history = false\n"
                 "end\n";
        }
        Parameters parameters;
        parameters.read("one_step.prm");
        std::ostringstream log;
        ContactProblem     problem(parameters,
                               parameters.contact.schemes.front(),
                               log);
        check(problem.run(), scheme + ", " + touch + ": the step is solved");
        const auto &row = problem.history().back();
        out << touch << ", " << scheme << ": " << row.newton_iterations
            << " Newton iterations, " << row.step_cuts << " step cuts, "
            << row.active_nodes << " nodes closed" << std::endl;
        check(row.newton_iterations <= 6 && row.step_cuts == 0,
              scheme + ", " + touch + ": at most 6 iterations, no cut");
        // The errors of p0 and a, the equilibrium's round-off only as a
        // verdict (its digits are the machine's).
        for (const auto &verdict : problem.verdicts())
          {
            out << "  " << verdict.quantity << ": ";
            if (verdict.tolerance >= 1e-3)
              out << "error " << std::setprecision(2) << std::scientific
                  << verdict.error << std::defaultfloat << std::setprecision(6)
                  << " (tolerance " << verdict.tolerance << ")" << std::endl;
            else
              out << (verdict.pass ? "within " : "beyond ") << verdict.tolerance
                  << std::endl;
            check(verdict.pass,
                  scheme + ", " + touch + ": " + verdict.quantity);
          }
      }
}
