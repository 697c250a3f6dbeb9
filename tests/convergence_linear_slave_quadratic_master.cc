// Mesh convergence of the nodal scheme with a linear slave facing a
// quadratic master, both ways round (Q1 outer slave / Q2 inner master as
// modelisation E, Q2 outer master / Q1 inner slave as F): small strain,
// p = 1e7 Pa, no rotation, curved rings (mapping degree 2), 40, 80 and 160
// elements around (refined radially in proportion), as a one-element
// sector. The nodal rule must see the master's mid-side nodes: with the
// slave vertices alone it was first order and 10 % off at 40 around. The
// error at A must fall at order 1.8 or more between 80 and 160 around, and
// on these facing meshes the nodal result is the mortar result (Gauss 3).
#include <ring_contact/problem/contact_problem.h>

#include "run_problem.h"

#include <cmath>
#include <iomanip>

using namespace RingContact;
using RingContactTests::check;

namespace
{
  double
  pressure_error(const std::string &mix,
                 const std::string &scheme,
                 const unsigned int around)
  {
    const bool         outer_slave = mix == "Q1 outer slave, Q2 inner master";
    std::ostringstream prm;
    prm << "subsection Mesh\n set Elements around = " << around
        << "\n set Radial elements outer ring = " << 3 * around / 40
        << "\n set Radial elements inner ring = " << 3 * around / 40
        << "\n set Sector elements = 1\nend\n"
        << "subsection Materials\n set Material law = linear elasticity\nend\n"
        << "subsection Finite elements\n"
        << " set Displacement degree outer ring = " << (outer_slave ? 1 : 2)
        << "\n set Displacement degree inner ring = " << (outer_slave ? 2 : 1)
        << "\n set Multiplier degree = 1\n set Mapping degree = 2\nend\n"
        << "subsection Contact\n set Slave boundary = "
        << (outer_slave ? 300 : 400)
        << "\n set Master boundary = " << (outer_slave ? 400 : 300)
        << "\n set Integration schemes = " << scheme << "\nend\n"
        << "subsection Load program\n set Program = ramp\n"
        << " set Ramp steps = 1\n set Reference pressure = 1e8\nend\n";
    return RingContactTests::run_problem("convergence_mixed", prm.str())
      .back()
      .value("relative_error");
  }
} // namespace

int
main()
{
  auto &out = RingContactTests::deallog_file;
  for (const std::string mix :
       {"Q1 outer slave, Q2 inner master", "Q2 outer master, Q1 inner slave"})
    {
      std::vector<double> errors;
      for (const unsigned int around : {40u, 80u, 160u})
        {
          errors.push_back(std::abs(pressure_error(mix, "nodal", around)));
          out << mix << ", nodal, " << std::setw(3) << around
              << " around: relative error " << std::scientific
              << std::setprecision(3) << errors.back() << std::defaultfloat;
          if (errors.size() > 1)
            out << ", observed order " << std::fixed << std::setprecision(2)
                << std::log(errors[errors.size() - 2] / errors.back()) /
                     std::log(2.0)
                << std::defaultfloat;
          out << std::endl;
        }
      check(errors[0] < 0.01, mix + ": below 1 % at 40 around");
      check(std::log(errors[1] / errors[2]) / std::log(2.0) >= 1.8,
            mix + ": at least order 1.8 between 80 and 160 around");

      const double gauss = std::abs(pressure_error(mix, "Gauss 3", 40));
      check(std::abs(gauss - errors[0]) < 1e-8,
            mix + ": nodal is the mortar (Gauss 3) result on facing meshes");
      out << mix << ", nodal and Gauss 3 agree at 40 around" << std::endl;
    }
}
