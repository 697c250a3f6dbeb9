// Newton with default settings on steel (outer) against aluminium (inner),
// plane strain, small strain, the 21-step ramp at p = 1e2 ... 1e4 Pa: every
// step is linear with a fixed active set, so it must converge in one or two
// iterations (the round-off of the contact rows, eps c w R, is 1e-9 of the
// reactions here: a fixed tolerance of 1e-10 never converged). The same with
// the logarithmic strain, whose stress must keep its digits at strains of
// 1e-9 (written with G - 2 F / kappa, its deviatoric part had a round-off of
// 1e-7 of the stress, and Newton stalled at the first step).
#include <ring_contact/config.h>
#include <ring_contact/problem/contact_problem.h>

#include "run_problem.h"

#include <iomanip>

using namespace RingContact;
using RingContactTests::check;

int
main()
{
  for (const std::string kinematics : {"small strain", "logarithmic strain"})
    for (const std::string scheme : {"nodal", "Gauss 3", "segment-based 2"})
      {
        std::ostringstream prm;
        prm << "include " << RING_CONTACT_SOURCE_DIR << "/prm/ssnp152b.prm\n"
            << "subsection Materials\n"
            << " set Young's modulus outer ring = 2e11\n"
            << " set Poisson's ratio outer ring = 0.3\n"
            << " set Young's modulus inner ring = 7e10\n"
            << " set Poisson's ratio inner ring = 0.33\n"
            << " set Material law = " << kinematics << "\nend\n"
            << "subsection Contact\n set Integration schemes = " << scheme
            << "\nend\n"
            << "subsection Load program\n set Reference pressure = 1e3\nend\n";
        const auto history =
          RingContactTests::run_problem("steel_aluminium", prm.str());
        check(history.size() == 21, kinematics + ", " + scheme + ": 21 steps");
        unsigned int most = 0;
        for (const auto &row : history)
          most = std::max(most, row.newton_iterations);
        check(most <= 2,
              kinematics + ", " + scheme +
                ": at most 2 Newton iterations per step");
        RingContactTests::deallog_file
          << (kinematics == "small strain" ? "" : kinematics + ", ")
          << std::left << std::setw(16) << scheme
          << " at most 2 iterations per step; p_A error at p = 1e4: "
          << std::fixed << std::setprecision(3)
          << 100 * history.back().value("relative_error") << " %" << std::endl;
      }
}
