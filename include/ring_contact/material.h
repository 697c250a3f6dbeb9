// The material law of each ring: Saint Venant-Kirchhoff in total Lagrangian
// form (Green-Lagrange strain E, second Piola-Kirchhoff stress S, with the
// linear isotropic law) or small-strain linear elasticity, in plane stress or
// plane strain. Everything is written in terms of the displacement gradient
// H = Grad u, so that the assembly only sees P(H) and dP/dH.
#ifndef ring_contact_material_h
#define ring_contact_material_h

#include <deal.II/base/tensor.h>

#include <ring_contact/parameters.h>

namespace RingContact
{
  using namespace dealii;

  class Material
  {
  public:
    /// E [Pa], nu [-]. In plane stress the in-plane law uses
    /// lambda* = 2 lambda mu / (lambda + 2 mu), which follows from S33 = 0.
    Material(const double          youngs_modulus,
             const double          poissons_ratio,
             const PlaneAssumption plane,
             const Kinematics      kinematics);

    /// The stress conjugate to Grad u in the virtual work: the first
    /// Piola-Kirchhoff stress P = F S (finite strain) or sigma (small strain).
    Tensor<2, 2>
    stress(const Tensor<2, 2> &grad_u) const;

    /// Stress and its consistent tangent A = dP/dH (A_iJkL = dP_iJ/dH_kL).
    void
    stress_and_tangent(const Tensor<2, 2> &grad_u,
                       Tensor<2, 2>       &P,
                       Tensor<4, 2>       &A) const;

    /// In-plane Cauchy stress sigma = P F^T / det(F) (det F includes the
    /// thickness stretch in plane stress); sigma itself in small strain.
    Tensor<2, 2>
    cauchy_stress(const Tensor<2, 2> &grad_u) const;

    /// Out-of-plane stretch F33 (1 in plane strain and small strain).
    double
    thickness_stretch(const Tensor<2, 2> &grad_u) const;

    const double          youngs_modulus;
    const double          poissons_ratio;
    const PlaneAssumption plane;
    const Kinematics      kinematics;

  private:
    /// Lamé constants of the in-plane law.
    const double lambda, mu;
    /// The 3d lambda (needed for E33 in plane stress).
    const double lambda_3d;
  };
} // namespace RingContact

#endif
