// @sect3{Contact surfaces: geometry, normals and the closest-point search}
//
// A contact surface is the boundary of one body with a given boundary id, seen
// as segments in the current configuration x = X + u. The slave and the master
// are both ContactSurfaces: the slave's segments carry the quadrature points
// and the multipliers, the master's give the partners and the normal. The
// geometry of a segment is written once, for any number type, in
// surface_kernel.h; this file is its double path (the Lagrange bases of a
// segment are in lagrange_basis.cc): the surface built from the mesh's
// faces (continued by rotated copies under cyclic symmetry), its current
// state with the vertex normals and a search tree, and the closest-point
// projection. The contact element
// (contact_assembly.cc) linearises in AD numbers what is computed here, so the
// two make the same choices: which normal, which partner.
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe.h>
#include <deal.II/grid/manifold.h>
#include <deal.II/physics/transformations.h>

#include <ring_contact/base/components.h>
#include <ring_contact/base/dimension.h>
#include <ring_contact/base/utilities.h>
#include <ring_contact/contact/contact_surface.h>

#include <boost/geometry/index/rtree.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <sstream>
#include <string>

namespace RingContact
{
  // @sect4{Building a contact surface}
  //
  // Every boundary face with the surface's boundary id becomes a segment: its
  // displacement (and, on the slave, multiplier and tangential) dofs ordered
  // along the face, the reference positions of the mapping's support points,
  // and the orientation of its outward normal. Under cyclic symmetry the master
  // is then continued by rotated copies; last, each segment learns its
  // neighbours, which the vertex normals, the smoothed normals and the
  // segment-based cuts need.

  namespace
  {
    // Newton's method for f(t) = 0 on a segment from t0, with f and f'
    // given by `f_and_slope`; t is kept in [-1, 2] (a projection further
    // out is of no use), and returned as it is after convergence or 30
    // iterations.
    // The interval [-1, 2] holds every parameter a projection may use (an
    // extension of a whole segment on either side, for held partners), and it
    // keeps a step from a poor start from running off to a far root of the
    // polynomial. A zero slope gives a non-finite t, which ends the iteration
    // and is clamped by finish_projection().
    template <typename Function>
    double
    solve_on_segment(double t, const Function &f_and_slope)
    {
      for (unsigned int it = 0; it < 30; ++it)
        {
          const auto [f, slope] = f_and_slope(t);
          const double dt       = -f / slope;
          t += dt;
          if (std::abs(dt) < 1e-15 || !std::isfinite(t))
            break;
          t = std::max(-1.0, std::min(2.0, t));
        }
      return t;
    }

    // Nodes of the mapping's support points on a face: Gauss-Lobatto, as in
    // MappingQ.
    // The contact surface interpolates the very points the bulk's mapping puts
    // on its boundary, so that contact and bulk see one boundary.
    std::vector<double>
    gauss_lobatto_nodes(const unsigned int degree)
    {
      std::vector<double> nodes;
      if (degree == 1)
        return {0.0, 1.0};
      const QGaussLobatto<1> q(degree + 1);
      for (const auto &p : q.get_points())
        nodes.push_back(p[0]);
      return nodes;
    }
    // A face's unknowns sorted into the segment's lists by component, with
    // the position t in [0, 1] along the face of each displacement and
    // multiplier node.
    void
    sort_face_dofs(const FiniteElement<dim>                   &fe,
                   const std::vector<types::global_dof_index> &face_dofs,
                   SurfaceSegment                             &segment,
                   std::vector<double>                        &u_nodes,
                   std::vector<double>                        &lambda_nodes)
    {
      for (unsigned int i = 0; i < face_dofs.size(); ++i)
        {
          const auto [component, index_in_base] =
            fe.face_system_to_component_index(i);
          const auto &base =
            fe.base_element(fe.component_to_base_index(component).first);
          const double t = base.unit_face_support_point(index_in_base)[0];
          if (component == Components::ux)
            {
              segment.dofs_x.push_back(face_dofs[i]);
              u_nodes.push_back(t);
            }
          else if (component == Components::uy)
            segment.dofs_y.push_back(face_dofs[i]);
          else if (component == Components::tangential<dim>)
            segment.tangential_dofs.push_back(face_dofs[i]);
          else
            {
              segment.multiplier_dofs.push_back(face_dofs[i]);
              lambda_nodes.push_back(t);
            }
        }
    }

    // One index per vertex of the continued surface, by its angle on the
    // circle: the end vertex of a copy is the start vertex of the next, and
    // where the surface closes the circle its two ends meet.
    // The copies carry their originals' mesh vertex indices, which would join a
    // copy to its original's neighbours; numbered by angle, every vertex of the
    // continued surface has one index. An angle within 1e-10 of 2 pi is the
    // start side's: where the window is exactly the circle, or the sector is
    // every element around (the rings cut open at angle 0, no copy), the
    // surface closes there into one curve.
    void
    number_vertices_by_angle(
      std::vector<SurfaceSegment>                     &segment_list,
      const std::function<double(const Point<dim> &)> &angle_of_point)
    {
      std::vector<std::pair<double, unsigned int>> ends; // angle, 2 s + end
      for (unsigned int s = 0; s < segment_list.size(); ++s)
        for (unsigned int side = 0; side < 2; ++side)
          {
            const Point<dim> x     = side == 0 ?
                                       segment_list[s].reference_nodes.front() :
                                       segment_list[s].reference_nodes.back();
            double           angle = angle_of_point(x);
            if (angle > 2 * numbers::PI - 1e-10)
              angle = 0;
            ends.emplace_back(angle, 2 * s + side);
          }
      // Ends closer than 1e-10 rad are one vertex: a copy's turned nodes meet
      // their neighbours' to round-off only.
      std::sort(ends.begin(), ends.end());
      unsigned int n_vertices = 0;
      for (unsigned int i = 0; i < ends.size(); ++i)
        {
          if (i > 0 && ends[i].first - ends[i - 1].first > 1e-10)
            ++n_vertices;
          segment_list[ends[i].second / 2].vertices[ends[i].second % 2] =
            n_vertices;
        }
    }
  } // namespace

  ContactSurface::ContactSurface(const DoFHandler<dim>   &dof_handler,
                                 const types::boundary_id boundary_id,
                                 const unsigned int       mapping_degree,
                                 const bool               smooth_normals,
                                 const double             sector_angle,
                                 const unsigned int       copies,
                                 const double             window_before,
                                 const double             window_after)
      : smooth_normals(smooth_normals)
  {
    const std::vector<double> geometry_nodes =
      gauss_lobatto_nodes(mapping_degree);
    AssertThrow(geometry_nodes.size() <= LagrangeBasis1D::max_size,
                ExcMessage("mapping degree above 4 is not supported"));
    geometry = LagrangeBasis1D(geometry_nodes);

    std::vector<double> displacement_nodes, multiplier_nodes;
    // Faces in the order of the active cells: the segments' numbering, and with
    // it the order of the pairing, is the mesh's; the vertex normals (update())
    // keep the results independent of it.
    for (const auto &cell : dof_handler.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary() &&
            cell->face(f)->boundary_id() == boundary_id)
          {
            const auto                           face = cell->face(f);
            const FiniteElement<dim>            &fe   = cell->get_fe();
            std::vector<types::global_dof_index> face_dofs(
              fe.n_dofs_per_face());
            face->get_dof_indices(face_dofs, cell->active_fe_index());

            SurfaceSegment segment;
            segment.cell     = cell;
            segment.face_no  = f;
            segment.vertices = {{face->vertex_index(0), face->vertex_index(1)}};

            // Sort the face dofs by component, and record where each sits
            // along the face (its support point in face coordinates).
            std::vector<double> u_nodes, lambda_nodes;
            // face_system_to_component_index() and unit_face_support_point()
            // speak of the face's own numbering, t from its vertex 0 to its
            // vertex 1: the parameter of the reference geometry below. A
            // component that is FE_Nothing on the face's cell (the multiplier
            // on the master, the tangential traction without friction) has no
            // dofs here.
            sort_face_dofs(fe, face_dofs, segment, u_nodes, lambda_nodes);
            // All faces of the surface belong to one ring: one element.
            // The bases are the surface's, shared by all its segments: a
            // surface whose faces have elements of two degrees is refused.
            if (segment_list.empty())
              {
                displacement_nodes = u_nodes;
                multiplier_nodes   = lambda_nodes;
              }
            AssertThrow(u_nodes == displacement_nodes &&
                          lambda_nodes == multiplier_nodes,
                        ExcMessage("contact surface " +
                                   std::to_string(boundary_id) +
                                   " mixes finite elements"));

            // Reference geometry: the mapping's support points, on the
            // face's manifold.
            // The vertices are taken as they are, not through the manifold,
            // whose chart would return them to round-off only: adjacent
            // segments share their end points exactly.
            const Point<dim> v0 = face->vertex(0), v1 = face->vertex(1);
            for (const double t : geometry_nodes)
              segment.reference_nodes.push_back(
                (t == 0.0) ?
                  v0 :
                (t == 1.0) ?
                  v1 :
                  face->get_manifold().get_intermediate_point(v0, v1, t));

            // Outward normal: n = (dx_y, -dx_x) / |dx| must point from the
            // cell center towards the face.
            // A face's vertex order says nothing of the side its cell lies on;
            // the cell centre does. Decided once, in the reference
            // configuration: a deformation that turned it round would have
            // inverted a cell, which Newton's method rejects.
            segment.orientation = 1.0;
            segment_list.push_back(segment);
            const CurvePoint mid =
              reference_point(segment_list.size() - 1, 0.5);
            if (SurfaceKernel::scaled_normal(mid.dx, 1.0) *
                  (mid.x - cell->center()) <
                0)
              segment_list.back().orientation = -1.0;
          }
    AssertThrow(displacement_nodes.size() <= LagrangeBasis1D::max_size,
                ExcMessage("displacement degree above 4 is not supported"));
    displacement                 = LagrangeBasis1D(displacement_nodes);
    multiplier                   = LagrangeBasis1D(multiplier_nodes);
    multiplier_node_parameters   = multiplier_nodes;
    displacement_node_parameters = displacement_nodes;
    // Copies before neighbours: the neighbours of the continued surface join
    // the copies to each other and to the sector.
    if (sector_angle > 0)
      add_rotated_copies(sector_angle, copies, window_before, window_after);

    find_neighbours();
  }


  // The neighbours of each segment: the segments that share a vertex.
  // By vertex index: the mesh's, or the numbering by angle of
  // add_rotated_copies(). A vertex of one segment only is an end of an open
  // surface: no neighbour there, the vertex normal is the segment's own, and
  // a projection beyond it is clamped.
  void
  ContactSurface::find_neighbours()
  {
    std::map<unsigned int, std::vector<unsigned int>> segments_at_vertex;
    for (unsigned int s = 0; s < segment_list.size(); ++s)
      for (const unsigned int v : segment_list[s].vertices)
        segments_at_vertex[v].push_back(s);
    for (unsigned int s = 0; s < segment_list.size(); ++s)
      for (unsigned int end = 0; end < 2; ++end)
        {
          const unsigned int v = segment_list[s].vertices[end];
          for (const unsigned int other : segments_at_vertex[v])
            if (other != s)
              {
                segment_list[s].neighbours[end] = other;
                segment_list[s].neighbour_t[end] =
                  segment_list[other].vertices[0] == v ? 0.0 : 1.0;
              }
        }
  }

  // @sect4{Cyclic symmetry: the master surface beyond the sector}
  //
  // Slave points near the sector's sides, and those that slide past them, need
  // the master surface beyond the sector. It is the sector's own, turned
  // through j Phi (j = +-1, ..., +-copies): copies of its segments with turned
  // reference nodes and the originals' unknowns, read turned (update()). Only
  // the segments inside the window of CyclicSymmetry::set_master_window() are
  // kept, so that the continued surface covers the circle at most once: copies
  // that lay on top of the sector made the pairing meet coincident master
  // segments, and Newton failed (k = 21 and 23 to 39 of 40 around).
  void
  ContactSurface::add_rotated_copies(const double       sector_angle,
                                     const unsigned int copies,
                                     const double       window_before,
                                     const double       window_after)
  {
    // The two open ends of the sector's surface: the vertices that only one
    // segment has; `start` at angle 0, `end` at the sector angle.
    std::map<unsigned int, unsigned int> count;
    std::map<unsigned int, Point<dim>>   position;
    for (const auto &segment : segment_list)
      for (unsigned int end = 0; end < 2; ++end)
        {
          const unsigned int v = segment.vertices[end];
          ++count[v];
          position[v] = end == 0 ? segment.reference_nodes.front() :
                                   segment.reference_nodes.back();
        }
    std::vector<unsigned int> open_ends;
    for (const auto &[v, n] : count)
      if (n == 1)
        open_ends.push_back(v);
    AssertThrow(open_ends.size() == 2,
                ExcMessage("cyclic symmetry: the contact surface of the "
                           "sector must be one open curve"));
    // The start side (angle 0) is the end whose turn through Phi lands on the
    // other; the sides must be images of each other to 1e-10 of the radius, or
    // the sector's ties would join points that are not images.
    using Physics::Transformations::Rotations::rotation_matrix_2d;
    const Tensor<2, dim> R_sector = rotation_matrix_2d(sector_angle);
    unsigned int         start = open_ends[0], end = open_ends[1];
    if (position[start].distance(Point<dim>(R_sector * position[end])) <
        position[end].distance(Point<dim>(R_sector * position[start])))
      std::swap(start, end);
    const double tolerance = 1e-10 * position[start].norm();
    AssertThrow(position[end].distance(Point<dim>(R_sector * position[start])) <
                  tolerance,
                ExcMessage("cyclic symmetry: the ends of the contact surface "
                           "are not images of each other"));

    // Angles from the start side, in [0, 2 pi): the sector's segments lie
    // in (0, sector_angle).
    // Measured from the start vertex with atan2 of the cross and dot products:
    // the start side is at 0 wherever the mesh puts it.
    const Point<dim> origin         = position[start];
    const auto       angle_of_point = [&](const Point<dim> &x) {
      const double angle =
        std::atan2(origin[0] * x[1] - origin[1] * x[0], origin * x);
      return angle < 0 ? angle + 2 * numbers::PI : angle;
    };
    const std::vector<SurfaceSegment> sector = segment_list;
    std::vector<double>               sector_angles;
    for (unsigned int s = 0; s < sector.size(); ++s)
      sector_angles.push_back(angle_of_point(reference_point(s, 0.5).x));

    // Copy j (j = -copies ... copies, 0: the sector itself) of a segment
    // sits at its angle + j sector_angle; keep the segments in the window,
    // which covers the circle at most once, so that no master position is
    // there twice.
    // The sector first, then -1, +1, -2, ...: every copy is made from the
    // untouched segments of `sector`, not from an already turned one. A copy
    // keeps its original's dofs: its unknowns are the original's, turned by
    // `rotation` where the surface reads them (update()) and in the contact
    // element.
    segment_list.clear();
    std::vector<int> shifts = {0};
    for (int j = 1; j <= static_cast<int>(copies); ++j)
      shifts.insert(shifts.end(), {-j, j});
    for (const int j : shifts)
      for (unsigned int s = 0; s < sector.size(); ++s)
        {
          const double angle = sector_angles[s] + j * sector_angle;
          // The sector itself (j = 0) is kept whole; the window is measured in
          // the sector's own angle, from its start side.
          if (j != 0 &&
              (angle < -window_before || angle >= sector_angle + window_after))
            continue;
          SurfaceSegment segment = sector[s];
          if (j != 0)
            {
              // x = R (X + u): the reference nodes are turned here, once; the
              // displacement at every update().
              segment.is_copy  = true;
              segment.rotation = rotation_matrix_2d(j * sector_angle);
              for (auto &node : segment.reference_nodes)
                node = Point<dim>(segment.rotation * node);
            }
          segment_list.push_back(segment);
        }

    number_vertices_by_angle(segment_list, angle_of_point);
  }

  // @sect4{Points and normals}
  //
  // Positions are evaluated into arrays on the stack: the projections of the
  // search evaluate segments millions of times, and these functions allocate
  // nothing. The current point is X + u in positions; where a gap must survive
  // the round-off of the positions, ContactInterface computes it from the
  // reference part and the displacement (displacement_at()) apart.
  CurvePoint
  ContactSurface::reference_point(const unsigned int segment,
                                  const double       t) const
  {
    double N[LagrangeBasis1D::max_size], dN[LagrangeBasis1D::max_size],
      ddN[LagrangeBasis1D::max_size];
    geometry.evaluate(t, N, dN, ddN);
    const auto &nodes = segment_list[segment].reference_nodes;
    CurvePoint  p;
    SurfaceKernel::add_interpolation(
      p, nodes.size(), N, dN, ddN, [&](const unsigned int j) {
        return nodes[j];
      });
    return p;
  }

  // x(t) = X(t) + u(t), each through its own basis: a ring's mapping degree may
  // differ from its displacement degree (Mapping degree = 1 keeps a quadratic
  // ring's reference segments straight).
  CurvePoint
  ContactSurface::current_point(const unsigned int segment,
                                const double       t) const
  {
    CurvePoint p = reference_point(segment, t);
    double     N[LagrangeBasis1D::max_size], dN[LagrangeBasis1D::max_size],
      ddN[LagrangeBasis1D::max_size];
    displacement.evaluate(t, N, dN, ddN);
    const auto &u = segment_list[segment].nodal_displacements;
    SurfaceKernel::add_interpolation(
      p, u.size(), N, dN, ddN, [&](const unsigned int i) { return u[i]; });
    return p;
  }

  // u(t) alone, in the current state: the gaps are computed as a reference part
  // plus the normal jump of this displacement.
  Tensor<1, dim>
  ContactSurface::displacement_at(const unsigned int segment,
                                  const double       t) const
  {
    double N[LagrangeBasis1D::max_size], dN[LagrangeBasis1D::max_size],
      ddN[LagrangeBasis1D::max_size];
    displacement.evaluate(t, N, dN, ddN);
    const auto    &u = segment_list[segment].nodal_displacements;
    Tensor<1, dim> value;
    for (unsigned int i = 0; i < u.size(); ++i)
      value += N[i] * u[i];
    return value;
  }

  // The segment's outward unit normal at a point, from its current tangent: n =
  // o (x'_y, -x'_x) / |x'|, o the orientation fixed at construction.
  Tensor<1, dim>
  ContactSurface::normal(const unsigned int segment,
                         const CurvePoint  &point) const
  {
    return SurfaceKernel::unit(
      SurfaceKernel::scaled_normal(point.dx,
                                   segment_list[segment].orientation));
  }

  // The turn at each shared vertex, from the two segments' own normals there
  // (not the vertex normal, their average). Rotated copies are left out:
  // they repeat the sector's own vertices.
  std::pair<double, Point<dim>>
  ContactSurface::sharpest_turn() const
  {
    std::pair<double, Point<dim>> sharpest{0.0, Point<dim>()};
    for (unsigned int s = 0; s < segment_list.size(); ++s)
      for (unsigned int end = 0; end < 2; ++end)
        {
          const SurfaceSegment &segment   = segment_list[s];
          const unsigned int    neighbour = segment.neighbours[end];
          if (segment.is_copy || neighbour == numbers::invalid_unsigned_int ||
              segment_list[neighbour].is_copy)
            continue;
          const CurvePoint     here = reference_point(s, end);
          const Tensor<1, dim> a =
            SurfaceKernel::scaled_normal(here.dx, segment.orientation);
          const Tensor<1, dim> b = SurfaceKernel::scaled_normal(
            reference_point(neighbour, segment.neighbour_t[end]).dx,
            segment_list[neighbour].orientation);
          const double angle =
            std::atan2(std::abs(a[0] * b[1] - a[1] * b[0]), a * b);
          if (angle > sharpest.first)
            sharpest = {angle, here.x};
        }
    return sharpest;
  }

  // Not normalised, |x'| n: the weight of the segment in a vertex normal.
  Tensor<1, dim>
  ContactSurface::scaled_normal(const unsigned int segment,
                                const double       t) const
  {
    return SurfaceKernel::scaled_normal(current_point(segment, t).dx,
                                        segment_list[segment].orientation);
  }

  Tensor<1, dim>
  ContactSurface::vertex_normal(const unsigned int segment,
                                const unsigned int end) const
  {
    return vertex_normals[segment][end];
  }

  // The original's LISSAGE: n(t) proportional to (1 - t) n0 + t n1 along the
  // segment, continuous across the vertices, so that a point sliding over a
  // vertex sees no jump of its normal and no vertex rule is needed. Not
  // normalised: the projection condition (x - x(t)) x m(t) = 0 takes the
  // direction as it is.
  Tensor<1, dim>
  ContactSurface::smoothed_normal_direction(const unsigned int segment,
                                            const double       t) const
  {
    return SurfaceKernel::smoothed_direction(vertex_normal(segment, 0),
                                             vertex_normal(segment, 1),
                                             t);
  }

  // The normal at a projection, chosen as the contact element chooses it
  // (evaluate_partner_and_normal()): the smoothed field, the vertex normal at a
  // vertex, else the segment's own. The two must agree, or the gaps of the
  // active set and those of the residual would differ.
  Tensor<1, dim>
  ContactSurface::normal(const Projection &projection) const
  {
    if (smooth_normals)
      {
        return SurfaceKernel::unit(
          smoothed_normal_direction(projection.segment, projection.t));
      }
    if (!projection.at_vertex)
      return normal(projection.segment,
                    current_point(projection.segment, projection.t));
    return vertex_normal(projection.segment,
                         static_cast<unsigned int>(projection.t));
  }

  Projection
  ContactSurface::project_along_smoothed_normal(const Point<dim>  &x,
                                                const unsigned int segment,
                                                const double extension) const
  {
    // Newton on f(t) = (x - x(t)) x m(t) with m(t) = (1 - t) n0 + t n1,
    // from the orthogonal projection.
    // The orthogonal projection is a close start: on a straight stretch of the
    // surface, where the vertex normals are the segment's, the two coincide.
    const Tensor<1, dim> n0 = vertex_normal(segment, 0);
    const Tensor<1, dim> n1 = vertex_normal(segment, 1);
    const double         t  = solve_on_segment(
      project_onto_segment(x, segment, 1.0).t, [&](const double t) {
        const CurvePoint p = current_point(segment, t);
        return SurfaceKernel::smoothed_normal_residual(x - p.x, p, n0, n1, t);
      });
    return finish_projection(x, segment, t, extension);
  }

  // @sect4{The current state}
  //
  // At every update of the interface: the nodal displacements of the iterate
  // (turned for copies), the search tree of the current segments and the vertex
  // normals, which all the projections of the iteration then share.
  void
  ContactSurface::update(const Vector<double> &solution)
  {
    std::vector<Box> boxes;
    boxes.reserve(segment_list.size());
    for (unsigned int s = 0; s < segment_list.size(); ++s)
      {
        auto &segment = segment_list[s];
        segment.nodal_displacements.resize(segment.dofs_x.size());
        // R u: for a copy the original's displacement turned, for the mesh's
        // own segments the identity.
        for (unsigned int i = 0; i < segment.dofs_x.size(); ++i)
          segment.nodal_displacements[i] =
            segment.rotation * Tensor<1, dim>({solution(segment.dofs_x[i]),
                                               solution(segment.dofs_y[i])});
        // Box around the current segment: its end points and a few points
        // in between, extended by a margin for the curvature.
        std::vector<Point<dim>> points;
        for (const double t : {0.0, 0.25, 0.5, 0.75, 1.0})
          points.push_back(current_point(s, t).x);
        BoundingBox<dim> box(points);
        box.extend(0.1 * points.front().distance(points.back()));
        boxes.emplace_back(box, s);
      }
    // The R-tree, packed at once from all the boxes, gives a point's candidate
    // segments without a test of every segment.
    search_tree = pack_rtree(boxes);

    // Vertex normals: the length-weighted average of the normals of the
    // segments that meet there.
    // The scaled normal |x'| n at each end: on a straight segment |x'| is its
    // length, hence the length weights. Cached once per update for the search,
    // the smoothed normals and the cuts; the contact element evaluates the same
    // expression (surface_kernel.h) in AD numbers.
    vertex_normals.resize(segment_list.size());
    for (unsigned int s = 0; s < segment_list.size(); ++s)
      for (unsigned int end = 0; end < 2; ++end)
        {
          const unsigned int neighbour = segment_list[s].neighbours[end];
          const bool has_neighbour = neighbour != numbers::invalid_unsigned_int;
          vertex_normals[s][end]   = SurfaceKernel::vertex_normal(
            scaled_normal(s, end),
            has_neighbour ?
                scaled_normal(neighbour, segment_list[s].neighbour_t[end]) :
                Tensor<1, dim>(),
            has_neighbour);
        }
  }

  Projection
  ContactSurface::project_onto_segment(const Point<dim>  &x,
                                       const unsigned int segment,
                                       const double       extension) const
  {
    // Newton on r(t) = (x - x(t)) . x'(t) = 0, from the chord projection.
    // On a straight segment the start is already the answer; on a curved one
    // Newton's method corrects it in a few steps.
    const Point<dim> a = current_point(segment, 0).x;
    const Point<dim> b = current_point(segment, 1).x;
    const double     t = solve_on_segment(
      ((x - a) * (b - a)) / (b - a).norm_square(), [&](const double t) {
        const CurvePoint p = current_point(segment, t);
        return SurfaceKernel::closest_point_residual(x - p.x, p);
      });
    return finish_projection(x, segment, t, extension);
  }

  // Beyond [-extension, 1 + extension], or not finite, the projection is
  // clamped to the nearer end, with the segment's normal there. Its gap is one
  // of positions, provisional: ContactInterface replaces it by the reference
  // part plus the displacement jump (gap_of()).
  Projection
  ContactSurface::finish_projection(const Point<dim>  &x,
                                    const unsigned int segment,
                                    double             t,
                                    const double       extension) const
  {
    Projection projection;
    projection.segment = segment;
    if (!std::isfinite(t) || t < -extension || t > 1 + extension)
      {
        projection.clamped = true;
        t                  = (!std::isfinite(t) || t < 0.5) ? 0.0 : 1.0;
      }
    projection.t   = t;
    projection.gap = (x - current_point(segment, t).x) * normal(projection);
    return projection;
  }

  // @sect4{The closest-point search}
  //
  // Every slave point is paired by project() unless the Newton loop holds its
  // partner. The candidates are the four segments whose current boxes are
  // nearest to x (R-tree), not every segment of the master: the search would
  // otherwise grow with the product of the two surfaces' sizes. Which of them
  // wins, and the vertex rule below, decide the pairing and with it which rows
  // the contact element writes.
  Projection
  ContactSurface::project(const Point<dim>  &x,
                          const unsigned int preferred) const
  {
    namespace bgi = boost::geometry::index;
    std::vector<Box> candidates;
    search_tree.query(bgi::nearest(x, 4), std::back_inserter(candidates));

    // Orthogonal projections that land on their segment are valid. A point
    // may have two (inside a concave corner, or sitting on a vertex as the
    // slave nodes of a node-matching interface do): it then keeps its
    // previous partner, so that the pairing, and the contact force with it,
    // does not flip between Newton iterations. Otherwise the closest valid
    // projection wins; with none (outside a convex corner) the nearest
    // segment end, i.e. a vertex.
    // A projection 1e-8 (in t) past an end still counts as on its segment:
    // round-off must not clamp a point that sits on a vertex. (The partner was
    // once kept up to a quarter of a segment past its end, as the original's
    // TOLE_PROJ_EXT; it is now kept only while its projection is valid.)
    constexpr double tolerance = 1e-8;
    Projection       best, closest_end;
    double           best_distance = std::numeric_limits<double>::max();
    double           end_distance  = std::numeric_limits<double>::max();
    // Every valid projection with its distance, for the tie test below.
    std::vector<std::pair<Projection, double>> valid;
    for (const auto &candidate : candidates)
      {
        const Projection p =
          smooth_normals ?
            project_along_smoothed_normal(x, candidate.second, tolerance) :
            project_onto_segment(x, candidate.second, tolerance);
        const double distance = x.distance(current_point(p.segment, p.t).x);
        if (p.clamped)
          {
            if (distance < end_distance)
              {
                closest_end  = p;
                end_distance = distance;
              }
            continue;
          }
        valid.emplace_back(p, distance);
        if (p.segment == preferred)
          {
            best          = p;
            best_distance = -1; // kept whatever the others
          }
        else if (distance < best_distance)
          {
            best          = p;
            best_distance = distance;
          }
      }
    if (best.segment == numbers::invalid_unsigned_int)
      best = closest_end;
    // No candidate at any finite distance: x, or the surface, is not a
    // finite position.
    // (Both rings with E <= 1e-200 crashed here once.) The Newton loop cuts the
    // step, as after a failed iteration.
    if (best.segment == numbers::invalid_unsigned_int)
      {
        std::ostringstream what;
        what << "a contact point at (" << x[0] << ", " << x[1]
             << ") has no partner on the master surface at a finite distance "
                "(a position is not a finite number)";
        throw NonFiniteState(what.str());
      }

    return settle_at_vertex(x, best, valid);
  }

  // The best projection of project() settled where a vertex decides it.
  Projection
  ContactSurface::settle_at_vertex(
    const Point<dim>                                 &x,
    Projection                                        best,
    const std::vector<std::pair<Projection, double>> &valid) const
  {
    // At a vertex (a corner of the faceted surface, or a point sitting on
    // one as slave nodes do on a node-matching interface) the segment normal
    // is not defined: use the vertex normal, so that the result does not
    // depend on which of the two segments the search met first.
    // This is what makes the nodal scheme independent of the element numbering:
    // the generated mesh and the original's give the same digits.
    constexpr double at_vertex = 1e-6;
    if (smooth_normals)
      {
        // The smoothed normal is continuous: no special case at vertices.
        // With no projection at all (far from the surface) the closest end
        // is used with its vertex normal, and t fixed.
        if (best.clamped)
          best.gap = (x - current_point(best.segment, best.t).x) * normal(best);
        return best;
      }
    // A tie: the point faces a vertex from inside the groove that two
    // segments make (a slave node facing a master vertex across a gap, on
    // matching meshes of a concave master), and projects onto both at the
    // same distance, neither near its end. Either facet's normal would do,
    // and which one the search met first decided: in small strain, which
    // pairs in the reference configuration where the gap stays open, the
    // nodal scheme's pressure error drifted from positive to negative around
    // the quarter of an axisymmetric closing gap (prm/closing_gap.prm, 20
    // segments; doc/validation.md, "Curved geometry, ties and touching
    // bodies"): every node pushed along the tilted facet normal of the
    // segment after it, the rings turned against each other. The vertex,
    // with its normal, is the symmetric choice. "The same distance" allows
    // for the mesh generator: gmsh puts the nodes of two circles at the same
    // angles to some 1e-9 only, and the two distances differ by about
    // 2 sin(half the angle between the segments) times the point's offset
    // along the surface; 1e-5 of the segment's length.
    // (Only where another valid projection exists: the search's hot path
    // is left as it was.)
    if (valid.size() > 1)
      {
        double d_best = 0;
        for (const auto &[p, distance] : valid)
          if (p.segment == best.segment)
            d_best = distance;
        const auto &n = segment_list[best.segment].neighbours;
        for (const auto &[q, distance] : valid)
          {
            const int shared =
              n[0] == q.segment ? 0 : (n[1] == q.segment ? 1 : -1);
            if (shared < 0)
              continue;
            const double h_best =
              current_point(best.segment, 0)
                .x.distance(current_point(best.segment, 1).x);
            if (std::abs(distance - d_best) <= 1e-5 * h_best)
              return project_onto_vertex(x, best.segment, shared);
          }
      }
    // The nearer end when the projection is clamped or within 1e-6 (in t) of
    // it; at the end of an open surface there is no vertex normal, and the
    // projection stands as it is.
    if (best.clamped || std::abs(best.t) < at_vertex ||
        std::abs(1 - best.t) < at_vertex)
      {
        const unsigned int end = best.t < 0.5 ? 0 : 1;
        if (segment_list[best.segment].neighbours[end] !=
            numbers::invalid_unsigned_int)
          return project_onto_vertex(x, best.segment, end);
      }
    return best;
  }

  // A point paired with a vertex: with the vertex normal where a neighbour
  // meets it, clamped at the end of an open surface. For project(), and for a
  // held partner that has run past its end (ContactPairing::pair_points()).
  Projection
  ContactSurface::project_onto_vertex(const Point<dim>  &x,
                                      const unsigned int segment,
                                      const unsigned int end) const
  {
    Projection p;
    p.segment = segment;
    p.t       = end;
    if (segment_list[segment].neighbours[end] != numbers::invalid_unsigned_int)
      p.at_vertex = true;
    else
      p.clamped = true;
    p.gap = (x - current_point(segment, p.t).x) * normal(p);
    return p;
  }

  // Projection onto a known partner: the pieces of segment-based integration
  // and the partners held by the Newton loop.
  Projection
  ContactSurface::project_onto(const Point<dim>  &x,
                               const unsigned int segment) const
  {
    // No clamping: an extension of 100 % of the segment is accepted.
    // A held partner is followed onto its extension, so that the residual stays
    // a smooth function of the displacement during the line search
    // (Pairing::hold); a point of a segment-based piece lies on its partner to
    // round-off anyway.
    Projection p = smooth_normals ?
                     project_along_smoothed_normal(x, segment, 1.0) :
                     project_onto_segment(x, segment, 1.0);
    p.gap        = (x - current_point(segment, p.t).x) * normal(p);
    return p;
  }

  // The segments whose boxes meet a box, in increasing order (the tree's own
  // order depends on its packing): the master vertices near a slave segment,
  // for the segment-based cuts.
  std::vector<unsigned int>
  ContactSurface::segments_near(const BoundingBox<dim> &box) const
  {
    namespace bgi = boost::geometry::index;
    std::vector<Box> found;
    search_tree.query(bgi::intersects(box), std::back_inserter(found));
    std::vector<unsigned int> indices;
    for (const auto &b : found)
      indices.push_back(b.second);
    std::sort(indices.begin(), indices.end());
    return indices;
  }

  // h, the shortest reference chord: the automatic c = E / h and the active
  // set's round-off tolerance are scaled by it.
  double
  ContactSurface::min_segment_length() const
  {
    double h = std::numeric_limits<double>::max();
    for (const auto &segment : segment_list)
      h = std::min(h,
                   segment.reference_nodes.front().distance(
                     segment.reference_nodes.back()));
    return h;
  }

} // namespace RingContact
