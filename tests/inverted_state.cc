// A state with inverted elements is never accepted: small strain at
// p = 1e10 Pa on E = 1e9 Pa turns the inner ring inside out (det F < 0 at
// the bulk quadrature points); the step is cut, then the run stops and says
// why, with no converged step. A displacement whose gradient overflows in
// det F (1e300 at an inner node: (1 + a)(1 + b) - a b is inf - inf) is
// rejected too, and said so: its det F is no number to give (the message
// once read "det F = 1.79769e+308 <= 0", the initial value of the smallest
// det F, which a NaN never replaced).
#include <ring_contact/config.h>
#include <ring_contact/problem/contact_problem.h>
#include <ring_contact/problem/inspector.h>


#include "tests.h"

using namespace RingContact;
using RingContactTests::check;

int
main()
{
  {
    std::ofstream prm("inverted.prm");
    prm << "include " << RING_CONTACT_SOURCE_DIR << "/prm/ssnp152a.prm\n"
        << "subsection Materials\n set Material law = linear elasticity\nend\n"
        << "subsection Contact\n set Integration schemes = nodal\nend\n"
        << "subsection Load program\n set Reference pressure = 1e10\n"
        << " set Ramp steps = 1\n set Time step = 1.1\nend\n"
        << "subsection Newton\n set Verbose = false\n"
        << " set Maximum step cuts = 2\nend\n"
        << "subsection Output\n set VTU interval = 0\n"
        << " set Print timing = false\n set Write history = false\nend\n";
  }
  Parameters parameters;
  parameters.read("inverted.prm");
  std::ostringstream  log;
  ContactProblem<dim> problem(parameters,
                              parameters.contact.schemes.front(),
                              log);
  check(!problem.run(), "the run stops");
  check(problem.history().empty(), "no step is accepted");
  check(log.str().find("Newton did not converge after 2 step cuts "
                       "(inverted elements: det F = ") != std::string::npos,
        "the message names the inverted elements: " + log.str());
  RingContactTests::deallog_file
    << "inverted state rejected: the run stops after 2 step cuts with the "
       "message 'inverted elements: det F = ... <= 0 at ... quadrature points'"
    << std::endl;

  // Both displacement unknowns of a node of a cell away from every
  // boundary (and so from the contact surfaces) set to 1e300: the four
  // cells around it have no det F at their quadrature points.
  {
    ContactProblem<dim>     nan_problem(parameters,
                                    parameters.contact.schemes.front(),
                                    log);
    ContactProblemInspector inspector(nan_problem);
    inspector.setup();
    inspector.set_load_state({0, {{"pressure", 1e5}, {"rotation", 0}}});
    const auto &dof_handler = inspector.get_dof_handler();
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (!cell->at_boundary())
        {
          std::vector<types::global_dof_index> dofs(
            cell->get_fe().n_dofs_per_cell());
          cell->get_dof_indices(dofs);
          // The first vertex's u_x and u_y.
          const auto &fe = cell->get_fe();
          check(fe.system_to_component_index(0).first == 0 &&
                  fe.system_to_component_index(1).first == 1,
                "u_x and u_y first");
          inspector.current_solution()(dofs[0]) = 1e300;
          inspector.current_solution()(dofs[1]) = 1e300;
          break;
        }
    inspector.assemble_newton_system();
    const std::string reason = inspector.stop_reason();
    check(inspector.n_inverted_points() > 0 &&
            reason.find("det F is not a number at ") != std::string::npos &&
            reason.find("e+308") == std::string::npos,
          "an overflowing gradient is named as such: " + reason);
    RingContactTests::deallog_file
      << "overflowing gradient rejected: " << reason << std::endl;
  }
}
