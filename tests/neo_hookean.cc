// The neo-Hookean law against independent computations, in plane strain and
// plane stress, for stretches from 0.2 to 2.5, shears, rotations and 1e-7
// strains:
// - P against central differences of the stored energy
//   W = mu/2 (tr(F^T F) - 3 - 2 ln J) + lambda/2 (ln J)^2 (3d lambda), in
//   plane stress with F33 minimising W (dW/dF33 = P33 = 0: golden-section
//   search, so that the law's Newton iteration for F33 is not reused);
// - the tangent dP/dH against central differences of P;
// - objectivity: P(Q F) = Q P(F), the Cauchy stress symmetric;
// - the closed form of uniaxial strain, F = diag(s, 1) in plane strain:
//   P11 = mu (s - 1/s) + lambda ln(s) / s, P22 = lambda ln s,
//   sigma33 = lambda ln(s) / s;
// - at 1e-7 strain, linear elasticity to 10 |H| (relative);
// - in uniaxial strain the stress decreases monotonically down to s = 0.05
//   (Saint Venant-Kirchhoff's has a maximum at s = 0.58: its Newton
//   iteration finds no state beyond; the test shows it for comparison).
#include <ring_contact/materials/material.h>

#include "tests.h"

#include <cmath>
#include <functional>
#include <iomanip>
#include <vector>

using namespace RingContact;
using RingContactTests::check;

namespace
{
  Tensor<2, 2>
  rotation(const double angle)
  {
    Tensor<2, 2> Q;
    Q[0][0] = Q[1][1] = std::cos(angle);
    Q[1][0]           = std::sin(angle);
    Q[0][1]           = -Q[1][0];
    return Q;
  }

  // The 3d stored energy of F = [F2 0; 0 F33].
  double
  energy(const Tensor<2, 2> &F2,
         const double        F33,
         const double        lambda,
         const double        mu)
  {
    const double J  = determinant(F2) * F33;
    const double I1 = scalar_product(F2, F2) + F33 * F33;
    return 0.5 * mu * (I1 - 3 - 2 * std::log(J)) +
           0.5 * lambda * std::log(J) * std::log(J);
  }

  // Plane stress: W minimised over F33 (golden section on ln F33).
  double
  plane_stress_energy(const Tensor<2, 2> &F2,
                      const double        lambda,
                      const double        mu)
  {
    double       a = -3, b = 3;
    const double g = (std::sqrt(5.0) - 1) / 2;
    for (unsigned int it = 0; it < 200; ++it)
      {
        const double x1 = b - g * (b - a), x2 = a + g * (b - a);
        if (energy(F2, std::exp(x1), lambda, mu) <
            energy(F2, std::exp(x2), lambda, mu))
          b = x2;
        else
          a = x1;
      }
    return energy(F2, std::exp(0.5 * (a + b)), lambda, mu);
  }
} // namespace

int
main()
{
  auto &out = RingContactTests::deallog_file;
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
  add("stretch 2.5 x 0.4", 1.5, 0, 0, -0.6);
  add("compression 0.2", -0.8, 0, 0, 0);
  add("shear 0.5", 0, 0.5, 0, 0);
  add("general", 0.3, -0.2, 0.15, -0.1);
  add("compression and shear", -0.35, 0.25, -0.05, 0.1);
  {
    Tensor<2, 2> U;
    U[0][0] = 1.3;
    U[1][1] = 0.8;
    states.emplace_back("stretch turned by 40 degrees",
                        rotation(40 * M_PI / 180) * U -
                          Tensor<2, 2>(unit_symmetric_tensor<2>()));
  }

  const double E = 1e9, nu = 0.3;
  for (const auto plane :
       {PlaneAssumption::plane_strain, PlaneAssumption::plane_stress})
    {
      const Material<2>      material(E, nu, plane, "neo-Hookean");
      const ElasticConstants c(E, nu, plane);
      const double           lambda = c.lambda_3d, mu = c.mu;
      const std::string plane_name = plane == PlaneAssumption::plane_strain ?
                                       "plane strain" :
                                       "plane stress";
      const std::function<double(const Tensor<2, 2> &)> W =
        [&](const Tensor<2, 2> &F2) {
          return plane == PlaneAssumption::plane_strain ?
                   energy(F2, 1.0, lambda, mu) :
                   plane_stress_energy(F2, lambda, mu);
        };
      double worst_energy = 0, worst_tangent = 0, worst_objectivity = 0,
             worst_symmetry = 0, worst_out_of_plane = 0;
      for (const auto &[name, H] : states)
        {
          const Tensor<2, 2> F     = unit_symmetric_tensor<2>() + H;
          const Tensor<2, 2> P     = material.stress(H);
          const double       scale = P.norm();
          // P = dW/dF by central differences of the energy.
          const double h = 1e-4;
          for (unsigned int k = 0; k < 2; ++k)
            for (unsigned int L = 0; L < 2; ++L)
              {
                Tensor<2, 2> Fp = F, Fm = F;
                Fp[k][L] += h;
                Fm[k][L] -= h;
                worst_energy =
                  std::max(worst_energy,
                           std::abs((W(Fp) - W(Fm)) / (2 * h) - P[k][L]) /
                             scale);
              }
          // The tangent against central differences of P.
          Tensor<2, 2> P0;
          Tensor<4, 2> A;
          material.stress_and_tangent(H, P0, A);
          check((P0 - P).norm() <= 1e-14 * scale,
                "stress_and_tangent gives stress()'s P");
          double difference = 0, size = 0;
          for (unsigned int k = 0; k < 2; ++k)
            for (unsigned int L = 0; L < 2; ++L)
              {
                Tensor<2, 2> Hp = H, Hm = H;
                Hp[k][L] += 1e-6;
                Hm[k][L] -= 1e-6;
                const Tensor<2, 2> dP =
                  (material.stress(Hp) - material.stress(Hm)) / 2e-6;
                for (unsigned int i = 0; i < 2; ++i)
                  for (unsigned int J = 0; J < 2; ++J)
                    {
                      difference = std::max(difference,
                                            std::abs(dP[i][J] - A[i][J][k][L]));
                      size       = std::max(size, std::abs(A[i][J][k][L]));
                    }
              }
          worst_tangent = std::max(worst_tangent, difference / size);
          // Objectivity and the Cauchy stress's symmetry.
          const Tensor<2, 2> Q = rotation(0.7);
          const Tensor<2, 2> HQ =
            Q * F - Tensor<2, 2>(unit_symmetric_tensor<2>());
          worst_objectivity =
            std::max(worst_objectivity,
                     (material.stress(HQ) - Q * P).norm() / scale);
          const Tensor<2, 2> sigma = material.cauchy_stress(H);
          worst_symmetry =
            std::max(worst_symmetry,
                     (sigma - transpose(sigma)).norm() / sigma.norm());
          // Plane stress: P33 = mu (F33 - 1/F33) + lambda ln(J) / F33 = 0.
          if (plane == PlaneAssumption::plane_stress)
            {
              const double F33 = material.thickness_stretch(H);
              const double J   = determinant(F) * F33;
              worst_out_of_plane =
                std::max(worst_out_of_plane,
                         std::abs(mu * (F33 - 1 / F33) +
                                  lambda * std::log(J) / F33) /
                           scale);
            }
        }
      out << plane_name << ": P = dW/dF "
          << (worst_energy < 1e-6 ? "within 1e-6" : "NOT within 1e-6")
          << ", tangent "
          << (worst_tangent < 1e-6 ? "within 1e-6" : "NOT within 1e-6")
          << " of differences, objective "
          << (worst_objectivity < 1e-13 ? "to 1e-13" : "NOT to 1e-13")
          << ", Cauchy stress symmetric "
          << (worst_symmetry < 1e-13 ? "to 1e-13" : "NOT to 1e-13");
      if (plane == PlaneAssumption::plane_stress)
        out << ", P33 = 0 "
            << (worst_out_of_plane < 1e-13 ? "to 1e-13" : "NOT to 1e-13");
      out << std::endl;
      check(worst_energy < 1e-6, plane_name + ": P = dW/dF");
      check(worst_tangent < 1e-6, plane_name + ": the tangent");
      check(worst_objectivity < 1e-13, plane_name + ": objectivity");
      check(worst_symmetry < 1e-13, plane_name + ": sigma symmetric");
      check(worst_out_of_plane < 1e-13, plane_name + ": P33 = 0");

      // Small strain: linear elasticity (the in-plane lambda).
      Tensor<2, 2> H;
      H[0][0] = 1e-7;
      H[0][1] = 3e-8;
      H[1][0] = -2e-8;
      H[1][1] = -5e-8;
      const Tensor<2, 2> linear =
        c.lambda * trace(H) * unit_symmetric_tensor<2>() +
        c.mu * (H + transpose(H));
      const double small =
        (material.stress(H) - linear).norm() / linear.norm() / H.norm();
      out << plane_name << ": at 1e-7 strain, linear elasticity "
          << (small < 10 ? "to 10 |H|" : "NOT to 10 |H|") << std::endl;
      check(small < 10, plane_name + ": linear elasticity at small strain");
    }

  // Uniaxial strain in plane strain: the closed form, and the monotonic
  // stress down to s = 0.05 (SVK's maximum shown beside).
  const double      lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
  const double      mu     = E / (2 * (1 + nu));
  const Material<2> neo(E, nu, PlaneAssumption::plane_strain, "neo-Hookean");
  const Material<2> svk(E, nu, PlaneAssumption::plane_strain, "finite strain");
  double            worst     = 0;
  bool              monotonic = true;
  double            previous = 0, svk_previous = 0, svk_peak = 0;
  for (unsigned int n = 0; n <= 95; ++n)
    {
      const double s = 1 - 0.01 * n; // 1 down to 0.05
      Tensor<2, 2> H;
      H[0][0]              = s - 1;
      const Tensor<2, 2> P = neo.stress(H);
      worst                = std::max(
        {worst,
                        std::abs(P[0][0] - (mu * (s - 1 / s) + lambda * std::log(s) / s)) /
                          std::abs(P[0][0] + 1e-300),
                        std::abs(P[1][1] - lambda * std::log(s)) / std::abs(P[1][1] + 1e-300),
                        std::abs(neo.out_of_plane_stress(H) - lambda * std::log(s) / s) /
                          std::abs(lambda * std::log(s) / s + 1e-300)});
      if (n > 0 && !(P[0][0] < previous))
        monotonic = false;
      previous           = P[0][0];
      const double svk_P = svk.stress(H)[0][0];
      if (n > 0 && svk_P > svk_previous && svk_peak == 0)
        svk_peak = s + 0.01;
      svk_previous = svk_P;
    }
  out << "uniaxial strain s = 1 ... 0.05: P11, P22, sigma33 "
      << (worst < 1e-12 ? "within 1e-12" : "NOT within 1e-12")
      << " of the closed form; P11 "
      << (monotonic ? "decreases monotonically" : "does NOT decrease")
      << " (Saint Venant-Kirchhoff's turns back at s = " << std::setprecision(2)
      << svk_peak << ")" << std::endl;
  check(worst < 1e-12, "uniaxial strain: the closed form");
  check(monotonic, "uniaxial strain: monotonic");
}
