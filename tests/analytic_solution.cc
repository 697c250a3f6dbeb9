// The closed-form solution against the values that doc/intro.md gives, and
// against its own definition: continuity of u_r and of the radial stress at
// r = R2, the pressure p at r = R1 and zero traction at r = R3.
#include <ring_contact/scenarios/ssnp152/analytic_solution.h>

#include "tests.h"

#include <cmath>
#include <iomanip>

using namespace RingContact;
using RingContactTests::check;

namespace
{
  bool
  close(const double a, const double b, const double tolerance)
  {
    return std::abs(a - b) <= tolerance * std::abs(b);
  }

  // Radial stress of the Lame solution (plane stress constants).
  double
  radial_stress(const double A, const double B, const double r)
  {
    return A - B / (r * r);
  }
} // namespace

int
main()
{
  auto &out = RingContactTests::deallog_file;
  out << std::setprecision(10);
  const double p = 1e7;

  const AnalyticSolution stress(
    1.0, 0.6, 0.2, 1e9, 0.2, 1e9, 0.2, PlaneAssumption::plane_stress);
  out << "plane stress: sigma_n = " << stress.contact_pressure(p)
      << " f(R1) = " << stress.f_R1(p) << " f(R3) = " << stress.f_R3(p)
      << std::endl;
  check(close(stress.contact_pressure(p), 25.0 / 27.0 * p, 1e-12),
        "sigma_n = 25/27 p");
  check(close(stress.contact_pressure(p), 9259259.26, 1e-9),
        "sigma_n = 9 259 259.26 Pa");
  check(close(stress.f_R1(p), -8.8333e-3, 1e-4), "f(R1) = -8.8333e-3");
  check(close(stress.f_R3(p), -4.1667e-3, 1e-4), "f(R3) = -4.1667e-3");

  // Plane stress constants: p at R1, sigma_n at R2 on both sides, 0 at R3.
  check(close(-radial_stress(stress.A1(p), stress.B1(p), 1.0), p, 1e-12),
        "sigma_rr(R1) = -p");
  check(close(-radial_stress(stress.A1(p), stress.B1(p), 0.6),
              stress.contact_pressure(p),
              1e-12),
        "sigma_rr(R2+) = -sigma_n");
  check(close(-radial_stress(stress.A2(p), stress.B2(p), 0.6),
              stress.contact_pressure(p),
              1e-12),
        "sigma_rr(R2-) = -sigma_n");
  check(std::abs(radial_stress(stress.A2(p), stress.B2(p), 0.2)) < 1e-9 * p,
        "sigma_rr(R3) = 0");
  check(close(stress.radial_displacement(0.6 + 1e-14, p),
              stress.radial_displacement(0.6 - 1e-14, p),
              1e-9),
        "u_r continuous at R2");

  const AnalyticSolution strain(
    1.0, 0.6, 0.2, 1e9, 0.2, 1e9, 0.2, PlaneAssumption::plane_strain);
  out << "plane strain: sigma_n = " << strain.contact_pressure(p)
      << " f(R1) = " << strain.f_R1(p) << " f(R3) = " << strain.f_R3(p)
      << std::endl;
  check(close(strain.contact_pressure(p), 25.0 / 27.0 * p, 1e-12),
        "plane strain sigma_n = 25/27 p");
  check(close(strain.radial_displacement(0.6 + 1e-14, p),
              strain.radial_displacement(0.6 - 1e-14, p),
              1e-9),
        "plane strain u_r continuous at R2");

  const AnalyticSolution d(
    1.0, 0.6, 0.2, 1e9, 0.3, 1e8, 0.2, PlaneAssumption::plane_stress);
  out << "modelisation D: sigma_n = " << d.contact_pressure(p) << std::endl;
  check(close(d.contact_pressure(p), 2417794.97, 1e-9),
        "modelisation D sigma_n = 2 417 794.97 Pa");

  // Linear in p.
  check(close(stress.contact_pressure(2 * p),
              2 * stress.contact_pressure(p),
              1e-14),
        "linear in p");
  out << "OK" << std::endl;
}
