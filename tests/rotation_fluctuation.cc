// The whole rotation of modelisation C (p = 1e7 Pa, the inner ring turned
// through one element in 100 steps): the fluctuation of the pressure at node
// A (largest minus smallest relative error over the rotation) per
// integration scheme. Segment-based (mortar) integration must stay within
// 0.1 percentage points on the faceted seed mesh, and within 0.02 with
// curved geometry and quadratic elements (isoparametric: the rigid rotation
// is in the discrete space).
#include <ring_contact/config.h>
#include <ring_contact/problem/contact_problem.h>

#include "run_problem.h"

#include <iomanip>

using namespace RingContact;
using RingContactTests::check;

namespace
{
  double
  fluctuation(const std::string &scheme,
              const bool         smooth,
              const unsigned int degree,
              const unsigned int mapping_degree)
  {
    std::ostringstream prm;
    prm << "include " << RING_CONTACT_SOURCE_DIR << "/prm/ssnp152c.prm\n"
        << "subsection Contact\n set Integration schemes = " << scheme
        << "\n set Smooth master normals = " << (smooth ? "true" : "false")
        << "\nend\nsubsection Finite elements\n"
        << " set Displacement degree outer ring = " << degree
        << "\n set Displacement degree inner ring = " << degree
        << "\n set Mapping degree = " << mapping_degree << "\nend\n";
    const auto history  = RingContactTests::run_problem("rotation", prm.str());
    double     smallest = 1, largest = -1;
    for (const auto &row : history)
      {
        smallest = std::min(smallest, row.value("relative_error"));
        largest  = std::max(largest, row.value("relative_error"));
      }
    const double points = 100 * (largest - smallest);
    RingContactTests::deallog_file
      << std::left << std::setw(16) << scheme
      << (smooth ? " smoothed normals" : " faceted normals ") << ", Q" << degree
      << ", mapping degree " << mapping_degree << ": fluctuation below "
      << (points < 0.02 ? "0.02" :
          points < 0.1  ? "0.1" :
                          "1 or more")
      << " percentage points" << std::endl;
    return points;
  }
} // namespace

int
main()
{
  check(fluctuation("segment-based 2", false, 1, 1) < 0.1,
        "segment-based, faceted: below 0.1 percentage points");
  check(fluctuation("segment-based 2", true, 1, 1) < 0.1,
        "segment-based, smoothed normals: below 0.1 percentage points");
  check(fluctuation("segment-based 3", false, 2, 2) < 0.02,
        "segment-based, curved Q2: below 0.02 percentage points");
}
