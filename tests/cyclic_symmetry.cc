// Cyclic symmetry: a sector of the rings (`Mesh/Sector elements` = k) gives
// the whole rings' solution. The rings, meshes and loads repeat every
// element, so the pressure at node A, the L2 error and the extreme pressures
// of every step must agree with the whole rings' to round-off (asserted:
// 1e-8 relative), for sectors of one and of three elements, through the
// rotation (past the sector's own width too), on faceted and curved
// geometry, with linear, quadratic and mixed elements, either ring slave,
// and after a global refinement.
#include <ring_contact/config.h>
#include <ring_contact/problem/contact_problem.h>

#include "run_problem.h"

#include <cmath>

using namespace RingContact;
using RingContactTests::check;
using RingContactTests::modelisation;

namespace
{
  void
  compare(const std::string &name, const std::string &prm_text)
  {
    const std::string whole_text =
      prm_text + "\nsubsection Mesh\n set Sector elements = 0\nend\n";
    const auto whole = RingContactTests::run_problem(name, whole_text);
    for (const unsigned int k : {1u, 3u})
      {
        const auto sector = RingContactTests::run_problem(
          name,
          prm_text + "\nsubsection Mesh\n set Sector elements = " +
            std::to_string(k) + "\nend\n");
        check(sector.size() == whole.size(), name + ": same number of steps");
        double difference = 0;
        for (unsigned int i = 0; i < whole.size(); ++i)
          {
            const double scale = std::abs(whole[i].value("analytic"));
            for (const auto &[a, b] :
                 {std::make_pair(whole[i].value("pressure_A"), sector[i].value("pressure_A")),
                  std::make_pair(whole[i].value("pressure_min"), sector[i].value("pressure_min")),
                  std::make_pair(whole[i].value("pressure_max"),
                                 sector[i].value("pressure_max"))})
              difference = std::max(difference, std::abs(a - b) / scale);
            difference = std::max(difference,
                                  std::abs(whole[i].value("l2_relative_error") -
                                           sector[i].value("l2_relative_error")));
          }
        RingContactTests::deallog_file
          << name << ", sector of " << k << " element" << (k > 1 ? "s" : "")
          << ": " << whole.size() << " steps, "
          << (difference < 1e-8 ? "same as" : "DIFFERENT FROM")
          << " the whole rings" << std::endl;
        check(difference < 1e-8,
              name + ": the sector gives the whole rings' solution");
      }
  }
} // namespace

int
main()
{
  compare("C, Q1 faceted, smoothed normals, nodal",
          modelisation('c',
                       "subsection Load program\n set Rotation steps = 10\n"
                       "end\nsubsection Contact\n set Integration schemes = "
                       "nodal\nend"));
  compare("C, facet normals, segment-based, two elements of rotation",
          modelisation('c',
                       "subsection Load program\n set Rotation steps = 10\n"
                       " set Rotation in elements = 2\nend\n"
                       "subsection Contact\n set Integration schemes = "
                       "segment-based 2\n set Smooth master normals = false\n"
                       "end"));
  compare("G, Q2 curved, Gauss 3",
          modelisation('g',
                       "subsection Load program\n set Rotation steps = 5\n"
                       "end\nsubsection Contact\n set Integration schemes = "
                       "Gauss 3\nend"));
  compare("E, outer ring slave (Q1), inner Q2, segment-based",
          modelisation('e',
                       "subsection Load program\n set Rotation steps = 5\n"
                       " set Rotation in elements = 0.5\nend\n"
                       "subsection Contact\n set Integration schemes = "
                       "segment-based 3\nend"));
  compare("A, ramp, Gauss 3, one global refinement",
          modelisation('a',
                       "subsection Load program\n set Ramp steps = 5\nend\n"
                       "subsection Mesh\n set Global refinements = 1\nend\n"
                       "subsection Contact\n set Integration schemes = "
                       "Gauss 3\nend"));
}
