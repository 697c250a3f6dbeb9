// @sect3{Hencky: the linear law on the logarithmic strain}
//
// Logarithmic strain (Hencky): the strain E = ln(C) / 2 and the linear
// isotropic law on it, T = lambda tr(E) I + 2 mu E, T the stress conjugate
// to E. For an elastic law this is the logarithmic-strain framework of
// Miehe, Apel and Lambrecht (2002) that Code_Aster runs as GDEF_LOG: there
// the small-strain law is written on E and its stress T projected to the
// second Piola-Kirchhoff stress S = T : dE/dC... with the exact projection
// tensor, which is what differentiating the energy below does.
//
// In two dimensions the energy psi = mu E : E + lambda/2 (tr E)^2 has a
// closed form in F that needs no eigenvectors. With J = det F (in plane),
// kappa = F : F = tr C and the eigenvalues c1, c2 of C,
//   tr E  = (ln c1 + ln c2) / 2 = ln J,
//   E : E = ((ln c1)^2 + (ln c2)^2) / 4 = (ln J)^2 / 2 + t^2 / 2,
//   t     = (ln c1 - ln c2) / 2 = atanh(u),  u^2 = 1 - 4 J^2 / kappa^2,
// so that
//   psi(F) = (lambda + mu) / 2 (ln J)^2 + mu / 2 t^2.
// Plane strain: E33 = 0. Plane stress: T33 = 0, i.e. E33 = -lambda /
// (lambda + 2 mu) ln J, and minimizing over E33 leaves the same energy with
// lambda* = 2 lambda mu / (lambda + 2 mu) (ElasticConstants::lambda): the
// reduced energy's derivatives are the plane-stress stress and tangent.
//
// Its derivatives, with G = F^-T, N = G - 2 F / kappa, r = 4 J^2 / kappa^2
// and w(r) = -atanh(u) / u (so that d(t^2)/dr r = w):
//   P = (lambda + mu) ln J G + mu w N,
//   A_iJkL = (lambda + mu) (G_kL G_iJ - ln J G_iL G_kJ)
//          + mu (2 r w'(r) N_kL N_iJ
//                + w (-G_iL G_kJ - 2 d_ik d_JL / kappa
//                     + 4 F_iJ F_kL / kappa^2)).
// w and w' are smooth at u = 0 (a pure dilatation, where c1 = c2 and the
// spectral formulas divide by zero); near it they are summed as series in
// u^2. And u^2 is computed without cancellation: kappa - 2 J = (F11 -
// F22)^2 + (F12 + F21)^2 = (H11 - H22)^2 + (H12 + H21)^2 exactly, so
// u^2 = (kappa - 2 J)(kappa + 2 J) / kappa^2; ln J = log1p(tr H + det H);
// N = (2 J (cof F - F) + (kappa - 2 J) cof F) / (J kappa), cof F - F
// written in H.
// At small strain P -> lambda tr(H) I + mu (H + H^T), linear elasticity.
#include <deal.II/base/symmetric_tensor.h>

#include <ring_contact/materials/material.h>

#include <array>
#include <cmath>

namespace RingContact
{
  namespace
  {
    // @sect4{The invariants of F}
    //
    // The kinematic quantities of F = I + H that the energy depends on,
    // computed once per quadrature point and shared by the stress, the
    // tangent and the out-of-plane quantities.
    struct Invariants
    {
      explicit Invariants(const Tensor<2, 2> &H)
      {
        const Tensor<2, 2> I = unit_symmetric_tensor<2>();
        F                    = I + H;
        // det F - 1 without cancellation, as det_F_minus_one<2>() has it
        // but summed in this order, which the 2D results' digits were
        // computed with (the two may differ in the last bits).
        const double dilatation =
          H[0][0] + H[1][1] + H[0][0] * H[1][1] - H[0][1] * H[1][0];
        J               = 1 + dilatation;
        log_J           = std::log1p(dilatation);
        const double d1 = H[0][0] - H[1][1], d2 = H[0][1] + H[1][0];
        const double shear = d1 * d1 + d2 * d2; // kappa - 2 J
        kappa              = 2 * J + shear;
        u2                 = shear * (kappa + 2 * J) / (kappa * kappa);
        r                  = 1 - u2;
        // G = cof(F) / J; N = G - 2 F / kappa = (2 J (cof(F) - F) +
        // (kappa - 2 J) cof(F)) / (J kappa), with cof(F) - F written in H:
        // at small strain N is O(H), and G - 2 F / kappa would leave it to
        // the round-off of O(1) terms (steel at p = 1e2: a stress noise of
        // 1e-7 of the stress, and Newton stalled there).
        Tensor<2, 2> cofactor, cofactor_minus_F;
        cofactor[0][0]         = 1 + H[1][1];
        cofactor[0][1]         = -H[1][0];
        cofactor[1][0]         = -H[0][1];
        cofactor[1][1]         = 1 + H[0][0];
        cofactor_minus_F[0][0] = H[1][1] - H[0][0];
        cofactor_minus_F[0][1] = -d2;
        cofactor_minus_F[1][0] = -d2;
        cofactor_minus_F[1][1] = H[0][0] - H[1][1];
        G                      = cofactor / J;
        N = (2 * J * cofactor_minus_F + shear * cofactor) / (J * kappa);
        // w = -atanh(u) / u and w' = dw/dr.
        if (u2 < 1e-2)
          {
            // -sum u^2k / (2k + 1) and sum k u^(2k-2) / (2k + 1), to u^14.
            w               = 0;
            w_prime         = 0;
            double power    = 1; // u^(2k)
            double previous = 1; // u^(2k-2)
            for (unsigned int k = 0; k <= 7; ++k)
              {
                w -= power / (2 * k + 1);
                if (k > 0)
                  w_prime += k * previous / (2 * k + 1);
                previous = power;
                power *= u2;
              }
          }
        else
          {
            const double u = std::sqrt(u2);
            w              = -std::atanh(u) / u;
            // w' = (1 / (r u^2) - atanh(u) / u^3) / 2.
            w_prime = 0.5 * (1 / (r * u2) + w / u2);
          }
      }

      Tensor<2, 2> F, G, N;
      double       J, log_J, kappa, u2, r, w, w_prime;
    };

    // @sect4{The law in two dimensions}
    //
    // P and A are the closed forms at the top of this file, lambda the
    // in-plane constant of the assumption (lambda* in plane stress); the
    // out-of-plane quantities use the 3d lambda. The law of a plane body,
    // the specialization for dim = 2 of the spectral law below.
    template <int dim>
    class LogarithmicStrain;

    template <>
    class LogarithmicStrain<2> : public MaterialLaw<2>
    {
    public:
      static constexpr int dim = 2;

      explicit LogarithmicStrain(const ElasticConstants &constants)
          : c(constants)
      {}

      Tensor<2, dim>
      stress(const Tensor<2, dim> &H) const override
      {
        const Invariants k(H);
        return (c.lambda + c.mu) * k.log_J * k.G + c.mu * k.w * k.N;
      }

      void
      stress_and_tangent(const Tensor<2, dim> &H,
                         Tensor<2, dim>       &P,
                         Tensor<4, dim>       &A) const override
      {
        const Invariants      k(H);
        const Tensor<2, dim> &F = k.F, &G = k.G, &N = k.N;
        P = (c.lambda + c.mu) * k.log_J * G + c.mu * k.w * N;
        const double volumetric = c.lambda + c.mu;
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int J = 0; J < dim; ++J)
            for (unsigned int m = 0; m < dim; ++m)
              for (unsigned int L = 0; L < dim; ++L)
                A[i][J][m][L] =
                  volumetric *
                    (G[m][L] * G[i][J] - k.log_J * G[i][L] * G[m][J]) +
                  c.mu * (2 * k.r * k.w_prime * N[m][L] * N[i][J] +
                          k.w * (-G[i][L] * G[m][J] -
                                 (i == m && J == L ? 2 / k.kappa : 0.) +
                                 4 * F[i][J] * F[m][L] / (k.kappa * k.kappa)));
      }

      // Plane strain: T33 = lambda tr(E) = lambda ln J is the Kirchhoff
      // stress tau33 (3 is a principal direction), sigma33 = tau33 / J.
      double
      out_of_plane_stress(const Tensor<2, dim> &H) const override
      {
        if (c.plane == PlaneAssumption::plane_stress)
          return 0;
        const Invariants k(H);
        return c.lambda_3d * k.log_J / k.J;
      }

      // Plane stress: F33 = exp(E33), E33 = -lambda / (lambda + 2 mu) ln J.
      double
      thickness_stretch(const Tensor<2, dim> &H) const override
      {
        if (c.plane == PlaneAssumption::plane_strain)
          return 1.0;
        const Invariants k(H);
        return std::exp(-c.lambda_3d / (c.lambda_3d + 2 * c.mu) * k.log_J);
      }

    private:
      const ElasticConstants c;
    };

    // @sect4{The law in three dimensions: the spectral form}
    //
    // A body in three dimensions has C = F^T F with three eigenvalues c_a
    // and orthonormal eigenvectors n_a, found by Jacobi's method (deal.II's
    // eigenvectors(), robust where eigenvalues coincide). The eigenvalues
    // are those of C - I = H + H^T + H^T H, written in H, so that
    // ln c_a = log1p(e_a) keeps the digits of small strains, as ln J =
    // log1p(det F - 1) does. The energy psi = mu E : E + lambda/2 (tr E)^2,
    // E = ln(C) / 2, is a function of the eigenvalues, and
    //   S = 2 dpsi/dC = sum_a g_a n_a (x) n_a,   g_a = T_a / c_a,
    //   T_a = lambda ln J + mu ln c_a,
    // T_a the principal stress conjugate to E (Kirchhoff's, as 3 is in the
    // 2d law); P = F S = sum_a g_a f_a (x) n_a with f_a = F n_a.
    //
    // The tangent A_iJkL = d_ik S_JL + 2 F_iM D_MJNL F_kN, D = dS/dC. For a
    // function of the eigenvalues D has, in the eigenvector frame, the
    // derivatives of the g_a on the diagonal, D_ab = dg_a/dc_b = lambda /
    // (2 c_a c_b) + d_ab (mu - T_a) / c_a^2, and on the off-diagonal pairs
    // the divided differences Theta_ab = (g_a - g_b) / (c_a - c_b) taken
    // with ln J held (Lewis, 1996; the Daleckii-Krein formula):
    //   Theta_ab = (mu c_b l_ab - T_b) / (c_a c_b),
    //   l_ab = (ln c_a - ln c_b) / (c_a - c_b) = log1p(x) / x / c_b,
    //   x = (e_a - e_b) / c_b,
    // whose limit at c_a = c_b (l_ab = 1 / c_b, a pure dilatation, a
    // uniaxial stretch) is dg_a/dc_a - dg_a/dc_b: no eigenvalue is divided
    // by the difference of two. So
    //   A = d_ik S_JL + 2 sum_ab D_ab (f_a (x) n_a) (x) (f_b (x) n_b)
    //     + sum_(a != b) Theta_ab (f_a (x) n_b) (x) (f_a (x) n_b + f_b (x)
    //     n_a),
    // which has the major symmetry. At F33 = 1 (H in the plane) it is the
    // plane-strain closed form above; tests/materials_3d checks it.
    template <int dim>
    class LogarithmicStrain : public MaterialLaw<dim>
    {
    public:
      explicit LogarithmicStrain(const ElasticConstants &constants)
          : c(constants)
      {}

      Tensor<2, dim>
      stress(const Tensor<2, dim> &H) const override
      {
        const Principal p(H, c);
        Tensor<2, dim>  P;
        for (unsigned int a = 0; a < dim; ++a)
          P += p.g[a] * outer_product(p.f[a], p.n[a]);
        return P;
      }

      void
      stress_and_tangent(const Tensor<2, dim> &H,
                         Tensor<2, dim>       &P,
                         Tensor<4, dim>       &A) const override
      {
        const Principal p(H, c);
        Tensor<2, dim>  S;
        P = Tensor<2, dim>();
        for (unsigned int a = 0; a < dim; ++a)
          {
            P += p.g[a] * outer_product(p.f[a], p.n[a]);
            S += p.g[a] * outer_product(p.n[a], p.n[a]);
          }
        // d_ik S_JL.
        A = Tensor<4, dim>();
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int J = 0; J < dim; ++J)
            for (unsigned int L = 0; L < dim; ++L)
              A[i][J][i][L] = S[J][L];
        // The diagonal of D: the derivatives of the g_a.
        for (unsigned int a = 0; a < dim; ++a)
          for (unsigned int b = 0; b < dim; ++b)
            {
              const double D_ab =
                c.lambda / (2 * p.c[a] * p.c[b]) +
                (a == b ? (c.mu - p.T[a]) / (p.c[a] * p.c[a]) : 0.);
              A += 2 * D_ab *
                   outer_product(outer_product(p.f[a], p.n[a]),
                                 outer_product(p.f[b], p.n[b]));
            }
        // The pairs a != b: the divided differences.
        for (unsigned int a = 0; a < dim; ++a)
          for (unsigned int b = a + 1; b < dim; ++b)
            {
              const double         theta = divided_difference(p, a, b);
              const Tensor<2, dim> ab    = outer_product(p.f[a], p.n[b]),
                                   ba    = outer_product(p.f[b], p.n[a]);
              A += theta *
                   (outer_product(ab, ab + ba) + outer_product(ba, ba + ab));
            }
      }

      // A body in 3d has no out-of-plane direction: the Cauchy stress holds
      // sigma_33 (Material asks it there) and F is whole.
      double
      out_of_plane_stress(const Tensor<2, dim> &H) const override
      {
        return this->cauchy_stress(H)[dim - 1][dim - 1];
      }

      double
      thickness_stretch(const Tensor<2, dim> &) const override
      {
        return 1.0;
      }

    private:
      // The principal quantities of F = I + H.
      struct Principal
      {
        Principal(const Tensor<2, dim> &H, const ElasticConstants &k)
        {
          const Tensor<2, dim> F = unit_symmetric_tensor<dim>() + H;
          const auto           pairs =
            eigenvectors(symmetrize(H + transpose(H) + transpose(H) * H),
                         SymmetricTensorEigenvectorMethod::jacobi);
          const double log_J = std::log1p(det_F_minus_one(H));
          for (unsigned int a = 0; a < dim; ++a)
            {
              e[a]              = pairs[a].first;
              n[a]              = pairs[a].second;
              c[a]              = 1 + e[a];
              const double ln_c = std::log1p(e[a]);
              T[a]              = k.lambda * log_J + k.mu * ln_c;
              g[a]              = T[a] / c[a];
              f[a]              = F * n[a];
            }
        }

        // e_a = c_a - 1, the eigenvalues c_a of C, its eigenvectors n_a,
        // the principal stresses T_a, g_a = T_a / c_a and f_a = F n_a.
        std::array<double, dim>         e, c, T, g;
        std::array<Tensor<1, dim>, dim> n, f;
      };

      // Theta_ab with l_ab = log1p(x) / x / c_b, x = (e_a - e_b) / c_b;
      // log1p(x) / x by its series where x is small (to x^4: an error of
      // x^5 / 6, below round-off at |x| < 1e-3), 1 at x = 0.
      double
      divided_difference(const Principal   &p,
                         const unsigned int a,
                         const unsigned int b) const
      {
        const double x = (p.e[a] - p.e[b]) / p.c[b];
        const double log1p_over_x =
          std::abs(x) < 1e-3 ?
            1 + x * (-1. / 2 + x * (1. / 3 + x * (-1. / 4 + x / 5))) :
            std::log1p(x) / x;
        const double l_ab = log1p_over_x / p.c[b];
        return (c.mu * p.c[b] * l_ab - p.T[b]) / (p.c[a] * p.c[b]);
      }

      const ElasticConstants c;
    };
  } // namespace

  // The registration line: Material law = Hencky (the former Kinematics =
  // logarithmic strain).
  namespace
  {
    const MaterialLaws::Add registration{
      MaterialLawRegistration::of<LogarithmicStrain>(
        "Hencky",
        {"logarithmic strain"},
        "the linear law on the logarithmic strain ln(C)/2 (current "
        "Code_Aster's GDEF_LOG; in plane stress the out-of-plane stress "
        "conjugate to it is zero).",
        false)};
  } // namespace
} // namespace RingContact
