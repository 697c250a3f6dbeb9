// The plane-stress thickness stretch F33 of every finite-strain law, under
// equibiaxial stretches s = 1 to 3 (and compressions down to 0.001), with
// nu = 0.1, 0.3 and 0.45:
// - Saint Venant-Kirchhoff against its closed form, F33^2 = 1 - 2 nu /
//   (1 - nu) (s^2 - 1), where that is positive; beyond s = sqrt(1 + (1 -
//   nu) / (2 nu)) (1.47 at nu = 0.3) sigma33 = 0 has no solution, and the
//   law says so: in_range() is false, thickness_stretch() throws a message
//   that names the bound (it returned the NaN of a square root, which
//   reached the Cauchy stress of the VTU files);
// - the neo-Hookean law against the residual sigma33 = 0, mu (F33^2 - 1) +
//   lambda ln(J2 F33) = 0, J2 = s^2, to 1e-12 of mu + lambda (its F33 is found
//   by a Newton iteration, kept within a bracket of the root);
// - Hencky against its closed form F33 = s^(-2 nu / (1 - nu)).
// Each law's Cauchy stress is finite wherever it is in range.
#include <ring_contact/materials/material.h>

#include "tests.h"

#include <cmath>
#include <iomanip>
#include <stdexcept>

using namespace RingContact;
using RingContactTests::check;

int
main()
{
  auto &out = RingContactTests::deallog_file;
  out << std::setprecision(6);
  const double E = 2e11;
  for (const double nu : {0.1, 0.3, 0.45})
    {
      const double lambda     = E * nu / ((1 + nu) * (1 - 2 * nu)),
                   mu         = E / (2 * (1 + nu));
      const double      ratio = nu / (1 - nu); // lambda / (lambda + 2 mu), 3d
      const Material<2> svk(E,
                            nu,
                            PlaneAssumption::plane_stress,
                            "finite strain");
      const Material<2> neo_hookean(E,
                                    nu,
                                    PlaneAssumption::plane_stress,
                                    "neo-Hookean");
      const Material<2> hencky(E,
                               nu,
                               PlaneAssumption::plane_stress,
                               "logarithmic strain");
      const double      svk_bound = std::sqrt(1 + 0.5 / ratio);
      out << "nu = " << nu
          << ": Saint Venant-Kirchhoff has F33 below s = " << svk_bound
          << std::endl;
      for (const double s :
           {0.001, 0.3, 0.7, 1.0, 1.25, 1.5, 1.75, 2.0, 2.25, 2.5, 2.75, 3.0})
        {
          Tensor<2, 2> H;
          H[0][0] = H[1][1] = s - 1;
          const std::string at =
            "nu = " + std::to_string(nu) + ", s = " + std::to_string(s);

          // Saint Venant-Kirchhoff: its closed form, or its refusal.
          const double       svk_squared = 1 - 2 * ratio * (s * s - 1);
          std::ostringstream svk_text;
          if (svk_squared > 0)
            {
              const double F33 = svk.thickness_stretch(H);
              check(svk.in_range(H) && std::abs(F33 - std::sqrt(svk_squared)) <=
                                         1e-14 * std::sqrt(svk_squared) + 1e-15,
                    "Saint Venant-Kirchhoff's F33, " + at);
              check(std::isfinite(svk.cauchy_stress(H).norm()),
                    "Saint Venant-Kirchhoff's Cauchy stress finite, " + at);
              svk_text << F33;
            }
          else
            {
              check(!svk.in_range(H),
                    "Saint Venant-Kirchhoff out of range, " + at);
              std::string message;
              try
                {
                  svk.thickness_stretch(H);
                }
              catch (const std::domain_error &e)
                {
                  message = e.what();
                }
              check(message.find("no thickness stretch here") !=
                        std::string::npos &&
                      message.find("equibiaxially") != std::string::npos,
                    "Saint Venant-Kirchhoff refuses, " + at + ": " + message);
              svk_text << "none";
            }

          // The neo-Hookean law: sigma33 = 0, with ln J2 as the law takes
          // it, log1p(tr H + det H) (at s = 0.001 its 1 - 1e-6 is known to
          // 1e-10 of J2 only, whatever F33).
          const double F33_nh = neo_hookean.thickness_stretch(H);
          const double residual =
            mu * (F33_nh * F33_nh - 1) +
            lambda * (std::log1p(trace(H) + determinant(H)) + std::log(F33_nh));
          check(std::isfinite(F33_nh) && F33_nh > 0 &&
                  std::abs(residual) <= 1e-12 * (mu + lambda) &&
                  neo_hookean.in_range(H) &&
                  std::isfinite(neo_hookean.cauchy_stress(H).norm()),
                "the neo-Hookean F33, " + at + ": residual " +
                  std::to_string(residual));

          // Hencky: the closed form, to the round-off of the law's
          // J2 = 1 + (tr H + det H), eps / J2 of itself.
          const double F33_h  = hencky.thickness_stretch(H);
          const double closed = std::pow(s, -2 * ratio);
          check(std::abs(F33_h - closed) <=
                    (1e-13 + 1e-15 / (s * s)) * closed &&
                  hencky.in_range(H) &&
                  std::isfinite(hencky.cauchy_stress(H).norm()),
                "Hencky's F33, " + at);
          out << "  s = " << std::setw(5) << s
              << ": F33 Saint Venant-Kirchhoff " << std::setw(11)
              << svk_text.str() << ", neo-Hookean " << std::setw(11) << F33_nh
              << ", Hencky " << std::setw(11) << F33_h << std::endl;
        }
    }
}
