// The resultant force on a boundary of a general problem (Quantity =
// resultant force x/y), right where boundaries meet.
//
// A boundary's resultant, int_Gamma t ds, is its applied load where it is
// loaded, and where it is supported the sum of the reactions of its nodes:
// at a node that two boundaries share (the corner of a loaded edge and a
// support, or of two supports) each gets its own part. The reaction of such
// a node is split along the directions each boundary holds (x, y, a normal,
// r or theta): into each direction's component, and within a direction
// between the boundaries that hold it by their traction next to the corner
// (see BoundaryResultants::resultant()). The sum of nodal forces over a
// boundary's nodes, which was used before, counts at a loaded corner the
// load share of the other edge and misses the corner's reaction.
#ifndef ring_contact_scenarios_general_boundary_resultants_h
#define ring_contact_scenarios_general_boundary_resultants_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/hp/mapping_collection.h>
#include <deal.II/lac/vector.h>

#include <ring_contact/base/dimension.h>

#include <array>
#include <functional>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace RingContact
{
  using namespace dealii;

  /// The displacement a boundary imposes, as directions held at each of its
  /// points.
  struct SupportCondition
  {
    enum class Kind
    {
      cartesian, ///< u_x, u_y and/or u_z
      polar, ///< u_r and/or u_theta about the origin (the z axis in 3D), u_z
      normal ///< u . N, N the outward normal of the reference boundary
    };
    types::boundary_id  boundary_id;
    Kind                kind;
    std::array<bool, 3> components = {{true, true, true}}; ///< x/r, y/theta, z

    /// The unit directions held at the point X of the boundary, where N is
    /// its outward normal.
    template <int dim>
    std::vector<Tensor<1, dim>>
    directions(const Point<dim> &X, const Tensor<1, dim> &N) const;
  };

  /// A node of a boundary face: its position, the outward normal there, its
  /// displacement unknowns, and the integral of its shape function over the
  /// face.
  template <int dim>
  struct BoundaryNode
  {
    Point<dim>                               X;
    Tensor<1, dim>                           N;
    std::array<types::global_dof_index, dim> dofs;
    double                                   weight;
  };

  /// The displacement nodes of face f of a cell of element `fe`, its
  /// unknowns `face_dofs` and its support points in `fv`: per node, the face
  /// index of its u_x unknown and its dim displacement unknowns.
  template <int dim>
  std::vector<std::pair<unsigned int, std::array<types::global_dof_index, dim>>>
  face_nodes(const FiniteElement<dim>                   &fe,
             const unsigned int                          f,
             const FEFaceValues<dim>                    &fv,
             const std::vector<types::global_dof_index> &face_dofs);

  /// Call `visit(cell, face, nodes)` for every boundary face with its nodes.
  template <int dim>
  void
  for_each_boundary_face(
    const DoFHandler<dim>            &dof_handler,
    const hp::MappingCollection<dim> &mapping,
    const std::function<
      void(const typename DoFHandler<dim>::active_cell_iterator &,
           const unsigned int,
           const std::vector<BoundaryNode<dim>> &)> &visit);

  /// The resultant force on boundaries, right at their corners (see the
  /// file's introduction). Built once per mesh: which boundaries hold each
  /// supported node, in which directions, with which weights.
  template <int dim>
  class BoundaryResultants
  {
  public:
    BoundaryResultants(const DoFHandler<dim>               &dof_handler,
                       const hp::MappingCollection<dim>    &mapping,
                       const std::vector<SupportCondition> &supports);

    /// The resultant on `boundary_id`: its applied load (`applied`, per
    /// boundary, the integral of the loads on its faces) plus its part of
    /// the reactions (`reactions`, NodalForces::reactions()).
    Tensor<1, dim>
    resultant(
      const types::boundary_id                            boundary_id,
      const Vector<double>                               &reactions,
      const std::map<types::boundary_id, Tensor<1, dim>> &applied) const;

    /// The moment about `centre` of the same forces: the applied loads'
    /// (`applied_moments` about the origin, per boundary, moved to the
    /// centre with `applied`) and each node's part of the reactions at the
    /// node's position: the reference one, or with `displacement` the
    /// current one (finite strain). Three components, about the axes x,
    /// y, z through the centre; in 2D the third alone (per unit thickness).
    Tensor<1, 3>
    moment(const types::boundary_id                            boundary_id,
           const Vector<double>                               &reactions,
           const std::map<types::boundary_id, Tensor<1, dim>> &applied,
           const std::map<types::boundary_id, Tensor<1, 3>>   &applied_moments,
           const Point<dim>                                   &centre,
           const Vector<double> *displacement) const;

  private:
    using Node = std::array<types::global_dof_index, dim>;

    /// Call `visit(node, force)` for each part of the reactions that
    /// belongs to `boundary_id`: a node and the force it gives the
    /// boundary (see resultant()).
    void
    for_each_part(
      const types::boundary_id boundary_id,
      const Vector<double>    &reactions,
      const std::function<void(const Node &, const Tensor<1, dim> &)> &visit)
      const;

    /// Each supported node's reference position.
    std::map<Node, Point<dim>> position_of;
    /// A node's reaction s and the linear map that gives a boundary, the
    /// only one that holds the node in that direction, its part of it.
    struct Share
    {
      Node           node;
      Tensor<2, dim> part;
    };
    std::map<types::boundary_id, std::vector<Share>> shares;

    /// A boundary that holds a node along a direction another holds too:
    /// the integral of its faces' shape function at the node, and its
    /// other nodes next to it with theirs (see resultant()).
    struct Member
    {
      types::boundary_id                   boundary;
      double                               weight;
      std::vector<std::pair<Node, double>> neighbours;
    };
    /// A direction held at a node by several boundaries: the node's
    /// reaction along it is amount . s.
    struct SharedDirection
    {
      Node                node;
      Tensor<1, dim>      direction, amount;
      std::vector<Member> members;
    };
    std::vector<SharedDirection> shared_directions;

    /// One boundary that holds a node: its directions, the integral of the
    /// node's shape function over its faces, and the other nodes of those
    /// faces.
    struct Holder
    {
      types::boundary_id          boundary;
      std::vector<Tensor<1, dim>> directions;
      double                      weight;
      std::set<Node>              neighbours;
    };
    using Holders = std::map<Node, std::vector<Holder>>;
    /// The weight of each node on each boundary.
    using Weights = std::map<std::pair<types::boundary_id, Node>, double>;

    /// A node's reaction split between the boundaries that hold it.
    void
    split_reaction(const Node                &node,
                   const std::vector<Holder> &list,
                   const Holders             &holders,
                   const Weights             &weight_on);
  };
} // namespace RingContact

#endif
