#include <ring_contact/gmsh_file.h>
#include <ring_contact/parameter_checks.h>
#include <ring_contact/parameter_file.h>
#include <ring_contact/parameters.h>
#include <ring_contact/utilities.h>

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
  namespace ParameterChecks
  {
    std::string
    to_text(const double value)
    {
      std::ostringstream out;
      out << value;
      return out.str();
    }

    // Throw a one-line error that names the entry, when `ok` is false
    // (Parameters::read() adds the file and line that set the value).
    void
    require(const bool         ok,
            const std::string &subsection,
            const std::string &entry,
            const std::string &what)
    {
      if (!ok)
        throw ParameterError(subsection,
                             entry,
                             "parameter '" + entry + "' in subsection '" +
                               subsection + "' " + what);
    }

    Condition
    positive(const std::string &what)
    {
      return {[](const double x) { return x > 0; }, what};
    }

    Condition
    not_negative()
    {
      return {nullptr, "", 0};
    }

    // The value of an entry as a finite double. The pattern has accepted
    // the text, but e.g. 1e-320 (a denormal) or 1e999 still cannot be
    // converted by deal.II: say so, naming the entry and the value.
    double
    number_from_text(const std::string &text,
                     const std::string &subsection,
                     const std::string &entry)
    {
      double value = 0;
      bool   ok    = true;
      try
        {
          value = Utilities::string_to_double(text);
        }
      catch (...)
        {
          ok = false;
        }
      require(ok && std::isfinite(value) &&
                (value == 0 ||
                 (std::abs(value) >= 1e-300 && std::abs(value) <= 1e300)),
              subsection,
              entry,
              "has the value '" + printable(text) +
                "', which is not a usable number (a floating-point number "
                "between 1e-300 and 1e300 in magnitude, or 0)");
      return value;
    }

    Subsection::Subsection(ParameterHandler &prm, const std::string &name)
        : name(name)
        , prm(prm)
    {
      prm.enter_subsection(name);
    }

    Subsection::~Subsection()
    {
      prm.leave_subsection();
    }

    void
    Subsection::add(const std::string           &entry,
                    const std::string           &default_value,
                    const Patterns::PatternBase &pattern,
                    const std::string           &documentation,
                    const std::function<void(const std::string &)> &read)
    {
      prm.declare_entry(entry, default_value, pattern, documentation);
      // Run on the default now, and on every value the file sets.
      prm.add_action(entry, read);
    }

    void
    Subsection::add(const std::string &entry,
                    double            &variable,
                    const std::string &default_value,
                    const std::string &documentation,
                    const Condition   &condition)
    {
      const std::string section = name;
      add(entry,
          default_value,
          Patterns::Double(condition.lowest),
          documentation,
          [&variable, section, entry, condition](const std::string &text) {
            const double value = number_from_text(text, section, entry);
            require(!condition.holds || condition.holds(value),
                    section,
                    entry,
                    condition.what + ", got " + to_text(value));
            variable = value;
          });
    }

    void
    Subsection::add(const std::string &entry,
                    unsigned int      &variable,
                    const std::string &default_value,
                    const int          lowest,
                    const int          highest,
                    const std::string &documentation)
    {
      add(entry,
          default_value,
          Patterns::Integer(lowest, highest),
          documentation,
          [&variable](const std::string &text) {
            variable = Utilities::string_to_int(text);
          });
    }

    void
    Subsection::add(const std::string &entry,
                    bool              &variable,
                    const std::string &default_value,
                    const std::string &documentation)
    {
      add(entry,
          default_value,
          Patterns::Bool(),
          documentation,
          [&variable](const std::string &text) {
            variable = (text == "true" || text == "yes");
          });
    }

    void
    Subsection::add(const std::string           &entry,
                    std::string                 &variable,
                    const std::string           &default_value,
                    const std::string           &documentation,
                    const Patterns::PatternBase &pattern)
    {
      add(entry,
          default_value,
          pattern,
          documentation,
          [&variable](const std::string &text) { variable = text; });
    }

    std::vector<std::pair<std::string, std::string>>
    get_assignments(const std::string &text,
                    const std::string &subsection,
                    const std::string &entry,
                    const std::string &example,
                    const std::string &kind_of_name,
                    const bool         leading_letter)
    {
      std::vector<std::pair<std::string, std::string>> items;
      if (Utilities::trim(text).empty())
        return items;
      const auto fail = [&](const std::string &what) {
        require(false, subsection, entry, what);
      };
      for (const std::string &item : Utilities::split_string_list(text, ','))
        {
          const std::size_t equal = item.find('=');
          if (equal == std::string::npos)
            fail("holds '" + printable(item) + "', not 'name = value' (e.g. '" +
                 example + "')");
          const std::string   name  = Utilities::trim(item.substr(0, equal));
          const std::string   value = Utilities::trim(item.substr(equal + 1));
          const unsigned char first =
            name.empty() ? '0' : static_cast<unsigned char>(name[0]);
          bool identifier = leading_letter ? std::isalpha(first) != 0 :
                                             std::isdigit(first) == 0;
          for (const char c : name)
            identifier =
              identifier &&
              (std::isalnum(static_cast<unsigned char>(c)) || c == '_');
          if (!identifier)
            fail("holds the name '" + printable(name) + "', which is not " +
                 kind_of_name);
          for (const auto &earlier : items)
            if (earlier.first == name)
              fail("gives '" + name + "' twice");
          items.emplace_back(name, value);
        }
      return items;
    }

    void
    steps_from_text(const std::string         &text,
                    const std::string         &subsection,
                    const std::string         &entry,
                    bool                      &every_step,
                    std::vector<unsigned int> &steps)
    {
      const std::string steps_text = Utilities::trim(text);
      require(!steps_text.empty(),
              subsection,
              entry,
              "is empty: give 'all', 'last', 'none' (no checks) or step "
              "numbers");
      every_step = (steps_text == "all");
      steps.clear();
      if (steps_text == "last")
        steps.push_back(numbers::invalid_unsigned_int);
      else if (!every_step && steps_text != "none")
        {
          for (const auto &s : Utilities::split_string_list(steps_text))
            {
              long n = 0;
              try
                {
                  n = Utilities::string_to_int(s);
                }
              catch (...)
                {
                  n = 0;
                }
              require(n >= 1 && n <= 100000,
                      subsection,
                      entry,
                      "must be 'all', 'last', 'none' or step numbers from 1 "
                      "to 100000, got '" +
                        printable(s) + "'");
              steps.push_back(n);
            }
          // "1,,2" or " , " select nothing where something was meant.
          require(!steps.empty(),
                  subsection,
                  entry,
                  "selects no step: give 'all', 'last', 'none' (no checks) "
                  "or step numbers");
        }
    }

    std::array<double, 2>
    point_from_text(const std::string &text,
                    const std::string &subsection,
                    const std::string &entry)
    {
      const auto            xy = Utilities::split_string_list(text);
      std::array<double, 2> point;
      for (unsigned int d = 0; d < 2; ++d)
        {
          double value = 0;
          try
            {
              value = xy.size() == 2 ? Utilities::string_to_double(xy.at(d)) :
                                       std::nan("");
            }
          catch (...)
            {
              value = std::nan("");
            }
          require(std::isfinite(value) && std::abs(value) < 1e300,
                  subsection,
                  entry,
                  "must be two finite coordinates 'x, y', got '" +
                    printable(text) + "'");
          point[d] = value;
        }
      return point;
    }
  } // namespace ParameterChecks

  namespace
  {
    using namespace ParameterChecks;

    // A gmsh script is text written by hand: a few kilobytes.
    constexpr std::size_t max_geo_file_bytes = std::size_t(64) << 20;

    // 'name = value, name = value' of the entry 'Geo parameters'.
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

    // Whether `name` occurs in `text` as a whole word.
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

  // ------------------------------------------------------------------
  // Mesh
  // ------------------------------------------------------------------

  void
  MeshParameters::add_parameters(ParameterHandler &prm)
  {
    Subsection s(prm, "Mesh");
    s.add("Mesh source",
          source,
          "generated",
          {{"generated", MeshSource::generated},
           {"gmsh file", MeshSource::gmsh_file},
           {"patch test", MeshSource::patch_test}},
          "generated: the two rings are built in code; gmsh "
          "file: read from 'Mesh file'; patch test: instead of "
          "the rings, two 1 x 0.5 m blocks with non-matching "
          "meshes pressed together (the upper one is the slave "
          "body, 101, the lower one the master, 100).");
    s.add("Mesh file",
          mesh_file,
          "",
          "gmsh mesh with the physical tags of SSNP152 (100, "
          "101, 200, 300, 400, 500), read by gmsh's own "
          "library: a .msh file (formats 1, 2.2 and 4.1, "
          "ASCII or binary; quadrilaterals of 4, 8 or 9 nodes "
          "and lines of 2 or 3 nodes), or a gmsh script "
          "(.geo) that gmsh meshes in 2d when the program "
          "reads it, with elements of order 1 if both rings "
          "have displacement degree 1 and 2 otherwise (see "
          "'Geo parameters'; a script is a program: give only "
          "trusted ones). The cells are the vertices only: "
          "the circles come from the polar geometry, and "
          "quadratic nodes on the circles are checked to lie "
          "on them. A relative path is taken from the folder "
          "of the .prm file that sets it (an included file's "
          "own folder).");
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
    s.add("Elements around",
          elements_around,
          "40",
          3,
          10000000,
          "Number of elements around every circle (generated mesh).");
    s.add("Radial elements outer ring",
          radial_elements_outer,
          "3",
          1,
          10000000,
          "Elements across the outer ring (generated mesh).");
    s.add("Radial elements inner ring",
          radial_elements_inner,
          "3",
          1,
          10000000,
          "Elements across the inner ring (generated mesh).");
    s.add("Global refinements",
          global_refinements,
          "0",
          0,
          8,
          "Uniform refinements of the mesh; new vertices are "
          "placed on the circles.");
    s.add("Sector elements",
          sector_elements,
          "0",
          0,
          10000000,
          "Cyclic symmetry (generated mesh): model only a sector of this many "
          "elements around, from angle 0, with the displacements of its two "
          "radial sides tied by the rotation through the sector angle and the "
          "master surface continued by rotated copies. The rings, their "
          "meshes and the loads repeat every element, so the solution is the "
          "whole rings' (to round-off) at a fraction of the cost. 0: the "
          "whole rings.");
    s.add("Patch test elements lower block",
          patch_elements_lower,
          "5",
          1,
          100000,
          "Patch test: elements along the interface, lower "
          "(master) block.");
    s.add("Patch test elements upper block",
          patch_elements_upper,
          "7",
          1,
          100000,
          "Patch test: elements along the interface, upper "
          "(slave) block.");
    s.add("Outer radius",
          outer_radius,
          "1.0",
          "R1, outer radius of the outer ring [m].");
    s.add("Interface radius",
          interface_radius,
          "0.6",
          "R2, radius of the contact interface [m].");
    s.add("Inner radius",
          inner_radius,
          "0.2",
          "R3, inner radius of the inner ring [m].",
          positive("must be positive (R3 > 0)"));
  }

  double
  MeshParameters::sector_angle() const
  {
    return 2 * numbers::PI * sector_elements / elements_around;
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
        std::filesystem::path path(mesh_file);
        if (path.is_relative())
          path = std::filesystem::path(prm_folder) / path;
        mesh_file = path.lexically_normal().string();
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
    require(sector_elements == 0 || source == MeshSource::generated,
            "Mesh",
            "Sector elements",
            "needs 'Mesh source' = generated (a sector is built in code)");
    require(sector_elements <= elements_around,
            "Mesh",
            "Sector elements",
            "must be at most 'Elements around' (0: the whole rings)");
    require(inner_radius < interface_radius,
            "Mesh",
            "Inner radius",
            "must be smaller than 'Interface radius' (R3 < R2)");
    require(interface_radius < outer_radius,
            "Mesh",
            "Interface radius",
            "must be smaller than 'Outer radius' (R2 < R1)");
    // The meshes identify their circles to 1e-8 R1: each ring must be
    // much thicker than that.
    require(interface_radius - inner_radius >= 1e-4 * outer_radius &&
              outer_radius - interface_radius >= 1e-4 * outer_radius,
            "Mesh",
            "Interface radius",
            "leaves a ring thinner than 1e-4 R1 (R1 = " +
              to_text(outer_radius) + ", R2 = " + to_text(interface_radius) +
              ", R3 = " + to_text(inner_radius) + ")");
  }

  // ------------------------------------------------------------------
  // Materials
  // ------------------------------------------------------------------

  void
  MaterialParameters::add_parameters(ParameterHandler &prm)
  {
    Subsection      s(prm, "Materials");
    const Condition poisson = {[](const double nu) {
                                 return nu > -1 && nu < 0.5;
                               },
                               "must satisfy -1 < nu < 0.5"};
    s.add("Young's modulus outer ring",
          youngs_modulus_outer,
          "1e9",
          "E1 [Pa], > 0.",
          positive());
    s.add("Poisson's ratio outer ring",
          poissons_ratio_outer,
          "0.2",
          "nu1 [-], -1 < nu1 < 0.5.",
          poisson);
    s.add("Young's modulus inner ring",
          youngs_modulus_inner,
          "1e9",
          "E2 [Pa], > 0.",
          positive());
    s.add("Poisson's ratio inner ring",
          poissons_ratio_inner,
          "0.2",
          "nu2 [-], -1 < nu2 < 0.5.",
          poisson);
    s.add("Kinematics",
          kinematics,
          "finite strain",
          kinematics_choices(),
          "finite strain: total Lagrangian Saint Venant-"
          "Kirchhoff (Green-Lagrange strain, second Piola-"
          "Kirchhoff stress; the original's GROT_GDEP); small "
          "strain: linear elasticity; logarithmic strain: "
          "Hencky, the linear law on the logarithmic strain "
          "ln(C)/2 (current Code_Aster's GDEF_LOG; in plane "
          "stress the out-of-plane stress conjugate to it is "
          "zero); neo-Hookean: the compressible neo-Hookean "
          "law W = mu/2 (tr C - 3 - 2 ln J) + lambda/2 (ln "
          "J)^2 (finite strain; linear elasticity at small "
          "strain; in plane stress F33 from sigma33 = 0).");
    s.add("Plane assumption",
          plane,
          "plane stress",
          {{"plane stress", PlaneAssumption::plane_stress},
           {"plane strain", PlaneAssumption::plane_strain}},
          "plane stress (S33 = 0, C_PLAN) or plane strain "
          "(E33 = 0, D_PLAN).");
  }

  // ------------------------------------------------------------------
  // Finite elements
  // ------------------------------------------------------------------

  void
  FiniteElementParameters::add_parameters(ParameterHandler &prm)
  {
    Subsection s(prm, "Finite elements");
    s.add("Displacement degree outer ring",
          degree_outer,
          "1",
          1,
          2,
          "Polynomial degree of the displacement on the outer "
          "ring (1: Q1, 2: 9-node Q2).");
    s.add("Displacement degree inner ring",
          degree_inner,
          "1",
          1,
          2,
          "Polynomial degree of the displacement on the inner "
          "ring.");
    s.add("Multiplier degree",
          multiplier_degree,
          "1",
          1,
          2,
          "Degree of the contact pressure (Lagrange multiplier) "
          "on the slave surface; at most the slave's "
          "displacement degree.");
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
    s.add("Reduced integration",
          reduced_integration,
          "false",
          "Integrate the bulk with p x p Gauss points instead of "
          "(p+1) x (p+1).");
  }

  // ------------------------------------------------------------------
  // Contact
  // ------------------------------------------------------------------

  void
  ContactParameters::add_parameters(ParameterHandler &prm)
  {
    Subsection s(prm, "Contact");
    s.add("Slave boundary",
          slave_boundary_id,
          "400",
          0,
          max_tag,
          "Boundary id (gmsh physical tag) of the slave surface, "
          "which carries the contact pressure: 400 (S2R2, inner "
          "ring) or 300 (S1R2, outer ring).");
    s.add("Master boundary",
          master_boundary_id,
          "300",
          0,
          max_tag,
          "Boundary id of the master surface (the normal is the "
          "master's outward normal).");
    s.add("Integration schemes",
          "nodal",
          Patterns::List(Patterns::Anything(), 1),
          "Comma-separated list; one analysis is run per scheme. "
          "nodal: at the slave nodes; Gauss n: n Gauss points "
          "per slave segment (1-20); Simpson n: composite "
          "Simpson with n sub-intervals; Newton-Cotes n: closed "
          "Newton-Cotes of order 1, 2, 4 or 6; segment-based "
          "n: each slave segment cut where the lines through "
          "the master vertices along their normals cross it, "
          "n Gauss points on each piece (mortar "
          "integration).",
          [this](const std::string &text) {
            schemes.clear();
            for (const auto &entry : Utilities::split_string_list(text))
              {
                try
                  {
                    schemes.push_back(IntegrationScheme::parse(entry));
                  }
                catch (const std::exception &e)
                  {
                    require(false, "Contact", "Integration schemes", e.what());
                  }
                // One run per scheme: a scheme listed twice would run twice
                // and write its files over its own.
                for (unsigned int k = 0; k + 1 < schemes.size(); ++k)
                  require(schemes[k].name() != schemes.back().name(),
                          "Contact",
                          "Integration schemes",
                          "lists '" + schemes.back().name() + "' twice");
              }
          });
    s.add("Smooth master normals",
          smooth_master_normals,
          "false",
          "Use averaged nodal normals on the master surface "
          "(the original's LISSAGE).");
    s.add("Complementarity constant",
          complementarity_constant,
          "0",
          "c [Pa/m] in the complementarity function "
          "lambda - max(0, lambda - c g); it decides the active "
          "set, not the converged solution. 0: automatic, the "
          "largest Young's modulus over the smallest slave "
          "segment length.",
          not_negative());
    s.add("Friction coefficient",
          friction_coefficient,
          "0",
          "Coulomb's mu: the tangential traction |t| <= mu p, sticking below "
          "the bound and opposed to the slip at it (a second multiplier on "
          "the slave surface). 0: frictionless, without that multiplier.",
          not_negative());
    s.add("Reported pressure",
          reported_pressure,
          "Cauchy",
          {{"Cauchy", PressureMeasure::cauchy},
           {"nominal", PressureMeasure::nominal}},
          "Cauchy: force per current length of the slave "
          "surface (the multiplier itself); nominal: force per "
          "reference length.");
    s.add("Probe point",
          "0.6, 0",
          Patterns::List(Patterns::Double(), 2, 2),
          "Reference position [m] of node A, the slave node "
          "whose pressure is checked (the nearest slave node is "
          "used). Not set: (R2, 0), node A of SSNP152 for any "
          "interface radius.",
          [this](const std::string &text) {
            const auto xy = point_from_text(text, "Contact", "Probe point");
            probe_point   = Point<2>(xy[0], xy[1]);
          });
  }

  void
  ContactParameters::finish() const
  {
    require(slave_boundary_id != master_boundary_id,
            "Contact",
            "Slave boundary",
            "must differ from 'Master boundary' (both are " +
              std::to_string(slave_boundary_id) + ")");
  }

  // ------------------------------------------------------------------
  // Load program
  // ------------------------------------------------------------------

  namespace
  {
    // The entry Time points: numbers and ranges from:step:to.
    std::vector<double>
    parse_time_points(const std::string &text)
    {
      std::vector<double> time_points;
      const std::string   points_text = Utilities::trim(text);
      // A number, or NaN for anything else.
      const auto number = [](const std::string &word) {
        double t = std::nan("");
        try
          {
            t = Utilities::string_to_double(Utilities::trim(word));
          }
        catch (...)
          {}
        return t;
      };
      for (const auto &item : Utilities::split_string_list(points_text))
        {
          const double previous =
            time_points.empty() ? 0.0 : time_points.back();
          const auto parts = Utilities::split_string_list(item, ':');
          if (parts.size() == 3)
            {
              // from:step:to, the points after `from` up to `to`.
              const double from = number(parts[0]), step = number(parts[1]),
                           to = number(parts[2]);
              const double n = std::round((to - from) / std::max(step, 1e-300));
              require(std::isfinite(from) && std::isfinite(step) &&
                        std::isfinite(to) && from >= previous && step > 0 &&
                        to > from &&
                        std::abs(n * step - (to - from)) <= 1e-9 * (to - from),
                      "Load program",
                      "Time points",
                      "has the range '" + printable(item) +
                        "': a range is from:step:to with from at or after "
                        "the previous point, step > 0 dividing to - from "
                        "(e.g. 0:0.02:1, 1:0.005:2)");
              require(time_points.size() + n <= LoadParameters::max_steps,
                      "Load program",
                      "Time points",
                      "gives more than " +
                        std::to_string(LoadParameters::max_steps) +
                        " steps (the range '" + printable(item) + "' has " +
                        to_text(n) + ")");
              for (unsigned int k = 1; k <= n; ++k)
                time_points.push_back(k == n ? to : from + (to - from) * k / n);
              continue;
            }
          const double t = parts.size() == 1 ? number(item) : std::nan("");
          require(std::isfinite(t) && std::abs(t) < 1e300 && t > previous,
                  "Load program",
                  "Time points",
                  "must be increasing finite numbers above 0, got '" +
                    printable(item) + "' in '" + printable(points_text) + "'");
          time_points.push_back(t);
        }
      require(time_points.size() <= LoadParameters::max_steps,
              "Load program",
              "Time points",
              "gives more than " + std::to_string(LoadParameters::max_steps) +
                " steps");
      return time_points;
    }
  } // namespace

  void
  LoadParameters::add_parameters(ParameterHandler &prm)
  {
    Subsection s(prm, "Load program");
    s.add("Program",
          program,
          "ramp",
          {{"ramp", LoadProgramType::ramp},
           {"rotation", LoadProgramType::rotation},
           {"steps", LoadProgramType::steps}},
          "ramp: p(t) = p0 10^(t - 1.1) at t = k dt, imposed "
          "radially (A, B, H); rotation: pressure fixed, the "
          "inner boundary turned through s elements (C-G); "
          "steps: the pseudo-times of 'Time points', or "
          "t = k / n for k = 1..n with n = 'Number of steps' "
          "(Problem/Scenario = general, whose expressions "
          "take t).");
    s.add("Number of steps",
          number_of_steps,
          "1",
          1,
          max_steps,
          "Program = steps: n equal steps from t = 0 to 1.");
    s.add("Time points",
          "",
          Patterns::Anything(),
          "Program = steps: the pseudo-times at the ends of "
          "the steps, increasing from above 0, e.g. '0.1, "
          "0.5, 1', and ranges from:step:to of equal steps "
          "after 'from' up to 'to', e.g. '0:0.02:1, "
          "1:0.005:2' (empty: 'Number of steps' equal "
          "steps).",
          [this](const std::string &text) {
            time_points = parse_time_points(text);
          });
    s.add("Loading",
          loading,
          "imposed displacements",
          {{"imposed displacements", Loading::imposed_displacements},
           {"pressure", Loading::pressure}},
          "imposed displacements: the analytic displacements of pressure p on "
          "r = R1 and r = R3 (the original's loading, the only one the "
          "rotation program takes); pressure: the pressure p on r = R1 as "
          "the problem states it, on the current configuration (a follower "
          "load; a dead load in small strain), r = R3 free, and each ring's "
          "rigid-body modes removed by u_y = 0 at (+-r, 0) and u_x = 0 at "
          "(0, r) of r = R1 and r = R3 (the symmetric solution satisfies "
          "them; the mesh needs nodes there).");
    s.add("Reference pressure",
          reference_pressure,
          "1e6",
          "p0 [Pa] of the ramp (p = p0 at t = 1.1).",
          positive());
    s.add("Ramp steps",
          ramp_steps,
          "21",
          1,
          max_steps,
          "Number of steps of the ramp.");
    s.add("Time step",
          time_step,
          "0.1",
          "dt of the ramp [pseudo-time].",
          positive());
    s.add("Rotation pressure",
          rotation_pressure,
          "1e7",
          "Equivalent pressure p [Pa] held during the rotation.",
          positive());
    s.add("Rotation steps",
          rotation_steps,
          "100",
          1,
          max_steps,
          "Nt, number of equal rotation steps.");
    s.add("Rotation in elements",
          rotation_elements,
          "1",
          "Final rotation parameter s: the angle is "
          "2 pi s / (elements around).");
  }

  void
  LoadParameters::finish()
  {
    if (time_points.empty())
      for (unsigned int k = 1; k <= number_of_steps; ++k)
        time_points.push_back(static_cast<double>(k) / number_of_steps);
    // The last pressure of the ramp, p0 10^(n dt - 1.1), must be a number.
    // Named: the pressure itself when it is beyond reason on its own
    // (over 1e99 Pa), else the time step that ramps it too far.
    require(program != LoadProgramType::ramp ||
              std::log10(reference_pressure) + ramp_steps * time_step - 1.1 <
                100,
            "Load program",
            reference_pressure >= 1e99 ? "Reference pressure" : "Time step",
            "makes the last pressure of the ramp, p0 10^(n dt - 1.1), "
            "exceed 1e100 Pa (p0 = " +
              to_text(reference_pressure) +
              " Pa, n = " + std::to_string(ramp_steps) +
              ", dt = " + to_text(time_step) + ")");
  }

  // ------------------------------------------------------------------
  // Newton
  // ------------------------------------------------------------------

  void
  NewtonParameters::add_parameters(ParameterHandler &prm)
  {
    Subsection s(prm, "Newton");
    s.add("Maximum iterations",
          max_iterations,
          "12",
          1,
          1000,
          "Newton iterations before the step is cut.");
    s.add("Tolerance",
          tolerance,
          "1e-10",
          "Converged when the active set no longer changes and "
          "(a) the residual of the free displacement rows "
          "relative to the reaction forces and (b) the largest "
          "gap of an active contact row relative to the largest "
          "displacement are each below this or at their "
          "round-off floor (10 eps times the magnitude of the "
          "terms of the rows, estimated at every iteration): "
          "scale-free, the same value fits any E, p and radii.",
          {[](const double x) { return x > 0; }, "must be positive", 0});
    s.add("Maximum step cuts",
          max_step_cuts,
          "5",
          0,
          30,
          "How many times a step that fails is halved and "
          "retried before the run stops.");
    s.add("Extrapolate",
          extrapolate,
          "true",
          "Start each step from the linear extrapolation of the "
          "last two converged states.");
    s.add("Verbose",
          verbose,
          "true",
          "Print the residual of every Newton iteration.");
    s.add("Linear solver",
          linear_solver,
          "auto",
          {{"auto", LinearSolverType::automatic},
           {"UMFPACK", LinearSolverType::umfpack},
           {"MUMPS", LinearSolverType::mumps},
           {"iterative", LinearSolverType::iterative}},
          "The solver of the Newton systems. auto: UMFPACK on one process, "
          "MUMPS on several (mpirun -np N ring_contact file.prm). UMFPACK is "
          "serial; MUMPS factorizes on every process together, and also runs "
          "on one (MPI is then started for it). Both keep their analysis of "
          "the matrix while the sparsity pattern does not change. iterative: "
          "GMRES with a block preconditioner (algebraic multigrid on the "
          "displacements, an approximate Schur complement for the "
          "multipliers), for meshes too large to factorize; one or several "
          "processes; its iterations are printed with the Newton iterations.");
    s.add("Linear tolerance",
          linear_tolerance,
          "1e-8",
          "Linear solver = iterative: GMRES stops when the "
          "relative residual |K x - b| / |b| is below this "
          "(1e-14 to 1e-7; the Newton iteration converges as "
          "with a direct solver when it is well below the "
          "Newton tolerance).",
          {[](const double x) { return x >= 1e-14 && x <= 1e-7; },
           "must be between 1e-14 and 1e-7"});
  }

  // ------------------------------------------------------------------
  // Output
  // ------------------------------------------------------------------

  void
  OutputParameters::add_parameters(ParameterHandler &prm)
  {
    Subsection s(prm, "Output");
    s.add("Directory",
          directory,
          "",
          "Where results go; empty: results/<prm file name> in "
          "the current folder.");
    s.add("VTU interval",
          vtu_interval,
          "1",
          0,
          1000000000,
          "Write VTU files every this many steps (0: never; the "
          "last step is always written when > 0).");
    s.add("VTU subdivisions",
          vtu_subdivisions,
          "0",
          0,
          8,
          "Subdivisions of each cell in the VTU files; 0: the "
          "mapping degree (curved cells are shown curved).");
    s.add("Write history",
          write_history,
          "true",
          "Write history.csv (one row per step and scheme) and "
          "verdicts.csv (one row per check).");
    s.add("Print steps",
          print_steps,
          "true",
          "Print one line per step (load, Newton iterations, "
          "pressure at A, error).");
    s.add("Print timing",
          print_timing,
          "true",
          "Print the timing summary at the end, and the direct "
          "solver's factorizations and their flops (switch off in "
          "tests).");
  }

  void
  OutputParameters::finish(const std::string &prm_name)
  {
    if (directory.empty())
      directory = "results/" + prm_name;
  }

  // ------------------------------------------------------------------
  // Checks
  // ------------------------------------------------------------------

  void
  CheckParameters::add_parameters(ParameterHandler &prm)
  {
    Subsection s(prm, "Checks");
    s.add("Quantity",
          quantity,
          "pressure at A",
          {{"pressure at A", CheckedQuantity::pressure_at_A},
           {"L2 error of pressure", CheckedQuantity::l2_pressure_error},
           {"pressure spread", CheckedQuantity::pressure_spread}},
          "The checked value (the original's TEST_RESU): the "
          "contact pressure at node A against the analytic "
          "pressure, the relative L2 error of the pressure "
          "over the slave surface (reference 0), or the spread "
          "(largest - smallest nodal pressure) / analytic "
          "pressure (reference 0).");
    s.add("Steps",
          "all",
          Patterns::Anything(),
          "'all', 'last', 'none', or a comma-separated list of "
          "step numbers (1-based).",
          [this](const std::string &text) {
            steps_from_text(text, "Checks", "Steps", every_step, steps);
          });
    s.add("Tolerance",
          tolerance,
          "0.02",
          "Largest admitted relative error (0.02 = 2 %).",
          not_negative());
  }

  // ------------------------------------------------------------------
  // All of them
  // ------------------------------------------------------------------

  void
  Parameters::add_parameters(ParameterHandler &prm)
  {
    mesh.add_parameters(prm);
    materials.add_parameters(prm);
    finite_elements.add_parameters(prm);
    contact.add_parameters(prm);
    load.add_parameters(prm);
    newton.add_parameters(prm);
    output.add_parameters(prm);
    checks.add_parameters(prm);
    problem.add_parameters(prm);
  }

  namespace
  {
    // The entries that only one scenario reads: set in a file of the other
    // scenario they would be silently ignored, so they are refused.
    bool
    only_for_general(const std::string &key)
    {
      for (const std::string prefix : {"Body ",
                                       "Contact pair ",
                                       "Boundary condition ",
                                       "Check ",
                                       "Problem/Constants",
                                       "Problem/Number of"})
        if (key.rfind(prefix, 0) == 0)
          return true;
      return key == "Load program/Number of steps" ||
             key == "Load program/Time points";
    }

    bool
    only_for_ssnp152(const std::string &key)
    {
      for (const std::string prefix : {"Checks/"})
        if (key.rfind(prefix, 0) == 0)
          return true;
      for (const std::string entry :
           {"Mesh/Elements around",
            "Mesh/Radial elements outer ring",
            "Mesh/Radial elements inner ring",
            "Mesh/Sector elements",
            "Mesh/Patch test elements lower block",
            "Mesh/Patch test elements upper block",
            "Mesh/Outer radius",
            "Mesh/Interface radius",
            "Mesh/Inner radius",
            "Materials/Young's modulus outer ring",
            "Materials/Poisson's ratio outer ring",
            "Materials/Young's modulus inner ring",
            "Materials/Poisson's ratio inner ring",
            "Finite elements/Displacement degree outer ring",
            "Finite elements/Displacement degree inner ring",
            "Load program/Loading",
            "Load program/Reference pressure",
            "Load program/Ramp steps",
            "Load program/Time step",
            "Load program/Rotation pressure",
            "Load program/Rotation steps",
            "Load program/Rotation in elements"})
        if (key == entry)
          return true;
      return false;
    }
  } // namespace

  void
  Parameters::read(const std::string &filename)
  {
    prm_file = filename;
    // Every entry is bound to its member here and takes its value (checked)
    // as the file is read; what remains is what involves several entries.
    ParameterHandler prm;
    add_parameters(prm);
    origins = read_parameter_file(prm, filename);

    const std::filesystem::path path(filename);
    const std::string           folder =
      path.has_parent_path() ? path.parent_path().string() : ".";
    const std::string name = path.stem().string();
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
        mesh.finish(mesh_folder);
        contact.finish();
        load.finish();
        output.finish(name);
        problem.finish();
        for (const auto &[key, origin] : origins)
          {
            const auto slash = key.rfind('/');
            if (general() && only_for_ssnp152(key))
              require(false,
                      key.substr(0, slash),
                      key.substr(slash + 1),
                      "is read for SSNP152 only, but Problem/Scenario is "
                      "general (a general problem takes its bodies, "
                      "conditions and checks from the subsections Body, "
                      "Boundary condition and Check)");
            if (!general() && only_for_general(key))
              require(false,
                      key.substr(0, slash),
                      key.substr(slash + 1),
                      "is read only when Problem/Scenario = general");
            // Body 3 set in a problem of two bodies, a pair beyond the
            // number of pairs: not read, so refused.
            for (const auto &[prefix, n, count] :
                 {std::make_tuple(std::string("Body "),
                                  static_cast<unsigned int>(
                                    problem.bodies.size()),
                                  std::string("Number of bodies")),
                  std::make_tuple(std::string("Contact pair "),
                                  static_cast<unsigned int>(
                                    problem.more_contact_pairs.size() + 1),
                                  std::string("Number of contact pairs"))})
              if (general() && key.rfind(prefix, 0) == 0)
                {
                  const unsigned int k =
                    std::atoi(key.substr(prefix.size()).c_str());
                  require(k <= n,
                          key.substr(0, slash),
                          key.substr(slash + 1),
                          "is not read: Problem/" + count + " is " +
                            std::to_string(n));
                }
          }
        // A general problem's probe: the point of its first pressure check.
        if (general() &&
            origins.count(entry_key("Contact", "Probe point")) == 0)
          {
            contact.probe_point = Point<2>();
            for (const auto &check : problem.checks)
              if (check.quantity == ProblemQuantity::contact_pressure)
                {
                  contact.probe_point = check.point;
                  break;
                }
          }
        // Node A of SSNP152 is the slave node at (R2, 0): a file that
        // changes the radii and not the probe point still checks node A.
        if (origins.count(entry_key("Contact", "Probe point")) == 0 &&
            mesh.source != MeshSource::patch_test)
          if (!general())
            contact.probe_point = Point<2>(mesh.interface_radius, 0);
        check_consistency();
      }
    catch (const ParameterError &e)
      {
        throw std::runtime_error(located(e));
      }
  }

  // Name the file and line that set the value, or say that it is the
  // default: for the checks as the file is read, and for those that need
  // the mesh (a traction on a supported direction, a rule too low for the
  // surfaces' degree), which come later.
  std::string
  Parameters::located(const ParameterError &e) const
  {
    const auto origin = origins.find(entry_key(e.subsection, e.entry));
    if (origin != origins.end())
      return origin->second.file + ":" + std::to_string(origin->second.line) +
             ": " + e.what();
    return prm_file + ": " + e.what() + " ('" + e.entry +
           "' is not set in the file: its default)";
  }

  void
  Parameters::check_consistency() const
  {
    if (general())
      {
        check_general_consistency();
        return;
      }
    require(load.program != LoadProgramType::steps,
            "Load program",
            "Program",
            "= steps takes Problem/Scenario = general (SSNP152 is loaded by "
            "the ramp or the rotation)");
    const unsigned int slave_degree =
      (contact.slave_boundary_id == Ids::outer_ring_contact) ?
        finite_elements.degree_outer :
        finite_elements.degree_inner;
    require(finite_elements.multiplier_degree <= slave_degree,
            "Finite elements",
            "Multiplier degree",
            "must not exceed the displacement degree of the slave ring");
    // The rings' loaded boundaries are not contact surfaces.
    for (const auto &[entry, id] :
         {std::pair<const char *, unsigned int>{"Slave boundary",
                                                contact.slave_boundary_id},
          {"Master boundary", contact.master_boundary_id}})
      require(id != Ids::outer_boundary && id != Ids::inner_boundary,
              "Contact",
              entry,
              "= " + std::to_string(id) + " is " +
                (id == Ids::outer_boundary ?
                   std::string("the outer ring's loaded boundary r = R1") :
                   std::string("the inner ring's loaded boundary r = R3")) +
                ", not a contact surface (SSNP152's are 300, the outer "
                "ring's, and 400, the inner ring's, at r = R2)");

    // Rotations: at most ten turns (the angle is 2 pi s over the elements
    // around the refined mesh); beyond, the rotated copies of the master
    // surface a sector needs would grow without bound.
    const double elements_around_refined =
      static_cast<double>(mesh.elements_around) *
      (1u << mesh.global_refinements);
    require(load.program != LoadProgramType::rotation ||
              std::abs(load.rotation_elements) <= 10 * elements_around_refined,
            "Load program",
            "Rotation in elements",
            "must be at most ten turns (|s| <= 10 x " +
              to_text(elements_around_refined) +
              " elements around the refined mesh), got " +
              to_text(load.rotation_elements));

    // The pressure load: the ramp on the whole rings.
    require(load.loading != Loading::pressure ||
              load.program == LoadProgramType::ramp,
            "Load program",
            "Loading",
            "= pressure takes the ramp program only: the rotation turns an "
            "imposed displacement of r = R3");
    require(load.loading != Loading::pressure || mesh.sector_elements == 0,
            "Load program",
            "Loading",
            "= pressure needs the whole rings: a sector leaves its rigid "
            "rotation free (set Mesh/Sector elements = 0)");
    require(contact.friction_coefficient == 0 || mesh.sector_elements == 0,
            "Contact",
            "Friction coefficient",
            "> 0 needs the whole rings: friction is not implemented with "
            "cyclic symmetry (set Mesh/Sector elements = 0)");
    require(load.loading != Loading::pressure ||
              mesh.source != MeshSource::patch_test,
            "Load program",
            "Loading",
            "= pressure is for the rings, not the patch test");

    // The probe point (node A) must be on the slave surface, or near it:
    // the nearest slave node is used, and a point far away names a node
    // the user did not mean.
    {
      const Point<2> &x = contact.probe_point;
      double          distance;
      double          scale;
      if (mesh.source == MeshSource::patch_test)
        {
          // The interface of the blocks: 0 <= x <= 1, y = 0.
          const double nearest_x = std::min(1.0, std::max(0.0, x[0]));
          distance               = Point<2>(nearest_x, 0).distance(x);
          scale                  = 1.0;
        }
      else
        {
          distance = std::abs(x.norm() - mesh.interface_radius);
          scale    = mesh.interface_radius;
        }
      require(distance <= 0.05 * scale,
              "Contact",
              "Probe point",
              "(" + to_text(x[0]) + ", " + to_text(x[1]) +
                ") is not near the slave surface: it is " + to_text(distance) +
                " m from it (at most " + to_text(0.05 * scale) +
                " m accepted)");
    }

    // Cyclic symmetry: the master surface seen by a sector of k < Ne
    // elements covers the circle at most once (CyclicSymmetry::
    // set_master_window()). A rotation that slides the slave sector all
    // the way round to its own start side, k + |s| >= Ne, makes it meet
    // the master surface across the seam of that window, where the pairing
    // relies on a symmetry the sector does not impose: Newton fails or
    // finds another solution (k = 9..11 of 12 with s = 3). Refuse those.
    // When k divides Ne the sector tiles the circle, and the master across
    // the seam is the same copy of the same segments (turned by a multiple
    // of 2 pi): any rotation is consistent (k = 1 through a whole turn).
    if (mesh.sector_elements > 0 &&
        mesh.elements_around % mesh.sector_elements != 0 &&
        load.program == LoadProgramType::rotation)
      {
        const double k = static_cast<double>(mesh.sector_elements) *
                         (1u << mesh.global_refinements);
        require(k + std::abs(load.rotation_elements) < elements_around_refined,
                "Mesh",
                "Sector elements",
                "= " + std::to_string(mesh.sector_elements) +
                  " is too wide for a rotation of " +
                  to_text(load.rotation_elements) +
                  " elements: the sector would slide round to its own start "
                  "side (k + |s| must stay below " +
                  to_text(elements_around_refined) +
                  " elements around, unless k divides the elements around)");
      }

    // A checked step beyond the last one of the load program is a typo.
    const unsigned int n_steps = load.program == LoadProgramType::ramp ?
                                   load.ramp_steps :
                                   load.rotation_steps;
    for (const unsigned int step : checks.steps)
      require(step == numbers::invalid_unsigned_int || step <= n_steps,
              "Checks",
              "Steps",
              "names step " + std::to_string(step) +
                ", but the load program has " + std::to_string(n_steps) +
                " steps");
  }

  std::vector<std::pair<unsigned int, unsigned int>>
  Parameters::contact_pairs() const
  {
    std::vector<std::pair<unsigned int, unsigned int>> pairs = {
      {contact.slave_boundary_id, contact.master_boundary_id}};
    if (general())
      pairs.insert(pairs.end(),
                   problem.more_contact_pairs.begin(),
                   problem.more_contact_pairs.end());
    return pairs;
  }

  // A general problem: a gmsh mesh, the steps program, its bodies, and
  // checked steps within the program.
  void
  Parameters::check_general_consistency() const
  {
    require(mesh.source == MeshSource::gmsh_file,
            "Mesh",
            "Mesh source",
            "must be 'gmsh file' for Problem/Scenario = general (its bodies "
            "and boundaries are the physical groups of the mesh)");
    require(load.program == LoadProgramType::steps,
            "Load program",
            "Program",
            "must be 'steps' for Problem/Scenario = general (ramp and "
            "rotation are SSNP152's programs)");
    for (unsigned int b = 1; b < problem.bodies.size(); ++b)
      for (unsigned int a = 0; a < b; ++a)
        require(problem.bodies[a].material_id != problem.bodies[b].material_id,
                "Body " + std::to_string(b + 1),
                "Material id",
                "is that of Body " + std::to_string(a + 1) + " (" +
                  std::to_string(problem.bodies[a].material_id) +
                  "): each body is its own physical group");
    // Each slave surface belongs to one pair.
    const auto pairs = contact_pairs();
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
    const unsigned int n_steps = load.time_points.size();
    for (const auto &check : problem.checks)
      for (const unsigned int step : check.steps)
        require(step == numbers::invalid_unsigned_int || step <= n_steps,
                check.name,
                "Steps",
                "names step " + std::to_string(step) +
                  ", but the load program has " + std::to_string(n_steps) +
                  " steps");
    for (const auto &condition : problem.boundary_conditions)
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
        for (const auto &other : problem.boundary_conditions)
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
        const auto disjoint = [](const BoundaryConditionParameters &a,
                                 const BoundaryConditionParameters &b) {
          return !a.normal && !b.normal && a.polar == b.polar &&
                 !(a.components[0] && b.components[0]) &&
                 !(a.components[1] && b.components[1]);
        };
        for (const auto &other : problem.boundary_conditions)
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
