// @sect3{Normal displacement conditions at a node}
//
// A boundary condition of Components = n imposes the normal displacement
// u . N = g on its boundary (general.cc gathers, per node, the faces of such
// conditions with their outward normals). Here one node's conditions become
// what the problem class imposes: values of its unknowns where they fix the
// node, or linear conditions N . u = g (NormalDisplacement), each of which
// the problem class makes a constraint on the component with the largest
// |N_a|. The node's Cartesian or polar conditions come first.
#ifndef ring_contact_scenarios_general_normal_conditions_h
#define ring_contact_scenarios_general_normal_conditions_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <ring_contact/scenarios/general/problem_description.h>
#include <ring_contact/scenarios/scenario.h>

#include <array>
#include <map>
#include <vector>

namespace RingContact
{
  namespace General
  {
    using namespace dealii;

    /// The displacement unknowns of a node.
    template <int dim>
    using NodeDofs = std::array<types::global_dof_index, dim>;

    /// A face of a normal condition at one of its nodes: the outward normal
    /// there, the imposed value g, the node's position and the condition.
    template <int dim>
    struct NormalFace
    {
      Tensor<1, dim>                     N;
      double                             g;
      Point<dim>                         X;
      const BoundaryConditionParameters *condition;
    };

    /// One node's normal conditions (the faces of `list`), with the values
    /// the Cartesian and polar conditions impose (`values`, by unknown):
    /// values added where the conditions fix the node, or lines added to
    /// `normal`. The faces' normals are averaged within 60 degrees of a
    /// group's first (the facets of a curve), and groups further apart are
    /// conditions of their own (a corner). In 2D: one group alone is one
    /// line N . u = g, two fix the node, one with a component imposed gives
    /// the other. In 3D: conditions that fix the node (three independent
    /// ones) are solved; one group with components imposed keeps its part
    /// on the others; two groups alone are an edge between two rollers
    /// (two lines on two components); any other is refused with a one-line
    /// std::runtime_error naming the condition and the node.
    template <int dim>
    void
    resolve_normal_conditions(const NodeDofs<dim>                       &node,
                              const std::vector<NormalFace<dim>>        &list,
                              std::map<types::global_dof_index, double> &values,
                              std::vector<NormalDisplacement<dim>> &normal);
  } // namespace General
} // namespace RingContact

#endif
