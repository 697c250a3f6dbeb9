// What a problem is, apart from the method that solves it: the bodies (their
// material ids, materials and elements), the boundary data at any load
// state (imposed displacements and boundary loads) and the contact pressure
// expected. The problem class (ring_contact_problem.h) knows only this
// interface; three scenarios implement it:
// - SSNP152: the rings, loaded by the analytic displacements of r = R1 and
//   r = R3 (turned for the rotation), or by the pressure on r = R1;
// - the patch test: two blocks pressed by a uniform pressure;
// - a general problem: the bodies and boundary conditions of the parameter
//   file, as expressions of x, y and t (problem_description.h).
#ifndef ring_contact_scenario_h
#define ring_contact_scenario_h

#include <deal.II/base/function.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/hp/mapping_collection.h>

#include <ring_contact/load_program.h>
#include <ring_contact/material.h>
#include <ring_contact/parameters.h>

#include <array>
#include <functional>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace RingContact
{
  using namespace dealii;

  /// One elastic body: the cells of one material id.
  struct Body
  {
    types::material_id material_id;
    std::string        name;           ///< "outer ring", "Body 1"
    unsigned int       degree;         ///< displacement degree
    unsigned int       mapping_degree; ///< of the geometry
    Material           material;
  };

  /// A load on a boundary, at a reference point and a load state.
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
    std::function<Tensor<1, 2>(const Point<2> &, const LoadState &)> value;
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
  struct NormalDisplacement
  {
    std::array<types::global_dof_index, 2> dofs; ///< u_x, u_y of the node
    Tensor<1, 2>                           normal;
    double                                 value;
  };

  /// What a scenario imposes on the boundary at a load state.
  struct ImposedMotion
  {
    std::map<types::global_dof_index, double> values;
    std::vector<NormalDisplacement>           normal;
  };

  class Scenario
  {
  public:
    virtual ~Scenario() = default;

    /// The bodies, in the order of their finite elements.
    virtual std::vector<Body>
    bodies() const = 0;

    /// The imposed displacements at a load state: the value of every
    /// unknown they fix, and the normal displacements N . u = g of the
    /// nodes they do not fix whole. The unknowns and normals are the same
    /// at every state (they define the constraints), only the values change.
    virtual ImposedMotion
    boundary_motion(const DoFHandler<2>            &dof_handler,
                    const hp::MappingCollection<2> &mapping,
                    const LoadState                &load) const = 0;

    /// The loads on boundaries (none by default).
    virtual std::vector<BoundaryLoad>
    boundary_loads() const
    {
      return {};
    }

    /// The contact pressure the load state should give everywhere on the
    /// slave surface (its analytic solution); NaN where none is known.
    virtual double
    reference_pressure(const LoadState &load) const;

    /// Check the boundary data against the mesh, at the load states of
    /// `times`, before the first step: throws a ParameterError that names
    /// the entry at fault (none by default).
    virtual void
    check_boundary_data(const DoFHandler<2> &,
                        const hp::MappingCollection<2> &,
                        const std::vector<double> &) const
    {}
  };

  /// The scenario of the parameters.
  std::unique_ptr<Scenario>
  make_scenario(const Parameters &parameters);
} // namespace RingContact

#endif
