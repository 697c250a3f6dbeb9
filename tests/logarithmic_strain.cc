// The logarithmic-strain (Hencky) law against an independent computation:
// the Kirchhoff stress tau = lambda tr(ln V) I + 2 mu ln V with ln V = ln(B)
// / 2 from the eigenvectors of B = F F^T (deal.II's eigenvectors()), and
// P = tau F^-T; the law computes P from a closed form in F without
// eigenvectors (logarithmic_strain.cc). Checked, in plane strain and plane
// stress, for stretches up to 2.7 and 0.4, shears, rotations, a pure
// dilatation (the two eigenvalues equal, where the spectral formulas divide
// by zero) and states within 1e-9 of it (the law's series branch), and
// 1e-7 and 1e-9 strains:
// - P against tau F^-T, relative to |P| (plane stress: lambda* in place of
//   lambda, the out-of-plane stress conjugate to ln(F33) zero);
// - the tangent dP/dH against central differences of P;
// - objectivity: P(Q F) = Q P(F) for a rotation Q, the Cauchy stress
//   symmetric;
// - the out of plane: plane strain sigma33 = lambda ln J / J; plane stress
//   T33 = lambda (ln J + ln F33) + 2 mu ln F33 = 0;
// - at 1e-7 and 1e-9 strains, linear elasticity to 10 |H| (relative; the
//   quadratic terms are of that size; before N was written in H, the
//   round-off at 1e-9 was 100 times that).
#include <deal.II/base/symmetric_tensor.h>

#include <ring_contact/materials/material.h>

#include "tests.h"

#include <cmath>
#include <iomanip>
#include <vector>

using namespace RingContact;
using RingContactTests::check;

namespace
{
  double
  norm_of(const Tensor<2, 2> &t)
  {
    return t.norm();
  }

  // P from the eigenvectors of B: the independent computation.
  Tensor<2, 2>
  spectral_stress(const Tensor<2, 2> &H, const double lambda, const double mu)
  {
    const Tensor<2, 2> F = unit_symmetric_tensor<2>() + H;
    const auto B = symmetrize(F * transpose(F)); // symmetric by construction
    SymmetricTensor<2, 2> log_V;
    for (const auto &[b, n] : eigenvectors(B))
      log_V += 0.5 * std::log(b) * symmetrize(outer_product(n, n));
    const Tensor<2, 2> tau =
      lambda * trace(log_V) * unit_symmetric_tensor<2>() +
      2 * mu * Tensor<2, 2>(log_V);
    return tau * transpose(invert(F));
  }

  Tensor<2, 2>
  rotation(const double angle)
  {
    Tensor<2, 2> Q;
    Q[0][0] = Q[1][1] = std::cos(angle);
    Q[1][0]           = std::sin(angle);
    Q[0][1]           = -Q[1][0];
    return Q;
  }
} // namespace

int
main()
{
  auto &out = RingContactTests::deallog_file;
  // Grad u of the states checked.
  std::vector<std::pair<std::string, Tensor<2, 2>>> states;
  const auto add = [&](const std::string &name,
                       const double       a,
                       const double       b,
                       const double       c,
                       const double       d) {
    Tensor<2, 2> H;
    H[0][0] = a;
    H[0][1] = b;
    H[1][0] = c;
    H[1][1] = d;
    states.emplace_back(name, H);
  };
  add("stretch 2.7 x 0.4", 1.7, 0, 0, -0.6);
  add("shear 0.5", 0, 0.5, 0, 0);
  add("general", 0.3, -0.2, 0.15, -0.1);
  add("compression and shear", -0.35, 0.25, -0.05, 0.1);
  {
    // A stretch of 1.3 x 0.8 turned by 40 degrees: F = Q U.
    Tensor<2, 2> U;
    U[0][0] = 1.3;
    U[1][1] = 0.8;
    states.emplace_back("stretch turned by 40 degrees",
                        rotation(40 * M_PI / 180) * U -
                          Tensor<2, 2>(unit_symmetric_tensor<2>()));
  }
  add("pure dilatation 1.2", 0.2, 0, 0, 0.2);
  add("dilatation 1.2 and 1e-9 shear", 0.2, 1e-9, 0, 0.2);
  add("dilatation 1.2 and 1e-5 stretch", 0.2 + 1e-5, 0, 0, 0.2);
  add("1e-7 strain", 1e-7, 3e-8, -2e-8, -5e-8);
  add("1e-9 strain", 1e-9, 3e-10, -2e-10, -5e-10);

  const double E = 1e9, nu = 0.3;
  for (const auto plane :
       {PlaneAssumption::plane_strain, PlaneAssumption::plane_stress})
    {
      const Material<2>      material(E, nu, plane, "logarithmic strain");
      const ElasticConstants c(E, nu, plane);
      const std::string plane_name = plane == PlaneAssumption::plane_strain ?
                                       "plane strain" :
                                       "plane stress";
      double worst_stress = 0, worst_tangent = 0, worst_objectivity = 0,
             worst_symmetry = 0, worst_out_of_plane = 0, worst_linear = 0;
      for (const auto &[name, H] : states)
        {
          const Tensor<2, 2> P     = material.stress(H);
          const double       scale = std::max(norm_of(P), 1e-300);
          // The spectral form: lambda is the in-plane law's (lambda* in
          // plane stress).
          const Tensor<2, 2> P_ref = spectral_stress(H, c.lambda, c.mu);
          const bool         at_small_strain = norm_of(H) < 1e-6;
          if (at_small_strain)
            {
              // Linear elasticity, to the second order of the strain.
              const Tensor<2, 2> linear =
                c.lambda * trace(H) * unit_symmetric_tensor<2>() +
                c.mu * (H + transpose(H));
              // Relative to the strain: the quadratic terms are of its size,
              // the round-off of a law that cancels O(1) terms far above.
              worst_linear = std::max(worst_linear,
                                      norm_of(P - linear) / scale / norm_of(H));
            }
          else
            worst_stress = std::max(worst_stress, norm_of(P - P_ref) / scale);

          // The tangent against central differences of P.
          Tensor<2, 2> P0;
          Tensor<4, 2> A;
          material.stress_and_tangent(H, P0, A);
          check((P0 - P).norm() <= 1e-14 * scale,
                "stress_and_tangent gives stress()'s P");
          const double h          = 1e-6 * std::max(1.0, norm_of(H));
          double       difference = 0, size = 0;
          for (unsigned int k = 0; k < 2; ++k)
            for (unsigned int L = 0; L < 2; ++L)
              {
                Tensor<2, 2> Hp = H, Hm = H;
                Hp[k][L] += h;
                Hm[k][L] -= h;
                const Tensor<2, 2> dP =
                  (material.stress(Hp) - material.stress(Hm)) / (2 * h);
                for (unsigned int i = 0; i < 2; ++i)
                  for (unsigned int J = 0; J < 2; ++J)
                    {
                      difference = std::max(difference,
                                            std::abs(dP[i][J] - A[i][J][k][L]));
                      size       = std::max(size, std::abs(A[i][J][k][L]));
                    }
              }
          worst_tangent = std::max(worst_tangent, difference / size);

          // Objectivity (at finite strain: Q F - I of a 1e-7 strain holds
          // the strain to 9 digits only) and a symmetric Cauchy stress.
          const Tensor<2, 2> Q = rotation(0.7);
          const Tensor<2, 2> F = unit_symmetric_tensor<2>() + H;
          const Tensor<2, 2> P_turned =
            material.stress(Q * F - Tensor<2, 2>(unit_symmetric_tensor<2>()));
          if (!at_small_strain)
            worst_objectivity =
              std::max(worst_objectivity, norm_of(P_turned - Q * P) / scale);
          const Tensor<2, 2> sigma = material.cauchy_stress(H);
          worst_symmetry           = std::max(worst_symmetry,
                                    std::abs(sigma[0][1] - sigma[1][0]) /
                                      std::max(sigma.norm(), 1e-300));

          // Out of plane.
          const double J     = determinant(F);
          const double log_J = std::log1p(
            H[0][0] + H[1][1] + H[0][0] * H[1][1] - H[0][1] * H[1][0]);
          if (plane == PlaneAssumption::plane_strain)
            {
              const double expected = c.lambda_3d * log_J / J;
              worst_out_of_plane =
                std::max(worst_out_of_plane,
                         std::abs(material.out_of_plane_stress(H) - expected) /
                           std::max(scale, std::abs(expected)));
              check(material.thickness_stretch(H) == 1,
                    "plane strain: F33 = 1");
            }
          else if (!at_small_strain) // F33 = 1 + 1e-7 holds E33 to 9 digits
            {
              const double E33 = std::log(material.thickness_stretch(H));
              const double T33 = c.lambda_3d * (log_J + E33) + 2 * c.mu * E33;
              worst_out_of_plane =
                std::max(worst_out_of_plane, std::abs(T33) / scale);
            }
          if (plane == PlaneAssumption::plane_stress)
            check(material.out_of_plane_stress(H) == 0,
                  "plane stress: sigma33 = 0");
        }
      out << std::scientific << std::setprecision(0) << plane_name << ", "
          << states.size() << " states: P against the spectral form "
          << (worst_stress < 1e-12 ? "< 1e-12" : "FAILS")
          << ", tangent against differences "
          << (worst_tangent < 1e-7 ? "< 1e-7" : "FAILS") << ", objectivity "
          << (worst_objectivity < 1e-13 ? "< 1e-13" : "FAILS")
          << ", Cauchy stress symmetric "
          << (worst_symmetry < 1e-13 ? "< 1e-13" : "FAILS") << ", out of plane "
          << (worst_out_of_plane < 1e-12 ? "< 1e-12" : "FAILS")
          << ", at 1e-7 and 1e-9 strain linear elasticity to 10 |H| "
          << (worst_linear < 10 ? "yes" : "FAILS") << std::endl;
      std::cout << plane_name << ": stress " << worst_stress << ", tangent "
                << worst_tangent << ", objectivity " << worst_objectivity
                << ", symmetry " << worst_symmetry << ", out of plane "
                << worst_out_of_plane << ", linear " << worst_linear
                << std::endl;
      check(worst_stress < 1e-12, plane_name + ": P is the Hencky stress");
      check(worst_tangent < 1e-7, plane_name + ": the tangent is dP/dH");
      check(worst_objectivity < 1e-13, plane_name + ": P is objective");
      check(worst_symmetry < 1e-13, plane_name + ": sigma is symmetric");
      check(worst_out_of_plane < 1e-12,
            plane_name + ": the out-of-plane condition");
      check(worst_linear < 10,
            plane_name + ": linear elasticity at small strain");
    }
}
