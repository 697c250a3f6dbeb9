#include <deal.II/base/function_parser.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/hp/fe_values.h>
#include <deal.II/hp/q_collection.h>
#include <deal.II/numerics/vector_tools.h>

#include <ring_contact/analytic_solution.h>
#include <ring_contact/boundary_motion.h>
#include <ring_contact/components.h>
#include <ring_contact/equilibrium.h>
#include <ring_contact/parameter_file.h>
#include <ring_contact/scenario.h>

#include <array>
#include <cmath>
#include <sstream>

namespace RingContact
{
  double
  Scenario::reference_pressure(const LoadState &) const
  {
    return std::nan("");
  }

  namespace
  {
    // The two rings of SSNP152, outer (100) and inner (101).
    std::vector<Body>
    ring_bodies(const Parameters &parameters)
    {
      const auto &m  = parameters.materials;
      const auto &fe = parameters.finite_elements;
      return {Body{Ids::outer_ring,
                   "outer ring",
                   fe.degree_outer,
                   fe.mapping_degree_of(Ids::outer_ring),
                   Material(m.youngs_modulus_outer,
                            m.poissons_ratio_outer,
                            m.plane,
                            m.kinematics)},
              Body{Ids::inner_ring,
                   "inner ring",
                   fe.degree_inner,
                   fe.mapping_degree_of(Ids::inner_ring),
                   Material(m.youngs_modulus_inner,
                            m.poissons_ratio_inner,
                            m.plane,
                            m.kinematics)}};
    }

    // SSNP152: the rings loaded through the analytic solution.
    class Ssnp152 : public Scenario
    {
    public:
      explicit Ssnp152(const Parameters &parameters)
          : parameters(parameters)
          , analytic(parameters.mesh, parameters.materials)
          , pressure_loading(parameters.load.loading == Loading::pressure)
      {}

      std::vector<Body>
      bodies() const override
      {
        return ring_bodies(parameters);
      }

      // Imposed displacements: the analytic ones on r = R1 and r = R3, the
      // inner boundary turned through the rotation. Pressure loading:
      // nothing is imposed, but nothing holds the rings in place either:
      // each can translate and turn (frictionless contact transmits no
      // torque). Three displacement components per ring fix them without
      // constraining the solution sought, which is radial: u_y = 0 at
      // (r, 0) and (-r, 0), u_x = 0 at (0, r), on r = R1 for the outer ring
      // and r = R3 for the inner one.
      ImposedMotion
      boundary_motion(const DoFHandler<2>            &dof_handler,
                      const hp::MappingCollection<2> &mapping,
                      const LoadState                &load) const override
      {
        std::map<types::global_dof_index, double> values;
        if (pressure_loading)
          {
            add_rigid_body_points(dof_handler, values);
            return {values, {}};
          }
        const double angle = 2 * numbers::PI * load.rotation_elements /
                             (parameters.mesh.elements_around *
                              (1u << parameters.mesh.global_refinements));
        const BoundaryMotion outer(analytic.f_R1(load.pressure),
                                   0.0,
                                   Components::n_components);
        const BoundaryMotion inner(analytic.f_R3(load.pressure),
                                   angle,
                                   Components::n_components);
        const std::map<types::boundary_id, const Function<2> *> motion = {
          {Ids::outer_boundary, &outer}, {Ids::inner_boundary, &inner}};
        VectorTools::interpolate_boundary_values(
          mapping,
          dof_handler,
          motion,
          values,
          Components::displacement_mask());
        return {values, {}};
      }

      // Pressure loading: p on r = R1.
      std::vector<BoundaryLoad>
      boundary_loads() const override
      {
        if (!pressure_loading)
          return {};
        return {BoundaryLoad{Ids::outer_boundary,
                             BoundaryLoad::Type::pressure,
                             [](const Point<2> &, const LoadState &load) {
                               return Tensor<1, 2>({load.pressure, 0.0});
                             }}};
      }

      double
      reference_pressure(const LoadState &load) const override
      {
        return analytic.contact_pressure(load.pressure);
      }

    private:
      void
      add_rigid_body_points(
        const DoFHandler<2>                       &dof_handler,
        std::map<types::global_dof_index, double> &values) const
      {
        const auto &mesh = parameters.mesh;
        for (const auto &[boundary, r] :
             {std::make_pair(Ids::outer_boundary, mesh.outer_radius),
              std::make_pair(Ids::inner_boundary, mesh.inner_radius)})
          {
            // point, component
            const std::array<std::pair<Point<2>, unsigned int>, 3> fixed = {
              {{Point<2>(r, 0), 1}, {Point<2>(-r, 0), 1}, {Point<2>(0, r), 0}}};
            std::array<bool, 3> found = {{false, false, false}};
            for (const auto &cell : dof_handler.active_cell_iterators())
              for (const auto &face : cell->face_iterators())
                if (face->at_boundary() && face->boundary_id() == boundary)
                  for (const unsigned int v : face->vertex_indices())
                    for (unsigned int k = 0; k < 3; ++k)
                      if (face->vertex(v).distance(fixed[k].first) < 1e-8 * r)
                        {
                          values[face->vertex_dof_index(
                            v, fixed[k].second, cell->active_fe_index())] = 0;
                          found[k] = true;
                        }
            for (unsigned int k = 0; k < 3; ++k)
              AssertThrow(found[k],
                          ExcMessage(
                            "Loading = pressure: no mesh node at (" +
                            Utilities::to_string(fixed[k].first[0]) + ", " +
                            Utilities::to_string(fixed[k].first[1]) +
                            ") on boundary " + std::to_string(boundary) +
                            ", where a rigid-body mode of its ring is fixed "
                            "(the number of elements around must be a "
                            "multiple of 4, with a node at angle 0)"));
          }
      }

      const Parameters       parameters;
      const AnalyticSolution analytic;
      const bool             pressure_loading;
    };

    // The contact patch test: two blocks (lower: 100, master; upper: 101,
    // slave), the bottom held vertically, the top moved down by the
    // shortening of the two blocks under the uniaxial pressure p (small
    // strain): p (H1 / E1* + H2 / E2*); the horizontal displacement held at
    // the left corner of each block (no rigid sliding).
    class PatchTest : public Scenario
    {
    public:
      explicit PatchTest(const Parameters &parameters)
          : parameters(parameters)
      {}

      std::vector<Body>
      bodies() const override
      {
        auto bodies    = ring_bodies(parameters);
        bodies[0].name = "lower block";
        bodies[1].name = "upper block";
        return bodies;
      }

      ImposedMotion
      boundary_motion(const DoFHandler<2>            &dof_handler,
                      const hp::MappingCollection<2> &mapping,
                      const LoadState                &load) const override
      {
        const auto &m       = parameters.materials;
        const auto  modulus = [&](const double E, const double nu) {
          return m.plane == PlaneAssumption::plane_stress ? E :
                                                             E / (1 - nu * nu);
        };
        const double shortening =
          load.pressure *
          (0.5 / modulus(m.youngs_modulus_outer, m.poissons_ratio_outer) +
           0.5 / modulus(m.youngs_modulus_inner, m.poissons_ratio_inner));
        std::map<types::global_dof_index, double> values;
        const ComponentMask                       vertical =
          Components::displacement_mask(false, true);
        VectorTools::interpolate_boundary_values(mapping,
                                                 dof_handler,
                                                 Ids::outer_boundary,
                                                 Functions::ZeroFunction<2>(
                                                   Components::n_components),
                                                 values,
                                                 vertical);
        VectorTools::interpolate_boundary_values(
          mapping,
          dof_handler,
          Ids::inner_boundary,
          Functions::ConstantFunction<2>(
            std::vector<double>{0, -shortening, 0, 0}), // u, the multipliers
          values,
          vertical);
        for (const auto &cell : dof_handler.active_cell_iterators())
          for (const unsigned int v : cell->vertex_indices())
            if (std::abs(cell->vertex(v)[0]) < 1e-12 &&
                std::abs(std::abs(cell->vertex(v)[1]) - 0.5) < 1e-12)
              values[cell->vertex_dof_index(
                v, Components::ux, cell->active_fe_index())] = 0;
        return {values, {}};
      }

      double
      reference_pressure(const LoadState &load) const override
      {
        return load.pressure;
      }

    private:
      const Parameters parameters;
    };

    // A value of a boundary condition, checked: "Boundary condition 2
    // (displacement on boundary 12): not a finite number (nan) at (0,
    // 0.25), t = 0.5".
    double
    finite_value(const double                       value,
                 const BoundaryConditionParameters &condition,
                 const Point<2>                    &X,
                 const double                       time)
    {
      if (std::isfinite(value))
        return value;
      std::ostringstream message;
      message << condition.name << " ("
              << (condition.type == BoundaryConditionType::displacement ?
                    "displacement" :
                  condition.type == BoundaryConditionType::traction ?
                    "traction" :
                    "pressure")
              << " on boundary " << condition.boundary_id
              << "): its value is not a finite number ("
              << (std::isnan(value) ? "nan" :
                  value > 0         ? "inf" :
                                      "-inf")
              << ") at (" << X[0] << ", " << X[1] << "), t = " << time;
      throw BoundaryDataError(message.str());
    }

    // An expression of the parameter file as a deal.II Function of the
    // reference position at the load state's time, with the layout of the
    // unknowns (u_x, u_y, multiplier): a polar displacement (u_r, u_theta)
    // is turned into Cartesian components.
    class ImposedDisplacement : public Function<2>
    {
    public:
      ImposedDisplacement(const BoundaryConditionParameters   &condition,
                          const std::map<std::string, double> &constants,
                          const double                         time)
          : Function<2>(Components::n_components, time)
          , condition(condition)
          , expression(
              make_expression(condition.expressions, constants, condition.name))
      {
        expression->set_time(time);
      }

      void
      vector_value(const Point<2> &X, Vector<double> &values) const override
      {
        Vector<double> u(2);
        expression->vector_value(X, u);
        for (unsigned int c = 0; c < 2; ++c)
          if (condition.components[c])
            finite_value(u(c), condition, X, this->get_time());
        if (condition.polar)
          {
            const double theta = std::atan2(X[1], X[0]);
            const double c = std::cos(theta), s = std::sin(theta);
            values(0) = c * u(0) - s * u(1);
            values(1) = s * u(0) + c * u(1);
          }
        else
          {
            values(0) = u(0);
            values(1) = u(1);
          }
        values(Components::multiplier) = 0;
      }

      double
      value(const Point<2> &X, const unsigned int component) const override
      {
        Vector<double> values(Components::n_components);
        vector_value(X, values);
        return values(component);
      }

    private:
      const BoundaryConditionParameters &condition;
      std::unique_ptr<FunctionParser<2>> expression;
    };

    // A problem written in the parameter file.
    class General : public Scenario
    {
    public:
      explicit General(const Parameters &parameters)
          : parameters(parameters)
      {}

      std::vector<Body>
      bodies() const override
      {
        const auto       &m = parameters.materials;
        std::vector<Body> bodies;
        for (unsigned int b = 0; b < parameters.problem.bodies.size(); ++b)
          {
            const auto &body = parameters.problem.bodies[b];
            bodies.push_back(
              Body{static_cast<types::material_id>(body.material_id),
                   "Body " + std::to_string(b + 1),
                   body.degree,
                   parameters.finite_elements.mapping_degree > 0 ?
                     parameters.finite_elements.mapping_degree :
                     body.degree,
                   Material(body.youngs_modulus,
                            body.poissons_ratio,
                            m.plane,
                            body.inherits_kinematics ? m.kinematics :
                                                       body.kinematics)});
          }
        return bodies;
      }

      std::vector<BoundaryLoad>
      boundary_loads() const override
      {
        std::vector<BoundaryLoad> loads;
        for (const auto &condition : parameters.problem.boundary_conditions)
          if (condition.type == BoundaryConditionType::traction ||
              condition.type == BoundaryConditionType::pressure)
            {
              std::shared_ptr<FunctionParser<2>> expression =
                make_expression(condition.expressions,
                                parameters.problem.constants,
                                condition.name);
              const unsigned int n = condition.expressions.size();
              loads.push_back(BoundaryLoad{
                static_cast<types::boundary_id>(condition.boundary_id),
                condition.type == BoundaryConditionType::pressure ?
                  BoundaryLoad::Type::pressure :
                  BoundaryLoad::Type::traction,
                [expression, n, condition](const Point<2>  &X,
                                           const LoadState &load) {
                  expression->set_time(load.time);
                  Tensor<1, 2> value;
                  for (unsigned int c = 0; c < n; ++c)
                    value[c] = finite_value(expression->value(X, c),
                                            condition,
                                            X,
                                            load.time);
                  return value;
                }});
            }
        return loads;
      }

      // A load on a boundary whose displacement is imposed along a
      // direction the load acts in: the support takes that part of the
      // load, which is silently ignored (a traction (0.1 p, -p) on a
      // boundary held in y: its y part never reached the body). Refused,
      // at the quadrature points of the loaded faces and the load
      // program's pseudo-times, where the load's component along a held
      // direction exceeds 1e-12 of its magnitude.
      void
      check_boundary_data(const DoFHandler<2>            &dof_handler,
                          const hp::MappingCollection<2> &mapping,
                          const std::vector<double>      &times) const override
      {
        const auto &conditions = parameters.problem.boundary_conditions;
        for (const auto &load : boundary_loads())
          for (const auto &condition : conditions)
            {
              if (condition.type != BoundaryConditionType::displacement ||
                  condition.boundary_id != load.boundary_id)
                continue;
              const SupportCondition support{
                load.boundary_id,
                condition.normal ? SupportCondition::Kind::normal :
                condition.polar  ? SupportCondition::Kind::polar :
                                   SupportCondition::Kind::cartesian,
                condition.components};
              const BoundaryConditionParameters *loaded = nullptr;
              for (const auto &other : conditions)
                if (other.boundary_id == load.boundary_id &&
                    other.type != BoundaryConditionType::displacement)
                  loaded = &other;
              for_each_boundary_face(
                dof_handler,
                mapping,
                [&](const auto                      &cell,
                    const unsigned int               f,
                    const std::vector<BoundaryNode> &nodes) {
                  if (cell->face(f)->boundary_id() != load.boundary_id)
                    return;
                  for (const BoundaryNode &node : nodes)
                    for (const double t : times)
                      {
                        const LoadState    state{0, 0, t};
                        const Tensor<1, 2> value = load.value(node.X, state);
                        const Tensor<1, 2> force =
                          load.type == BoundaryLoad::Type::pressure ?
                            Tensor<1, 2>(-value[0] * node.N) :
                            value;
                        for (const auto &d : support.directions(node.X, node.N))
                          if (std::abs(force * d) > 1e-12 * force.norm())
                            {
                              std::ostringstream what;
                              what << "= " << load.boundary_id << " is loaded by "
                                   << loaded->name << " along a direction ("
                                   << d[0] << ", " << d[1] << ") that "
                                   << condition.name
                                   << " holds (at (" << node.X[0] << ", "
                                   << node.X[1] << "), t = " << t
                                   << "): the support would take that part "
                                      "of the load, which would never reach "
                                      "the body; impose the displacement "
                                      "only along the other direction, or "
                                      "load only across the held one";
                              throw ParameterError(loaded->name,
                                                   "Boundary id",
                                                   "parameter 'Boundary id' "
                                                   "in subsection '" +
                                                     loaded->name + "' " +
                                                     what.str());
                            }
                      }
                });
            }
      }

    private:
      // The displacement conditions at a load state, in the order of the
      // file: at a node on two boundaries with Cartesian or polar
      // conditions, the later one decides the components both impose.
      // Then the normal conditions (Components = n), node by node: the
      // outward normals of the faces at the node are averaged, unless they
      // are more than 60 degrees apart (a corner, or two conditions that
      // meet at an angle): then both directions are imposed, N1 . u = g1
      // and N2 . u = g2 fix the node. A node with one component imposed
      // already gets the other from its normal condition; only a node with
      // nothing else imposed keeps the single linear condition N . u = g.
      ImposedMotion
      boundary_motion(const DoFHandler<2>            &dof_handler,
                      const hp::MappingCollection<2> &mapping,
                      const LoadState                &load) const override
      {
        std::map<types::global_dof_index, double> values;
        for (const auto &condition : parameters.problem.boundary_conditions)
          if (condition.type == BoundaryConditionType::displacement &&
              !condition.normal)
            {
              const ImposedDisplacement                 motion(condition,
                                               parameters.problem.constants,
                                               load.time);
              std::map<types::global_dof_index, double> these;
              VectorTools::interpolate_boundary_values(
                mapping,
                dof_handler,
                condition.boundary_id,
                motion,
                these,
                Components::displacement_mask(condition.components[0],
                                              condition.components[1]));
              for (const auto &[dof, value] : these)
                values[dof] = value;
            }

        // Per node (its u_x and u_y unknowns): the face normals and values.
        using Node = std::array<types::global_dof_index, 2>;
        std::map<Node, std::vector<std::pair<Tensor<1, 2>, double>>> faces;
        const auto        &fe_collection = dof_handler.get_fe_collection();
        hp::QCollection<1> support_points;
        for (unsigned int i = 0; i < fe_collection.size(); ++i)
          support_points.push_back(
            Quadrature<1>(fe_collection[i].get_unit_face_support_points(0)));
        hp::FEFaceValues<2>                  face_values(mapping,
                                        fe_collection,
                                        support_points,
                                        update_quadrature_points |
                                          update_normal_vectors);
        std::vector<types::global_dof_index> face_dofs;
        for (const auto &condition : parameters.problem.boundary_conditions)
          if (condition.type == BoundaryConditionType::displacement &&
              condition.normal)
            {
              auto expression = make_expression(condition.expressions,
                                                parameters.problem.constants,
                                                condition.name);
              expression->set_time(load.time);
              for (const auto &cell : dof_handler.active_cell_iterators())
                for (const unsigned int f : cell->face_indices())
                  if (cell->face(f)->at_boundary() &&
                      cell->face(f)->boundary_id() == condition.boundary_id)
                    {
                      face_values.reinit(cell, f);
                      const FEFaceValues<2> &fv =
                        face_values.get_present_fe_values();
                      const FiniteElement<2> &fe = cell->get_fe();
                      face_dofs.resize(fe.n_dofs_per_face(f));
                      cell->face(f)->get_dof_indices(face_dofs,
                                                     cell->active_fe_index());
                      // The support points of the face, each with its u_x
                      // and u_y unknowns.
                      for (unsigned int i = 0; i < face_dofs.size(); ++i)
                        if (fe.face_system_to_component_index(i, f).first ==
                            Components::ux)
                          for (unsigned int j = 0; j < face_dofs.size(); ++j)
                            if (fe.face_system_to_component_index(j, f).first ==
                                  Components::uy &&
                                fv.quadrature_point(j) ==
                                  fv.quadrature_point(i))
                              faces[Node{{face_dofs[i], face_dofs[j]}}]
                                .emplace_back(
                                  fv.normal_vector(i),
                                  finite_value(expression->value(
                                                 fv.quadrature_point(i)),
                                               condition,
                                               fv.quadrature_point(i),
                                               load.time));
                    }
            }

        std::vector<NormalDisplacement> normal;
        const double                    corner = 0.5; // cos 60 degrees
        for (const auto &[node, list] : faces)
          {
            // Two groups: the normals near the first one, and the others.
            std::array<Tensor<1, 2>, 2> sum;
            std::array<double, 2>       value = {{0, 0}};
            for (const auto &[n, g] : list)
              {
                const unsigned int group = n * list[0].first >= corner ? 0 : 1;
                sum[group] += n;
                value[group] = g; // the later condition decides
              }
            std::array<Tensor<1, 2>, 2> N;
            for (unsigned int k = 0; k < 2; ++k)
              if (sum[k].norm() > 0)
                N[k] = sum[k] / sum[k].norm();
            const bool has_x = values.count(node[0]) > 0,
                       has_y = values.count(node[1]) > 0;
            if (has_x && has_y)
              continue;
            if (has_x || has_y)
              {
                // The other component from the group most across the
                // imposed one (none if the normal is along it: the
                // Cartesian condition then decides).
                const unsigned int a = has_x ? 0 : 1, b = 1 - a;
                const unsigned int k =
                  std::abs(N[1][b]) > std::abs(N[0][b]) ? 1 : 0;
                if (std::abs(N[k][b]) >= 0.1)
                  values[node[b]] =
                    (value[k] - N[k][a] * values.at(node[a])) / N[k][b];
                continue;
              }
            if (N[1].norm() == 0)
              {
                normal.push_back(NormalDisplacement{node, N[0], value[0]});
                continue;
              }
            // A corner: N1 . u = g1, N2 . u = g2.
            const double det = N[0][0] * N[1][1] - N[0][1] * N[1][0];
            values[node[0]]  = (value[0] * N[1][1] - value[1] * N[0][1]) / det;
            values[node[1]]  = (N[0][0] * value[1] - N[1][0] * value[0]) / det;
          }
        return {values, normal};
      }

      const Parameters parameters;
    };
  } // namespace

  std::unique_ptr<Scenario>
  make_scenario(const Parameters &parameters)
  {
    if (parameters.general())
      return std::make_unique<General>(parameters);
    if (parameters.mesh.source == MeshSource::patch_test)
      return std::make_unique<PatchTest>(parameters);
    return std::make_unique<Ssnp152>(parameters);
  }
} // namespace RingContact
