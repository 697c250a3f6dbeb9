// @sect3{The NonlinearProblem interface}
//
// What the load steps (load_stepper.h), the Newton solver (newton_solver.h)
// and its strategies for a contact zone that grows from a point
// (first_step.h) need of a problem: its state and load state, the boundary
// motion of a load step, the assembly with its convergence measures, the
// linear solve, and a few switches of the contact pairs. As lethe's
// NewtonNonLinearSolver works on a physics interface and ASPECT keeps its
// Newton method in a NewtonHandler, the nonlinear solution here knows the
// problem only through this class: ContactProblem implements it
// (problem/nonlinear_problem.cc), and a small problem of a test can too.
//
// Every process of an MPI run calls every function alike and gets the same
// answers (the decisions of the Newton loop must be the same everywhere).
#ifndef ring_contact_problem_nonlinear_problem_h
#define ring_contact_problem_nonlinear_problem_h

#include <deal.II/base/mpi.h>
#include <deal.II/lac/vector.h>

#include <ring_contact/contact/active_set.h>
#include <ring_contact/contact/contact_pairing.h>
#include <ring_contact/problem/load_program.h>

#include <string>
#include <vector>

namespace RingContact
{
  using namespace dealii;

  /// The measures of one Newton iterate that decide convergence, each
  /// relative to the problem's own scales (see
  /// ContactProblem::residual_measure()).
  struct ResidualMeasure
  {
    /// |R| of the free displacement rows over the reaction forces.
    double force = 0;
    /// The round-off floor of that ratio: what evaluating the residual in
    /// double precision can resolve at the current state.
    double force_floor = 0;
    /// Largest |gap residual| of an active contact row, in metres, over the
    /// largest displacement; the largest |lambda| of an open row over the
    /// largest |lambda|.
    double gap = 0;
    /// The round-off floor of that ratio (largest over the rows).
    double gap_floor = 0;
    /// True while nothing has moved (the first iteration from rest): gap
    /// is then a length over no displacement, not a ratio worth showing.
    bool at_rest = false;
    /// Euclidean norm of the free rows: the merit of the line search.
    double merit = 0;
    /// False when the system was assembled without its tangent: the bulk's
    /// part of force_floor (from the cell matrices) is then unknown and
    /// force_floor is 0, so that converged() errs only towards "not yet".
    bool force_floor_known = true;

    /// Both groups below max(tolerance, their floor).
    bool
    converged(const double tolerance) const;
    /// Not converged(), but might be once the force floor is known.
    bool
    undecided(const double tolerance) const;
  };

  /// What the Newton solver's strategies read of one contact pair.
  struct ContactPairState
  {
    /// Gaps linear in the displacement: small strain, or a finite-strain
    /// pair while the step is solved linearised.
    bool small_strain = false;
    bool friction     = false;
    /// No pressure on the pair when the step began: a zone that grows
    /// from nothing, a point or an initial overlap.
    bool zone_grows_from_point = false;
    /// The contact rows piecewise linear in the unknowns (small strain, and
    /// no friction or the stick held).
    bool piecewise_linear = false;
    /// The closed nodes, and all the contact nodes of the pair.
    unsigned int n_closed = 0;
    unsigned int n_nodes  = 0;
  };

  class NonlinearProblem
  {
  public:
    virtual ~NonlinearProblem() = default;

    /// What an assembly computes: the right-hand side -R and the tangent
    /// (for a Newton update), or -R alone, which is what a convergence test
    /// or a line search's trial needs. The contact rows and columns are
    /// whole in both.
    enum class Assembly
    {
      residual_and_tangent,
      residual
    };

    /// @name The state
    /// @{

    /// The current iterate: the unknowns, read and written by the solver.
    virtual Vector<double> &
    iterate() = 0;
    /// The converged state the last converged increment started from: the
    /// second point of the predictor's extrapolation, and the start of a
    /// step solved again on a refined mesh.
    virtual Vector<double> &
    increment_start() = 0;
    /// The load state of the boundary data.
    virtual const LoadState &
    load_state() const = 0;
    /// Back to a converged `state` at the load state `load` (a try that
    /// failed): the contact pairs describe that state again.
    virtual void
    restore_state(const Vector<double> &state, const LoadState &load) = 0;
    /// Friction: the slips of the next iterations are measured from
    /// `state` (a converged one).
    virtual void
    accept_contact_state(const Vector<double> &state) = 0;
    /// @}

    /// @name The boundary motion of a load step
    /// @{

    /// The boundary data of `load` become the target of the next solve
    /// (the iterate is not changed).
    virtual void
    apply_boundary_motion(const LoadState &load) = 0;
    /// The next update imposes the increment from the iterate's boundary
    /// values to the target (step-44's inhomogeneous constraints); false,
    /// and the boundary set exactly, when the iterate is at the target
    /// already.
    virtual bool
    impose_boundary_increment() = 0;
    /// Whether the next update imposes the boundary increment.
    virtual bool
    imposing_boundary_increment() const = 0;
    /// The boundary values of the iterate exactly at the target, and the
    /// updates from here homogeneous (after the update that imposed it).
    virtual void
    set_boundary_at_target() = 0;
    /// The updates from here homogeneous, the iterate unchanged (a solve
    /// that failed before its first update).
    virtual void
    drop_boundary_increment() = 0;
    /// Whether the boundary values of the iterate are near the target
    /// (within a tenth of their increment from `converged`): a predictor
    /// that misses them has crossed a kink of the load program.
    virtual bool
    boundary_near_target(const Vector<double> &converged) const = 0;
    /// @}

    /// @name Assembly, convergence measures and the linear solve
    /// @{

    /// Pair the contact points as `pairing` says, choose the active set
    /// and assemble at the iterate; returns the number of contact nodes
    /// whose state changed.
    virtual unsigned int
    assemble_newton_system(const Pairing pairing, const Assembly what) = 0;
    /// The same state and pairing assembled again (`what`): the tangent of
    /// an iterate assembled with its residual alone.
    virtual void
    assemble_system(const Assembly what) = 0;
    /// Whether the system last assembled has its tangent.
    virtual bool
    assembled_with_tangent() const = 0;
    /// The convergence measures of the system last assembled.
    virtual ResidualMeasure
    residual_measure() const = 0;
    /// Whether the state last assembled is rejected (inverted elements, a
    /// point outside its material law), and why.
    virtual bool
    state_rejected() const = 0;
    virtual std::string
    rejection_reason() const = 0;
    /// The Newton update from the system last assembled (with its tangent);
    /// false, with the reason in `failure_reason`, if the solve fails.
    virtual bool
    solve_linear_system(Vector<double> &newton_update,
                        std::string    &failure_reason) = 0;
    /// @}

    /// @name The contact pairs' switches (contact/active_set.h)
    /// @{

    /// Each pair as the strategies see it, in the order of the pairs.
    virtual std::vector<ContactPairState>
    contact_pair_states() const = 0;
    /// The state of every node of every pair.
    virtual std::vector<NodeStates>
    contact_node_states() const = 0;
    /// The next choice of the active set is the first of a load step.
    virtual void
    start_contact_step() = 0;
    /// Friction: every closed node held in stick, or not.
    virtual void
    hold_stick(const bool hold) = 0;
    /// Per pair: whether its active set extrapolates the zones' edges.
    virtual void
    allow_edge_extrapolation(const std::vector<bool> &allow) = 0;
    /// Whether a step's problem may be solved linearised at the undeformed
    /// state first (small-strain laws and contact geometry).
    virtual bool
    may_linearise() const = 0;
    /// The small-strain laws and contact geometry (on), or the model's own
    /// (off).
    virtual void
    linearise(const bool on) = 0;
    /// @}

    /// @name Adaptive refinement after a converged step
    /// @{

    /// How many cycles of refinement follow the converged step `step` (0:
    /// none is due).
    virtual unsigned int
    refinement_cycles(const unsigned int step) = 0;
    /// Refine the mesh and carry the iterate and the increment's start to
    /// it; false, with a note, when the mesh may grow no more.
    virtual bool
    refine_mesh_after_step(const unsigned int step,
                           const unsigned int cycle) = 0;
    /// @}

    /// @name Every process alike
    /// @{
    virtual MPI_Comm
    get_communicator() const = 0;
    /// A signal asked the run to stop (on any process).
    virtual bool
    stop_requested() const = 0;
    /// @}
  };
} // namespace RingContact

#endif
