// @sect3{Adaptive refinement: the mesh follows the contact}
//
// A contact zone is small: a mesh fine enough for its pressure everywhere
// spends most of its cells where nothing happens. After a load step has
// converged (every 'Refine every' steps, and at the last), the cells of
// largest error indicator are refined, those of smallest coarsened, the
// state is carried to the new mesh and the step is solved again there,
// 'Adaptive cycles' times (subsection Mesh refinement).
//
// The indicator is the registered estimator's the file chooses
// (refinement_estimator.h, estimators/): by default Kelly's (deal.II's
// KellyErrorEstimator: the jumps of the displacement gradient across the
// inner faces) plus, on the faces of the slave surfaces, the residual of the
// contact condition (the body's traction P N against the force the
// multiplier puts on it) and the jumps of the pressure's slope between
// neighbouring faces, weighed by the distance from the contact zone. Kelly's
// alone sees no boundary, and the pressure's error sits on one. Where the
// surfaces face each other, their faces are kept within a factor 1.5 of each
// other.
//
// The new mesh has hanging nodes, on the inner faces only: in 2d a face
// on a boundary has no neighbour, so neither contact surface has one, and
// a surface of faces of several sizes is what the contact search already
// handles. The hanging nodes' constraints join the others (constraints.cc);
// a multiplier at a hanging node lies off the slave surface and means
// nothing.
//
// The state goes to the new mesh in two parts. The displacement, one
// FE_Q(p)^2 per body, goes by deal.II's SolutionTransfer on a DoFHandler of
// its own: a cell's body never changes, so its children keep its element,
// which the transfer requires (the contact problem's own elements differ on
// the slave layer, whose children are not all on the surface). The
// multipliers live on the slave surfaces only, and go face by face: a new
// face inherits the values of the face it came from (interpolated by the
// multiplier's Lagrange polynomial) or of the faces it replaces. The
// friction's reference state is the transferred state of the step's start.
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/grid_refinement.h>
#include <deal.II/numerics/solution_transfer.h>

#include <ring_contact/base/components.h>
#include <ring_contact/base/dimension.h>
#include <ring_contact/base/utilities.h>
#include <ring_contact/problem/contact_problem.h>
#include <ring_contact/problem/face_multipliers.h>
#include <ring_contact/problem/refinement_estimator.h>

#include <algorithm>
#include <array>
#include <iomanip>
#include <set>

namespace RingContact
{
  namespace
  {
    using FaceMultipliers::face_multipliers;
    using FaceMultipliers::FacePoint;
    using FaceMultipliers::FaceValues;
    using FaceMultipliers::interpolate;
    using FaceMultipliers::multiplier_face_points;

    // A face known by its ends: the indices of lines (and vertices) are
    // reused once coarsening frees them, its place is not.
    using FaceKey = std::array<double, 4>;
    FaceKey
    key_of(const Triangulation<dim>::face_iterator &face)
    {
      return {{face->vertex(0)[0],
               face->vertex(0)[1],
               face->vertex(1)[0],
               face->vertex(1)[1]}};
    }

    // Which half of its parent face a child cell's face f is: the cell's
    // face is the parent's face f's child 0 or 1.
    unsigned int
    half_of_parent_face(const Triangulation<dim>::cell_iterator &cell,
                        const unsigned int                       f)
    {
      const auto parent_face = cell->parent()->face(f);
      return parent_face->child(0) == cell->face(f) ? 0 : 1;
    }
    // Where the surfaces face each other, their faces are kept within a
    // factor 1.5 of each other (see the flags' comments below).
    void
    keep_facing_faces_matched(
      const std::vector<std::unique_ptr<ContactInterface<dim>>> &contacts,
      const unsigned int                                         maximum_level)
    {
      // Where the surfaces face each other, their faces are kept within a
      // factor 1.5 of each other: the longer one is refined, and if it
      // already is in this cycle, the shorter one waits for the next; neither
      // is coarsened. Refined on its own, one surface ends up several times
      // finer than the other, which the contact does not survive (Hertz,
      // segment-based 2: p0 far off without the rule, close with it). Other
      // rules measured: the master a level ahead of the slave, the slave at
      // least as fine as the master (doc/validation.md, "Adaptive refinement").
      const auto future_length = [](const auto &cell, const unsigned int f) {
        const double length = cell->face(f)->measure();
        return cell->refine_flag_set() ? length / 2 : length;
      };
      const auto refine =
        [&](const Triangulation<dim>::active_cell_iterator &cell) {
          if (!cell->refine_flag_set() &&
              cell->level() < static_cast<int>(maximum_level))
            cell->set_refine_flag();
        };
      constexpr double ratio = 1.5;
      for (const auto &contact : contacts)
        {
          const auto &slave_segments  = contact->slave_surface().segments();
          const auto &master_segments = contact->master_surface().segments();
          for (const auto &[s, m] : contact->pairing().paired_segments())
            {
              const auto &slave_segment  = slave_segments[s];
              const auto &master_segment = master_segments[m];
              if (master_segment.is_copy)
                continue;
              const Triangulation<dim>::active_cell_iterator slave =
                slave_segment.cell;
              const Triangulation<dim>::active_cell_iterator master =
                master_segment.cell;
              slave->clear_coarsen_flag();
              master->clear_coarsen_flag();
              const auto slave_length = [&]() {
                return future_length(slave, slave_segment.face_no);
              };
              const auto master_length = [&]() {
                return future_length(master, master_segment.face_no);
              };
              if (master_length() > ratio * slave_length())
                refine(master);
              else if (slave_length() > ratio * master_length())
                refine(slave);
              if (master_length() > ratio * slave_length())
                slave->clear_refine_flag();
              if (slave_length() > ratio * master_length())
                master->clear_refine_flag();
            }
        }
    }

    // From the contact problem's unknowns to the displacement's (`to` true)
    // or back, cell by cell: the same FE_Q(p) for each component. The two
    // handlers share the mesh and walk its active cells in one order.
    void
    copy_displacement(const DoFHandler<dim> &problem_dofs,
                      const DoFHandler<dim> &displacement_dofs,
                      Vector<double>        &u,
                      Vector<double>        &v,
                      const bool             to)
    {
      std::vector<types::global_dof_index> dofs, u_dofs;
      auto other = displacement_dofs.begin_active();
      for (const auto &cell : problem_dofs.active_cell_iterators())
        {
          const auto &fe   = cell->get_fe();
          const auto &u_fe = other->get_fe();
          dofs.resize(fe.n_dofs_per_cell());
          u_dofs.resize(u_fe.n_dofs_per_cell());
          cell->get_dof_indices(dofs);
          other->get_dof_indices(u_dofs);
          for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
            {
              const auto [component, index] = fe.system_to_component_index(i);
              if (!Components::is_displacement<dim>(component))
                continue;
              const auto j =
                u_dofs[u_fe.component_to_system_index(component, index)];
              if (to)
                v(j) = u(dofs[i]);
              else
                u(dofs[i]) = v(j);
            }
          ++other;
        }
    }

    // The slave boundaries of all pairs.
    std::set<types::boundary_id>
    slave_boundaries(const Parameters &parameters)
    {
      std::set<types::boundary_id> ids;
      for (const auto &[slave, master] : parameters.contact_pairs())
        ids.insert(slave);
      return ids;
    }

    // The multipliers of `u` on every active face of a slave surface and on
    // every face it came from: the coarser faces' values are those of their
    // descendants at their support points (nested points), so that a face
    // that coarsening makes active again finds its own.
    using FaceRecord = std::map<FaceKey, FaceValues>;
    FaceRecord
    record_multipliers(const DoFHandler<dim>              &dof_handler,
                       const std::set<types::boundary_id> &slave_ids,
                       const Vector<double>               &u)
    {
      FaceRecord record;
      for (const auto &cell : dof_handler.active_cell_iterators())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() &&
              slave_ids.count(cell->face(f)->boundary_id()) > 0)
            {
              const auto       points = multiplier_face_points(cell->get_fe());
              const FaceValues values = face_multipliers(cell, f, points, u);
              record[key_of(cell->face(f))] = values;
              // Up the ancestors: t on this face is (half + t) / 2 on its
              // parent's, and so on up.
              Triangulation<dim>::cell_iterator c  = cell;
              double                            lo = 0, hi = 1;
              while (c->level() > 0)
                {
                  const unsigned int half = half_of_parent_face(c, f);
                  lo                      = (half + lo) / 2;
                  hi                      = (half + hi) / 2;
                  c                       = c->parent();
                  auto &ancestor          = record[key_of(c->face(f))];
                  for (const auto &p : points)
                    if (p.t >= lo - 1e-12 && p.t <= hi + 1e-12)
                      ancestor[{p.component, p.index}] = interpolate(
                        values, points, p.component, (p.t - lo) / (hi - lo));
                }
            }
      return record;
    }

    // The multipliers of `u` on the new mesh's slave faces from a record:
    // a face's own values, or its nearest recorded ancestor's interpolated
    // where the face lies on it.
    void
    restore_multipliers(const DoFHandler<dim>              &dof_handler,
                        const std::set<types::boundary_id> &slave_ids,
                        const FaceRecord                   &record,
                        Vector<double>                     &u)
    {
      std::vector<types::global_dof_index> face_dofs;
      for (const auto &cell : dof_handler.active_cell_iterators())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() &&
              slave_ids.count(cell->face(f)->boundary_id()) > 0)
            {
              const auto &fe     = cell->get_fe();
              const auto  points = multiplier_face_points(fe);
              face_dofs.resize(fe.n_dofs_per_face());
              cell->face(f)->get_dof_indices(face_dofs,
                                             cell->active_fe_index());
              Triangulation<dim>::cell_iterator c  = cell;
              double                            lo = 0, hi = 1;
              while (record.count(key_of(c->face(f))) == 0)
                {
                  Assert(c->level() > 0, ExcInternalError());
                  const unsigned int half = half_of_parent_face(c, f);
                  lo                      = (half + lo) / 2;
                  hi                      = (half + hi) / 2;
                  c                       = c->parent();
                }
              const FaceValues &values = record.at(key_of(c->face(f)));
              for (unsigned int i = 0, k = 0; i < fe.n_dofs_per_face(); ++i)
                if (!Components::is_displacement<dim>(
                      fe.face_system_to_component_index(i).first))
                  {
                    u(face_dofs[i]) = interpolate(values,
                                                  points,
                                                  points[k].component,
                                                  lo + points[k].t * (hi - lo));
                    ++k;
                  }
            }
    }
  } // namespace

  // @sect4{The error indicator}
  //
  // The estimator the file chooses (Mesh refinement/Estimator), given what
  // it reads of the problem (refinement_estimator.h; the estimators
  // themselves are in estimators/). Kelly's estimator takes one mapping: the
  // bodies' highest degree.
  template <int dim>
  Vector<float>
  ContactProblem<dim>::estimate_error() const
  {
    // Adaptive refinement is two-dimensional (a 3D run that asks for it
    // is refused with the input, setup.cc).
    if constexpr (dim == 3)
      {
        AssertThrow(false, ExcMessage("adaptive refinement is 2D only"));
        return Vector<float>();
      }
    else
      {
        hp::QCollection<1> face_quadrature;
        for (unsigned int k = 0; k < fe_collection.size(); ++k)
          face_quadrature.push_back(QGauss<1>(fe_collection[k].degree + 1));
        unsigned int mapping_degree = 1;
        for (const Body<dim> &body : bodies)
          mapping_degree = std::max(mapping_degree, body.mapping_degree);
        const EstimatorInput input{triangulation,
                                   dof_handler,
                                   fe_collection,
                                   mapping_collection,
                                   face_quadrature,
                                   mapping_degree,
                                   solution,
                                   materials,
                                   slave_boundaries(parameters),
                                   parameters.contact.frictional()};
        return RingContact::estimate_error(parameters.refinement.estimator,
                                           input);
      }
  }

  // @sect4{Refine, carry the state over, set the problem up again}
  template <int dim>
  void
  ContactProblem<dim>::refine_mesh()
  {
    // Adaptive refinement is two-dimensional (a 3D run that asks for it
    // is refused with the input, setup.cc).
    if constexpr (dim == 3)
      {
        AssertThrow(false, ExcMessage("adaptive refinement is 2D only"));
        return;
      }
    else
      {
        TimerOutput::Scope  t(timer, "refinement");
        const auto         &refinement = parameters.refinement;
        const Vector<float> indicator  = estimate_error();
        GridRefinement::refine_and_coarsen_fixed_number(
          triangulation,
          indicator,
          refinement.refine_fraction,
          refinement.coarsen_fraction,
          refinement.maximum_cells);
        // Never finer than 'Maximum level', never coarser than the mesh the
        // scenario made (its global refinements).
        for (const auto &cell : triangulation.active_cell_iterators())
          {
            if (cell->level() >= static_cast<int>(refinement.maximum_level))
              cell->clear_refine_flag();
            if (cell->level() <=
                static_cast<int>(parameters.mesh.global_refinements))
              cell->clear_coarsen_flag();
          }

        keep_facing_faces_matched(contacts, refinement.maximum_level);

        // The displacement on a DoFHandler of its own: one FE_Q(p)^2 per body,
        // each cell the element of its body.
        hp::FECollection<dim> displacement_fe;
        for (const Body<dim> &body : bodies)
          displacement_fe.push_back(FESystem<dim>(FE_Q<dim>(body.degree), 2));
        DoFHandler<dim> displacement_dofs(triangulation);
        const auto      set_bodies = [&]() {
          for (const auto &cell : displacement_dofs.active_cell_iterators())
            cell->set_active_fe_index(fe_index_of.at(cell->material_id()));
          displacement_dofs.distribute_dofs(displacement_fe);
        };
        set_bodies();
        std::vector<Vector<double>> states(
          2, Vector<double>(displacement_dofs.n_dofs()));
        copy_displacement(
          dof_handler, displacement_dofs, solution, states[0], true);
        copy_displacement(
          dof_handler, displacement_dofs, previous_solution, states[1], true);

        // The multipliers, face by face along the slave surfaces.
        const auto slave_ids = slave_boundaries(parameters);
        const std::array<FaceRecord, 2> face_record = {
          {record_multipliers(dof_handler, slave_ids, solution),
           record_multipliers(dof_handler, slave_ids, previous_solution)}};

        SolutionTransfer<dim, Vector<double>> transfer(displacement_dofs);
        triangulation.prepare_coarsening_and_refinement();
        // The rest of the cycle's line in the log (refine_and_solve_again()
        // starts it): the flags as deal.II's smoothing left them.
        unsigned int       n_refined = 0, n_coarsened = 0;
        const unsigned int cells_before = triangulation.n_active_cells();
        for (const auto &cell : triangulation.active_cell_iterators())
          {
            n_refined += cell->refine_flag_set() ? 1 : 0;
            n_coarsened += cell->coarsen_flag_set() ? 1 : 0;
          }
        transfer.prepare_for_coarsening_and_refinement(states);
        triangulation.execute_coarsening_and_refinement();
        set_bodies();
        std::vector<Vector<double>> new_states(
          2, Vector<double>(displacement_dofs.n_dofs()));
        transfer.interpolate(states, new_states);

        // The contact problem on the new mesh: its elements per cell, unknowns,
        // solver, interfaces and constraints (setup.cc), the reference geometry
        // and the arc length made again when next needed.
        distribute_dofs();
        make_linear_system();
        make_contact_interfaces();
        for (Vector<double> *v : {&solution,
                                  &previous_solution,
                                  &internal_force,
                                  &external_force,
                                  &residual_magnitude})
          v->reinit(dof_handler.n_dofs());
        make_constraints();
        reference_geometry.start.clear();
        arc_length.reinit(0);

        copy_displacement(
          dof_handler, displacement_dofs, solution, new_states[0], false);
        copy_displacement(dof_handler,
                          displacement_dofs,
                          previous_solution,
                          new_states[1],
                          false);
        restore_multipliers(dof_handler, slave_ids, face_record[0], solution);
        restore_multipliers(dof_handler,
                            slave_ids,
                            face_record[1],
                            previous_solution);
        // The hanging nodes take their constrained values (the transfer gives
        // them already where a cell was refined; coarsening may not).
        hanging_node_constraints.distribute(solution);
        hanging_node_constraints.distribute(previous_solution);
        ++n_refinements;

        for (const auto &contact : contacts)
          contact->update(solution);
        make_sparsity_pattern();
        log << cells_before << " -> " << triangulation.n_active_cells()
            << " cells (" << n_refined << " refined, " << n_coarsened
            << " coarsened), " << dof_handler.n_dofs() << " unknowns\n";
      }
  }

  // @sect4{Refinement after a converged step}
  //
  // The load stepper asks after each converged step how many cycles of
  // refinement are due, and solves the step again after each
  // (LoadStepper::solve_again_on_refined_meshes()): every Mesh
  // refinement/Every steps, and after the last step.
  template <int dim>
  unsigned int
  ContactProblem<dim>::refinement_cycles(const unsigned int step)
  {
    const auto &refinement = parameters.refinement;
    if (refinement.adaptive_cycles == 0 ||
        (step % refinement.every != 0 && step != load_program.n_steps()))
      return 0;
    // Once per run: refinement makes the surfaces non-matching, which only
    // the segment-based scheme integrates exactly.
    if (n_refinements == 0 && !scheme.cuts_at_master_kinks())
      log << wrap_text(
        "Note: adaptive refinement makes the contact surfaces non-matching, "
        "where the " +
        scheme.name() +
        " scheme's pressure oscillates (Hertz, 11 cycles: p0 -8.6 % nodal, "
        "-2.2 % Gauss 2, -0.02 % segment-based 2); segment-based "
        "integration is exact there");
    return refinement.adaptive_cycles;
  }

  // One cycle: the mesh refined and the state carried over (refine_mesh()),
  // unless it has reached Mesh refinement/Maximum cells, which ends the
  // cycles for good (said once).
  template <int dim>
  bool
  ContactProblem<dim>::refine_mesh_after_step(const unsigned int step,
                                              const unsigned int cycle)
  {
    if (triangulation.n_active_cells() >= parameters.refinement.maximum_cells)
      {
        if (!said_maximum_cells)
          log << "  step " << step << ": " << triangulation.n_active_cells()
              << " cells, Mesh refinement/Maximum cells reached: the "
                 "mesh stays as it is from here\n";
        said_maximum_cells = true;
        return false;
      }
    log << "  step " << step << ", refinement cycle " << cycle << ": ";
    refine_mesh();
    return true;
  }


  // This chapter's members for the dimensions the program runs in: the
  // explicit instantiation of the class in a chapter instantiates the
  // members defined here (see contact_problem.cc).
  template class ContactProblem<2>;
  template class ContactProblem<3>;
} // namespace RingContact
