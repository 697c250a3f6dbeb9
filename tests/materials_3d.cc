// The four material laws in three dimensions (issue 48, item 5), against
// what each must be:
// - a plane state (H with no third row or column, F33 = 1) gives the 2d
//   law in plane strain: P, the tangent A, sigma_33 and the von Mises
//   stress. For linear elasticity, Saint Venant-Kirchhoff and neo-Hookean
//   the 3d law is the 2d formula in three dimensions; for Hencky it is the
//   spectral form (eigenvectors of C), checked against the 2d closed form
//   that needs none;
// - Hencky at any F = Q diag(s) R^T against the closed form P = Q diag(T_a
//   / s_a) R^T, T_a = lambda ln(s1 s2 s3) + 2 mu ln s_a: stretches up to 2.5
//   and down to 0.4 (48 states: two of them equal, as (1, 1, s) and (1.2,
//   1.2, s), or all three, (1.2, 1.2, 1.2)), turned by two rotations;
// - the tangent of each law against central differences of P, at general
//   states and, for Hencky, where eigenvalues of C coincide (a pure
//   dilatation, a uniaxial stretch: two equal) or nearly so (1e-9 apart),
//   where its spectral formulas take their limits;
// - the major symmetry of A (the assembly computes the upper triangle),
//   objectivity P(Q F) = Q P(F), a symmetric Cauchy stress;
// - at strains of 1e-9 every finite-strain law is linear elasticity to 10
//   |H| relative to the stress (a law that loses the digits of small
//   strains, F^T F - I formed in F, exceeds it).
#include <deal.II/base/symmetric_tensor.h>

#include <ring_contact/materials/material.h>

#include "tests.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

using namespace RingContact;
using RingContactTests::check;

namespace
{
  const double E = 2e11, nu = 0.3;

  // A rotation by an angle about a unit axis (Rodrigues).
  Tensor<2, 3>
  rotation(const Tensor<1, 3> &axis, const double angle)
  {
    Tensor<2, 3> K;
    K[0][1] = -axis[2];
    K[0][2] = axis[1];
    K[1][0] = axis[2];
    K[1][2] = -axis[0];
    K[2][0] = -axis[1];
    K[2][1] = axis[0];
    return Tensor<2, 3>(unit_symmetric_tensor<3>()) + std::sin(angle) * K +
           (1 - std::cos(angle)) * K * K;
  }

  Tensor<1, 3>
  vector3(const double x, const double y, const double z)
  {
    Tensor<1, 3> v;
    v[0] = x;
    v[1] = y;
    v[2] = z;
    return v;
  }

  Tensor<1, 3>
  unit(const double x, const double y, const double z)
  {
    return vector3(x, y, z) / vector3(x, y, z).norm();
  }

  // The displacement gradient of F = Q diag(s) R^T.
  Tensor<2, 3>
  gradient(const Tensor<2, 3> &Q, const Tensor<1, 3> &s, const Tensor<2, 3> &R)
  {
    Tensor<2, 3> D;
    for (unsigned int a = 0; a < 3; ++a)
      D[a][a] = s[a];
    return Q * D * transpose(R) - Tensor<2, 3>(unit_symmetric_tensor<3>());
  }

  // The largest |dP/dH - A| of central differences, relative to |A|.
  template <int dim>
  double
  tangent_error(const Material<dim> &material, const Tensor<2, dim> &H)
  {
    Tensor<2, dim> P;
    Tensor<4, dim> A;
    material.stress_and_tangent(H, P, A);
    const double h          = 1e-6 * std::max(1.0, H.norm());
    double       difference = 0, size = 0;
    for (unsigned int k = 0; k < dim; ++k)
      for (unsigned int L = 0; L < dim; ++L)
        {
          Tensor<2, dim> Hp = H, Hm = H;
          Hp[k][L] += h;
          Hm[k][L] -= h;
          const Tensor<2, dim> dP =
            (material.stress(Hp) - material.stress(Hm)) / (2 * h);
          for (unsigned int i = 0; i < dim; ++i)
            for (unsigned int J = 0; J < dim; ++J)
              {
                difference =
                  std::max(difference, std::abs(dP[i][J] - A[i][J][k][L]));
                size = std::max(size, std::abs(A[i][J][k][L]));
              }
        }
    return difference / size;
  }

  // The largest |A_iJkL - A_kLiJ| relative to |A|.
  double
  asymmetry(const Tensor<4, 3> &A)
  {
    double difference = 0;
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int J = 0; J < 3; ++J)
        for (unsigned int k = 0; k < 3; ++k)
          for (unsigned int L = 0; L < 3; ++L)
            difference =
              std::max(difference, std::abs(A[i][J][k][L] - A[k][L][i][J]));
    return difference / A.norm();
  }

  // The states of the general checks.
  std::vector<std::pair<std::string, Tensor<2, 3>>>
  general_states()
  {
    std::vector<std::pair<std::string, Tensor<2, 3>>> states;
    Tensor<2, 3>                                      H;
    const double values[3][3] = {{0.12, -0.05, 0.03},
                                 {0.04, -0.08, 0.06},
                                 {-0.02, 0.07, 0.1}};
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = 0; j < 3; ++j)
        H[i][j] = values[i][j];
    states.emplace_back("a general gradient", H);
    states.emplace_back("a large one", 4 * H);
    const Tensor<2, 3> Q = rotation(unit(1, 2, 3), 0.9),
                       R = rotation(unit(-2, 1, 0.5), 0.4);
    states.emplace_back("stretches 2.5, 0.4, 1.3 turned",
                        gradient(Q, unit(2.5, 0.4, 1.3) * 2.7, R));
    states.emplace_back("a pure dilatation 1.2",
                        gradient(Q, vector3(1.2, 1.2, 1.2), Q));
    states.emplace_back("a uniaxial stretch 1.3",
                        gradient(Q, vector3(1.3, 1, 1), R));
    states.emplace_back("two stretches 1e-9 apart",
                        gradient(Q, vector3(1.1, 1.1 + 1e-9, 0.9), R));
    states.emplace_back("three stretches 1e-9 apart",
                        gradient(Q, vector3(1.1, 1.1 + 1e-9, 1.1 - 1e-9), R));
    return states;
  }

  // A plane state, H in the x-y plane, and its 2d gradient.
  std::pair<Tensor<2, 3>, Tensor<2, 2>>
  plane_state(const double h00,
              const double h01,
              const double h10,
              const double h11)
  {
    Tensor<2, 3> H3;
    Tensor<2, 2> H2;
    H3[0][0] = H2[0][0] = h00;
    H3[0][1] = H2[0][1] = h01;
    H3[1][0] = H2[1][0] = h10;
    H3[1][1] = H2[1][1] = h11;
    return {H3, H2};
  }

  // A 3d law at plane states against the 2d law in plane strain: the
  // largest difference of P, A, sigma_33 and the von Mises stress, each
  // relative to its size.
  double
  plane_difference(const std::string &law)
  {
    const Material<3> law_3d(E, nu, PlaneAssumption::plane_strain, law);
    const Material<2> law_2d(E, nu, PlaneAssumption::plane_strain, law);
    double            worst = 0;
    for (const auto &[H3, H2] : {plane_state(0.2, -0.1, 0.05, -0.15),
                                 plane_state(1.0, 0.3, -0.4, -0.5),
                                 plane_state(0.2, 0, 0, 0.2),
                                 plane_state(1e-9, 3e-10, -2e-10, -5e-10)})
      {
        Tensor<2, 3> P3;
        Tensor<4, 3> A3;
        Tensor<2, 2> P2;
        Tensor<4, 2> A2;
        law_3d.stress_and_tangent(H3, P3, A3);
        law_2d.stress_and_tangent(H2, P2, A2);
        double dP = 0, dA = 0;
        for (unsigned int i = 0; i < 2; ++i)
          for (unsigned int J = 0; J < 2; ++J)
            {
              dP = std::max(dP, std::abs(P3[i][J] - P2[i][J]) / P3.norm());
              for (unsigned int k = 0; k < 2; ++k)
                for (unsigned int L = 0; L < 2; ++L)
                  dA = std::max(dA,
                                std::abs(A3[i][J][k][L] - A2[i][J][k][L]) /
                                  A3.norm());
            }
        const double sigma_33 = law_3d.out_of_plane_stress(H3),
                     expected = law_2d.out_of_plane_stress(H2);
        const double d33 =
          std::abs(sigma_33 - expected) / law_3d.cauchy_stress(H3).norm();
        const double dvm =
          std::abs(law_3d.von_mises_stress(H3) - law_2d.von_mises_stress(H2)) /
          law_2d.von_mises_stress(H2);
        worst = std::max({worst, dP, dA, d33, dvm});
      }
    return worst;
  }
} // namespace

int
main()
{
  std::ofstream                  out("output");
  const std::vector<std::string> laws = {"linear elasticity",
                                         "Saint Venant-Kirchhoff",
                                         "neo-Hookean",
                                         "Hencky"};
  const Tensor<2, 3>             Q    = rotation(unit(0.3, -1, 0.2), 2.1);

  // Each law: the plane states, then the general ones.
  for (const std::string &law : laws)
    {
      const double      plane = plane_difference(law);
      const Material<3> material(E, nu, PlaneAssumption::plane_strain, law);
      double worst_tangent = 0, worst_symmetry = 0, worst_objectivity = 0,
             worst_cauchy = 0;
      for (const auto &[name, H] : general_states())
        {
          worst_tangent = std::max(worst_tangent, tangent_error(material, H));
          Tensor<2, 3> P;
          Tensor<4, 3> A;
          material.stress_and_tangent(H, P, A);
          check((P - material.stress(H)).norm() <= 1e-14 * P.norm(),
                law + ", " + name + ": stress_and_tangent gives stress()'s P");
          worst_symmetry       = std::max(worst_symmetry, asymmetry(A));
          const Tensor<2, 3> F = unit_symmetric_tensor<3>() + H;
          const Tensor<2, 3> turned =
            material.stress(Q * F - Tensor<2, 3>(unit_symmetric_tensor<3>()));
          // Linear elasticity is not objective: it is checked for the rest.
          if (law != "linear elasticity")
            worst_objectivity =
              std::max(worst_objectivity, (turned - Q * P).norm() / P.norm());
          const Tensor<2, 3> sigma = material.cauchy_stress(H);
          worst_cauchy =
            std::max(worst_cauchy,
                     (sigma - transpose(sigma)).norm() / sigma.norm());
        }
      // At a strain of 1e-9, linear elasticity.
      Tensor<2, 3> H;
      const double small[3][3] = {{1e-9, 3e-10, -2e-10},
                                  {-4e-10, -5e-10, 1e-10},
                                  {2e-10, 6e-10, 7e-10}};
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          H[i][j] = small[i][j];
      const Material<3>  linear(E,
                               nu,
                               PlaneAssumption::plane_strain,
                               "linear elasticity");
      const Tensor<2, 3> P = material.stress(H);
      const double       to_linear =
        (P - linear.stress(H)).norm() / P.norm() / H.norm();

      std::cout << law << ": plane " << plane << ", tangent " << worst_tangent
                << ", major symmetry " << worst_symmetry << ", objectivity "
                << worst_objectivity << ", Cauchy symmetry " << worst_cauchy
                << ", small strain " << to_linear << std::endl;
      out << std::scientific << std::setprecision(0) << law
          << " in 3d: plane states = the 2d law in plane strain "
          << (plane < 1e-12 ? "< 1e-12" : "FAILS") << "; at "
          << general_states().size() << " states tangent against differences "
          << (worst_tangent < 1e-7 ? "< 1e-7" : "FAILS") << ", major symmetry "
          << (worst_symmetry < 1e-14 ? "< 1e-14" : "FAILS") << ", objectivity "
          << (worst_objectivity < 1e-13 ? "< 1e-13" : "FAILS")
          << ", Cauchy stress symmetric "
          << (worst_cauchy < 1e-13 ? "< 1e-13" : "FAILS")
          << "; at 1e-9 strain linear elasticity to 10 |H| "
          << (to_linear < 10 ? "yes" : "FAILS") << std::endl;
      check(plane < 1e-12, law + ": a plane state is the 2d law's");
      check(worst_tangent < 1e-7, law + ": the tangent is dP/dH");
      check(worst_symmetry < 1e-14, law + ": the tangent is major-symmetric");
      check(worst_objectivity < 1e-13, law + ": P is objective");
      check(worst_cauchy < 1e-13, law + ": sigma is symmetric");
      check(to_linear < 10, law + ": linear elasticity at small strain");
    }

  // Hencky against its closed form at F = Q diag(s) R^T.
  const Material<3> hencky(E, nu, PlaneAssumption::plane_strain, "Hencky");
  const double      lambda = E * nu / ((1 + nu) * (1 - 2 * nu)),
               mu          = E / (2 * (1 + nu));
  const Tensor<2, 3> R     = rotation(unit(2, -1, 3), 1.3);
  double             worst = 0;
  unsigned int       n     = 0;
  for (const double s1 : {0.4, 1.0, 1.2, 2.5})
    for (const double s2 : {0.6, 1.0, 1.2, 2.0})
      for (const double s3 : {0.8, 1.2, 1.5})
        {
          const Tensor<1, 3> s     = vector3(s1, s2, s3);
          const double       log_J = std::log(s1 * s2 * s3);
          Tensor<2, 3>       D;
          for (unsigned int a = 0; a < 3; ++a)
            D[a][a] = (lambda * log_J + 2 * mu * std::log(s[a])) / s[a];
          const Tensor<2, 3> expected = Q * D * transpose(R);
          const Tensor<2, 3> P        = hencky.stress(gradient(Q, s, R));
          worst = std::max(worst, (P - expected).norm() / expected.norm());
          ++n;
        }
  std::cout << "Hencky against Q diag(T / s) R^T: " << worst << std::endl;
  out << "Hencky at " << n
      << " stretches (0.4 to 2.5) turned by two rotations: P = Q diag(T_a / "
         "s_a) R^T "
      << (worst < 1e-13 ? "< 1e-13" : "FAILS") << std::endl;
  check(worst < 1e-13, "Hencky is the closed form at principal stretches");
}
