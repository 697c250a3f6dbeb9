// @sect3{The contact rows of the Newton system}
//
// The walk over the slave points of a contact interface, which builds the
// contact element of each (contact_element.cc) and adds its residual and
// exact derivative to the Newton system (assemble()), its forces alone
// (add_forces()), or the weighted slips of friction (weighted_slips()); and
// the sparsity pattern of the contact couplings.
#include <deal.II/base/mpi.h>
#include <deal.II/differentiation/ad/sacado_number_types.h>
#include <deal.II/lac/full_matrix.h>

#include <ring_contact/base/dimension.h>
#include <ring_contact/contact/contact_element.h>
#include <ring_contact/contact/contact_interface.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace RingContact
{
  using namespace ContactElements;


  // eps of the sticking rows (see assemble()).
  constexpr double stick_regularisation = 1e-12;

  // @sect4{The walk over the slave points}
  //
  // Every use of the contact element goes through visit_points(): assemble()
  // with derivatives, add_forces() with values only; the two had their own
  // copies of the element's set-up before. Under MPI each process walks the
  // points of its own slave faces (the cells are partitioned so that every
  // process has a share of them, see setup.cc), unless `process` is invalid:
  // add_forces() wants the whole sum on every process.
  template <typename Visitor>
  void
  ContactInterface<dim>::visit_points(const Vector<double> &solution,
                                      const bool            derivatives,
                                      const unsigned int    process,
                                      const Visitor        &visit) const
  {
    // The active set and the friction states are those of the last update(),
    // fixed while the element is assembled: in the semi-smooth Newton method
    // the linearisation of the max in C_k (and of the Coulomb projection) is
    // the choice of a row per node.
    const auto is_active = [this](const types::global_dof_index dof) {
      return states.is_closed(multiplier_nodes.index.at(dof));
    };
    // 0 sticking, +1 or -1 sliding, 2 open or sticking where held on both
    // sides (no tangential row from the points, see find_tangential_ties()).
    const auto friction_state = [this](const types::global_dof_index dof) {
      const unsigned int k    = multiplier_nodes.index.at(dof);
      const int          sign = states.friction_state(k);
      const bool         held = k < tied.size() && tied[k] && sign == 0;
      return states.is_closed(k) && !held ? sign : 2;
    };
    // (Before the first assembly there is no converged state yet: only
    // add_forces() can come that early, and the tangential rows, which
    // need it, are not forces.)
    const std::optional<ConvergedState> converged =
      friction_coefficient > 0 && converged_slave ?
        std::optional<ConvergedState>(ConvergedState{converged_solution,
                                                     *converged_slave,
                                                     *converged_master,
                                                     dual_basis}) :
        std::nullopt;
    for (const auto &point : point_pairing.points())
      {
        if (process != numbers::invalid_unsigned_int &&
            slave.segments()[point.slave_segment].cell->subdomain_id() !=
              process)
          continue;
        const ElementLayout layout(slave,
                                   master,
                                   point,
                                   !geometrically_linear,
                                   segment_based,
                                   converged ? &*converged : nullptr);
        // The element in AD numbers that hold its unknowns.
        const auto evaluate = [&](auto &&element) {
          element.gather_unknowns(solution, derivatives);
          element.evaluate_slave_point();
          element.evaluate_partner_and_normal();
          auto residual = element.residual(complementarity_constant,
                                           is_active,
                                           friction_state,
                                           friction_coefficient);
          visit(element, residual);
        };
        // A safety net: with displacement degrees of at most 4
        // (LagrangeBasis1D::max_size) an element has at most 60 unknowns.
        AssertThrow(layout.n_unknowns() <= large_capacity,
                    ExcMessage("a contact element with " +
                               std::to_string(layout.n_unknowns()) +
                               " unknowns, more than the " +
                               std::to_string(large_capacity) +
                               " its AD numbers hold (displacement degree "
                               "above 4?)"));
        // The smaller numbers wherever they fit (see the capacities above).
        if (layout.n_unknowns() <= small_capacity)
          evaluate(ContactElement<SmallAD>(layout));
        else
          evaluate(ContactElement<LargeAD>(layout));
      }
  }

  // @sect4{The contact rows of the Newton system}
  //
  // The slave points' contributions, then the rows that are one equation per
  // node rather than a sum over points: the open nodes' w_k lambda_k = 0 and,
  // with friction, the per-node parts of the tangential rows. Those are added
  // once, by the process that stores the row, whereas the points' contributions
  // from every process are summed.
  void
  ContactInterface<dim>::assemble(const Vector<double>            &solution,
                                  const AffineConstraints<double> &constraints,
                                  LinearSystem                    &system) const
  {
    find_tangential_ties(solution, constraints, system.get_communicator());
    const bool friction = friction_coefficient > 0;
    visit_points(solution,
                 true,
                 this_process(system.get_communicator()),
                 [&](auto &element, auto &residual) {
                   element.scatter(residual, constraints, system);
                 });

    // Open nodes: w_k lambda_k = 0 (and w_k lambda_t,k = 0).
    // w_k lambda_k rather than lambda_k: every row is a force per unit
    // thickness, so that the residual norm weighs them with the others; w_k is
    // the reference weight, a constant, so the row stays linear.
    const auto &nodes = multiplier_nodes;
    for (unsigned int k = 0; k < nodes.size(); ++k)
      if (!states.is_closed(k) && system.owned_rows().is_element(nodes.dofs[k]))
        {
          const auto dof = nodes.dofs[k];
          system.add_diagonal(dof,
                              nodes.reference_weight[k],
                              -nodes.reference_weight[k] * solution(dof));
        }
    if (!friction)
      return;
    for (unsigned int k = 0; k < nodes.size(); ++k)
      {
        const auto   t = nodes.tangential_dofs[k], n = nodes.dofs[k];
        const double w         = nodes.reference_weight[k];
        const int    slip_sign = states.friction_state(k);
        if (!system.owned_rows().is_element(t))
          continue;
        if (!states.is_closed(k) || (tied[k] && slip_sign == 0))
          system.add_diagonal(t, w, -w * solution(t));
        else if (slip_sign == 0)
          // Sticking: c s~_k (the points' rows) + eps w lambda_t = 0. The
          // nodes whose slip depends on no unknown are tied (above); eps =
          // 1e-12 allows a slip of 1e-12 w lambda_t / c, and gives a node
          // whose supports move against each other by less than the bound
          // allows a traction -c s~_k / (eps w), far past it, so that it
          // slides at the next update (measured before the ties: Hertz with
          // mu = 0.2 was singular at its first step without it).
          system.add_diagonal(t,
                              stick_regularisation * w,
                              -stick_regularisation * w * solution(t));
        else
          {
            // Sliding: w lambda_t - sign mu (w lambda - c g~) = 0, the
            // points' sum of sign mu c Phi_k g ds already in the row.
            // b = sign mu w: the row w lambda_t - b lambda couples the node's
            // two multipliers, hence a 2 x 2 element with the normal
            // multiplier's column rather than a diagonal entry.
            const double       b = slip_sign * friction_coefficient * w;
            FullMatrix<double> matrix(2, 2);
            Vector<double>     rhs(2);
            matrix(0, 0) = w;
            matrix(0, 1) = -b;
            rhs(0)       = -(w * solution(t) - b * solution(n));
            system.add(constraints, matrix, rhs, {t, n});
          }
      }
  }

  // A node whose tangential motion is held alike on both sides: the slave's
  // displacement along the surface at the node fixed by a support, and the
  // master's at a master vertex across from it, moved by the same increment
  // in the step (a symmetry plane, rollers at the ends of both surfaces).
  // Its slip is zero whatever the unknowns, and its stick row c s~_k zero up
  // to round-off and the surfaces' mismatch: with the dual basis a row of
  // tiny entries, which gave its traction any value (two blocks on rollers,
  // Hertz's symmetry node: linear convergence at fixed states). Sticking, its
  // traction has no equation of its own: it is set to zero, as an open
  // node's, and the supports take the force. Supports that move against each
  // other (the frictional patch test) are not a tie: the node slides, and
  // its row is the Coulomb law's. Along the surface: the support's axis
  // within 10 degrees of the tangent (a faceted curve's segment is inclined
  // at its end node by half its angle). Held means constrained without
  // entries (a support, not a hanging node or a twin). Across from it: a
  // master vertex at the node's coordinate along the axis, less than the
  // shortest slave segment away (a symmetry plane whose gap is wider is not
  // found). The largest over the processes, so that every process decides
  // alike whatever constraints it holds.
  void
  ContactInterface<dim>::find_tangential_ties(
    const Vector<double>            &solution,
    const AffineConstraints<double> &constraints,
    const MPI_Comm                   communicator) const
  {
    const unsigned int n = multiplier_nodes.size();
    tied.assign(n, false);
    if (friction_coefficient == 0)
      return;
    const double along = std::cos(10 * numbers::PI / 180);
    // The axis (0: x, 1: y) along which `surface` is held at (segment s,
    // parameter t), a displacement node, if the tangent there is within 10
    // degrees of it; else -1.
    // The increment of a displacement dof in the step (its value before the
    // first converged state).
    const bool from_converged = converged_solution.size() == solution.size();
    const auto increment      = [&](const types::global_dof_index dof) {
      return solution(dof) - (from_converged ? converged_solution(dof) : 0.0);
    };
    // And its increment in `moved`.
    const auto held_axis = [&](const ContactSurface &surface,
                               const unsigned int    s,
                               const double          t,
                               double               &moved) {
      const auto         &segment = surface.segments()[s];
      std::vector<double> N;
      surface.displacement_basis().evaluate(t, N);
      const Tensor<1, dim> dx = surface.reference_point(s, t).dx;
      for (unsigned int j = 0; j < N.size(); ++j)
        if (std::abs(N[j] - 1) < 1e-12)
          for (unsigned int axis = 0; axis < dim; ++axis)
            {
              const auto dof =
                axis == 0 ? segment.dofs_x[j] : segment.dofs_y[j];
              const auto *entries = constraints.get_constraint_entries(dof);
              if (entries != nullptr && entries->empty() &&
                  std::abs(dx[axis]) >= along * dx.norm())
                {
                  moved = increment(dof);
                  return static_cast<int>(axis);
                }
            }
      return -1;
    };
    // Per node: 1 + the slave's held axis, and the same for a held master
    // vertex across from it (its coordinate along that axis the node's).
    std::vector<unsigned int> slave_axis(n, 0), master_axis(n, 0);
    for (unsigned int k = 0; k < n; ++k)
      {
        const auto &[s, t] =
          multiplier_nodes.sites.at(multiplier_nodes.dofs[k]).front();
        double    moved = 0;
        const int axis  = held_axis(slave, s, t, moved);
        if (axis < 0)
          continue;
        slave_axis[k]      = 1 + axis;
        const Point<dim> x = slave.reference_point(s, t).x;
        for (unsigned int m = 0; m < master.segments().size(); ++m)
          for (const double end : {0.0, 1.0})
            {
              const Point<dim> xm           = master.reference_point(m, end).x;
              double           master_moved = 0;
              if (std::abs(xm[axis] - x[axis]) <=
                    1e-6 * segment_length +
                      SurfaceKernel::position_round_off(x) &&
                  xm.distance(x) < segment_length &&
                  held_axis(master, m, end, master_moved) == axis &&
                  std::abs(master_moved - moved) <=
                    1e-12 * (std::abs(moved) + std::abs(master_moved)) +
                      1e-12 * segment_length)
                master_axis[k] = 1 + axis;
            }
      }
    if (Utilities::MPI::job_supports_mpi() &&
        Utilities::MPI::n_mpi_processes(communicator) > 1)
      {
        Utilities::MPI::max(slave_axis, communicator, slave_axis);
        Utilities::MPI::max(master_axis, communicator, master_axis);
      }
    for (unsigned int k = 0; k < n; ++k)
      tied[k] = slave_axis[k] != 0 && slave_axis[k] == master_axis[k];
  }

  // The contact force on every node at `solution`, with the sign of an internal
  // force, whatever process owns the slave point: the boundary resultants leave
  // it out of the reactions (postprocessing.cc).
  void
  ContactInterface<dim>::add_forces(const Vector<double> &solution,
                                    Vector<double>       &forces) const
  {
    visit_points(solution,
                 false,
                 numbers::invalid_unsigned_int,
                 [&](auto &element, auto &residual) {
                   element.add_values(residual, forces);
                 });
  }

  // s~_k = sum Psi_k s ds over the slave points, from the same contact
  // element as the residual (its values only).
  // Values only (AD constants: no derivative arrays at every slave point and
  // Newton iteration), and every slave point on every process: each process
  // decides the stick and slip states from s~, and all must decide the same.
  // The element needs the current partner and normal too: the slip is measured
  // along the current tangent.
  std::vector<double>
  ContactInterface<dim>::weighted_slips(const Vector<double> &solution) const
  {
    std::vector<double>  weighted_slip(multiplier_nodes.size(), 0.0);
    const ConvergedState converged{converged_solution,
                                   *converged_slave,
                                   *converged_master,
                                   dual_basis};
    for (const auto &point : point_pairing.points())
      {
        const ElementLayout layout(slave,
                                   master,
                                   point,
                                   !geometrically_linear,
                                   segment_based,
                                   &converged);
        const auto          add_slip = [&](auto &&element) {
          element.gather_unknowns(solution, false); // values only
          element.evaluate_slave_point();
          element.evaluate_partner_and_normal();
          const double s   = element.slip().val();
          const double ds  = element.length_element().val();
          const auto  &seg = slave.segments()[point.slave_segment];
          for (unsigned int k = 0; k < seg.multiplier_dofs.size(); ++k)
            weighted_slip[multiplier_nodes.index.at(seg.multiplier_dofs[k])] +=
              element.tangential_basis(k).val() * s * ds;
        };
        if (layout.n_unknowns() <= small_capacity)
          add_slip(ContactElement<SmallAD>(layout));
        else
          add_slip(ContactElement<LargeAD>(layout));
      }
    return weighted_slip;
  }

  // @sect4{The sparsity pattern of the contact couplings}
  //
  // The tangent's pattern holds, per slave segment, the master segments its
  // points are paired with and their neighbours. A new pattern costs a new
  // symbolic analysis of the factorization, which the direct solvers keep while
  // the pattern does not change; with the neighbours in it, a point that slips
  // to the next segment needs none. After each update() the Newton loop asks
  // whether the pattern still covers the pairs (problem/assembly.cc).
  bool
  ContactInterface<dim>::sparsity_covers_pairing() const
  {
    for (const auto &point : point_pairing.points())
      {
        if (pattern_pairs.count(
              {point.slave_segment, point.projection.segment}) == 0)
          return false;
        // Friction: the old partner enters through the slip.
        if (friction_coefficient > 0 &&
            pattern_pairs.count(
              {point.slave_segment, point.old_projection.segment}) == 0)
          return false;
        // The neighbours enter through vertex and smoothed normals.
        for (const unsigned int b :
             master.segments()[point.projection.segment].neighbours)
          if (b != numbers::invalid_unsigned_int &&
              pattern_pairs.count({point.slave_segment, b}) == 0)
            return false;
      }
    return true;
  }

  std::vector<std::vector<types::global_dof_index>>
  ContactInterface<dim>::coupling_blocks()
  {
    // Per slave segment, the master segments its points are paired with and
    // their neighbours (which enter through vertex and smoothed normals, and
    // which a slip may reach next): one block couples all their unknowns.
    pattern_pairs.clear();
    for (const auto &point : point_pairing.points())
      {
        pattern_pairs.insert({point.slave_segment, point.projection.segment});
        if (friction_coefficient > 0)
          pattern_pairs.insert(
            {point.slave_segment, point.old_projection.segment});
        for (const unsigned int m :
             master.segments()[point.projection.segment].neighbours)
          if (m != numbers::invalid_unsigned_int)
            pattern_pairs.insert({point.slave_segment, m});
      }
    // One block per slave segment couples its displacements, multipliers and
    // tangential tractions with the displacements of all those master segments.
    std::map<unsigned int, std::vector<types::global_dof_index>> block;
    for (const auto &[s, m] : pattern_pairs)
      {
        auto &dofs = block[s];
        if (dofs.empty())
          for (const auto *list : {&slave.segments()[s].dofs_x,
                                   &slave.segments()[s].dofs_y,
                                   &slave.segments()[s].multiplier_dofs,
                                   &slave.segments()[s].tangential_dofs})
            dofs.insert(dofs.end(), list->begin(), list->end());
        for (const auto *list :
             {&master.segments()[m].dofs_x, &master.segments()[m].dofs_y})
          dofs.insert(dofs.end(), list->begin(), list->end());
      }
    std::vector<std::vector<types::global_dof_index>> blocks;
    for (auto &[s, dofs] : block)
      {
        std::sort(dofs.begin(), dofs.end());
        dofs.erase(std::unique(dofs.begin(), dofs.end()), dofs.end());
        blocks.push_back(std::move(dofs));
      }
    return blocks;
  }
} // namespace RingContact
