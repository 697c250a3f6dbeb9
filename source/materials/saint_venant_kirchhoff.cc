// @sect3{Saint Venant-Kirchhoff}
//
// Saint Venant-Kirchhoff in total Lagrangian form: the Green-Lagrange strain
// E = (F^T F - I) / 2, the second Piola-Kirchhoff stress S = lambda tr(E) I
// + 2 mu E, and P = F S, in plane stress (S33 = 0, through lambda*) or
// plane strain (E33 = 0). The original's GROT_GDEP.
//
// The law of Material law = Saint Venant-Kirchhoff, the one the original
// computes with. Finite strain at all because the inner ring turns through a
// finite angle, and a linearised rotation strains it (doc/intro.md). The law's
// limit is compression: in uniaxial strain its stress turns back at a
// stretch of 0.58 and Newton finds no state beyond it, which is why
// problems pressed hard use the neo-Hookean law. In plane stress it has a
// second limit, in tension: S33 = 0 is linear in E33, E33 = -nu / (1 - nu)
// tr E (3d lambda and mu), but F33^2 = 1 + 2 E33 is positive only while
// tr E < (1 - nu) / (2 nu): an equibiaxial stretch below sqrt(1 + (1 -
// nu) / (2 nu)), 1.47 at nu = 0.3 (2.35 at nu = 0.1, 1.27 at nu = 0.45).
// Beyond it no thickness satisfies sigma33 = 0 (the 3d energy's minimum
// over E33 is at the bound F33 = 0, where S33 is not zero): the state is
// outside the law (in_range()), rejected by the Newton iteration as an
// inverted one; F33 was its square root, a NaN in the Cauchy stress.
#include <ring_contact/materials/material.h>

#include <cmath>
#include <iomanip>
#include <sstream>
#include <stdexcept>
#include <string>

namespace RingContact
{
  namespace
  {
    // E = (F^T F - I) / 2 written in H = Grad u: F^T F - I loses the digits
    // of small strains (at |H| = 1e-7 it keeps 9 of 16, and Newton stalled
    // at a relative residual of 1e-9 on steel at p = 1e4).
    template <int dim>
    Tensor<2, dim>
    green_lagrange(const Tensor<2, dim> &H)
    {
      return 0.5 * (H + transpose(H) + transpose(H) * H);
    }

    template <int dim>
    class SaintVenantKirchhoff : public MaterialLaw<dim>
    {
    public:
      explicit SaintVenantKirchhoff(const ElasticConstants &constants)
          : c(constants)
      {}

      // P = F S: the stress conjugate to Grad u in the reference
      // configuration, which is where the bulk is integrated.
      Tensor<2, dim>
      stress(const Tensor<2, dim> &H) const override
      {
        const Tensor<2, dim> I = unit_symmetric_tensor<dim>();
        const Tensor<2, dim> F = I + H;
        const Tensor<2, dim> E = green_lagrange(H);
        const Tensor<2, dim> S = c.lambda * trace(E) * I + 2 * c.mu * E;
        return F * S;
      }

      // P_iJ = F_iM S_MJ, S = lambda tr(E) I + 2 mu E. Differentiating,
      // A_iJkL = delta_ik S_LJ + F_iM C_MJLQ F_kQ
      //        = delta_ik S_LJ + lambda F_iJ F_kL + mu F_iL F_kJ
      //          + mu (F F^T)_ik delta_JL.
      void
      stress_and_tangent(const Tensor<2, dim> &H,
                         Tensor<2, dim>       &P,
                         Tensor<4, dim>       &A) const override
      {
        const Tensor<2, dim> I   = unit_symmetric_tensor<dim>();
        const Tensor<2, dim> F   = I + H;
        const Tensor<2, dim> E   = green_lagrange(H);
        const Tensor<2, dim> S   = c.lambda * trace(E) * I + 2 * c.mu * E;
        const Tensor<2, dim> FFt = F * transpose(F);
        P                        = F * S;
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int J = 0; J < dim; ++J)
            for (unsigned int k = 0; k < dim; ++k)
              for (unsigned int L = 0; L < dim; ++L)
                A[i][J][k][L] =
                  I[i][k] * S[L][J] + c.lambda * F[i][J] * F[k][L] +
                  c.mu * F[i][L] * F[k][J] + c.mu * FFt[i][k] * I[J][L];
      }

      // Plane strain: E33 = 0, S33 = lambda (E11 + E22), F33 = 1, so
      // sigma33 = S33 / det F.
      double
      out_of_plane_stress(const Tensor<2, dim> &H) const override
      {
        // A 3d body: the zz component of its Cauchy stress.
        if constexpr (dim == 3)
          return this->cauchy_stress(H)[2][2];
        if (c.plane == PlaneAssumption::plane_stress)
          return 0;
        const Tensor<2, dim> F = unit_symmetric_tensor<dim>() + H;
        return c.lambda_3d * trace(green_lagrange(H)) / determinant(F);
      }

      double
      thickness_stretch(const Tensor<2, dim> &H) const override
      {
        if (c.plane == PlaneAssumption::plane_strain)
          return 1.0;
        const double F33_squared = thickness_stretch_squared(H);
        if (!(F33_squared > 0))
          {
            std::ostringstream value;
            value << F33_squared;
            throw std::domain_error("no thickness stretch here (F33^2 = " +
                                    value.str() + "): " + range_condition());
          }
        return std::sqrt(F33_squared);
      }

      bool
      in_range(const Tensor<2, dim> &H) const override
      {
        return c.plane == PlaneAssumption::plane_strain ||
               thickness_stretch_squared(H) > 0;
      }

      std::string
      range_condition() const override
      {
        if (c.plane == PlaneAssumption::plane_strain)
          return "";
        // The equibiaxial stretch where F33 reaches zero, for the message.
        const double       ratio = c.lambda_3d / (c.lambda_3d + 2 * c.mu);
        std::ostringstream limit;
        limit << std::setprecision(3) << std::sqrt(1 + 0.5 / ratio);
        return "Saint Venant-Kirchhoff in plane stress has a thickness "
               "stretch (sigma33 = 0) only while F33^2 = 1 - 2 nu / (1 - "
               "nu) tr E > 0, a stretch of the plane below " +
               limit.str() +
               " equibiaxially; the neo-Hookean law or the logarithmic "
               "strain has one at any stretch";
      }

    private:
      const ElasticConstants c;

      // S33 = 0: E33 = -lambda/(lambda + 2 mu) (E11 + E22) (3d lambda),
      // and F33^2 = 1 + 2 E33.
      double
      thickness_stretch_squared(const Tensor<2, dim> &H) const
      {
        const double E33 =
          -c.lambda_3d / (c.lambda_3d + 2 * c.mu) * trace(green_lagrange(H));
        return 1 + 2 * E33;
      }
    };
  } // namespace

  // The registration line: Material law = Saint Venant-Kirchhoff (the
  // former Kinematics = finite strain), the default.
  namespace
  {
    const MaterialLaws::Add registration{
      MaterialLawRegistration::of<SaintVenantKirchhoff>(
        "Saint Venant-Kirchhoff",
        {"finite strain"},
        "total Lagrangian Saint Venant-Kirchhoff (Green-Lagrange strain, "
        "second Piola-Kirchhoff stress; the original's GROT_GDEP).",
        false)};
  } // namespace
} // namespace RingContact
