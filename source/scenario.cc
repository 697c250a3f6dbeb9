#include <deal.II/base/function_parser.h>
#include <deal.II/numerics/vector_tools.h>

#include <ring_contact/analytic_solution.h>
#include <ring_contact/boundary_motion.h>
#include <ring_contact/components.h>
#include <ring_contact/scenario.h>

#include <array>
#include <cmath>

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
      std::map<types::global_dof_index, double>
      imposed_displacements(const DoFHandler<2>            &dof_handler,
                            const hp::MappingCollection<2> &mapping,
                            const LoadState                &load) const override
      {
        std::map<types::global_dof_index, double> values;
        if (pressure_loading)
          {
            add_rigid_body_points(dof_handler, values);
            return values;
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
        return values;
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

      std::map<types::global_dof_index, double>
      imposed_displacements(const DoFHandler<2>            &dof_handler,
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
            std::vector<double>{0, -shortening, 0}), // u_x, u_y, multiplier
          values,
          vertical);
        for (const auto &cell : dof_handler.active_cell_iterators())
          for (const unsigned int v : cell->vertex_indices())
            if (std::abs(cell->vertex(v)[0]) < 1e-12 &&
                std::abs(std::abs(cell->vertex(v)[1]) - 0.5) < 1e-12)
              values[cell->vertex_dof_index(
                v, Components::ux, cell->active_fe_index())] = 0;
        return values;
      }

      double
      reference_pressure(const LoadState &load) const override
      {
        return load.pressure;
      }

    private:
      const Parameters parameters;
    };

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
          , polar(condition.polar)
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
        if (polar)
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
      const bool                         polar;
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
        for (unsigned int b = 0; b < ProblemParameters::n_bodies; ++b)
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
                            m.kinematics)});
          }
        return bodies;
      }

      // The conditions in the order of the file: at a node on two
      // boundaries with displacement conditions, the later one decides the
      // components both impose.
      std::map<types::global_dof_index, double>
      imposed_displacements(const DoFHandler<2>            &dof_handler,
                            const hp::MappingCollection<2> &mapping,
                            const LoadState                &load) const override
      {
        std::map<types::global_dof_index, double> values;
        for (const auto &condition : parameters.problem.boundary_conditions)
          if (condition.type == BoundaryConditionType::displacement)
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
        return values;
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
                [expression, n](const Point<2> &X, const LoadState &load) {
                  expression->set_time(load.time);
                  Tensor<1, 2> value;
                  for (unsigned int c = 0; c < n; ++c)
                    value[c] = expression->value(X, c);
                  return value;
                }});
            }
        return loads;
      }

    private:
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
