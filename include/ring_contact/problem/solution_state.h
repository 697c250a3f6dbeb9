// What a scenario may read of a converged state to report its quantities:
// the mesh and the solution, the load state, the contact interfaces and the
// contact pressure at their nodes, and the nodal forces. The contact problem
// (contact_problem.h) implements it; the scenarios (scenarios/) see only
// this, so that nothing of the solver's inner workings leaks into them.
#ifndef ring_contact_problem_solution_state_h
#define ring_contact_problem_solution_state_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/hp/mapping_collection.h>
#include <deal.II/lac/vector.h>

#include <ring_contact/base/dimension.h>
#include <ring_contact/contact/contact_interface.h>
#include <ring_contact/diagnostics/equilibrium.h>
#include <ring_contact/problem/load_program.h>

#include <map>
#include <vector>

namespace RingContact
{
  using namespace dealii;

  template <int dim>
  class SolutionState
  {
  public:
    virtual ~SolutionState() = default;

    /// The unknowns, the geometry, and their values at the state.
    virtual const DoFHandler<dim> &
    get_dof_handler() const = 0;
    virtual const hp::MappingCollection<dim> &
    get_mapping() const = 0;
    virtual const Vector<double> &
    get_solution() const = 0;

    /// The load state of the step.
    virtual const LoadState &
    load_state() const = 0;

    /// The contact interfaces, one per pair, in the order of the pairs.
    virtual std::vector<const ContactInterface<dim> *>
    contact_interfaces() const = 0;

    /// The contact node (multiplier unknown) nearest to a reference point
    /// over every pair, and the interface it belongs to.
    virtual types::global_dof_index
    contact_node_nearest_to(const Point<dim> &point) const = 0;
    virtual const ContactInterface<dim> &
    contact_of(const types::global_dof_index node) const = 0;

    /// Every contact node of every pair.
    virtual std::vector<types::global_dof_index>
    contact_nodes() const = 0;

    /// The contact pressure reported at a contact node: Cauchy or nominal,
    /// as Contact/Reported pressure says.
    virtual double
    reported_pressure(const types::global_dof_index node) const = 0;

    /// The nodal forces of the state (equilibrium.h), the integral of the
    /// applied loads over each loaded boundary, and that of their moment
    /// about the origin (x x t, x current where the body is in finite
    /// strain; three components, in 2D the third alone).
    virtual NodalForces
    nodal_forces() const = 0;
    virtual const std::map<types::boundary_id, Tensor<1, dim>> &
    applied_resultants() const = 0;
    virtual const std::map<types::boundary_id, Tensor<1, 3>> &
    applied_moments() const = 0;
    /// Whether some body is in finite strain (its forces then act at the
    /// current positions).
    virtual bool
    in_finite_strain() const = 0;

    /// A number that changes whenever the mesh and its unknowns do
    /// (adaptive refinement): what a reader built from them must build
    /// again.
    virtual unsigned int
    mesh_version() const = 0;
  };
} // namespace RingContact

#endif
