// Coulomb friction with a large coefficient: the discrete problem has more
// than one solution, and the one Newton's method finds need not be the one
// sought. The frictional contact patch test of prm/two_blocks_friction.prm
// (5 against 7 segments, segment-based 2, sliding throughout: the upper
// block's bottom is moved 5e-2 along the interface, faster than the lower
// block's top) has a uniform exact solution for any mu: the pressure p t and
// the traction -mu p t at every node. Up to mu = 1.4 the run finds it; at
// mu = 2 it finds a second state, with the last node open and the others
// between 0.9 and 1.26 p t, whose residual is as converged as the first one's.
//
// This test shows that both are solutions of the same discrete equations at
// mu = 2: the run's state converges (the program's own test of convergence),
// and the uniform state, set as the unknowns at the same load, has a residual
// at round-off. It is not a wrong tangent or a false convergence, but the
// known loss of uniqueness of Coulomb friction for large coefficients
// (Hassani, Hild, Ionescu and Sakki 2003), which the run now names before
// its first step when mu exceeds 1 (checked here too).
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/mapping_q.h>

#include <ring_contact/config.h>
#include <ring_contact/problem/inspector.h>

#include "tests.h"

#include <cmath>
#include <iomanip>

using namespace RingContact;
using RingContactTests::check;
using RingContactTests::deallog_file;

namespace
{
  // The constants of prm/two_blocks_friction.prm, with D large enough that
  // the interface slides one way for every mu below.
  constexpr double p = 1e6, E1 = 1e9, nu1 = 0.3, E2 = 2e9, nu2 = 0.25, H = 0.5,
                   D = 5e-2;

  std::string
  prm_text(const double mu)
  {
    std::ostringstream text;
    text << "include " << RING_CONTACT_SOURCE_DIR
         << "/prm/two_blocks_friction.prm\n"
         << "subsection Problem\n set Constants = p = 1e6, E1 = 1e9, nu1 = "
            "0.3, E2 = 2e9, nu2 = 0.25, H = 0.5, mu = "
         << mu << ", D = 5e-2\nend\n"
         << "subsection Mesh\n set Mesh file = " << RING_CONTACT_SOURCE_DIR
         << "/meshes/two_blocks.geo\nend\n"
         << "subsection Contact\n set Friction coefficient = " << mu
         << "\nend\n"
         << "subsection Newton\n set Verbose = false\nend\n"
         << "subsection Output\n set VTU interval = 0\n"
         << " set Print timing = false\n set Write history = false\nend\n";
    return text.str();
  }

  Parameters
  read(const double mu)
  {
    {
      std::ofstream prm("case.prm");
      prm << prm_text(mu);
    }
    Parameters parameters;
    parameters.read("case.prm");
    return parameters;
  }

  // The exact solution at pseudo-time t (the file's boundary expressions):
  // a uniform state in each block, material 1 below y = 0, 2 above.
  Tensor<1, 2>
  exact_displacement(const Point<2>    &x,
                     const unsigned int body,
                     const double       t,
                     const double       mu)
  {
    const double y = x[1];
    if (body == 1)
      return Tensor<1, 2>(
        {mu * p * t * (y + H) * 2 * (1 + nu1) / E1,
         -p * t * (y + H) * (1 + nu1) * (1 - 2 * nu1) / (E1 * (1 - nu1))});
    return Tensor<1, 2>(
      {D * t + mu * p * t * y * 2 * (1 + nu2) / E2,
       -p * t * H * (1 + nu1) * (1 - 2 * nu1) / (E1 * (1 - nu1)) -
         p * t * y * (1 + nu2) * (1 - 2 * nu2) / (E2 * (1 - nu2))});
  }

  // The uniform state as the unknowns: the displacement at every support
  // point of every cell (of its own body), the pressure p t and the
  // traction -mu p t at every slave node.
  void
  set_uniform_state(ContactProblemInspector &inspector,
                    const double             t,
                    const double             mu)
  {
    Vector<double>   &solution = inspector.current_solution();
    const MappingQ<2> mapping(1);
    std::vector<types::global_dof_index> dofs;
    for (const auto &cell : inspector.get_dof_handler().active_cell_iterators())
      {
        const auto &fe = cell->get_fe();
        dofs.resize(fe.n_dofs_per_cell());
        cell->get_dof_indices(dofs);
        const auto &unit = fe.get_unit_support_points();
        for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
          {
            const unsigned int component =
              fe.system_to_component_index(i).first;
            const Point<2> x =
              mapping.transform_unit_to_real_cell(cell, unit[i]);
            solution(dofs[i]) =
              component < 2 ?
                exact_displacement(x, cell->material_id(), t, mu)[component] :
              component == 2 ? p * t :
                               -mu * p * t;
          }
      }
  }
} // namespace

int
main()
{
  auto &out = deallog_file;
  out << std::setprecision(4);
  const double mu = 2, t = 0.25;

  // What the run finds: a converged first step whose pressure is not
  // uniform, and a warning before the first step.
  {
    Parameters          parameters = read(mu);
    std::ostringstream  log;
    ContactProblem<dim> problem(parameters,
                                parameters.contact.schemes.front(),
                                log);
    check(problem.run(), "the run converges");
    const auto  &row  = problem.history().front();
    const double low  = row.value("pressure_min") / (p * t),
                 high = row.value("pressure_max") / (p * t);
    out << "mu = 2, the run's first step: pressure from " << low << " to "
        << high << " of p t" << std::endl;
    check(low < 0.5 && high > 1.1, "the run finds the second solution");
    const bool warned =
      log.str().find("may have more than one solution") != std::string::npos;
    out << "warned before the first step: " << (warned ? "yes" : "no")
        << std::endl;
    check(warned, "a friction coefficient above 1 is named");
  }

  // The uniform state at the same load: its residual is round-off.
  {
    Parameters              parameters = read(mu);
    std::ostringstream      log;
    ContactProblem<dim>     problem(parameters,
                                parameters.contact.schemes.front(),
                                log);
    ContactProblemInspector inspector(problem);
    inspector.setup();
    inspector.set_load_state(LoadProgram::steps(parameters.load).state(t));
    set_uniform_state(inspector, t, mu);
    inspector.assemble_newton_system();
    const ResidualMeasure measure = inspector.residual_measure();
    out << "mu = 2, the uniform state: force residual "
        << (measure.force < 1e-12 ? "below 1e-12" : "above 1e-12")
        << ", gap residual "
        << (measure.gap < 1e-12 ? "below 1e-12" : "above 1e-12") << std::endl;
    check(measure.converged(1e-10), "the uniform state solves the equations");
  }

  // Below the bound: the run finds the uniform state, and says nothing.
  {
    Parameters          parameters = read(1.0);
    std::ostringstream  log;
    ContactProblem<dim> problem(parameters,
                                parameters.contact.schemes.front(),
                                log);
    check(problem.run(), "the run converges at mu = 1");
    const auto &row = problem.history().front();
    check(std::abs(row.value("pressure_min") / (p * t) - 1) < 1e-9 &&
            std::abs(row.value("pressure_max") / (p * t) - 1) < 1e-9,
          "mu = 1: the uniform state");
    check(log.str().find("may have more than one solution") ==
            std::string::npos,
          "mu = 1 is not named");
    out << "mu = 1: the uniform state, no warning" << std::endl;
  }
}
