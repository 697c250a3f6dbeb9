// The VTU files read back with VTK's own reader (Debian's python3-vtk9),
// for linear and quadratic elements, faceted and curved: the rings and the
// slave surface of modelisation A (Q1) and H (Q2), two steps. Every cell's
// point ids in range, every point referenced, the number of cells, every
// data array one finite value per point, the files the .pvd lists exist;
// and the geometry VTK makes of the cells: the area of the rings and the
// length of the slave surface from VTK's triangulation of each cell (signed
// and absolute: a wrongly numbered Lagrange cell folds) against the exact
// values of the polygons that triangulation makes, to 1e-6.
#include "run_program.h"

#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>

using RingContactTests::check;

namespace
{
  constexpr double       R1 = 1.0, R2 = 0.6, R3 = 0.2;
  constexpr unsigned int around = 40, cells = 240; // 3 + 3 across

  void
  check_case(const std::string &name,
             const std::string &prm_name,
             const unsigned int mapping_degree,
             const bool         curved,
             const unsigned int subdivisions)
  {
    auto &out = RingContactTests::deallog_file;
    {
      std::ofstream prm(name + ".prm");
      prm << "include " RING_CONTACT_SOURCE_DIR "/prm/" << prm_name << "\n"
          << "subsection Finite elements\n set Mapping degree = "
          << mapping_degree << "\nend\n"
          << "subsection Contact\n set Integration schemes = nodal\nend\n"
          << "subsection Load program\n set Ramp steps = 2\nend\n"
          << "subsection Output\n set Directory = " << name
          << "\n set VTU interval = 1\n set Print timing = false\n"
             " set Print steps = false\nend\n"
             "subsection Newton\n set Verbose = false\nend\n";
    }
    const auto result = RingContactTests::run_program(name + ".prm");
    check(result.exit_code == 0, name + ": the run");

    // VTK's triangulation of a cell joins its points by straight lines:
    // the exact values are those of polygons with `sectors` sides, whose
    // vertices lie on the circles r = R1, R2, R3 (a curved cell's points are
    // on the polar manifold; a faceted cell's extra points on its chords).
    const double pi      = std::acos(-1.0);
    const double sectors = curved ? around * subdivisions : around;
    const double area =
      0.5 * sectors * std::sin(2 * pi / sectors) * (R1 * R1 - R3 * R3);
    const double       length = 2 * sectors * R2 * std::sin(pi / sectors);
    std::ostringstream options;
    options << std::setprecision(12) << "--rows 2 --all-listed "
            << "--vtu-every-step --bulk-cells " << cells << " --surface-cells "
            << around * subdivisions << " --bulk-area " << area
            << " --surface-length " << length << " --tolerance "
            << 1e-6; // points are stored in single precision
    std::string report;
    check(RingContactTests::check_results(name, options.str(), &report),
          name + ": the files read back whole:\n" + report);
    out << name << ":\n" << report;
  }
} // namespace

int
main()
{
  // Q1, faceted: linear quadrilaterals and segments.
  check_case("q1_faceted", "ssnp152a.prm", 1, false, 1);
  // Q1 on a quadratic mapping: Lagrange quadrilaterals, two segments a face.
  check_case("q1_curved", "ssnp152a.prm", 2, true, 2);
  // Q2, isoparametric (the shipped modelisation H).
  check_case("q2_curved", "ssnp152h.prm", 0, true, 2);
  // Q2 on straight cells.
  check_case("q2_faceted", "ssnp152h.prm", 1, false, 2);
}
