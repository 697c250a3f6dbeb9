// @sect3{Run-time parameters}
//
// The entries of the parameter file that every problem reads, one struct per
// subsection as in step-44; the scenarios' own entries are declared in their
// folders (scenarios/*/). Where step-44 declares its entries in one function
// and reads them back in another, each entry here is one statement,
// ParameterChecks::Subsection::add() (parameter_checks.cc), that holds its
// name, default, pattern, documentation, the member it sets and the checks of
// its value, so that these cannot drift apart. deal.II runs the entry's action
// when the file sets it: a value refused there is reported at its own line, in
// an included file too. What an action cannot check, because it involves
// another entry that may come later in the file, waits for the finish()
// functions, which Parameters::read() calls once the whole file is read.
//
// The documentation strings are the program's reference manual (printed by
// `ring_contact --print-parameters`, kept in doc/parameters.prm); the comments
// say why the defaults and limits are what they are. Where an entry is the
// rings', its default is the rings' modelisation A: plane stress, finite
// strain, Q1 rings, nodal integration, the 21-step ramp checked at every step
// to 2 %.
#include <ring_contact/base/utilities.h>
#include <ring_contact/input/gmsh_file.h>
#include <ring_contact/input/parameter_checks.h>
#include <ring_contact/input/parameter_file.h>
#include <ring_contact/input/parameters.h>
#include <ring_contact/scenarios/scenario.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/numbers.h>
#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <tuple>

namespace RingContact
{
  using namespace ParameterChecks;

  // @sect4{The whole file}
  //
  // The common subsections (subsections.cc), Problem/Scenario, and every
  // registered
  // scenario's own entries, declared together; then the file read, the entries
  // checked against each other, and every error located at its line.

  // Every scenario's entries are made and declared, not only those of the
  // scenario the file chooses: deal.II needs every entry declared before the
  // file is read, and the file may name its scenario anywhere, after the
  // entries or in an included file.
  Parameters::Parameters()
  {
    for (const auto &scenario : registered_scenarios())
      scenario_parameters[scenario.name] = scenario.make_parameters();
  }

  // The entries of the common subsections that not every scenario reads, listed
  // here once; a scenario claims those it reads in its `reads`. A claim on an
  // entry missing here is a programming error, which readers.at() in
  // add_parameters() throws on at the declaration. Any other common entry is
  // read by all scenarios.
  std::vector<std::string>
  Parameters::restricted_entries()
  {
    return {"Load program/Number of steps", "Load program/Time points"};
  }

  namespace
  {
    // How the message of an entry that the chosen scenario does not read
    // names who reads it, by the names the scenarios give themselves in
    // messages: "A", "A and B", "A, B and C".
    std::string
    describe_readers(const std::set<std::string> &names)
    {
      std::vector<std::string> descriptions;
      for (const auto &scenario : registered_scenarios())
        if (names.count(scenario.name))
          descriptions.push_back(scenario.description);
      std::string text;
      for (unsigned int k = 0; k < descriptions.size(); ++k)
        text += (k == 0                       ? "" :
                 k + 1 == descriptions.size() ? " and " :
                                                ", ") +
                descriptions[k];
      return text;
    }
  } // namespace

  void
  Parameters::add_parameters(ParameterHandler &prm)
  {
    // One walk over the registered scenarios gives the choices, default and
    // documentation of Problem/Scenario (a new scenario adds no line here),
    // and what the common entries offer that the scenarios define: the
    // load programs (the default scenario's first, its first the default)
    // and the default contact surfaces, the default scenario's.
    std::string names, default_name, documentation = "The problem posed.";
    std::vector<std::pair<std::string, std::string>> programs, others;
    std::pair<unsigned int, unsigned int>            surfaces;
    for (const auto &registered : registered_scenarios())
      {
        names += (names.empty() ? "" : "|") + registered.name;
        documentation +=
          " " + registered.name + ": " + registered.documentation;
        const ScenarioParameters &entries =
          *scenario_parameters.at(registered.name);
        const auto programs_of = entries.load_programs();
        if (registered.is_default)
          {
            default_name = registered.name;
            surfaces     = entries.default_contact_surfaces();
            programs.insert(programs.begin(),
                            programs_of.begin(),
                            programs_of.end());
          }
        else
          others.insert(others.end(), programs_of.begin(), programs_of.end());
      }
    for (const auto &program : others)
      if (std::none_of(programs.begin(), programs.end(), [&](const auto &p) {
            return p.first == program.first;
          }))
        programs.push_back(program);
    {
      ParameterChecks::Subsection s(prm, "Problem");
      s.add("Scenario",
            scenario,
            default_name,
            documentation,
            Patterns::Selection(names));
    }
    mesh.add_parameters(prm);
    refinement.add_parameters(prm);
    materials.add_parameters(prm);
    finite_elements.add_parameters(prm);
    contact.add_parameters(prm, surfaces);
    load.add_parameters(prm, programs);
    newton.add_parameters(prm);
    output.add_parameters(prm);
    // Who reads the entries that only some scenarios read: the common
    // ones some scenarios say they read, and every scenario's own.
    readers.clear();
    for (const auto &key : restricted_entries())
      readers[key];
    for (const auto &[name, entries] : scenario_parameters)
      {
        entries->declared.clear();
        entries->add_parameters(prm);
        for (const auto &key : entries->declared)
          readers[key].insert(name);
        for (const auto &key : entries->reads)
          readers.at(key).insert(name);
      }
  }

  // Subsection Contact holds the first pair for every scenario; a general
  // problem adds its 'Contact pair 2' to '4'. The schemes and constants of
  // subsection Contact serve every pair.
  std::vector<std::pair<unsigned int, unsigned int>>
  Parameters::contact_pairs() const
  {
    std::vector<std::pair<unsigned int, unsigned int>> pairs = {
      {contact.slave_boundary_id, contact.master_boundary_id}};
    const auto more = scenario_parameters.at(scenario)->more_contact_pairs();
    pairs.insert(pairs.end(), more.begin(), more.end());
    return pairs;
  }

  void
  Parameters::read(const std::string              &filename,
                   const std::vector<std::string> &overrides)
  {
    prm_file = filename;
    // Every entry is bound to its member here and takes its value (checked)
    // as the file is read; what remains is what involves several entries.
    ParameterHandler prm;
    add_parameters(prm);
    // Entries that moved (the patch test's, once in subsection Mesh) go to the
    // reader, which answers an old file with where the entry is now, instead of
    // refusing it as unknown.
    std::map<std::string, std::string> moved;
    for (const auto &[name, entries] : scenario_parameters)
      {
        const auto these = entries->moved_entries();
        moved.insert(these.begin(), these.end());
      }
    origins = read_parameter_file(prm, filename, moved, overrides);

    // The top file's folder and name: the folder of a relative mesh path that
    // it sets itself, and the default results folder, results/<name>.
    const std::filesystem::path path(filename);
    const std::string           folder =
      path.has_parent_path() ? path.parent_path().string() : ".";
    const std::string name = path.stem().string();
    // The actions' ParameterErrors were located by the reader, line by
    // line; those of the checks below are located here, from the origins
    // the reader recorded.
    try
      {
        // A relative mesh path is taken from the folder of the file that
        // sets it (an included file's own folder), not the top file's.
        std::string mesh_folder = folder;
        {
          const auto origin = origins.find(entry_key("Mesh", "Mesh file"));
          if (origin != origins.end())
            {
              const std::filesystem::path set_in(origin->second.file);
              mesh_folder =
                set_in.has_parent_path() ? set_in.parent_path().string() : ".";
            }
        }
        // An entry that only other scenarios read would be silently
        // ignored: refused, naming who reads it.
        for (const auto &[key, origin] : origins)
          {
            const auto reader = readers.find(key);
            if (reader == readers.end() || reader->second.count(scenario))
              continue;
            // One scenario that a file chooses by name reads it: "is read
            // only when Problem/Scenario = general"; else name the readers.
            const auto                  slash = key.rfind('/');
            const ScenarioRegistration *only = nullptr, *current = nullptr;
            for (const auto &registered : registered_scenarios())
              {
                if (reader->second.size() == 1 &&
                    registered.name == *reader->second.begin() &&
                    !registered.is_default)
                  only = &registered;
                if (registered.name == scenario)
                  current = &registered;
              }
            const std::string why =
              scenario_parameters.at(scenario)->why_not_read(key);
            require(false,
                    key.substr(0, slash),
                    key.substr(slash + 1),
                    !why.empty() ?
                      why :
                    only != nullptr ?
                      "is read only when Problem/Scenario = " + only->name :
                      "is read for " + describe_readers(reader->second) +
                        " only, but Problem/Scenario is " + scenario +
                        current->foreign_entry_hint);
          }
        // The common subsections' checks first, the scenario's last: they
        // compare its entries with the common ones.
        mesh.finish(mesh_folder);
        refinement.finish();
        materials.finish(origins.count(entry_key("Materials", "Material law")) >
                           0,
                         notes);
        require(refinement.adaptive_cycles == 0 ||
                  refinement.maximum_level > mesh.global_refinements,
                "Mesh refinement",
                "Maximum level",
                "is " + std::to_string(refinement.maximum_level) +
                  ", not above Mesh/Global refinements (" +
                  std::to_string(mesh.global_refinements) +
                  "): adaptive refinement could refine nothing");
        contact.finish();
        load.finish();
        output.finish(name);
        scenario_parameters.at(scenario)->finish(*this);
        dimension = scenario_parameters.at(scenario)->dimension();
        if (dimension == 3)
          refuse_two_dimensional_entries();
        contact.choose_schemes(
          scenario_parameters.at(scenario)->default_integration_schemes(),
          scenario_parameters.at(scenario)->highest_displacement_degree());
      }
    catch (const ParameterError &e)
      {
        throw std::runtime_error(located(e));
      }
    used_parameters = describe_used_parameters(prm);
  }


  // What a 3D problem does not have yet, each refused with the entry that
  // asks for it: friction (frictionless 3D contact, its friction the next
  // step), adaptive refinement, the plane assumption (a 3D body has none),
  // and the Newton-Cotes rules of the 2D segments (the 3D schemes are
  // segment-based, nodal and Gauss n x n).
  void
  Parameters::refuse_two_dimensional_entries() const
  {
    using namespace ParameterChecks;
    require(contact.friction_coefficient == 0,
            "Contact",
            "Friction coefficient",
            "must be 0 in 3D: 3D contact is frictionless so far");
    require(refinement.adaptive_cycles == 0,
            "Mesh refinement",
            "Adaptive cycles",
            "must be 0 in 3D: adaptive refinement is 2D only so far");
    require(origins.count("Materials/Plane assumption") == 0,
            "Materials",
            "Plane assumption",
            "is a 2D entry: a 3D body has no plane assumption (remove the "
            "line)");
    for (const auto &scheme : contact.schemes)
      require(scheme.cuts_at_master_kinks() || scheme.family->name == "nodal" ||
                scheme.family->name == "Gauss",
              "Contact",
              "Integration schemes",
              "'" + scheme.name() +
                "' is a 2D scheme: in 3D the schemes are segment-based, "
                "nodal and Gauss n (n x n points per slave face)");
  }


  // The record of the entries as they ran (results/<name>/used_parameters.prm):
  // deal.II's own listing of every entry, its includes resolved, in which
  // the entries the file (or --set) set stay `set` lines and the others
  // become comments that show their default, so that the file runs the same
  // problem again: an entry set to its default would not be the same (a
  // scenario replaces the probe point the file leaves alone), and the
  // entries of other scenarios are left out (a file that set them would be
  // refused). A relative mesh path is written resolved, since the record
  // lies in another folder.
  std::string
  Parameters::describe_used_parameters(const ParameterHandler &prm) const
  {
    std::ostringstream listing;
    prm.print_parameters(listing, ParameterHandler::ShortPRM);
    std::istringstream       in(listing.str());
    std::vector<std::string> path, pending;
    std::string              line, text;
    // Subsection lines wait until something is written inside them.
    std::vector<bool> opened;
    while (std::getline(in, line))
      {
        const std::string trimmed = Utilities::trim(line);
        if (trimmed.rfind("subsection ", 0) == 0)
          {
            path.push_back(trimmed.substr(11));
            pending.push_back(line);
            opened.push_back(false);
            continue;
          }
        if (trimmed == "end")
          {
            if (opened.back())
              text += line + "\n";
            path.pop_back();
            pending.pop_back();
            opened.pop_back();
            continue;
          }
        const std::size_t equal = trimmed.find('=');
        if (trimmed.rfind("set ", 0) != 0 || equal == std::string::npos)
          continue;
        std::string subsection;
        for (const auto &p : path)
          subsection += (subsection.empty() ? "" : "/") + p;
        const std::string entry = Utilities::trim(trimmed.substr(4, equal - 4));
        const std::string key   = entry_key(subsection, entry);
        const auto        reader = readers.find(key);
        if (reader != readers.end() && reader->second.count(scenario) == 0)
          continue;
        for (unsigned int k = 0; k < path.size(); ++k)
          if (!opened[k])
            {
              text += pending[k] + "\n";
              opened[k] = true;
            }
        const std::string indent = line.substr(0, line.find("set "));
        std::string       value  = Utilities::trim(trimmed.substr(equal + 1));
        if (key == entry_key("Mesh", "Mesh file") && !value.empty())
          value = mesh.mesh_file;
        if (origins.count(key))
          text += indent + "set " + entry + " = " + value + "\n";
        else
          text += indent + "# set " + entry + " = " + value + "  (default)\n";
      }
    std::string set_on_command_line;
    for (const auto &[key, origin] : origins)
      if (origin.line == 0)
        set_on_command_line += "#   " + key + "\n";
    return "# The parameters of a run of ring_contact on " + prm_file +
           ", as it ran:\n"
           "# the entries the file set (includes resolved) and, as comments, "
           "the\n# defaults of the others. `ring_contact used_parameters.prm` "
           "runs it again.\n" +
           (set_on_command_line.empty() ?
              std::string() :
              "# Set on the command line (--set):\n" + set_on_command_line) +
           text;
  }

  // Name the file and line that set the value, or say that it is the default:
  // for the checks once the file is read (the finish() functions), and for
  // those that need the mesh (a traction on a supported direction, a rule too
  // low for the surfaces' degree), which come later (driver/run.cc). The
  // actions' own refusals are located by the reader as it reads.
  std::string
  Parameters::located(const ParameterError &e) const
  {
    const auto origin = origins.find(entry_key(e.subsection, e.entry));
    // Line 0: set on the command line (--set k), named by itself.
    if (origin != origins.end())
      return origin->second.file +
             (origin->second.line == 0 ?
                std::string() :
                ":" + std::to_string(origin->second.line)) +
             ": " + e.what();
    return prm_file + ": " + e.what() + " ('" + e.entry +
           "' is not set in the file: its default)";
  }

  // A Parameters of its own: the actions bind the entries to its members, which
  // must outlive the handler, and its values are the defaults.
  void
  Parameters::print_reference(std::ostream &out, const bool as_prm)
  {
    ParameterHandler prm;
    Parameters       defaults;
    defaults.add_parameters(prm);
    prm.print_parameters(out,
                         as_prm ? ParameterHandler::PRM :
                                  ParameterHandler::Text);
  }
} // namespace RingContact
