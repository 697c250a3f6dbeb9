// @sect3{A problem written in the parameter file}
//
// `Problem/Scenario = general` poses a contact problem without a line of
// C++: the bodies are physical groups of a gmsh mesh, the boundary
// conditions and the checks are expressions of x, y (and z in 3D) and the
// pseudo-time t (deal.II's FunctionParser, muparser's syntax) with the
// file's named constants. This file reads that description: it declares the
// entries, parses and evaluates each expression once when the file is read, and
// checks everything that can be checked without the mesh, each refusal a
// ParameterError that names its entry (and so, through the reader, its
// file and line). What needs the mesh (boundary tags that exist, a load
// along a held direction, a check's point near the slave surface) is
// checked by the scenario itself (mesh_checks.cc, general.cc,
// quantities.cc), before the first step.
//
// deal.II's ParameterHandler has no lists of subsections, so the bodies,
// pairs, conditions and checks are fixed numbered slots (Body 1-4, Contact
// pair 2-4, Boundary condition 1-12, Check 1-12), each declared and bound
// to its member; a slot is unused until its Type or Quantity says
// otherwise, and finish() keeps only the slots in use.
#include <deal.II/base/numbers.h>
#include <deal.II/base/utilities.h>
#include <deal.II/lac/vector.h>

#include <ring_contact/base/dimension.h>
#include <ring_contact/base/utilities.h>
#include <ring_contact/input/parameter_checks.h>
#include <ring_contact/materials/material.h>
#include <ring_contact/scenarios/general/problem_description.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <tuple>

namespace RingContact
{
  using namespace ParameterChecks;

  namespace
  {
    // deal.II's FunctionParser writes muparser's message to std::cerr
    // before it throws: catch it, for the one-line error. The reason (an
    // unknown name, a missing bracket) is then one line, without the text
    // of deal.II's exception around it, and nothing reaches the terminal
    // twice. The stream is given back by the destructor, so that an
    // exception cannot leave std::cerr captured.
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
      // muparser's "Message:  <...>", or what else was written (a failure
      // that is not muparser's has no such line).
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

    // The constants every expression has: pi, and those of the file. (A
    // constant of the file named pi is refused in parse_constants().)
    std::map<std::string, double>
    with_pi(const std::map<std::string, double> &constants)
    {
      auto all  = constants;
      all["pi"] = numbers::PI;
      return all;
    }


    // "x, y", "r, theta", "y", "all" ... of a displacement condition.
    // Called by the entry's action, so that a wrong list is refused at its
    // own line (z in a 2D model is refused in finish(), when the model's
    // dimension is known). The normal component n comes alone: it fixes
    // the direction of the condition at every node (the boundary's
    // normal), and every unknown of a node takes part in it (components =
    // all). In 3D, r and theta are cylindrical about the z axis, and z may
    // join them.
    void
    parse_components(const std::string   &text,
                     const std::string   &subsection,
                     bool                &polar,
                     bool                &normal,
                     std::array<bool, 3> &components,
                     bool                &names_z)
    {
      components     = {{false, false, false}};
      names_z        = false;
      bool cartesian = false;
      polar          = false;
      normal         = false;
      // n first, whatever its place in the list: "x, n" is refused as a
      // mix, not read as x.
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
            components = {{true, true, true}};
            return;
          }
      for (const auto &word : words)
        {
          if (word == "all")
            {
              cartesian  = true;
              components = {{true, true, true}};
            }
          else if (word == "z")
            components[2] = names_z = true;
          else if (word == "x" || word == "y")
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
                      "': the components are x, y, z (Cartesian), all, r, "
                      "theta (polar, about the origin or the z axis), or n "
                      "(normal)");
        }
      require(components[0] || components[1] || components[2],
              subsection,
              "Components",
              "names no component (x, y, z, all, r, theta, or n)");
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

  // 'name = value, name = value' of the entry Problem/Constants. The
  // items are split at the commas outside parentheses (get_assignments()),
  // so that a value may be min(a, b) or atan2(y, x).
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
        // x, y and t are the variables of every expression, pi its
        // constant, and 'unused' the variable of the parser below that
        // evaluates a constant: a constant of that name would shadow it.
        // (z, the third variable in 3D, is refused there by
        // ProblemParameters::finish(), once the model's dimension is known.)
        require(name != "x" && name != "y" && name != "t" && name != "pi" &&
                  name != "unused",
                "Problem",
                "Constants",
                "gives a value to '" + name +
                  "', which every expression already has (x, y: the point, "
                  "t: the pseudo-time, pi)");
        // A constant may use the constants before it: 'a = 0.1, P = a*a'.
        // It is evaluated here, once, to a number: every expression then
        // sees a value, not a formula.
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
        // A constant that is not a finite number (1/0, sqrt(-1)) would
        // make every expression that uses it one too.
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

  // @sect4{Expressions}
  //
  // Every expression of the file goes through here: a condition's value, a
  // check's reference. It is made into a FunctionParser of (x, y[, z]; t) with
  // the constants, and evaluated once at the origin and t = 0, so that an
  // expression that does not parse or cannot be evaluated is refused while
  // the file is read, with muparser's reason, rather than at the first load
  // step. Its value there is not judged: sqrt(x - 2) is not a number at the
  // origin but may be on its boundary; whether a value is finite is checked
  // where and when it is used (a BoundaryDataError that names the
  // condition, the point and the time).
  template <int spacedim>
  std::unique_ptr<FunctionParser<spacedim>>
  make_expression(const std::vector<std::string>      &expressions,
                  const std::map<std::string, double> &constants,
                  const std::string                   &what)
  {
    // One component per expression; t is the parser's time, set by the
    // scenario to each load state's pseudo-time before it evaluates. The
    // variables are the reference coordinates: a condition is written on
    // the undeformed mesh, whatever the body's motion.
    auto function =
      std::make_unique<FunctionParser<spacedim>>(expressions.size(), 0.0);
    const std::string variables = spacedim == 2 ? "x,y" : "x,y,z";
    const std::string named     = spacedim == 2 ? "x, y" : "x, y, z";
    std::string       problem;
    {
      CaptureStandardError capture;
      try
        {
          function->initialize(variables + ",t",
                               expressions,
                               with_pi(constants),
                               true);
          Vector<double> values(expressions.size());
          function->vector_value(Point<spacedim>(), values);
        }
      catch (...)
        {
          problem = capture.message();
          if (problem.empty())
            problem = "it cannot be evaluated";
        }
    }
    // The expression quoted as the file wrote it, its components joined by
    // '; ' again, and muparser's reason after it.
    if (!problem.empty())
      {
        std::string text;
        for (const auto &e : expressions)
          text += (text.empty() ? "" : "; ") + e;
        throw std::runtime_error(what + ": the expression '" + printable(text) +
                                 "' is not a usable function of " + named +
                                 ", t and "
                                 "the constants of Problem/Constants (" +
                                 printable(problem, 200) + ")");
      }
    return function;
  }

  template std::unique_ptr<FunctionParser<2>>
  make_expression<2>(const std::vector<std::string> &,
                     const std::map<std::string, double> &,
                     const std::string &);
  template std::unique_ptr<FunctionParser<3>>
  make_expression<3>(const std::vector<std::string> &,
                     const std::map<std::string, double> &,
                     const std::string &);

  // @sect4{Bodies}
  //
  // A body is a physical group of the mesh (its material id) with its own
  // constants, displacement degree and, optionally, material law. The
  // degree goes up to 4: the contact element has quartic surfaces in every
  // integration scheme. Poisson's ratio is bounded as for the rings: in
  // (-1, 0.5) the elastic energy is positive definite.
  void
  BodyParameters::add_parameters(Subsection &s)
  {
    // Up to max_tag, the bound of gmsh_file.cc on physical tags: deal.II
    // keeps the largest ids for itself. The default 0 is refused for a
    // second body (two bodies of one group), so a body whose subsection
    // the file forgot is said, not run with default constants.
    s.add("Material id",
          material_id,
          "0",
          0,
          max_tag,
          "Scenario = general: the tag of the mesh's physical "
          "group (material id) that is this body.");
    // Only its sign is checked: the convergence test is scale-free, and
    // E = 1e6 runs as well as E = 1e12.
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
    // The registered laws, and the empty string first: a body that does
    // not say takes the common law, so that a file written for one law
    // needs no entry per body.
    s.add("Material law",
          law,
          "",
          "The body's material law; empty: that of Materials/Material law. "
          "A body in small strain (linear elasticity) may touch one in "
          "finite strain: the contact is then written on the current "
          "configuration (it is geometrically linear only when both bodies "
          "are in small strain), and a pressure load on a body follows its "
          "surface unless that body is in small strain.",
          Patterns::Selection("|" + MaterialLaws::selection()));
    // The entry's name until version 0.11, still read (ProblemParameters::
    // finish()).
    s.add("Kinematics",
          old_kinematics,
          "",
          "The old name of Material law, still read (with a note).",
          Patterns::Selection("|" + MaterialLaws::selection()));
  }

  // @sect4{Boundary conditions}
  //
  // One condition per slot, on one boundary tag: an imposed displacement
  // (Cartesian, polar about the origin, or along the normal only), a dead
  // traction, or a pressure that follows the surface. A boundary without a
  // condition is free. The slot's name ("Boundary condition 3") is kept
  // for the messages: the scenario reports a value that is not a number at
  // a load step by it, long after the file was read.
  void
  BoundaryConditionParameters::add_parameters(Subsection &s)
  {
    name = s.name;
    // The types reach the problem differently: a displacement is
    // interpolated at the support points of the boundary's unknowns and
    // imposed through the constraints; a traction or a pressure is
    // integrated over the faces, at the reference positions of their
    // quadrature points.
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
    // Whether the tag exists in the mesh is checked once the mesh is read
    // (mesh_checks.cc): here the mesh is not known yet.
    s.add("Boundary id",
          boundary_id,
          "0",
          0,
          max_tag,
          "The mesh's boundary tag (physical group of lines).");
    // Read by its own parser (parse_components()), not by a pattern: the
    // message then says which components exist and which combinations
    // are allowed.
    s.add("Components",
          "all",
          Patterns::Anything(),
          "Displacement: which components are imposed: all (x, y "
          "and in 3D z), or a list of x, y, z, "
          "or 'r, theta' (polar about the origin, in 3D about the z "
          "axis, with z or not: u = "
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
            parse_components(text, name, polar, normal, components, names_z);
          });
    s.add("Value",
          "0; 0",
          Patterns::Anything(),
          "Expressions of x, y, z (reference position [m]; z in 3D "
          "only), t (pseudo-time) and the constants, separated by ';': "
          "displacement: one per dimension, in the order x; y (; z) or "
          "r; theta (; z) "
          "(a component not imposed is not used), or one, u . N, "
          "for Components = n [m]; traction: "
          "tx; ty (; tz) [Pa]; pressure: p [Pa]. A value that is not "
          "a finite number where and when it is used (an "
          "imposed displacement at t = 0 too) stops the load "
          "step, the condition, point and time named.",
          // Only split here: the constants the expressions use may be set
          // later in the file, so they are parsed in finish().
          [this](const std::string &text) {
            expressions = Utilities::split_string_list(text, ';');
          });
  }

  // Once the whole file is read: as many expressions as the condition has
  // components (a displacement one per dimension even when fewer are
  // imposed: the order x; y; z is then unambiguous), and each usable with
  // the constants. An error of make_expression() becomes a ParameterError
  // of the entry Value, which the reader locates at its line.
  void
  BoundaryConditionParameters::finish(
    const std::map<std::string, double> &constants,
    const unsigned int                   dimension) const
  {
    require(dimension == 3 || !names_z,
            name,
            "Components",
            "names z, but the model is two-dimensional (x, y)");
    const unsigned int expected =
      type == BoundaryConditionType::pressure || normal ? 1 : dimension;
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
        if (dimension == 3)
          make_expression<3>(expressions, constants, "the value");
        else
          make_expression<2>(expressions, constants, "the value");
      }
    catch (const std::exception &e)
      {
        require(false, name, "Value", e.what());
      }
  }

  // @sect4{Checks}
  //
  // A check compares a computed quantity with a reference expression at
  // chosen steps; its verdict goes to the table after the run and to
  // verdicts.csv. What the quantities are and how they are computed is in
  // quantities.cc and boundary_resultants.cc.

  // "(0, 0.5)" or "(0, 0.5, 1)". Six digits name a point well enough to
  // find it.
  std::string
  ProblemCheckParameters::point_text() const
  {
    std::ostringstream where;
    where << std::setprecision(6) << "(";
    for (unsigned int d = 0; d < coordinates.size(); ++d)
      where << (d > 0 ? ", " : "") << coordinates[d];
    return where.str() + ")";
  }

  // The quantity in words, for the verdict table: "pressure at (0, 0)",
  // "force y on 3".
  std::string
  ProblemCheckParameters::description() const
  {
    const auto at = [&]() { return " at " + point_text(); };
    switch (quantity)
      {
        case ProblemQuantity::contact_pressure:
          return "pressure" + at();
        case ProblemQuantity::tangential_traction:
          return "tangential traction" + at();
        case ProblemQuantity::contact_half_width:
          return "contact half-width";
        case ProblemQuantity::minimum_contact_pressure:
          return "minimum pressure";
        case ProblemQuantity::maximum_contact_pressure:
          return "maximum pressure";
        case ProblemQuantity::mean_contact_pressure:
          return "mean pressure";
        case ProblemQuantity::contact_pressure_l2_error:
          return "pressure L2 error";
        case ProblemQuantity::resultant_force_x:
          return "force x on " + std::to_string(boundary_id);
        case ProblemQuantity::resultant_force_y:
          return "force y on " + std::to_string(boundary_id);
        case ProblemQuantity::resultant_force_z:
          return "force z on " + std::to_string(boundary_id);
        case ProblemQuantity::resultant_moment_x:
          return "moment x on " + std::to_string(boundary_id) + " about " +
                 point_text();
        case ProblemQuantity::resultant_moment_y:
          return "moment y on " + std::to_string(boundary_id) + " about " +
                 point_text();
        case ProblemQuantity::resultant_moment_z:
          return "moment z on " + std::to_string(boundary_id) + " about " +
                 point_text();
        case ProblemQuantity::displacement_x:
          return "ux" + at();
        case ProblemQuantity::displacement_y:
          return "uy" + at();
        case ProblemQuantity::displacement_z:
          return "uz" + at();
        case ProblemQuantity::none:
          break;
      }
    return "";
  }

  // The column of history.csv: the slot's name first, so that two checks
  // of the same quantity (the pressure at two points) have two columns,
  // then the quantity, in the lower case and underscores of the other
  // columns.
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
        case ProblemQuantity::minimum_contact_pressure:
          return prefix + "_minimum_pressure";
        case ProblemQuantity::maximum_contact_pressure:
          return prefix + "_maximum_pressure";
        case ProblemQuantity::mean_contact_pressure:
          return prefix + "_mean_pressure";
        case ProblemQuantity::contact_pressure_l2_error:
          return prefix + "_pressure_l2_error";
        case ProblemQuantity::resultant_force_x:
          return prefix + "_force_x";
        case ProblemQuantity::resultant_force_y:
          return prefix + "_force_y";
        case ProblemQuantity::resultant_force_z:
          return prefix + "_force_z";
        case ProblemQuantity::resultant_moment_x:
          return prefix + "_moment_x";
        case ProblemQuantity::resultant_moment_y:
          return prefix + "_moment_y";
        case ProblemQuantity::resultant_moment_z:
          return prefix + "_moment_z";
        case ProblemQuantity::displacement_x:
          return prefix + "_ux";
        case ProblemQuantity::displacement_y:
          return prefix + "_uy";
        case ProblemQuantity::displacement_z:
          return prefix + "_uz";
        case ProblemQuantity::none:
          break;
      }
    return prefix;
  }

  // The entries of one Check slot. A slot is unused until its Quantity
  // says otherwise; the other entries mean something only for some
  // quantities (Point for the pointwise ones and the half-width, Boundary
  // id for the resultants) and are ignored by the others.
  void
  ProblemCheckParameters::add_parameters(Subsection &s)
  {
    name = s.name;
    // The half-width counts the nodes in contact: active and with a
    // positive pressure (quantities.cc). An open node's multiplier is zero
    // only to the linear solver's accuracy, of either sign (the iterative
    // solver stops at 1e-8 of the right-hand side).
    s.add(
      "Quantity",
      quantity,
      "none",
      {{"none", ProblemQuantity::none},
       {"contact pressure", ProblemQuantity::contact_pressure},
       {"tangential traction", ProblemQuantity::tangential_traction},
       {"contact half-width", ProblemQuantity::contact_half_width},
       {"minimum contact pressure", ProblemQuantity::minimum_contact_pressure},
       {"maximum contact pressure", ProblemQuantity::maximum_contact_pressure},
       {"mean contact pressure", ProblemQuantity::mean_contact_pressure},
       {"contact pressure L2 error",
        ProblemQuantity::contact_pressure_l2_error},
       {"resultant force x", ProblemQuantity::resultant_force_x},
       {"resultant force y", ProblemQuantity::resultant_force_y},
       {"resultant force z", ProblemQuantity::resultant_force_z},
       {"resultant moment x", ProblemQuantity::resultant_moment_x},
       {"resultant moment y", ProblemQuantity::resultant_moment_y},
       {"resultant moment z", ProblemQuantity::resultant_moment_z},
       {"displacement x", ProblemQuantity::displacement_x},
       {"displacement y", ProblemQuantity::displacement_y},
       {"displacement z", ProblemQuantity::displacement_z}},
      "Scenario = general: none (slot not used); contact pressure at the "
      "slave node nearest to 'Point' (as Contact/Reported pressure) [Pa]; "
      "tangential traction there (friction: Cauchy, on the tangent e_z x n "
      "of the master's outward normal n; it has the sign of the slave's "
      "slip) [Pa]; "
      "contact half-width: the largest distance from 'Point' to which the "
      "slave surface is in contact, to half a segment (midway between the "
      "last node with positive pressure and the next open one) [m]; "
      "minimum, maximum or mean contact pressure: over the nodes of the "
      "slave surface nearest to 'Point' (the mean: the integral of the "
      "pressure over the surface's reference length, divided by that "
      "length) [Pa]; "
      "contact pressure L2 error: over the same surface, "
      "||p_h - p_ref|| / ||p_ref|| with p_ref the 'Reference' expression "
      "as a function of x, y (reference position) and t; the check "
      "passes when it is at most 'Tolerance' [-]; "
      "resultant force x, y or z (3D): the resultant of the traction on "
      "'Boundary id', its load where it is loaded and, where its "
      "displacement is imposed, the reactions of its nodes (contact "
      "forces left out), a node shared with another boundary split "
      "between them along the directions each holds [N per unit "
      "thickness in 2D]; resultant moment x, y (3D) or z: the moment of "
      "the same forces about the axis x, y or z through 'Point', at their "
      "points' current positions where a body is in finite strain [N m, "
      "per unit thickness in 2D]; displacement x, y or z (3D) at 'Point' "
      "(reference position) [m].");
    // In the reference configuration, as the boundary conditions' x and
    // y: a point on a body stays the same material point at every step.
    s.add("Point",
          "0, 0",
          Patterns::Anything(),
          "x, y [m] (x, y, z in 3D): where a pressure or displacement is "
          "taken, from where a contact width is measured, about which a "
          "moment is taken.",
          [this](const std::string &text) {
            coordinates = coordinates_from_text(text, name, "Point");
          });
    s.add("Boundary id",
          boundary_id,
          "0",
          0,
          max_tag,
          "The boundary of a resultant force or moment.");
    // Kept as text: parsed in finish(), once the constants are known, and
    // evaluated by the scenario at each checked row's pseudo-time and at
    // the check's point.
    s.add("Reference",
          reference,
          "0",
          "The expected value: an expression of t (the step's "
          "pseudo-time), x, y (, z: the point) and the constants.");
    // Relative by default: a reference of the size of the answer is the
    // usual case; an absolute error is for a reference that is zero (a
    // resultant that must vanish, a displacement held at rest).
    s.add("Relative",
          relative,
          "true",
          "true: the error is (value - reference) / |reference|; "
          "false: value - reference.");
    // 0 is allowed: a quantity that must be exact (a resultant of zero
    // given as an absolute check) then passes only at 0.
    s.add("Tolerance",
          tolerance,
          "0.01",
          "Largest admitted |error|.",
          not_negative());
    // Said in the verdict table beside the error: a closed form and a
    // digitised curve of a publication are not the same kind of evidence.
    s.add("Reference source",
          "",
          Patterns::Selection("|closed form|Code_Aster|publication|"
                              "other code"),
          "Where the reference comes from, shown in the verdict table "
          "(empty: not said).",
          [this](const std::string &text) { source = text; });
    // The last step by default: a check is usually of the final state; a
    // step that the run did not reach fails rather than passes.
    s.add("Steps",
          "last",
          Patterns::Anything(),
          "'all', 'last', 'none', or a comma-separated list of "
          "step numbers (1-based).",
          [this](const std::string &text) {
            steps_from_text(text, name, "Steps", every_step, steps);
          });
  }

  // The quantity and the point against the model's dimension, and the
  // reference parsed with the constants, once the file is read (as a
  // condition's value: the constants may come after it). A resultant does
  // not use the point: its default "0, 0" is not refused in 3D.
  void
  ProblemCheckParameters::finish(const std::map<std::string, double> &constants,
                                 const unsigned int dimension) const
  {
    const bool along_z = quantity == ProblemQuantity::resultant_force_z ||
                         quantity == ProblemQuantity::displacement_z;
    require(dimension == 3 || !along_z,
            name,
            "Quantity",
            "is along z, but the model is two-dimensional (x, y)");
    const bool in_plane_axis =
      quantity == ProblemQuantity::resultant_moment_x ||
      quantity == ProblemQuantity::resultant_moment_y;
    require(dimension == 3 || !in_plane_axis,
            name,
            "Quantity",
            "is a moment about an axis in the plane, but the model is "
            "two-dimensional: its moments are about z (resultant moment z)");
    const bool resultant = quantity == ProblemQuantity::resultant_force_x ||
                           quantity == ProblemQuantity::resultant_force_y ||
                           quantity == ProblemQuantity::resultant_force_z;
    require(resultant || coordinates.size() == dimension,
            name,
            "Point",
            "has " + std::to_string(coordinates.size()) +
              " coordinates, but the model is " +
              (dimension == 3 ? "three-dimensional: give x, y, z" :
                                "two-dimensional: give x, y"));
    try
      {
        if (dimension == 3)
          make_expression<3>({reference}, constants, "the reference");
        else
          make_expression<2>({reference}, constants, "the reference");
      }
    catch (const std::exception &e)
      {
        require(false, name, "Reference", e.what());
      }
  }
} // namespace RingContact
