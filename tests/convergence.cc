// Mesh convergence with small-strain kinematics: the error of the contact
// pressure at node A against the analytic value must fall when the mesh is
// refined (40, 80 and 160 elements around, the rings refined radially in
// proportion), for nodal and Gauss integration; the observed order is
// printed.
#include <ring_contact/problem/contact_problem.h>

#include "run_problem.h"

#include <cmath>
#include <iomanip>

using namespace RingContact;
using RingContactTests::check;

int
main()
{
  auto &out = RingContactTests::deallog_file;
  for (const std::string scheme : {"nodal", "Gauss 2"})
    {
      std::vector<double> errors;
      for (const unsigned int around : {40u, 80u, 160u})
        {
          std::ostringstream prm;
          prm << "subsection Mesh\n set Elements around = " << around
              << "\n set Radial elements outer ring = " << 3 * around / 40
              << "\n set Radial elements inner ring = " << 3 * around / 40
              << "\nend\nsubsection Materials\n"
              << " set Material law = linear elasticity\nend\n"
              << "subsection Contact\n set Integration schemes = " << scheme
              << "\nend\nsubsection Load program\n set Ramp steps = 1\n"
              << "end\n";
          const auto history =
            RingContactTests::run_problem("convergence", prm.str());
          errors.push_back(std::abs(history.back().value("relative_error")));
          out << scheme << ", " << std::setw(3) << around
              << " elements around: relative error " << std::scientific
              << std::setprecision(3) << errors.back() << std::defaultfloat;
          if (errors.size() > 1)
            out << ", observed order " << std::fixed << std::setprecision(2)
                << std::log(errors[errors.size() - 2] / errors.back()) /
                     std::log(2.0)
                << std::defaultfloat;
          out << std::endl;
        }
      check(errors[1] < errors[0] && errors[2] < errors[1],
            scheme + ": the error falls with refinement");
      check(std::log(errors[1] / errors[2]) / std::log(2.0) > 1.5,
            scheme + ": at least order 1.5 between 80 and 160 around");
    }
}
