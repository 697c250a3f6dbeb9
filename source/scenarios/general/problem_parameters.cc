// @sect3{A general problem: the whole description}
//
// The subsection Problem (the number of bodies and contact pairs, the named
// constants), the slots Body k, Contact pair k, Boundary condition k and
// Check k declared together, and once the file is read: the slots in use
// kept, the entries checked against each other (problem_description.cc has
// the parts of one slot).
#include <deal.II/base/numbers.h>
#include <deal.II/base/utilities.h>
#include <deal.II/lac/vector.h>

#include <ring_contact/base/utilities.h>
#include <ring_contact/input/gmsh_file.h>
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
    // A body's law under the entry's old name (Body n/Kinematics, until
    // version 0.11): read as its Material law, with a note, unless Material
    // law says otherwise. A law under one of its old names (finite strain,
    // ...) is read as the law, with a note too.
    void
    read_old_law_names(std::vector<BodyParameters> &bodies,
                       std::vector<std::string>    &notes)
    {
      for (unsigned int b = 0; b < bodies.size(); ++b)
        if (!bodies[b].law.empty() &&
            MaterialLaws::get(bodies[b].law).name != bodies[b].law)
          {
            const std::string name = MaterialLaws::get(bodies[b].law).name;
            notes.push_back("Note: '" + bodies[b].law +
                            "' is the old name of the law '" + name +
                            "'; read as Body " + std::to_string(b + 1) +
                            "/Material law = " + name + ".");
            bodies[b].law = name;
          }
      for (unsigned int b = 0; b < bodies.size(); ++b)
        if (!bodies[b].old_kinematics.empty())
          {
            const std::string name = "Body " + std::to_string(b + 1);
            const std::string old_law =
              MaterialLaws::get(bodies[b].old_kinematics).name;
            require(bodies[b].law.empty() ||
                      MaterialLaws::get(bodies[b].law).name == old_law,
                    name,
                    "Kinematics",
                    "is the old name of Material law, which the file sets "
                    "to '" +
                      bodies[b].law + "'; give Material law alone");
            bodies[b].law = old_law;
            notes.push_back(
              "Note: " + name + "/Kinematics is the old name of " + name +
              "/Material law; read as Material law = " + old_law + ".");
          }
    }
  } // namespace

  // @sect4{The whole description}
  //
  // The common entries a general problem reads of subsection Load program
  // are those of the steps program; a file of another scenario that sets
  // them is refused (ScenarioParameters::reads).
  ProblemParameters::ProblemParameters()
  {
    reads = {"Load program/Number of steps", "Load program/Time points"};
  }

  void
  ProblemParameters::add_parameters(ParameterHandler &prm)
  {
    {
      // At least two bodies and one pair: a contact problem. At most four
      // bodies and four pairs, twelve conditions and twelve checks: the
      // numbers of slots declared below, each of which appears in the
      // parameter reference (--print-parameters).
      Subsection s(prm, "Problem", &declared);
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
            "it, e.g. 'R = 1, E = 2e11, q = 1e6, a = min(R, 2)' "
            "(a comma inside parentheses is the expression's).",
            // Parsed at its own line: a bad constant is refused where it
            // is written, and the expressions, checked in finish(), see
            // the values.
            [this](const std::string &text) {
              constants = parse_constants(text);
            });
    }
    // Every slot is declared and bound; finish() keeps those in use. The
    // vectors are sized before the entries are declared and not resized
    // until finish(): each entry's action holds a reference to its slot's
    // member, which must not move.
    bodies.assign(max_bodies, BodyParameters());
    for (unsigned int b = 0; b < max_bodies; ++b)
      {
        Subsection s(prm, "Body " + std::to_string(b + 1), &declared);
        bodies[b].add_parameters(s);
      }
    // The first pair is subsection Contact (common to every scenario, with
    // the integration schemes and constants all pairs use): the slots here
    // start at 2.
    contact_pairs.assign(max_contact_pairs - 1, {0, 0});
    // Their tags default to 0 and 0: a pair counted by Number of contact
    // pairs whose subsection the file forgot is refused in finish() (slave
    // and master the same), not paired with whatever tag 0 is.
    for (unsigned int k = 2; k <= max_contact_pairs; ++k)
      {
        Subsection s(prm, "Contact pair " + std::to_string(k), &declared);
        s.add("Slave boundary",
              contact_pairs[k - 2].first,
              "0",
              0,
              max_tag,
              "Scenario = general: the boundary tag of this "
              "pair's slave surface (it carries the contact "
              "pressure).");
        s.add("Master boundary",
              contact_pairs[k - 2].second,
              "0",
              0,
              max_tag,
              "The boundary tag of this pair's master surface.");
      }
    boundary_conditions.assign(max_boundary_conditions,
                               BoundaryConditionParameters());
    for (unsigned int k = 0; k < max_boundary_conditions; ++k)
      {
        Subsection s(prm,
                     "Boundary condition " + std::to_string(k + 1),
                     &declared);
        boundary_conditions[k].add_parameters(s);
      }
    checks.assign(max_checks, ProblemCheckParameters());
    for (unsigned int k = 0; k < max_checks; ++k)
      {
        Subsection s(prm, "Check " + std::to_string(k + 1), &declared);
        checks[k].add_parameters(s);
      }
  }

  // Once the whole file is read, with this scenario chosen: the slots in
  // use kept, their expressions checked (the constants are now known), and
  // the description checked against itself and against the common
  // entries. Every refusal names the entry whose value is wrong; the
  // reader adds the file and line that set it.
  std::vector<std::pair<std::string, std::string>>
  ProblemParameters::load_programs() const
  {
    return {{steps_program,
             "the pseudo-times of 'Time points', or t = k / n for k = 1..n "
             "with n = 'Number of steps' (a general problem, whose "
             "expressions take t)"}};
  }

  // The probe places the rings' node A (history.csv's pressure_A): a general
  // problem has no node A, and its history no such column. A quantity at a
  // point is a check's, reported at every step.
  std::string
  ProblemParameters::why_not_read(const std::string &entry) const
  {
    if (entry != "Contact/Probe point")
      return "";
    return "has no meaning in a general problem (it places the rings' node "
           "A); a quantity at a point is a Check subsection's, reported at "
           "every step (Quantity = contact pressure, Point = x, y; Steps = "
           "none to report it without checking it)";
  }

  void
  ProblemParameters::finish(Parameters &parameters)
  {
    bodies.resize(number_of_bodies);
    contact_pairs.resize(number_of_contact_pairs - 1);
    // A surface in contact with itself is not a pair. (Subsection
    // Contact's own pair is checked with the common entries.)
    for (unsigned int k = 0; k < contact_pairs.size(); ++k)
      require(contact_pairs[k].first != contact_pairs[k].second,
              "Contact pair " + std::to_string(k + 2),
              "Slave boundary",
              "must differ from 'Master boundary' (both are " +
                std::to_string(contact_pairs[k].first) + ")");
    // A slot whose entries are set but whose Type or Quantity is not is
    // refused before the unused slots go (the slot numbers are still
    // those of the file).
    refuse_idle_slots(parameters);
    // Unused slots (Type = none, Quantity = none) go; the others keep
    // their order, and their names keep their slot numbers.
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
    find_dimension(parameters);
    // The parsers made by these checks are thrown away: the scenario makes
    // its own where it evaluates (general.cc). This pass only refuses a bad
    // expression before the mesh is read and anything is computed.
    for (const auto &condition : boundary_conditions)
      condition.finish(constants, model_dimension);
    for (const auto &check : checks)
      check.finish(constants, model_dimension);

    refuse_unread_slots(parameters);
    read_old_law_names(bodies, parameters.notes);
    // The description refers to the mesh by its physical groups: only a
    // gmsh mesh has them (the generated meshes are the rings' and the
    // patch test's). Its load states are pseudo-times, which only the
    // steps program gives.
    require(parameters.mesh.source == MeshSource::gmsh_file,
            "Mesh",
            "Mesh source",
            "must be 'gmsh file' for Problem/Scenario = general (its bodies "
            "and boundaries are the physical groups of the mesh)");
    require(parameters.load.program == steps_program,
            "Load program",
            "Program",
            "must be 'steps' for Problem/Scenario = general (the ramp and "
            "the rotation are the programs of the other scenarios)");
    // Two bodies of one physical group would be one body with two sets of
    // constants.
    for (unsigned int b = 1; b < bodies.size(); ++b)
      for (unsigned int a = 0; a < b; ++a)
        require(bodies[a].material_id != bodies[b].material_id,
                "Body " + std::to_string(b + 1),
                "Material id",
                "is that of Body " + std::to_string(a + 1) + " (" +
                  std::to_string(bodies[a].material_id) +
                  "): each body is its own physical group");
    // Each slave surface belongs to one pair: a multiplier node belongs to
    // one pair, whose active set decides it. (A body may still be the
    // slave of two pairs through two surfaces: the middle of three
    // blocks.)
    const auto pairs = parameters.contact_pairs();
    for (unsigned int k = 1; k < pairs.size(); ++k)
      for (unsigned int j = 0; j < k; ++j)
        require(pairs[k].first != pairs[j].first,
                "Contact pair " + std::to_string(k + 1),
                "Slave boundary",
                "is the slave surface of " +
                  (j == 0 ? std::string("subsection Contact") :
                            "Contact pair " + std::to_string(j + 1)) +
                  " too (" + std::to_string(pairs[k].first) +
                  "): each pair has its own slave surface");
    // A checked step beyond the program's last is a typo, said now rather
    // than as 'step not reached' after the run.
    const unsigned int n_steps = parameters.load.time_points.size();
    for (const auto &check : checks)
      for (const unsigned int step : check.steps)
        require(step == numbers::invalid_unsigned_int || step <= n_steps,
                check.name,
                "Steps",
                "names step " + std::to_string(step) +
                  ", but the load program has " + std::to_string(n_steps) +
                  " steps");
    check_boundary_conditions(pairs);
  }


  // The problem's dimension is the model's (issue 48): 3 for a model of
  // volumes. A model that gmsh cannot open is said here, with gmsh's reason
  // (the one-line error the mesh's reading would give): taken as 2, as it
  // was, a 3D script stopped by an error of its own was refused for the
  // parameter file's three components (a traction needs 2), not for its
  // error. A signal while gmsh reads it is said where the mesh is read,
  // which ends the run as the signal asks (exit 130 or 143, run.cc): the
  // reading finds the signal and stops at once.
  void
  ProblemParameters::find_dimension(const Parameters &parameters)
  {
    model_dimension = 2;
    if (parameters.mesh.source == MeshSource::gmsh_file)
      try
        {
          model_dimension =
            Geometry::model_dimension(parameters.mesh.mesh_file,
                                      parameters.mesh.geo_numbers);
        }
      catch (const Interrupted &)
        {}
    // z is the third variable of a 3D problem's expressions.
    require(model_dimension == 2 || constants.count("z") == 0,
            "Problem",
            "Constants",
            "gives a value to 'z', which every expression of a "
            "three-dimensional model already has (x, y, z: the point)");
  }


  // Body 3 set in a problem of two bodies, a pair beyond the number of
  // pairs: not read, so refused. Found from the entries the file set
  // (their keys "Body 3/Young's modulus"), so that the message names the
  // very entry and its line; nothing set is silently ignored.
  void
  ProblemParameters::refuse_unread_slots(const Parameters &parameters) const
  {
    for (const auto &[key, origin] : parameters.origins)
      for (const auto &[prefix, n, count] :
           {std::make_tuple(std::string("Body "),
                            static_cast<unsigned int>(bodies.size()),
                            std::string("Number of bodies")),
            std::make_tuple(std::string("Contact pair "),
                            static_cast<unsigned int>(contact_pairs.size() + 1),
                            std::string("Number of contact pairs"))})
        // "Contact/..." (the first pair) does not start with "Contact
        // pair ": only the numbered slots are matched. atoi() reads the
        // slot's number and stops at the '/' after it.
        if (key.rfind(prefix, 0) == 0)
          {
            const auto         slash = key.rfind('/');
            const unsigned int k = std::atoi(key.substr(prefix.size()).c_str());
            require(k <= n,
                    key.substr(0, slash),
                    key.substr(slash + 1),
                    "is not read: Problem/" + count + " is " +
                      std::to_string(n));
          }
  }


  // A Boundary condition or Check slot is used only when its Type or
  // Quantity says so: a slot given a boundary and a value but no Type was
  // dropped without a word, the load or support it describes missing from
  // the problem. Refused at the first entry the file sets in it, naming
  // them all. A Type or Quantity set to none by the file itself is a
  // deliberate switch-off (a file that includes another and drops one of
  // its conditions, as tests/general_problem_input's floating body does),
  // and is kept.
  void
  ProblemParameters::refuse_idle_slots(const Parameters &parameters) const
  {
    const auto refuse_if_set = [&](const std::string &slot,
                                   const std::string &switch_entry,
                                   const std::string &choices) {
      if (parameters.origins.count(entry_key(slot, switch_entry)) != 0)
        return;
      // The entries set in the slot, the first (by line) named first, so
      // that the message is located where the reader meets the slot.
      std::vector<std::pair<unsigned int, std::string>> set;
      for (const auto &[key, origin] : parameters.origins)
        if (key.rfind(slot + "/", 0) == 0)
          set.emplace_back(origin.line, key.substr(slot.size() + 1));
      if (set.empty())
        return;
      std::sort(set.begin(), set.end());
      std::string names;
      for (const auto &entry : set)
        names += (names.empty() ? "" : ", ") + entry.second;
      require(false,
              slot,
              set.front().second,
              "is set, but the slot's " + switch_entry +
                " is not (none: the slot is not used, and its entries " +
                names + " would be ignored): set " + switch_entry + " (" +
                choices + "), or remove them");
    };
    for (unsigned int k = 0; k < boundary_conditions.size(); ++k)
      if (boundary_conditions[k].type == BoundaryConditionType::none)
        refuse_if_set(boundary_conditions[k].name,
                      "Type",
                      "displacement, traction or pressure");
    for (unsigned int k = 0; k < checks.size(); ++k)
      if (checks[k].quantity == ProblemQuantity::none)
        refuse_if_set(
          checks[k].name,
          "Quantity",
          "contact pressure, displacement y, ...: --print-parameters "
          "lists them");
  }


  // A boundary condition is never on a contact surface; a boundary has at
  // most one load, and each component of its displacement is imposed once.
  // (A load along a direction that a displacement of the same boundary
  // holds is refused later, once the mesh is known: the scenario checks it
  // at the faces and pseudo-times of the load program.)
  //
  // A contact surface's traction is the contact's: a support or a load
  // there would take part of it. One load per boundary: the file is asked
  // for the sum of two, so that what is said of a boundary's load (the
  // held-direction check of general.cc names it) is about one condition.
  // Two displacements of one component used to let the later one win,
  // silently.
  void
  ProblemParameters::check_boundary_conditions(
    const std::vector<std::pair<unsigned int, unsigned int>> &pairs) const
  {
    for (const auto &condition : boundary_conditions)
      {
        for (unsigned int k = 0; k < pairs.size(); ++k)
          require(condition.boundary_id != pairs[k].first &&
                    condition.boundary_id != pairs[k].second,
                  condition.name,
                  "Boundary id",
                  "= " + std::to_string(condition.boundary_id) +
                    " is a contact surface (" +
                    (k == 0 ? std::string("Contact") :
                              "Contact pair " + std::to_string(k + 1)) +
                    "/Slave boundary or Master boundary)");
        // Against every other condition: a clash of two loads is reported
        // at the first of the two slots.
        for (const auto &other : boundary_conditions)
          require(&other == &condition ||
                    other.boundary_id != condition.boundary_id ||
                    other.type == BoundaryConditionType::displacement ||
                    condition.type == BoundaryConditionType::displacement,
                  condition.name,
                  "Boundary id",
                  "= " + std::to_string(condition.boundary_id) +
                    " has two loads (" + other.name +
                    " too): give their sum "
                    "in one");
        // Two displacements on one boundary: each component once (x and y
        // apart, or r and theta apart); a normal one alone.
        // Disjoint: both Cartesian or both polar, no component in common.
        // A normal condition is never disjoint from another on its
        // boundary: it involves both unknowns of every node.
        const auto disjoint = [](const BoundaryConditionParameters &a,
                                 const BoundaryConditionParameters &b) {
          return !a.normal && !b.normal && a.polar == b.polar &&
                 !(a.components[0] && b.components[0]) &&
                 !(a.components[1] && b.components[1]) &&
                 !(a.components[2] && b.components[2]);
        };
        // Against the earlier conditions only: each clash is reported
        // once, at the later of the two slots.
        for (const auto &other : boundary_conditions)
          {
            if (&other == &condition)
              break;
            require(other.boundary_id != condition.boundary_id ||
                      other.type != BoundaryConditionType::displacement ||
                      condition.type != BoundaryConditionType::displacement ||
                      disjoint(other, condition),
                    condition.name,
                    "Boundary id",
                    "= " + std::to_string(condition.boundary_id) +
                      " has a displacement of " + other.name +
                      " too, on the same components: impose each "
                      "component of a boundary once");
          }
      }
  }
} // namespace RingContact
