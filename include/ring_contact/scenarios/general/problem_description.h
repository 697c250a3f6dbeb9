// A contact problem of two or more bodies written in the parameter file:
// the bodies (the physical groups of a gmsh mesh, each with its material
// and elements), the boundary conditions per boundary tag (imposed
// displacement, traction, or pressure on the current configuration), and
// checks of computed quantities against references, all as expressions of
// x, y (and z in 3D), the pseudo-time t and named constants (deal.II's
// FunctionParser, muparser syntax). The problem's dimension is the gmsh
// model's: a model of volumes is three-dimensional. The contact pairs are
// subsection Contact and Contact pair 2, 3, ..., the load program subsection
// 'Load program' with Program = steps.
//
//   subsection Problem
//     set Scenario  = general
//     set Constants = R = 1, q = 1e6
//   end
//   subsection Body 1
//     set Material id = 1
//     set Young's modulus = 2e11
//   end
//   subsection Boundary condition 1
//     set Boundary id = 3
//     set Type        = traction
//     set Value       = 0; -q * t
//   end
//   subsection Check 1
//     set Quantity  = contact pressure
//     set Point     = 0, 0
//     set Reference = sqrt(...)
//   end
#ifndef ring_contact_scenarios_general_problem_description_h
#define ring_contact_scenarios_general_problem_description_h

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <ring_contact/base/dimension.h>
#include <ring_contact/input/parameter_checks.h>
#include <ring_contact/input/parameters.h>

#include <algorithm>
#include <array>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace RingContact
{
  using namespace dealii;

  /// One body of a general problem: a physical group of the mesh.
  struct BodyParameters
  {
    unsigned int material_id; ///< the physical group's tag
    double       youngs_modulus;
    double       poissons_ratio;
    unsigned int degree; ///< displacement degree
    /// The body's own material law (a registered name); empty: that of
    /// Materials/Material law.
    std::string law;
    /// The value of the entry's old name, Kinematics ("" if not given).
    std::string old_kinematics;

    /// Declare the entries of a subsection Body k (entered), bound to
    /// these members.
    void
    add_parameters(ParameterChecks::Subsection &s);
  };

  enum class BoundaryConditionType
  {
    none,         ///< the slot is not used
    displacement, ///< imposed displacement components
    traction,     ///< a dead load per reference length [N/m per unit thickness]
    pressure      ///< p on the current configuration (follower) [Pa]
  };

  /// One boundary condition of a general problem, on one boundary tag.
  struct BoundaryConditionParameters
  {
    BoundaryConditionType type = BoundaryConditionType::none;
    unsigned int          boundary_id;
    /// Displacement: components in polar form (u_r, u_theta about the
    /// origin; in 3D cylindrical about the z axis) instead of (u_x, u_y).
    bool polar = false;
    /// Displacement: which components are imposed (x/r, y/theta, z); z is
    /// not read in 2D.
    std::array<bool, 3> components = {{true, true, true}};
    /// Whether Components names z itself (refused in 2D; all does not).
    bool names_z = false;
    /// Displacement: only the normal component u . N is imposed (N the
    /// outward unit normal of the reference boundary), the tangential one
    /// is free: a roller on an inclined or curved boundary.
    bool normal = false;
    /// The expressions of x, y (, z) and t: displacement and traction one
    /// per dimension (the components not imposed are not used), a normal
    /// displacement and a pressure one.
    std::vector<std::string> expressions;
    std::string              name; ///< "Boundary condition 3"

    /// Declare the entries of a subsection Boundary condition k.
    void
    add_parameters(ParameterChecks::Subsection &s);
    /// Once the file is read: the components and the number of
    /// expressions against the problem's dimension, and whether the
    /// expressions parse with the problem's constants.
    void
    finish(const std::map<std::string, double> &constants,
           const unsigned int                   dimension) const;
  };

  enum class ProblemQuantity
  {
    none,
    contact_pressure,    ///< at the slave node nearest to the point
    tangential_traction, ///< friction: at the slave node nearest to the point
    contact_half_width,  ///< farthest extent of the contact from the point
    /// Over the slave surface nearest to the point: the smallest and the
    /// largest nodal pressure, and the mean, int p dS / int dS.
    minimum_contact_pressure,
    maximum_contact_pressure,
    mean_contact_pressure,
    /// Over the slave surface nearest to the point: the relative L2 error
    /// of the pressure against the reference expression, a function of x,
    /// y and t, ||p_h - p_ref|| / ||p_ref||.
    contact_pressure_l2_error,
    /// The resultant of the traction on a boundary: its load, or its part
    /// of the reactions (BoundaryResultants).
    resultant_force_x,
    resultant_force_y,
    resultant_force_z,
    /// The moment of the same forces about the axis x, y or z through the
    /// point (in 2D about z alone).
    resultant_moment_x,
    resultant_moment_y,
    resultant_moment_z,
    displacement_x, ///< at the point (reference coordinates)
    displacement_y,
    displacement_z
  };

  /// One check of a general problem: a computed quantity against a
  /// reference expression, at chosen steps.
  struct ProblemCheckParameters
  {
    ProblemQuantity quantity = ProblemQuantity::none;
    /// The point's coordinates as the file gives them (two or three: their
    /// count is checked against the problem's dimension in finish()).
    std::vector<double> coordinates = {0, 0};
    unsigned int        boundary_id;
    /// The reference, an expression of x, y (, z: the point) and t.
    std::string reference;
    double      tolerance;
    bool        relative;
    /// Where the reference comes from (for the verdict table).
    std::string               source;
    bool                      every_step;
    std::vector<unsigned int> steps; ///< invalid_unsigned_int: the last
    std::string               name;  ///< "Check 2"

    /// The point in a problem of dimension spacedim.
    template <int spacedim>
    Point<spacedim>
    point() const
    {
      Point<spacedim> p;
      for (unsigned int d = 0; d < spacedim && d < coordinates.size(); ++d)
        p[d] = coordinates[d];
      return p;
    }

    /// The point as the messages write it: "(0, 0.5)".
    std::string
    point_text() const;

    /// "contact pressure at (0, 0)", "force y on 3", ...
    std::string
    description() const;
    /// A column name for history.csv: "contact_pressure", "force_y_3", ...
    std::string
    column() const;

    /// Declare the entries of a subsection Check k.
    void
    add_parameters(ParameterChecks::Subsection &s);
    /// Once the file is read: the point and the quantity against the
    /// problem's dimension, and whether the reference parses with the
    /// problem's constants.
    void
    finish(const std::map<std::string, double> &constants,
           const unsigned int                   dimension) const;
  };

  /// The value of Problem/Constants, 'name = value, ...': each value a
  /// number or an expression of the constants before it; a one-line
  /// ParameterError names the faulty item.
  std::map<std::string, double>
  parse_constants(const std::string &text);

  /// The entries of a general problem: subsection Problem's constants and
  /// numbers of bodies and pairs, and the subsections Body 1..n, Contact
  /// pair 2..m, Boundary condition 1..12, Check 1..12.
  struct ProblemParameters : public ScenarioParameters
  {
    static constexpr unsigned int max_bodies              = 4;
    static constexpr unsigned int max_contact_pairs       = 4;
    static constexpr unsigned int max_boundary_conditions = 12;
    static constexpr unsigned int max_checks              = 12;

    /// The common entries a general problem reads: its steps.
    ProblemParameters();

    std::map<std::string, double> constants;
    /// Problem/Number of bodies of them (2 by default).
    std::vector<BodyParameters> bodies;
    /// The contact pairs after the first (which is subsection Contact):
    /// slave and master tags of the subsections Contact pair 2, 3, ...
    std::vector<std::pair<unsigned int, unsigned int>> contact_pairs;
    std::vector<BoundaryConditionParameters>           boundary_conditions;
    std::vector<ProblemCheckParameters>                checks;

    /// Declare subsection Problem's entries and every slot of the
    /// subsections Body, Contact pair, Boundary condition and Check, bound
    /// to these members (the vectors hold every slot until finish()).
    void
    add_parameters(ParameterHandler &prm) override;
    /// Keep the bodies and pairs of the numbers given, the conditions and
    /// checks whose slots are used; check their expressions, and everything
    /// against the common entries.
    void
    finish(Parameters &parameters) override;

  private:
    /// The model's dimension (model_dimension), and the constants against
    /// it.
    void
    find_dimension(const Parameters &parameters);
    /// The entries set in a Body or Contact pair slot beyond the numbers.
    void
    refuse_unread_slots(const Parameters &parameters) const;
    /// The entries set in a Boundary condition or Check slot whose Type or
    /// Quantity the file leaves at none.
    void
    refuse_idle_slots(const Parameters &parameters) const;
    /// The boundary conditions against the contact surfaces and each other.
    void
    check_boundary_conditions(
      const std::vector<std::pair<unsigned int, unsigned int>> &pairs) const;

  public:
    /// The steps program's value of Load program/Program.
    static constexpr const char *steps_program = "steps";

    /// The steps program: the pseudo-times its expressions take.
    std::vector<std::pair<std::string, std::string>>
    load_programs() const override;

    /// The probe (node A of the rings): a quantity at a point is a
    /// check's here.
    std::string
    why_not_read(const std::string &entry) const override;

    std::vector<std::pair<unsigned int, unsigned int>>
    more_contact_pairs() const override
    {
      return contact_pairs;
    }

    /// The gmsh model's: 3 for a model of volumes (found in finish()).
    unsigned int
    dimension() const override
    {
      return model_dimension;
    }

    unsigned int
    highest_displacement_degree() const override
    {
      unsigned int degree = 1;
      for (const BodyParameters &body : bodies)
        degree = std::max(degree, body.degree);
      return degree;
    }

  private:
    unsigned int number_of_bodies;
    unsigned int number_of_contact_pairs;
    unsigned int model_dimension = 2;
  };

  /// An expression of x, y (, z) and t with the problem's constants, n
  /// components separated by ';' (deal.II's FunctionParser). Throws a
  /// one-line message naming `what` if it does not parse or does not
  /// evaluate at the origin.
  template <int spacedim>
  std::unique_ptr<FunctionParser<spacedim>>
  make_expression(const std::vector<std::string>      &expressions,
                  const std::map<std::string, double> &constants,
                  const std::string                   &what);
} // namespace RingContact

#endif
