#include <ring_contact/analytic_solution.h>

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
    // Plane strain is plane stress with E/(1 - nu^2) and nu/(1 - nu).
    const auto effective = [plane](const double E, const double nu) {
      if (plane == PlaneAssumption::plane_stress)
        return std::make_pair(E, nu);
      return std::make_pair(E / (1 - nu * nu), nu / (1 - nu));
    };
    std::tie(E1, nu1) = effective(E1_, nu1_);
    std::tie(E2, nu2) = effective(E2_, nu2_);
  }

  AnalyticSolution::AnalyticSolution(const MeshParameters     &mesh,
                                     const MaterialParameters &mat)
      : AnalyticSolution(mesh.outer_radius,
                         mesh.interface_radius,
                         mesh.inner_radius,
                         mat.youngs_modulus_outer,
                         mat.poissons_ratio_outer,
                         mat.youngs_modulus_inner,
                         mat.poissons_ratio_inner,
                         mat.plane)
  {}

  double
  AnalyticSolution::contact_pressure(const double p) const
  {
    const double a = R1 * R1, b = R2 * R2, c = R3 * R3;
    return 2 * p * a /
           (a * (1 + nu1) + b * (1 - nu1) +
            (E1 / E2) * (a - b) / (b - c) * (b * (1 - nu2) + c * (1 + nu2)));
  }

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

  double
  AnalyticSolution::radial_displacement(const double r, const double p) const
  {
    if (r >= R2)
      return (A1(p) * (1 - nu1) * r + B1(p) * (1 + nu1) / r) / E1;
    return (A2(p) * (1 - nu2) * r + B2(p) * (1 + nu2) / r) / E2;
  }

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
