// Coulomb friction on SSNP152's turning rings (modelisation C's load
// program, small strain), against the closed form of doc/theory.md. While
// the rings stick, the inner boundary's rotation alpha is carried by the
// torsion of the two annuli: u_theta = a r + b / r in each ring, the shear
// tau = -2 G b / r^2, with u_theta = (R3 + f(R3)) sin(alpha) on r = R3 (the
// imposed motion), 0 on r = R1, u_theta and tau continuous at r = R2. The
// slave's tangential traction is tau(R2) = K sin(alpha). The rings slide
// once |tau| reaches mu sigma_n, at sin(alpha_s) = mu sigma_n / |K|, and
// then the traction is -mu sigma_n everywhere on the interface, sigma_n
// being Lame's for the radial data the rotation imposes in small strain:
// u_r(R1) = f(R1), u_r(R3) = (R3 + f(R3)) cos(alpha) - R3.
//
// For four ring pairs (C's, C's in plane strain, D's materials, steel on
// aluminium in plane strain with radii 2, 1.5, 0.8), three
// friction coefficients and three integration schemes, on C's mesh refined
// once (80 around), and with mu = 0.2 the element mixes of E, F and G
// (the slave on the outer ring in E: the traction's sign is the same, the
// master's tangent turning with its normal): the traction at node A while
// sticking within 1 % of K sin(alpha) at every stick step; no node sliding at
// 0.92 alpha_s, every node at 1.08 alpha_s; the sliding traction -mu p_A at the
// node to 1e-9 and within 1 % of -mu sigma_n. And the stick traction's mesh
// convergence: second order (error ratio above 3 per refinement, C, nodal).
#include <deal.II/lac/full_matrix.h>

#include <ring_contact/scenarios/ssnp152/analytic_solution.h>

#include "run_problem.h"

#include <cmath>
#include <iomanip>

using namespace RingContact;
using RingContactTests::check;

namespace
{
  struct Rings
  {
    std::string name;
    double      E_outer, nu_outer, E_inner, nu_inner;
    std::string plane;
    double      R1 = 1.0, R2 = 0.6, R3 = 0.2; ///< SSNP152's radii
    /// The modelisation whose file gives the elements and the slave side.
    char modelisation = 'c';
  };

  // The closed form: tau(R2) / sin(alpha) for the imposed radius R3 + f3.
  double
  torsion_stiffness(const Rings            &rings,
                    const AnalyticSolution &analytic,
                    const double            p)
  {
    const double R1 = analytic.R1, R2 = analytic.R2, R3 = analytic.R3;
    const double G1 = rings.E_outer / (2 * (1 + rings.nu_outer));
    const double G2 = rings.E_inner / (2 * (1 + rings.nu_inner));
    const double U3 = R3 + analytic.f_R3(p); // times sin(alpha)
    // Inner ring: a2 R3 + b2 / R3 = U3; outer: a1 R1 + b1 / R1 = 0; shear
    // G2 b2 = G1 b1; u_theta continuous at R2.
    const double b2 =
      U3 * R2 / R3 /
      ((R2 / (R3 * R3) - 1 / R2) + (G2 / G1) * (1 / R2 - R2 / (R1 * R1)));
    return -2 * G2 * b2 / (R2 * R2);
  }

  // Lame: u_r = a r + b / r in each ring, sigma_rr = C ((1 + nu) a - (1 -
  // nu) b / r^2), C = E / (1 - nu^2) (plane stress; plane strain with
  // E / (1 - nu^2) and nu / (1 - nu)); u_r imposed on R1 and R3, u_r and
  // sigma_rr continuous at R2. Returns sigma_n = -sigma_rr(R2).
  double
  lame_contact_pressure(const Rings &rings, const double f1, const double f3)
  {
    const double R1 = rings.R1, R2 = rings.R2, R3 = rings.R3;
    const bool   strain    = rings.plane == "plane strain";
    const auto   constants = [&](const double E, const double nu) {
      const double Ee = strain ? E / (1 - nu * nu) : E;
      const double ne = strain ? nu / (1 - nu) : nu;
      return std::make_pair(Ee / (1 - ne * ne), ne);
    };
    const auto [C1, n1] = constants(rings.E_outer, rings.nu_outer);
    const auto [C2, n2] = constants(rings.E_inner, rings.nu_inner);
    // Unknowns a1, b1 (outer ring), a2, b2 (inner ring).
    FullMatrix<double> M(4, 4);
    M(0, 0) = R1, M(0, 1) = 1 / R1;
    M(1, 2) = R3, M(1, 3) = 1 / R3;
    M(2, 0) = R2, M(2, 1) = 1 / R2, M(2, 2) = -R2, M(2, 3) = -1 / R2;
    M(3, 0) = C1 * (1 + n1), M(3, 1) = -C1 * (1 - n1) / (R2 * R2);
    M(3, 2) = -C2 * (1 + n2), M(3, 3) = C2 * (1 - n2) / (R2 * R2);
    M.gauss_jordan();
    const double a2 = M(2, 0) * f1 + M(2, 1) * f3;
    const double b2 = M(3, 0) * f1 + M(3, 1) * f3;
    return -C2 * ((1 + n2) * a2 - (1 - n2) * b2 / (R2 * R2));
  }

  std::string
  prm_text(const Rings       &rings,
           const double       mu,
           const std::string &scheme,
           const unsigned int refinements,
           const double       final_alpha,
           const unsigned int steps)
  {
    const double       around = 40 * (1u << refinements);
    std::ostringstream prm;
    prm << std::setprecision(17)
        << "subsection Mesh\n set Global refinements = " << refinements
        << "\n set Outer radius = " << rings.R1
        << "\n set Interface radius = " << rings.R2
        << "\n set Inner radius = " << rings.R3 << "\nend\n"
        << "subsection Materials\n"
        << " set Young's modulus outer ring = " << rings.E_outer << '\n'
        << " set Poisson's ratio outer ring = " << rings.nu_outer << '\n'
        << " set Young's modulus inner ring = " << rings.E_inner << '\n'
        << " set Poisson's ratio inner ring = " << rings.nu_inner << '\n'
        << " set Material law = linear elasticity\n"
        << " set Plane assumption = " << rings.plane << "\nend\n"
        << "subsection Contact\n set Integration schemes = " << scheme
        << "\n set Friction coefficient = " << mu << "\nend\n"
        << "subsection Load program\n set Rotation steps = " << steps
        << "\n set Rotation in elements = "
        << final_alpha * around / (2 * numbers::PI) << "\nend\n";
    return RingContactTests::modelisation(rings.modelisation, prm.str());
  }

  AnalyticSolution
  analytic_for(const Rings &rings)
  {
    return AnalyticSolution(rings.R1,
                            rings.R2,
                            rings.R3,
                            rings.E_outer,
                            rings.nu_outer,
                            rings.E_inner,
                            rings.nu_inner,
                            rings.plane == "plane strain" ?
                              PlaneAssumption::plane_strain :
                              PlaneAssumption::plane_stress);
  }
} // namespace

int
main()
{
  const double             p          = 1e7; // C's rotation pressure
  const std::vector<Rings> ring_pairs = {
    {"C", 1e9, 0.2, 1e9, 0.2, "plane stress"},
    {"C plane strain", 1e9, 0.2, 1e9, 0.2, "plane strain"},
    {"D", 1e9, 0.3, 1e8, 0.2, "plane stress"},
    {"steel on aluminium, radii 2/1.5/0.8",
     2e11,
     0.3,
     7e10,
     0.33,
     "plane strain",
     2.0,
     1.5,
     0.8},
    // The element mixes of E (outer ring Q1 and slave, inner Q2), F (outer
    // Q2, inner Q1 and slave) and G (both Q2, curved), with mu = 0.2.
    {"E's elements", 1e9, 0.2, 1e9, 0.2, "plane stress", 1.0, 0.6, 0.2, 'e'},
    {"F's elements", 1e9, 0.2, 1e9, 0.2, "plane stress", 1.0, 0.6, 0.2, 'f'},
    {"G's elements", 1e9, 0.2, 1e9, 0.2, "plane stress", 1.0, 0.6, 0.2, 'g'}};
  auto &log = RingContactTests::deallog_file;
  log << std::scientific << std::setprecision(2);

  // The stick traction's mesh convergence (C, nodal): alpha = 1e-4.
  {
    const Rings           &rings    = ring_pairs[0];
    const AnalyticSolution analytic = analytic_for(rings);
    const double alpha = 1e-4, K = torsion_stiffness(rings, analytic, p);
    double       previous = 0;
    for (unsigned int refinements = 0; refinements < 3; ++refinements)
      {
        const auto history = RingContactTests::run_problem(
          "friction_convergence",
          prm_text(rings, 0.5, "nodal", refinements, alpha, 1));
        const double error =
          std::abs(history.back().value("tangential_traction_A") / (K * std::sin(alpha)) - 1);
        log << "C, nodal, " << 40 * (1u << refinements)
            << " around: stick traction error " << error;
        if (refinements > 0)
          {
            log << " (ratio " << std::fixed << std::setprecision(1)
                << previous / error << std::scientific << std::setprecision(2)
                << ")";
            check(previous / error > 3,
                  "stick traction converges at second order");
          }
        log << std::endl;
        previous = error;
      }
    check(previous < 2e-3, "stick traction within 0.2 % at 160 around");
  }

  for (const Rings &rings : ring_pairs)
    for (const double mu : {0.05, 0.2, 0.5})
      for (const std::string scheme : {"nodal", "Gauss 2", "segment-based 2"})
        {
          if (rings.modelisation != 'c' && mu != 0.2)
            continue;
          const AnalyticSolution analytic = analytic_for(rings);
          const double           sigma_n  = analytic.contact_pressure(p);
          const double           f1 = analytic.f_R1(p), f3 = analytic.f_R3(p);
          check(std::abs(lame_contact_pressure(rings, f1, f3) / sigma_n - 1) <
                  1e-12,
                "Lame's sigma_n from the imposed displacements");
          const double K       = torsion_stiffness(rings, analytic, p);
          const double alpha_s = std::asin(mu * sigma_n / std::abs(K));
          // Twelve steps, the onset in the middle of the seventh.
          const unsigned int steps   = 12;
          const double       alpha_f = alpha_s * steps / 6.5;
          const auto         history = RingContactTests::run_problem(
            "friction_torsion", prm_text(rings, mu, scheme, 1, alpha_f, steps));
          const std::string case_name = rings.name + ", mu " +
                                        std::to_string(mu).substr(0, 4) + ", " +
                                        scheme;
          check(history.size() == steps, case_name + ": every step");
          double       stick_error = 0, slide_error = 0, slide_exact = 0;
          unsigned int most_iterations = 0;
          for (unsigned int k = 0; k < steps; ++k)
            {
              const auto        &row      = history[k];
              const double       traction = row.value("tangential_traction_A");
              const unsigned int sliding  = row.value("slipping_nodes");
              const double       alpha    = alpha_f * (k + 1) / steps;
              most_iterations =
                std::max(most_iterations, row.newton_iterations);
              if (k + 1 <= 6)
                {
                  check(sliding == 0,
                        case_name + ": no node slides before alpha_s");
                  stick_error =
                    std::max(stick_error,
                             std::abs(traction / (K * std::sin(alpha)) - 1));
                }
              else
                {
                  check(sliding == row.active_nodes && sliding > 0,
                        case_name + ": every node slides after alpha_s");
                  slide_exact =
                    std::max(slide_exact,
                             std::abs(traction / (-mu * row.value("pressure_A")) - 1));
                  const double R3 = rings.R3;
                  const double sigma_n_alpha =
                    lame_contact_pressure(rings,
                                          f1,
                                          (R3 + f3) * std::cos(alpha) - R3);
                  slide_error =
                    std::max(slide_error,
                             std::abs(traction / (-mu * sigma_n_alpha) - 1));
                }
            }
          check(stick_error < 0.01, case_name + ": stick traction within 1 %");
          check(slide_exact < 1e-9, case_name + ": sliding traction = -mu p_A");
          check(slide_error < 0.01,
                case_name + ": sliding traction within 1 % of -mu sigma_n");
          log << std::left << std::setw(34) << case_name << " alpha_s "
              << alpha_s << "  stick " << stick_error << "  slide "
              << slide_error << "  Newton <= " << most_iterations << std::endl;
        }
}
