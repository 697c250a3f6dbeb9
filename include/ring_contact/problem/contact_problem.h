// @sect3{The ContactProblem class}
//
// The main class: elastic bodies in contact, for one contact integration
// scheme. Its public face is a constructor and run(), as a deal.II
// tutorial's; the rest are its chapters, one source file each, in the order
// the story runs:
// - problem/setup.cc: the mesh (the scenario's), the finite elements
//   (displacement on every body, contact pressure on the slave surfaces)
//   and their degrees of freedom, the contact interfaces;
// - problem/constraints.cc: the imposed displacements as constraints of the
//   Newton updates;
// - problem/assembly.cc: the bulk's virtual work and its tangent, the
//   boundary loads, and the contact terms (contact/);
// - problem/nonlinear_problem.cc: the problem as the load steps and the
//   Newton solver see it (NonlinearProblem): its convergence measures, its
//   linear solve, the switches of its contact pairs. The load steps
//   (load_stepper.h), the semi-smooth Newton method (newton_solver.h) and
//   its strategies for a contact zone that grows from a point
//   (first_step.h) are classes of their own, which know the problem only
//   through that interface;
// - problem/refinement.cc: adaptive refinement, the state carried over;
// - problem/postprocessing.cc: what a converged step reports (history row,
//   invariants, VTU files);
// - problem/contact_problem.cc: the constructor and run().
// The problem posed (mesh, bodies, loads, what to report and check) is the
// scenario's (scenarios/scenario.h); the class implements SolutionState,
// what a scenario may read of a converged state, and NonlinearProblem, what
// the nonlinear solution may do with it.
#ifndef ring_contact_problem_contact_problem_h
#define ring_contact_problem_contact_problem_h

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_values_extractors.h>
#include <deal.II/grid/tria.h>
#include <deal.II/hp/fe_collection.h>
#include <deal.II/hp/mapping_collection.h>
#include <deal.II/hp/q_collection.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <ring_contact/base/dimension.h>
#include <ring_contact/contact/contact_interface.h>
#include <ring_contact/contact/cyclic_symmetry.h>
#include <ring_contact/diagnostics/equilibrium.h>
#include <ring_contact/diagnostics/stiffness_spread.h>
#include <ring_contact/input/parameters.h>
#include <ring_contact/linear_algebra/linear_system.h>
#include <ring_contact/materials/material.h>
#include <ring_contact/output/history.h>
#include <ring_contact/output/progress.h>
#include <ring_contact/output/verdicts.h>
#include <ring_contact/output/vtu_writer.h>
#include <ring_contact/problem/load_program.h>
#include <ring_contact/problem/nonlinear_problem.h>
#include <ring_contact/problem/solution_state.h>
#include <ring_contact/scenarios/scenario.h>

#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <ostream>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace RingContact
{
  using namespace dealii;

  template <int dim>
  class ContactProblem
      : public SolutionState<dim>
      , public NonlinearProblem
  {
  public:
    /// Under MPI (`communicator` with several processes) every process
    /// constructs the problem and runs it: each assembles its own cells and
    /// contact points, the linear solver works on all of them together, and
    /// every process holds the whole state (see LinearSystem). Only process
    /// 0's `log` should be shown.
    ContactProblem(const Parameters        &parameters,
                   const IntegrationScheme &scheme,
                   std::ostream            &log,
                   const MPI_Comm           communicator = MPI_COMM_WORLD);

    /// Run the whole load program. Returns false if a step could not be
    /// solved (the history then ends at the last converged step).
    bool
    run();

    /// One row per converged step.
    const std::vector<HistoryRow> &
    history() const
    {
      return history_rows;
    }

    /// The columns of history.csv (the solver's and the scenario's).
    std::vector<std::string>
    history_columns() const;

    /// The verdicts of the scenario's checks over the history.
    std::vector<Verdict>
    verdicts() const;

    /// Number of steps of the load program.
    unsigned int
    n_steps() const;

    /// Number of degrees of freedom (after the set-up).
    types::global_dof_index
    n_dofs() const
    {
      return dof_handler.n_dofs();
    }

    /// Called once, when the problem is set up and its checks can be
    /// evaluated, before anything is written: the run's input has then
    /// been found good (an earlier run's results may go).
    void
    set_start_observer(std::function<void()> observer)
    {
      start_observer = std::move(observer);
    }

    /// Called after each converged step, once its results are complete
    /// (history row, VTU files); the run stops after that step when it
    /// returns false (a run asked to stop ends with whole files).
    void
    set_step_observer(std::function<bool(const HistoryRow &)> observer)
    {
      step_observer = std::move(observer);
    }

    /// The clock of the run this problem is a scheme of, for the step
    /// lines' elapsed and remaining times (by default the problem's own,
    /// started when it is made).
    void
    set_progress(const RunProgress &run_progress)
    {
      progress = &run_progress;
    }

    /// @name What a scenario may read (SolutionState)
    /// @{
    const DoFHandler<dim> &
    get_dof_handler() const override
    {
      return dof_handler;
    }
    const hp::MappingCollection<dim> &
    get_mapping() const override
    {
      return mapping_collection;
    }
    const Vector<double> &
    get_solution() const override
    {
      return solution;
    }
    /// (Also NonlinearProblem's.)
    const LoadState &
    load_state() const override
    {
      return current_load;
    }
    std::vector<const ContactInterface<dim> *>
    contact_interfaces() const override;
    types::global_dof_index
    contact_node_nearest_to(const Point<dim> &point) const override;
    const ContactInterface<dim> &
    contact_of(const types::global_dof_index node) const override
    {
      return *contacts[pair_of_node.at(node)];
    }
    std::vector<types::global_dof_index>
    contact_nodes() const override;
    double
    reported_pressure(const types::global_dof_index node) const override;
    NodalForces
    nodal_forces() const override;
    const std::map<types::boundary_id, Tensor<1, dim>> &
    applied_resultants() const override
    {
      return applied_resultant;
    }
    const std::map<types::boundary_id, Tensor<1, 3>> &
    applied_moments() const override
    {
      return applied_moment;
    }
    bool
    in_finite_strain() const override
    {
      return std::any_of(bodies.begin(), bodies.end(), [](const auto &body) {
        return !body.material.geometrically_linear;
      });
    }
    unsigned int
    mesh_version() const override
    {
      return n_refinements;
    }
    /// @}

    /// The tests' view of the inside (problem/inspector.h).
    friend class ContactProblemInspector;

  private:
    /// @name Set-up (setup.cc)
    /// @{
    void
    setup();
    void
    make_grid();
    void
    partition_cells();
    void
    setup_system();
    void
    make_finite_elements();
    void
    distribute_dofs();
    void
    make_linear_system();
    void
    make_contact_interfaces();
    /// Refuse a slave surface with a corner (a turn above 45 degrees).
    void
    refuse_slave_corners(const ContactSurface    &slave,
                         const types::boundary_id slave_id) const;
    /// One pair's interface (slave and master boundary tags) under `scheme`.
    std::unique_ptr<ContactInterface<dim>>
    make_contact_interface(const types::boundary_id slave,
                           const types::boundary_id master,
                           const IntegrationScheme &scheme,
                           const bool               geometrically_linear) const;
    void
    make_sparsity_pattern();
    /// @}

    /// @name Constraints (constraints.cc)
    /// @{
    void
    make_constraints();
    void
    add_constraints(
      AffineConstraints<double>                       &target,
      const std::map<types::global_dof_index, double> &boundary_increment,
      const std::vector<double>                       &normal_increment,
      std::vector<bool>                               *fixed_dofs = nullptr);
    double
    normal_constrained_value(const unsigned int    k,
                             const Vector<double> &u) const;
    /// The constraints of the next Newton update: those that impose the
    /// boundary increment while there is one (see
    /// impose_boundary_increment()), else the homogeneous ones.
    const AffineConstraints<double> &
    update_constraints() const
    {
      return imposing_boundary_increment() ? lifting_constraints : constraints;
    }
    /// The boundary motion of a load step (NonlinearProblem).
    /// Set the boundary displacements of a load state as the target of the
    /// next Newton solve: its first update imposes them (see
    /// impose_boundary_increment()), the solution is not changed here.
    void
    apply_boundary_motion(const LoadState &load) override;
    bool
    impose_boundary_increment() override;
    bool
    imposing_boundary_increment() const override
    {
      return lifting_constraints.n_constraints() > 0;
    }
    void
    set_boundary_at_target() override;
    void
    drop_boundary_increment() override
    {
      lifting_constraints.clear();
    }
    bool
    boundary_near_target(const Vector<double> &converged) const override;
    /// @}

    /// @name Assembly (assembly.cc)
    /// @{
    void
    store_reference_geometry();
    /// Pair, choose the active set and assemble the tangent and the
    /// right-hand side -R at the current solution; returns the number of
    /// contact nodes whose status changed (NonlinearProblem).
    unsigned int
    assemble_newton_system(const Pairing pairing, const Assembly what) override;
    void
    assemble_system(const Assembly what) override;
    void
    assemble_contact_terms();
    void
    assemble_bulk(const bool tangent);
    void
    add_local_system(const FullMatrix<double>                   &matrix,
                     const Vector<double>                       &rhs,
                     const std::vector<types::global_dof_index> &dofs,
                     Vector<double>                             &force,
                     const unsigned int cell = numbers::invalid_unsigned_int);
    void
    assemble_boundary_loads();
    /// Why the state last assembled is rejected: its inverted points (det
    /// F <= 0, the smallest given), those where det F is not a number, and
    /// those outside the material law.
    std::string
    inverted_state_reason() const;
    /// Whether `material` has no state at `grad_u` (MaterialLaw::
    /// in_range()): the point is then counted as rejected.
    bool
    outside_law(const Material<dim>     &material,
                const Tensor<2, dim>    &grad_u,
                const types::material_id body);
    /// @}

    /// @name The problem as the Newton solver sees it (nonlinear_problem.cc)
    /// @{
    Vector<double> &
    iterate() override
    {
      return solution;
    }
    Vector<double> &
    increment_start() override
    {
      return previous_solution;
    }
    void
    restore_state(const Vector<double> &state, const LoadState &load) override;
    void
    accept_contact_state(const Vector<double> &state) override;
    bool
    assembled_with_tangent() const override
    {
      return tangent_assembled;
    }
    ResidualMeasure
    residual_measure() const override;
    bool
    state_rejected() const override;
    std::string
    rejection_reason() const override;
    bool
    solve_linear_system(Vector<double> &newton_update,
                        std::string    &failure_reason) override;
    /// Why the factorization of the tangent may need much memory (the
    /// contact surfaces' relative mesh sizes), for the error that says so.
    std::string
    describe_fill_in() const;
    std::vector<ContactPairState>
    contact_pair_states() const override;
    std::vector<NodeStates>
    contact_node_states() const override;
    void
    start_contact_step() override;
    void
    hold_stick(const bool hold) override;
    void
    allow_edge_extrapolation(const std::vector<bool> &allow) override;
    bool
    may_linearise() const override;
    void
    linearise(const bool on) override;
    MPI_Comm
    get_communicator() const override
    {
      return communicator;
    }
    bool
    stop_requested() const override;
    /// @}

    /// @name Adaptive refinement (refinement.cc)
    /// @{
    /// Each active cell's error indicator (subsection Mesh refinement).
    Vector<float>
    estimate_error() const;
    /// Mark, refine and coarsen, carry the state (solution and
    /// previous_solution) to the new mesh and set the problem up on it.
    void
    refine_mesh();
    /// After a converged step: 'Adaptive cycles' if refinement is due
    /// (NonlinearProblem; the load stepper solves the step again after
    /// each).
    unsigned int
    refinement_cycles(const unsigned int step) override;
    bool
    refine_mesh_after_step(const unsigned int step,
                           const unsigned int cycle) override;
    /// @}

    /// @name Postprocessing (postprocessing.cc)
    /// @{
    unsigned int
    n_contact_nodes() const;
    unsigned int
    n_active_nodes() const;
    void
    postprocess_step(const unsigned int step,
                     const unsigned int iterations,
                     const unsigned int cuts,
                     const double       wall_time);
    /// The step's line on the terminal (output/progress.h).
    void
    print_step_line(const HistoryRow &row);
    /// The invariants of a converged state into `row` (equilibrium.h);
    /// false if the state cannot be trusted (see unbalanced_forces).
    bool
    measure_balance_of_forces(HistoryRow &row);
    void
    output_results(const unsigned int step);
    /// The slave faces in the VTU file's order, along each chain of each
    /// slave surface; the arc length made at the first call.
    std::vector<typename VtuWriter<dim>::SlaveFace>
    slave_faces_along_chains();
    /// The diagnostics before the first step (diagnostics/): the rigid
    /// motions that only the contact holds, surfaces that interpenetrate.
    void
    diagnose_start();
    /// Warn when the scheme is point-wise and fails the contact patch test
    /// on the surfaces of contact pair `pair` (surfaces_at_rest.h).
    void
    report_non_matching_surfaces(const unsigned int pair) const;
    /// @}

    // @sect4{The data}

    const Parameters        parameters;
    const IntegrationScheme scheme;
    std::ostream           &log;
    const MPI_Comm          communicator;
    /// The processes, and this one (its cells are the subdomain of this
    /// number; on one process, all of them).
    const unsigned int n_processes, this_process;

    /// The problem posed: bodies, boundary data, what to report.
    const std::unique_ptr<const Scenario<dim>> scenario;
    const std::vector<Body<dim>>               bodies;
    const std::vector<BoundaryLoad<dim>>       boundary_loads;
    const LoadProgram                         &load_program;
    std::map<unsigned int, Material<dim>>      materials; ///< by material id

    Triangulation<dim>               triangulation;
    DoFHandler<dim>                  dof_handler;
    hp::FECollection<dim>            fe_collection;
    hp::MappingCollection<dim>       mapping_collection;
    hp::QCollection<dim>             q_collection;
    const FEValuesExtractors::Vector displacement;
    /// The body (its index in `bodies`) of a material id, and of an
    /// element of fe_collection (the bodies', then the slave layer's).
    std::map<types::material_id, unsigned int> fe_index_of;
    std::vector<unsigned int>                  body_of_fe_index;
    /// The element of the slave layer of each slave body (setup_system()).
    std::map<types::material_id, unsigned int> layer_of;

    /// One interface per contact pair (subsection Contact first).
    std::vector<std::unique_ptr<ContactInterface<dim>>> contacts;
    /// The bodies that some rigid motion leaves held by the contact only.
    std::set<types::material_id> held_by_contact;
    /// How far apart the cells' stiffnesses are (diagnose_start()): a
    /// solve that fails names it where it explains the failure.
    Diagnostics::StiffnessSpread stiffness_spread;
    /// The pair of each contact node (multiplier dof).
    std::map<types::global_dof_index, unsigned int> pair_of_node;
    /// The body (material id) of each boundary tag.
    std::map<types::boundary_id, types::material_id> body_of_boundary;
    /// Cyclic symmetry: the sector, the nodes of its end side and their
    /// images.
    CyclicSymmetry::Sector                sector;
    std::vector<CyclicSymmetry::NodePair> cyclic_pairs;

    /// Homogeneous constraints of a Newton update: the imposed
    /// displacements, zero multiplier off the slave surfaces.
    AffineConstraints<double> constraints;
    /// The hanging nodes' lines alone (adaptive refinement): the nodal
    /// forces at a hanging node are its masters' (nodal_forces()).
    AffineConstraints<double> hanging_node_constraints;
    /// How many times the mesh was refined adaptively (mesh_version()).
    unsigned int n_refinements = 0;
    /// The log has said that Mesh refinement/Maximum cells stops it.
    bool              said_maximum_cells = false;
    std::vector<bool> is_dirichlet;
    std::vector<bool> is_multiplier;
    /// The unknowns whose rows this process stores (all on one process).
    IndexSet locally_owned_dofs;
    /// The tangent, the right-hand side -R and their solver.
    std::unique_ptr<LinearSystem> system;
    /// The nodal forces of the bulk (whole on every process).
    Vector<double> internal_force;
    /// The boundary loads' nodal forces, for the scale of the residual.
    Vector<double> external_force;
    /// The displacement unknowns the scenario imposes.
    std::vector<types::global_dof_index> imposed_dofs;
    /// The unknowns whose reaction a support takes (NodalForces).
    std::vector<bool> supported;
    /// The integral of the applied loads on each loaded boundary, from the
    /// last assembly.
    std::map<types::boundary_id, Tensor<1, dim>> applied_resultant;
    /// ... and of their moments about the origin (SolutionState).
    std::map<types::boundary_id, Tensor<1, 3>> applied_moment;
    /// Why the last converged state cannot be trusted.
    std::string unbalanced_forces;

    /// The constraints of the first update of a load step: the same lines,
    /// with the remaining boundary increment as inhomogeneity (step-44);
    /// empty when the next update keeps the boundary.
    AffineConstraints<double> lifting_constraints;
    /// The imposed displacements at the current load state.
    std::map<types::global_dof_index, double> boundary_target;
    /// The normal displacements N . u = g of the scenario, each as the
    /// constraint u_a = g / N_a - (N_b / N_a) u_b on the component a with
    /// the larger |N_a| (its values g at the current load state).
    std::vector<NormalDisplacement<dim>> normal_target;
    std::vector<unsigned int>            normal_component;

    /// Per row, the sum of the magnitudes of the terms that make up the
    /// residual, sum_j |K_ij| |z_j| + |R_i| with z the displacement (bulk)
    /// or the position X + u and the multiplier (contact): machine epsilon
    /// times this is the noise of evaluating R_i.
    Vector<double> residual_magnitude;
    /// residual_magnitude at the last assembly with the tangent.
    Vector<double> tangent_magnitude;
    /// Quadrature points where the state is rejected at the last
    /// assembly: det F not positive, and among them those where it is not
    /// a number, and the smallest of the numbers; or outside the material
    /// law's range (MaterialLaw::in_range()), the first such body by
    /// material id (see inverted_state_reason()).
    unsigned int       n_inverted        = 0;
    unsigned int       n_undefined_det_F = 0;
    double             min_det_F         = 1;
    unsigned int       n_outside_law     = 0;
    types::material_id outside_law_body  = numbers::invalid_material_id;
    /// Whether the system last assembled has its tangent (see Assembly).
    bool tangent_assembled = false;
    /// The reference geometry of this process's cells for the assembly
    /// (see store_reference_geometry()).
    struct ReferenceGeometry
    {
      /// Per finite element of the collection: the component of each of
      /// its unknowns; its displacement unknowns, the index of each one's
      /// scalar shape function in its base element, and their number; the
      /// number of quadrature points.
      struct Layout
      {
        std::vector<unsigned int> component, u_dofs, base;
        unsigned int              n_bases    = 0;
        unsigned int              n_q_points = 0;
      };
      std::vector<Layout> layout;
      /// Per active cell (of this process), where its values start in JxW
      /// and in gradients (n_bases gradients per quadrature point).
      std::vector<std::pair<std::size_t, std::size_t>> start;
      std::vector<double>                              JxW;
      std::vector<Tensor<1, dim>>                      gradients;
    } reference_geometry;
    /// Linear solver = iterative: GMRES's iterations and solves in the run.
    unsigned int linear_iterations = 0;
    unsigned int linear_solves     = 0;
    /// The largest factorization's memory estimate said in the log.
    double largest_estimate_said = 0;
    /// The model's own materials while the problem is linearised (empty
    /// otherwise, see linearise()).
    std::map<unsigned int, Material<dim>> model_materials;
    /// The current iterate, the converged state the last increment started
    /// from (both carried over by refine_mesh()), and the load state.
    Vector<double> solution;
    Vector<double> previous_solution;
    LoadState      current_load;

    std::vector<HistoryRow>         history_rows;
    std::unique_ptr<VtuWriter<dim>> vtu_writer;
    /// The reference arc length at the slave nodes, for the VTU files
    /// (made at the first output: the reference geometry does not change),
    /// and the same with each closed chain's start at the chain's length.
    Vector<double> arc_length, arc_length_closed;
    TimerOutput    timer;

    /// The step lines (output/progress.h) and the clock they read.
    RunProgress        own_progress;
    const RunProgress *progress = &own_progress;
    StepTable          step_table;

    /// See set_start_observer() and set_step_observer().
    std::function<void()>                   start_observer;
    std::function<bool(const HistoryRow &)> step_observer;
  };
} // namespace RingContact

#endif
