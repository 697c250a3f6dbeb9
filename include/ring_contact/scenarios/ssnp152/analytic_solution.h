// The closed-form small-strain solution of SSNP152: two concentric rings in
// frictionless contact under an equivalent external pressure p. It gives both
// the boundary data (the displacements imposed on r = R1 and r = R3) and the
// reference contact pressure sigma_n.
#ifndef ring_contact_scenarios_ssnp152_analytic_solution_h
#define ring_contact_scenarios_ssnp152_analytic_solution_h

#include <ring_contact/input/parameters.h>
#include <ring_contact/scenarios/ssnp152/ssnp152.h>

namespace RingContact
{
  /**
   * Lamé's solution of a thick ring, u_r(r) = (A (1 - nu) r + B (1 + nu) / r)
   * / E, in each ring, with continuity of u_r and of the radial stress at
   * r = R2. Plane strain uses E / (1 - nu^2) and nu / (1 - nu). All
   * quantities are linear in p.
   */
  class AnalyticSolution
  {
  public:
    AnalyticSolution(const double          R1,
                     const double          R2,
                     const double          R3,
                     const double          E1,
                     const double          nu1,
                     const double          E2,
                     const double          nu2,
                     const PlaneAssumption plane);

    /// The rings of the parameters.
    AnalyticSolution(const Ssnp152::RingParameters &rings,
                     const PlaneAssumption          plane);

    /// Contact pressure sigma_n (positive in compression) for pressure p.
    double
    contact_pressure(const double p) const;

    /// Coefficients A1, B1 (outer ring) and A2, B2 (inner ring).
    double
    A1(const double p) const;
    double
    B1(const double p) const;
    double
    A2(const double p) const;
    double
    B2(const double p) const;

    /// Radial displacement at radius r (ring chosen by r >= R2: outer).
    double
    radial_displacement(const double r, const double p) const;

    /// f(R1): radial displacement imposed on the outer boundary.
    double
    f_R1(const double p) const;
    /// f(R3): radial displacement imposed on the inner boundary.
    double
    f_R3(const double p) const;

    const double R1, R2, R3;

  private:
    // Effective in-plane constants (plane strain mapped to plane stress).
    double E1, nu1, E2, nu2;
  };
} // namespace RingContact

#endif
