// The run-time parameters of the program: one struct per subsection of the
// `.prm` file, each with `add_parameters()`, which declares every entry once,
// bound to the member it sets, with its default, pattern, units,
// documentation and checks (ParameterChecks::Subsection, after deal.II's
// ParameterHandler::add_parameter()), and, where entries depend on each
// other, `finish()`, the checks once the whole file is read. Units are SI
// throughout: metres, pascals.
#ifndef ring_contact_parameters_h
#define ring_contact_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <ring_contact/contact_quadrature.h>
#include <ring_contact/parameter_file.h>
#include <ring_contact/problem_description.h>

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace RingContact
{
  using namespace dealii;

  /// Where the two rings come from.
  enum class MeshSource
  {
    generated, ///< built in code for any number of elements around
    gmsh_file, ///< read from a gmsh mesh (.msh) or made by a gmsh script (.geo)
    patch_test ///< the contact patch test: two blocks pressed together
  };

  /// The 2d assumption.
  enum class PlaneAssumption
  {
    plane_stress, ///< S33 = 0 (C_PLAN)
    plane_strain  ///< E33 = 0 (D_PLAN)
  };

  /// Which contact pressure is reported (the unknown is always the Cauchy one).
  enum class PressureMeasure
  {
    cauchy, ///< force per current length of the slave surface
    nominal ///< force per reference length of the slave surface
  };

  /// The load programs of SSNP152.
  /// How the load reaches the rings.
  enum class Loading
  {
    /// The analytic displacements imposed on r = R1 and r = R3 (the
    /// original's loading; the rotation turns r = R3).
    imposed_displacements,
    /// The pressure p on r = R1, on the current configuration (a follower
    /// load; a dead load in small strain), r = R3 free; each ring's
    /// rigid-body modes removed by u_y = 0 at (+-r, 0) and u_x = 0 at (0, r)
    /// of its outer boundary, which the symmetric solution satisfies.
    pressure
  };

  enum class LoadProgramType
  {
    ramp,     ///< p(t) = p0 10^(t - 1.1), no rotation (modelisations A, B, H)
    rotation, ///< p fixed, inner boundary turned through s elements (C-G)
    steps     ///< given pseudo-times (Scenario = general)
  };

  /// The linear solver of the Newton systems.
  enum class LinearSolverType
  {
    automatic, ///< UMFPACK on one process, MUMPS on several
    umfpack,   ///< SuiteSparse's UMFPACK (one process)
    mumps,     ///< MUMPS through Trilinos Amesos (one or several processes)
    iterative  ///< GMRES with a block preconditioner (AMG; see BlockSolver)
  };

  /// The checked quantity of a verdict.
  enum class CheckedQuantity
  {
    pressure_at_A,     ///< contact pressure at the probe node A
    l2_pressure_error, ///< relative L2 error of the pressure on the slave
    pressure_spread    ///< (max - min) / reference over the slave nodes
  };

  /// Boundary and material ids of the original mesh (gmsh physical tags).
  namespace Ids
  {
    constexpr unsigned int outer_ring         = 100; // C1
    constexpr unsigned int inner_ring         = 101; // C2
    constexpr unsigned int outer_boundary     = 200; // S1R1, r = R1
    constexpr unsigned int outer_ring_contact = 300; // S1R2, r = R2
    constexpr unsigned int inner_ring_contact = 400; // S2R2, r = R2
    constexpr unsigned int inner_boundary     = 500; // S2R3, r = R3
    /// Cyclic sector: the radial sides at angle 0 and at the sector angle.
    constexpr unsigned int sector_start = 600;
    constexpr unsigned int sector_end   = 601;
  } // namespace Ids

  struct MeshParameters
  {
    MeshSource   source;
    std::string  mesh_file; ///< absolute, resolved against the .prm's folder
    unsigned int elements_around;
    unsigned int radial_elements_outer;
    unsigned int radial_elements_inner;
    unsigned int global_refinements;
    /// Cyclic symmetry: number of elements around in the modelled sector
    /// (0: the whole rings). See cyclic_symmetry.h.
    unsigned int sector_elements = 0;
    /// The angle of the sector, 2 pi k / Ne (0: the whole rings).
    double
           sector_angle() const;
    double outer_radius;     ///< R1
    double interface_radius; ///< R2
    double inner_radius;     ///< R3
    /// Patch test: elements along the interface of the lower (master) and
    /// the upper (slave) block.
    unsigned int patch_elements_lower;
    unsigned int patch_elements_upper;
    /// Numbers handed to a .geo mesh file (gmsh's -setnumber), in order.
    std::vector<std::pair<std::string, double>> geo_numbers;

    /// Declare subsection Mesh, bound to these members.
    void
    add_parameters(ParameterHandler &prm);
    /// Resolve the mesh file against `prm_folder`; check the entries
    /// against each other.
    void
    finish(const std::string &prm_folder);
  };

  struct MaterialParameters
  {
    double          youngs_modulus_outer;
    double          poissons_ratio_outer;
    double          youngs_modulus_inner;
    double          poissons_ratio_inner;
    Kinematics      kinematics;
    PlaneAssumption plane;

    void
    add_parameters(ParameterHandler &prm);
  };

  struct FiniteElementParameters
  {
    unsigned int degree_outer;
    unsigned int degree_inner;
    unsigned int multiplier_degree;
    unsigned int mapping_degree; ///< 0: isoparametric (see below)
    bool         reduced_integration;

    /// The mapping degree of a ring (material id 100 or 101).
    unsigned int
    mapping_degree_of(const unsigned int ring) const
    {
      if (mapping_degree > 0)
        return mapping_degree;
      return ring == Ids::outer_ring ? degree_outer : degree_inner;
    }

    void
    add_parameters(ParameterHandler &prm);
  };


  struct ContactParameters
  {
    unsigned int                   slave_boundary_id;
    unsigned int                   master_boundary_id;
    std::vector<IntegrationScheme> schemes;
    bool                           smooth_master_normals;
    double                         complementarity_constant; ///< 0: automatic
    double                         friction_coefficient;     ///< mu; 0: none
    PressureMeasure                reported_pressure;
    Point<2>                       probe_point;

    void
    add_parameters(ParameterHandler &prm);
    /// Slave and master differ.
    void
    finish() const;
  };

  struct LoadParameters
  {
    LoadProgramType program;
    Loading         loading;
    double          reference_pressure; ///< p0 of the ramp
    unsigned int    ramp_steps;
    double          time_step;
    double          rotation_pressure;
    unsigned int    rotation_steps;
    double          rotation_elements; ///< final s
    /// Program = steps: the pseudo-time at the end of each step.
    std::vector<double> time_points;

    /// Program = steps: n equal steps when no time points are given.
    unsigned int number_of_steps;
    /// The most steps of a load program.
    static constexpr int max_steps = 100000;

    void
    add_parameters(ParameterHandler &prm);
    /// The equal steps when no time points are given; the ramp's last
    /// pressure a number.
    void
    finish();
  };

  struct NewtonParameters
  {
    unsigned int     max_iterations;
    double           tolerance;
    unsigned int     max_step_cuts;
    bool             extrapolate;
    bool             verbose;
    LinearSolverType linear_solver;
    /// GMRES's relative residual (Linear solver = iterative).
    double linear_tolerance;

    void
    add_parameters(ParameterHandler &prm);
  };

  struct OutputParameters
  {
    std::string  directory; ///< resolved; empty entry: results/<prm name>
    unsigned int vtu_interval;
    unsigned int vtu_subdivisions;
    bool         write_history;
    bool         print_timing;
    bool         print_steps;

    void
    add_parameters(ParameterHandler &prm);
    /// An empty directory becomes results/<prm_name>.
    void
    finish(const std::string &prm_name);
  };

  /// One check of the original's TEST_RESU kind.
  struct CheckParameters
  {
    CheckedQuantity           quantity;
    bool                      every_step;
    std::vector<unsigned int> steps; ///< when not every step
    double                    tolerance;

    void
    add_parameters(ParameterHandler &prm);
  };

  /// All parameters of one run.
  struct Parameters
  {
    std::string             prm_file;
    MeshParameters          mesh;
    MaterialParameters      materials;
    FiniteElementParameters finite_elements;
    ContactParameters       contact;
    LoadParameters          load;
    NewtonParameters        newton;
    OutputParameters        output;
    CheckParameters         checks;
    /// The scenario, and for a general problem its bodies, boundary
    /// conditions and checks.
    ProblemParameters problem;

    /// Scenario = general.
    bool
    general() const
    {
      return problem.scenario == ScenarioType::general;
    }

    /// The contact pairs (slave and master boundary tags): subsection
    /// Contact's, then those of Contact pair 2, 3, ... (general problems).
    std::vector<std::pair<unsigned int, unsigned int>>
    contact_pairs() const;

    /// Declare every entry of the parameter file, bound to these members.
    /// The members must stay where they are while `prm` is used (its
    /// actions refer to them).
    void
    add_parameters(ParameterHandler &prm);

    /// Read and validate a parameter file; throws ExcMessage with a one-line
    /// explanation that names the file and the entry on any problem.
    void
    read(const std::string &filename);

    /// The message of a ParameterError with the file and line that set
    /// the entry (or the note that it is its default).
    std::string
    located(const ParameterError &e) const;

    /// Where each entry the file sets was set ("Subsection/Entry").
    std::map<std::string, EntryOrigin> origins;

    /// Checks across subsections (called by read()): the multiplier degree
    /// against the slave ring's, the rotation against the mesh, the
    /// checked steps against the load program.
    void
    check_consistency() const;
    /// The same for Problem/Scenario = general.
    void
    check_general_consistency() const;

    /// Print every entry with default and documentation.
    static void
    print_reference(std::ostream &out, bool as_prm);
  };
} // namespace RingContact

#endif
