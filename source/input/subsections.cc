// @sect3{Run-time parameters: the common subsections}
//
// One struct per subsection of the parameter file that every problem reads,
// each with its add_parameters() and, where entries depend on each other,
// its finish(): here those of the model (Mesh, Mesh refinement, Materials,
// Finite elements, Contact); those of the run (Load program, Newton,
// Output, Checks) are in run_subsections.cc. How an entry is declared, checked
// and documented is told at the top of parameters.cc, which assembles these
// subsections and the scenarios' own into the whole file.
#include <ring_contact/base/dimension.h>
#include <ring_contact/base/utilities.h>
#include <ring_contact/input/gmsh_file.h>
#include <ring_contact/input/parameter_checks.h>
#include <ring_contact/input/parameter_file.h>
#include <ring_contact/input/parameters.h>
#include <ring_contact/materials/material.h>
#include <ring_contact/problem/refinement_estimator.h>
#include <ring_contact/scenarios/scenario.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/numbers.h>
#include <deal.II/base/utilities.h>

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <tuple>

namespace RingContact
{

  namespace
  {
    using namespace ParameterChecks;

    // A gmsh script is text written by hand: a few kilobytes. It is read whole
    // to look for the names of 'Geo parameters' in it, and the bound keeps that
    // from reading a file of any size into memory.
    constexpr std::size_t max_geo_file_bytes = std::size_t(64) << 20;

    // 'name = value, name = value' of the entry 'Geo parameters'. The names are
    // gmsh's (letters, digits and _, not starting with a digit). Each value
    // goes to gmsh as it is, so it is held to what every number of the file
    // must be: the whole text one number (strtod's end at the terminator,
    // '1e3x' refused), 0 or between 1e-300 and 1e300 in magnitude.
    std::vector<std::pair<std::string, double>>
    parse_geo_numbers(const std::string &text)
    {
      std::vector<std::pair<std::string, double>> numbers;
      for (const auto &[name, value] :
           get_assignments(text,
                           "Mesh",
                           "Geo parameters",
                           "Ne = 80, Nr1 = 6",
                           "a gmsh variable name (letters, digits and _, not "
                           "starting with a digit)",
                           false))
        {
          char        *end    = nullptr;
          const double number = std::strtod(value.c_str(), &end);
          require(!value.empty() && *end == '\0' && std::isfinite(number) &&
                    (number == 0 ||
                     (std::abs(number) >= 1e-300 && std::abs(number) <= 1e300)),
                  "Mesh",
                  "Geo parameters",
                  "gives '" + name + "' the value '" + printable(value) +
                    "', which is not a usable number");
          numbers.emplace_back(name, number);
        }
      return numbers;
    }

    // Whether `name` occurs in `text` as a whole word: a name 'R' must not
    // count as found inside the script's 'R1' or 'Rmax', or a misspelt name
    // would pass.
    bool
    occurs_as_word(const std::string &text, const std::string &name)
    {
      const auto word_character = [](const char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
      };
      for (std::size_t at = text.find(name); at != std::string::npos;
           at             = text.find(name, at + 1))
        if ((at == 0 || !word_character(text[at - 1])) &&
            (at + name.size() == text.size() ||
             !word_character(text[at + name.size()])))
          return true;
      return false;
    }

  } // namespace

  using namespace ParameterChecks;

  // @sect4{Subsection Mesh}
  //
  // Where the mesh comes from. The rings build theirs in code for any number of
  // elements, or read it from a gmsh file (the original's own meshes included);
  // the patch test builds its blocks in code; a general problem always reads a
  // gmsh file or script. The entries that shape a generated mesh (elements
  // around, radii, sector) are the rings' own, declared by the rings' scenario.

  void
  MeshParameters::add_parameters(ParameterHandler &prm)
  {
    Subsection s(prm, "Mesh");
    s.add("Mesh source",
          "generated",
          Patterns::Selection("generated|gmsh file|patch test"),
          "generated: the scenario builds its mesh in code (the rings of "
          "any size and number of elements); gmsh file: read from 'Mesh "
          "file'.",
          [this](const std::string &text) {
            // The patch test was a mesh source before it became a scenario.
            // 'patch test' stays in the pattern for that reason: an old file
            // that sets it is told where the patch test went, instead of
            // getting deal.II's list of the allowed values.
            require(text != "patch test",
                    "Mesh",
                    "Mesh source",
                    "= patch test: the patch test is a scenario now, set "
                    "'Scenario = patch test' in subsection Problem (its "
                    "entries are in subsection Patch test)");
            source = text == "generated" ? MeshSource::generated :
                                           MeshSource::gmsh_file;
          });
    // Stored as written. A relative path is resolved in finish(): it is
    // relative to the folder of the file that set it, which is known only once
    // the reader has recorded where each entry came from.
    s.add("Mesh file",
          mesh_file,
          "",
          "gmsh mesh with the scenario's physical tags, read by gmsh's own "
          "library: a .msh file (formats 1, 2.2 and 4.1, ASCII or binary; "
          "quadrilaterals of 4, 8 or 9 nodes and lines of 2 or 3 nodes), or "
          "a gmsh script (.geo) that gmsh meshes in 2d when the program "
          "reads it, with elements of order 1 if every body has "
          "displacement degree 1 and 2 otherwise (see 'Geo parameters'; a "
          "script is a program: give only trusted ones). The cells are the "
          "vertices only: curved boundaries come from the scenario's "
          "geometry. A relative path is taken from the folder of the .prm "
          "file that sets it (an included file's own folder).");
    // Parsed when its line is read; whether each name occurs in the script is
    // checked in finish(), since 'Mesh file' may be set after this entry.
    s.add("Geo parameters",
          "",
          Patterns::Anything(),
          "Numbers handed to a .geo 'Mesh file', as gmsh's "
          "'-setnumber name value' does: comma-separated "
          "'name = value' pairs, e.g. 'Ne = 80, Nr1 = 6'. "
          "Each name must be set in the script with "
          "DefineConstant[] (a plain assignment in the script "
          "overrides the number) and must occur in it. Empty: "
          "the script's own values. Only with a .geo file.",
          [this](const std::string &text) {
            geo_numbers = parse_geo_numbers(text);
          });
    // At most 8: each refinement multiplies the cells by 4, and 8 of them make
    // the seed rings' 240 cells 15.7 million. Whether the refined mesh fits the
    // machine is checked before it is made (Geometry::check_size()).
    s.add("Global refinements",
          global_refinements,
          "0",
          0,
          8,
          "Uniform refinements of the mesh; new vertices are placed on the "
          "scenario's curved boundaries.");
  }

  void
  MeshParameters::finish(const std::string &prm_folder)
  {
    if (source == MeshSource::gmsh_file)
      {
        require(!mesh_file.empty(),
                "Mesh",
                "Mesh file",
                "is empty but 'Mesh source' is 'gmsh file'");
        // A relative path is taken from the folder of the .prm file that set
        // the entry (an included file's own folder, as Parameters::read() found
        // it), so that a file and its mesh can move together and be included
        // from anywhere.
        std::filesystem::path path(mesh_file);
        if (path.is_relative())
          path = std::filesystem::path(prm_folder) / path;
        mesh_file = path.lexically_normal().string();
        // Checked here, so that the error names the entry and its line; gmsh
        // reads the file much later, in a child process. The error_code
        // overloads do not throw: a path that cannot be examined reads as
        // absent, with this message, instead of escaping as a filesystem_error
        // that names no entry.
        std::error_code error;
        require(std::filesystem::exists(mesh_file, error),
                "Mesh",
                "Mesh file",
                "names a file that does not exist: " + printable(mesh_file));
        require(std::filesystem::is_regular_file(mesh_file, error),
                "Mesh",
                "Mesh file",
                "names something that is not a regular file: " +
                  printable(mesh_file));
      }
    require(geo_numbers.empty() || (source == MeshSource::gmsh_file &&
                                    Geometry::is_geo_file(mesh_file)),
            "Mesh",
            "Geo parameters",
            "needs a gmsh script as mesh ('Mesh source' = gmsh file and "
            "a 'Mesh file' ending in .geo)");
    if (!geo_numbers.empty())
      {
        // gmsh 4.8's API cannot list a script's variables, and gmsh
        // ignores a number the script does not use: at least catch a
        // misspelt name.
        const std::string script =
          read_text_file(mesh_file, "mesh file", max_geo_file_bytes);
        for (const auto &[name, value] : geo_numbers)
          require(occurs_as_word(script, name),
                  "Mesh",
                  "Geo parameters",
                  "names '" + name + "', which does not occur in " +
                    printable(mesh_file, 200));
      }
  }

  // @sect4{Subsection Mesh refinement}
  //
  // Adaptive refinement (problem/refinement.cc): after a load step has
  // converged, the cells with the largest error estimates are refined (and
  // those with the smallest coarsened), the state is carried to the new
  // mesh and the step is solved again there, 'Adaptive cycles' times. The
  // fractions are of the number of cells, as deal.II's
  // GridRefinement::refine_and_coarsen_fixed_number() takes them: a
  // fraction of the error (Doerfler's marking) refined a few cells at the
  // load's corners per cycle, and the pressure's L2 error stayed large (Hertz:
  // doc/validation.md, "Adaptive refinement").
  void
  RefinementParameters::add_parameters(ParameterHandler &prm)
  {
    Subsection s(prm, "Mesh refinement");
    s.add("Adaptive cycles",
          adaptive_cycles,
          "0",
          0,
          30,
          "How many times a refined step is refined again and solved on the "
          "new mesh. 0: no adaptive refinement (the mesh of subsection Mesh "
          "throughout).");
    // The registered estimators (problem/estimators/), each documented by
    // its own words after the one it builds on.
    s.add("Estimator",
          estimator,
          "Contact weighted",
          "The error indicator of a cell. " +
            refinement_estimators_documentation(),
          Patterns::Selection(RefinementEstimators::selection()));
    // 0.1 by default: on Hertz a small L2 error of the pressure took far fewer
    // unknowns in cycles of 0.1 than in cycles of 0.3, which refine far from
    // the contact too (doc/validation.md, "Adaptive refinement").
    s.add("Refine fraction",
          refine_fraction,
          "0.1",
          "The fraction of the cells, those of largest indicator, refined in "
          "each cycle (between 0 and 1).",
          {[](const double x) { return x >= 0 && x <= 1; },
           "must lie between 0 and 1"});
    s.add("Coarsen fraction",
          coarsen_fraction,
          "0",
          "The fraction of the cells, those of smallest indicator, coarsened "
          "in each cycle (between 0 and 1; with 'Refine fraction' at most "
          "1). Cells are never coarsened below the mesh of subsection Mesh.",
          {[](const double x) { return x >= 0 && x <= 1; },
           "must lie between 0 and 1"});
    s.add("Refine every",
          every,
          "1",
          1,
          100000,
          "Refine after every k-th load step (k = 1: every step); the last "
          "step is always refined.");
    s.add("Maximum level",
          maximum_level,
          "10",
          1,
          20,
          "The finest cells: a cell of the coarse mesh (the scenario's, before "
          "'Global refinements') is refined at most this many times, the "
          "global refinements included.");
    // A bound that a refinement running away meets before the machine's
    // memory does: the rings refined at each of their 21 steps grew 1.8
    // times a step.
    s.add("Maximum cells",
          maximum_cells,
          "200000",
          100,
          100000000,
          "The mesh is not refined beyond about this many cells (deal.II "
          "lowers the fractions as it nears it); once there, steps keep "
          "their mesh, and the run says so.");
  }

  void
  RefinementParameters::finish()
  {
    require(refine_fraction + coarsen_fraction <= 1,
            "Mesh refinement",
            "Coarsen fraction",
            "and 'Refine fraction' add up to more than 1");
  }

  // @sect4{Subsection Materials}
  //
  // The material law and the plane assumption, shared by all bodies. The
  // elastic constants are each scenario's (the rings', the blocks', the
  // bodies' of a general problem), and a general problem's body may choose
  // its own law. The laws are registered (materials/material.h): the
  // entry's choices and documentation are the registry's.

  void
  MaterialParameters::add_parameters(ParameterHandler &prm)
  {
    Subsection s(prm, "Materials");
    // Saint Venant-Kirchhoff by default, as the original computes
    // (GROT_GDEP): the inner ring turns through a finite angle, and a
    // linearised rotation through one element strains it by cos 9 deg - 1 =
    // -1.2 %, as much as the elastic strains that carry the pressure
    // (doc/intro.md). Small strain is the check of the discretisation alone
    // against the small-strain closed form.
    s.add("Material law",
          "Saint Venant-Kirchhoff",
          Patterns::Selection(MaterialLaws::selection()),
          "The law of every body. " + MaterialLaws::documentation(),
          [this](const std::string &text) { law = text; });
    // The entry's name until version 0.11: a kinematics chose the law.
    // Still read, with a note (finish()).
    s.add("Kinematics",
          "",
          Patterns::Selection("|" + MaterialLaws::selection()),
          "The old name of Material law, still read (with a note): "
          "finite strain, small strain, logarithmic strain and neo-Hookean "
          "choose Saint Venant-Kirchhoff, linear elasticity, Hencky and "
          "neo-Hookean.",
          [this](const std::string &text) { old_kinematics = text; });
    // Plane stress, the original's C_PLAN, is that of every modelisation but B.
    s.add("Plane assumption",
          plane,
          "plane stress",
          {{"plane stress", PlaneAssumption::plane_stress},
           {"plane strain", PlaneAssumption::plane_strain}},
          "plane stress (S33 = 0, C_PLAN) or plane strain "
          "(E33 = 0, D_PLAN).");
  }

  // A law under one of its old names (finite strain, small strain,
  // logarithmic strain, until version 0.11) is read as the law, with a note,
  // as the entry's old name is.
  void
  MaterialParameters::finish(const bool                law_set,
                             std::vector<std::string> &notes)
  {
    const std::string name = MaterialLaws::get(law).name;
    if (name != law)
      notes.push_back("Note: '" + law + "' is the old name of the law '" +
                      name + "'; read as Materials/Material law = " + name +
                      ".");
    law = name;
    if (old_kinematics.empty())
      return;
    const std::string old_law = MaterialLaws::get(old_kinematics).name;
    require(!law_set || old_law == law,
            "Materials",
            "Kinematics",
            "is the old name of Material law, which the file sets to '" + law +
              "'; give Material law alone");
    law = old_law;
    notes.push_back("Note: Materials/Kinematics is the old name of "
                    "Materials/Material law; read as Material law = " +
                    law + ".");
  }

  // @sect4{Subsection Finite elements}
  //
  // The displacement degree is each body's, a scenario entry. What is common is
  // the degree of the multiplier, the mapping of the geometry and the bulk
  // quadrature.

  void
  FiniteElementParameters::add_parameters(ParameterHandler &prm)
  {
    Subsection s(prm, "Finite elements");
    // Linear by default, on a quadratic slave too (G, H): a linear multiplier
    // against quadratic displacements satisfies the inf-sup condition, where
    // one as rich as the slave's displacement would not (doc/intro.md). The
    // bound by the slave's degree needs the scenario's bodies and is checked by
    // each scenario.
    s.add("Multiplier degree",
          multiplier_degree,
          "1",
          1,
          2,
          "Degree of the contact pressure (Lagrange multiplier) "
          "on the slave surface; at most the slave's "
          "displacement degree.");
    // 1 by default: the original's linear meshes are faceted circles. 0 is the
    // original's isoparametric choice, curved quadratic rings; with rings of
    // different degrees it puts a curved surface against a faceted one, and the
    // two overlap before any load (diagnostics/surfaces_at_rest.cc
    // warns of it).
    s.add("Mapping degree",
          mapping_degree,
          "1",
          0,
          4,
          "1: straight element edges (faceted circles, as the "
          "original's linear mesh); 2 or more: edges follow the "
          "circles (polar manifold); 0: isoparametric, each "
          "ring's mapping degree is its displacement degree "
          "(as the original's meshes: linear rings faceted, "
          "quadratic rings curved).");
    // Modelisation H (the original's C_PLAN_SI): 2 x 2 Gauss points on the
    // 9-node quadrilateral, a rule that leaves the element zero-energy modes.
    s.add("Reduced integration",
          reduced_integration,
          "false",
          "Integrate the bulk with p x p Gauss points instead of "
          "(p+1) x (p+1).");
  }

  namespace
  {
    // 'automatic' by default: the scenario's choice, made once the file is
    // read (ContactParameters::choose_schemes()), since it depends on the
    // scenario and the elements. The schemes of a list are run one after the
    // other on the same mesh and load program, each with its own output
    // files, so that one file compares them. Each name is parsed by
    // IntegrationScheme::parse(); the list is the member `schemes` of
    // ContactParameters, empty for 'automatic'.
    void
    add_integration_schemes(Subsection                     &s,
                            std::vector<IntegrationScheme> &schemes)
    {
      s.add("Integration schemes",
            "automatic",
            Patterns::List(Patterns::Anything(), 1),
            // Each family's own words (contact/schemes/) follow.
            "Comma-separated list; one analysis is run per scheme. "
            "automatic: segment-based at the degree the surfaces need "
            "(nodal for the rings of SSNP152, the original's). " +
              integration_schemes_documentation(),
            [&schemes](const std::string &text) {
              // The action runs on the default first, then on the file's value.
              schemes.clear();
              if (Utilities::trim(text) == "automatic")
                return;
              for (const auto &entry : Utilities::split_string_list(text))
                {
                  // parse() knows the schemes but not the file: its message
                  // becomes a ParameterError of this entry, reported at its
                  // line.
                  try
                    {
                      schemes.push_back(IntegrationScheme::parse(entry));
                    }
                  catch (const std::exception &e)
                    {
                      require(false,
                              "Contact",
                              "Integration schemes",
                              e.what());
                    }
                }
            });
    }
  } // namespace

  // @sect4{Subsection Contact}
  //
  // The first contact pair, and what every pair shares: the integration
  // schemes, the normals, the complementarity constant, friction and the
  // reported pressure. A general problem's further pairs ('Contact pair 2' to
  // '4') give only their two surfaces.

  void
  ContactParameters::add_parameters(
    ParameterHandler                            &prm,
    const std::pair<unsigned int, unsigned int> &surfaces)
  {
    Subsection s(prm, "Contact");
    // The defaults are the default scenario's surfaces (the original's tags,
    // scenarios/ssnp152). Tags go up to 1e9 because gmsh's are ints.
    s.add("Slave boundary",
          slave_boundary_id,
          std::to_string(surfaces.first),
          0,
          max_tag,
          "Boundary id (gmsh physical tag) of the slave surface, "
          "which carries the contact pressure (the rings: 400, S2R2, the "
          "inner ring's, or 300, S1R2, the outer ring's).");
    s.add("Master boundary",
          master_boundary_id,
          std::to_string(surfaces.second),
          0,
          max_tag,
          "Boundary id of the master surface (the normal is the "
          "master's outward normal).");
    add_integration_schemes(s, schemes);
    // Off by default: the master's facet normals, and the length-weighted
    // vertex normal at a vertex. The files of modelisations C to H switch the
    // smoothing on (the original's LISSAGE).
    s.add("Smooth master normals",
          smooth_master_normals,
          "false",
          "Use averaged nodal normals on the master surface "
          "(the original's LISSAGE).");
    // c only decides the active set: at a converged state each node has
    // lambda_k = 0 or g~_k = 0 whatever c is. During the iteration it weighs
    // the weighted gap against the multiplier, c g~_k against w_k lambda_k,
    // both forces per unit thickness. With c = E/h, c times a gap is the stress
    // that would squeeze an element of size h by that gap, of the order of the
    // pressure it is compared with. The automatic value takes the stiffest body
    // and the shortest slave segment.
    s.add("Complementarity constant",
          complementarity_constant,
          "0",
          "c [Pa/m] in the complementarity function "
          "lambda - max(0, lambda - c g); it decides the active "
          "set, not the converged solution. 0: automatic, the "
          "largest Young's modulus over the smallest slave "
          "segment length.",
          not_negative());
    // 0 by default: the rings' case is frictionless. With 0 the tangential
    // multiplier is FE_Nothing, so a frictionless run has the same unknowns,
    // numbering and digits as before friction existed (doc/design.md).
    s.add("Friction coefficient",
          friction_coefficient,
          "0",
          "Coulomb's mu: the tangential traction |t| <= mu p, sticking below "
          "the bound and opposed to the slip at it (a second multiplier on "
          "the slave surface). 0: frictionless, without that multiplier.",
          not_negative());
    // The unknown is the Cauchy pressure, force per current length. The
    // original reports the nominal one (its LAGS_C, per reference length),
    // which 'nominal' reproduces to Code_Aster's digits. At p = 1e7 Pa the
    // interface circle shrinks by about 1 %, and the nominal pressure is lower
    // by as much: as large as the effects the checks measure, so a comparison
    // must say which of the two it uses.
    s.add("Reported pressure",
          reported_pressure,
          "Cauchy",
          {{"Cauchy", PressureMeasure::cauchy},
           {"nominal", PressureMeasure::nominal}},
          "Cauchy: force per current length of the slave "
          "surface (the multiplier itself); nominal: force per "
          "reference length.");
  }

  // Checked once the file is read, since either entry may be set first. A
  // surface is not in contact with itself: the program has no self-contact.
  void
  ContactParameters::finish() const
  {
    require(slave_boundary_id != master_boundary_id,
            "Contact",
            "Slave boundary",
            "must differ from 'Master boundary' (both are " +
              std::to_string(slave_boundary_id) + ")");
  }

  // The schemes that run: the scenario's default where the file names none,
  // and 'segment-based' without a number given the points its surfaces need.
  // p + 1 Gauss points on each piece, as the bulk's rule has per direction:
  // exact to degree 2 p + 1, above the degree p + q of the mortar integrand
  // Phi_k psi_i on a straight piece (q <= p, the multiplier's degree), with
  // a margin for the curved surfaces' length element and normal, and more
  // points than the multiplier has nodes on a piece (see contact_quadrature(),
  // which the setup asks of every listed scheme on every pair before the
  // first scheme runs).
  void
  ContactParameters::choose_schemes(const std::string &scenario_default,
                                    const unsigned int displacement_degree)
  {
    if (schemes.empty())
      for (const auto &entry : Utilities::split_string_list(scenario_default))
        schemes.push_back(IntegrationScheme::parse(entry));
    for (IntegrationScheme &scheme : schemes)
      if (scheme.family->default_points && scheme.n_points == 0)
        scheme.n_points = scheme.family->default_points(displacement_degree);
    // One run per scheme: a scheme listed twice would run twice and write
    // its files over its own.
    for (unsigned int k = 0; k < schemes.size(); ++k)
      for (unsigned int j = 0; j < k; ++j)
        require(schemes[j].name() != schemes[k].name(),
                "Contact",
                "Integration schemes",
                "lists '" + schemes[k].name() + "' twice" +
                  (schemes[k].family->default_points ?
                     " ('" + schemes[k].family->name + "' is " +
                       schemes[k].family->name + " " +
                       std::to_string(schemes[k].family->default_points(
                         displacement_degree)) +
                       " on these elements)" :
                     std::string()));
  }

} // namespace RingContact
