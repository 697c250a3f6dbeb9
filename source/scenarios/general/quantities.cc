// @sect3{The quantities a general problem checks}
//
// The quantities a general problem checks (Check k/Quantity), at a
// converged state. The scenario (general.cc) asks for each check's value
// at every converged step, and writes it to history.csv; the verdicts
// compare those columns with the references after the run. Every
// quantity is evaluated once at rest too, before the first step, and
// thrown away: a check that cannot be evaluated (a point outside the mesh,
// or off every slave surface) stops the run then, not after the first
// step's work.
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/numerics/vector_tools.h>

#include <ring_contact/base/components.h>
#include <ring_contact/base/dimension.h>
#include <ring_contact/contact/face_kernel.h>
#include <ring_contact/scenarios/general/general.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace RingContact
{
  namespace General
  {
    namespace
    {
      // The reported pressure p_h at the points of `rule` on every segment
      // of a slave surface (a cyclic sector's rotated copies hold the
      // originals' unknowns and are left out), handed to
      // visit(p_h, X, dS) with the reference position X and the reference
      // length element times the weight.
      template <typename Visitor>
      void
      along_slave_surface(const ContactSurface   &slave,
                          const SolutionState<2> &state,
                          const Quadrature<1>    &rule,
                          const Visitor          &visit)
      {
        std::vector<double> Phi;
        for (unsigned int s = 0; s < slave.segments().size(); ++s)
          {
            const auto &segment = slave.segments()[s];
            if (segment.is_copy)
              continue;
            for (unsigned int q = 0; q < rule.size(); ++q)
              {
                slave.multiplier_basis().evaluate(rule.point(q)[0], Phi);
                double p = 0;
                for (unsigned int k = 0; k < Phi.size(); ++k)
                  p += Phi[k] *
                       state.reported_pressure(segment.multiplier_dofs[k]);
                const auto X = slave.reference_point(s, rule.point(q)[0]);
                visit(p, X.x, X.dx.norm() * rule.weight(q));
              }
          }
      }
    } // namespace

    // The boundary resultants need the mesh and the unknowns, which do not
    // exist yet when the scenario is made: they are built at the first
    // resultant asked for (boundary_resultants()).
    template <int dim>
    CheckedQuantities<dim>::CheckedQuantities(const ProblemParameters &problem)
        : problem(problem)
    {}

    // @sect4{The value of a check's quantity}
    //
    // Each quantity is read from the converged state through SolutionState,
    // the narrow view the problem class gives of itself; the ones that
    // need more than a line have a function of their own below.
    template <int dim>
    double
    CheckedQuantities<dim>::value(const ProblemCheckParameters &check,
                                  const SolutionState<dim>     &state) const
    {
      // The pair whose slave surface is nearest to the point: with several
      // pairs, a check's point names its pair by where it lies. Looked up
      // for every quantity; only the slave surface's quantities use it.
      const auto nearest =
        state.contact_node_nearest_to(check.template point<dim>());
      if (check.quantity == ProblemQuantity::contact_pressure ||
          check.quantity == ProblemQuantity::tangential_traction)
        require_on_slave_surface(check, state, nearest);
      switch (check.quantity)
        {
          case ProblemQuantity::contact_pressure:
            return state.reported_pressure(nearest);

          case ProblemQuantity::tangential_traction:
            return tangential_traction(state, nearest);

          case ProblemQuantity::contact_half_width:
            return contact_half_width(check, state, nearest);

          case ProblemQuantity::minimum_contact_pressure:
          case ProblemQuantity::maximum_contact_pressure:
          case ProblemQuantity::mean_contact_pressure:
            return surface_pressure(check, state, nearest);

          case ProblemQuantity::contact_pressure_l2_error:
            return pressure_l2_error(check, state, nearest);

          // The components in the order x, y, z of the quantities.
          case ProblemQuantity::resultant_force_x:
          case ProblemQuantity::resultant_force_y:
          case ProblemQuantity::resultant_force_z:
            return resultant_force(
              check,
              state)[static_cast<int>(check.quantity) -
                     static_cast<int>(ProblemQuantity::resultant_force_x)];

          case ProblemQuantity::resultant_moment_x:
          case ProblemQuantity::resultant_moment_y:
          case ProblemQuantity::resultant_moment_z:
            return resultant_moment(
              check,
              state)[static_cast<int>(check.quantity) -
                     static_cast<int>(ProblemQuantity::resultant_moment_x)];

          case ProblemQuantity::displacement_x:
          case ProblemQuantity::displacement_y:
          case ProblemQuantity::displacement_z:
            return displacement(check, state);

          // finish() has dropped the unused slots: not reached, but a NaN
          // would fail any check that got here.
          case ProblemQuantity::none:
            break;
        }
      return std::nan("");
    }


    // A traction is read at a contact node: the point must be on a slave
    // surface (the nearest node within a segment of it), not anywhere.
    // Without this, a pressure check at (100, 100) silently reported the
    // nearest node's pressure as the pressure there. The longest slave
    // segment, in the reference configuration as the point is, is the
    // tolerance: any point of the surface is within it of a node, whatever
    // the mesh. Written !(d <= l) so that a distance that is not a number
    // is refused too.
    template <>
    void
    CheckedQuantities<2>::require_on_slave_surface(
      const ProblemCheckParameters &check,
      const SolutionState<2>       &state,
      const types::global_dof_index nearest) const
    {
      const ContactSurface &slave = state.contact_of(nearest).slave_surface();
      double                distance = 0, longest = 0;
      state.contact_of(nearest).multiplier_dof_nearest_to(check.point<2>(),
                                                          &distance);
      for (unsigned int k = 0; k < slave.segments().size(); ++k)
        longest = std::max(longest,
                           slave.reference_point(k, 0).x.distance(
                             slave.reference_point(k, 1).x));
      if (!(distance <= longest))
        {
          std::ostringstream where;
          where << check.coordinates[0] << ", " << check.coordinates[1]
                << ") is " << distance;
          throw std::runtime_error(
            check.name + ": the point (" + where.str() +
            " from the nearest contact node, farther than a segment of "
            "its slave surface: give a point on a slave surface");
        }
    }


    // The farthest slave node in contact (active, with a positive pressure)
    // from the point, or, where a node in contact is next to an open one on
    // a segment, the midpoint between the two: the edge of the contact to
    // half a node spacing. (An open node's pressure is zero to the linear
    // solver's accuracy, of either sign.)
    // Without friction the tangential traction has no unknown
    // (FE_Nothing): it is zero by definition, not missing.
    template <>
    double
    CheckedQuantities<2>::tangential_traction(
      const SolutionState<2>       &state,
      const types::global_dof_index nearest) const
    {
      const auto dof =
        state.contact_of(nearest).nodes().tangential_dof(nearest);
      return dof == numbers::invalid_dof_index ? 0.0 :
                                                 state.get_solution()(dof);
    }

    template <>
    double
    CheckedQuantities<2>::contact_half_width(
      const ProblemCheckParameters &check,
      const SolutionState<2>       &state,
      const types::global_dof_index nearest) const
    {
      const ContactSurface &slave = state.contact_of(nearest).slave_surface();
      // The nodes of a segment in the order of its unknowns (vertices
      // first); sorted by their parameter t, neighbours along the segment
      // are neighbours in the list, which the edge test below needs.
      double              width = 0;
      const auto         &nodes = slave.multiplier_nodes();
      std::vector<double> t(nodes.begin(), nodes.end());
      std::sort(t.begin(), t.end());
      for (unsigned int s = 0; s < slave.segments().size(); ++s)
        {
          // A cyclic sector's rotated copies hold the originals' unknowns
          // again: the sector's own segments are enough.
          const auto &segment = slave.segments()[s];
          if (segment.is_copy)
            continue;
          const auto dof_at = [&](const double t_node) {
            for (unsigned int k = 0; k < nodes.size(); ++k)
              if (nodes[k] == t_node)
                return segment.multiplier_dofs[k];
            return segment.multiplier_dofs[0];
          };
          // Distances in the reference configuration, as the check's point
          // is given; a node shared by two segments is seen from both,
          // with the same answer.
          for (unsigned int k = 0; k < t.size(); ++k)
            {
              const Point<2> x      = slave.reference_point(s, t[k]).x;
              const auto in_contact = [&](const types::global_dof_index dof) {
                return state.contact_of(dof).active_set().is_active(dof) &&
                       state.reported_pressure(dof) > 0;
              };
              const bool in = in_contact(dof_at(t[k]));
              if (in)
                width = std::max(width, x.distance(check.point<2>()));
              for (const int side : {-1, 1})
                {
                  const int j = static_cast<int>(k) + side;
                  if (!in || j < 0 || j >= static_cast<int>(t.size()))
                    continue;
                  if (in_contact(dof_at(t[j])))
                    continue;
                  const Point<2> edge =
                    slave.reference_point(s, 0.5 * (t[k] + t[j])).x;
                  width = std::max(width, edge.distance(check.point<2>()));
                }
            }
        }
      return width;
    }


    // @sect4{The slave surface's quantities in 3D}
    //
    // A 3D pair's slave surface is a set of bilinear quadrilaterals
    // (ContactInterface<3>::slave_faces()), its pressure interpolated
    // bilinearly from the nodes' reported pressures, as the multiplier is.
    // The quantities mean what they mean in 2D, with areas for lengths: the
    // half-width is the contact's radius about the point.
    namespace
    {
      // The reported pressure p_h at the points of `rule` on every slave
      // face of `contact`, handed to visit(p_h, X, dA) with the reference
      // position X and the reference area element times the weight.
      template <typename Visitor>
      void
      over_slave_faces(const ContactInterface<3> &contact,
                       const SolutionState<3>    &state,
                       const Quadrature<2>       &rule,
                       const Visitor             &visit)
      {
        const FaceKernel::FaceBasis bilinear(1);
        std::vector<double>         N;
        std::vector<Tensor<1, 2>>   dN;
        for (const auto &face : contact.slave_faces())
          for (unsigned int q = 0; q < rule.size(); ++q)
            {
              bilinear.evaluate(rule.point(q), N, dN);
              double       p = 0;
              Tensor<1, 3> X, a1, a2;
              for (unsigned int v = 0; v < 4; ++v)
                {
                  p += N[v] * state.reported_pressure(face.multipliers[v]);
                  X += N[v] * face.X[v];
                  a1 += dN[v][0] * face.X[v];
                  a2 += dN[v][1] * face.X[v];
                }
              visit(p,
                    Point<3>(X),
                    cross_product_3d(a1, a2).norm() * rule.weight(q));
            }
      }
    } // namespace

    // Within a face's diagonal of a slave node: any point of the surface is.
    template <>
    void
    CheckedQuantities<3>::require_on_slave_surface(
      const ProblemCheckParameters &check,
      const SolutionState<3>       &state,
      const types::global_dof_index nearest) const
    {
      const ContactInterface<3> &contact  = state.contact_of(nearest);
      double                     distance = 0, longest = 0;
      contact.multiplier_dof_nearest_to(check.point<3>(), &distance);
      for (const auto &face : contact.slave_faces())
        longest = std::max({longest,
                            face.X[0].distance(face.X[3]),
                            face.X[1].distance(face.X[2])});
      if (!(distance <= longest))
        throw std::runtime_error(
          check.name + ": the point " + check.point_text() + " is " +
          std::to_string(distance) +
          " from the nearest contact node, farther than a face of its "
          "slave surface: give a point on a slave surface");
    }

    // Frictionless in 3D (friction is refused there): zero by definition.
    template <>
    double
    CheckedQuantities<3>::tangential_traction(
      const SolutionState<3> &,
      const types::global_dof_index) const
    {
      return 0;
    }

    // The farthest node in contact (active, with a positive pressure) from
    // the point, or the midpoint of a face edge from a node in contact to an
    // open one: the contact's radius to half an edge, as the 2D half-width.
    template <>
    double
    CheckedQuantities<3>::contact_half_width(
      const ProblemCheckParameters &check,
      const SolutionState<3>       &state,
      const types::global_dof_index nearest) const
    {
      const auto in_contact = [&](const types::global_dof_index dof) {
        return state.contact_of(dof).active_set().is_active(dof) &&
               state.reported_pressure(dof) > 0;
      };
      const Point<3> P     = check.point<3>();
      double         width = 0;
      // The edges of a face in deal.II's lexicographic vertex order.
      const std::array<std::array<unsigned int, 2>, 4> edges = {
        {{{0, 1}}, {{2, 3}}, {{0, 2}}, {{1, 3}}}};
      for (const auto &face : state.contact_of(nearest).slave_faces())
        {
          for (unsigned int v = 0; v < 4; ++v)
            if (in_contact(face.multipliers[v]))
              width = std::max(width, face.X[v].distance(P));
          for (const auto &[a, b] : edges)
            if (in_contact(face.multipliers[a]) !=
                in_contact(face.multipliers[b]))
              width =
                std::max(width, (0.5 * (face.X[a] + face.X[b])).distance(P));
        }
      return width;
    }

    // @sect4{The pressure over a whole slave surface, in either dimension}
    //
    // The surface's segments (2D) or faces (3D) walked with a rule for the
    // mean or for the L2 error, and its nodes; the quantities themselves
    // are written once, below.
    namespace
    {
      // What the walk's rule is for.
      enum class Rule
      {
        mean, ///< Gauss points enough for p times the geometry's stretch
        /// Gauss points on pieces of each segment or face: p_h^2 exactly,
        /// and a reference that is not smooth, as Hertz's sqrt at the edge
        /// of the contact (fewer points per segment read a smaller error:
        /// doc/validation.md, "Figures that were in the code's comments").
        error
      };

      // The 2D slave surface of the pair of node `nearest`: 8 pieces per
      // segment for the error.
      template <typename Visitor>
      void
      walk_slave_surface(const SolutionState<2>       &state,
                         const types::global_dof_index nearest,
                         const Rule                    rule,
                         const Visitor                &visit)
      {
        const ContactSurface &slave = state.contact_of(nearest).slave_surface();
        const unsigned int    n     = slave.multiplier_basis().size();
        if (rule == Rule::mean)
          along_slave_surface(slave, state, QGauss<1>(n + 2), visit);
        else
          along_slave_surface(slave,
                              state,
                              QIterated<1>(QGauss<1>(n + 1), 8),
                              visit);
      }

      // The 3D slave surface: 3 x 3 Gauss points per face (exact for the
      // bilinear p on a parallelogram), 4 x 4 pieces per face for the
      // error.
      template <typename Visitor>
      void
      walk_slave_surface(const SolutionState<3>       &state,
                         const types::global_dof_index nearest,
                         const Rule                    rule,
                         const Visitor                &visit)
      {
        if (rule == Rule::mean)
          over_slave_faces(state.contact_of(nearest),
                           state,
                           QGauss<2>(3),
                           visit);
        else
          over_slave_faces(state.contact_of(nearest),
                           state,
                           QIterated<2>(QGauss<1>(3), 4),
                           visit);
      }

      // The multiplier unknowns of the slave surface (a cyclic sector's
      // rotated copies hold the originals' and are left out), each as
      // often as its segments or faces name it.
      std::vector<types::global_dof_index>
      slave_nodes(const SolutionState<2>       &state,
                  const types::global_dof_index nearest)
      {
        std::vector<types::global_dof_index> dofs;
        for (const auto &segment :
             state.contact_of(nearest).slave_surface().segments())
          if (!segment.is_copy)
            dofs.insert(dofs.end(),
                        segment.multiplier_dofs.begin(),
                        segment.multiplier_dofs.end());
        return dofs;
      }

      std::vector<types::global_dof_index>
      slave_nodes(const SolutionState<3>       &state,
                  const types::global_dof_index nearest)
      {
        std::vector<types::global_dof_index> dofs;
        for (const auto &face : state.contact_of(nearest).slave_faces())
          dofs.insert(dofs.end(),
                      face.multipliers.begin(),
                      face.multipliers.end());
        return dofs;
      }
    } // namespace

    // Its extremes over the nodes (every node, open ones at zero: a press
    // fit with a node open has a minimum of 0), or its mean, the integral
    // of the interpolated nodal pressures over the reference length (area)
    // divided by that length (area).
    template <int dim>
    double
    CheckedQuantities<dim>::surface_pressure(
      const ProblemCheckParameters &check,
      const SolutionState<dim>     &state,
      const types::global_dof_index nearest) const
    {
      double minimum  = std::numeric_limits<double>::max(),
             maximum  = -std::numeric_limits<double>::max();
      double integral = 0, measure = 0;
      for (const auto dof : slave_nodes(state, nearest))
        {
          minimum = std::min(minimum, state.reported_pressure(dof));
          maximum = std::max(maximum, state.reported_pressure(dof));
        }
      walk_slave_surface(state,
                         nearest,
                         Rule::mean,
                         [&](const double p,
                             const Point<dim> &,
                             const double dS) {
                           integral += p * dS;
                           measure += dS;
                         });
      switch (check.quantity)
        {
          case ProblemQuantity::minimum_contact_pressure:
            return minimum;
          case ProblemQuantity::maximum_contact_pressure:
            return maximum;
          default:
            return integral / measure;
        }
    }

    // ||p_h - p_ref|| / ||p_ref|| over the slave surface, in the reference
    // configuration (the expression's x, y (, z), as every check's).
    template <int dim>
    double
    CheckedQuantities<dim>::pressure_l2_error(
      const ProblemCheckParameters &check,
      const SolutionState<dim>     &state,
      const types::global_dof_index nearest) const
    {
      const auto reference = make_expression<dim>({check.reference},
                                                  problem.constants,
                                                  check.name + "/Reference");
      reference->set_time(state.load_state().time);
      double error = 0, norm = 0;
      walk_slave_surface(state,
                         nearest,
                         Rule::error,
                         [&](const double      p,
                             const Point<dim> &X,
                             const double      dS) {
                           const double p_ref = reference->value(X);
                           error += (p - p_ref) * (p - p_ref) * dS;
                           norm += p_ref * p_ref * dS;
                         });
      return std::sqrt(error / norm);
    }

    // The resultant of the traction over a boundary: its load where it is
    // loaded, its part of the reactions where it is supported
    // (BoundaryResultants, which splits a corner node's reaction between
    // the boundaries that hold it).
    template <int dim>
    const BoundaryResultants<dim> &
    CheckedQuantities<dim>::boundary_resultants(
      const SolutionState<dim> &state) const
    {
      // Summing the nodal forces over a boundary's nodes gave wrong resultants
      // for blocks loaded by (0.1 p, -p) with one x-support, on the support and
      // on a free edge (doc/validation.md, "Figures that were in the code's
      // comments"): a corner node's force belongs to two boundaries.
      if (!resultants || resultants_mesh != state.mesh_version())
        {
          resultants_mesh = state.mesh_version();
          // The directions each boundary's displacement holds.
          std::vector<SupportCondition> supports;
          for (const auto &condition : problem.boundary_conditions)
            if (condition.type == BoundaryConditionType::displacement)
              supports.push_back(
                {static_cast<types::boundary_id>(condition.boundary_id),
                 condition.normal ? SupportCondition::Kind::normal :
                 condition.polar  ? SupportCondition::Kind::polar :
                                    SupportCondition::Kind::cartesian,
                 condition.components});
          resultants =
            std::make_unique<BoundaryResultants<dim>>(state.get_dof_handler(),
                                                      state.get_mapping(),
                                                      supports);
        }
      return *resultants;
    }

    // The resultant of the traction over a boundary: its load where it is
    // loaded, its part of the reactions where it is supported
    // (BoundaryResultants, which splits a corner node's reaction between
    // the boundaries that hold it). The reactions used leave the contact
    // forces out: a support whose end node lies on a contact surface took
    // that node's contact force as its own.
    template <int dim>
    Tensor<1, dim>
    CheckedQuantities<dim>::resultant_force(
      const ProblemCheckParameters &check,
      const SolutionState<dim>     &state) const
    {
      return boundary_resultants(state).resultant(
        check.boundary_id,
        state.nodal_forces().reactions(),
        state.applied_resultants());
    }

    // Their moment about the check's point: in small strain at the
    // reference positions (the linear theory's balance), in finite strain at
    // the current ones.
    template <int dim>
    Tensor<1, 3>
    CheckedQuantities<dim>::resultant_moment(
      const ProblemCheckParameters &check,
      const SolutionState<dim>     &state) const
    {
      return boundary_resultants(state).moment(check.boundary_id,
                                               state.nodal_forces().reactions(),
                                               state.applied_resultants(),
                                               state.applied_moments(),
                                               check.template point<dim>(),
                                               state.in_finite_strain() ?
                                                 &state.get_solution() :
                                                 nullptr);
    }


    // The displacement at a point of the mesh (in the reference
    // configuration), found in whichever cell holds it.
    template <int dim>
    double
    CheckedQuantities<dim>::displacement(const ProblemCheckParameters &check,
                                         const SolutionState<dim> &state) const
    {
      // The triangulation is the reference configuration: point_value()
      // finds the cell that holds the point there, so the value is that of
      // a material point, followed through the whole motion. Its error (a
      // point in no cell) becomes one line that names the check.
      Vector<double> value(Components::n_components<dim>);
      try
        {
          VectorTools::point_value(state.get_mapping(),
                                   state.get_dof_handler(),
                                   state.get_solution(),
                                   check.template point<dim>(),
                                   value);
        }
      catch (...)
        {
          throw std::runtime_error(check.name + ": the point " +
                                   check.point_text() +
                                   " is in no cell of the mesh");
        }
      // The components in the order x, y, z of the quantities and of the
      // unknowns.
      return value(static_cast<int>(check.quantity) -
                   static_cast<int>(ProblemQuantity::displacement_x));
    }

    // The two dimensions of the program (issue 48); the slave surface's
    // quantities of 3D are in quantities_3d.cc.
    template class CheckedQuantities<2>;
    template class CheckedQuantities<3>;
  } // namespace General
} // namespace RingContact
