// @sect3{Adaptive refinement: the mesh follows the contact}
//
// A contact zone is small: a mesh fine enough for its pressure everywhere
// spends most of its cells where nothing happens. After a load step has
// converged (every 'Refine every' steps, and at the last), the cells of
// largest error indicator are refined, those of smallest coarsened, the
// state is carried to the new mesh and the step is solved again there,
// 'Adaptive cycles' times (subsection Mesh refinement).
//
// The indicator is Kelly's (deal.II's KellyErrorEstimator: the jumps of the
// displacement gradient across the inner faces) plus, on the faces of the
// slave surfaces, the residual of the contact condition (the body's
// traction P N against the force the multiplier puts on it) and the jumps
// of the pressure's slope between neighbouring faces. Kelly's alone sees
// no boundary, and the pressure's error sits on one. Where the surfaces
// face each other, their faces are kept within a factor 1.5 of each other.
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
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_refinement.h>
#include <deal.II/hp/fe_values.h>
#include <deal.II/numerics/error_estimator.h>
#include <deal.II/numerics/rtree.h>
#include <deal.II/numerics/solution_transfer.h>

#include <ring_contact/base/components.h>
#include <ring_contact/base/dimension.h>
#include <ring_contact/base/utilities.h>
#include <ring_contact/problem/contact_problem.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <set>
#include <tuple>

namespace RingContact
{
  namespace
  {
    // The multiplier values of one face of a slave surface, by component
    // and by the index of the face's support point in its base element
    // FE_Q(q) (0 and 1 its ends, then the points between).
    using FaceValues = std::map<std::pair<unsigned int, unsigned int>, double>;

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

    // The parameter in [0, 1] along a face (from its vertex 0) of the
    // support point of face unknown i of `fe`, and its component and index
    // in the base element.
    struct FacePoint
    {
      unsigned int component, index;
      double       t;
    };

    std::vector<FacePoint>
    multiplier_face_points(const FiniteElement<dim> &fe)
    {
      std::vector<FacePoint> points;
      for (unsigned int i = 0; i < fe.n_dofs_per_face(); ++i)
        {
          const unsigned int component =
            fe.face_system_to_component_index(i).first;
          if (Components::is_displacement(component))
            continue;
          const auto base = fe.face_system_to_base_index(i);
          points.push_back({component,
                            base.second,
                            fe.base_element(base.first.first)
                              .get_unit_face_support_points()[base.second][0]});
        }
      return points;
    }

    // The value at t of the Lagrange polynomial through a face's values of
    // `component` (at the support points `points` of its element).
    double
    interpolate(const FaceValues             &values,
                const std::vector<FacePoint> &points,
                const unsigned int            component,
                const double                  t)
    {
      double sum = 0;
      for (const auto &p : points)
        if (p.component == component)
          {
            double basis = 1;
            for (const auto &q : points)
              if (q.component == component && q.index != p.index)
                basis *= (t - q.t) / (p.t - q.t);
            sum += basis * values.at({component, p.index});
          }
      return sum;
    }

    // d/dt of that polynomial.
    double
    derivative(const FaceValues             &values,
               const std::vector<FacePoint> &points,
               const unsigned int            component,
               const double                  t)
    {
      double sum = 0;
      for (const auto &p : points)
        if (p.component == component)
          for (const auto &r : points)
            if (r.component == component && r.index != p.index)
              {
                double term = 1 / (p.t - r.t);
                for (const auto &q : points)
                  if (q.component == component && q.index != p.index &&
                      q.index != r.index)
                    term *= (t - q.t) / (p.t - q.t);
                sum += term * values.at({component, p.index});
              }
      return sum;
    }

    // The multipliers of `u` on face f of a slave layer's cell.
    FaceValues
    face_multipliers(const DoFHandler<dim>::active_cell_iterator &cell,
                     const unsigned int                           f,
                     const std::vector<FacePoint>                &points,
                     const Vector<double>                        &u)
    {
      const auto                          &fe = cell->get_fe();
      std::vector<types::global_dof_index> face_dofs(fe.n_dofs_per_face());
      cell->face(f)->get_dof_indices(face_dofs, cell->active_fe_index());
      FaceValues values;
      for (unsigned int i = 0, k = 0; i < fe.n_dofs_per_face(); ++i)
        if (!Components::is_displacement(
              fe.face_system_to_component_index(i).first))
          {
            values[{points[k].component, points[k].index}] = u(face_dofs[i]);
            ++k;
          }
      return values;
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
      const std::vector<std::unique_ptr<ContactInterface>> &contacts,
      const unsigned int                                    maximum_level)
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
              if (!Components::is_displacement(component))
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
                if (!Components::is_displacement(
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

    // Contact weighted: the error that matters is the contact's. A cell's
    // error reaches the contact pressure through the dual solution of a
    // functional on the contact zone, whose second derivatives (which
    // weigh the cell's residual) fall like 1 / r^2 away from a zone of
    // length l: each indicator is weighed by (l / (l + d))^2, d the
    // distance from the cell to the nearest active slave face. Hertz
    // (a = R / 30, 11 cycles of 5 %): a smaller L2 error of the pressure than
    // unweighted for as many unknowns (doc/validation.md, "Adaptive
    // refinement").
    // The faces in contact: a multiplier above 1e-8 of the largest (an open
    // node's multiplier is zero up to the linear solver's round-off, which
    // differs between one process and several).
    void
    weigh_by_distance_from_contact(
      const Triangulation<dim>                                  &triangulation,
      const std::vector<std::tuple<Point<dim>, double, double>> &slave_faces,
      Vector<float>                                             &indicator)
    {
      double largest = 0;
      for (const auto &face : slave_faces)
        largest = std::max(largest, std::get<2>(face));
      std::vector<Point<dim>> active_points;
      double                  active_length = 0;
      for (const auto &[center, length, multiplier] : slave_faces)
        if (multiplier > 1e-8 * largest)
          {
            active_points.push_back(center);
            active_length += length;
          }
      if (!active_points.empty())
        {
          const auto tree = pack_rtree(active_points);
          for (const auto &cell : triangulation.active_cell_iterators())
            {
              std::vector<Point<dim>> nearest;
              tree.query(boost::geometry::index::nearest(cell->center(), 1),
                         std::back_inserter(nearest));
              const double d = std::max(0.0,
                                        nearest[0].distance(cell->center()) -
                                          cell->diameter() / 2);
              indicator[cell->active_cell_index()] *=
                Utilities::fixed_power<2>(active_length / (active_length + d));
            }
        }
    }

  } // namespace

  // @sect4{The error indicator}
  //
  // Kelly's on the displacement, and on each slave face
  // h/24 int |P N + lambda cof(F) N|^2 / E^2 dS: P N dS is the force the
  // body's stress puts on the face, lambda cof(F) N dS the pressure's (the
  // multiplier is the Cauchy pressure, per current length), and Kelly's
  // scale, the cell's diameter over 24, with the strain's units (over E).
  // With friction the tangential traction is a multiplier of its own, and
  // only the normal part of the residual is taken. At each slave vertex
  // the jump of the pressure's slope, h^3/24 [dp/ds]^2 / E^2 to both
  // cells: the edge of a contact, where the pressure falls as a square
  // root, is where it is largest (Hertz: the L2 error of the pressure fell with
  // it for as many unknowns; doc/validation.md, "Adaptive refinement").
  Vector<float>
  ContactProblem::estimate_error() const
  {
    Vector<float>      indicator(triangulation.n_active_cells());
    hp::QCollection<1> face_quadrature;
    for (unsigned int k = 0; k < fe_collection.size(); ++k)
      face_quadrature.push_back(QGauss<1>(fe_collection[k].degree + 1));
    // Every process holds the whole solution and the whole mesh: each
    // computes every cell's indicator, and all refine alike.
    // Kelly's estimator takes one mapping: the bodies' highest degree (an
    // indicator only; the faces' jumps do not need each body's own).
    unsigned int mapping_degree = 1;
    for (const Body &body : bodies)
      mapping_degree = std::max(mapping_degree, body.mapping_degree);
    KellyErrorEstimator<dim>::estimate(MappingQ<dim>(mapping_degree),
                                       dof_handler,
                                       face_quadrature,
                                       {},
                                       solution,
                                       indicator,
                                       Components::displacement_mask());
    if (parameters.refinement.estimator == RefinementEstimator::kelly)
      return indicator;

    const auto slave_ids = slave_boundaries(parameters);
    const bool friction  = parameters.contact.friction_coefficient > 0;
    hp::FEFaceValues<dim>            face_values(mapping_collection,
                                      fe_collection,
                                      face_quadrature,
                                      update_values | update_gradients |
                                        update_normal_vectors |
                                        update_JxW_values);
    const FEValuesExtractors::Scalar pressure(Components::multiplier);
    std::vector<Tensor<2, dim>>      grad_u;
    std::vector<double>              lambda;
    struct Slope
    {
      Tensor<1, dim> slope;
      unsigned int   cell;
      double         length, E;
    };
    std::map<unsigned int, std::vector<Slope>> slopes;
    // The slave faces with their largest |multiplier|, for the weight of
    // 'Contact weighted' (weigh_by_distance_from_contact()).
    std::vector<std::tuple<Point<dim>, double, double>> slave_faces;
    for (const auto &cell : dof_handler.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary() &&
            slave_ids.count(cell->face(f)->boundary_id()) > 0)
          {
            face_values.reinit(cell, f);
            const auto &fv = face_values.get_present_fe_values();
            grad_u.resize(fv.n_quadrature_points);
            lambda.resize(fv.n_quadrature_points);
            fv[displacement].get_function_gradients(solution, grad_u);
            fv[pressure].get_function_values(solution, lambda);
            const Material &material = materials.at(cell->material_id());
            const bool linear = material.kinematics == Kinematics::small_strain;
            double     sum    = 0;
            for (unsigned int q = 0; q < fv.n_quadrature_points; ++q)
              {
                const Tensor<1, dim> N = fv.normal_vector(q);
                Tensor<2, dim>       F = unit_symmetric_tensor<dim>();
                F += grad_u[q];
                // cof(F) = det(F) F^-T; the reference normal in small strain.
                const Tensor<1, dim> area =
                  linear ? N : determinant(F) * transpose(invert(F)) * N;
                Tensor<1, dim> residual =
                  material.stress(grad_u[q]) * N + lambda[q] * area;
                if (friction)
                  residual =
                    (residual * area / area.norm()) * area / area.norm();
                sum += residual.norm_square() * fv.JxW(q);
              }
            double largest = 0;
            for (const double l : lambda)
              largest = std::max(largest, std::abs(l));
            slave_faces.emplace_back(cell->face(f)->center(),
                                     cell->face(f)->measure(),
                                     largest);
            const double E = material.youngs_modulus;
            indicator[cell->active_cell_index()] =
              std::sqrt(std::pow(indicator[cell->active_cell_index()], 2) +
                        cell->diameter() / 24 * sum / (E * E));

            // The pressure's slope at the face's two ends, as a vector
            // along the face (orientation-free), for the jumps below.
            const auto       face   = cell->face(f);
            const auto       points = multiplier_face_points(cell->get_fe());
            const FaceValues values =
              face_multipliers(cell, f, points, solution);
            const Tensor<1, dim> along  = face->vertex(1) - face->vertex(0);
            const double         length = along.norm();
            for (unsigned int end = 0; end < 2; ++end)
              slopes[face->vertex_index(end)].push_back(
                {derivative(values, points, Components::multiplier, end) /
                   (length * length) * along,
                 cell->active_cell_index(),
                 length,
                 E});
          }
    // The jump of the pressure's slope at each slave vertex, h^3/24
    // [dp/ds]^2 / E^2 to each of the two cells.
    for (const auto &[vertex, list] : slopes)
      if (list.size() == 2)
        {
          const double jump = (list[0].slope - list[1].slope).norm();
          for (const auto &end : list)
            {
              auto &eta = indicator[end.cell];
              eta = std::sqrt(eta * eta + std::pow(end.length, 3) / 24 * jump *
                                            jump / (end.E * end.E));
            }
        }
    if (parameters.refinement.estimator ==
        RefinementEstimator::contact_weighted)
      weigh_by_distance_from_contact(triangulation, slave_faces, indicator);
    return indicator;
  }

  // @sect4{Refine, carry the state over, set the problem up again}
  void
  ContactProblem::refine_mesh()
  {
    TimerOutput::Scope  t(timer, "refinement");
    const auto         &refinement = parameters.refinement;
    const Vector<float> indicator  = estimate_error();
    GridRefinement::refine_and_coarsen_fixed_number(triangulation,
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
    for (const Body &body : bodies)
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
    const auto                      slave_ids   = slave_boundaries(parameters);
    const std::array<FaceRecord, 2> face_record = {
      {record_multipliers(dof_handler, slave_ids, solution),
       record_multipliers(dof_handler, slave_ids, previous_solution)}};

    SolutionTransfer<2, Vector<double>> transfer(displacement_dofs);
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
    copy_displacement(
      dof_handler, displacement_dofs, previous_solution, new_states[1], false);
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

  // @sect4{Refinement after a converged step}
  //
  // The load stepper asks after each converged step how many cycles of
  // refinement are due, and solves the step again after each
  // (LoadStepper::solve_again_on_refined_meshes()): every Mesh
  // refinement/Every steps, and after the last step.
  unsigned int
  ContactProblem::refinement_cycles(const unsigned int step)
  {
    const auto &refinement = parameters.refinement;
    if (refinement.adaptive_cycles == 0 ||
        (step % refinement.every != 0 && step != load_program.n_steps()))
      return 0;
    // Once per run: refinement makes the surfaces non-matching, which only
    // the segment-based scheme integrates exactly.
    if (n_refinements == 0 && scheme.type != ContactIntegration::segment_based)
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
  bool
  ContactProblem::refine_mesh_after_step(const unsigned int step,
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
} // namespace RingContact
