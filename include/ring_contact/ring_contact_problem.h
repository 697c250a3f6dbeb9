// The main class: two elastic rings in frictionless contact (SSNP152), for
// one contact integration scheme. Its story, in the order of the member
// functions: make the mesh, set up the finite elements (displacement on both
// rings, contact pressure on the slave surface), follow the load program
// step by step with a semi-smooth Newton method (pairing, assembly, direct
// solve), and report.
#ifndef ring_contact_ring_contact_problem_h
#define ring_contact_ring_contact_problem_h

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

#include <ring_contact/contact_interface.h>
#include <ring_contact/equilibrium.h>
#include <ring_contact/linear_system.h>
#include <ring_contact/load_program.h>
#include <ring_contact/material.h>
#include <ring_contact/parameters.h>
#include <ring_contact/postprocessing.h>
#include <ring_contact/scenario.h>

#include <algorithm>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <ostream>
#include <set>
#include <string>
#include <utility>

namespace RingContact
{
  using namespace dealii;

  /// The measures of one Newton iterate that decide convergence, each
  /// relative to the problem's own scales (see solve_newton_step()).
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

  class RingContactProblem
  {
  public:
    /// Under MPI (`communicator` with several processes) every process
    /// constructs the problem and runs it: each assembles its own cells and
    /// contact points, the linear solver works on all of them together, and
    /// every process holds the whole state (see LinearSystem). Only process
    /// 0's `log` should be shown.
    RingContactProblem(const Parameters        &parameters,
                       const IntegrationScheme &scheme,
                       std::ostream            &log,
                       const MPI_Comm           communicator = MPI_COMM_WORLD);

    /// Run the whole load program. Returns false if a step could not be
    /// solved (the history then ends at the last converged step).
    bool
    run();

    /// Set the load state `load` (its boundary displacements become the
    /// target of the next Newton solve, its pressure the load) without
    /// solving: for tests that assemble at a given state.
    void
    set_load_state(const LoadState &load)
    {
      apply_boundary_motion(load);
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

    /// One row per converged step.
    const std::vector<HistoryRow> &
    history() const
    {
      return history_rows;
    }

    /// Number of degrees of freedom (after setup).
    types::global_dof_index
    n_dofs() const
    {
      return dof_handler.n_dofs();
    }

    /// @name Access for tests
    /// @{
    /// Make the mesh, the finite elements, the contact interface.
    void
    setup();
    /// What an assembly computes: the right-hand side -R and the tangent
    /// (for a Newton update), or -R alone, which is what a convergence test
    /// or a line search's trial needs. The contact rows and columns are
    /// whole in both.
    enum class Assembly
    {
      residual_and_tangent,
      residual
    };
    /// Pair, choose the active set and assemble the tangent and the
    /// right-hand side -R at the current solution; returns the number of
    /// contact nodes whose status changed.
    /// `pairing`: see ContactInterface::update().
    unsigned int
    assemble_newton_system(
      const ContactInterface::Pairing pairing =
        ContactInterface::Pairing::search,
      const Assembly what = Assembly::residual_and_tangent);
    Vector<double> &
    current_solution()
    {
      return solution;
    }
    /// The tangent on one process (deal.II's matrix).
    const SparseMatrix<double> &
    tangent_matrix() const
    {
      return system->serial_matrix();
    }
    const Vector<double> &
    residual_rhs() const
    {
      return system->rhs();
    }
    const AffineConstraints<double> &
    newton_constraints() const
    {
      return constraints;
    }
    const DoFHandler<2> &
    get_dof_handler() const
    {
      return dof_handler;
    }
    const hp::MappingCollection<2> &
    get_mapping() const
    {
      return mapping_collection;
    }
    /// The contact interface of the first pair (subsection Contact).
    const ContactInterface &
    contact_interface() const
    {
      return *contacts[0];
    }
    /// The convergence measures of the system last assembled.
    ResidualMeasure
    residual_measure() const;
    /// Quadrature points with det F <= 0 found by the last assembly (the
    /// material law is not evaluated there), and the smallest det F.
    unsigned int
    n_inverted_points() const
    {
      return n_inverted;
    }
    /// Set the boundary displacements of a load state as the target of the
    /// next Newton solve: its first update imposes them (see
    /// make_lifting_constraints()), the solution is not changed here.
    void
    apply_boundary_motion(const LoadState &load);
    /// @}

  private:
    void
    assemble_system(const Assembly what = Assembly::residual_and_tangent);
    void
    store_reference_geometry();
    void
    make_grid();
    void
    partition_cells();
    void
    setup_system();
    void
    make_constraints();
    void
    add_constraints(
      AffineConstraints<double>                       &target,
      const std::map<types::global_dof_index, double> &boundary_increment,
      const std::vector<double>                       &normal_increment,
      std::vector<bool>                               *fixed_dofs = nullptr);
    bool
    make_lifting_constraints();
    void
    set_boundary_target();
    /// Notes the rigid-body motions that no imposed displacement fixes;
    /// returns their number.
    unsigned int
    report_rigid_body_modes();
    /// Warns when the contact surfaces interpenetrate before any load.
    void
    report_initial_interpenetration();
    const AffineConstraints<double> &
    update_constraints() const
    {
      return lifting ? lifting_constraints : constraints;
    }
    void
    make_sparsity_pattern();
    bool
    solve_linear_system(Vector<double> &newton_update);
    /// The pairing at an accepted Newton iterate: the search, or, once the
    /// pairing is held, the held partners stopped at their segments' ends.
    ContactInterface::Pairing
    accepted_pairing() const;
    bool
    solve_newton_step(unsigned int &iterations, double &final_residual);
    void
    assemble_boundary_loads();
    void
    add_local_system(const FullMatrix<double>                   &matrix,
                     const Vector<double>                       &rhs,
                     const std::vector<types::global_dof_index> &dofs,
                     Vector<double>                             &force,
                     const unsigned int cell = numbers::invalid_unsigned_int);
    bool
    line_search(const Vector<double>  &newton_update,
                const ResidualMeasure &before,
                const Assembly         assembly,
                unsigned int          &n_changed,
                double                &step_length);
    bool
    solve_load_step(const unsigned int step);
    /// A signal asked the run to stop (on any process).
    bool
    stop_requested() const;
    /// Why the factorization of the tangent may need much memory (the
    /// contact surfaces' relative mesh sizes), for the error that says so.
    std::string
    describe_fill_in() const;
    void
    postprocess_step(const unsigned int step,
                     const unsigned int iterations,
                     const unsigned int cuts,
                     const double       wall_time);
    void
    output_results(const unsigned int step);
    /// The invariants of a converged state into `row` (equilibrium.h);
    /// false if the state cannot be trusted (see unbalanced_forces).
    bool
    measure_balance_of_forces(HistoryRow &row);
    /// A quantity of a general problem's check at the current state.
    double
    checked_quantity(const ProblemCheckParameters &check) const;
    /// The contact pressure reported at a multiplier node (Cauchy or
    /// nominal, as Contact/Reported pressure says).
    double
    reported_pressure(const types::global_dof_index dof) const;
    /// Over every pair: the contact nodes, how many are active, the node
    /// nearest to a reference point, and the pair of a node.
    std::vector<types::global_dof_index>
    contact_nodes() const;
    unsigned int
    n_contact_nodes() const;
    unsigned int
    n_active_nodes() const;
    types::global_dof_index
    contact_node_nearest_to(const Point<2> &point) const;
    const ContactInterface &
    contact_of(const types::global_dof_index node) const
    {
      return *contacts[pair_of_node.at(node)];
    }

    const Parameters        parameters;
    const IntegrationScheme scheme;
    std::ostream           &log;
    const MPI_Comm          communicator;
    /// The processes, and this one (its cells are the subdomain of this
    /// number; on one process, all of them).
    const unsigned int n_processes, this_process;

    Triangulation<2>                 triangulation;
    DoFHandler<2>                    dof_handler;
    hp::FECollection<2>              fe_collection;
    hp::MappingCollection<2>         mapping_collection;
    hp::QCollection<2>               q_collection;
    const FEValuesExtractors::Vector displacement;
    /// The problem posed: bodies, boundary data, reference.
    const std::unique_ptr<const Scenario> scenario;
    const std::vector<Body>               bodies;
    const std::vector<BoundaryLoad>       boundary_loads;
    std::map<unsigned int, Material>      materials; ///< by material id
    /// The finite element (and mapping) of each body's cells.
    /// The body (its index in `bodies`) of a material id, and of an
    /// element of fe_collection (the bodies', then the slave layer's).
    std::map<types::material_id, unsigned int> fe_index_of;
    std::vector<unsigned int>                  body_of_fe_index;
    types::material_id                         slave_ring;
    const LoadProgram                          load_program;
    /// One interface per contact pair (subsection Contact first).
    std::vector<std::unique_ptr<ContactInterface>> contacts;
    /// The bodies that some rigid motion leaves held by the contact only.
    std::set<types::material_id> held_by_contact;
    /// The pair of each contact node (multiplier dof).
    std::map<types::global_dof_index, unsigned int> pair_of_node;
    /// The body (material id) of each slave and master boundary tag.
    std::map<types::boundary_id, types::material_id> body_of_boundary;
    /// Cyclic symmetry: the nodes of the sector's end side and their images.
    std::vector<CyclicSymmetry::NodePair> cyclic_pairs;

    /// Homogeneous constraints of a Newton update: fixed displacements on
    /// r = R1 and r = R3, zero multiplier off the slave surface.
    AffineConstraints<double> constraints;
    std::vector<bool>         is_dirichlet;
    std::vector<bool>         is_multiplier;
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
    std::map<types::boundary_id, Tensor<1, 2>> applied_resultant;
    /// The resultant forces of boundaries (built when a check asks).
    mutable std::unique_ptr<BoundaryResultants> boundary_resultants;
    /// Why the last converged state cannot be trusted.
    std::string unbalanced_forces;

    /// The constraints of the first update of a load step: the same lines,
    /// with the remaining boundary increment as inhomogeneity (step-44).
    AffineConstraints<double> lifting_constraints;
    /// Assemble and solve with lifting_constraints.
    bool lifting = false;
    /// The imposed displacements at the current load state.
    std::map<types::global_dof_index, double> boundary_target;
    /// The normal displacements N . u = g of the scenario, each as the
    /// constraint u_a = g / N_a - (N_b / N_a) u_b on the component a with
    /// the larger |N_a| (its values g at the current load state).
    std::vector<NormalDisplacement> normal_target;
    std::vector<unsigned int>       normal_component;
    /// The value of u_a that satisfies normal_target[k] given u_b.
    double
    normal_constrained_value(const unsigned int    k,
                             const Vector<double> &u) const;

    /// Per row, the sum of the magnitudes of the terms that make up the
    /// residual, sum_j |K_ij| |z_j| + |R_i| with z the displacement (bulk)
    /// or the position X + u and the multiplier (contact): machine epsilon
    /// times this is the noise of evaluating R_i.
    Vector<double> residual_magnitude;
    /// residual_magnitude at the last assembly with the tangent.
    Vector<double> tangent_magnitude;
    /// |X| of the support point of every displacement unknown.
    Vector<double> position_magnitude;
    unsigned int   n_inverted = 0;
    double         min_det_F  = 1;
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
      std::vector<Tensor<1, 2>>                        gradients;
    } reference_geometry;
    /// Whether the iterate after a Newton update is expected to converge,
    /// from this run's record. Such an iterate is assembled without its
    /// tangent first: the test of convergence does not need it, and after
    /// the last update of a load step it would not be used. One that does
    /// not converge needs it for its own update, and is assembled again.
    struct ConvergenceRecord
    {
      /// Whether the last update that imposed a boundary increment led to
      /// a converged iterate.
      bool lifting_converged = false;
      /// r_k+1 / r_k^2 of the last other update, r the relative residual
      /// (the larger of the force and gap measures): Newton's quadratic
      /// rate, from which the next residual is forecast. None (infinite)
      /// before the first.
      double rate = std::numeric_limits<double>::infinity();

      bool
      expects(const bool   lifting,
              const double residual,
              const double tolerance) const
      {
        return lifting ? lifting_converged :
                         rate * residual * residual <= tolerance;
      }
      void
      record(const bool   lifting,
             const double from,
             const double to,
             const bool   converged)
      {
        if (lifting)
          lifting_converged = converged;
        else if (from > 0 && std::isfinite(from) && std::isfinite(to))
          rate = to / (from * from);
      }
    } convergence_record;
    /// Linear solver = iterative: GMRES's iterations and solves in the run.
    unsigned int linear_iterations = 0;
    unsigned int linear_solves     = 0;
    /// Why the last Newton solve stopped without converging.
    std::string failure_reason;
    /// The largest factorization's memory estimate said in the log.
    double largest_estimate_said = 0;
    /// The contact points keep their partners (pairing cycles).
    bool                    keep_partners = false;
    Vector<double>          solution;
    Vector<double>          previous_solution;
    double                  previous_time, current_time;
    LoadState               current_load;
    types::global_dof_index probe_dof;

    std::vector<HistoryRow>    history_rows;
    std::unique_ptr<VtuWriter> vtu_writer;
    TimerOutput                timer;

    /// See set_start_observer() and set_step_observer().
    std::function<void()>                   start_observer;
    std::function<bool(const HistoryRow &)> step_observer;
  };
} // namespace RingContact

#endif
