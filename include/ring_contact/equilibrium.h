// What the forces of a converged state must satisfy, checked by the program
// itself at every step, and the resultant force on a boundary computed so
// that it stays right where boundaries meet.
//
// The nodal forces of a state: f_int (the bulk's stresses, int P : Grad
// phi_i), the applied loads, the contact terms (with the sign of an internal
// force: minus what the other body exerts), and at the supported unknowns
// the reaction s = f_int - applied + contact, what the support exerts. Then
// - each body is in equilibrium: the applied loads, the reactions and the
//   forces of the other bodies on it sum to zero (this is the sum of the
//   residual over its free unknowns, since the internal forces of a body sum
//   to zero for any state);
// - each contact pair exerts equal and opposite forces on its two bodies.
// Each is measured relative to the sum of the magnitudes of the nodal
// forces involved (or their round-off, where a body carries no more), so
// that it is a pure number at any scale.
//
// A boundary's resultant, int_Gamma t ds, is its applied load where it is
// loaded, and where it is supported the sum of the reactions of its nodes:
// at a node that two boundaries share (the corner of a loaded edge and a
// support, or of two supports) each gets its own part. The reaction of such
// a node is split along the directions each boundary holds (x, y, a normal,
// r or theta): into each direction's component, and within a direction
// between the boundaries that hold it in proportion to the length of their
// faces there. The sum of nodal forces over a boundary's nodes, which was
// used before, counts at a loaded corner the load share of the other edge
// and misses the corner's reaction.
#ifndef ring_contact_equilibrium_h
#define ring_contact_equilibrium_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/hp/mapping_collection.h>
#include <deal.II/lac/vector.h>

#include <array>
#include <functional>
#include <map>
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
      cartesian, ///< u_x and/or u_y
      polar,     ///< u_r and/or u_theta about the origin
      normal     ///< u . N, N the outward normal of the reference boundary
    };
    types::boundary_id  boundary_id;
    Kind                kind;
    std::array<bool, 2> components = {{true, true}}; ///< x/r, y/theta

    /// The unit directions held at the point X of the boundary, where N is
    /// its outward normal.
    std::vector<Tensor<1, 2>>
    directions(const Point<2> &X, const Tensor<1, 2> &N) const;
  };

  /// The nodal forces of a converged state, each with the sign of an
  /// internal force where it is one: see the file's introduction.
  struct NodalForces
  {
    Vector<double> internal; ///< f_int
    Vector<double> applied;  ///< the applied loads
    /// The contact terms of each pair (the sign of an internal force).
    std::vector<Vector<double>> contact;
    /// The unknowns whose reaction a support (an imposed displacement, a
    /// normal condition, a cyclic constraint) takes.
    std::vector<bool> supported;
    /// Per unknown, the round-off of its forces (a few eps times the
    /// magnitude of the terms they are summed from): the scale of a body
    /// whose forces are round-off only (moved rigidly, not loaded).
    Vector<double> round_off;

    /// The reaction at a supported unknown, zero elsewhere.
    Vector<double>
    reactions() const;
  };

  /// The invariants of one state.
  struct Balance
  {
    /// Per body: |sum of applied, reaction and contact forces| over the
    /// sum of their magnitudes (or over the round-off of its forces, where
    /// that is larger), and the body's name.
    std::vector<std::pair<std::string, double>> bodies;
    /// Per body: whether that sum is more than the round-off of its forces
    /// (only then can it be an error).
    std::vector<bool> beyond_round_off;
    /// Per contact pair: |force on the slave body + force on the master
    /// body| over the sum of the magnitudes of the pair's nodal forces
    /// (NaN where it is not measured: cyclic symmetry, whose copies carry
    /// the master's forces turned).
    std::vector<double> pairs;

    double
    worst_body() const;
    double
    worst_pair() const;
  };

  /// The equilibrium of every body (cells of one material id) and the
  /// action and reaction of every pair (`pair_bodies`: the slave's and the
  /// master's material ids; `measure_pairs` false for cyclic symmetry).
  Balance
  measure_balance(
    const DoFHandler<2>                                          &dof_handler,
    const NodalForces                                            &forces,
    const std::vector<std::pair<types::material_id, std::string>> &bodies,
    const std::vector<std::pair<types::material_id, types::material_id>>
              &pair_bodies,
    const bool measure_pairs = true);

  /// A node of a boundary face: its position, the outward normal there, its
  /// u_x and u_y unknowns, and the integral of its shape function over the
  /// face.
  struct BoundaryNode
  {
    Point<2>                               X;
    Tensor<1, 2>                           N;
    std::array<types::global_dof_index, 2> dofs;
    double                                 weight;
  };

  /// Call `visit(cell, face, nodes)` for every boundary face with its nodes.
  void
  for_each_boundary_face(
    const DoFHandler<2>            &dof_handler,
    const hp::MappingCollection<2> &mapping,
    const std::function<void(const DoFHandler<2>::active_cell_iterator &,
                             const unsigned int,
                             const std::vector<BoundaryNode> &)> &visit);

  /// The resultant force on boundaries, right at their corners (see the
  /// file's introduction). Built once per mesh: which boundaries hold each
  /// supported node, in which directions, with which weights.
  class BoundaryResultants
  {
  public:
    BoundaryResultants(const DoFHandler<2>                 &dof_handler,
                       const hp::MappingCollection<2>      &mapping,
                       const std::vector<SupportCondition> &supports);

    /// The resultant on `boundary_id`: its applied load (`applied`, per
    /// boundary, the integral of the loads on its faces) plus its part of
    /// the reactions (`reactions`, NodalForces::reactions()).
    Tensor<1, 2>
    resultant(const types::boundary_id                         boundary_id,
              const Vector<double>                            &reactions,
              const std::map<types::boundary_id, Tensor<1, 2>> &applied) const;

  private:
    using Node = std::array<types::global_dof_index, 2>;
    /// A node's reaction s and the linear map that gives a boundary, the
    /// only one that holds the node in that direction, its part of it.
    struct Share
    {
      Node         node;
      Tensor<2, 2> part;
    };
    std::map<types::boundary_id, std::vector<Share>> shares;

    /// A boundary that holds a node along a direction another holds too:
    /// the integral of its faces' shape function at the node, and its
    /// other nodes next to it with theirs (see resultant()).
    struct Member
    {
      types::boundary_id                  boundary;
      double                              weight;
      std::vector<std::pair<Node, double>> neighbours;
    };
    /// A direction held at a node by several boundaries: the node's
    /// reaction along it is amount . s.
    struct SharedDirection
    {
      Node                node;
      Tensor<1, 2>        direction, amount;
      std::vector<Member> members;
    };
    std::vector<SharedDirection> shared_directions;
  };
} // namespace RingContact

#endif
