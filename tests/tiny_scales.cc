// Scale-free in fact: the same problem at loads of 1e6 Pa and of 1e-200 Pa
// gives the same relative answer. Before, loads below about 1e-160 Pa gave
// zero displacement and pressure at Newton iteration 0: the squares of the
// residual underflowed, the imposed displacement of the rings was computed
// as a difference of positions X (1 + u / r) - X, in which u = 1e-210 m is
// lost, and the gap was the normal distance of the positions X + u, whose
// round-off (1e-17 m at Gauss points facing a node-matching surface) is a
// gap of its own, a load 1e193 times the one applied.
// - SSNP152 A on its ramp (three steps), small and finite strain, nodal,
//   Gauss 3 and segment-based 3: the pressure at node A over the analytic
//   one at p0 = 1e-200 equals that at p0 = 1e6 in small strain (a linear
//   problem) to 1e-9, and in finite strain equals the small-strain one
//   (the geometric nonlinearity of displacements of 1e-210 m is nil).
// - The patch test of two blocks (general problem) with p = 1e-200, and in
//   a consistent tiny system of units (E = 1e-150, p = 1e-156): the
//   pressure is p to 1e-10.
#include "run_problem.h"

#include <cmath>
#include <iomanip>

using RingContactTests::check;
using RingContactTests::run_problem;

namespace
{
  // The ratio of the pressure at node A to the analytic pressure at each of
  // the three steps.
  std::vector<double>
  ratios(const std::string &kinematics,
         const std::string &scheme,
         const double       p0)
  {
    std::ostringstream extra;
    extra << std::setprecision(17)
          << "subsection Materials\n set Material law = " << kinematics
          << "\nend\n"
             "subsection Load program\n set Ramp steps = 3\n"
             " set Reference pressure = "
          << p0
          << "\nend\n"
             "subsection Contact\n set Integration schemes = "
          << scheme << "\nend\n";
    const auto history =
      run_problem("a", RingContactTests::modelisation('a', extra.str()));
    std::vector<double> r;
    for (const auto &row : history)
      r.push_back(row.value("pressure_A") / row.value("analytic"));
    return r;
  }

  double
  largest_difference(const std::vector<double> &a,
                     const std::vector<double> &b)
  {
    check(a.size() == b.size() && !a.empty(), "same number of steps");
    double d = 0;
    for (unsigned int i = 0; i < a.size(); ++i)
      d = std::max(d, std::abs(a[i] - b[i]));
    return d;
  }
} // namespace

int
main()
{
  auto &out = RingContactTests::deallog_file;
  out << std::setprecision(6);
  for (const std::string scheme : {"nodal", "Gauss 3", "segment-based 3"})
    {
      const auto small_1e6    = ratios("small strain", scheme, 1e6);
      const auto small_tiny   = ratios("small strain", scheme, 1e-200);
      const auto finite_tiny  = ratios("finite strain", scheme, 1e-200);
      const double small_diff = largest_difference(small_1e6, small_tiny);
      const double finite_diff =
        largest_difference(small_tiny, finite_tiny);
      check(small_diff < 1e-9,
            scheme + ": small strain at p0 = 1e-200 against 1e6: " +
              std::to_string(small_diff));
      check(finite_diff < 1e-9,
            scheme + ": finite against small strain at p0 = 1e-200: " +
              std::to_string(finite_diff));
      out << scheme << ": p_A / analytic at step 3 = " << small_1e6.back()
          << " at p0 = 1e6 and at p0 = 1e-200 (small strain, finite strain)"
          << std::endl;
    }

  // The patch test in two tiny systems.
  for (const auto &[E_scale, p] :
       {std::make_pair(1.0, 1e-200), std::make_pair(1e-159, 1e-156)})
    {
      std::ostringstream prm;
      prm << std::setprecision(17)
          << "include " RING_CONTACT_SOURCE_DIR "/prm/two_blocks.prm\n"
          << "subsection Mesh\n set Mesh file = " RING_CONTACT_SOURCE_DIR
             "/meshes/two_blocks.geo\nend\n"
          << "subsection Problem\n set Constants = p = " << p
          << ", E1 = " << 1e9 * E_scale << ", nu1 = 0.3, E2 = "
          << 2e9 * E_scale << ", nu2 = 0.25, H = 0.5\nend\n"
          << "subsection Body 1\n set Young's modulus = " << 1e9 * E_scale
          << "\nend\n"
          << "subsection Body 2\n set Young's modulus = " << 2e9 * E_scale
          << "\nend\n";
      const auto history = run_problem("blocks", prm.str());
      // The first check's quantity: the contact pressure at (0.3, 0).
      const double pressure = history.back().trailing.at(0).second;
      check(std::abs(pressure / p - 1) < 1e-10,
            "patch test at p = " + std::to_string(p) + ": pressure / p = " +
              std::to_string(pressure / p));
      out << "patch test, E = " << 1e9 * E_scale << ", p = " << p
          << ": pressure / p = 1 to 1e-10" << std::endl;
    }
}
