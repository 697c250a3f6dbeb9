#include <deal.II/base/numbers.h>
#include <deal.II/base/utilities.h>
#include <deal.II/lac/vector.h>

#include <ring_contact/parameter_checks.h>
#include <ring_contact/problem_description.h>
#include <ring_contact/utilities.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace RingContact
{
  using namespace ParameterChecks;

  namespace
  {
    // deal.II's FunctionParser writes muparser's message to std::cerr
    // before it throws: catch it, for the one-line error.
    class CaptureStandardError
    {
    public:
      CaptureStandardError()
          : saved(std::cerr.rdbuf(captured.rdbuf()))
      {}
      ~CaptureStandardError()
      {
        std::cerr.rdbuf(saved);
      }
      // muparser's "Message:  <...>", or what else was written.
      std::string
      message() const
      {
        const std::string text = captured.str();
        const auto        at   = text.find("Message:");
        if (at == std::string::npos)
          return text;
        const auto open  = text.find('<', at);
        const auto close = text.find('>', open);
        return open == std::string::npos || close == std::string::npos ?
                 text.substr(at) :
                 text.substr(open + 1, close - open - 1);
      }

    private:
      std::ostringstream captured;
      std::streambuf    *saved;
    };

    // The constants every expression has: pi, and those of the file.
    std::map<std::string, double>
    with_pi(const std::map<std::string, double> &constants)
    {
      auto all  = constants;
      all["pi"] = numbers::PI;
      return all;
    }

    // 'name = value, name = value' of the entry Problem/Constants.
    std::map<std::string, double>
    parse_constants(const std::string &text)
    {
      std::map<std::string, double> constants;
      for (const auto &[name, value] :
           get_assignments(text,
                           "Problem",
                           "Constants",
                           "R = 1, q = 1e6",
                           "a name (letters, digits and _, starting with a "
                           "letter)",
                           true))
        {
          require(name != "x" && name != "y" && name != "t" && name != "pi" &&
                    name != "unused",
                  "Problem",
                  "Constants",
                  "gives a value to '" + name +
                    "', which every expression already has (x, y: the point, "
                    "t: the pseudo-time, pi)");
          // A constant may use the constants before it: 'a = 0.1, P = a*a'.
          double      number = 0;
          std::string problem;
          {
            CaptureStandardError capture;
            try
              {
                FunctionParser<1> parser(1);
                parser.initialize("unused", value, with_pi(constants));
                number = parser.value(Point<1>());
              }
            catch (...)
              {
                number  = std::nan("");
                problem = capture.message();
              }
          }
          require(!value.empty() && std::isfinite(number),
                  "Problem",
                  "Constants",
                  "gives '" + name + "' the value '" + printable(value) +
                    "', which is not a number nor an expression of the "
                    "constants before it" +
                    (problem.empty() ? std::string() :
                                       " (" + printable(problem, 100) + ")"));
          constants[name] = number;
        }
      return constants;
    }

    // "x, y", "r, theta", "y" ... of a displacement condition.
    void
    parse_components(const std::string   &text,
                     const std::string   &subsection,
                     bool                &polar,
                     bool                &normal,
                     std::array<bool, 2> &components)
    {
      components       = {{false, false}};
      bool cartesian   = false;
      polar            = false;
      normal           = false;
      const auto words = Utilities::split_string_list(text);
      for (const auto &word : words)
        if (word == "n")
          {
            require(words.size() == 1,
                    subsection,
                    "Components",
                    "= " + printable(text) +
                      ": the normal component n is imposed alone (the "
                      "tangential one is then free)");
            normal     = true;
            components = {{true, true}};
            return;
          }
      for (const auto &word : words)
        {
          if (word == "x" || word == "y")
            {
              cartesian                       = true;
              components[word == "x" ? 0 : 1] = true;
            }
          else if (word == "r" || word == "theta")
            {
              polar                           = true;
              components[word == "r" ? 0 : 1] = true;
            }
          else
            require(false,
                    subsection,
                    "Components",
                    "holds '" + printable(word) +
                      "': the components are x, y (Cartesian), r, theta "
                      "(polar, about the origin), or n (normal)");
        }
      require(components[0] || components[1],
              subsection,
              "Components",
              "names no component (x, y, r, theta, or n)");
      require(!(cartesian && polar),
              subsection,
              "Components",
              "mixes Cartesian (x, y) and polar (r, theta) components");
      // u_r alone or u_theta alone is a condition on a combination of u_x
      // and u_y that changes from node to node.
      require(!polar || (components[0] && components[1]),
              subsection,
              "Components",
              "= " + printable(text) +
                ": a polar condition imposes both r and theta (a single "
                "polar component is not supported)");
    }
  } // namespace

  std::unique_ptr<FunctionParser<2>>
  make_expression(const std::vector<std::string>      &expressions,
                  const std::map<std::string, double> &constants,
                  const std::string                   &what)
  {
    auto function =
      std::make_unique<FunctionParser<2>>(expressions.size(), 0.0);
    std::string problem;
    {
      CaptureStandardError capture;
      try
        {
          function->initialize("x,y,t", expressions, with_pi(constants), true);
          Vector<double> values(expressions.size());
          function->vector_value(Point<2>(), values);
        }
      catch (...)
        {
          problem = capture.message();
          if (problem.empty())
            problem = "it cannot be evaluated";
        }
    }
    if (!problem.empty())
      {
        std::string text;
        for (const auto &e : expressions)
          text += (text.empty() ? "" : "; ") + e;
        throw std::runtime_error(what + ": the expression '" + printable(text) +
                                 "' is not a usable function of x, y, t and "
                                 "the constants of Problem/Constants (" +
                                 printable(problem, 200) + ")");
      }
    return function;
  }

  // ------------------------------------------------------------------
  // Body
  // ------------------------------------------------------------------

  void
  BodyParameters::add_parameters(Subsection &s)
  {
    s.add("Material id",
          material_id,
          "0",
          0,
          max_tag,
          "Scenario = general: the tag of the mesh's physical "
          "group (material id) that is this body.");
    s.add("Young's modulus", youngs_modulus, "1e9", "E [Pa].", positive());
    s.add("Poisson's ratio",
          poissons_ratio,
          "0.3",
          "nu [-], below 0.5.",
          {[](const double nu) { return nu > -1 && nu < 0.5; },
           "must be in (-1, 0.5)"});
    s.add("Displacement degree",
          degree,
          "1",
          1,
          4,
          "Degree of the displacement elements (1: Q1, 2: Q2, up to 4: "
          "Q4).");
    std::string names;
    for (const auto &[name, value] : kinematics_choices())
      names += "|" + name;
    s.add("Kinematics",
          "",
          Patterns::Selection(names),
          "The body's kinematics; empty: that of "
          "Materials/Kinematics. A body in small strain may "
          "touch one in finite strain: the contact is then "
          "written on the current configuration (it is "
          "geometrically linear only when both bodies are in "
          "small strain), and a pressure load on a body follows "
          "its surface when that body is in finite or "
          "logarithmic strain or neo-Hookean.",
          [this](const std::string &text) {
            inherits_kinematics = text.empty();
            kinematics          = Kinematics::finite_strain;
            for (const auto &[name, value] : kinematics_choices())
              if (name == text)
                kinematics = value;
          });
  }

  // ------------------------------------------------------------------
  // Boundary condition
  // ------------------------------------------------------------------

  void
  BoundaryConditionParameters::add_parameters(Subsection &s)
  {
    name = s.name;
    s.add("Type",
          type,
          "none",
          {{"none", BoundaryConditionType::none},
           {"displacement", BoundaryConditionType::displacement},
           {"traction", BoundaryConditionType::traction},
           {"pressure", BoundaryConditionType::pressure}},
          "Scenario = general: none (slot not used); "
          "displacement: the components of 'Components' "
          "imposed; traction: a dead load (tx; ty) per "
          "reference length [Pa]; pressure: p [Pa] on the "
          "current configuration, along the current inward "
          "normal (a follower load, with its exact tangent; a "
          "dead load in small strain). A boundary without "
          "condition is free.");
    s.add("Boundary id",
          boundary_id,
          "0",
          0,
          max_tag,
          "The mesh's boundary tag (physical group of lines).");
    s.add("Components",
          "x, y",
          Patterns::Anything(),
          "Displacement: which components are imposed: x, y, "
          "'x, y', 'r, theta' (polar about the origin: u = "
          "u_r e_r + u_theta e_theta), or n: the normal "
          "displacement u . N, N the outward unit normal of "
          "the reference boundary, the tangential displacement "
          "free (a roller on an inclined or a curved boundary; "
          "at a node the normals of the faces are averaged, "
          "where they are more than 60 degrees apart (a corner) "
          "both directions are imposed, and where a Cartesian "
          "or polar condition imposes a component the normal "
          "condition sets the other).",
          [this](const std::string &text) {
            parse_components(text, name, polar, normal, components);
          });
    s.add("Value",
          "0; 0",
          Patterns::Anything(),
          "Expressions of x, y (reference position [m]), t "
          "(pseudo-time) and the constants, separated by ';': "
          "displacement: two, in the order x; y or r; theta "
          "(a component not imposed is not used), or one, u . N, "
          "for Components = n [m]; traction: "
          "tx; ty [Pa]; pressure: p [Pa]. A value that is not "
          "a finite number where and when it is used (an "
          "imposed displacement at t = 0 too) stops the load "
          "step, the condition, point and time named.",
          [this](const std::string &text) {
            expressions = Utilities::split_string_list(text, ';');
          });
  }

  void
  BoundaryConditionParameters::finish(
    const std::map<std::string, double> &constants) const
  {
    const unsigned int expected =
      type == BoundaryConditionType::pressure || normal ? 1 : 2;
    require(expressions.size() == expected,
            name,
            "Value",
            "holds " + std::to_string(expressions.size()) +
              " expression(s) separated by ';', a " +
              (normal ? std::string("normal displacement") :
               type == BoundaryConditionType::displacement ?
                        std::string("displacement") :
               type == BoundaryConditionType::traction ?
                        std::string("traction") :
                        std::string("pressure")) +
              " needs " + std::to_string(expected));
    try
      {
        make_expression(expressions, constants, "the value");
      }
    catch (const std::exception &e)
      {
        require(false, name, "Value", e.what());
      }
  }

  // ------------------------------------------------------------------
  // Check
  // ------------------------------------------------------------------

  std::string
  ProblemCheckParameters::description() const
  {
    std::ostringstream out;
    out << std::setprecision(6);
    const auto at = [&]() {
      std::ostringstream where;
      where << std::setprecision(6) << " at (" << point[0] << ", " << point[1]
            << ")";
      return where.str();
    };
    switch (quantity)
      {
        case ProblemQuantity::contact_pressure:
          return "pressure" + at();
        case ProblemQuantity::tangential_traction:
          return "tangential traction" + at();
        case ProblemQuantity::contact_half_width:
          return "contact half-width";
        case ProblemQuantity::resultant_force_x:
          return "force x on " + std::to_string(boundary_id);
        case ProblemQuantity::resultant_force_y:
          return "force y on " + std::to_string(boundary_id);
        case ProblemQuantity::displacement_x:
          return "ux" + at();
        case ProblemQuantity::displacement_y:
          return "uy" + at();
        case ProblemQuantity::none:
          break;
      }
    return "";
  }

  std::string
  ProblemCheckParameters::column() const
  {
    // "Check 2" -> "check_2_"
    std::string prefix = name;
    for (char &c : prefix)
      c = c == ' ' ?
            '_' :
            static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    switch (quantity)
      {
        case ProblemQuantity::contact_pressure:
          return prefix + "_contact_pressure";
        case ProblemQuantity::tangential_traction:
          return prefix + "_tangential_traction";
        case ProblemQuantity::contact_half_width:
          return prefix + "_contact_half_width";
        case ProblemQuantity::resultant_force_x:
          return prefix + "_force_x";
        case ProblemQuantity::resultant_force_y:
          return prefix + "_force_y";
        case ProblemQuantity::displacement_x:
          return prefix + "_ux";
        case ProblemQuantity::displacement_y:
          return prefix + "_uy";
        case ProblemQuantity::none:
          break;
      }
    return prefix;
  }

  void
  ProblemCheckParameters::add_parameters(Subsection &s)
  {
    name = s.name;
    s.add("Quantity",
          quantity,
          "none",
          {{"none", ProblemQuantity::none},
           {"contact pressure", ProblemQuantity::contact_pressure},
           {"tangential traction", ProblemQuantity::tangential_traction},
           {"contact half-width", ProblemQuantity::contact_half_width},
           {"resultant force x", ProblemQuantity::resultant_force_x},
           {"resultant force y", ProblemQuantity::resultant_force_y},
           {"displacement x", ProblemQuantity::displacement_x},
           {"displacement y", ProblemQuantity::displacement_y}},
          "Scenario = general: none (slot not used); contact pressure at the "
          "slave node nearest to 'Point' (as Contact/Reported pressure) [Pa]; "
          "tangential traction there (friction: Cauchy, on the tangent e_z x n "
          "of the master's outward normal n; it has the sign of the slave's "
          "slip) [Pa]; "
          "contact half-width: the largest distance from 'Point' to which the "
          "slave surface is in contact, to half a segment (midway between the "
          "last node with positive pressure and the next open one) [m]; "
          "resultant force x or y: the sum of the nodal forces on 'Boundary "
          "id' (the reaction of an imposed displacement, or the resultant of "
          "a load) [N per unit thickness]; displacement x or y at 'Point' "
          "(reference position) [m].");
    s.add("Point",
          "0, 0",
          Patterns::Anything(),
          "x, y [m]: where a pressure or displacement is taken, "
          "from where a contact width is measured.",
          [this](const std::string &text) {
            const auto xy = point_from_text(text, name, "Point");
            point         = Point<2>(xy[0], xy[1]);
          });
    s.add("Boundary id",
          boundary_id,
          "0",
          0,
          max_tag,
          "The boundary of a resultant force.");
    s.add("Reference",
          reference,
          "0",
          "The expected value: an expression of t (the step's "
          "pseudo-time), x, y (the point) and the constants.");
    s.add("Relative",
          relative,
          "true",
          "true: the error is (value - reference) / |reference|; "
          "false: value - reference.");
    s.add("Tolerance",
          tolerance,
          "0.01",
          "Largest admitted |error|.",
          not_negative());
    s.add("Reference source",
          "",
          Patterns::Selection("|closed form|Code_Aster|publication|"
                              "other code"),
          "Where the reference comes from, shown in the verdict table "
          "(empty: not said).",
          [this](const std::string &text) { source = text; });
    s.add("Steps",
          "last",
          Patterns::Anything(),
          "'all', 'last', 'none', or a comma-separated list of "
          "step numbers (1-based).",
          [this](const std::string &text) {
            steps_from_text(text, name, "Steps", every_step, steps);
          });
  }

  void
  ProblemCheckParameters::finish(
    const std::map<std::string, double> &constants) const
  {
    try
      {
        make_expression({reference}, constants, "the reference");
      }
    catch (const std::exception &e)
      {
        require(false, name, "Reference", e.what());
      }
  }

  // ------------------------------------------------------------------
  // All of the problem description
  // ------------------------------------------------------------------

  void
  ProblemParameters::add_parameters(ParameterHandler &prm)
  {
    {
      Subsection s(prm, "Problem");
      s.add("Scenario",
            scenario,
            "SSNP152",
            {{"SSNP152", ScenarioType::ssnp152},
             {"general", ScenarioType::general}},
            "SSNP152: the two rings (or, with Mesh/Mesh source = patch test, "
            "the patch test), loaded and checked through their analytic "
            "solutions (subsections Mesh, Materials, Finite elements, Load "
            "program, Checks); general: the bodies of a gmsh mesh "
            "(Mesh/Mesh source = gmsh file), described by the subsections Body "
            "1, 2, ... (Number of bodies), Boundary condition 1 to " +
              std::to_string(max_boundary_conditions) + " and Check 1 to " +
              std::to_string(max_checks) +
              ", with the contact pair of subsection Contact (and the pairs of "
              "subsections Contact pair 2 to " +
              std::to_string(max_contact_pairs) +
              ") and the steps of Load program/Program = steps.");
      s.add("Number of bodies",
            number_of_bodies,
            "2",
            2,
            max_bodies,
            "Scenario = general: the bodies, subsections Body 1 "
            "to " +
              std::to_string(max_bodies) + ".");
      s.add("Number of contact pairs",
            number_of_contact_pairs,
            "1",
            1,
            max_contact_pairs,
            "Scenario = general: the contact pairs: the first is subsection "
            "Contact (its slave and master boundaries, and the integration "
            "schemes, normals and constants every pair uses), the others "
            "the subsections Contact pair 2, 3, ... with their slave and "
            "master boundaries. The slave surfaces of two pairs share no "
            "node.");
      s.add("Constants",
            "",
            Patterns::Anything(),
            "Named constants for every expression: 'name = "
            "value' pairs separated by commas, each value a "
            "number or an expression of the constants before "
            "it, e.g. 'R = 1, E = 2e11, q = 1e6'.",
            [this](const std::string &text) {
              constants = parse_constants(text);
            });
    }
    // Every slot is declared and bound; finish() keeps those in use.
    bodies.assign(max_bodies, BodyParameters());
    for (unsigned int b = 0; b < max_bodies; ++b)
      {
        Subsection s(prm, "Body " + std::to_string(b + 1));
        bodies[b].add_parameters(s);
      }
    more_contact_pairs.assign(max_contact_pairs - 1, {0, 0});
    for (unsigned int k = 2; k <= max_contact_pairs; ++k)
      {
        Subsection s(prm, "Contact pair " + std::to_string(k));
        s.add("Slave boundary",
              more_contact_pairs[k - 2].first,
              "0",
              0,
              max_tag,
              "Scenario = general: the boundary tag of this "
              "pair's slave surface (it carries the contact "
              "pressure).");
        s.add("Master boundary",
              more_contact_pairs[k - 2].second,
              "0",
              0,
              max_tag,
              "The boundary tag of this pair's master surface.");
      }
    boundary_conditions.assign(max_boundary_conditions,
                               BoundaryConditionParameters());
    for (unsigned int k = 0; k < max_boundary_conditions; ++k)
      {
        Subsection s(prm, "Boundary condition " + std::to_string(k + 1));
        boundary_conditions[k].add_parameters(s);
      }
    checks.assign(max_checks, ProblemCheckParameters());
    for (unsigned int k = 0; k < max_checks; ++k)
      {
        Subsection s(prm, "Check " + std::to_string(k + 1));
        checks[k].add_parameters(s);
      }
  }

  void
  ProblemParameters::finish()
  {
    bodies.resize(number_of_bodies);
    more_contact_pairs.resize(number_of_contact_pairs - 1);
    for (unsigned int k = 0; k < more_contact_pairs.size(); ++k)
      require(more_contact_pairs[k].first != more_contact_pairs[k].second,
              "Contact pair " + std::to_string(k + 2),
              "Slave boundary",
              "must differ from 'Master boundary' (both are " +
                std::to_string(more_contact_pairs[k].first) + ")");
    boundary_conditions.erase(
      std::remove_if(boundary_conditions.begin(),
                     boundary_conditions.end(),
                     [](const BoundaryConditionParameters &condition) {
                       return condition.type == BoundaryConditionType::none;
                     }),
      boundary_conditions.end());
    checks.erase(std::remove_if(checks.begin(),
                                checks.end(),
                                [](const ProblemCheckParameters &check) {
                                  return check.quantity ==
                                         ProblemQuantity::none;
                                }),
                 checks.end());
    for (const auto &condition : boundary_conditions)
      condition.finish(constants);
    for (const auto &check : checks)
      check.finish(constants);
  }
} // namespace RingContact
