#include <deal.II/base/numbers.h>
#include <deal.II/base/utilities.h>
#include <deal.II/lac/vector.h>

#include <ring_contact/parameter_checks.h>
#include <ring_contact/problem_description.h>
#include <ring_contact/utilities.h>

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
  BodyParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Material id",
                      "0",
                      Patterns::Integer(0),
                      "Scenario = general: the tag of the mesh's physical "
                      "group (material id) that is this body.");
    prm.declare_entry("Young's modulus", "1e9", Patterns::Double(), "E [Pa].");
    prm.declare_entry("Poisson's ratio",
                      "0.3",
                      Patterns::Double(),
                      "nu [-], below 0.5.");
    prm.declare_entry("Displacement degree",
                      "1",
                      Patterns::Integer(1, 4),
                      "Degree of the displacement elements (1: Q1, 2: Q2).");
    prm.declare_entry("Kinematics",
                      "",
                      Patterns::Selection(std::string("|") + kinematics_names),
                      "The body's kinematics; empty: that of "
                      "Materials/Kinematics. A body in small strain may "
                      "touch one in finite strain: the contact is then "
                      "written on the current configuration (it is "
                      "geometrically linear only when both bodies are in "
                      "small strain), and a pressure load on a body follows "
                      "its surface when that body is in finite or "
                      "logarithmic strain or neo-Hookean.");
  }

  void
  BodyParameters::parse_parameters(ParameterHandler  &prm,
                                   const std::string &subsection)
  {
    material_id = get_count(
      prm, subsection, "Material id", 0, numbers::invalid_material_id - 1);
    youngs_modulus = get_double(prm, subsection, "Young's modulus");
    require(youngs_modulus > 0,
            subsection,
            "Young's modulus",
            "must be positive, got " + to_text(youngs_modulus));
    poissons_ratio = get_double(prm, subsection, "Poisson's ratio");
    require(poissons_ratio > -1 && poissons_ratio < 0.5,
            subsection,
            "Poisson's ratio",
            "must be in (-1, 0.5), got " + to_text(poissons_ratio));
    degree = get_count(prm, subsection, "Displacement degree", 1, 4);
    const std::string kind = prm.get("Kinematics");
    inherits_kinematics    = kind.empty();
    kinematics             = kinematics_from_name(kind);
  }

  // ------------------------------------------------------------------
  // Boundary condition
  // ------------------------------------------------------------------

  void
  BoundaryConditionParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Type",
                      "none",
                      Patterns::Selection(
                        "none|displacement|traction|pressure"),
                      "Scenario = general: none (slot not used); "
                      "displacement: the components of 'Components' "
                      "imposed; traction: a dead load (tx; ty) per "
                      "reference length [Pa]; pressure: p [Pa] on the "
                      "current configuration, along the current inward "
                      "normal (a follower load, with its exact tangent; a "
                      "dead load in small strain). A boundary without "
                      "condition is free.");
    prm.declare_entry("Boundary id",
                      "0",
                      Patterns::Integer(0),
                      "The mesh's boundary tag (physical group of lines).");
    prm.declare_entry("Components",
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
                      "condition sets the other).");
    prm.declare_entry("Value",
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
                      "step, the condition, point and time named.");
  }

  void
  BoundaryConditionParameters::parse_parameters(
    ParameterHandler                    &prm,
    const std::string                   &subsection,
    const std::map<std::string, double> &constants)
  {
    name                   = subsection;
    const std::string kind = prm.get("Type");
    type                   = kind == "none" ? BoundaryConditionType::none :
                             kind == "displacement" ? BoundaryConditionType::displacement :
                             kind == "traction" ? BoundaryConditionType::traction :
                                                  BoundaryConditionType::pressure;
    boundary_id = get_count(prm, subsection, "Boundary id", 0, 1000000000);
    if (type == BoundaryConditionType::none)
      return;
    if (type == BoundaryConditionType::displacement)
      parse_components(
        prm.get("Components"), subsection, polar, normal, components);
    expressions = Utilities::split_string_list(prm.get("Value"), ';');
    const unsigned int expected =
      type == BoundaryConditionType::pressure || normal ? 1 : 2;
    require(expressions.size() == expected,
            subsection,
            "Value",
            "holds " + std::to_string(expressions.size()) +
              " expression(s) separated by ';', a " +
              (normal ? std::string("normal displacement") : kind) + " needs " +
              std::to_string(expected));
    try
      {
        make_expression(expressions, constants, "the value");
      }
    catch (const std::exception &e)
      {
        require(false, subsection, "Value", e.what());
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
  ProblemCheckParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry(
      "Quantity",
      "none",
      Patterns::Selection("none|contact pressure|tangential traction|"
                          "contact half-width|"
                          "resultant force x|resultant force y|"
                          "displacement x|displacement y"),
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
    prm.declare_entry("Point",
                      "0, 0",
                      Patterns::Anything(),
                      "x, y [m]: where a pressure or displacement is taken, "
                      "from where a contact width is measured.");
    prm.declare_entry("Boundary id",
                      "0",
                      Patterns::Integer(0),
                      "The boundary of a resultant force.");
    prm.declare_entry("Reference",
                      "0",
                      Patterns::Anything(),
                      "The expected value: an expression of t (the step's "
                      "pseudo-time), x, y (the point) and the constants.");
    prm.declare_entry("Relative",
                      "true",
                      Patterns::Bool(),
                      "true: the error is (value - reference) / |reference|; "
                      "false: value - reference.");
    prm.declare_entry("Tolerance",
                      "0.01",
                      Patterns::Double(0),
                      "Largest admitted |error|.");
    prm.declare_entry("Steps",
                      "last",
                      Patterns::Anything(),
                      "'all', 'last', 'none', or a comma-separated list of "
                      "step numbers (1-based).");
  }

  void
  ProblemCheckParameters::parse_parameters(
    ParameterHandler                    &prm,
    const std::string                   &subsection,
    const std::map<std::string, double> &constants)
  {
    name                   = subsection;
    const std::string what = prm.get("Quantity");
    quantity =
      what == "none"                ? ProblemQuantity::none :
      what == "contact pressure"    ? ProblemQuantity::contact_pressure :
      what == "tangential traction" ? ProblemQuantity::tangential_traction :
      what == "contact half-width"  ? ProblemQuantity::contact_half_width :
      what == "resultant force x"   ? ProblemQuantity::resultant_force_x :
      what == "resultant force y"   ? ProblemQuantity::resultant_force_y :
      what == "displacement x"      ? ProblemQuantity::displacement_x :
                                      ProblemQuantity::displacement_y;
    if (quantity == ProblemQuantity::none)
      return;
    const auto xy = get_point(prm, subsection, "Point");
    point         = Point<2>(xy[0], xy[1]);
    boundary_id   = get_count(prm, subsection, "Boundary id", 0, 1000000000);
    reference     = prm.get("Reference");
    try
      {
        make_expression({reference}, constants, "the reference");
      }
    catch (const std::exception &e)
      {
        require(false, subsection, "Reference", e.what());
      }
    relative  = prm.get_bool("Relative");
    tolerance = get_double(prm, subsection, "Tolerance");
    get_steps(prm, subsection, "Steps", every_step, steps);
  }

  // ------------------------------------------------------------------
  // All of the problem description
  // ------------------------------------------------------------------

  void
  ProblemParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Problem");
    {
      prm.declare_entry(
        "Scenario",
        "SSNP152",
        Patterns::Selection("SSNP152|general"),
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
      prm.declare_entry("Number of bodies",
                        "2",
                        Patterns::Integer(2, max_bodies),
                        "Scenario = general: the bodies, subsections Body 1 "
                        "to " +
                          std::to_string(max_bodies) + ".");
      prm.declare_entry(
        "Number of contact pairs",
        "1",
        Patterns::Integer(1, max_contact_pairs),
        "Scenario = general: the contact pairs: the first is subsection "
        "Contact (its slave and master boundaries, and the integration "
        "schemes, normals and constants every pair uses), the others "
        "the subsections Contact pair 2, 3, ... with their slave and "
        "master boundaries. The slave surfaces of two pairs share no "
        "node.");
      prm.declare_entry("Constants",
                        "",
                        Patterns::Anything(),
                        "Named constants for every expression: 'name = "
                        "value' pairs separated by commas, each value a "
                        "number or an expression of the constants before "
                        "it, e.g. 'R = 1, E = 2e11, q = 1e6'.");
    }
    prm.leave_subsection();
    for (unsigned int b = 1; b <= max_bodies; ++b)
      {
        prm.enter_subsection("Body " + std::to_string(b));
        BodyParameters::declare_parameters(prm);
        prm.leave_subsection();
      }
    for (unsigned int k = 2; k <= max_contact_pairs; ++k)
      {
        prm.enter_subsection("Contact pair " + std::to_string(k));
        prm.declare_entry("Slave boundary",
                          "0",
                          Patterns::Integer(0),
                          "Scenario = general: the boundary tag of this "
                          "pair's slave surface (it carries the contact "
                          "pressure).");
        prm.declare_entry("Master boundary",
                          "0",
                          Patterns::Integer(0),
                          "The boundary tag of this pair's master surface.");
        prm.leave_subsection();
      }
    for (unsigned int k = 1; k <= max_boundary_conditions; ++k)
      {
        prm.enter_subsection("Boundary condition " + std::to_string(k));
        BoundaryConditionParameters::declare_parameters(prm);
        prm.leave_subsection();
      }
    for (unsigned int k = 1; k <= max_checks; ++k)
      {
        prm.enter_subsection("Check " + std::to_string(k));
        ProblemCheckParameters::declare_parameters(prm);
        prm.leave_subsection();
      }
  }

  void
  ProblemParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Problem");
    scenario  = prm.get("Scenario") == "general" ? ScenarioType::general :
                                                   ScenarioType::ssnp152;
    constants = parse_constants(prm.get("Constants"));
    const unsigned int n_bodies =
      get_count(prm, "Problem", "Number of bodies", 2, max_bodies);
    const unsigned int n_pairs = get_count(
      prm, "Problem", "Number of contact pairs", 1, max_contact_pairs);
    prm.leave_subsection();

    bodies.resize(n_bodies);
    for (unsigned int b = 0; b < n_bodies; ++b)
      {
        const std::string subsection = "Body " + std::to_string(b + 1);
        prm.enter_subsection(subsection);
        bodies[b].parse_parameters(prm, subsection);
        prm.leave_subsection();
      }
    more_contact_pairs.clear();
    for (unsigned int k = 2; k <= n_pairs; ++k)
      {
        const std::string subsection = "Contact pair " + std::to_string(k);
        prm.enter_subsection(subsection);
        const unsigned int slave =
          get_count(prm, subsection, "Slave boundary", 0, 1000000000);
        const unsigned int master =
          get_count(prm, subsection, "Master boundary", 0, 1000000000);
        prm.leave_subsection();
        require(slave != master,
                subsection,
                "Slave boundary",
                "must differ from 'Master boundary' (both are " +
                  std::to_string(slave) + ")");
        more_contact_pairs.emplace_back(slave, master);
      }
    boundary_conditions.clear();
    for (unsigned int k = 1; k <= max_boundary_conditions; ++k)
      {
        const std::string subsection =
          "Boundary condition " + std::to_string(k);
        prm.enter_subsection(subsection);
        BoundaryConditionParameters condition;
        condition.parse_parameters(prm, subsection, constants);
        prm.leave_subsection();
        if (condition.type != BoundaryConditionType::none)
          boundary_conditions.push_back(condition);
      }
    checks.clear();
    for (unsigned int k = 1; k <= max_checks; ++k)
      {
        const std::string subsection = "Check " + std::to_string(k);
        prm.enter_subsection(subsection);
        ProblemCheckParameters check;
        check.parse_parameters(prm, subsection, constants);
        prm.leave_subsection();
        if (check.quantity != ProblemQuantity::none)
          checks.push_back(check);
      }
  }
} // namespace RingContact
