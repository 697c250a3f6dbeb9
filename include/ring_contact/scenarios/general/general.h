// @sect3{A general problem}
//
// Bodies of a gmsh model and everything else written in the parameter file
// (problem_description.h): the pieces of the scenario that its files share.
#ifndef ring_contact_scenarios_general_general_h
#define ring_contact_scenarios_general_general_h

#include <deal.II/grid/tria.h>

#include <ring_contact/base/dimension.h>
#include <ring_contact/input/parameters.h>
#include <ring_contact/problem/solution_state.h>
#include <ring_contact/scenarios/general/boundary_resultants.h>
#include <ring_contact/scenarios/general/problem_description.h>

#include <memory>

namespace RingContact
{
  namespace General
  {
    using namespace dealii;

    /// Throw a one-line error if the mesh lacks what the problem needs:
    /// every cell in one of the bodies, each body present, every boundary
    /// tag that a condition, a check or a contact pair names present, the
    /// slave and master surfaces each on one body and not the same one, the
    /// multiplier degree at most the slave body's, and the slave surfaces
    /// of two pairs apart.
    template <int dim>
    void
    check_bodies(const Triangulation<dim> &triangulation,
                 const Parameters         &parameters);

    /// The quantities of the checks at a converged state.
    template <int dim>
    class CheckedQuantities
    {
    public:
      explicit CheckedQuantities(const ProblemParameters &problem);

      /// The value of a check's quantity; throws a one-line error if it
      /// cannot be evaluated (a point outside the mesh, a pressure point
      /// off every slave surface).
      double
      value(const ProblemCheckParameters &check,
            const SolutionState<dim>     &state) const;

    private:
      /// The quantities of a slave surface: that of the pair of the contact
      /// node `nearest` to the check's point (segments in 2D,
      /// quadrilaterals in 3D: quantities.cc and quantities_3d.cc).
      ///
      /// A traction's point on a slave surface, else a one-line error.
      void
      require_on_slave_surface(const ProblemCheckParameters &check,
                               const SolutionState<dim>     &state,
                               const types::global_dof_index nearest) const;
      /// The tangential traction at a node (0 without friction).
      double
      tangential_traction(const SolutionState<dim>     &state,
                          const types::global_dof_index nearest) const;
      double
      contact_half_width(const ProblemCheckParameters &check,
                         const SolutionState<dim>     &state,
                         const types::global_dof_index nearest) const;
      double
      pressure_l2_error(const ProblemCheckParameters &check,
                        const SolutionState<dim>     &state,
                        const types::global_dof_index nearest) const;
      double
      surface_pressure(const ProblemCheckParameters &check,
                       const SolutionState<dim>     &state,
                       const types::global_dof_index nearest) const;
      Tensor<1, dim>
      resultant_force(const ProblemCheckParameters &check,
                      const SolutionState<dim>     &state) const;
      Tensor<1, 3>
      resultant_moment(const ProblemCheckParameters &check,
                       const SolutionState<dim>     &state) const;
      /// The boundary resultants of the state's mesh, built again when it
      /// changes.
      const BoundaryResultants<dim> &
      boundary_resultants(const SolutionState<dim> &state) const;
      double
      displacement(const ProblemCheckParameters &check,
                   const SolutionState<dim>     &state) const;

      const ProblemParameters &problem;
      /// Built at the first resultant asked for, again when the mesh changes.
      mutable std::unique_ptr<BoundaryResultants<dim>> resultants;
      /// The SolutionState::mesh_version() they were built for.
      mutable unsigned int resultants_mesh = 0;
    };
  } // namespace General
} // namespace RingContact

#endif
