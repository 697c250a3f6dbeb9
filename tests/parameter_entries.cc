// Each entry of the parameter file is declared once, bound to the member it
// sets (ParameterChecks::Subsection). This test reads files through
// Parameters::read() and checks, for every kind of entry (number, integer,
// flag, text, choice, list, point, steps, time points, and the slots of a
// general problem), that
// - the member holds the default before any file is read, and the default
//   printed by --print-parameters is that value;
// - a value set in a file reaches the member, the last one when an entry is
//   set twice;
// - a value refused by its entry's check names the file and the line that
//   set it, an included file's own;
// - a general problem keeps only the slots it uses, and refuses a slot
//   whose entries are set but whose Type or Quantity is left at none;
// - a UTF-8 byte order mark is skipped.
#include <deal.II/base/parameter_handler.h>

#include <ring_contact/config.h>
#include <ring_contact/input/parameters.h>
#include <ring_contact/scenarios/general/problem_description.h>
#include <ring_contact/scenarios/ssnp152/ssnp152.h>

#include "tests.h"

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

using namespace RingContact;
using RingContactTests::check;
using RingContactTests::deallog_file;

namespace
{
  void
  write(const std::string &name, const std::string &text)
  {
    std::ofstream(name) << text;
  }

  // The message of the error that reading `name` gives ("" if none).
  std::string
  error_of(const std::string &name)
  {
    try
      {
        Parameters parameters;
        parameters.read(name);
      }
    catch (const std::exception &e)
      {
        return e.what();
      }
    return "";
  }

  // The default of an entry as --print-parameters shows it.
  std::string
  printed_default(const std::string &subsection, const std::string &entry)
  {
    std::ostringstream reference;
    Parameters::print_reference(reference, true);
    std::istringstream lines(reference.str());
    std::string        line, current;
    while (std::getline(lines, line))
      {
        const auto first = line.find_first_not_of(' ');
        if (first == std::string::npos)
          continue;
        line = line.substr(first);
        if (line.rfind("subsection ", 0) == 0)
          current = line.substr(11);
        else if (line.rfind("set ", 0) == 0 && current == subsection)
          {
            const auto  equal = line.find('=');
            std::string name  = line.substr(4, equal - 4);
            name.erase(name.find_last_not_of(' ') + 1);
            if (name == entry)
              {
                std::string value = line.substr(equal + 1);
                value.erase(0, value.find_first_not_of(' '));
                const auto comment = value.find(" #");
                if (comment != std::string::npos)
                  value.erase(comment);
                value.erase(value.find_last_not_of(' ') + 1);
                return value;
              }
          }
      }
    return "(not printed)";
  }
  // The entries of a scenario, as its type.
  const Ssnp152::RingParameters &
  rings(const Parameters &p)
  {
    return dynamic_cast<const Ssnp152::RingParameters &>(
      *p.scenario_parameters.at("SSNP152"));
  }

  const ProblemParameters &
  general(const Parameters &p)
  {
    return dynamic_cast<const ProblemParameters &>(
      *p.scenario_parameters.at("general"));
  }
} // namespace

int
main()
{
  // Defaults: the members hold them as soon as the entries are declared.
  {
    Parameters       p;
    ParameterHandler prm;
    p.add_parameters(prm);
    check(rings(p).youngs_modulus_outer == 1e9 &&
            printed_default("Materials", "Young's modulus outer ring") == "1e9",
          "number default");
    check(rings(p).reference.ramp.steps == 21 &&
            printed_default("Load program", "Ramp steps") == "21",
          "integer default");
    check(p.newton.extrapolate &&
            printed_default("Newton", "Extrapolate") == "true",
          "flag default");
    check(p.materials.plane == PlaneAssumption::plane_stress &&
            printed_default("Materials", "Plane assumption") == "plane stress",
          "choice default");
    // The schemes' default is the scenario's, chosen once the scenario is
    // known (ContactParameters::choose_schemes()): none before.
    check(p.contact.schemes.empty() &&
            printed_default("Contact", "Integration schemes") == "automatic",
          "list default");
    check(rings(p).reference.probe_point<2>().distance(Point<2>(0.6, 0)) == 0,
          "point default");
    check(rings(p).reference.checks.every_step &&
            rings(p).reference.checks.steps.empty(),
          "steps default");
    check(general(p).bodies.size() == ProblemParameters::max_bodies &&
            general(p).checks.size() == ProblemParameters::max_checks,
          "every slot of a general problem is bound before the file is read");
    deallog_file << "defaults: the members hold the printed defaults"
                 << std::endl;
  }

  // Values set in a file reach their members; the last of two wins.
  {
    write("values.prm",
          "subsection Materials\n"
          "  set Young's modulus outer ring = 2e11\n"
          "  set Plane assumption = plane strain\n"
          "  set Material law = neo-Hookean\n"
          "end\n"
          "subsection Finite elements\n"
          "  set Reduced integration = true\n"
          "end\n"
          "subsection Load program\n"
          "  set Ramp steps = 4\n"
          "  set Ramp steps = 5\n"
          "end\n"
          "subsection Contact\n"
          "  set Integration schemes = nodal, Gauss 3\n"
          "  set Probe point = 0.6, 0.01\n"
          "end\n"
          "subsection Checks\n"
          "  set Steps = 1, 3\n"
          "end\n"
          "subsection Newton\n"
          "  set Linear solver = MUMPS\n"
          "end\n"
          "subsection Output\n"
          "  set Directory = elsewhere\n"
          "end\n");
    Parameters p;
    p.read("values.prm");
    check(rings(p).youngs_modulus_outer == 2e11, "number");
    check(p.materials.plane == PlaneAssumption::plane_strain, "choice");
    check(p.materials.law == "neo-Hookean", "material law");
    check(p.finite_elements.reduced_integration, "flag");
    check(rings(p).reference.ramp.steps == 5,
          "integer set twice: the last value");
    check(p.contact.schemes.size() == 2 &&
            p.contact.schemes[1].name() == "Gauss 3",
          "list");
    const ReferencePressureEntries &reference = rings(p).reference;
    check(reference.probe_point<2>().distance(Point<2>(0.6, 0.01)) == 0, "point");
    check(!reference.checks.every_step && reference.checks.steps.size() == 2 &&
            reference.checks.steps[1] == 3,
          "steps");
    check(p.newton.linear_solver == LinearSolverType::mumps, "solver");
    check(p.output.directory == "elsewhere", "text");
    // Untouched entries keep their defaults.
    check(rings(p).youngs_modulus_inner == 1e9 &&
            rings(p).reference.ramp.time_step == 0.1,
          "defaults of the entries not set");
    deallog_file << "values: every kind of entry reaches its member"
                 << std::endl;
  }

  // A refused value names the line that set it, in the file that set it.
  {
    write("included.prm",
          "# a comment\n"
          "subsection Materials\n"
          "  set Poisson's ratio inner ring = 0.5\n"
          "end\n");
    write("includes.prm", "\ninclude included.prm\n");
    deallog_file << "included: " << error_of("includes.prm") << std::endl;
    write("time_points.prm",
          "subsection Problem\n  set Scenario = general\nend\n"
          "subsection Load program\n  set Program = steps\n"
          "  set Time points = 0:1e-9:1\nend\n");
    deallog_file << "time points: " << error_of("time_points.prm") << std::endl;
    write("body.prm", "subsection Body 3\n  set Poisson's ratio = 0.7\nend\n");
    deallog_file << "body: " << error_of("body.prm") << std::endl;
    // An error that comes from an entry the file does not set says so.
    write("default_entry.prm",
          "subsection Mesh\n  set Mesh source = gmsh file\nend\n");
    deallog_file << "default entry: " << error_of("default_entry.prm")
                 << std::endl;
    // The pressure named when it alone is beyond reason.
    write("huge_pressure.prm",
          "subsection Load program\n  set Reference pressure = 1e300\nend\n");
    deallog_file << "huge pressure: " << error_of("huge_pressure.prm")
                 << std::endl;
  }

  // A UTF-8 byte order mark at the start of a file is not text.
  {
    write("bom.prm",
          "\xEF\xBB\xBFsubsection Materials\n"
          "  set Poisson's ratio inner ring = 0.25\nend\n");
    Parameters p;
    p.read("bom.prm");
    check(rings(p).poissons_ratio_inner == 0.25, "byte order mark");
    deallog_file << "byte order mark: read" << std::endl;
  }

  // A general problem keeps the bodies and pairs of its numbers and the
  // conditions and checks whose slots it uses, in their order.
  {
    write("general.prm",
          "subsection Problem\n  set Scenario = general\n"
          "  set Number of bodies = 3\n  set Constants = q = 2\nend\n"
          "subsection Mesh\n  set Mesh source = gmsh file\n"
          "  set Mesh file = " RING_CONTACT_SOURCE_DIR
          "/meshes/three_blocks.geo\nend\n"
          "subsection Load program\n  set Program = steps\nend\n"
          "subsection Body 1\n  set Material id = 1\nend\n"
          "subsection Body 2\n  set Material id = 2\nend\n"
          "subsection Body 3\n  set Material id = 7\nend\n"
          "subsection Boundary condition 2\n  set Type = pressure\n"
          "  set Boundary id = 5\n  set Value = q * t\nend\n"
          "subsection Boundary condition 9\n  set Type = traction\n"
          "  set Boundary id = 6\n  set Value = 0; -q\nend\n"
          "subsection Check 4\n  set Quantity = resultant force y\n"
          "  set Boundary id = 6\n  set Reference = -q\nend\n");
    Parameters p;
    p.read("general.prm");
    const auto &problem = p.scenario_entries<ProblemParameters>();
    check(problem.bodies.size() == 3 && problem.bodies[2].material_id == 7,
          "bodies");
    check(problem.boundary_conditions.size() == 2 &&
            problem.boundary_conditions[0].name == "Boundary condition 2" &&
            problem.boundary_conditions[0].expressions.size() == 1 &&
            problem.boundary_conditions[1].boundary_id == 6,
          "boundary conditions");
    check(problem.checks.size() == 1 && problem.checks[0].name == "Check 4" &&
            problem.checks[0].reference == "-q",
          "checks");
    check(problem.more_contact_pairs().empty(), "contact pairs");
    check(problem.constants.at("q") == 2, "constants");
    deallog_file << "general: the slots in use, in order" << std::endl;
  }

  // A Boundary condition or Check slot whose entries are set but whose
  // Type or Quantity is left at none was dropped without a word: refused,
  // at the first entry set, naming them all. Set to none by the file
  // itself, the slot is switched off on purpose, and kept quiet.
  {
    const std::string head =
      "subsection Problem\n  set Scenario = general\nend\n"
      "subsection Mesh\n  set Mesh source = gmsh file\n"
      "  set Mesh file = " RING_CONTACT_SOURCE_DIR
      "/meshes/two_blocks.geo\nend\n"
      "subsection Load program\n  set Program = steps\nend\n"
      "subsection Body 1\n  set Material id = 1\nend\n"
      "subsection Body 2\n  set Material id = 2\nend\n"
      "subsection Contact\n  set Slave boundary = 10\n"
      "  set Master boundary = 20\nend\n";
    write("idle_condition.prm",
          head + "subsection Boundary condition 4\n  set Boundary id = 21\n"
                 "  set Value = 0; 0\nend\n");
    const std::string condition = error_of("idle_condition.prm");
    check(condition.find("idle_condition.prm:22: parameter 'Boundary id' in "
                         "subsection 'Boundary condition 4' is set, but the "
                         "slot's Type is not") != std::string::npos,
          "an idle condition is refused at its line: " + condition);
    deallog_file << "idle condition: " << condition << std::endl;
    write("idle_check.prm",
          head + "subsection Check 3\n  set Reference = 1\n"
                 "  set Point = 0.3, 0\nend\n");
    const std::string check_slot = error_of("idle_check.prm");
    check(check_slot.find("subsection 'Check 3' is set, but the slot's "
                          "Quantity is not") != std::string::npos,
          "an idle check is refused: " + check_slot);
    deallog_file << "idle check: " << check_slot << std::endl;
    write("switched_off.prm",
          head + "subsection Boundary condition 4\n  set Boundary id = 21\n"
                 "  set Type = none\nend\n"
                 "subsection Check 3\n  set Quantity = none\n"
                 "  set Reference = 1\nend\n");
    check(error_of("switched_off.prm").empty(),
          "a slot switched off by the file is not refused");
    deallog_file << "switched off: read, no condition and no check"
                 << std::endl;

    // Problem/Constants is split at the commas outside parentheses: a
    // function of two arguments is one value; bad input keeps its messages.
    write("two_argument_constants.prm",
          head + "subsection Problem\n  set Constants = a = 2, b = 3, "
                 "m = min(a, b), th = atan2(b, a),\nend\n");
    Parameters p;
    p.read("two_argument_constants.prm");
    const auto &constants = p.scenario_entries<ProblemParameters>().constants;
    check(constants.size() == 4 && constants.at("m") == 2 &&
            constants.at("th") == std::atan2(3., 2.),
          "min(a, b) and atan2(b, a) as constants");
    deallog_file << "constants with commas inside parentheses: m = "
                 << constants.at("m") << ", th = " << constants.at("th")
                 << std::endl;
    for (const std::string constants :
         {"a = min(1, 2", "a = 1, 2", "a = 1), b = 2", "a = max(1, 2)) + 1"})
      {
        write("bad_constants.prm",
              head + "subsection Problem\n  set Constants = " + constants +
                "\nend\n");
        const std::string error = error_of("bad_constants.prm");
        check(error.find("parameter 'Constants' in subsection 'Problem'") !=
                std::string::npos,
              "'" + constants + "' refused: " + error);
        deallog_file << "constants '" << constants << "': " << error
                     << std::endl;
      }

    // The entry's old name, Kinematics (until 0.11), is still read, with a
    // note for the log; beside a Material law that says otherwise it is
    // refused. The same for a body of a general problem.
    write("old_name.prm",
          "subsection Materials\n  set Kinematics = small strain\nend\n");
    Parameters old;
    old.read("old_name.prm");
    check(old.materials.law == "linear elasticity" && old.notes.size() == 1,
          "Materials/Kinematics read as Material law");
    deallog_file << "old name: " << old.notes.at(0) << std::endl;
    write("old_name_conflict.prm",
          "subsection Materials\n  set Kinematics = small strain\n"
          "  set Material law = Hencky\nend\n");
    deallog_file << "old name against the new: "
                 << error_of("old_name_conflict.prm") << std::endl;
    write("old_name_body.prm",
          head + "subsection Body 2\n  set Kinematics = logarithmic strain\n"
                 "end\n");
    Parameters body;
    body.read("old_name_body.prm");
    check(body.scenario_entries<ProblemParameters>().bodies.at(1).law ==
              "Hencky" &&
            body.notes.size() == 1,
          "Body 2/Kinematics read as Material law");
    deallog_file << "old name of a body: " << body.notes.at(0) << std::endl;
    // An old value under the new name: read as the law, with a note too.
    write("old_value.prm",
          "subsection Materials\n  set Material law = finite strain\nend\n");
    Parameters old_value;
    old_value.read("old_value.prm");
    check(old_value.materials.law == "Saint Venant-Kirchhoff" &&
            old_value.notes.size() == 1,
          "Material law = finite strain read as Saint Venant-Kirchhoff");
    deallog_file << "old value: " << old_value.notes.at(0) << std::endl;
    write("old_value_body.prm",
          head + "subsection Body 2\n  set Material law = small strain\nend\n");
    Parameters body_value;
    body_value.read("old_value_body.prm");
    check(body_value.scenario_entries<ProblemParameters>().bodies.at(1).law ==
              "linear elasticity" &&
            body_value.notes.size() == 1,
          "Body 2/Material law = small strain read as linear elasticity");
    deallog_file << "old value of a body: " << body_value.notes.at(0)
                 << std::endl;
  }
}
