// @sect3{Saint Venant-Kirchhoff}
//
// Saint Venant-Kirchhoff in total Lagrangian form: the Green-Lagrange strain
// E = (F^T F - I) / 2, the second Piola-Kirchhoff stress S = lambda tr(E) I
// + 2 mu E, and P = F S, in plane stress (S33 = 0, through lambda*) or
// plane strain (E33 = 0). The original's GROT_GDEP.
//
// The law of Kinematics = finite strain, the one the original computes
// with. Finite strain at all because the inner ring turns through a finite
// angle, and a linearised rotation strains it (doc/intro.md). The law's
// limit is compression: in uniaxial strain its stress turns back at a
// stretch of 0.58 and Newton finds no state beyond it, which is why
// problems pressed hard use the neo-Hookean law.
#include <ring_contact/materials/material.h>

#include <cmath>

namespace RingContact
{
  namespace
  {
    // E = (F^T F - I) / 2 written in H = Grad u: F^T F - I loses the digits
    // of small strains (at |H| = 1e-7 it keeps 9 of 16, and Newton stalled
    // at a relative residual of 1e-9 on steel at p = 1e4).
    Tensor<2, 2>
    green_lagrange(const Tensor<2, 2> &H)
    {
      return 0.5 * (H + transpose(H) + transpose(H) * H);
    }

    class SaintVenantKirchhoff : public MaterialLaw
    {
    public:
      explicit SaintVenantKirchhoff(const ElasticConstants &constants)
          : c(constants)
      {}

      // P = F S: the stress conjugate to Grad u in the reference
      // configuration, which is where the bulk is integrated.
      Tensor<2, 2>
      stress(const Tensor<2, 2> &H) const override
      {
        const Tensor<2, 2> I = unit_symmetric_tensor<2>();
        const Tensor<2, 2> F = I + H;
        const Tensor<2, 2> E = green_lagrange(H);
        const Tensor<2, 2> S = c.lambda * trace(E) * I + 2 * c.mu * E;
        return F * S;
      }

      // P_iJ = F_iM S_MJ, S = lambda tr(E) I + 2 mu E. Differentiating,
      // A_iJkL = delta_ik S_LJ + F_iM C_MJLQ F_kQ
      //        = delta_ik S_LJ + lambda F_iJ F_kL + mu F_iL F_kJ
      //          + mu (F F^T)_ik delta_JL.
      void
      stress_and_tangent(const Tensor<2, 2> &H,
                         Tensor<2, 2>       &P,
                         Tensor<4, 2>       &A) const override
      {
        const Tensor<2, 2> I   = unit_symmetric_tensor<2>();
        const Tensor<2, 2> F   = I + H;
        const Tensor<2, 2> E   = green_lagrange(H);
        const Tensor<2, 2> S   = c.lambda * trace(E) * I + 2 * c.mu * E;
        const Tensor<2, 2> FFt = F * transpose(F);
        P                      = F * S;
        for (unsigned int i = 0; i < 2; ++i)
          for (unsigned int J = 0; J < 2; ++J)
            for (unsigned int k = 0; k < 2; ++k)
              for (unsigned int L = 0; L < 2; ++L)
                A[i][J][k][L] =
                  I[i][k] * S[L][J] + c.lambda * F[i][J] * F[k][L] +
                  c.mu * F[i][L] * F[k][J] + c.mu * FFt[i][k] * I[J][L];
      }

      // Plane strain: E33 = 0, S33 = lambda (E11 + E22), F33 = 1, so
      // sigma33 = S33 / det F.
      double
      out_of_plane_stress(const Tensor<2, 2> &H) const override
      {
        if (c.plane == PlaneAssumption::plane_stress)
          return 0;
        const Tensor<2, 2> F = unit_symmetric_tensor<2>() + H;
        return c.lambda_3d * trace(green_lagrange(H)) / determinant(F);
      }

      double
      thickness_stretch(const Tensor<2, 2> &H) const override
      {
        if (c.plane == PlaneAssumption::plane_strain)
          return 1.0;
        // S33 = 0: E33 = -lambda/(lambda + 2 mu) (E11 + E22),
        // F33^2 = 1 + 2 E33.
        const Tensor<2, 2> E = green_lagrange(H);
        const double E33 = -c.lambda_3d / (c.lambda_3d + 2 * c.mu) * trace(E);
        return std::sqrt(1 + 2 * E33);
      }

    private:
      const ElasticConstants c;
    };
  } // namespace

  std::shared_ptr<const MaterialLaw>
  make_saint_venant_kirchhoff(const ElasticConstants &constants)
  {
    return std::make_shared<SaintVenantKirchhoff>(constants);
  }
} // namespace RingContact
