// @sect3{Newton's method and the load steps}
//
// Each load step is solved by a semi-smooth Newton method: pair the slave
// points with the current master surface, choose the active set, assemble
// (assembly.cc), solve the linearised system directly, and move along the
// update as far as the residual decreases (line search). It has converged
// when the active set no longer changes and both the force rows and the
// contact rows are below the tolerance relative to their own scales, or at
// their round-off floor (residual_measure()): one tolerance fits any
// material, load and size. A step whose Newton iteration fails is tried
// again from the last converged state if it started from an extrapolated
// one, then cut in halves.
//
// This chapter only drives: the state it moves is the solution vector, the
// boundary target of a load state comes from constraints.cc (whose lifting
// constraints carry the boundary increment into the first update, as in
// step-44), every iterate is paired and assembled by
// assemble_newton_system() in assembly.cc, and a converged step is handed
// to postprocessing.cc. What it adds is the logic that makes the method
// robust: a convergence test that knows what double precision can resolve,
// a line search against the jumps of a faceted master surface, the pairing
// held when it cycles, and the rejection of inverted states.
#include <ring_contact/base/utilities.h>
#include <ring_contact/problem/contact_problem.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <memory>
#include <sstream>

namespace RingContact
{
  // @sect4{The convergence test}
  //
  // Two groups of rows, each with its own scale and its own floor: the
  // force rows (free displacement unknowns) and the contact rows (the
  // multipliers' rows, normal and tangential). A group passes when it is
  // below the tolerance or below what evaluating it in double precision can
  // resolve at this state; a floor larger than the tolerance means the
  // iterate is as good as the arithmetic allows, and more iterations would
  // only stir the noise.
  bool
  ResidualMeasure::converged(const double tolerance) const
  {
    return force <= std::max(tolerance, force_floor) &&
           gap <= std::max(tolerance, gap_floor);
  }

  // An iterate assembled without its tangent has no force floor (it needs
  // the cell matrices, see residual_magnitude), and converged() then errs
  // towards "not yet". Only when the contact rows pass already can the
  // missing floor change the verdict: then, and only then, is the tangent
  // worth assembling just to decide (line_search()).
  bool
  ResidualMeasure::undecided(const double tolerance) const
  {
    return !force_floor_known && !converged(tolerance) &&
           gap <= std::max(tolerance, gap_floor);
  }

  // The convergence measures of the assembled system, each relative to the
  // problem's own scale, so that one tolerance fits E = 1e6 as well as
  // E = 1e12, p = 1e2 as well as p = 1e9, and rings of any size:
  // - free displacement rows (forces): |R| over the reaction forces on the
  //   fixed boundaries;
  // - active contact rows c int Phi_k g dS: divided by the sum of their
  //   row's |K_kj| (about 2 c w_k), a length, over the largest displacement;
  //   open contact rows w_k lambda_k: lambda_k over the largest |lambda|.
  // Each has a floor: what double precision resolves at this state,
  // round_off_factor * eps * sum_j |K_ij| |z_j| (see residual_magnitude).
  // A fixed tolerance cannot do this: the contact rows are evaluated from
  // positions of size R, so their noise does not scale with the load, and
  // at p = 1e4 on steel it is 1e-9 of the reactions.
  ResidualMeasure
  ContactProblem::residual_measure() const
  {
    // Several roundings per term, the linear solver's backward error, and
    // the row sums of the noise: a factor of ten over eps |K| |z|, measured
    // on the variants of scripts/studies/variants (the stalled residuals of
    // steel/aluminium at p = 1e2 are 0.05 to 0.3 of eps |K| |z|).
    constexpr double round_off_factor = 10;
    const double     eps              = std::numeric_limits<double>::epsilon();

    // The norms with a running scale (EuclideanNorm): squares of forces
    // of 1e-200 would underflow to zero, and every ratio below with them.
    // The scale of the forces: on a supported unknown the internal force is
    // the support's reaction, and the boundary loads count wherever they
    // act; the multiplier rows are not forces and stay out. The largest
    // displacement and the largest pressure are the scales of the contact
    // rows below (a length row and a traction row).
    EuclideanNorm reaction;
    double        largest_displacement = 0, largest_pressure = 0;
    for (types::global_dof_index i = 0; i < solution.size(); ++i)
      {
        if (is_dirichlet[i] && !is_multiplier[i])
          reaction.add(internal_force(i));
        reaction.add(external_force(i));
        if (is_multiplier[i])
          largest_pressure = std::max(largest_pressure, std::abs(solution(i)));
        else
          largest_displacement =
            std::max(largest_displacement, std::abs(solution(i)));
      }
    // Under the pressure load the reactions vanish: the scale of the forces
    // is then the load itself (both are in `reaction`).
    const double reaction_norm =
      reaction.value() > 0 ? reaction.value() : 1e-300;
    // From rest (the first iterate of the first step) nothing has moved
    // and there is no pressure yet: the scales are kept off zero, so that a
    // ratio is large rather than a division by zero, and the iteration
    // line says why it is not worth showing (at_rest).
    ResidualMeasure measure;
    measure.at_rest      = largest_displacement == 0;
    largest_displacement = std::max(largest_displacement, 1e-300);
    largest_pressure     = std::max(largest_pressure, 1e-300);

    // The constrained rows are condensed out of the system (their entries
    // of -R are not residuals): only the free rows are measured. The
    // right-hand side is whole on every process, so the force group and the
    // merit come out the same everywhere without communication. The merit
    // of the line search takes every free row, the contact rows included:
    // all rows are forces per unit thickness, so their norm has one unit.
    EuclideanNorm force, force_floor, merit;
    for (types::global_dof_index i = 0; i < solution.size(); ++i)
      {
        if (constraints.is_constrained(i))
          continue;
        const double r = system->rhs()(i);
        merit.add(r);
        if (!is_multiplier[i])
          {
            force.add(r);
            force_floor.add(residual_magnitude(i));
            continue;
          }
        // A contact row: active when it depends on displacements. Its
        // entries are on the process that owns it.
        if (!locally_owned_dofs.is_element(i))
          continue;
        // A gap or a stick row (c s~_k) measures a length; an open node's
        // row or a sliding node's (w lambda_t - sign mu w lambda) a
        // traction. Dividing by the row's sum sum_j |K_kj| removes the
        // complementarity constant c and the weight w_k, whatever their
        // values: what remains is a length of the order of the gap, or the
        // multiplier in pascals, which the largest displacement or pressure
        // makes a ratio.
        double row_sum = 0;
        bool   active  = false;
        system->for_each_entry(i, [&](const auto j, const double value) {
          row_sum += std::abs(value);
          active = active || (!is_multiplier[j] && value != 0);
        });
        // An empty row (an unknown no term reaches) measures nothing.
        if (row_sum == 0)
          continue;
        const double scale = active ? largest_displacement : largest_pressure;
        measure.gap = std::max(measure.gap, std::abs(r) / row_sum / scale);
        measure.gap_floor =
          std::max(measure.gap_floor,
                   round_off_factor * eps *
                     (active ? residual_magnitude(i) / row_sum / scale : 1.0));
      }
    // Each contact row was seen on its owner only: the largest over the
    // processes, so that every process takes the same decision.
    if (n_processes > 1)
      {
        measure.gap = Utilities::MPI::max(measure.gap, communicator);
        measure.gap_floor =
          Utilities::MPI::max(measure.gap_floor, communicator);
      }
    // The floor estimates the round-off of positions |X| over the
    // displacement, but the gap is computed with its reference part apart
    // (zero where node-matching surfaces face each other), so that it
    // stays accurate far below that: displacements of 1e-210 on bodies of
    // 1 m gave a floor of 1e195, which accepted any iterate. A gap residual
    // of 1e-4 of the displacement is never a round-off worth accepting.
    measure.gap_floor = std::min(measure.gap_floor, 1e-4);
    // Without the tangent the bulk's part of the magnitudes is missing; a
    // floor of zero then leaves the test to the tolerance alone, which can
    // only delay convergence, never accept an iterate too early.
    measure.force             = force.value() / reaction_norm;
    measure.force_floor_known = tangent_assembled;
    measure.force_floor =
      tangent_assembled ?
        round_off_factor * eps * force_floor.value() / reaction_norm :
        0;
    measure.merit = merit.value();
    return measure;
  }

  // @sect4{The linear solve}
  //
  // The Newton update by the linear solver (a direct solve, or GMRES with
  // Newton/Linear solver = iterative). A singular tangent (UMFPACK
  // refuses it) or a nearly singular one (the solution does not satisfy
  // the system) is a failure of the iteration with its reason, not an
  // exception that ends the run: usually a body that nothing holds in some
  // direction (a missing support, or a contact that is open). Before this
  // was so, UMFPACK's code ended the run, or a block pushed sideways with
  // no support "converged", slid away, to 13 % of its contact pressure.
  bool
  ContactProblem::solve_linear_system(Vector<double> &newton_update)
  {
    Assert(tangent_assembled, ExcMessage("The system has no tangent."));
    TimerOutput::Scope t(timer, "linear solver");
    const std::string  advice =
      ": " + stiffness_spread.singular_tangent_advice();
    double relative_residual;
    try
      {
        relative_residual = system->solve(newton_update);
        if (system->iterative())
          {
            linear_iterations += system->last_iterations();
            ++linear_solves;
            if (parameters.newton.verbose)
              log << "      GMRES: " << system->last_iterations()
                  << " iterations\n";
          }
      }
    catch (const FactorizationTooLarge &e)
      {
        // The factorization's memory is estimated by the solver's analysis
        // before it runs, and refused beyond what this process can have.
        // Cutting the step would not help (the pattern, hence the fill-in,
        // stays the same): say what makes the system so large to
        // factorize, and end the run.
        // Thrown again as what it is: the driver refuses the input for it
        // (exit code 2), the mesh being too large for the machine.
        throw FactorizationTooLarge(one_line_message(e) + describe_fill_in(),
                                    e.bytes);
      }
    // GMRES that stops short says nothing about the tangent itself: a
    // direct solver can tell a singular tangent from a weak preconditioner.
    catch (const IterativeSolverFailure &e)
      {
        failure_reason = "the iterative linear solver failed (" +
                         one_line_message(e) +
                         "): a direct solver (Newton/Linear solver = auto) "
                         "tells whether the tangent is singular";
        return false;
      }
    catch (const std::exception &e)
      {
        failure_reason = "the tangent matrix is singular (" +
                         one_line_message(e) + ")" + advice;
        return false;
      }
    // A direct solve of a regular matrix, however ill-conditioned, leaves
    // K x - b a round-off of b. A singular one (a body free to slide) leaves
    // x without meaning: a residual of the order of b, or an x so large
    // that the next state is nonsense. Written as !(r <= 1e-6) so that a
    // residual that is not a number fails too.
    if (!(relative_residual <= 1e-6))
      {
        std::ostringstream reason;
        reason << "the tangent matrix is singular to working precision (the "
               << (system->iterative() ? "iterative" : "direct")
               << " solve leaves a relative residual of "
               << std::setprecision(3) << relative_residual << ")" << advice;
        failure_reason = reason.str();
        return false;
      }
    // The solver sees the condensed system: the constrained entries of the
    // update come from the constraints, which in the first update of a
    // step (lifting) carry the boundary increment itself.
    update_constraints().distribute(newton_update);
    return true;
  }

  // @sect4{Held pairing}
  //
  // After how many iterations of a Newton solve the pairing is held. On a
  // faceted master surface turned by the rotation, every slave point of C
  // with the nodal scheme (80 of 80, step 1) flipped between the two
  // segments of a groove at every iteration. Ordinary steps converge
  // before (one or two iterations per ramp step), with a free pairing.
  constexpr unsigned int hold_pairing_after = 4;

  // The iterations of a Newton solve whose updates may move the contact
  // zones' edges by extrapolation; the later ones are plain active-set
  // iterations.
  constexpr unsigned int extrapolate_edges_until = 8;

  // While the pairing is held, an accepted iterate stops a point that has
  // passed its partner's end at that vertex, with the vertex normal: past
  // a groove's vertex the segment's extension runs inside the neighbouring
  // segment, and holding points there ended a rotation of C (facet
  // normals, nodal scheme, one element per step) 6.8 % low. The line
  // search's trials follow the extension instead (Pairing::hold): the
  // switch to the vertex is a jump of the residual, which stopped the
  // search (C, facet normals, nodal, 80 around, failed at step 5).
  ContactInterface::Pairing
  ContactProblem::accepted_pairing() const
  {
    return keep_partners ? ContactInterface::Pairing::hold_within_segments :
                           ContactInterface::Pairing::search;
  }

  // @sect4{A press from rest in finite strain}
  //
  // A step that starts from the undeformed state (every unknown zero) with
  // no contact pressure, some body in finite strain: its problem linearised
  // at that state is the small-strain one, with the same Lame constants (the
  // laws agree to first order at F = I) and the contact measured on the
  // reference configuration. That problem is piecewise linear, and the rules
  // that find a contact zone growing from a point in a few iterations (the
  // edges' extrapolation, whole updates that open or close nodes) hold for
  // it. Its solution is the starting iterate of the finite-strain Newton
  // iteration, whose zone is then within a node or two. Solved in finite
  // strain from the start, the first update put the whole load on the two or
  // three nodes that touch, a state far outside the range of the
  // linearisation (relative residual 2 after the update, then damped
  // updates, inverted elements and cuts). Steel on aluminium (Hertz, a = R /
  // 10, the whole load in one step from touching), Saint Venant-Kirchhoff,
  // frictionless: 45 to 144 iterations and two to five cuts before, 6 to 10
  // and none now (bench/first-step, validation.md).
  bool
  ContactProblem::starts_from_rest_in_finite_strain() const
  {
    const bool finite_strain =
      std::any_of(contacts.begin(), contacts.end(), [](const auto &c) {
        return !c->small_strain();
      });
    const bool zones_to_find =
      std::all_of(contacts.begin(), contacts.end(), [](const auto &c) {
        return c->zone_grows_from_point();
      });
    // With friction too: the small-strain iterations find the zone with
    // every closed node sticking, and the stick and slip states are chosen
    // under the model's laws from there (solve_newton_step()). Steel on
    // aluminium from touching, Saint Venant-Kirchhoff, mu = 0.2 and 0.5,
    // one step at h = 0.01 to 0.0025 and the first of four at h = 0.01 and
    // 0.005: 6 to 9 iterations and no cut, where the finite-strain iteration
    // from rest took 12 to 164 and up to five cuts or failed
    // (bench/first-step). Not with a
    // cyclic sector: small strain there solved a sector of 11 of 12 elements
    // (C, Gauss 2) with an inexact tangent, linearly converging, a defect of
    // its own, left open. Every process decides alike (each holds the whole
    // vector, but a decision that differed would leave the others waiting).
    return finite_strain && zones_to_find && sector.angle == 0 &&
           Utilities::MPI::max(solution.linfty_norm(), communicator) == 0;
  }

  void
  ContactProblem::linearise(const bool on)
  {
    if (on == linearised)
      return;
    if (on)
      {
        model_materials = materials;
        for (auto &[id, material] : materials)
          material = Material(material.youngs_modulus,
                              material.poissons_ratio,
                              material.plane,
                              Kinematics::small_strain);
      }
    else
      materials = model_materials;
    for (const auto &contact : contacts)
      contact->linearise(on);
    linearised = on;
  }

  // Whether a signal asked the run to stop, on any process (all of them
  // leave their Newton loop at the same iteration: a process that left
  // alone would leave the others waiting in the next collective call).
  // Asked at every iteration and between step cuts: a SIGTERM used to wait
  // for all the cuts of a step (with Maximum step cuts = 30, over a
  // minute).
  bool
  ContactProblem::stop_requested() const
  {
    const bool here = stop_signal != 0;
    return n_processes > 1 ? Utilities::MPI::logical_or(here, communicator) :
                             here;
  }

  // @sect4{The load step}
  //
  // The predictor of a load step: extrapolate the last increment when it
  // was of the same kind (pressure only, or rotation only), in the
  // parameter the state is linear in: the pressure of the ramp, the
  // rotation, or else the pseudo-time, in which a general problem's
  // boundary data are written (its load states carry no pressure or
  // rotation: it was never extrapolated). Returns the factor of the last
  // increment (0: no extrapolation).
  //
  // The increments must be of the same kind because the factor is a ratio
  // of one parameter's increments: the rotation program presses the rings
  // in its first step and turns them after, and its first turn has only a
  // pressure increment behind it, from which no turn can be scaled.
  double
  ContactProblem::extrapolation_factor(const double t_next) const
  {
    // The first step has no increment behind it (both times are 0).
    if (!parameters.newton.extrapolate || !(current_time > previous_time))
      return 0;
    const LoadState next = load_program.state(t_next);
    const LoadState now  = current_load;
    const LoadState prev = load_program.state(previous_time);
    const double    dp0  = now.pressure - prev.pressure,
                 dp1     = next.pressure - now.pressure;
    const double ds0     = now.rotation_elements - prev.rotation_elements,
                 ds1     = next.rotation_elements - now.rotation_elements;
    if (ds0 == 0 && ds1 == 0 && dp0 != 0)
      return dp1 / dp0;
    if (dp0 == 0 && dp1 == 0 && ds0 != 0)
      return ds1 / ds0;
    if (dp0 == 0 && dp1 == 0 && ds0 == 0 && ds1 == 0)
      return (t_next - current_time) / (current_time - previous_time);
    return 0;
  }

  // Whether the extrapolated state has the boundary near its target at the
  // load state tried: its imposed values (and normal conditions) within a
  // tenth of their increment from the converged state. On a path linear in the
  // extrapolated parameter they agree to round-off (or to second order, turning
  // a boundary in small steps).
  bool
  ContactProblem::predictor_meets_boundary(
    const Vector<double> &converged) const
  {
    double miss = 0, increment = 0, largest = 0;
    for (const auto &[dof, value] : boundary_target)
      {
        miss      = std::max(miss, std::abs(solution(dof) - value));
        increment = std::max(increment, std::abs(value - converged(dof)));
        largest   = std::max(largest, std::abs(value));
      }
    // The normal conditions N . u = g on their constrained component.
    for (unsigned int k = 0; k < normal_target.size(); ++k)
      {
        const auto dof = normal_target[k].dofs[normal_component[k]];
        miss           = std::max(miss,
                        std::abs(normal_constrained_value(k, solution) -
                                 solution(dof)));
        increment      = std::max(increment,
                             std::abs(normal_constrained_value(k, converged) -
                                      converged(dof)));
        largest        = std::max(largest, std::abs(normal_target[k].value));
      }
    // The same decision on every process.
    if (n_processes > 1)
      {
        miss      = Utilities::MPI::max(miss, communicator);
        increment = Utilities::MPI::max(increment, communicator);
        largest   = Utilities::MPI::max(largest, communicator);
      }
    // The extrapolation's round-off (x + a x - a x) is no miss: the bound of
    // make_lifting_constraints().
    return miss <= 0.1 * increment +
                     1e3 * std::numeric_limits<double>::epsilon() * largest;
  }

  // One step of the load program, cut in halves while Newton fails. The
  // step is reached through sub-increments: each one that converges
  // becomes the new start, and a halved increment is kept for the rest of
  // the step (it is not doubled again). A run ends only when a step still
  // fails after Newton/Maximum step cuts halvings; the steps before it are
  // kept.
  bool
  ContactProblem::solve_load_step(const unsigned int step)
  {
    unsigned int cuts = 0, total_iterations = 0;
    Timer        wall;
    if (!advance_to(step, load_program.time(step), cuts, total_iterations))
      return false;
    // Adaptive refinement (refinement.cc): the step solved again on finer
    // meshes before it is reported.
    if (!refine_and_solve_again(step, cuts, total_iterations))
      return false;
    postprocess_step(step, total_iterations, cuts, wall.wall_time());
    return true;
  }

  // From the current state to the load state at t_end, through increments
  // halved while Newton fails (at most Newton/Maximum step cuts times).
  bool
  ContactProblem::advance_to(const unsigned int step,
                             const double       t_end,
                             unsigned int      &cuts,
                             unsigned int      &total_iterations)
  {
    double dt = t_end - current_time;
    // Whether the increment being tried starts from the last converged
    // state itself: after a failure from the extrapolated state, the same
    // increment is tried from there before it is cut.
    bool from_converged = false;
    // Whether the last converged state is a step from rest (the previous
    // state is the rest state) in which some pair's contact zone closed over
    // part of its slave surface: some node closed, fewer than half. Every
    // process decides alike.
    const auto zone_closed_from_rest = [this]() {
      if (Utilities::MPI::max(previous_solution.linfty_norm(), communicator) !=
          0)
        return false;
      const bool here =
        std::any_of(contacts.begin(), contacts.end(), [](const auto &c) {
          const unsigned int closed = c->n_active();
          return closed > 0 && 2 * closed < c->multiplier_dofs().size();
        });
      return n_processes > 1 ? Utilities::MPI::logical_or(here, communicator) :
                               here;
    };
    // Sums of halved increments reach t_end only up to round-off: a
    // relative margin keeps them from adding a sub-increment of 1e-16.
    while (current_time < t_end - 1e-12 * std::abs(t_end))
      {
        const double         t_next    = std::min(current_time + dt, t_end);
        const Vector<double> converged = solution;

        // Predictor: the extrapolation of the last increment, unless a try
        // from it has just failed.
        const double linear =
          from_converged ? 0.0 : extrapolation_factor(t_next);
        double scale = linear;
        // After a step from rest in which a contact zone closed over part of
        // its slave surface (some node closed, fewer than half), the state is
        // scaled by sqrt(r), r = 1 + linear the ratio of the loads from rest
        // (when the load is zero at rest), not by r. Such a zone grows as the
        // square root of the load (Hertz; the displacements away from it grow
        // about as the load), and the linear extrapolation, twice the first
        // of equal steps, closed 39 nodes where 29 close (h = 0.005): 12
        // iterations failed from there, and the step was solved in 10 more
        // from the first step's state. The square root is a measured choice,
        // not a derived one: steel on aluminium from touching, four steps, h
        // = 0.01 and 0.005, mu = 0, 0.2, 0.5, nodal / Gauss 2 / segment-based
        // 2, the second step's iterations: finite strain 7 to 22 -> 3 to 6,
        // small strain 2 to 10 -> 1 to 5 (bench/first-step, its n=4 lines).
        // A zone over most of its surface (conforming bodies: the rings, the
        // patch test, a fit) or none (bodies apart) is linear in the load,
        // and keeps the linear extrapolation (exact for the patch test; the
        // rings' ramp took one more iteration with the square root). Imposed
        // displacements are not scaled so: the square root moves them short
        // of their target, and the linear extrapolation is taken (below).
        if (scale != 0 && zone_closed_from_rest())
          scale = std::sqrt(1 + linear) - 1;
        if (scale != 0)
          solution.add(scale, converged, -scale, previous_solution);
        // Boundary data that is not a number (a general problem's
        // expression, e.g. sqrt(0.6 - t)) and a state that is not finite (a
        // diverging iterate) fail this try like a Newton failure: the step
        // is cut, and the converged steps stay. Reported as inverted
        // elements or a bare "not finite", they used to hide their cause.
        unsigned int iterations = 0;
        double       residual   = std::numeric_limits<double>::infinity();
        bool         ok         = false;
        try
          {
            apply_boundary_motion(load_program.state(t_next));
            // A load program with a kink in it (pressed, then moved
            // sideways) is not extrapolated across the kink: the predictor
            // would go on pressing. Seen where the imposed displacements
            // are: a cylinder pressed by its top moved down, then sideways
            // in one step, started from a zone pressed on by 90 % more, and
            // its Newton iteration failed after 12 iterations before it was
            // tried again from the converged state (17 in all, 5 without).
            if (scale != 0 && !predictor_meets_boundary(converged))
              {
                solution = converged;
                if (scale != linear)
                  solution.add(linear, converged, -linear, previous_solution);
                scale = scale != linear && predictor_meets_boundary(converged) ?
                          linear :
                          0;
                if (scale == 0)
                  solution = converged;
              }
            ok = solve_newton_step(iterations, residual);
          }
        catch (const BoundaryDataError &e)
          {
            failure_reason = e.what();
          }
        catch (const NonFiniteState &e)
          {
            failure_reason = e.what();
          }
        // A failure in the first iteration (or an exception) leaves the
        // lifting flag set; between Newton solves the constraints are the
        // homogeneous ones.
        lifting = false;
        total_iterations += iterations;
        // Converged: the interfaces keep this state as the reference of the
        // next increment's slip (friction), and the state it started from
        // becomes the second point of the next extrapolation.
        if (ok)
          {
            for (const auto &contact : contacts)
              contact->accept_state(solution);
            previous_solution = converged;
            previous_time     = current_time;
            current_time      = t_next;
            from_converged    = false;
            continue;
          }
        // Failed: back to the last converged state, half the increment.
        // The load state and the pairing go back with it, so that the
        // interfaces (read by the next try and by the output if the run
        // stops here) describe the state that is kept.
        solution     = converged;
        current_load = load_program.state(current_time);
        for (const auto &contact : contacts)
          contact->update(solution);
        if (stop_requested())
          {
            log << "Interrupted by a signal in step " << step
                << ": stopping with the last converged state (t = "
                << current_time << ")\n";
            return false;
          }
        // The extrapolation is a guess: a state off the path (a body held
        // by the contact whose first step removed an initial overlap, not
        // in proportion to the load, was extrapolated apart from it) is
        // not a reason to cut the step.
        if (scale != 0)
          {
            from_converged = true;
            log << wrap_text("  step " + std::to_string(step) +
                             ": Newton failed from the extrapolated state (" +
                             failure_reason +
                             "); trying again from the last converged state");
            continue;
          }
        from_converged = false;
        if (cuts == parameters.newton.max_step_cuts)
          {
            std::ostringstream message;
            message << "Step " << step << ": Newton did not converge after "
                    << cuts << " step cuts (" << failure_reason
                    << "; last relative residual " << residual
                    << " at t = " << t_next << ", increment " << dt
                    << "); stopping with the last converged state (t = "
                    << current_time << ")";
            log << wrap_text(message.str());
            return false;
          }
        ++cuts;
        dt /= 2;
        std::ostringstream message;
        message << "  step " << step << ": Newton failed (" << failure_reason
                << "; relative residual " << residual
                << "), cutting the increment to " << dt;
        log << wrap_text(message.str());
      }
    return true;
  }

  // One line per Newton iteration (Newton/Verbose). Before the update that
  // moves the boundary, the measures are those of the previous load state
  // (the reactions may be zero): not shown. The line gives each measure
  // beside its floor, so that a stalled step shows whether it is stuck
  // above the arithmetic's limit or merely at it.
  void
  ContactProblem::print_newton_iteration(const unsigned int     it,
                                         const ResidualMeasure &measure,
                                         const unsigned int     n_changed) const
  {
    if (lifting)
      {
        log << "    Newton " << std::setw(2) << it
            << "  boundary increment imposed on the update  active "
            << n_active_nodes() << "/" << n_contact_nodes() << '\n';
        return;
      }
    log << "    Newton " << std::setw(2) << it << "  relative residual "
        << std::scientific << std::setprecision(3) << measure.force;
    // Converged before the tangent (and the floor) was assembled.
    if (measure.force_floor_known)
      log << " (floor " << measure.force_floor << ")";
    else
      log << " (floor not needed)";
    if (measure.at_rest)
      log << "  gap (nothing has moved yet)";
    else
      log << "  gap " << measure.gap << " (floor " << measure.gap_floor << ")";
    log << std::defaultfloat << "  active " << n_active_nodes() << "/"
        << n_contact_nodes() << "  changed " << n_changed << '\n';
  }

  // @sect4{The Newton iteration}
  //
  // Semi-smooth Newton: pair, choose the active set, assemble, solve, and
  // move along the update as far as the residual decreases (line search).
  // Converged when the active set did not change, and both the force rows
  // and the contact rows are below the tolerance relative to their own
  // scales, or at their round-off floor (see residual_measure()).
  // A state with an inverted element (det F <= 0) is never accepted.
  //
  // The active-set choice max(0, w_k lambda_k - c g~_k) makes the residual
  // only piecewise smooth; Newton's method on it is the primal-dual
  // active-set method, which is converged only when the set it solved with
  // is the set the new iterate chooses: hence n_changed == 0 in the test.
  bool
  ContactProblem::solve_newton_step(unsigned int &iterations,
                                    double       &final_residual)
  {
    const auto    &newton = parameters.newton;
    Vector<double> newton_update(dof_handler.n_dofs());
    iterations = 0;
    failure_reason.clear();
    // Every load step pairs afresh; the pairing is held only within the
    // step whose Newton iteration cycled.
    keep_partners = false;
    visited_states.clear();
    stalled_on_kink = false;
    // The edges' extrapolation belongs to this solve's first iterations:
    // every update after it (a state restored after a failure, the
    // postprocessing, a refined mesh) chooses by the plain rule.
    const auto plain_rule_after = [this](ContactProblem *) {
      extrapolating_edges = false;
      stalled_on_kink     = false;
      holding_stick       = false;
      for (const auto &contact : contacts)
        {
          contact->allow_edge_extrapolation(false);
          contact->hold_stick(false);
        }
      linearise(false);
    };
    const std::unique_ptr<ContactProblem, decltype(plain_rule_after)>
      restore_plain_rule(this, plain_rule_after);
    // The first update moves the boundary to the new load state. Written
    // straight into the solution, the whole increment sat in the first
    // layer of elements along the boundary; at finite strain with thin
    // layers (F, 160 x 12 per ring, p = 1e7 in one step: about 27 % strain
    // there) Newton went to another solution, the rings apart, p_A = 0.
    // Through the linearised problem the increment spreads over the bodies.
    // No lifting update (false) when the predictor hit the target already.
    lifting = make_lifting_constraints();
    for (const auto &contact : contacts)
      contact->start_step(solution);
    linearise(starts_from_rest_in_finite_strain());
    unsigned int hold_pairing_at = hold_pairing_after;
    // The iteration up to which the stick zones' edges are extrapolated in
    // finite strain (a frictional step from rest, see below).
    unsigned int stick_edges_until = 0;
    // From a linearised iterate to the model's own laws and contact
    // geometry, at the same iterate: paired afresh in the current
    // configuration (the partners held in the linearised iterations are the
    // reference configuration's), and held again only after as many
    // iterations as at the start. The first assembly there chooses the
    // states by the plain rule (extrapolated across the switch, from the
    // linearised profile, the stick zone's edge went astray: steel on
    // aluminium, mu = 0.2, h = 0.0025, Gauss 2, 52 iterations and a cut).
    const auto to_the_model_laws = [&](const unsigned int it) {
      linearise(false);
      extrapolating_edges = false;
      // (A damped small-strain update's stall, line_search(), says nothing
      // of the next update under the model's laws.)
      stalled_on_kink = false;
      for (const auto &contact : contacts)
        contact->allow_edge_extrapolation(false);
      keep_partners   = false;
      hold_pairing_at = it + hold_pairing_after;
      return assemble_newton_system();
    };
    // With friction, a contact zone that grows from a point (the first step
    // of a press) first finds its width with every closed node sticking:
    // the contact is then a linear tie with a moving edge, whose edges the
    // extrapolation finds in a few iterations (small strain). The stick and
    // slip states are chosen once the zone no longer moves. Chosen together
    // from the first iteration, the states flipped in waves over a zone that
    // grew by a node or two per damped iteration: steel on aluminium, mu =
    // 0.2, h = 0.005, 29 iterations and a cut with Gauss 2.
    holding_stick =
      std::any_of(contacts.begin(),
                  contacts.end(),
                  [](const auto &c) { return c->has_friction(); }) &&
      std::all_of(contacts.begin(), contacts.end(), [](const auto &c) {
        return c->small_strain() && c->zone_grows_from_point();
      });
    for (const auto &contact : contacts)
      contact->hold_stick(holding_stick);
    unsigned int n_changed = assemble_newton_system();
    // The update that led to the current iterate: none yet, or whether it
    // imposed the boundary increment and the residual it started from.
    bool   updated = false, update_lifted = false;
    double update_from = 0;
    for (unsigned int it = 0;; ++it)
      {
        if (must_stop(it))
          {
            final_residual = std::numeric_limits<double>::infinity();
            return false;
          }
        // The zone has found its width, to a node (or the iterations for
        // finding it are over): the stick and slip states from here on,
        // chosen at this iterate, which is assembled again with them. Before
        // the test of convergence: an iterate converged under held stick is
        // not one under friction. To a node: with segment-based 2 an edge
        // node can open and close in turn under whole updates (steel on
        // aluminium, the first of four steps, h = 0.0025: 41, 40, 41, 40
        // closed), and waiting for no change held the stick to the 8th
        // iteration (12 iterations in all). And at the latest halfway
        // through Newton/Maximum iterations, whatever it is set to.
        if (holding_stick && !lifting && it > 0 &&
            (last_closed_changes <= 1 || it >= extrapolate_edges_until ||
             2 * it >= newton.max_iterations))
          {
            holding_stick = false;
            for (const auto &contact : contacts)
              contact->hold_stick(false);
            // A frictional step from rest in finite strain (linearised
            // first): the contact zone is found, and the stick and slip
            // states are chosen under the model's laws right away, their
            // edges extrapolated there for as many iterations as a step's
            // first. The linearised stick zone is not the finite-strain one
            // (a = R / 10 strains the bodies by 5 %: steel on aluminium,
            // mu = 0.2, h = 0.005, its edge is 3 nodes further in), and
            // finding it first cost 4 to 6 damped iterations, after which
            // the finite-strain iteration moved the edge a node per
            // iteration: h = 0.0025, 13 to 16 iterations (and cuts under the
            // default 12); now 8 or 9 (bench/first-step).
            if (linearised)
              {
                if (newton.verbose)
                  log << "    the contact zone is found: the model's laws "
                         "from here, with the stick and slip states\n";
                n_changed += to_the_model_laws(it);
                stick_edges_until = it + extrapolate_edges_until;
              }
            else
              n_changed += assemble_newton_system(accepted_pairing());
          }
        ResidualMeasure measure = residual_measure();
        // An iterate assembled without its tangent: the tangent now, at the
        // same state and pairing, unless the iterate has converged. The
        // update needs it, and so may the test of convergence (the round-off
        // floor of the forces).
        if (!tangent_assembled && !(!lifting && n_changed == 0 &&
                                    measure.converged(newton.tolerance)))
          {
            assemble_system();
            measure = residual_measure();
          }
        // The iterate before the lifting update is the last load state's
        // equilibrium, its boundary not yet moved: never converged.
        bool converged = !lifting && !holding_stick && n_changed == 0 &&
                         measure.converged(newton.tolerance);
        // The linearised step has converged: the model's own laws and
        // contact geometry from here, at the same iterate, with the active
        // set the plain rule chooses there (a node or two from the
        // linearised one). Without friction: with it, the switch came at the
        // end of the held stick (above).
        if (converged && linearised)
          {
            if (newton.verbose)
              log << "    the linearised step has converged: the model's "
                     "laws from here\n";
            // Not converged with an inverted element: the law was not
            // evaluated there.
            n_changed = to_the_model_laws(it);
            measure   = residual_measure();
            converged = n_changed == 0 && n_inverted == 0 &&
                        measure.converged(newton.tolerance);
          }
        // One number for the step's report and for the rate of the update
        // that led here: the worse of the two groups.
        final_residual = std::max(measure.force, measure.gap);
        if (updated)
          convergence_record.record(update_lifted,
                                    update_from,
                                    final_residual,
                                    converged);
        if (newton.verbose)
          print_newton_iteration(it, measure, n_changed);
        // A residual that is not a number would only give an update that is
        // not one: the step fails here, with its reason, and is cut.
        if (!std::isfinite(measure.merit))
          {
            failure_reason = "the residual is not finite";
            return false;
          }
        if (converged)
          return true;
        if (it == newton.max_iterations)
          {
            failure_reason = "no convergence in " +
                             std::to_string(newton.max_iterations) +
                             " iterations";
            return false;
          }

        // A slave point in a groove of a faceted master (a master vertex seen
        // from the slave side, where the normal turns by the angle between
        // the segments) has no position with one normal where the residual
        // vanishes: the pairing flips between the two segments at every
        // iteration and Newton cycles. After a few iterations every point
        // keeps its partner (on the segment's extension if need be): the
        // residual is smooth, and the step converges to the state with that
        // pairing. The next step pairs afresh.
        if (it + 1 == hold_pairing_at)
          keep_partners = true;
        // The zones' edges extrapolated in the iterates of the first
        // iterations (see ContactInterface::extrapolate_zone_edges()), at
        // small strain: the contact zones' while the contact is piecewise
        // linear (no friction, or every closed node held in stick), and the
        // stick zones' once the stick and slip states are free. Where the
        // contact is piecewise linear, updates that open or close nodes are
        // also taken whole (line_search()). Not at finite strain: shallow
        // ironing (friction 0.3, 40 steps) went from 181 iterations to 365
        // and 4 cuts, its zone moving by a node or two a step on a sliding,
        // turning surface. Except the stick zones' in the first iterations
        // under the model's laws of a frictional step from rest (the
        // contact zone is then in place, from the linearised iterations;
        // the contact zones' edges are never extrapolated at finite strain,
        // where the contact is not piecewise linear).
        const bool move_edges =
          (it < extrapolate_edges_until &&
           std::all_of(contacts.begin(),
                       contacts.end(),
                       [](const auto &c) { return c->small_strain(); })) ||
          it < stick_edges_until;
        extrapolating_edges =
          move_edges &&
          std::all_of(contacts.begin(), contacts.end(), [](const auto &c) {
            return c->piecewise_linear();
          });
        // Per pair: the contact zones' edges only where every pair is
        // piecewise linear (their updates are then taken whole), the stick
        // zones' wherever the states are free.
        for (const auto &contact : contacts)
          contact->allow_edge_extrapolation(
            extrapolating_edges ||
            (move_edges && !contact->piecewise_linear()));
        // Updates that change the stick and slip states are not taken whole
        // in a growing zone's first iterations (they were before the
        // tangential traction's dual basis, against a stall on the kink
        // between stick and slip that the dual basis removed: steel on
        // aluminium, mu = 0.2, h = 0.01, the first of four steps, Gauss 2,
        // 5 iterations either way; kept, the rule made h = 0.0025 in one
        // step take 40 iterations and a cut instead of 10).

        if (!solve_linear_system(newton_update))
          {
            final_residual = std::numeric_limits<double>::infinity();
            return false;
          }
        ++iterations;
        // The next iterate without its tangent first when it is expected to
        // converge (see ConvergenceRecord): the test of convergence needs
        // only the residual, and after the last update of a step the tangent
        // was thrown away (21 of 48 assemblies on A's ramp). The forecast
        // uses this run's own quadratic rate: always assembling the
        // residual first wasted an assembly at every iteration that did not
        // converge (a loss on the rotation modelisations); on A's ramp the
        // forecast skips 19 tangents and wastes none.
        updated             = true;
        update_lifted       = lifting;
        update_from         = final_residual;
        const Assembly next = convergence_record.expects(lifting,
                                                         final_residual,
                                                         newton.tolerance) ?
                                Assembly::residual :
                                Assembly::residual_and_tangent;
        if (!take_update(newton_update, measure, next, n_changed))
          return false;
      }
  }


  // Whether the Newton iteration `it` must not go on: a signal ends the
  // step here, not after it (and its cuts): the converged steps are on disk
  // already; an inverted element (det F <= 0 at a quadrature point) makes
  // the material law meaningless, and the step is cut. The assembly does
  // not evaluate the law at such a point but counts it (n_inverted), so
  // that the rejection comes here with the smallest det F in its message.
  bool
  ContactProblem::must_stop(const unsigned int it)
  {
    if (stop_requested())
      {
        failure_reason = "interrupted by a signal";
        return true;
      }
    if (n_inverted > 0)
      {
        failure_reason = inverted_state_reason();
        if (parameters.newton.verbose)
          log << "    Newton " << std::setw(2) << it << "  " << failure_reason
              << '\n';
        return true;
      }
    return false;
  }


  // @sect4{Taking the update}
  //
  // The Newton update applied, and the next iterate assembled (`next`
  // says whether with its tangent). The update that imposes the boundary
  // increment is taken whole: a fraction of it would leave the boundary
  // short of the load state, and the merit of the state before it does not
  // see the increment. An inverted state is rejected at the next iteration
  // (the load step is then cut). Any other update goes through the line
  // search; where it finds no decrease, the pairing is the suspect and is
  // held, and where it is held already, the step fails (false).
  bool
  ContactProblem::take_update(const Vector<double>  &newton_update,
                              const ResidualMeasure &measure,
                              const Assembly         next,
                              unsigned int          &n_changed)
  {
    // The solve leaves the boundary at its target up to round-off; the
    // homogeneous updates after it would keep that error for the whole
    // step, so the imposed values are written again, exactly.
    const auto states_before = contact_states();
    if (lifting)
      {
        solution += newton_update;
        set_boundary_target(); // exactly, not up to round-off
        lifting             = false;
        n_changed           = assemble_newton_system(accepted_pairing(), next);
        last_closed_changes = n_closed_changed_since(states_before);
        return true;
      }
    // The changes are counted from here: each trial of the line search is
    // assembled afresh, and counting against the trial before it said
    // "changed 0" while the active set grew by three nodes per iteration
    // (and an iterate could pass as converged with a set it was not solved
    // with).
    double     step_length   = 1;
    const auto count_changes = [&]() {
      n_changed           = n_changed_since(states_before);
      last_closed_changes = n_closed_changed_since(states_before);
    };
    // No decrease along the update: with a free pairing the residual may
    // jump between pairings at every trial, so the pairing is held and the
    // same iterate assembled again, now smooth in the displacement; the
    // next iteration solves from there. With the pairing held already
    // there is nothing left to try, and the step is cut.
    if (!line_search(newton_update, measure, next, n_changed, step_length))
      {
        stalled_on_kink = false; // it concerned the update that failed
        if (keep_partners)
          return false;
        keep_partners = true;
        assemble_newton_system(accepted_pairing());
        count_changes();
        if (parameters.newton.verbose)
          log << "      line search failed: pairing held\n";
        return true;
      }
    if (parameters.newton.verbose && step_length < 1)
      log << "      line search: step length " << step_length << '\n';
    // A damped update with friction at small strain that changed no state
    // (see line_search()).
    stalled_on_kink =
      step_length < 1 && n_changed_since(states_before) == 0 &&
      std::all_of(contacts.begin(), contacts.end(), [](const auto &c) {
        return c->small_strain() && c->has_friction();
      });
    // The trials followed held partners onto their extensions.
    if (keep_partners)
      assemble_newton_system(accepted_pairing(), next);
    count_changes();
    return true;
  }

  std::vector<ContactInterface::NodeStates>
  ContactProblem::contact_states() const
  {
    std::vector<ContactInterface::NodeStates> states;
    for (const auto &contact : contacts)
      states.push_back(contact->node_states());
    return states;
  }

  std::vector<int>
  ContactProblem::state_key() const
  {
    std::vector<int> key;
    for (const auto &contact : contacts)
      {
        const auto states = contact->node_states();
        for (unsigned int k = 0; k < states.active.size(); ++k)
          key.push_back(states.active[k] ? 2 + states.slip_sign[k] : 0);
      }
    return key;
  }

  // The nodes that opened or closed (friction's states aside).
  unsigned int
  ContactProblem::n_closed_changed_since(
    const std::vector<ContactInterface::NodeStates> &before) const
  {
    unsigned int n = 0;
    for (unsigned int i = 0; i < contacts.size(); ++i)
      {
        const auto now = contacts[i]->node_states();
        for (unsigned int k = 0; k < now.active.size(); ++k)
          n += k >= before[i].active.size() ||
               now.active[k] != before[i].active[k];
      }
    return n;
  }

  unsigned int
  ContactProblem::n_changed_since(
    const std::vector<ContactInterface::NodeStates> &before) const
  {
    unsigned int n = 0;
    for (unsigned int i = 0; i < contacts.size(); ++i)
      n += contacts[i]->n_changed_since(before[i]);
    return n;
  }

  // @sect4{The line search}
  //
  // Globalisation of the semi-smooth Newton method: u + a du with a = 1,
  // 1/2, 1/4, ... until the merit |R| (the Euclidean norm of the free rows)
  // decreases by the Armijo fraction, |R(u + a du)| <= (1 - 1e-4 a) |R(u)|,
  // and no element is inverted; the system at the accepted state is left
  // assembled. With faceted master surfaces the residual jumps where a
  // contact point crosses a master vertex (its normal turns by the angle
  // between the segments), and a full step can jump back and forth between
  // two pairings forever; the line search stops on the lower side.
  bool
  ContactProblem::line_search(const Vector<double>  &newton_update,
                              const ResidualMeasure &before,
                              const Assembly         assembly,
                              unsigned int          &n_changed,
                              double                &step_length)
  {
    constexpr unsigned int max_halvings  = 6;
    constexpr double       armijo        = 1e-4;
    const Vector<double>   start         = solution;
    const auto             states_before = contact_states();
    visited_states.insert(state_key());
    // Each trial is paired and assembled as an iterate would be (the
    // active set is chosen anew): the merit must be that of the state the
    // loop would continue from. A held pairing follows the segments'
    // extensions here, not stopped at the vertices (see
    // accepted_pairing()).
    for (unsigned int halving = 0;; ++halving)
      {
        solution = start;
        solution.add(step_length, newton_update);
        n_changed = assemble_newton_system(keep_partners ?
                                             ContactInterface::Pairing::hold :
                                             ContactInterface::Pairing::search,
                                           assembly);
        // While the zones' edges move (the first iterations, see
        // extrapolate_edges_until), a whole update that opens or closes
        // nodes is taken whatever its merit: the merit of a state with
        // another active set has other rows (a gap where there was a
        // pressure), and its increase says nothing about the step. Damped,
        // a zone grew by three nodes per iteration from a touching point
        // (steps of 1/16); whole, it finds its width in two or three
        // iterations. The line search stays for the rest: a fixed active
        // set, friction's stick and slip, faceted masters.
        if (halving == 0 && extrapolating_edges && n_inverted == 0 &&
            n_closed_changed_since(states_before) > 0)
          return true;
        // Likewise, in any step, right after a damped update that changed
        // no state, one that changes only friction's states (a stall on the
        // kink between stick and slip: the fraction taken keeps the states,
        // and the next update aims at the same states again; the residual
        // halved at each iteration, 8e-8, 4e-8, 2e-8, ...). Never back to
        // states this step has met: the method can cycle (with every such
        // update whole, the second step of the problem above alternated
        // between two sets of 14 and 15 closed nodes).
        const bool whole_state_change =
          stalled_on_kink && n_closed_changed_since(states_before) == 0;
        if (halving == 0 && whole_state_change && n_inverted == 0 &&
            n_changed_since(states_before) > 0 &&
            visited_states.insert(state_key()).second)
          return true;
        // A trial with an inverted element is never accepted, whatever its
        // merit: the stress there was not evaluated.
        if (n_inverted == 0)
          {
            const double    tolerance = parameters.newton.tolerance;
            ResidualMeasure trial     = residual_measure();
            // At the round-off floor the merit is noise: take the step.
            const auto accept = [&]() {
              return trial.merit <= (1 - armijo * step_length) * before.merit ||
                     trial.converged(tolerance) || before.converged(tolerance);
            };
            // The floor of the forces, which needs the tangent, may decide:
            // the trial is assembled again at the same state and pairing,
            // with its tangent, so that the decision is the one a whole
            // assembly would have taken.
            if (!accept() && trial.undecided(tolerance))
              {
                assemble_system();
                trial = residual_measure();
              }
            if (accept())
              return true;
          }
        // Down to 1/64 of the update without a decrease: the iterate is
        // restored and the caller decides (hold the pairing, or fail).
        if (halving == max_halvings)
          {
            if (n_inverted > 0)
              return true; // rejected by the Newton loop with its message
            failure_reason = "the line search found no decrease of the "
                             "residual";
            solution       = start;
            return false;
          }
        step_length /= 2;
      }
  }
} // namespace RingContact
