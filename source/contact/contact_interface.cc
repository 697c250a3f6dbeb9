// @sect3{The contact interface: one pair of surfaces}
//
// One contact pair: a slave surface that carries the multipliers and a master
// surface that gives the normal (contact_surface.cc), with the quadrature rule
// of the chosen scheme on the slave (contact_quadrature.cc). Before every
// assembly the Newton solver calls update(): the surfaces move to the current
// iterate, every slave quadrature point is paired with a point of the master
// (contact_pairing.cc), and the active set chooses each multiplier node closed
// or open, and with friction sticking or sliding (active_set.cc). The contact
// element of contact_assembly.cc then turns each pair into rows of the Newton
// system; this file also gives what the postprocessing asks of a pair: the
// node nearest to a point, the stretch, the nodal gap, the deepest overlap and
// the L2 error of the pressure.
#include <deal.II/base/quadrature_lib.h>

#include <ring_contact/base/dimension.h>
#include <ring_contact/contact/contact_interface.h>
#include <ring_contact/contact/contact_quadrature.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace RingContact
{
  namespace
  {
    // The tangential traction's basis (contact_element.h): the dual one,
    // unless the scheme's points are the multiplier nodes themselves (the
    // nodal scheme, whose weights are diagonal: there Psi = Phi).
    bool
    needs_dual_basis(const ContactSurface &slave,
                     const Quadrature<1>  &quadrature,
                     const bool            segment_based,
                     const bool            friction)
    {
      if (!friction)
        return false;
      const auto &nodes = slave.multiplier_nodes();
      bool at_nodes     = !segment_based && quadrature.size() == nodes.size();
      for (unsigned int q = 0; at_nodes && q < quadrature.size(); ++q)
        at_nodes = std::any_of(nodes.begin(), nodes.end(), [&](double t) {
          return std::abs(t - quadrature.point(q)[0]) < 1e-12;
        });
      return !at_nodes;
    }
  } // namespace

  // @sect4{Construction: the surfaces, the rule and the multiplier nodes}
  //
  // The quadrature rule is chosen for the higher displacement degree of the two
  // surfaces: the same rule integrates the slave's and the master's rows, and a
  // rule that saw only a linear slave's vertices would give a quadratic
  // master's mid-side nodes no contact force (doc/theory.md).
  ContactInterface<dim>::ContactInterface(
    const DoFHandler<dim>        &dof_handler,
    const ContactParameters      &parameters,
    const IntegrationScheme      &scheme,
    const unsigned int            slave_mapping_degree,
    const unsigned int            master_mapping_degree,
    const double                  largest_youngs_modulus,
    const bool                    geometrically_linear,
    const CyclicSymmetry::Sector &sector)
      : slave(dof_handler, parameters.slave_boundary_id, slave_mapping_degree)
      , master(dof_handler,
               parameters.master_boundary_id,
               master_mapping_degree,
               parameters.smooth_master_normals,
               sector.angle,
               sector.copies,
               sector.window_before,
               sector.window_after)
      // Automatic complementarity constant: E / h of the slave surface, the
      // stiffness of a layer one element thick (closing a gap g against it
      // takes a pressure E g / h). c only chooses the active set (at the
      // solution c g~_k = 0 on the closed nodes and lambda_k = 0 on the open
      // ones, whatever c), but it weighs a gap against a pressure in w lambda -
      // c g~, and with E / h the two terms are of one size.
      , complementarity_constant(parameters.complementarity_constant > 0 ?
                                   parameters.complementarity_constant :
                                   largest_youngs_modulus /
                                     slave.min_segment_length())
      , friction_coefficient(parameters.friction_coefficient)
      , small_strain_model(geometrically_linear)
      , geometrically_linear(geometrically_linear)
      , segment_based(scheme.cuts_at_master_kinks())
      , segment_length(slave.min_segment_length())
      , multiplier_nodes(slave,
                         sector.multiplier_twins,
                         friction_coefficient > 0)
      , point_pairing(
          slave,
          master,
          contact_quadrature(scheme,
                             std::max(slave.displacement_basis().size(),
                                      master.displacement_basis().size()) -
                               1,
                             slave.multiplier_basis().size() - 1),
          segment_based)
      , states(multiplier_nodes,
               complementarity_constant,
               friction_coefficient,
               segment_length)
      , dual_basis(needs_dual_basis(slave,
                                    point_pairing.rule(),
                                    segment_based,
                                    friction_coefficient > 0))
  {}

  // @sect4{The update of an iteration}
  //
  // The surfaces to the state of `solution`, the pairing, the weighted gaps and
  // the active set from the current multipliers and gaps (the primal-dual
  // active-set strategy: the max in C_k is decided at the iterate). The number
  // of changes is what the Newton solver needs: an iterate is converged only if
  // no node changed its state.
  unsigned int
  ContactInterface<dim>::update(const Vector<double> &solution,
                                const Pairing         pairing)
  {
    // Finite strain: pair and measure in the current configuration. Small
    // strain: pair in the reference configuration, and the gap is the
    // reference gap plus the normal jump of the displacement.
    // The surfaces then keep zero displacement, so that every position, normal
    // and length the contact sees is the reference one.
    if (geometrically_linear)
      {
        const Vector<double> zero(solution.size());
        slave.update(zero);
        master.update(zero);
      }
    else
      {
        slave.update(solution);
        master.update(solution);
      }
    point_pairing.pair(solution, pairing, geometrically_linear);
    const unsigned int n_changed = states.choose_closed_nodes(
      solution, slave, point_pairing.points(), piecewise_linear());
    // A changed friction state counts as a change: Newton stops only when
    // neither the active set nor a state changed.
    if (friction_coefficient == 0)
      return n_changed;
    // Before the first converged state: the reference configuration.
    if (!converged_master)
      accept_state(Vector<double>(solution.size()));
    point_pairing.find_old_partners(*converged_slave,
                                    *converged_master,
                                    geometrically_linear);
    // From the contact element, values only (contact_assembly.cc): the slips
    // need the current tangent, the moving pieces and the old partners exactly
    // as the residual does.
    return n_changed + states.choose_friction_states(solution,
                                                     weighted_slips(solution),
                                                     geometrically_linear);
  }

  // @sect4{Friction: the converged state}
  //
  // The slip of a slave point in a step is its motion relative to the master
  // point it was paired with at the last converged state. accept_state() keeps
  // copies of both surfaces in that state, and every update() projects the
  // points' old positions onto the old master (ContactPairing::
  // find_old_partners()). Measured so, rather than by integrating a tangential
  // velocity, the slip is objective (a rigid motion of the pair slips nothing)
  // and the same with every integration scheme.
  void
  ContactInterface<dim>::accept_state(const Vector<double> &solution)
  {
    if (friction_coefficient == 0)
      return;
    converged_solution = solution;
    converged_slave    = std::make_unique<ContactSurface>(slave);
    converged_master   = std::make_unique<ContactSurface>(master);
    // Small strain: both at the reference configuration, where the pairing is
    // made.
    const Vector<double> zero(solution.size());
    converged_slave->update(geometrically_linear ? zero : solution);
    converged_master->update(geometrically_linear ? zero : solution);
  }

  // The deepest mean gap g~_k / w_k below zero, for the warning before any load
  // (diagnostics/surfaces_at_rest.cc): a curved slave facing a faceted
  // master overlaps it by 2/3 of the sagitta in g~_k / w_k, and modelisation H
  // so set up once gave 0 of 63 checks with no word of why. The mean gap is 0
  // where w_k is 0 (ActiveSet::mean_gaps()).
  std::pair<double, Point<dim>>
  ContactInterface<dim>::deepest_interpenetration() const
  {
    const std::vector<double> mean_gap = states.mean_gaps();
    double                    depth    = 0;
    Point<dim>                where;
    for (unsigned int k = 0; k < mean_gap.size(); ++k)
      if (-mean_gap[k] > depth)
        {
          depth = -mean_gap[k];
          const auto &site =
            multiplier_nodes.sites.at(multiplier_nodes.dofs[k]).front();
          where = slave.reference_point(site.first, site.second).x;
        }
    return {depth, where};
  }

  // @sect4{What the postprocessing asks of a pair}
  //
  // The node nearest to a reference point: the rings' node A is named by its
  // initial position (0.6, 0), a general problem's checks by theirs.
  types::global_dof_index
  ContactInterface<dim>::multiplier_dof_nearest_to(const Point<dim> &point,
                                                   double *distance) const
  {
    double                  best = std::numeric_limits<double>::max();
    types::global_dof_index dof  = numbers::invalid_dof_index;
    for (unsigned int s = 0; s < slave.segments().size(); ++s)
      for (unsigned int k = 0; k < slave.multiplier_nodes().size(); ++k)
        {
          const double d = point.distance(
            slave.reference_point(s, slave.multiplier_nodes()[k]).x);
          if (d < best)
            {
              best = d;
              dof  = slave.segments()[s].multiplier_dofs[k];
            }
        }
    if (distance)
      *distance = best;
    // The node's own dof (not a cyclic twin).
    return multiplier_nodes.dofs[multiplier_nodes.index.at(dof)];
  }

  // The points as paired by the last update(): the master's shape functions
  // at each partner, weighted by the point's length element. A rotated copy
  // of a sector's segment carries the original's unknowns, so its weights
  // land on them.
  std::map<types::global_dof_index, double>
  ContactInterface<dim>::master_load_weights() const
  {
    std::map<types::global_dof_index, double> weights;
    std::vector<double> psi(master.displacement_basis().size());
    for (const auto &point : point_pairing.points())
      {
        if (point.projection.segment == numbers::invalid_unsigned_int)
          continue;
        const SurfaceSegment &segment =
          master.segments()[point.projection.segment];
        master.displacement_basis().evaluate(point.projection.t, psi);
        for (unsigned int j = 0; j < psi.size(); ++j)
          weights[segment.dofs_x[j]] += psi[j] * point.current_length;
      }
    return weights;
  }

  // Cauchy to nominal: lambda is a force per current length, the nominal
  // pressure one per reference length, lambda ds / dS. At a vertex the
  // stretches of the two segments differ: the node gets their mean.
  double
  ContactInterface<dim>::stretch_at(const types::global_dof_index dof) const
  {
    double      sum   = 0;
    const auto &sites = multiplier_nodes.sites.at(dof);
    for (const auto &[s, t] : sites)
      sum += slave.current_point(s, t).dx.norm() /
             slave.reference_point(s, t).dx.norm();
    return sum / sites.size();
  }

  // The nodal gap of the VTU files: the node's slave point projected afresh,
  // with the gap computed as in the pairing.
  double
  ContactInterface<dim>::gap_at(const types::global_dof_index dof,
                                const Vector<double>         &solution) const
  {
    const auto [s, t] = multiplier_nodes.sites.at(dof).front();
    return point_pairing.gap_at(s, t, solution, geometrically_linear);
  }

  // The relative L2 error of the pressure against a uniform reference
  // (the rings' Lame pressure is the same all round), with a rule of its own
  // (the displacement degree + 3 Gauss points per slave segment) rather than
  // the contact scheme's, so that every scheme is measured alike.
  double
  ContactInterface<dim>::l2_relative_error(const Vector<double> &solution,
                                           const double          reference,
                                           const PressureMeasure measure) const
  {
    const QGauss<1>     rule(slave.displacement_basis().size() + 2);
    double              error = 0, norm = 0;
    std::vector<double> Phi;
    for (unsigned int s = 0; s < slave.segments().size(); ++s)
      {
        const auto &segment = slave.segments()[s];
        for (unsigned int q = 0; q < rule.size(); ++q)
          {
            const double t = rule.point(q)[0];
            slave.multiplier_basis().evaluate(t, Phi);
            double lambda = 0;
            for (unsigned int k = 0; k < Phi.size(); ++k)
              lambda += Phi[k] * solution(segment.multiplier_dofs[k]);
            const double ds = slave.current_point(s, t).dx.norm();
            const double dS = slave.reference_point(s, t).dx.norm();
            // Cauchy: lambda over ds; nominal: lambda ds/dS over dS.
            const double pressure =
              measure == PressureMeasure::cauchy ? lambda : lambda * ds / dS;
            const double length =
              (measure == PressureMeasure::cauchy ? ds : dS) * rule.weight(q);
            // Relative to the reference before squaring: pressures of
            // 1e-200 would underflow.
            const double relative = (pressure - reference) / reference;
            error += relative * relative * length;
            norm += length;
          }
      }
    return std::sqrt(error / norm);
  }
} // namespace RingContact
