// The cases of the Hertz problem in one step, shared by the tests
// hertz_one_step (frictionless, small and finite strain),
// hertz_one_step_friction (small strain) and
// hertz_one_step_friction_finite (finite strain): one test of them all
// took 7 minutes on a busy machine, near the harness's limit of 10.
//
// The whole Hertz load (prm/hertz.prm: a cylinder on a block, a = R / 10) in
// one step from bodies that touch, on a fine mesh (h = 0.005, 41 of 121
// contact nodes closed at the end), with every scheme: the contact zone
// grows from the touching point to its width within the step.
//
// Without friction. The plain primal-dual active-set method moved the
// zone's edge by a few nodes per iteration (a line search of steps 1/16 to
// 1/2 while it grew, then one or two nodes released per iteration); a steel
// cylinder on aluminium so took 12 iterations at h = 0.005, 28 to 33 and a
// step cut at h = 0.0025. With the edges extrapolated
// (ActiveSet::extrapolate_zone_edges()) and the whole update taken
// while they move: 3 to 5 iterations here, no cut, from an exact touch (d0
// = 0) and from the shipped overlap (d0 = 2e-4) alike; the test allows 6.
//
// With Coulomb friction, mu = 0.2 and 0.5, a steel cylinder (E = 2.1e11,
// nu = 0.3) on an aluminium block (E = 7e10, nu = 0.33) from the exact
// touch: the bodies' different Poisson ratios make the block's surface move
// inwards against the cylinder's, so an outer part of the zone slides and
// an inner part sticks (Goodman's problem), and Newton must find the zone's
// width and its stick zone in the same step. Chosen together from the first
// iteration, the stick and slip states flipped in waves over a zone that
// grew by a node or two per damped iteration: with mu = 0.2, 69 iterations
// and 4 cuts (nodal), and failure after 5 cuts for Gauss 2 and
// segment-based 2 (a singular tangent, then no decrease); from the overlap
// d0 = 2e-4: 11, 29 and a cut, 35 and a cut. Now the zone finds its width
// with every closed node sticking (piecewise linear: its edges are
// extrapolated), then the stick zones' edges are extrapolated the same way
// (first_step.cc, ActiveSet::choose_friction_states()): 5 iterations here. The
// issue asks for at most 10 and no cut, which the test asserts, with a
// stick zone and sliding edges; bench/first-step runs h = 0.01 to 0.0025,
// one step or the first of four (3 to 10). The test asserts the same for
// the first of four steps at h = 0.01, mu = 0.2, where the line search
// stalled on the kink between stick and slip (first_of_four()), and for the
// first of four frictional steps in finite strain (mu = 0.2 and 0.5, Saint
// Venant-Kirchhoff, linearised first), and the whole load in one frictional
// step in finite strain at h = 0.005 (frictional_step_in_finite_strain()).
//
// And the answer is Hertz's (the checks of prm/hertz.prm: p0 within 1.5 %,
// a within 5 %, the reaction equal to the load; friction changes the
// pressure little between these bodies).
//
// In finite strain (Saint Venant-Kirchhoff and neo-Hookean, steel on
// aluminium, frictionless, from the exact touch), solved from the start in
// finite strain the first update put the whole load on the three touching
// nodes: 112 to 144 iterations and four or five cuts at h = 0.005. The step
// is now solved linearised first (the small-strain problem,
// first_step.h "the linearised start"), then in finite strain from there:
// at most 10 iterations and no cut, asserted. Finite strain has no closed
// form here (p0 moves by about 1 % from Hertz's), so the answer is checked
// against the same problem in 8 steps, whose last seven start pressed (only
// the first, an eighth of the load, is linearised): the
// same closed nodes and the largest pressure within 1e-6 (the linearised
// step's is 1 % off). Paired afresh once the model's laws take over: with
// the partners of the linearised iterations kept, Gauss 2 converged to a
// state with the edge node closed (42 nodes and p_max 2.865634e9, against
// 41 and 2.865444e9).
#ifndef ring_contact_tests_hertz_one_step_h
#define ring_contact_tests_hertz_one_step_h

#include <ring_contact/config.h>
#include <ring_contact/problem/contact_problem.h>

#include "tests.h"

#include <fstream>
#include <memory>
#include <sstream>
#include <string>

using namespace RingContact;
using RingContactTests::check;

namespace
{
  // The steel cylinder on the aluminium block (a = R / 10), in `kinematics`.
  std::string
  steel_on_aluminium(const std::string &kinematics = "small strain")
  {
    return "subsection Problem\n set Constants = R = 1, a0 = 0.1, E1 = 2.1e11, "
           "nu1 = 0.3, E2 = 7e10, nu2 = 0.33, Es = 1 / ((1 - nu1^2) / E1 + "
           "(1 - nu2^2) / E2), P = pi * a0^2 * Es / (4 * R), q = P / (2 * R)\n"
           "end\n"
           "subsection Mesh\n set Geo parameters = h = 0.005, d0 = 0\nend\n"
           "subsection Materials\n set Material law = " +
           kinematics +
           "\nend\n"
           "subsection Body 1\n set Young's modulus = 2.1e11\nend\n"
           "subsection Body 2\n set Young's modulus = 7e10\n"
           " set Poisson's ratio = 0.33\nend\n";
  }

  // prm/hertz.prm at h = 0.005 with `entries` added, solved in `steps`
  // steps: the history of the run and its checks.
  std::unique_ptr<ContactProblem<dim>>
  solve(const std::string  &what,
        const std::string  &entries,
        const unsigned int  steps,
        std::ostringstream &log)
  {
    {
      std::ofstream prm("one_step.prm");
      prm << "include " RING_CONTACT_SOURCE_DIR "/prm/hertz.prm\n"
          << "subsection Mesh\n set Mesh file = " RING_CONTACT_SOURCE_DIR
             "/meshes/hertz.geo\nend\n"
          << entries
          << "subsection Load program\n set Number of steps = " << steps
          << "\nend\n"
          << "subsection Newton\n set Verbose = false\nend\n"
          << "subsection Output\n set VTU interval = 0\n"
             " set Print timing = false\n set Write history = false\n"
             "end\n";
    }
    Parameters parameters;
    parameters.read("one_step.prm");
    auto problem =
      std::make_unique<ContactProblem<dim>>(parameters,
                                            parameters.contact.schemes.front(),
                                            log);
    check(problem->run(), what + ": the step is solved");
    return problem;
  }

  // The finite-strain step: its iterations and cuts, and the answer against
  // the same problem in 8 steps.
  void
  finite_strain_step(const std::string &kinematics, const std::string &scheme)
  {
    auto             &out = RingContactTests::deallog_file;
    const std::string what =
      "steel on aluminium, " + kinematics + ", " + scheme;
    const std::string entries =
      steel_on_aluminium(kinematics) +
      "subsection Contact\n set Integration schemes = " + scheme + "\nend\n";
    std::ostringstream log_one, log_eight;
    const auto         one = solve(what, entries, 1, log_one);
    const auto   eight     = solve(what + " in 8 steps", entries, 8, log_eight);
    const auto  &row       = one->history().back();
    const auto  &last      = eight->history().back();
    const double difference =
      std::abs(row.value("pressure_max") - last.value("pressure_max")) /
      last.value("pressure_max");
    out << what << ": " << row.newton_iterations << " Newton iterations, "
        << row.step_cuts << " step cuts, " << row.active_nodes
        << " nodes closed (in 8 steps " << last.active_nodes
        << "), largest pressure " << (difference < 1e-6 ? "within" : "beyond")
        << " 1e-6 of the 8 steps'" << std::endl;
    check(row.newton_iterations <= 10 && row.step_cuts == 0,
          what + ": at most 10 iterations, no cut");
    check(row.active_nodes == last.active_nodes,
          what + ": the closed nodes of the 8 steps");
    check(difference < 1e-6, what + ": the largest pressure of the 8 steps");
  }

  // prm/hertz.prm at h = 0.005 in one step with `entries` added: the step's
  // iterations, cuts and closed (and sliding) nodes, and the file's checks.
  void
  one_step(const std::string &what,
           const std::string &entries,
           const unsigned int max_iterations,
           const bool         friction)
  {
    auto              &out = RingContactTests::deallog_file;
    std::ostringstream log;
    const auto         problem = solve(what, entries, 1, log);
    const auto        &row     = problem->history().back();
    out << what << ": " << row.newton_iterations << " Newton iterations, "
        << row.step_cuts << " step cuts, " << row.active_nodes
        << " nodes closed";
    if (friction)
      out << ", " << row.value("slipping_nodes") << " sliding";
    out << std::endl;
    check(row.newton_iterations <= max_iterations && row.step_cuts == 0,
          what + ": at most " + std::to_string(max_iterations) +
            " iterations, no cut");
    // With friction, some of the zone slides, not all of it.
    if (friction)
      check(row.value("slipping_nodes") > 0 &&
              row.value("slipping_nodes") < row.active_nodes,
            what + ": a stick zone and sliding edges");
    // The errors of p0 and a, the equilibrium's round-off only as a verdict
    // (its digits are the machine's).
    for (const auto &verdict : problem->verdicts())
      {
        out << "  " << verdict.quantity << ": ";
        if (verdict.tolerance >= 1e-3)
          out << "error " << std::setprecision(2) << std::scientific
              << verdict.error << std::defaultfloat << std::setprecision(6)
              << " (tolerance " << verdict.tolerance << ")" << std::endl;
        else
          out << (verdict.pass ? "within " : "beyond ") << verdict.tolerance
              << std::endl;
        check(verdict.pass, what + ": " + verdict.quantity);
      }
  }

  // The first of four steps from touching at h = 0.01, mu = 0.2: once the
  // stick is freed, a node beside the zone's centre slid at the whole update
  // and stuck again at any fraction of it, and the line search stalled (33
  // iterations and 2 cuts with Gauss 2 and segment-based 2; 9 and 10 with
  // every update that changes a state taken whole in a growing zone's first
  // iterations). With the tangential traction in the dual basis
  // (contact_element.h), and that rule dropped (active_set.cc): 4, 5 and 5. In
  // finite strain (Saint Venant-Kirchhoff), linearised first, mu = 0.2 and
  // 0.5: 7, 8, 9 and 7, 9, 8, where it took 12 to 113 iterations and up to
  // four cuts, or failed.
  void
  first_of_four(const std::string &scheme,
                const std::string &mu,
                const std::string &kinematics = "small strain")
  {
    auto             &out  = RingContactTests::deallog_file;
    const std::string what = "first of 4 steps, h = 0.01, mu = " + mu + ", " +
                             kinematics + ", " + scheme;
    std::ostringstream log;
    const auto         problem =
      solve(what,
            steel_on_aluminium(kinematics) +
              "subsection Mesh\n set Geo parameters = h = 0.01, d0 = 0\nend\n"
              "subsection Contact\n set Integration schemes = " +
              scheme + "\n set Friction coefficient = " + mu + "\nend\n",
            4,
            log);
    const auto &row = problem->history().front();
    out << what << ": " << row.newton_iterations << " Newton iterations, "
        << row.step_cuts << " step cuts, " << row.active_nodes
        << " nodes closed, " << row.value("slipping_nodes") << " sliding"
        << std::endl;
    check(row.newton_iterations <= 10 && row.step_cuts == 0,
          what + ": at most 10 iterations, no cut");
    // In finite strain the four steps too: a sliding node whose trial turns
    // past the opposite bound sticks first (ActiveSet::
    // choose_friction_states()); without that rule Gauss 2 took 58 (mu = 0.2)
    // and 39 (mu = 0.5) iterations in all, with it 28 and 29; and the second
    // step, after one from rest, starts from the first's state scaled as the
    // square root of the load (ContactProblem::extrapolation_factor()):
    // 22 to 24 in all (25 to 31 linearly extrapolated).
    if (kinematics != "small strain")
      {
        unsigned int total = 0;
        for (const auto &step : problem->history())
          total += step.newton_iterations;
        out << "  the four steps: " << total << " Newton iterations"
            << std::endl;
        check(total <= 26, what + ": at most 26 iterations in the four steps");
      }
  }

  // The whole load in one frictional step from touching in finite strain
  // (Saint Venant-Kirchhoff, h = 0.005, mu = 0.2 and 0.5): linearised while
  // the zone finds its width with every closed node sticking, then the stick
  // and slip states under the model's laws (first_step.cc). The linearised
  // stick zone is three nodes short of the finite-strain one here (the bodies
  // strain by 5 %): found first in small strain and then moved node by node
  // in finite strain, the step took 42 or 43 iterations and a cut with every
  // scheme at mu = 0.2 (13 with room for them); now 7 or 8. Asserted: at
  // most 10 and no cut, a stick zone and sliding edges, the reaction equal to
  // the load. (Hertz's p0 is 1 % off in finite strain; the same step solved
  // with the old path and room for its iterations gives the same closed and
  // sliding nodes and the same largest pressure to 1e-9, printed here to four
  // digits.)
  void
  frictional_step_in_finite_strain(const std::string &scheme,
                                   const std::string &mu)
  {
    auto             &out = RingContactTests::deallog_file;
    const std::string what =
      "one step, h = 0.005, mu = " + mu + ", finite strain, " + scheme;
    std::ostringstream log;
    const auto         problem =
      solve(what,
            steel_on_aluminium("finite strain") +
              "subsection Contact\n set Integration schemes = " + scheme +
              "\n set Friction coefficient = " + mu + "\nend\n",
            1,
            log);
    const auto &row = problem->history().back();
    out << what << ": " << row.newton_iterations << " Newton iterations, "
        << row.step_cuts << " step cuts, " << row.active_nodes
        << " nodes closed, " << row.value("slipping_nodes")
        << " sliding, largest pressure " << std::setprecision(4)
        << row.value("pressure_max") << std::setprecision(6) << std::endl;
    check(row.newton_iterations <= 10 && row.step_cuts == 0,
          what + ": at most 10 iterations, no cut");
    check(row.value("slipping_nodes") > 0 &&
            row.value("slipping_nodes") < row.active_nodes,
          what + ": a stick zone and sliding edges");
    unsigned int n_reactions = 0;
    for (const auto &verdict : problem->verdicts())
      if (verdict.quantity.find("force") != std::string::npos)
        {
          ++n_reactions;
          check(verdict.pass, what + ": " + verdict.quantity);
        }
    check(n_reactions == 1, what + ": the reaction is checked");
  }
} // namespace


#endif
