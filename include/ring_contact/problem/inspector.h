// @sect3{The tests' view of a ContactProblem}
//
// ContactProblem's public face is that of a tutorial's main class: a
// constructor, run() and what a converged run produced. The tests that
// check its pieces (the consistent tangent against differences of the
// residual, above all: tests/tangent.cc) need its inside: set it up, put it
// at a load state, assemble, and read the matrix and the right-hand side.
// This class opens that inside to them, and to nothing else: the program
// never includes this header.
#ifndef ring_contact_problem_inspector_h
#define ring_contact_problem_inspector_h

#include <ring_contact/base/dimension.h>
#include <ring_contact/problem/contact_problem.h>
#include <ring_contact/problem/newton_solver.h>

namespace RingContact
{
  class ContactProblemInspector
  {
  public:
    explicit ContactProblemInspector(ContactProblem<dim> &problem)
        : problem(problem)
    {}

    /// The mesh, the unknowns, the constraints and the contact interfaces,
    /// as run() makes them before its first step.
    void
    setup()
    {
      problem.setup();
    }

    /// Impose the boundary data of `load` at the next assembly (the
    /// solution itself is not changed).
    void
    set_load_state(const LoadState &load)
    {
      problem.apply_boundary_motion(load);
    }

    /// Pair, choose the active set and assemble -R (and the tangent) at
    /// the current solution.
    unsigned int
    assemble_newton_system(
      const Pairing                       pairing = Pairing::search,
      const ContactProblem<dim>::Assembly what =
        ContactProblem<dim>::Assembly::residual_and_tangent)
    {
      return problem.assemble_newton_system(pairing, what);
    }

    Vector<double> &
    current_solution()
    {
      return problem.solution;
    }

    const SparseMatrix<double> &
    tangent_matrix() const
    {
      return problem.system->serial_matrix();
    }

    const Vector<double> &
    residual_rhs() const
    {
      return problem.system->rhs();
    }

    /// The homogeneous constraints of a Newton update.
    const AffineConstraints<double> &
    newton_constraints() const
    {
      return problem.constraints;
    }

    const DoFHandler<dim> &
    get_dof_handler() const
    {
      return problem.dof_handler;
    }

    const hp::MappingCollection<dim> &
    get_mapping() const
    {
      return problem.mapping_collection;
    }

    /// The first contact pair's interface.
    const ContactInterface<dim> &
    contact_interface() const
    {
      return *problem.contacts.front();
    }

    ResidualMeasure
    residual_measure() const
    {
      return problem.residual_measure();
    }

    /// Quadrature points with det F <= 0 at the last assembly.
    unsigned int
    n_inverted_points() const
    {
      return problem.n_inverted;
    }

    /// Whether a Newton iteration at the state last assembled must stop,
    /// and why ("" if it goes on).
    std::string
    stop_reason() const
    {
      return RingContact::stop_reason(problem);
    }

  private:
    ContactProblem<dim> &problem;
  };
} // namespace RingContact

#endif
