// The run-time parameters of the program: one struct per subsection of the
// `.prm` file that every problem reads, each with `add_parameters()`, which
// declares every entry once, bound to the member it sets, with its default,
// pattern, units, documentation and checks (ParameterChecks::Subsection,
// after deal.II's ParameterHandler::add_parameter()), and, where entries
// depend on each other, `finish()`, the checks once the whole file is read.
// Units are SI throughout: metres, pascals.
//
// What differs between problems is the scenario's (Problem/Scenario): each
// scenario declares its own entries (ScenarioParameters), and an entry that
// only another scenario reads is refused, not silently ignored.
#ifndef ring_contact_input_parameters_h
#define ring_contact_input_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <ring_contact/base/dimension.h>
#include <ring_contact/contact/contact_quadrature.h>
#include <ring_contact/input/parameter_file.h>

#include <map>
#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace RingContact
{
  using namespace dealii;

  /// Where the mesh comes from.
  enum class MeshSource
  {
    generated, ///< built in code by the scenario
    gmsh_file  ///< read from a gmsh mesh (.msh) or made by a gmsh script (.geo)
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

  /// The linear solver of the Newton systems.
  enum class LinearSolverType
  {
    automatic, ///< UMFPACK on one process, MUMPS on several
    umfpack,   ///< SuiteSparse's UMFPACK (one process)
    mumps,     ///< MUMPS through Trilinos Amesos (one or several processes)
    iterative  ///< GMRES with a block preconditioner (AMG; see BlockSolver)
  };

  struct MeshParameters
  {
    MeshSource   source;
    std::string  mesh_file; ///< absolute, resolved against the .prm's folder
    unsigned int global_refinements;
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

  /// Subsection Mesh refinement: the mesh refined where the error estimate
  /// is largest, and each such step solved again on the new mesh.
  struct RefinementParameters
  {
    unsigned int adaptive_cycles;
    /// The registered estimator (problem/refinement_estimator.h) that
    /// gives each cell's error indicator.
    std::string  estimator;
    double       refine_fraction;
    double       coarsen_fraction;
    unsigned int every;
    unsigned int maximum_level;
    unsigned int maximum_cells;

    void
    add_parameters(ParameterHandler &prm);
    void
    finish();
  };

  /// Subsection Materials: the law and the plane assumption of every body
  /// (a general problem's body may choose its own law).
  struct MaterialParameters
  {
    /// The registered name of the law (materials/material.h).
    std::string     law;
    PlaneAssumption plane;
    /// The value of the entry's old name, Kinematics ("" if not given).
    std::string old_kinematics;

    void
    add_parameters(ParameterHandler &prm);
    /// Read the old name where it is given: as Material law, with a note in
    /// `notes`, or refused if Material law (set: `law_set`) says otherwise.
    void
    finish(const bool law_set, std::vector<std::string> &notes);
  };

  struct FiniteElementParameters
  {
    unsigned int multiplier_degree;
    unsigned int mapping_degree; ///< 0: isoparametric (each body's degree)
    bool         reduced_integration;

    void
    add_parameters(ParameterHandler &prm);
  };

  struct ContactParameters
  {
    unsigned int slave_boundary_id;
    unsigned int master_boundary_id;
    /// The schemes to run, in order (empty until choose_schemes() when the
    /// file names none).
    std::vector<IntegrationScheme> schemes;
    bool                           smooth_master_normals;
    double                         complementarity_constant; ///< 0: automatic
    double                         friction_coefficient;     ///< mu; 0: none
    PressureMeasure                reported_pressure;

    /// Whether the contact is frictional (Coulomb, mu > 0): the one
    /// place outside contact/ that reads the coefficient to decide it.
    bool
    frictional() const
    {
      return friction_coefficient > 0;
    }

    /// Declare subsection Contact; the default surfaces are the default
    /// scenario's (ScenarioParameters::default_contact_surfaces()).
    void
    add_parameters(ParameterHandler                            &prm,
                   const std::pair<unsigned int, unsigned int> &surfaces);
    /// Slave and master differ.
    void
    finish() const;
    /// Once the scenario is known: the scenario's default schemes
    /// (`scenario_default`, a list as the entry takes) where the file names
    /// none ('automatic'), and the number of points of a 'segment-based'
    /// without one, for surfaces of displacement degree up to
    /// `displacement_degree`. Refuses a scheme listed twice. (A rule too
    /// poor for the surfaces or the multiplier is refused by the setup,
    /// which knows each pair's surfaces, before the first scheme runs.)
    void
    choose_schemes(const std::string &scenario_default,
                   const unsigned int displacement_degree);
  };

  /// Subsection Load program: which program loads the problem, and the
  /// entries of the steps program, the given pseudo-times in which a
  /// general problem's boundary data are written. The other programs and
  /// their entries are the scenarios' (ScenarioParameters::load_programs()).
  struct LoadParameters
  {
    /// The name of the program, one of the scenarios' (the scenario
    /// refuses a program it does not run).
    std::string program;
    /// Program = steps: the pseudo-time at the end of each step.
    std::vector<double> time_points;
    /// Program = steps: n equal steps when no time points are given.
    unsigned int number_of_steps;
    /// The most steps of a load program.
    static constexpr int max_steps = 100000;

    /// Declare the entries; `programs` are every scenario's (name and
    /// sentence), the first the default.
    void
    add_parameters(
      ParameterHandler                                       &prm,
      const std::vector<std::pair<std::string, std::string>> &programs);
    /// The equal steps when no time points are given.
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

  struct Parameters;

  /// The entries of one scenario: declared with every other (a file names
  /// its scenario anywhere in it), read only when the file chooses that
  /// scenario (an entry of another one is refused).
  class ScenarioParameters
  {
  public:
    virtual ~ScenarioParameters() = default;

    /// Declare the scenario's entries, each recorded in `declared` (pass
    /// it to ParameterChecks::Subsection).
    virtual void
    add_parameters(ParameterHandler &prm) = 0;

    /// Once the file is read with this scenario chosen: check the entries
    /// against each other and against the common ones (throw a
    /// ParameterError that names the entry).
    virtual void
    finish(Parameters &parameters) = 0;

    /// Entries the scenario had elsewhere before: "Subsection/Entry" ->
    /// where it is now, for the message that meets an old file (none by
    /// default).
    virtual std::map<std::string, std::string>
    moved_entries() const
    {
      return {};
    }

    /// The contact integration schemes a file that names none runs, as the
    /// entry Contact/Integration schemes writes them: segment-based at the
    /// degree the surfaces need by default, which passes the contact patch
    /// test on any meshes.
    virtual std::string
    default_integration_schemes() const
    {
      return "segment-based";
    }

    /// The highest displacement degree of the bodies (after finish()).
    virtual unsigned int
    highest_displacement_degree() const = 0;

    /// The space dimension of the problem the entries pose, 2 or 3 (after
    /// finish()); 2 by default.
    virtual unsigned int
    dimension() const
    {
      return 2;
    }

    /// The contact pairs after the one of subsection Contact (none by
    /// default): slave and master boundary tags.
    virtual std::vector<std::pair<unsigned int, unsigned int>>
    more_contact_pairs() const
    {
      return {};
    }

    /// The load programs the scenario runs: each one's name and its
    /// sentence of the entry Load program/Program (the first is the
    /// default of the default scenario).
    virtual std::vector<std::pair<std::string, std::string>>
    load_programs() const = 0;

    /// The default slave and master boundaries of subsection Contact: the
    /// default scenario's are the entries' defaults (none by default).
    virtual std::pair<unsigned int, unsigned int>
    default_contact_surfaces() const
    {
      return {0, 0};
    }

    /// Why the scenario does not read an entry ("Subsection/Entry") that
    /// another declares, where it has more to say than who reads it ("":
    /// nothing more).
    virtual std::string
    why_not_read(const std::string &) const
    {
      return "";
    }

    /// "Subsection/Entry" of every entry the scenario declared.
    std::vector<std::string> declared;

    /// The entries of the common subsections that only some scenarios read
    /// (Parameters::restricted_entries()) and this one does.
    std::set<std::string> reads;
  };

  /// All parameters of one run.
  struct Parameters
  {
    /// Every scenario's entries, declared (see ScenarioParameters).
    Parameters();

    std::string prm_file;
    /// Problem/Scenario: the name of a registered scenario (scenario.h).
    std::string scenario;
    /// The space dimension of the problem, 2 or 3: the scenario's
    /// (ScenarioParameters::dimension()).
    unsigned int            dimension = 2;
    MeshParameters          mesh;
    RefinementParameters    refinement;
    MaterialParameters      materials;
    FiniteElementParameters finite_elements;
    ContactParameters       contact;
    LoadParameters          load;
    NewtonParameters        newton;
    OutputParameters        output;

    /// Each registered scenario's entries, by its name.
    std::map<std::string, std::shared_ptr<ScenarioParameters>>
      scenario_parameters;

    /// The entries of the chosen scenario, as their type.
    template <typename ScenarioEntries>
    const ScenarioEntries &
    scenario_entries() const
    {
      return dynamic_cast<const ScenarioEntries &>(
        *scenario_parameters.at(scenario));
    }

    /// The contact pairs (slave and master boundary tags): subsection
    /// Contact's, then the scenario's others.
    std::vector<std::pair<unsigned int, unsigned int>>
    contact_pairs() const;

    /// Declare every entry of the parameter file, bound to these members.
    /// The members must stay where they are while `prm` is used (its
    /// actions refer to them).
    void
    add_parameters(ParameterHandler &prm);

    /// Read and validate a parameter file; throws with a one-line
    /// explanation that names the file, the line and the entry on any
    /// problem.
    void
    read(const std::string              &filename,
         const std::vector<std::string> &overrides = {});

    /// The entries as they ran, for results/<name>/used_parameters.prm:
    /// the entries the file and the command line set (includes resolved,
    /// a relative mesh path resolved), the others as comments with their
    /// defaults. Runnable: it reproduces the run.
    std::string used_parameters;

    /// Refuse the entries a 3D problem cannot honour yet (friction,
    /// adaptive refinement, a plane assumption, a 2D contact rule).
    void
    refuse_two_dimensional_entries() const;

    /// The message of a ParameterError with the file and line that set
    /// the entry (or the note that it is its default).
    std::string
    located(const ParameterError &e) const;

    /// Notes for the run's log about how the file was read (an entry read
    /// under its old name), printed before the first step.
    std::vector<std::string> notes;

    /// Where each entry the file sets was set ("Subsection/Entry").
    std::map<std::string, EntryOrigin> origins;

    /// The scenarios that read an entry ("Subsection/Entry"), for the
    /// entries only some of them read; an entry not listed is read by all.
    std::map<std::string, std::set<std::string>> readers;

    /// The entries of the common subsections that only some scenarios
    /// read: the steps program's (ScenarioParameters::reads says who
    /// reads them).
    static std::vector<std::string>
    restricted_entries();

    /// Print every entry with default and documentation.
    static void
    print_reference(std::ostream &out, bool as_prm);

  private:
    std::string
    describe_used_parameters(const ParameterHandler &prm) const;
  };
} // namespace RingContact

#endif
