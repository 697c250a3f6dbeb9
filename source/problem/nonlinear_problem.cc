// @sect3{The contact problem as the Newton solver sees it}
//
// ContactProblem implements NonlinearProblem (nonlinear_problem.h), the
// narrow interface through which the load steps and the Newton solver work
// (load_stepper.cc, newton_solver.cc): its convergence measures, its linear
// solve, and the switches of its contact pairs. The assembly is
// assembly.cc's, the boundary motion constraints.cc's, the refinement
// refinement.cc's; what is here is what the Newton iteration reads of the
// assembled system and how it steers the contact interfaces.
//
// The measures are the problem's because only the problem knows its scales:
// the reactions, the largest displacement and pressure, and what double
// precision can resolve in each row (residual_magnitude).
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
  template <int dim>
  ResidualMeasure
  ContactProblem<dim>::residual_measure() const
  {
    // Several roundings per term, the linear solver's backward error, and
    // the row sums of the noise: a factor of ten over eps |K| |z|, above the
    // stalled residuals measured on the variants of scripts/studies/variants
    // (doc/validation.md, "Newton").
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
  // was so, UMFPACK's code ended the run, or a block pushed sideways with no
  // support "converged", slid away, with a fraction of its contact pressure
  // (doc/validation.md, "Figures that were in the code's comments").
  template <int dim>
  bool
  ContactProblem<dim>::solve_linear_system(Vector<double> &newton_update,
                                           std::string    &failure_reason)
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

  // @sect4{The state and its contact pairs}
  //
  // A failed try goes back to a converged state: the load state with it, and
  // the contact interfaces paired again there, so that what they say (to the
  // next try, and to the output if the run stops here) is that state's.
  template <int dim>
  void
  ContactProblem<dim>::restore_state(const Vector<double> &state,
                                     const LoadState      &load)
  {
    solution     = state;
    current_load = load;
    for (const auto &contact : contacts)
      contact->update(solution);
  }

  template <int dim>
  void
  ContactProblem<dim>::accept_contact_state(const Vector<double> &state)
  {
    for (const auto &contact : contacts)
      contact->accept_state(state);
  }

  template <int dim>
  std::vector<ContactPairState>
  ContactProblem<dim>::contact_pair_states() const
  {
    std::vector<ContactPairState> pairs;
    for (const auto &contact : contacts)
      {
        ContactPairState pair;
        pair.small_strain = contact->small_strain();
        pair.friction     = contact->has_friction();
        pair.zone_grows_from_point =
          contact->active_set().zone_grows_from_point();
        pair.piecewise_linear = contact->piecewise_linear();
        pair.n_closed         = contact->active_set().n_active();
        pair.n_nodes          = contact->nodes().size();
        pairs.push_back(pair);
      }
    return pairs;
  }

  template <int dim>
  std::vector<NodeStates>
  ContactProblem<dim>::contact_node_states() const
  {
    std::vector<NodeStates> states;
    for (const auto &contact : contacts)
      states.push_back(contact->active_set().node_states());
    return states;
  }

  template <int dim>
  void
  ContactProblem<dim>::start_contact_step()
  {
    for (const auto &contact : contacts)
      contact->active_set().start_step(solution);
  }

  template <int dim>
  void
  ContactProblem<dim>::hold_stick(const bool hold)
  {
    for (const auto &contact : contacts)
      contact->active_set().hold_stick(hold);
  }

  template <int dim>
  void
  ContactProblem<dim>::allow_edge_extrapolation(const std::vector<bool> &allow)
  {
    AssertDimension(allow.size(), contacts.size());
    for (unsigned int i = 0; i < contacts.size(); ++i)
      contacts[i]->active_set().allow_edge_extrapolation(allow[i]);
  }

  // @sect4{The linearised problem}
  //
  // A step from rest in finite strain may be solved with the small-strain
  // laws and contact geometry first (problem/first_step.cc). Not with a
  // cyclic sector: small strain there solved a sector of 11 of 12 elements
  // (C, Gauss 2) with an inexact tangent, linearly converging, a defect of
  // its own, left open.
  template <int dim>
  bool
  ContactProblem<dim>::may_linearise() const
  {
    return sector.angle == 0;
  }

  // The model's laws are kept aside while the problem is linearised
  // (model_materials is then not empty), and come back after.
  template <int dim>
  void
  ContactProblem<dim>::linearise(const bool on)
  {
    if (on == !model_materials.empty())
      return;
    if (on)
      {
        model_materials = materials;
        for (auto &[id, material] : materials)
          material = Material<dim>(material.youngs_modulus,
                                   material.poissons_ratio,
                                   material.plane,
                                   linear_elasticity_law);
      }
    else
      {
        materials = model_materials;
        model_materials.clear();
      }
    for (const auto &contact : contacts)
      contact->linearise(on);
  }

  // @sect4{Rejected states and signals}
  //
  // A state with inverted points (det F <= 0), or points outside their
  // material law, is never accepted: the assembly counts them
  // (assembly.cc), and the Newton solver stops there with the reason.
  template <int dim>
  bool
  ContactProblem<dim>::state_rejected() const
  {
    return n_inverted > 0;
  }

  template <int dim>
  std::string
  ContactProblem<dim>::rejection_reason() const
  {
    return inverted_state_reason();
  }

  // Whether a signal asked the run to stop, on any process (all of them
  // leave their Newton loop at the same iteration: a process that left
  // alone would leave the others waiting in the next collective call).
  // Asked at every iteration and between step cuts: a SIGTERM used to wait
  // for all the cuts of a step (with Maximum step cuts = 30, over a
  // minute).
  template <int dim>
  bool
  ContactProblem<dim>::stop_requested() const
  {
    const bool here = stop_signal != 0;
    return n_processes > 1 ? Utilities::MPI::logical_or(here, communicator) :
                             here;
  }


  // This chapter's members for the dimensions the program runs in: the
  // explicit instantiation of the class in a chapter instantiates the
  // members defined here (see contact_problem.cc).
  template class ContactProblem<2>;
  template class ContactProblem<3>;
} // namespace RingContact
