#include <deal.II/base/symmetric_tensor.h>

#include <ring_contact/material.h>

#include <cmath>

namespace RingContact
{
  namespace
  {
    double
    lame_lambda(const double E, const double nu)
    {
      return E * nu / ((1 + nu) * (1 - 2 * nu));
    }

    double
    lame_mu(const double E, const double nu)
    {
      return E / (2 * (1 + nu));
    }
  } // namespace

  ElasticConstants::ElasticConstants(const double          E,
                                     const double          nu,
                                     const PlaneAssumption plane)
      : youngs_modulus(E)
      , poissons_ratio(nu)
      , plane(plane)
      , lambda(plane == PlaneAssumption::plane_strain ?
                 lame_lambda(E, nu) :
                 2 * lame_lambda(E, nu) * lame_mu(E, nu) /
                   (lame_lambda(E, nu) + 2 * lame_mu(E, nu)))
      , mu(lame_mu(E, nu))
      , lambda_3d(lame_lambda(E, nu))
  {}

  std::shared_ptr<const MaterialLaw>
  make_material_law(const ElasticConstants &constants,
                    const Kinematics        kinematics)
  {
    switch (kinematics)
      {
        case Kinematics::finite_strain:
          return make_saint_venant_kirchhoff(constants);
        case Kinematics::small_strain:
          return make_linear_elasticity(constants);
        case Kinematics::logarithmic_strain:
          return make_logarithmic_strain(constants);
        case Kinematics::neo_hookean:
          return make_neo_hookean(constants);
      }
    return nullptr;
  }

  Material::Material(const double          E,
                     const double          nu,
                     const PlaneAssumption plane,
                     const Kinematics      kinematics)
      : youngs_modulus(E)
      , poissons_ratio(nu)
      , plane(plane)
      , kinematics(kinematics)
      , law(make_material_law(ElasticConstants(E, nu, plane), kinematics))
  {}

  Tensor<2, 2>
  MaterialLaw::cauchy_stress(const Tensor<2, 2> &H) const
  {
    const Tensor<2, 2> F = unit_symmetric_tensor<2>() + H;
    return stress(H) * transpose(F) / (determinant(F) * thickness_stretch(H));
  }

  double
  Material::von_mises_stress(const Tensor<2, 2> &grad_u) const
  {
    const Tensor<2, 2> s   = cauchy_stress(grad_u);
    const double       s33 = out_of_plane_stress(grad_u);
    return std::sqrt(0.5 * ((s[0][0] - s[1][1]) * (s[0][0] - s[1][1]) +
                            (s[1][1] - s33) * (s[1][1] - s33) +
                            (s33 - s[0][0]) * (s33 - s[0][0])) +
                     3 * s[0][1] * s[0][1]);
  }
} // namespace RingContact
