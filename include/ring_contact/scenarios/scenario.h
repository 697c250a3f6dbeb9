// @sect3{The problem posed: the Scenario}
//
// What a problem is, apart from the method that solves it. The contact
// problem (problem/contact_problem.h) knows only this interface; a scenario
// gives
// - the mesh, with its geometry (manifolds) and the checks the problem
//   needs of it;
// - the bodies (their material ids, materials and elements);
// - the load program, and the boundary data at any load state (imposed
//   displacements and boundary loads);
// - what it reports after each step (its quantities, by name: the columns
//   of history.csv and its part of the step's line) and its checks (the
//   verdicts);
// - its own entries of the parameter file (ScenarioParameters).
//
// A scenario is one folder of scenarios/ with one registration line
// (ScenarioRegistration, at the end of its .cc file); nothing outside its
// folder asks which scenario runs. Three are registered: the rings of the
// validation case (doc/intro.md), the contact patch test, and a general
// problem written in the parameter file.
#ifndef ring_contact_scenarios_scenario_h
#define ring_contact_scenarios_scenario_h

#include <deal.II/base/function.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/grid/tria.h>
#include <deal.II/hp/mapping_collection.h>

#include <ring_contact/base/dimension.h>
#include <ring_contact/input/parameters.h>
#include <ring_contact/materials/material.h>
#include <ring_contact/output/history.h>
#include <ring_contact/output/progress.h>
#include <ring_contact/output/verdicts.h>
#include <ring_contact/problem/load_program.h>
#include <ring_contact/problem/solution_state.h>

#include <array>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace RingContact
{
  using namespace dealii;

  /// One elastic body: the cells of one material id.
  template <int dim>
  struct Body
  {
    types::material_id material_id;
    std::string        name;           ///< "outer ring", "Body 1"
    unsigned int       degree;         ///< displacement degree
    unsigned int       mapping_degree; ///< of the geometry
    Material<dim>      material;
  };

  /// A load on a boundary, at a reference point and a load state.
  template <int dim>
  struct BoundaryLoad
  {
    enum class Type
    {
      /// p along the inward normal of the current configuration (a
      /// follower load; the reference normal in small strain).
      pressure,
      /// A dead load per reference length.
      traction
    };
    types::boundary_id boundary_id;
    Type               type;
    /// The pressure (component 0) or the traction.
    std::function<Tensor<1, dim>(const Point<dim> &, const LoadState &)> value;
  };

  /// Boundary data that is not a finite number at a load state (an
  /// expression of the parameter file such as 1 / (t - 0.5) or sqrt(x - 2)):
  /// the load step fails with this message, and is cut like a step whose
  /// Newton iteration fails.
  class BoundaryDataError : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };

  /// An imposed normal displacement at a boundary node, N . u = value with
  /// N the outward unit normal of the reference boundary there: one linear
  /// condition on the node's two displacement unknowns, the tangential
  /// motion free.
  template <int dim>
  struct NormalDisplacement
  {
    std::array<types::global_dof_index, dim> dofs; ///< u_x, u_y (, u_z)
    Tensor<1, dim>                           normal;
    double                                   value;
  };

  /// What a scenario imposes on the boundary at a load state.
  template <int dim>
  struct ImposedMotion
  {
    std::map<types::global_dof_index, double> values;
    std::vector<NormalDisplacement<dim>>      normal;
  };

  /// Cyclic symmetry (cyclic_symmetry.h): the mesh is a sector of a
  /// body of revolution whose mesh and loads repeat every element around.
  struct CyclicSector
  {
    double             angle;           ///< the sector's angle
    types::boundary_id start_side;      ///< its radial side at angle 0
    types::boundary_id end_side;        ///< and at `angle`
    unsigned int       sector_elements; ///< elements around in the sector
    unsigned int       elements_around; ///< and in the whole circle
    double             slave_rotation;  ///< the slave's turn (elements)
  };

  template <int dim>
  class Scenario
  {
  public:
    virtual ~Scenario() = default;

    /// @name The problem posed
    /// @{

    /// Make the mesh: generate or read it, attach its geometry
    /// (manifolds), refine, and check that it has what the problem needs.
    virtual void
    create_mesh(Triangulation<dim> &triangulation) const = 0;

    /// The bodies, in the order of their finite elements.
    virtual std::vector<Body<dim>>
    bodies() const = 0;

    /// The steps and the load state at any pseudo-time.
    virtual const LoadProgram &
    load_program() const = 0;

    /// The imposed displacements at a load state: the value of every
    /// unknown they fix, and the normal displacements N . u = g of the
    /// nodes they do not fix whole. The unknowns and normals are the same
    /// at every state (they define the constraints), only the values change.
    virtual ImposedMotion<dim>
    boundary_motion(const DoFHandler<dim>            &dof_handler,
                    const hp::MappingCollection<dim> &mapping,
                    const LoadState                  &load) const = 0;

    /// The loads on boundaries (none by default).
    virtual std::vector<BoundaryLoad<dim>>
    boundary_loads() const
    {
      return {};
    }

    /// Cyclic symmetry, when the mesh is a sector (none by default).
    virtual std::optional<CyclicSector>
    cyclic_sector() const
    {
      return {};
    }

    /// Check the boundary data against the mesh, at the load states of
    /// `times`, before the first step: throws a ParameterError that names
    /// the entry at fault (none by default).
    virtual void
    check_boundary_data(const DoFHandler<dim> &,
                        const hp::MappingCollection<dim> &,
                        const std::vector<double> &) const
    {}
    /// @}

    /// @name What it reports
    /// @{

    /// The names of its quantities: those shown before the solver's columns
    /// of history.csv (Newton iterations, ...), and those after them.
    virtual std::vector<std::string>
    leading_columns() const = 0;
    virtual std::vector<std::string>
    trailing_columns() const
    {
      return {};
    }

    /// The quantities at a converged state into `row` (in the order of the
    /// columns). Called once before the first step too, at rest, so that a
    /// quantity that cannot be evaluated (a point outside the mesh) is an
    /// error before any step is solved.
    virtual void
    report(const SolutionState<dim> &state, HistoryRow &row) const = 0;

    /// Its columns of the step's line (output/progress.h), between the
    /// solver's (step, pseudo-time, Newton iterations, cuts) and the
    /// invariants and times; a legend printed once above them where the
    /// headers need one (none by default); and a warning about the step
    /// where it has one (none by default).
    virtual std::vector<StepField>
    step_fields(const HistoryRow &row) const = 0;
    virtual std::vector<std::string>
    step_legend() const
    {
      return {};
    }
    virtual void
    warn(std::ostream &, const HistoryRow &) const
    {}

    /// The verdicts of its checks over the history of one scheme; a
    /// checked step the run did not reach fails.
    virtual std::vector<Verdict>
    evaluate_checks(const std::string             &scheme,
                    const std::vector<HistoryRow> &history) const = 0;
    /// @}
  };

  /// A scenario as the parameter file names it (Problem/Scenario), how its
  /// entries are made and how it is made from the parameters.
  struct ScenarioRegistration
  {
    /// Its value of Problem/Scenario.
    std::string name;
    /// How messages name it (for example "the patch test").
    std::string description;
    /// What it is, for the documentation of Problem/Scenario.
    std::string documentation;
    /// The scenario of a file that does not say.
    bool is_default = false;
    /// Said after the refusal of an entry that this scenario does not read
    /// (where its own entries are, say).
    std::string                                          foreign_entry_hint;
    std::function<std::shared_ptr<ScenarioParameters>()> make_parameters;
    std::function<std::unique_ptr<Scenario<dim>>(const Parameters &)> make;
    /// How it is made in 3D; empty for a scenario that is 2D only (the
    /// rings, the cyclic sector).
    std::function<std::unique_ptr<Scenario<3>>(const Parameters &)> make_3d =
      {};

    /// Register a scenario: in its .cc file,
    ///   const ScenarioRegistration::Add registration{...};
    struct Add
    {
      explicit Add(ScenarioRegistration registration);
    };
  };

  /// Every registered scenario.
  const std::vector<ScenarioRegistration> &
  registered_scenarios();

  /// The scenario of the parameters, in `spacedim` dimensions; a scenario
  /// that has no 3D form is refused in 3D.
  template <int spacedim>
  std::unique_ptr<Scenario<spacedim>>
  make_scenario(const Parameters &parameters);
} // namespace RingContact

#endif
