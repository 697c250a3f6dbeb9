// A contact surface: the boundary faces of one ring with a given boundary id,
// seen in the current configuration x = X + u. Each face is a segment
// parametrised by t in [0, 1] from its first to its second vertex; the
// reference position X(t) interpolates the mapping's support points (straight
// for mapping degree 1, on the circle's polar manifold for degree >= 2) and
// the displacement u(t) the face's degrees of freedom. The same description
// serves the slave (where contact integrals are evaluated) and the master
// (onto which slave points are projected).
#ifndef ring_contact_contact_contact_surface_h
#define ring_contact_contact_contact_surface_h

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/point.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/rtree.h>

#include <ring_contact/base/dimension.h>
#include <ring_contact/contact/surface_kernel.h>
#include <ring_contact/input/parameters.h>

#include <array>
#include <map>
#include <utility>
#include <vector>

namespace RingContact
{
  using namespace dealii;

  /// Lagrange interpolation on a segment, t in [0, 1], through given nodes
  /// (at most max_size). Each basis function is evaluated as the product of
  /// its linear factors (t - t_j) / (t_i - t_j), with its first and second
  /// derivatives carried along by Leibniz's rule: the projections of the
  /// contact search evaluate the segments' curves millions of times, and
  /// deal.II's general Polynomial (any number of derivatives, its roots in a
  /// std::vector) made this a large part of the search (doc/validation.md,
  /// "Time and memory behind the code's choices").
  class LagrangeBasis1D
  {
  public:
    LagrangeBasis1D() = default;
    explicit LagrangeBasis1D(const std::vector<double> &nodes);

    unsigned int
    size() const
    {
      return n_nodes;
    }

    /// Values and first and second derivatives of every basis function.
    void
    evaluate(const double         t,
             std::vector<double> &values,
             std::vector<double> &first,
             std::vector<double> &second) const;

    /// Values only.
    void
    evaluate(const double t, std::vector<double> &values) const;

    /// Values and first and second derivatives into caller's arrays of at
    /// least size() entries (no allocation: used in the hot loops).
    void
    evaluate(const double t,
             double      *values,
             double      *first,
             double      *second) const;

    /// The largest basis this class is used with (degree 4).
    static constexpr unsigned int max_size = 5;

  private:
    unsigned int                 n_nodes = 0;
    std::array<double, max_size> nodes{};
    /// 1 / (t_i - t_j) for j != i.
    std::array<std::array<double, max_size>, max_size> inverse_differences{};
  };

  /// Position and derivatives of a point of a segment (surface_kernel.h).
  using CurvePoint = SurfaceKernel::CurvePoint<double>;

  /// One boundary face of a contact surface.
  struct SurfaceSegment
  {
    DoFHandler<dim>::active_cell_iterator cell;
    unsigned int                          face_no;
    /// Global vertex indices at t = 0 and t = 1.
    std::array<unsigned int, 2> vertices;
    /// Reference positions of the mapping's support points on the face.
    std::vector<Point<dim>> reference_nodes;
    /// Displacement dofs (x and y) at the displacement nodes of the face.
    std::vector<types::global_dof_index> dofs_x, dofs_y;
    /// Multiplier dofs at the multiplier nodes (slave surface only).
    std::vector<types::global_dof_index> multiplier_dofs;
    /// Tangential-traction dofs at the same nodes (slave surface, with
    /// friction only).
    std::vector<types::global_dof_index> tangential_dofs;
    /// +1 or -1: n = orientation (dx_y, -dx_x) / |dx| is the outward normal.
    double orientation;
    /// Cyclic symmetry: a rotated copy of a segment of the sector carries
    /// the original's unknowns turned by this rotation (identity for the
    /// segments of the mesh itself): x = R (X + u).
    Tensor<2, dim> rotation = unit_symmetric_tensor<dim>();
    /// True for a rotated copy.
    bool is_copy = false;
    /// Current nodal displacements R u (set by ContactSurface::update()).
    std::vector<Tensor<1, dim>> nodal_displacements;
    /// The segments that share the vertex at t = 0 and t = 1 (invalid at
    /// the end of an open surface), and the vertex's parameter on them.
    std::array<unsigned int, 2> neighbours = {
      {numbers::invalid_unsigned_int, numbers::invalid_unsigned_int}};
    std::array<double, 2> neighbour_t = {{0, 0}};
  };

  /// Result of the closest-point projection of a point onto a surface.
  struct Projection
  {
    unsigned int segment = numbers::invalid_unsigned_int;
    double       t       = 0; ///< parameter of the closest point
    double       gap     = 0; ///< (x - x_m) . n, > 0 when apart
    /// True if the closest point is an end of a segment and no orthogonal
    /// projection exists (outside a convex corner): t is then fixed.
    bool clamped = false;
    /// True if the closest point is a vertex shared with a neighbouring
    /// segment (SurfaceSegment::neighbours[t]): the normal is then the
    /// vertex normal, the length-weighted average of the normals of the two
    /// segments, and t (0 or 1) is fixed.
    bool at_vertex = false;
  };

  class ContactSurface
  {
  public:
    /// Collect the faces with `boundary_id`; `mapping_degree` fixes the
    /// reference geometry of each face (straight for 1). Cyclic symmetry
    /// (`sector_angle` > 0): the surface of the sector is continued on each
    /// side by `copies` copies of itself turned through multiples of the
    /// sector angle (see cyclic_symmetry.h), trimmed to the segments whose
    /// midpoint lies at an angle in [-window_before, sector_angle +
    /// window_after) from the sector's start side; the copies share the
    /// originals' unknowns. A surface that closes the circle is one closed
    /// curve.
    ContactSurface(const DoFHandler<dim>   &dof_handler,
                   const types::boundary_id boundary_id,
                   const unsigned int       mapping_degree,
                   const bool               smooth_normals = false,
                   const double             sector_angle   = 0,
                   const unsigned int       copies         = 0,
                   const double             window_before  = 0,
                   const double             window_after   = 0);

    const std::vector<SurfaceSegment> &
    segments() const
    {
      return segment_list;
    }

    /// Interpolation bases along a segment: reference geometry,
    /// displacement, multiplier.
    const LagrangeBasis1D &
    geometry_basis() const
    {
      return geometry;
    }
    const LagrangeBasis1D &
    displacement_basis() const
    {
      return displacement;
    }
    const LagrangeBasis1D &
    multiplier_basis() const
    {
      return multiplier;
    }
    /// Parameters t of the multiplier nodes, in the order of
    /// SurfaceSegment::multiplier_dofs.
    const std::vector<double> &
    multiplier_nodes() const
    {
      return multiplier_node_parameters;
    }

    /// Parameters t of the displacement nodes, in the order of
    /// SurfaceSegment::dofs_x and dofs_y.
    const std::vector<double> &
    displacement_nodes() const
    {
      return displacement_node_parameters;
    }

    /// Read the current nodal displacements from the solution and rebuild
    /// the search tree of the current segments.
    void
    update(const Vector<double> &solution);

    /// Current position and derivatives at parameter t of a segment.
    CurvePoint
    current_point(const unsigned int segment, const double t) const;

    /// Reference position and derivative at parameter t of a segment.
    CurvePoint
    reference_point(const unsigned int segment, const double t) const;

    /// The displacement at parameter t of a segment (the current state of
    /// update()), apart from the reference position.
    Tensor<1, dim>
    displacement_at(const unsigned int segment, const double t) const;

    /// Outward unit normal of a segment at a current-configuration point.
    Tensor<1, dim>
    normal(const unsigned int segment, const CurvePoint &point) const;

    /// Outward unit normal at a projection: the segment's, the vertex
    /// normal when the projection is at a vertex, the smoothed normal when
    /// normals are smoothed.
    Tensor<1, dim>
    normal(const Projection &projection) const;

    /// Outward normal scaled by |dx/dt|: orientation (dx_y, -dx_x).
    Tensor<1, dim>
    scaled_normal(const unsigned int segment, const double t) const;

    /// Unit vertex normal at the end `end` (0 or 1) of a segment: the
    /// length-weighted average of the normals of the segments there.
    Tensor<1, dim>
    vertex_normal(const unsigned int segment, const unsigned int end) const;

    /// Smoothed normal field (the original's LISSAGE): the vertex normals
    /// interpolated linearly along the segment, not normalised.
    Tensor<1, dim>
    smoothed_normal_direction(const unsigned int segment, const double t) const;

    /// True if this surface uses the smoothed normal field.
    bool
    smooths_normals() const
    {
      return smooth_normals;
    }

    /// Closest-point projection of x onto the current surface. The search
    /// looks at the few segments nearest to x (R-tree); `preferred` (a
    /// segment index or invalid), the previous partner, is kept while the
    /// projection stays on it or close to it, so that a point sitting on a
    /// vertex is not paired back and forth between its two segments.
    Projection
    project(const Point<dim>  &x,
            const unsigned int preferred = numbers::invalid_unsigned_int) const;

    /// Projection onto a given segment, whatever the others: orthogonal
    /// (or along the smoothed normal field), not clamped to [0, 1]. Used
    /// where the partner is known (segment-based integration).
    Projection
    project_onto(const Point<dim> &x, const unsigned int segment) const;

    /// The best projection of x among the valid ones (`valid`, with their
    /// distances) settled where a vertex decides it: with the smoothed
    /// normal as it is; at a tie between the two segments of a groove, or
    /// within 1e-6 of a segment's end, the vertex with its normal.
    Projection
    settle_at_vertex(
      const Point<dim>                                 &x,
      Projection                                        best,
      const std::vector<std::pair<Projection, double>> &valid) const;

    /// x paired with the end `end` (0 or 1) of `segment`: with the vertex
    /// normal where a neighbouring segment meets it (at_vertex), clamped to
    /// the end of an open surface otherwise.
    Projection
    project_onto_vertex(const Point<dim>  &x,
                        const unsigned int segment,
                        const unsigned int end) const;

    /// Indices of the segments whose current bounding box meets `box`.
    std::vector<unsigned int>
    segments_near(const BoundingBox<dim> &box) const;

    /// Smallest reference length of a segment.
    double
    min_segment_length() const;

    /// The largest angle by which the surface turns at a vertex between two
    /// of its segments (the angle between their outward normals there, in
    /// the reference configuration, in radians), and that vertex; 0 on a
    /// surface without shared vertices.
    std::pair<double, Point<dim>>
    sharpest_turn() const;

  private:
    /// Add the rotated copies of the sector's segments that lie in the
    /// window, and give every vertex of the continued surface one index
    /// (the end vertex of a copy is the start vertex of the next; where the
    /// surface closes the circle, its two ends are one vertex).
    void
    add_rotated_copies(const double       sector_angle,
                       const unsigned int copies,
                       const double       window_before,
                       const double       window_after);

    /// Each segment's neighbours: the segments that share its vertices.
    void
    find_neighbours();

    /// Along the smoothed normal field: (x - x(t)) x n(t) = 0.
    Projection
    project_along_smoothed_normal(const Point<dim>  &x,
                                  const unsigned int segment,
                                  const double       extension) const;

    /// The projection at parameter t: clamped to the nearer end if t is
    /// outside [-extension, 1 + extension], with its gap.
    Projection
    finish_projection(const Point<dim>  &x,
                      const unsigned int segment,
                      double             t,
                      const double       extension) const;

    Projection
    project_onto_segment(const Point<dim>  &x,
                         const unsigned int segment,
                         const double       extension) const;

    std::vector<SurfaceSegment> segment_list;
    const bool                  smooth_normals;
    LagrangeBasis1D             geometry;
    LagrangeBasis1D             displacement;
    LagrangeBasis1D             multiplier;
    std::vector<double>         multiplier_node_parameters;
    std::vector<double>         displacement_node_parameters;
    /// Vertex normals at both ends of each segment (set by update()).
    std::vector<std::array<Tensor<1, dim>, 2>> vertex_normals;

    using Box = std::pair<BoundingBox<dim>, unsigned int>;
    RTree<Box> search_tree;
  };

} // namespace RingContact

#endif
