// @sect3{The contact problem: construction and the run}
//
// The reading order of the program starts here (doc/intro.md has it in
// full): run() is the story in twenty lines. It sets the problem up (the
// scenario's mesh, the finite elements, the contact interfaces:
// setup.cc), checks the input against the mesh and says what the problem
// is, then follows the load program step by step (load_stepper.cc, which
// solves each step by newton_solver.cc), each converged step reported
// (postprocessing.cc) and handed to the run's driver (driver/), which writes
// it to disk before the next step starts.
#include <deal.II/base/timer.h>

#include <ring_contact/base/dimension.h>
#include <ring_contact/base/utilities.h>
#include <ring_contact/problem/contact_problem.h>
#include <ring_contact/problem/load_stepper.h>

#include <iomanip>

namespace RingContact
{
  // @sect4{The constructor}
  //
  // Everything the problem is made of comes from the scenario, which the
  // parameter file names (the rings of doc/intro.md, the patch test, or a
  // general problem written in the file): the bodies with their materials,
  // the boundary loads and the load program. The constructor only stores them;
  // the mesh and the unknowns are made by run() (setup.cc).
  template <int dim>
  ContactProblem<dim>::ContactProblem(const Parameters        &parameters,
                                      const IntegrationScheme &scheme,
                                      std::ostream            &log,
                                      const MPI_Comm           communicator)
      : parameters(parameters)
      , scheme(scheme)
      , log(log)
      , communicator(communicator)
      , n_processes(RingContact::n_processes(communicator))
      , this_process(RingContact::this_process(communicator))
      , scenario(make_scenario<dim>(parameters))
      , bodies(scenario->bodies())
      , boundary_loads(scenario->boundary_loads())
      , load_program(scenario->load_program())
      // Adaptive refinement (refinement.cc) keeps neighbouring cells within
      // one level at every vertex, so that a refined patch grades into the
      // mesh around it; uniform refinement is unaffected.
      , triangulation(Triangulation<dim>::limit_level_difference_at_vertices)
      , dof_handler(triangulation)
      , displacement(0)
      , current_load{}
      // The summary is printed by run() when it ends, not by the
      // destructor: a run that ends by an error prints the error only.
      , timer(log, TimerOutput::never, TimerOutput::wall_times)
  {
    // A body is known by its material id in the mesh. Its index b in
    // `bodies` is also the index of its FESystem in fe_collection, since
    // make_finite_elements() pushes the bodies' elements first and in this
    // order (the slave layers' elements come after them).
    for (unsigned int b = 0; b < bodies.size(); ++b)
      {
        materials.emplace(bodies[b].material_id, bodies[b].material);
        fe_index_of[bodies[b].material_id] = b;
      }
  }

  // @sect4{ContactProblem::run}
  //
  // The order matters for what a failed run leaves behind. Everything that
  // can refuse the input (the mesh, the schemes against the surfaces'
  // degree, the boundary data, a body that nothing holds) is done before
  // the start observer is called: the driver clears an earlier run's
  // results only then, so that a run that fails on its input does not wipe
  // them.
  template <int dim>
  bool
  ContactProblem<dim>::run()
  {
    setup();
    diagnose_start();
    if (start_observer)
      start_observer();
    // The undeformed state, step 0: the start of every animation.
    if (parameters.output.vtu_interval > 0)
      output_results(0);

    // Each step solved by the load stepper (load_stepper.h: predictor,
    // Newton, cuts, adaptive cycles) through the problem's NonlinearProblem
    // face, then reported. Each converged step is handed to the driver,
    // which appends its row to history.csv before the next step starts: a
    // run stopped by a signal or a failure keeps every step it converged.
    // The driver's answer is how a signal stops the run between two steps,
    // never inside a write.
    LoadStepper load_stepper(*this, load_program, parameters.newton, log);
    bool        ok = true;
    for (unsigned int step = 1; step <= load_program.n_steps() && ok; ++step)
      {
        unsigned int iterations = 0, cuts = 0;
        Timer        wall;
        ok = load_stepper.solve_step(step, iterations, cuts);
        if (ok)
          postprocess_step(step, iterations, cuts, wall.wall_time());
        if (ok && step_observer && !step_observer(history_rows.back()))
          break;
      }
    // A step that failed leaves the solution at the last converged state
    // (the load stepper restores it): that state is written whatever the
    // output interval, so that the place where the run stopped can be
    // looked at.
    if (!ok && parameters.output.vtu_interval > 0)
      output_results(history_rows.empty() ? 0 : history_rows.back().step);

    // The linear solver's work, with the timing summary. GMRES's iterations
    // per solve say how well the block preconditioner holds up (they grow with
    // the mesh: doc/validation.md, "The iterative solver"); the direct
    // solver's factorizations, analyses (one per sparsity pattern) and the
    // flops of the last LU say how far a run is from the flop limit that
    // bench/ measures against.
    if (system->iterative() && linear_solves > 0)
      log << "GMRES: " << linear_iterations << " iterations in "
          << linear_solves << " solves (" << std::fixed << std::setprecision(1)
          << double(linear_iterations) / linear_solves << " per solve)\n"
          << std::defaultfloat;
    else if (const auto done = system->direct_statistics();
             parameters.output.print_timing && done.factorizations > 0)
      log << system->direct_solver_name() << ": " << done.factorizations
          << (done.factorizations == 1 ? " factorization, " :
                                         " factorizations, ")
          << done.analyses
          << (done.analyses == 1 ? " analysis, " : " analyses, ")
          << std::setprecision(3) << done.flops << " flops in the last\n"
          << std::defaultfloat << std::setprecision(6);
    if (parameters.output.print_timing)
      timer.print_summary();
    return ok;
  }

  // @sect4{What the driver reads}
  //
  // The columns and the verdicts are the scenario's: the problem class
  // knows the solver's own columns (steps, iterations, cuts, invariants)
  // and leaves the quantities and their references to the problem posed.
  template <int dim>
  std::vector<std::string>
  ContactProblem<dim>::history_columns() const
  {
    return RingContact::history_columns(scenario->leading_columns(),
                                        scenario->trailing_columns());
  }

  template <int dim>
  std::vector<Verdict>
  ContactProblem<dim>::verdicts() const
  {
    return scenario->evaluate_checks(scheme.name(), history_rows);
  }

  template <int dim>
  unsigned int
  ContactProblem<dim>::n_steps() const
  {
    return load_program.n_steps();
  }


  // The class for the dimensions the program runs in: this file's
  // members, those defined in the header and the virtual table. An
  // explicit instantiation of the class takes only the members defined
  // where it stands, so every other chapter instantiates the class too,
  // for its own members.
  template class ContactProblem<2>;
  template class ContactProblem<3>;
} // namespace RingContact
