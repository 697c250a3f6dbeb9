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

    // E = (F^T F - I) / 2 written in H = Grad u: F^T F - I loses the digits
    // of small strains (at |H| = 1e-7 it keeps 9 of 16, and Newton stalled
    // at a relative residual of 1e-9 on steel at p = 1e4).
    Tensor<2, 2>
    green_lagrange(const Tensor<2, 2> &H)
    {
      return 0.5 * (H + transpose(H) + transpose(H) * H);
    }
  } // namespace

  Material::Material(const double          E,
                     const double          nu,
                     const PlaneAssumption plane,
                     const Kinematics      kinematics)
      : youngs_modulus(E)
      , poissons_ratio(nu)
      , plane(plane)
      , kinematics(kinematics)
      , lambda(plane == PlaneAssumption::plane_strain ?
                 lame_lambda(E, nu) :
                 2 * lame_lambda(E, nu) * lame_mu(E, nu) /
                   (lame_lambda(E, nu) + 2 * lame_mu(E, nu)))
      , mu(lame_mu(E, nu))
      , lambda_3d(lame_lambda(E, nu))
  {}

  Tensor<2, 2>
  Material::stress(const Tensor<2, 2> &H) const
  {
    const Tensor<2, 2> I = unit_symmetric_tensor<2>();
    if (kinematics == Kinematics::small_strain)
      {
        const Tensor<2, 2> eps = 0.5 * (H + transpose(H));
        return lambda * trace(eps) * I + 2 * mu * eps;
      }
    const Tensor<2, 2> F = I + H;
    const Tensor<2, 2> E = green_lagrange(H);
    const Tensor<2, 2> S = lambda * trace(E) * I + 2 * mu * E;
    return F * S;
  }

  void
  Material::stress_and_tangent(const Tensor<2, 2> &H,
                               Tensor<2, 2>       &P,
                               Tensor<4, 2>       &A) const
  {
    const Tensor<2, 2> I = unit_symmetric_tensor<2>();
    if (kinematics == Kinematics::small_strain)
      {
        const Tensor<2, 2> eps = 0.5 * (H + transpose(H));
        P                      = lambda * trace(eps) * I + 2 * mu * eps;
        for (unsigned int i = 0; i < 2; ++i)
          for (unsigned int J = 0; J < 2; ++J)
            for (unsigned int k = 0; k < 2; ++k)
              for (unsigned int L = 0; L < 2; ++L)
                A[i][J][k][L] = lambda * I[i][J] * I[k][L] +
                                mu * (I[i][k] * I[J][L] + I[i][L] * I[J][k]);
        return;
      }
    // P_iJ = F_iM S_MJ, S = lambda tr(E) I + 2 mu E. Differentiating,
    // A_iJkL = delta_ik S_LJ + F_iM C_MJLQ F_kQ
    //        = delta_ik S_LJ + lambda F_iJ F_kL + mu F_iL F_kJ
    //          + mu (F F^T)_ik delta_JL.
    const Tensor<2, 2> F   = I + H;
    const Tensor<2, 2> E   = green_lagrange(H);
    const Tensor<2, 2> S   = lambda * trace(E) * I + 2 * mu * E;
    const Tensor<2, 2> FFt = F * transpose(F);
    P                      = F * S;
    for (unsigned int i = 0; i < 2; ++i)
      for (unsigned int J = 0; J < 2; ++J)
        for (unsigned int k = 0; k < 2; ++k)
          for (unsigned int L = 0; L < 2; ++L)
            A[i][J][k][L] = I[i][k] * S[L][J] + lambda * F[i][J] * F[k][L] +
                            mu * F[i][L] * F[k][J] + mu * FFt[i][k] * I[J][L];
  }

  double
  Material::thickness_stretch(const Tensor<2, 2> &H) const
  {
    if (kinematics == Kinematics::small_strain ||
        plane == PlaneAssumption::plane_strain)
      return 1.0;
    // S33 = 0: E33 = -lambda/(lambda + 2 mu) (E11 + E22), F33^2 = 1 + 2 E33.
    const Tensor<2, 2> E   = green_lagrange(H);
    const double       E33 = -lambda_3d / (lambda_3d + 2 * mu) * trace(E);
    return std::sqrt(1 + 2 * E33);
  }

  Tensor<2, 2>
  Material::cauchy_stress(const Tensor<2, 2> &H) const
  {
    if (kinematics == Kinematics::small_strain)
      return stress(H);
    const Tensor<2, 2> F = unit_symmetric_tensor<2>() + H;
    return stress(H) * transpose(F) / (determinant(F) * thickness_stretch(H));
  }
} // namespace RingContact
