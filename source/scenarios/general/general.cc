// @sect3{The general scenario}
//
// A general problem as a scenario (general.h): the bodies of a gmsh model,
// the boundary conditions, loads and checks of the parameter file as
// expressions of x, y (, z) and t, in the model's dimension: one class
// for 2D and 3D. The description itself is read and checked
// by problem_description.cc; this file answers the problem class's
// questions with it (scenario.h): the mesh, the bodies, the imposed
// displacements of a load state (normal conditions resolved node by
// node), the boundary loads, what each step reports and how the checks
// judge it. The mesh is checked against the description in
// mesh_checks.cc, the checked quantities are computed in quantities.cc.
// A general problem replaced the branches the problem class once had for
// the patch test and the pressure load: the class asks a Scenario, and
// this one is a file's problem.
#include <deal.II/base/function_parser.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/hp/fe_values.h>
#include <deal.II/hp/q_collection.h>
#include <deal.II/numerics/vector_tools.h>

#include <ring_contact/base/components.h>
#include <ring_contact/base/dimension.h>
#include <ring_contact/input/gmsh_mesh.h>
#include <ring_contact/input/model_curves.h>
#include <ring_contact/input/model_surfaces.h>
#include <ring_contact/input/parameter_file.h>
#include <ring_contact/scenarios/general/general.h>
#include <ring_contact/scenarios/general/normal_conditions.h>
#include <ring_contact/scenarios/reference_pressure.h>
#include <ring_contact/scenarios/scenario.h>

#include <array>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace RingContact
{
  namespace General
  {
    namespace
    {
      // "0, 0.25" or "0, 0.25, 1": a point or a direction in the messages.
      template <int dim>
      std::string
      components_text(const Tensor<1, dim> &v)
      {
        std::ostringstream out;
        for (unsigned int d = 0; d < dim; ++d)
          out << (d > 0 ? ", " : "") << v[d];
        return out.str();
      }

      // A value of a boundary condition, checked: "Boundary condition 2
      // (displacement on boundary 12): not a finite number (nan) at (0,
      // 0.25), t = 0.5". Checked where it is evaluated, because only there
      // are the point and the time known. A BoundaryDataError fails the load
      // step, which is cut like a failed Newton iteration (the converged
      // steps stay). Before, Value = sqrt(-1); 0 was reported as 'inverted
      // elements: det F = 1 <= 0' (a NaN det F counted as inverted), and a
      // traction sqrt(0.6 - t) only as 'the residual is not finite'.
      template <int dim>
      double
      finite_value(const double                       value,
                   const BoundaryConditionParameters &condition,
                   const Point<dim>                  &X,
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
                << ") at (" << components_text(X) << "), t = " << time;
        throw BoundaryDataError(message.str());
      }

      // An expression of the parameter file as a deal.II Function of the
      // reference position at the load state's time, with the layout of the
      // unknowns (u_x, u_y (, u_z), multiplier): a polar displacement (u_r,
      // u_theta (, u_z)) is turned into Cartesian components.
      template <int dim>
      class ImposedDisplacement : public Function<dim>
      {
      public:
        // Made per condition and load state, its expression parsed anew:
        // cheap beside the load step it serves.
        ImposedDisplacement(const BoundaryConditionParameters   &condition,
                            const std::map<std::string, double> &constants,
                            const double                         time)
            : Function<dim>(Components::n_components<dim>, time)
            , condition(condition)
            , expression(make_expression<dim>(condition.expressions,
                                              constants,
                                              condition.name))
        {
          expression->set_time(time);
        }

        // Only the imposed components must be numbers: the others are not
        // used, and a file may leave them as anything. The multiplier's
        // component is masked out by the caller, but a Function of the
        // system must give every component.
        void
        vector_value(const Point<dim> &X, Vector<double> &values) const override
        {
          Vector<double> u(dim);
          expression->vector_value(X, u);
          for (unsigned int c = 0; c < dim; ++c)
            if (condition.components[c])
              finite_value(u(c), condition, X, this->get_time());
          for (unsigned int c = 0; c < dim; ++c)
            values(c) = u(c);
          // u = u_r e_r + u_theta e_theta (+ u_z e_z), with the angle of the
          // reference position about the origin (the z axis).
          if (condition.polar)
            {
              const double theta = std::atan2(X[1], X[0]);
              const double c = std::cos(theta), s = std::sin(theta);
              values(0) = c * u(0) - s * u(1);
              values(1) = s * u(0) + c * u(1);
            }
          values(Components::multiplier<dim>) = 0;
        }

        // deal.II's interpolation may ask for one component at a time.
        double
        value(const Point<dim> &X, const unsigned int component) const override
        {
          Vector<double> values(Components::n_components<dim>);
          vector_value(X, values);
          return values(component);
        }

      private:
        // By reference: the condition lives in the problem's entries, which
        // outlive every load state's function.
        const BoundaryConditionParameters   &condition;
        std::unique_ptr<FunctionParser<dim>> expression;
      };

      // A problem written in the parameter file.
      template <int dim>
      class GeneralProblem : public Scenario<dim>
      {
      public:
        // `problem` refers to the scenario's entries, which the copy of the
        // parameters kept here shares (Parameters holds them by shared_ptr):
        // they live as long as this object.
        explicit GeneralProblem(const Parameters &parameters)
            : parameters(parameters)
            , problem(parameters.scenario_entries<ProblemParameters>())
            , program(LoadProgram::steps(parameters.load))
            , quantities(problem)
        {}

        // The bodies of a gmsh model, on the model's curves and surfaces,
        // meshed from a script with linear elements (the cells take the
        // vertices only); the audit of its tags first (a line it drops leaves a
        // boundary without faces, which check_bodies() would report).
        void
        create_mesh(Triangulation<dim> &triangulation) const override
        {
          const Geometry::GmshMesh<dim> mesh =
            Geometry::read_gmsh<dim>(triangulation,
                                     parameters.mesh.mesh_file,
                                     parameters.mesh.geo_numbers,
                                     1,
                                     false);
          Geometry::check_boundary_tags(triangulation, mesh);
          check_bodies<dim>(triangulation, parameters);
          // The size estimate takes the highest degree of the bodies: the
          // estimate errs on the large side, as a refusal should.
          unsigned int degree = 1;
          for (const auto &body : problem.bodies)
            degree = std::max(degree, body.degree);
          Geometry::check_size<dim>(triangulation.n_active_cells(),
                                    degree,
                                    parameters.mesh.global_refinements);
          // A script's curves (in 3D its spheres and cylinders) are the
          // geometry (model_curves.h, model_surfaces.h): refined vertices
          // go onto them, and a Mapping degree >= 2 curves the cells. A
          // mesh file has straight sides.
          if constexpr (dim == 2)
            Geometry::attach_model_curves(triangulation, mesh);
          else
            Geometry::attach_model_surfaces(triangulation, mesh);
          triangulation.refine_global(parameters.mesh.global_refinements);
        }

        const LoadProgram &
        load_program() const override
        {
          return program;
        }

        // The bodies in the order of the file; each named "Body k" in the
        // messages, with its own material law or the common one. Mapping
        // degree = 0 gives each body its displacement degree.
        std::vector<Body<dim>>
        bodies() const override
        {
          const auto            &m = parameters.materials;
          std::vector<Body<dim>> bodies;
          for (unsigned int b = 0; b < problem.bodies.size(); ++b)
            {
              const auto &body = problem.bodies[b];
              bodies.push_back(
                Body<dim>{static_cast<types::material_id>(body.material_id),
                          "Body " + std::to_string(b + 1),
                          body.degree,
                          parameters.finite_elements.mapping_degree > 0 ?
                            parameters.finite_elements.mapping_degree :
                            body.degree,
                          Material<dim>(body.youngs_modulus,
                                        body.poissons_ratio,
                                        m.plane,
                                        body.law.empty() ? m.law : body.law)});
            }
          return bodies;
        }

        std::vector<BoundaryLoad<dim>>
        boundary_loads() const override
        {
          std::vector<BoundaryLoad<dim>> loads;
          for (const auto &condition : problem.boundary_conditions)
            if (condition.type == BoundaryConditionType::traction ||
                condition.type == BoundaryConditionType::pressure)
              {
                // Parsed once here and shared by the load's function, which
                // the problem class keeps and calls at every quadrature point
                // of the loaded faces. Setting its time from a const lambda
                // is safe because the program runs one thread.
                std::shared_ptr<FunctionParser<dim>> expression =
                  make_expression<dim>(condition.expressions,
                                       problem.constants,
                                       condition.name);
                // dim components for a traction, one for a pressure: the
                // pressure is the load's first component (BoundaryLoad).
                const unsigned int n = condition.expressions.size();
                loads.push_back(BoundaryLoad<dim>{
                  static_cast<types::boundary_id>(condition.boundary_id),
                  condition.type == BoundaryConditionType::pressure ?
                    BoundaryLoad<dim>::Type::pressure :
                    BoundaryLoad<dim>::Type::traction,
                  [expression, n, condition](const Point<dim> &X,
                                             const LoadState  &load) {
                    expression->set_time(load.time);
                    Tensor<1, dim> value;
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
        // direction exceeds 1e-12 of its magnitude. Called by the problem
        // class once the unknowns exist, before the first step, with the
        // pseudo-time of every step of the load program.
        void
        check_boundary_data(const DoFHandler<dim>            &dof_handler,
                            const hp::MappingCollection<dim> &mapping,
                            const std::vector<double> &times) const override
        {
          const auto &conditions = problem.boundary_conditions;
          for (const auto &load : boundary_loads())
            for (const auto &condition : conditions)
              {
                if (condition.type != BoundaryConditionType::displacement ||
                    condition.boundary_id != load.boundary_id)
                  continue;
                // The directions this displacement condition holds: x and y,
                // e_r and e_theta, or the normal, as imposed.
                const SupportCondition support{
                  load.boundary_id,
                  condition.normal ? SupportCondition::Kind::normal :
                  condition.polar  ? SupportCondition::Kind::polar :
                                     SupportCondition::Kind::cartesian,
                  condition.components};
                // The condition that is the load, for the message (one load
                // per boundary: problem_description.cc refuses two).
                const BoundaryConditionParameters *loaded = nullptr;
                for (const auto &other : conditions)
                  if (other.boundary_id == load.boundary_id &&
                      other.type != BoundaryConditionType::displacement)
                    loaded = &other;
                for_each_boundary_face<dim>(
                  dof_handler,
                  mapping,
                  [&](const auto                           &cell,
                      const unsigned int                    f,
                      const std::vector<BoundaryNode<dim>> &nodes) {
                    if (cell->face(f)->boundary_id() != load.boundary_id)
                      return;
                    // At every pseudo-time of the program: a load that turns
                    // into a held direction only later (a traction written
                    // with sin t) is found too. A general problem's load
                    // states carry no parameters, only t.
                    for (const BoundaryNode<dim> &node : nodes)
                      for (const double t : times)
                        {
                          const LoadState      state{t, {}};
                          const Tensor<1, dim> value =
                            load.value(node.X, state);
                          // A pressure pushes along the inward normal, -p N,
                          // taken on the reference boundary.
                          const Tensor<1, dim> force =
                            load.type == BoundaryLoad<dim>::Type::pressure ?
                              Tensor<1, dim>(-value[0] * node.N) :
                              value;
                          // Relative to the force: a component that is zero
                          // up to round-off (cos(pi / 2) = 6e-17) passes.
                          for (const auto &d :
                               support.template directions<dim>(node.X, node.N))
                            if (std::abs(force * d) > 1e-12 * force.norm())
                              {
                                std::ostringstream what;
                                what << "= " << load.boundary_id
                                     << " is loaded by " << loaded->name
                                     << " along a direction ("
                                     << components_text(d) << ") that "
                                     << condition.name << " holds (at ("
                                     << components_text(node.X)
                                     << "), t = " << t
                                     << "): the support would take that part "
                                        "of the load, which would never reach "
                                        "the body; impose the displacement "
                                        "only along the other direction, or "
                                        "load only across the held one";
                                // A ParameterError of the load's Boundary id:
                                // located at the line that set it.
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

        // What it reports: the extreme contact pressures over every slave
        // node (the rings' pressure at A and its analytic value mean nothing
        // here), then the quantities of its checks and, with friction, the
        // number of sliding nodes. A quantity at a point (a pressure, a
        // tangential traction, a displacement) is a Check subsection's:
        // `Steps = none` reports it at every step without checking it.
        std::vector<std::string>
        leading_columns() const override
        {
          return {"pressure_min", "pressure_max"};
        }

        std::vector<std::string>
        trailing_columns() const override
        {
          // One column per check, named after its slot and quantity
          // (check_2_contact_pressure), in the order of the slots.
          std::vector<std::string> columns;
          for (const auto &check : problem.checks)
            columns.push_back(check.column());
          if (parameters.contact.frictional())
            columns.emplace_back("slipping_nodes");
          return columns;
        }

        // Every check's quantity at every converged step, checked or not:
        // the history holds its whole curve, and the verdicts pick the rows
        // of the checked steps.
        void
        report(const SolutionState<dim> &state, HistoryRow &row) const override
        {
          const auto [lowest, highest] =
            ReferencePressure::pressure_extremes(state);
          row.leading = {{"pressure_min", lowest}, {"pressure_max", highest}};
          for (const auto &check : problem.checks)
            row.trailing.emplace_back(check.column(),
                                      quantities.value(check, state));
          // (Friction is refused in 3D.)
          if constexpr (dim == 2)
            if (parameters.contact.frictional())
              row.trailing.emplace_back("slipping_nodes",
                                        static_cast<double>(
                                          Friction::n_slipping(state)));
        }

        // The step's line: the active nodes and the largest pressure, then
        // every checked quantity as it goes (headed "check k", the legend
        // above the table says which is which), so that a long run shows
        // whether it is on track before its verdicts. The checks that do
        // not fit within the line's width are left out, the last first.
        std::vector<StepField>
        step_fields(const HistoryRow &row) const override
        {
          std::vector<StepField> fields = {
            {"active", format_number(row.active_nodes), 6},
            {"p_max", format_number(row.value("pressure_max")), 10}};
          for (unsigned int k = 0; k < problem.checks.size(); ++k)
            fields.push_back(
              {"check " + std::to_string(k + 1),
               format_number(row.value(problem.checks[k].column())),
               10,
               1});
          if (parameters.contact.frictional())
            fields.push_back(
              {"sliding", format_number(row.value("slipping_nodes")), 7, 2});
          return fields;
        }

        std::vector<std::string>
        step_legend() const override
        {
          std::vector<std::string> legend;
          for (unsigned int k = 0; k < problem.checks.size(); ++k)
            legend.push_back("check " + std::to_string(k + 1) + ": " +
                             problem.checks[k].description());
          return legend;
        }

        // Each check's quantity against its reference expression, evaluated
        // at the row's pseudo-time.
        std::vector<Verdict>
        evaluate_checks(const std::string             &scheme,
                        const std::vector<HistoryRow> &history) const override
        {
          std::vector<Verdict> verdicts;
          for (const auto &check : problem.checks)
            {
              // Parsed once per check; evaluated at the check's point and at
              // each checked row's pseudo-time.
              const auto reference =
                make_expression<dim>({check.reference},
                                     problem.constants,
                                     check.name + "/Reference");
              const auto check_row = [&](const HistoryRow &row) {
                Verdict v;
                v.scheme    = row.scheme;
                v.quantity  = check.description();
                v.step      = row.step;
                v.tolerance = check.tolerance;
                v.value     = row.value(check.column());
                reference->set_time(row.time);
                // An L2 error is its own error: its reference expression is
                // the pressure it was measured against.
                const bool is_error =
                  check.quantity == ProblemQuantity::contact_pressure_l2_error;
                v.reference =
                  is_error ? 0 : reference->value(check.template point<dim>());
                v.error = v.value - v.reference;
                if (check.relative && !is_error)
                  v.error /= std::abs(v.reference);
                v.relative = check.relative && !is_error;
                v.source   = check.source;
                // A reference that is no number, or a relative error against
                // a reference of 0, fails the check: it cannot pass by a
                // comparison with NaN (a reference sqrt(t - 2) once printed a
                // bare '-nan' in the verdicts). For a reference of 0 the
                // check should be absolute (Relative = false).
                v.pass =
                  std::isfinite(v.error) && std::abs(v.error) <= v.tolerance;
                verdicts.push_back(v);
              };
              // The rows of the checked steps; a step the run did not reach
              // gets a failing 'step not reached' verdict.
              for_checked_rows(check.every_step,
                               check.steps,
                               history,
                               program.n_steps(),
                               check_row,
                               scheme,
                               check.tolerance,
                               verdicts);
            }
          return verdicts;
        }

      private:
        // Per node (its displacement unknowns): the faces of a normal
        // condition at the node (normal_faces()).
        using Node        = std::array<types::global_dof_index, dim>;
        using NormalFaces = std::map<Node, std::vector<NormalFace<dim>>>;

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
        ImposedMotion<dim>
        boundary_motion(const DoFHandler<dim>            &dof_handler,
                        const hp::MappingCollection<dim> &mapping,
                        const LoadState                  &load) const override
        {
          std::map<types::global_dof_index, double> values =
            cartesian_displacements(dof_handler, mapping, load);
          const NormalFaces faces = normal_faces(dof_handler, mapping, load);

          std::vector<NormalDisplacement<dim>> normal;
          for (const auto &[node, list] : faces)
            resolve_normal_conditions<dim>(node, list, values, normal);
          return {values, normal};
        }

        // The Cartesian and polar conditions, in the order of the file,
        // interpolated at the support points of the boundary's unknowns: a
        // node on two boundaries (a corner) takes the later condition's value
        // for a component both impose.
        std::map<types::global_dof_index, double>
        cartesian_displacements(const DoFHandler<dim>            &dof_handler,
                                const hp::MappingCollection<dim> &mapping,
                                const LoadState                  &load) const
        {
          std::map<types::global_dof_index, double> values;
          for (const auto &condition : problem.boundary_conditions)
            if (condition.type == BoundaryConditionType::displacement &&
                !condition.normal)
              {
                const ImposedDisplacement<dim> motion(condition,
                                                      problem.constants,
                                                      load.time);
                // The mask selects Cartesian components: a roller in y leaves
                // u_x free. A polar condition imposes both components, which
                // is why problem_description.cc refuses u_r or u_theta alone:
                // no mask of u_x and u_y expresses it.
                std::map<types::global_dof_index, double> these;
                VectorTools::interpolate_boundary_values(
                  mapping,
                  dof_handler,
                  condition.boundary_id,
                  motion,
                  these,
                  Components::displacement_mask<dim>(condition.components[0],
                                                     condition.components[1],
                                                     condition.components[2]));
                for (const auto &[dof, value] : these)
                  values[dof] = value;
              }
          return values;
        }

        // Per node (its displacement unknowns): the outward normal and the
        // imposed value g of each face of a normal condition at the node.
        NormalFaces
        normal_faces(const DoFHandler<dim>            &dof_handler,
                     const hp::MappingCollection<dim> &mapping,
                     const LoadState                  &load) const
        {
          // The quadrature of a face is its support points, one per face
          // unknown: quadrature point i is then where face unknown i sits, and
          // the normal there is the face's outward normal at that node, in the
          // reference configuration.
          NormalFaces faces;
          const auto &fe_collection = dof_handler.get_fe_collection();
          hp::QCollection<dim - 1> support_points;
          for (unsigned int i = 0; i < fe_collection.size(); ++i)
            support_points.push_back(Quadrature<dim - 1>(
              fe_collection[i].get_unit_face_support_points(0)));
          hp::FEFaceValues<dim>                face_values(mapping,
                                            fe_collection,
                                            support_points,
                                            update_quadrature_points |
                                              update_normal_vectors);
          std::vector<types::global_dof_index> face_dofs;
          for (const auto &condition : problem.boundary_conditions)
            if (condition.type == BoundaryConditionType::displacement &&
                condition.normal)
              {
                auto expression = make_expression<dim>(condition.expressions,
                                                       problem.constants,
                                                       condition.name);
                expression->set_time(load.time);
                for (const auto &cell : dof_handler.active_cell_iterators())
                  for (const unsigned int f : cell->face_indices())
                    if (cell->face(f)->at_boundary() &&
                        cell->face(f)->boundary_id() == condition.boundary_id)
                      {
                        face_values.reinit(cell, f);
                        const FEFaceValues<dim> &fv =
                          face_values.get_present_fe_values();
                        const FiniteElement<dim> &fe = cell->get_fe();
                        face_dofs.resize(fe.n_dofs_per_face(f));
                        cell->face(f)->get_dof_indices(face_dofs,
                                                       cell->active_fe_index());
                        // The support points of the face, each with its
                        // displacement unknowns (face_nodes()). Each face adds
                        // its normal to the node's list, which
                        // boundary_motion() then averages.
                        for (const auto &[i, node] :
                             face_nodes(fe, f, fv, face_dofs))
                          {
                            const Point<dim> &X = fv.quadrature_point(i);
                            faces[node].push_back(
                              NormalFace<dim>{fv.normal_vector(i),
                                              finite_value(expression->value(X),
                                                           condition,
                                                           X,
                                                           load.time),
                                              X,
                                              &condition});
                          }
                      }
              }
          return faces;
        }

        const Parameters             parameters;
        const ProblemParameters     &problem;
        const LoadProgram            program;
        const CheckedQuantities<dim> quantities;
      };

      // The registration line: Problem/Scenario = general. Not the default
      // (the rings are): a file says that it is a general problem.
      const ScenarioRegistration::Add registration{ScenarioRegistration{
        "general",
        "general",
        "any bodies of a gmsh model (Mesh source = gmsh file), with the "
        "conditions and checks written in this file: the subsections Body "
        "1, 2, ... (Number of bodies), Boundary condition 1 to 12 and Check "
        "1 to 12, the contact pair of subsection Contact and those of Contact "
        "pair 2 to 4, the steps of Load program/Program = steps.",
        false,
        " (a general problem takes its bodies, conditions and checks from "
        "the subsections Body, Boundary condition and Check)",
        []() { return std::make_shared<ProblemParameters>(); },
        [](const Parameters &parameters) {
          return std::make_unique<GeneralProblem<2>>(parameters);
        },
        [](const Parameters &parameters) {
          return std::make_unique<GeneralProblem<3>>(parameters);
        }}};
    } // namespace
  }   // namespace General
} // namespace RingContact
