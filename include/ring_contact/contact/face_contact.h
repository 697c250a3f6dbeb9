// @sect3{The contact of two surfaces in three dimensions}
//
// The 3D counterpart of the 2D contact surfaces and pairing: a
// slave surface of bilinear faces that carries the contact pressure (the
// Lagrange multiplier at its vertices, in the same finite-element system
// as the displacement), a master surface of bilinear faces, and the rows
// of the Newton system they make. Weak form, as in 2D (contact_interface.h)
// with the faces' clip cells in place of the segments' cuts
// (mortar_3d.h):
//   displacement rows:  the forces of PairTerms, + int lambda N_a n dA on
//                       the slave, - int lambda Phi_b n dA on the master;
//   multiplier row k:   the weighted gap g~_k = sum over the pairs of g_k;
// and per multiplier node k the complementarity function
//   C_k = w_k lambda_k - max(0, w_k lambda_k - c g~_k) = 0,
// w_k = int N_k dA over the reference slave surface: C_k = c g~_k on the
// active set, w_k lambda_k off it (the primal-dual active-set method, a
// semi-smooth Newton method). n is the slave face's normal, towards the
// master; lambda > 0 is a compression.
//
// In finite strain the clip, the points and the normal follow the current
// configuration and every row is differentiated in AD numbers through
// them (the exact tangent); in small strain they are the reference
// configuration's and the gaps are linear in the displacement.
//
// The pairs are the slave and master faces whose boxes meet (FaceSearch)
// and whose projections on the slave face's plane overlap. The point-wise
// schemes (nodal, Gauss N x N; point_to_face.h) pair each point of a slave
// face with its closest point on the master surface instead, and make the
// same rows from it. The faces are bilinear (Q1 hexahedra) or biquadratic
// (Q2: nine nodes, clipped as four bilinear quarters, mortar_3d.h); the
// pressure is bilinear on the slave faces' vertices in both. This is
// the geometry and the rows of one pair of surfaces; ContactInterface<3>
// (face_contact_interface.h) adds the active set and is what
// ContactProblem<3> holds per pair.
#ifndef ring_contact_contact_face_contact_h
#define ring_contact_contact_face_contact_h

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/hp/mapping_collection.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <ring_contact/contact/face_clipping.h>
#include <ring_contact/contact/multiplier_nodes.h>
#include <ring_contact/contact/point_to_face.h>

#include <array>
#include <functional>
#include <optional>
#include <utility>
#include <vector>

namespace RingContact
{
  using namespace dealii;

  class FaceContact
  {
  public:
    /// How the slave surface is integrated: segment-based (clipped, exact
    /// on non-matching surfaces), at the slave nodes, or at Gauss points.
    enum class Scheme
    {
      segment_based,
      nodal,
      gauss
    };

    /// A face of a contact surface: its four vertices in the lexicographic
    /// order of the face basis, oriented so that a1 x a2 points out of its
    /// body; their displacement unknowns (x, y, z) and reference
    /// positions, and on the slave surface the index of each vertex among
    /// the multiplier nodes. The same of all its nodes in the basis' order
    /// (support_dofs, support_points): the four vertices of a bilinear
    /// face, the nine nodes of a biquadratic one (vertices 0, 2, 6, 8).
    struct Face
    {
      std::array<std::array<types::global_dof_index, 3>, 4> u_dofs;
      std::vector<FaceClipping::Vector3<double>>            reference;
      std::array<unsigned int, 4>                           node;
      std::vector<std::array<types::global_dof_index, 3>>   support_dofs;
      std::vector<FaceClipping::Vector3<double>>            support_points;
      /// The body (material id) of the face's cell.
      types::material_id body = numbers::invalid_material_id;
    };

    /// The surfaces are the faces of `slave` and `master` boundary tags
    /// (the unknowns' first three components are the displacement, the
    /// fourth the multiplier on the slave body's cells). `c` is the
    /// complementarity constant (a stiffness per length, E / h).
    /// `gauss_points`: n of the Gauss n x n scheme. `mapping` (one per
    /// active finite element index) places a quadratic face's mid-side
    /// and centre nodes where the bulk's mapping puts them; without it
    /// they lie on the cells' straight (trilinear) geometry.
    FaceContact(const DoFHandler<3>            &dof_handler,
                const types::boundary_id        slave,
                const types::boundary_id        master,
                const double                    c,
                const bool                      geometrically_linear,
                const Scheme                    scheme = Scheme::segment_based,
                const unsigned int              gauss_points = 2,
                const hp::MappingCollection<3> *mapping      = nullptr);

    /// Pair the faces at `solution` (the reference configuration's in
    /// small strain) and evaluate the weighted gaps g~_k and which nodes
    /// a master face covers (the active set is chosen from them by the
    /// caller: ContactInterface<3>, whose ActiveSet is the 2D one).
    void
    pair(const Vector<double> &solution);

    /// Small strain (pairs, normals and clip of the reference
    /// configuration, gaps linear in the displacement) or finite strain;
    /// switched while a step is solved linearised (ContactInterface<3>).
    void
    set_geometrically_linear(const bool linear)
    {
      geometrically_linear = linear;
    }

    /// The couplings of every candidate pair of the last pair() (each
    /// pair's unknowns with each other: 28 between bilinear faces, 58
    /// between biquadratic ones), through `constraints`.
    void
    add_couplings(DynamicSparsityPattern          &pattern,
                  const AffineConstraints<double> &constraints) const;

    /// The unknowns of each candidate pair of the last pair(), sorted: the
    /// blocks of the sparsity pattern (LinearSystem's memory estimate).
    std::vector<std::vector<types::global_dof_index>>
    coupling_blocks() const;

    /// What assemble() hands on per pair: its local matrix (the
    /// derivatives; empty without them), its local right-hand side (minus
    /// the residual's values) and its unknowns.
    using LocalRows =
      std::function<void(const FullMatrix<double> &,
                         const Vector<double> &,
                         const std::vector<types::global_dof_index> &)>;

    /// The pairs' rows at `solution`: the forces of the pressure on both
    /// faces and, for the nodes `closed`, c times the weighted gaps (the
    /// open nodes' rows w_k lambda_k are the caller's). With
    /// `derivatives` their exact derivatives in AD numbers. The pairs
    /// numbered i with i % n_processes == process (all of them with one
    /// process), so that processes share the work.
    void
    assemble(const Vector<double>    &solution,
             const std::vector<bool> &closed,
             const bool               derivatives,
             const unsigned int       process,
             const unsigned int       n_processes,
             const LocalRows         &add) const;

    /// @name The multiplier nodes (the slave surface's vertices)
    /// @{
    unsigned int
    n_nodes() const
    {
      return multiplier_dofs.size();
    }
    types::global_dof_index
    multiplier_dof(const unsigned int k) const
    {
      return multiplier_dofs[k];
    }
    /// w_k = int N_k dA over the reference slave surface, per node k.
    const std::vector<double> &
    weights() const
    {
      return node_weights;
    }
    /// The slave surface's nodes as the active set reads them: their
    /// multiplier dofs in the order of k, w_k, and the faces' edges and the
    /// nodes' reference positions for the extrapolation of the contact
    /// zones' edges.
    MultiplierNodes
    multiplier_nodes() const;
    /// g~_k at the last pair().
    const std::vector<double> &
    weighted_gaps() const
    {
      return gaps;
    }
    /// Whether a master face covers node k (a clip cell or a paired point
    /// reaches it) at the last pair().
    const std::vector<bool> &
    covered() const
    {
      return is_covered;
    }
    /// @}

    /// The faces of the surfaces, and the pairs of the last pair() that
    /// make rows (slave face, master face; with a point-wise scheme, one
    /// per paired point).
    const std::vector<Face> &
    slave_faces() const
    {
      return slave;
    }
    const std::vector<Face> &
    master_faces() const
    {
      return master;
    }
    const std::vector<std::pair<unsigned int, unsigned int>> &
    pairs() const
    {
      return overlapping;
    }
    /// The candidate pairs of the last pair(): the faces near each other,
    /// whose couplings the sparsity pattern holds.
    const std::vector<std::pair<unsigned int, unsigned int>> &
    candidates() const
    {
      return near_pairs;
    }

  private:
    /// A point of a slave face (PointToFace::SlavePoint, by its index)
    /// with the master face of its closest point; in small strain, where
    /// that point ties between master faces, the Tie's partner there.
    struct PointPair
    {
      unsigned int                    slave_face, point, master_face;
      std::optional<PointToFace::Tie> tie = {};
    };

    /// A face's node positions at `solution` (the reference + u).
    std::vector<FaceClipping::Vector3<double>>
    current(const Face &face, const Vector<double> &solution) const;

    /// The pair's rows (residual, and derivatives if asked) at
    /// `solution`, handed to `add`.
    void
    assemble_pair(const Face              &s,
                  const Face              &m,
                  const PointPair         *point,
                  const Vector<double>    &solution,
                  const std::vector<bool> &closed,
                  const bool               derivatives,
                  const LocalRows         &add) const;

    /// The point-wise schemes' pairs at the positions `geometry` of the
    /// faces (their reference or current configuration), and the weighted
    /// gaps they give; `covered` marks the nodes that some point reaches.
    void
    pair_points(const std::function<std::vector<FaceClipping::Vector3<double>>(
                  const Face &)>     &geometry,
                const Vector<double> &solution,
                std::vector<bool>    &covered);

    /// The unknowns of a candidate pair, in the local order of its rows:
    /// the slave face's displacements (3 per node, all its nodes), the
    /// master face's, the slave face's pressures (its four vertices).
    std::vector<types::global_dof_index>
    pair_dofs(const Face &s, const Face &m) const;

    std::vector<Face>                                  slave, master;
    std::vector<types::global_dof_index>               multiplier_dofs;
    std::vector<double>                                node_weights, gaps;
    std::vector<bool>                                  is_covered;
    const double                                       c;
    bool                                               geometrically_linear;
    std::vector<std::pair<unsigned int, unsigned int>> near_pairs;
    std::vector<std::pair<unsigned int, unsigned int>> overlapping;
    const Scheme                                       scheme;
    /// The points of a slave face under a point-wise scheme, and their
    /// pairs at the last pair().
    const std::vector<PointToFace::SlavePoint> points;
    std::vector<PointPair>                     point_pairs;
  };
} // namespace RingContact

#endif
