// A standing probe: randomised general problems, checked against the
// invariants the program must satisfy, not against stored numbers, so that
// a whole class of silent wrong answers is caught the next time one
// appears. Seeded, so that every run poses the same cases.
//
// Each case is one of the shipped gmsh models (two blocks, the two blocks
// turned with rollers along the turned sides, three blocks, a cylinder on a
// block) with random mesh densities, random bodies (Young's modulus over
// four decades, Poisson's ratio, degree 1 or 2, any of the four
// kinematics), a random contact scheme, friction or none, and a random load
// (its size relative to the softer body, a shear part where a support takes
// it, two to four steps). For every converged step:
// - each body is in equilibrium (applied loads, reactions and contact
//   forces) to 1e-6 of its forces, and each contact pair's forces on its
//   two bodies are equal and opposite to 1e-8 (the program's own checks,
//   equilibrium.h, read from the history);
// - the resultants of all the boundaries that are not contact surfaces
//   (int t ds over each, reactions and loads) sum to zero, component by
//   component, to 1e-6 of their magnitudes (what the Newton tolerance
//   leaves: the corner errors this catches were 7e-2): the resultants are
//   right at the corners where supports and loads meet;
// - every recorded number is finite.
// Every case must solve: a case that does not is a finding.
#include "run_problem.h"

#include <cmath>
#include <iomanip>
#include <random>

using RingContactTests::check;

namespace
{
  std::mt19937_64 generator(20261203);

  double
  uniform(const double a, const double b)
  {
    return std::uniform_real_distribution<double>(a, b)(generator);
  }

  double
  log_uniform(const double a, const double b)
  {
    return std::exp(uniform(std::log(a), std::log(b)));
  }

  unsigned int
  integer(const unsigned int a, const unsigned int b)
  {
    return std::uniform_int_distribution<unsigned int>(a, b)(generator);
  }

  template <typename T>
  const T &
  one_of(const std::vector<T> &choices)
  {
    return choices[integer(0, choices.size() - 1)];
  }

  struct Case
  {
    std::string               description;
    std::string               prm;
    std::vector<unsigned int> free_boundaries; ///< not contact surfaces
    unsigned int              n_bodies;
  };

  // Bodies 1..n with random materials and elements; returns their
  // subsections, and the smallest plane modulus in `softest`.
  std::string
  random_bodies(const unsigned int n, double &softest, std::string &summary)
  {
    std::ostringstream text;
    text << std::setprecision(6);
    softest = std::numeric_limits<double>::max();
    for (unsigned int b = 1; b <= n; ++b)
      {
        const double       E  = log_uniform(1e7, 1e11);
        const double       nu = uniform(0, 0.45);
        const unsigned int p  = integer(1, 2);
        const std::string  kinematics =
          one_of<std::string>({"small strain",
                               "finite strain",
                               "logarithmic strain",
                               "neo-Hookean"});
        softest = std::min(softest, E);
        text << "subsection Body " << b << "\n set Young's modulus = " << E
             << "\n set Poisson's ratio = " << nu
             << "\n set Displacement degree = " << p
             << "\n set Material law = " << kinematics << "\nend\n";
        summary += (b > 1 ? ", " : "") + kinematics + " Q" + std::to_string(p);
      }
    return text.str();
  }

  // Checks of the resultant force, x and y, of each boundary in `ids`
  // (at most 12 checks: y for all, x while there is room); their
  // quantities are summed by the probe, the checks themselves not
  // evaluated.
  std::string
  resultant_checks(const std::vector<unsigned int> &ids)
  {
    std::ostringstream text;
    unsigned int       k = 0;
    for (const char *component : {"y", "x"})
      for (const unsigned int id : ids)
        if (k < 12)
          text << "subsection Check " << ++k
               << "\n set Quantity = resultant force " << component
               << "\n set Boundary id = " << id
               << "\n set Reference = 0\n set Steps = none\nend\n";
    for (; k < 12; ++k)
      text << "subsection Check " << k + 1 << "\n set Quantity = none\nend\n";
    return text.str();
  }

  std::string
  common_choices(std::string &summary, const bool rotated)
  {
    const std::string scheme = one_of<std::string>(
      {"nodal", "Gauss 2", "Gauss 3", "segment-based 2", "segment-based 3"});
    // Friction only where the supports hold every body without it (the
    // rigid-body check is skipped with friction).
    const double mu = integer(0, 2) == 0 ? uniform(0.1, 0.5) : 0.0;
    summary += ", " + scheme + (mu > 0 ? ", friction" : "");
    std::ostringstream text;
    text << std::setprecision(6) << "subsection Contact\n set Integration "
         << "schemes = " << scheme << "\n set Friction coefficient = " << mu
         << "\nend\n"
         << "subsection Load program\n set Number of steps = " << integer(2, 4)
         << "\n set Time points =\nend\n";
    (void)rotated;
    return text.str();
  }

  Case
  two_blocks(const bool turned)
  {
    Case c;
    c.n_bodies = 2;
    double             softest;
    std::string        summary;
    const auto         bodies = random_bodies(2, softest, summary);
    const unsigned int nl = integer(2, 8), nu = integer(2, 9),
                       nh    = integer(1, 4);
    const double       angle = turned ? uniform(5, 60) : 0.0;
    const double       p     = softest * log_uniform(1e-5, 3e-4);
    const double       shear = turned ? 0.0 : uniform(-0.3, 0.3);
    std::ostringstream text;
    text << std::setprecision(6) << "include " RING_CONTACT_SOURCE_DIR "/prm/"
         << (turned ? "two_blocks_inclined.prm" : "two_blocks.prm")
         << "\nsubsection Mesh\n set Mesh file = " RING_CONTACT_SOURCE_DIR
            "/meshes/two_blocks.geo\n set Geo parameters = nl = "
         << nl << ", nu = " << nu << ", nh = " << nh;
    if (turned)
      text << ", angle = " << angle;
    text << "\nend\n" << bodies << common_choices(summary, turned);
    if (!turned)
      text << "subsection Boundary condition 1\n set Value = " << shear * p
           << " * t; " << -p << " * t\nend\n";
    else
      text << "subsection Problem\n set Constants = p = " << p << "\nend\n";
    c.free_boundaries = {11, 12, 13, 21, 22, 23};
    text << resultant_checks(c.free_boundaries);
    c.prm = text.str();
    std::ostringstream d;
    d << (turned ? "two blocks turned" : "two blocks") << " (" << nl << "/"
      << nu << " x " << nh << "), " << summary;
    c.description = d.str();
    return c;
  }

  Case
  three_blocks()
  {
    Case c;
    c.n_bodies = 3;
    double             softest;
    std::string        summary;
    const auto         bodies = random_bodies(3, softest, summary);
    const unsigned int nl = integer(2, 6), nm = integer(2, 7),
                       nu = integer(2, 6), nh = integer(1, 3);
    const double       p = softest * log_uniform(1e-5, 3e-4);
    std::ostringstream text;
    text << std::setprecision(6)
         << "include " RING_CONTACT_SOURCE_DIR "/prm/three_blocks.prm"
         << "\nsubsection Mesh\n set Mesh file = " RING_CONTACT_SOURCE_DIR
            "/meshes/three_blocks.geo\n set Geo parameters = nl = "
         << nl << ", nm = " << nm << ", nu = " << nu << ", nh = " << nh
         << "\nend\nsubsection Problem\n set Constants = p = " << p << "\nend\n"
         << bodies << common_choices(summary, false);
    c.free_boundaries = {21, 22, 23, 12, 13, 31, 32, 33};
    text << resultant_checks(c.free_boundaries);
    c.prm = text.str();
    std::ostringstream d;
    d << "three blocks (" << nl << "/" << nm << "/" << nu << " x " << nh
      << "), " << summary;
    c.description = d.str();
    return c;
  }

  Case
  cylinder_on_block()
  {
    Case c;
    c.n_bodies = 2;
    double             softest;
    std::string        summary;
    const auto         bodies = random_bodies(2, softest, summary);
    const double       h      = one_of<double>({0.05, 0.04, 0.03});
    std::ostringstream text;
    text << std::setprecision(6)
         << "include " RING_CONTACT_SOURCE_DIR "/prm/hertz.prm"
         << "\nsubsection Mesh\n set Mesh file = " RING_CONTACT_SOURCE_DIR
            "/meshes/hertz.geo\n set Geo parameters = h = "
         << h << "\nend\n"
         << bodies << common_choices(summary, false)
         << "subsection Problem\n set Constants = R = 1, a0 = 0.1, q = "
         << softest * log_uniform(1e-6, 1e-4) << "\nend\n";
    c.free_boundaries = {11, 12, 21, 22, 23};
    text << resultant_checks(c.free_boundaries);
    c.prm = text.str();
    std::ostringstream d;
    d << "cylinder on block (h = " << h << "), " << summary;
    c.description = d.str();
    return c;
  }
} // namespace

int
main()
{
  auto              &out     = RingContactTests::deallog_file;
  const unsigned int n_cases = 32;
  unsigned int       n_steps = 0;
  for (unsigned int k = 1; k <= n_cases; ++k)
    {
      const unsigned int family = integer(0, 3);
      const Case         c      = family == 0 ? two_blocks(false) :
                                  family == 1 ? two_blocks(true) :
                                  family == 2 ? three_blocks() :
                                                cylinder_on_block();
      const std::string  name   = "case " + std::to_string(k) + ": ";
      {
        std::ofstream prm("probe.prm");
        prm << c.prm
            << "\nsubsection Output\n set VTU interval = 0\n"
               " set Print timing = false\n set Write history = false\nend\n"
               "subsection Newton\n set Verbose = false\nend\n";
      }
      RingContact::Parameters parameters;
      try
        {
          parameters.read("probe.prm");
        }
      catch (const std::exception &e)
        {
          check(false, name + c.description + ": refused: " + e.what());
        }
      std::ostringstream                            log;
      RingContact::ContactProblem<RingContact::dim> problem(
        parameters, parameters.contact.schemes.front(), log);
      bool solved = false;
      try
        {
          solved = problem.run();
        }
      catch (const std::exception &e)
        {
          check(false, name + c.description + ": " + e.what());
        }
      check(solved,
            name + c.description + ": a step could not be solved:\n" +
              log.str());
      for (const auto &row : problem.history())
        {
          const std::string at =
            name + c.description + ", step " + std::to_string(row.step) + ": ";
          check(row.equilibrium_error <= 1e-6,
                at + "equilibrium " + std::to_string(row.equilibrium_error));
          check(std::isnan(row.action_reaction_error) ||
                  row.action_reaction_error <= 1e-8,
                at + "action and reaction " +
                  std::to_string(row.action_reaction_error));
          // The quantities: the y resultants of the free boundaries, then
          // the x ones (as many as fit in 12 checks).
          double       sum[2] = {0, 0}, magnitude[2] = {0, 0};
          unsigned int q = 0;
          for (unsigned int component : {1u, 0u})
            for (unsigned int b = 0;
                 b < c.free_boundaries.size() && q < row.trailing.size();
                 ++b, ++q)
              {
                const double value = row.trailing[q].second;
                check(std::isfinite(value), at + "a resultant is not finite");
                sum[component] += value;
                magnitude[component] += std::abs(value);
              }
          // x is summed only when every boundary's x resultant is there.
          const bool all_x =
            row.trailing.size() >= 2 * c.free_boundaries.size();
          for (unsigned int component = 0; component < 2; ++component)
            if (component == 1 || all_x)
              check(std::abs(sum[component]) <=
                      1e-6 * std::max(magnitude[component], 1e-300),
                    at + "the resultants of the boundaries sum to " +
                      std::to_string(sum[component] / magnitude[component]) +
                      " of their magnitudes in " +
                      (component == 0 ? "x" : "y") + ", of " +
                      std::to_string(magnitude[component]));
          ++n_steps;
        }
      out << name << c.description << ": " << problem.history().size()
          << " steps, invariants hold" << std::endl;
    }
  out << n_cases << " cases, " << n_steps
      << " converged steps, every invariant holds" << std::endl;
}
