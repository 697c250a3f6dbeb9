// Cyclic symmetry with every sector of the 12-element rings, k = 1 ... 12:
// the wide sectors (2c + 1) k > Ne, whose rotated master copies would go
// further round than the circle, get copies trimmed to cover it once, and
// k = 12 is the whole circle cut open. Every sector must give the whole
// rings' pressure at node A, extreme pressures and L2 error at every step
// (asserted: 1e-8 relative), for a short ramp and a short rotation (half an
// element) with the nodal, Gauss and segment-based schemes.
#include <ring_contact/config.h>
#include <ring_contact/problem/contact_problem.h>

#include "run_problem.h"

#include <cmath>
#include <iomanip>
#include <iostream>

using namespace RingContact;
using RingContactTests::check;
using RingContactTests::modelisation;

namespace
{
  void
  compare_every_sector(const std::string &name, const std::string &prm_text)
  {
    const std::string mesh = "\nsubsection Mesh\n set Elements around = 12\n"
                             " set Radial elements outer ring = 1\n"
                             " set Radial elements inner ring = 1\n"
                             " set Sector elements = ";
    const auto        whole =
      RingContactTests::run_problem("whole", prm_text + mesh + "0\nend\n");
    for (unsigned int k = 1; k <= 12; ++k)
      {
        const auto sector = RingContactTests::run_problem(
          "sector", prm_text + mesh + std::to_string(k) + "\nend\n");
        check(sector.size() == whole.size(), name + ": same number of steps");
        double difference = 0, difference_A = 0;
        for (unsigned int i = 0; i < whole.size(); ++i)
          {
            const double scale = std::abs(whole[i].value("analytic"));
            difference_A =
              std::max(difference_A,
                       std::abs(whole[i].value("pressure_A") - sector[i].value("pressure_A")) /
                         std::abs(whole[i].value("pressure_A")));
            for (const auto &[a, b] :
                 {std::make_pair(whole[i].value("pressure_min"), sector[i].value("pressure_min")),
                  std::make_pair(whole[i].value("pressure_max"),
                                 sector[i].value("pressure_max"))})
              difference = std::max(difference, std::abs(a - b) / scale);
            difference = std::max(difference,
                                  std::abs(whole[i].value("l2_relative_error") -
                                           sector[i].value("l2_relative_error")));
          }
        // The figures themselves are round-off: on the console only.
        std::cout << name << ", k = " << std::setw(2) << k << ": pressure at A "
                  << std::scientific << std::setprecision(2) << difference_A
                  << ", extremes and L2 error " << difference
                  << std::defaultfloat << std::endl;
        RingContactTests::deallog_file
          << name << ", sector of " << k << " element" << (k > 1 ? "s" : "")
          << ": " << whole.size() << " steps, "
          << (std::max(difference, difference_A) < 1e-8 ? "same as" :
                                                          "DIFFERENT FROM")
          << " the whole rings" << std::endl;
        check(difference_A < 1e-8,
              name + ", k = " + std::to_string(k) +
                ": the pressure at A is the whole rings'");
        check(difference < 1e-8,
              name + ", k = " + std::to_string(k) +
                ": the extreme pressures and the L2 error are the whole "
                "rings'");
      }
  }
} // namespace

int
main()
{
  compare_every_sector("A, ramp, nodal",
                       modelisation('a',
                                    "subsection Load program\n"
                                    " set Ramp steps = 2\nend\n"
                                    "subsection Contact\n"
                                    " set Integration schemes = nodal\nend"));
  compare_every_sector(
    "C, rotation, Gauss 2, smoothed normals",
    modelisation(
      'c',
      "subsection Load program\n set Rotation steps = 2\n"
      " set Rotation in elements = 0.5\nend\n"
      "subsection Contact\n set Integration schemes = Gauss 2\nend"));
  compare_every_sector(
    "C, rotation, segment-based 2, facet normals",
    modelisation('c',
                 "subsection Load program\n set Rotation steps = 2\n"
                 " set Rotation in elements = 0.5\nend\n"
                 "subsection Contact\n set Integration schemes = "
                 "segment-based 2\n set Smooth master normals = false\nend"));
}
