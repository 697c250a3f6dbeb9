// @sect3{The compressible neo-Hookean law}
//
// The compressible neo-Hookean law in total Lagrangian form, with the
// stored energy (Simo and Pister's form, as in deal.II's step-44 with the
// volumetric part written in ln J; Wriggers, Nonlinear Finite Element
// Methods, 2008, eq. 3.118)
//
//   W(F) = mu/2 (tr(F^T F) - 3 - 2 ln J) + lambda/2 (ln J)^2,  J = det F,
//
// whose first Piola-Kirchhoff stress is P = mu (F - F^-T) + lambda ln(J)
// F^-T. It agrees with linear elasticity at small strain (the same
// lambda, mu), and, unlike Saint Venant-Kirchhoff, its stress grows without
// bound as J -> 0: a body pressed hard cannot be squashed flat (SVK's
// stress has a maximum in compression, at a stretch of 0.58 in uniaxial
// strain, past which the Newton iteration finds no state). It is the law of
// the published large-sliding benchmarks (the shallow ironing of Fischer
// and Wriggers, Hartmann et al., Poulios and Renard, Code_Aster SSNP153).
//
// In 3d, F = [F2 0; 0 F33]. Plane strain: F33 = 1. Plane stress: F33 is the
// root of P33 = mu (F33 - 1/F33) + lambda ln(J2 F33) / F33 = 0, i.e.
// mu (F33^2 - 1) + lambda ln(J2 F33) = 0, whose left side increases with
// F33 (one root, found by Newton's method from F33 = 1, kept within a
// bracket of the root), and the in-plane
// tangent is condensed: dP/dF2 = dP/dF2|_F33 - dP/dF33 (dP33/dF33)^-1
// dP33/dF2. A body in three dimensions has the same P and A with its whole
// F, without the condensation (its constants are plane strain's).
#include <ring_contact/materials/material.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace RingContact
{
  namespace
  {
    template <int dim>
    class NeoHookean : public MaterialLaw<dim>
    {
    public:
      explicit NeoHookean(const ElasticConstants &constants)
          : c(constants)
      {}

      // P without its tangent: an iterate expected to converge is assembled
      // without the tangent (design.md), and the output needs none.
      Tensor<2, dim>
      stress(const Tensor<2, dim> &H) const override
      {
        Tensor<2, dim> P;
        evaluate(H, P, nullptr);
        return P;
      }

      void
      stress_and_tangent(const Tensor<2, dim> &H,
                         Tensor<2, dim>       &P,
                         Tensor<4, dim>       &A) const override
      {
        evaluate(H, P, &A);
      }

      // Plane strain: sigma33 = P33 / J = lambda ln J / J.
      double
      out_of_plane_stress(const Tensor<2, dim> &H) const override
      {
        // A 3d body: the zz component of its Cauchy stress.
        if constexpr (dim == 3)
          return this->cauchy_stress(H)[2][2];
        if (c.plane == PlaneAssumption::plane_stress)
          return 0;
        return c.lambda_3d * log_J2(H) /
               determinant(unit_symmetric_tensor<dim>() + H);
      }

      double
      thickness_stretch(const Tensor<2, dim> &H) const override
      {
        if (c.plane == PlaneAssumption::plane_strain)
          return 1.0;
        return std::exp(log_plane_stress_stretch(H));
      }

    private:
      // ln det F of the in-plane F = I + H, as log1p(tr H + det H): with
      // log(det F) the strains of 1e-8 that a stiff body under a small load
      // has were known to 2e-8 of themselves only (det F - 1 lost in the
      // round-off of det F ~ 1), a noise in the stress that kept Newton's
      // residual above its tolerance (found by the standing probe).
      static double
      log_J2(const Tensor<2, dim> &H)
      {
        return std::log1p(det_F_minus_one(H));
      }

      // ln F33 of plane stress: f(x) = mu (e^2x - 1) + lambda (ln J2 + x) =
      // 0 with x = ln F33 (3d lambda), e^2x - 1 as expm1(2x). f is
      // increasing and convex, so Newton's method from x = 0 converges
      // (from above after its first step, monotonically); a few iterations
      // reach round-off. Both terms of f vanish at x = 0 and increase, so
      // the root lies between 0 and -ln J2, a bracket that the Newton
      // steps shrink and never leave, whatever the stretch. It is kept
      // anyway: under a compression so extreme that e^2x overflows at the
      // first step (J2 below 1e-150 or so), f / f' is inf / inf, and a
      // step out of the bracket (or not a number) is replaced by bisection.
      double
      log_plane_stress_stretch(const Tensor<2, dim> &H) const
      {
        if (!(determinant(unit_symmetric_tensor<dim>() + H) > 0))
          return 0; // an inverted element: rejected by the caller
        const double lnJ2 = log_J2(H);
        const double mu = c.mu, lambda = c.lambda_3d;
        double       x   = 0; // ln F33
        double       low = std::min(0.0, -lnJ2), high = std::max(0.0, -lnJ2);
        for (unsigned int it = 0; it < 200; ++it)
          {
            const double f       = mu * std::expm1(2 * x) + lambda * (lnJ2 + x);
            const double df      = 2 * mu * std::exp(2 * x) + lambda;
            (f > 0 ? high : low) = x;
            double dx            = -f / df;
            if (!(x + dx >= low && x + dx <= high))
              dx = 0.5 * (low + high) - x;
            x += dx;
            if (!(std::abs(dx) > 1e-15 * std::abs(x)))
              break;
          }
        return x;
      }

      // P and (if asked) A_iJkL = dP_iJ / dF_kL:
      // dP/dF|_F33 = mu d_ik d_JL + lambda Fi_Ji Fi_Lk
      //              + (mu - lambda ln J) Fi_Li Fi_Jk,  Fi = F2^-1,
      // and in plane stress minus (lambda / F33)^2 Fi_Ji Fi_Lk / (dP33/dF33),
      // dP33/dF33 = mu (1 + 1/F33^2) + lambda (1 - ln J) / F33^2.
      void
      evaluate(const Tensor<2, dim> &H,
               Tensor<2, dim>       &P,
               Tensor<4, dim>       *A) const
      {
        const Tensor<2, dim> I      = unit_symmetric_tensor<dim>();
        const Tensor<2, dim> F      = I + H;
        const Tensor<2, dim> Fi     = invert(F);
        const Tensor<2, dim> FiT    = transpose(Fi);
        const double         lnF33  = c.plane == PlaneAssumption::plane_strain ?
                                        0.0 :
                                        log_plane_stress_stretch(H);
        const double         F33    = std::exp(lnF33);
        const double         lambda = c.lambda_3d;
        const double         lnJ    = log_J2(H) + lnF33;
        // F - F^-T written in H: H + (I - F^-T) = H + F^-T (F^T - I) =
        // H + F^-T H^T, without the cancellation of F - F^-T at small H.
        P = c.mu * (H + FiT * transpose(H)) + lambda * lnJ * FiT;
        if (A == nullptr)
          return;
        const double condensed =
          c.plane == PlaneAssumption::plane_strain ?
            0.0 :
            (lambda / F33) * (lambda / F33) /
              (c.mu * (1 + 1 / (F33 * F33)) + lambda * (1 - lnJ) / (F33 * F33));
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int J = 0; J < dim; ++J)
            for (unsigned int k = 0; k < dim; ++k)
              for (unsigned int L = 0; L < dim; ++L)
                (*A)[i][J][k][L] =
                  c.mu * I[i][k] * I[J][L] +
                  (lambda - condensed) * FiT[i][J] * FiT[k][L] +
                  (c.mu - lambda * lnJ) * Fi[L][i] * Fi[J][k];
      }

      const ElasticConstants c;
    };
  } // namespace

  // The registration line: Material law = neo-Hookean.
  namespace
  {
    const MaterialLaws::Add registration{
      MaterialLawRegistration::of<NeoHookean>(
        "neo-Hookean",
        {},
        "the compressible neo-Hookean law W = mu/2 (tr C - 3 - 2 ln J) + "
        "lambda/2 (ln J)^2 (finite strain; linear elasticity at small strain; "
        "in plane stress F33 from sigma33 = 0).",
        false)};
  } // namespace
} // namespace RingContact
