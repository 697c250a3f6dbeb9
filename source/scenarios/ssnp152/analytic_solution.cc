// @sect3{The closed form of SSNP152}
//
// Lamé's solution of two thick rings in frictionless contact under an
// equivalent external pressure p, as doc/intro.md states it in "The closed-form
// solution". It is the rings' reference twice over: its u_r(R1) and u_r(R3) are
// the displacements imposed on r = R1 and r = R3 (boundary_motion.cc), and its
// sigma_n is the pressure every step is checked against. It is a small-strain
// solution: the finite-strain computation drifts from it by 1-2 % at the
// highest load (doc/intro.md). Everything is linear in p. Units: radii in m, E
// and p in Pa, A_i in Pa, B_i in Pa m^2, u_r in m. Test analytic_solution
// checks the values below against the check values of doc/intro.md and against
// the conditions that define them.
#include <ring_contact/scenarios/ssnp152/analytic_solution.h>

namespace RingContact
{
  AnalyticSolution::AnalyticSolution(const double          R1,
                                     const double          R2,
                                     const double          R3,
                                     const double          E1_,
                                     const double          nu1_,
                                     const double          E2_,
                                     const double          nu2_,
                                     const PlaneAssumption plane)
      : R1(R1)
      , R2(R2)
      , R3(R3)
  {
    // Plane strain is plane stress with E/(1 - nu^2) and nu/(1 - nu). The
    // plane-stress formulas of doc/intro.md are therefore written once, for
    // effective constants E*, nu*:
    //   (1 - nu*)/E* = (1 + nu)(1 - 2 nu)/E,   (1 + nu*)/E* = (1 + nu)/E
    // turn u_r into the plane-strain u_r = ((1 + nu)/E) (A (1 - 2 nu) r + B/r),
    // and sigma_n into the document's eq. 1.3. Only the material constants
    // change; the A_i, B_i below come from stresses alone and are the same in
    // both.
    const auto effective = [plane](const double E, const double nu) {
      if (plane == PlaneAssumption::plane_stress)
        return std::make_pair(E, nu);
      return std::make_pair(E / (1 - nu * nu), nu / (1 - nu));
    };
    std::tie(E1, nu1) = effective(E1_, nu1_);
    std::tie(E2, nu2) = effective(E2_, nu2_);
  }

  AnalyticSolution::AnalyticSolution(const Ssnp152::RingParameters &rings,
                                     const PlaneAssumption          plane)
      : AnalyticSolution(rings.outer_radius,
                         rings.interface_radius,
                         rings.inner_radius,
                         rings.youngs_modulus_outer,
                         rings.poissons_ratio_outer,
                         rings.youngs_modulus_inner,
                         rings.poissons_ratio_inner,
                         plane)
  {}

  // The contact pressure, from the continuity of u_r at r = R2 (doc/intro.md,
  // the formula for sigma_n; with the plane-strain constants, eq. 1.3), with
  // a = R1^2, b = R2^2, c = R3^2:
  //   sigma_n = 2 p a / [a (1 + nu1) + b (1 - nu1)
  //             + (E1/E2) (a - b)/(b - c) (b (1 - nu2) + c (1 + nu2))].
  // For equal materials the bracket is 2 b (a - c)/(b - c), and sigma_n the
  // radial stress at R2 of a single annulus R3 <= r <= R1,
  // p a (b - c)/(b (a - c)): 25/27 p on the seed radii, whatever nu.
  double
  AnalyticSolution::contact_pressure(const double p) const
  {
    const double a = R1 * R1, b = R2 * R2, c = R3 * R3;
    return 2 * p * a /
           (a * (1 + nu1) + b * (1 - nu1) +
            (E1 / E2) * (a - b) / (b - c) * (b * (1 - nu2) + c * (1 + nu2)));
  }

  // The outer ring's constants, from sigma_rr = A1 - B1/r^2 with
  // sigma_rr(R1) = -p and sigma_rr(R2) = -sigma_n (doc/intro.md):
  //   A1 = (sigma_n R2^2 - p R1^2)/(R1^2 - R2^2),
  //   B1 = (sigma_n - p) R1^2 R2^2/(R1^2 - R2^2).
  double
  AnalyticSolution::A1(const double p) const
  {
    const double a = R1 * R1, b = R2 * R2;
    return (contact_pressure(p) * b - p * a) / (a - b);
  }

  double
  AnalyticSolution::B1(const double p) const
  {
    const double a = R1 * R1, b = R2 * R2;
    return (contact_pressure(p) - p) * a * b / (a - b);
  }

  // The inner ring's, from sigma_rr(R2) = -sigma_n and a traction-free r = R3,
  // sigma_rr(R3) = 0:
  //   A2 = -sigma_n R2^2/(R2^2 - R3^2),  B2 = -sigma_n R2^2 R3^2/(R2^2 - R3^2).
  // At p = 1e7 Pa with equal materials A1 = A2 = -1.0417e7 Pa and
  // B1 = B2 = -4.1667e5 Pa m^2: the two rings are one annulus.
  double
  AnalyticSolution::A2(const double p) const
  {
    const double b = R2 * R2, c = R3 * R3;
    return -contact_pressure(p) * b / (b - c);
  }

  double
  AnalyticSolution::B2(const double p) const
  {
    const double b = R2 * R2, c = R3 * R3;
    return -contact_pressure(p) * b * c / (b - c);
  }

  // Lamé's radial displacement in ring i (doc/intro.md, plane stress; plane
  // strain through the effective constants):
  //   u_r(r) = (A_i (1 - nu_i) r + B_i (1 + nu_i)/r)/E_i.
  // At r = R2 both rings give the same value, by the very condition that fixed
  // sigma_n, so which ring r = R2 is given to does not matter.
  double
  AnalyticSolution::radial_displacement(const double r, const double p) const
  {
    if (r >= R2)
      return (A1(p) * (1 - nu1) * r + B1(p) * (1 + nu1) / r) / E1;
    return (A2(p) * (1 - nu2) * r + B2(p) * (1 + nu2) / r) / E2;
  }

  // The imposed displacements of doc/intro.md ("Loads"): f(R1) = u_r(R1) of the
  // outer ring on S1R1 and f(R3) = u_r(R3) of the inner ring on S2R3. At
  // p = 1e7 Pa in plane stress they are -8.8333e-3 m and -4.1667e-3 m (plane
  // strain: -8.0000e-3 m and -4.0000e-3 m).
  double
  AnalyticSolution::f_R1(const double p) const
  {
    return radial_displacement(R1, p);
  }

  double
  AnalyticSolution::f_R3(const double p) const
  {
    return radial_displacement(R3, p);
  }
} // namespace RingContact
