// The contact of two surfaces in 3D (face_contact.h): the surfaces from
// the mesh, the pairs and the active set, and the rows of the Newton
// system in AD numbers.
//
// A Newton iteration asks two things of the class, in this order (through
// ContactInterface<3>, which chooses the active set between them): pair()
// at the iterate (the pairs and the weighted gaps in double), then
// assemble() at the same iterate (each pair's rows and their derivatives). The
// values and the derivatives come from one function per pair, written in
// any number type: Mortar3D::pair_terms() for the clipped pairs,
// PointToFace::point_terms() for a slave point; in double it gives the
// weighted gaps of pair(), in Sacado's DFad numbers of the pair's 28
// unknowns (58 between biquadratic faces) the residual and its exact
// tangent. Nothing here is
// linearised by hand: the clip vertices, the preimages, the closest points
// and the normals all move with the unknowns through the AD numbers.
#include <deal.II/base/geometry_info.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/grid/reference_cell.h>
#include <deal.II/lac/full_matrix.h>

#include <ring_contact/contact/face_contact.h>
#include <ring_contact/contact/face_projection.h>
#include <ring_contact/contact/mortar_3d.h>

#include <Sacado.hpp>

#include <algorithm>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <tuple>

namespace RingContact
{
  namespace
  {
    using FaceClipping::Vector3;
    using AD = Sacado::Fad::DFad<double>;

    /// The refusals of a contact surface's cell: its displacement of
    /// degree 1 or 2 (bilinear or biquadratic faces) and, on the slave
    /// surface, a bilinear contact pressure.
    void
    require_contact_element(const FiniteElement<3>  &fe,
                            const std::string       &surface,
                            const types::boundary_id tag,
                            const bool               slave)
    {
      const std::string where = "the 3D " + surface +
                                " surface (boundary tag " +
                                std::to_string(tag) + ")";
      if (fe.n_components() < 3 ||
          fe.base_element(fe.component_to_base_index(0).first).degree > 2)
        throw std::runtime_error(
          where +
          " lies on cells that are not first- or second-order (Q1, Q2) "
          "hexahedra: the 3D contact takes bilinear and biquadratic faces");
      if (!slave)
        return;
      if (fe.n_components() < 4 ||
          fe.base_element(fe.component_to_base_index(3).first)
              .n_dofs_per_vertex() != 1)
        throw std::runtime_error("the cells of the 3D slave surface (boundary "
                                 "tag " +
                                 std::to_string(tag) +
                                 ") carry no contact pressure");
      if (fe.base_element(fe.component_to_base_index(3).first).degree != 1)
        throw std::runtime_error(
          "Finite elements/Multiplier degree: the contact pressure of " +
          where +
          " must be bilinear (Multiplier degree = 1) in 3D: a quadratic "
          "pressure is 2D only");
    }

    /// The nodes of face `f` of `cell` in the order of the face basis (the
    /// face's lexicographic order, (p + 1)^2 of them for displacement
    /// degree p): their displacement unknowns and reference positions.
    /// Each node is the cell's support point at the face point (i / p,
    /// j / p), found among the displacement's unit support points; the
    /// vertices are the cell's own, the others where `mapping` (or, with
    /// none, the cell's trilinear geometry) puts them.
    void
    add_support_nodes(const DoFHandler<3>::active_cell_iterator  &cell,
                      const unsigned int                          f,
                      const std::vector<types::global_dof_index> &local,
                      const hp::MappingCollection<3>             *mapping,
                      FaceContact::Face                          &face)
    {
      const FiniteElement<3> &fe = cell->get_fe();
      const FiniteElement<3> &base =
        fe.base_element(fe.component_to_base_index(0).first);
      const unsigned int      p = base.degree;
      std::array<Point<3>, 4> corner; // the face's vertices, unit cell
      for (unsigned int v = 0; v < 4; ++v)
        corner[v] = GeometryInfo<3>::unit_cell_vertex(
          GeometryInfo<3>::face_to_cell_vertices(f, v));
      const Mapping<3> &linear =
        ReferenceCells::get_hypercube<3>().get_default_linear_mapping<3, 3>();
      for (unsigned int j = 0; j <= p; ++j)
        for (unsigned int i = 0; i <= p; ++i)
          {
            const double   s = double(i) / p, t = double(j) / p;
            const Point<3> unit =
              Point<3>((1 - s) * (1 - t) * corner[0] + s * (1 - t) * corner[1] +
                       (1 - s) * t * corner[2] + s * t * corner[3]);
            unsigned int b = 0;
            while (b < base.n_dofs_per_cell() &&
                   base.unit_support_point(b).distance(unit) > 1e-12)
              ++b;
            AssertThrow(b < base.n_dofs_per_cell(),
                        ExcMessage("a face node is no support point"));
            std::array<types::global_dof_index, 3> dofs;
            for (unsigned int d = 0; d < 3; ++d)
              dofs[d] = local[fe.component_to_system_index(d, b)];
            const bool vertex = i % p == 0 && j % p == 0;
            const auto x =
              vertex ?
                cell->vertex(
                  GeometryInfo<3>::face_to_cell_vertices(f,
                                                         i / p + 2 * (j / p))) :
              mapping != nullptr ?
                (*mapping)[cell->active_fe_index()].transform_unit_to_real_cell(
                  cell, unit) :
                linear.transform_unit_to_real_cell(cell, unit);
            face.support_dofs.push_back(dofs);
            face.support_points.push_back({{x[0], x[1], x[2]}});
          }
    }

    /// A face turned over: its basis' xi_1 and xi_2 exchanged (the
    /// vertices 1 and 2; on a biquadratic face the nodes (i, j) and (j, i)).
    void
    turn_over(FaceContact::Face &face)
    {
      std::swap(face.u_dofs[1], face.u_dofs[2]);
      std::swap(face.reference[1], face.reference[2]);
      std::swap(face.node[1], face.node[2]);
      const unsigned int n = face.support_points.size() == 9 ? 3 : 2;
      for (unsigned int j = 0; j < n; ++j)
        for (unsigned int i = j + 1; i < n; ++i)
          {
            std::swap(face.support_dofs[i + n * j],
                      face.support_dofs[j + n * i]);
            std::swap(face.support_points[i + n * j],
                      face.support_points[j + n * i]);
          }
    }

    /// The faces of boundary tag `tag`, oriented out of their cells. On
    /// the slave surface (`multipliers` given) each vertex's multiplier
    /// unknown is numbered as a node, in the order first met.
    std::vector<FaceContact::Face>
    surface_faces(const DoFHandler<3>                  &dof_handler,
                  const types::boundary_id              tag,
                  std::vector<types::global_dof_index> *multipliers,
                  const hp::MappingCollection<3>       *mapping)
    {
      // Each boundary face of the tag is one face of the surface; a face
      // holds its cell's unknowns at its vertices, found through the
      // cell's vertex numbers (face_to_cell_vertices() gives them in the
      // face's lexicographic order, the order of the face basis), and at
      // all its nodes (add_support_nodes()).
      const std::string              surface = multipliers ? "slave" : "master";
      std::vector<FaceContact::Face> faces;
      std::map<types::global_dof_index, unsigned int> node_of;
      std::vector<types::global_dof_index>            local;
      for (const auto &cell : dof_handler.active_cell_iterators())
        for (const unsigned int f : cell->face_indices())
          {
            if (!cell->face(f)->at_boundary() ||
                cell->face(f)->boundary_id() != tag)
              continue;
            const FiniteElement<3> &fe = cell->get_fe();
            require_contact_element(fe, surface, tag, multipliers != nullptr);
            // The unknowns of the cell; the FESystem's component c at cell
            // vertex v is its base element's unknown v (FE_Q numbers its
            // vertices' unknowns first, in the cell's vertex order).
            local.resize(fe.n_dofs_per_cell());
            cell->get_dof_indices(local);
            FaceContact::Face face;
            face.body = cell->material_id();
            for (unsigned int v = 0; v < 4; ++v)
              {
                const unsigned int cv =
                  GeometryInfo<3>::face_to_cell_vertices(f, v);
                for (unsigned int d = 0; d < 3; ++d)
                  face.u_dofs[v][d] =
                    local[fe.component_to_system_index(d, cv)];
                const Point<3> &x = cell->vertex(cv);
                face.reference.push_back({{x[0], x[1], x[2]}});
                face.node[v] = numbers::invalid_unsigned_int;
                if (multipliers == nullptr)
                  continue;
                // The pressure unknown at the vertex: one node of the slave
                // surface, shared by the faces around the vertex.
                const auto dof = local[fe.component_to_system_index(3, cv)];
                const auto [at, added] =
                  node_of.emplace(dof, multipliers->size());
                if (added)
                  multipliers->push_back(dof);
                face.node[v] = at->second;
              }
            add_support_nodes(cell, f, local, mapping, face);
            // a1 x a2 at the centre, against the direction out of the cell:
            // a face seen from inside is turned over.
            const auto  &x = face.reference;
            Tensor<1, 3> a1, a2, out;
            for (unsigned int d = 0; d < 3; ++d)
              {
                a1[d]  = x[1][d] - x[0][d] + x[3][d] - x[2][d];
                a2[d]  = x[2][d] - x[0][d] + x[3][d] - x[1][d];
                out[d] = (x[0][d] + x[1][d] + x[2][d] + x[3][d]) / 4 -
                         cell->center()[d];
              }
            if (cross_product_3d(a1, a2) * out < 0)
              turn_over(face);
            faces.push_back(face);
          }
      if (faces.empty())
        throw std::runtime_error("the 3D " + surface +
                                 " surface (boundary tag " +
                                 std::to_string(tag) + ") has no faces");
      return faces;
    }

    /// The unit normal of a face (its nodes) at xi, a1 x a2: out of its
    /// cell, as the faces are oriented.
    Tensor<1, 3>
    unit_normal(const std::vector<Vector3<double>> &nodes, const Point<2> &xi)
    {
      std::vector<double>       N;
      std::vector<Tensor<1, 2>> dN;
      FaceKernel::basis_for(nodes.size()).evaluate(xi, N, dN);
      const auto   p = FaceKernel::evaluate(nodes, N, dN);
      const auto   a = FaceClipping::cross(p.a1, p.a2);
      Tensor<1, 3> n;
      for (unsigned int d = 0; d < 3; ++d)
        n[d] = a[d];
      return n / n.norm();
    }

    /// Whether a face is a parallelogram (x0 - x1 - x2 + x3 = 0 relative to
    /// its size): its map from the plane is then affine. x0 - x1 - x2 + x3
    /// is the bilinear map's twist, the coefficient of xi_1 xi_2; it is
    /// compared with the square of the face's diagonal, so that the test
    /// does not depend on the units. A biquadratic face is taken as none.
    bool
    parallelogram(const std::vector<Vector3<double>> &x)
    {
      if (x.size() != 4)
        return false;
      double warp = 0, size = 0;
      for (unsigned int d = 0; d < 3; ++d)
        {
          warp += std::pow(x[0][d] - x[1][d] - x[2][d] + x[3][d], 2);
          size += std::pow(x[3][d] - x[0][d], 2);
        }
      return warp <= 1e-24 * size;
    }

    /// The rule on the clip triangles of a pair of faces (pair_terms()):
    /// between parallelograms the integrands are polynomials and the
    /// 7-point rule (degree 5) integrates them exactly; on other faces they
    /// are rational functions of the plane's coordinates, and the 28-point
    /// rule (degree 11) leaves an error at round-off on moderately
    /// distorted faces (doc/validation.md). Between biquadratic faces the
    /// integrands are of degree 6 and more: the 28-point rule.
    const Quadrature<2> &
    clip_rule(const std::vector<Vector3<double>> &slave,
              const std::vector<Vector3<double>> &master)
    {
      static const QGaussSimplex<2>            exact(3);
      static const QWitherdenVincentSimplex<2> high(6);
      if (parallelogram(slave) && parallelogram(master))
        return exact;
      return high;
    }

    /// The nodes of a face in AD numbers of value x and derivative 1 in
    /// unknown `first` + 3 k + d (or none, `first` invalid). The pair's
    /// independent variables are its unknowns' increments: a node's value
    /// is its position, reference plus displacement, and its derivative
    /// with respect to its displacement unknown is 1.
    std::vector<Vector3<AD>>
    ad_nodes(const std::vector<Vector3<double>> &x,
             const unsigned int                  n_unknowns,
             const unsigned int                  first)
    {
      std::vector<Vector3<AD>> nodes(x.size());
      for (unsigned int k = 0; k < x.size(); ++k)
        for (unsigned int d = 0; d < 3; ++d)
          nodes[k][d] = first == numbers::invalid_unsigned_int ?
                          AD(x[k][d]) :
                          AD(n_unknowns, first + 3 * k + d, x[k][d]);
      return nodes;
    }
  } // namespace


  FaceContact::FaceContact(const DoFHandler<3>            &dof_handler,
                           const types::boundary_id        slave_tag,
                           const types::boundary_id        master_tag,
                           const double                    c,
                           const bool                      geometrically_linear,
                           const Scheme                    scheme,
                           const unsigned int              gauss_points,
                           const hp::MappingCollection<3> *mapping)
      : c(c)
      , geometrically_linear(geometrically_linear)
      , scheme(scheme)
      , points(
          PointToFace::slave_points(scheme == Scheme::gauss ? gauss_points : 0))
  {
    if (!(c > 0))
      throw std::invalid_argument("the complementarity constant must be > 0");
    if (scheme == Scheme::gauss && gauss_points == 0)
      throw std::invalid_argument("the Gauss scheme needs at least one point");
    // The two surfaces, as faces with their unknowns; the slave's vertices
    // numbered as the multiplier nodes.
    slave  = surface_faces(dof_handler, slave_tag, &multiplier_dofs, mapping);
    master = surface_faces(dof_handler, master_tag, nullptr, mapping);
    // The nodal scheme's points are the vertices, the pressure's nodes: on
    // a biquadratic face they would leave the other five nodes unloaded.
    if (scheme == Scheme::nodal && slave.front().support_points.size() != 4)
      throw std::runtime_error(
        "Contact/Integration schemes: the nodal scheme takes bilinear (Q1) "
        "slave faces; on quadratic (Q2) faces it would leave the mid-side "
        "nodes without load: use segment-based or Gauss n");
    // w_k = int M_k dA by the (p + 1) x (p + 1) Gauss rule on each
    // reference slave face (exact for a parallelogram's M_k |a1 x a2|; M_k
    // the pressure's bilinear functions). The weights are the reference
    // configuration's in finite strain too: they scale the open nodes'
    // rows w_k lambda_k and the active-set choice, where a fixed scale
    // keeps the complementarity function's switch where it was.
    node_weights.assign(n_nodes(), 0.);
    std::vector<double>       N, M;
    std::vector<Tensor<1, 2>> dN, dM;
    for (const Face &face : slave)
      {
        const auto &basis = FaceKernel::basis_for(face.support_points.size());
        const QGauss<2> rule(basis.size() == 4 ? 2 : 3);
        for (unsigned int q = 0; q < rule.size(); ++q)
          {
            basis.evaluate(rule.point(q), N, dN);
            FaceKernel::basis_for(4).evaluate(rule.point(q), M, dM);
            const auto   p = FaceKernel::evaluate(face.support_points, N, dN);
            const auto   n = FaceClipping::cross(p.a1, p.a2);
            const double dA =
              std::sqrt(FaceClipping::dot(n, n)) * rule.weight(q);
            for (unsigned int k = 0; k < 4; ++k)
              node_weights[face.node[k]] += M[k] * dA;
          }
      }
    gaps.assign(n_nodes(), 0.);
    is_covered.assign(n_nodes(), false);
  }

  MultiplierNodes
  FaceContact::multiplier_nodes() const
  {
    std::vector<Point<3>>                    positions(n_nodes());
    std::vector<std::array<unsigned int, 4>> faces;
    for (const Face &face : slave)
      {
        faces.push_back(face.node);
        for (unsigned int v = 0; v < 4; ++v)
          positions[face.node[v]] = Point<3>(face.reference[v][0],
                                             face.reference[v][1],
                                             face.reference[v][2]);
      }
    return MultiplierNodes(multiplier_dofs, node_weights, faces, positions);
  }


  // The positions of a face's nodes at a solution: the reference
  // positions moved by the displacement unknowns.
  std::vector<Vector3<double>>
  FaceContact::current(const Face &face, const Vector<double> &solution) const
  {
    std::vector<Vector3<double>> x = face.support_points;
    for (unsigned int k = 0; k < x.size(); ++k)
      for (unsigned int d = 0; d < 3; ++d)
        x[k][d] += solution(face.support_dofs[k][d]);
    return x;
  }


  // @sect4{The pairs and the active set}
  namespace
  {
    /// The master faces at their positions, and their R-tree.
    struct PlacedSurface
    {
      std::vector<FaceKernel::SurfaceFace> faces;
      FaceKernel::FaceSearch               search;
    };

    /// Where a master face comes nearest to a slave point: its closest
    /// point inside the face (`inside`), or else the nearest point of the
    /// face's four straight edges; the distance and the point's xi. (The
    /// face's normal there is taken only where a tie or a free edge needs
    /// it: unit_normal().)
    struct Hit
    {
      unsigned int face;
      double       distance;
      Point<2>     xi;
      bool         inside;
    };

    Hit
    hit_face(const std::vector<Vector3<double>> &nodes,
             const unsigned int                  face,
             const Vector3<double>              &x)
    {
      const auto &basis = FaceKernel::basis_for(nodes.size());
      const auto  found = FaceKernel::closest_point(basis, nodes, x);
      if (found.converged && found.inside &&
          PointToFace::is_minimum(basis, nodes, x, found.xi))
        return {face, found.distance, found.xi, true};
      // The edges as the rows of n nodes along them (n = 2 on a bilinear
      // face, 3 on a biquadratic one, whose edges are taken as two straight
      // halves), in deal.II's lexicographic order: e = 0 at xi_2 = 0, 1 at
      // xi_2 = 1, 2 at xi_1 = 0, 3 at xi_1 = 1.
      const unsigned int n = nodes.size() == 9 ? 3 : 2;
      const auto node      = [n](const unsigned int e, const unsigned int m) {
        return e == 0 ? m :
                    e == 1 ? m + n * (n - 1) :
                    e == 2 ? n * m :
                             n - 1 + n * m;
      };
      Hit best{face, std::numeric_limits<double>::max(), {}, false};
      for (unsigned int e = 0; e < 4; ++e)
        for (unsigned int k = 0; k + 1 < n; ++k)
          {
            const auto  &a = nodes[node(e, k)], &b = nodes[node(e, k + 1)];
            Tensor<1, 3> ab, ax;
            for (unsigned int d = 0; d < 3; ++d)
              {
                ab[d] = b[d] - a[d];
                ax[d] = x[d] - a[d];
              }
            const double t = std::min(1., std::max(0., ax * ab / (ab * ab)));
            const double distance = (ax - t * ab).norm();
            const double s        = (k + t) / (n - 1);
            if (distance < best.distance)
              {
                best.distance = distance;
                best.xi       = e < 2 ? Point<2>(s, e) : Point<2>(e - 2, s);
              }
          }
      return best;
    }

    /// A tie: the master faces that come nearest to a slave point x within
    /// `tolerance` of the nearest, two or more of them (the point faces a
    /// master vertex or edge, as where the meshes match; or it lies behind
    /// one where the master bends towards it, as a penetrated concave
    /// master, where no face holds its closest point inside). The tie's
    /// normal is the mean of theirs, its partner the point where the line
    /// through x along it meets one of them (else the nearest one's point):
    /// PointToFace::Tie, and its face. None otherwise. The tolerance is
    /// 1e-5 of the slave face (gmsh puts the nodes of two meshes at the
    /// same place only to about 1e-9: a test at round-off missed every tie
    /// in 2D).
    std::optional<std::pair<unsigned int, PointToFace::Tie>>
    find_tie(const std::vector<Hit>                     &hits,
             const double                                tolerance,
             const std::vector<FaceKernel::SurfaceFace> &faces,
             const Vector3<double>                      &x)
    {
      double nearest = std::numeric_limits<double>::max();
      for (const Hit &hit : hits)
        nearest = std::min(nearest, hit.distance);
      Tensor<1, 3>     sum;
      std::vector<Hit> tied;
      for (const Hit &hit : hits)
        if (hit.distance <= nearest + tolerance)
          {
            sum += unit_normal(faces[hit.face].nodes, hit.xi);
            tied.push_back(hit);
          }
      if (tied.size() < 2 || sum.norm() == 0)
        return {};
      // The line through x along the normal as a plane point: the plane
      // through x normal to it, at its origin.
      FaceClipping::Plane<double> line;
      for (unsigned int d = 0; d < 3; ++d)
        {
          line.centre[d] = x[d];
          line.normal[d] = sum[d] / sum.norm();
        }
      const Vector3<double> other = std::abs(line.normal[0]) < 0.9 ?
                                      Vector3<double>{{1, 0, 0}} :
                                      Vector3<double>{{0, 1, 0}};
      line.e1 = FaceClipping::unit(FaceClipping::cross(line.normal, other));
      line.e2 = FaceClipping::cross(line.normal, line.e1);
      for (const Hit &hit : tied)
        {
          const auto on_face =
            FaceKernel::find_on_face(FaceKernel::basis_for(
                                       faces[hit.face].nodes.size()),
                                     faces[hit.face].nodes,
                                     line,
                                     FaceClipping::Vector2<double>{{0, 0}});
          const double slack = 1e-9;
          if (on_face.converged && on_face.xi[0] > -slack &&
              on_face.xi[0] < 1 + slack && on_face.xi[1] > -slack &&
              on_face.xi[1] < 1 + slack)
            {
              Point<2> xi;
              for (unsigned int i = 0; i < 2; ++i)
                xi[i] = std::min(1., std::max(0., on_face.xi[i]));
              return std::make_pair(hit.face,
                                    PointToFace::Tie{line.normal, xi});
            }
        }
      return std::make_pair(tied.front().face,
                            PointToFace::Tie{line.normal, tied.front().xi});
    }

    /// A point whose nearest master point is on a face's free edge (no
    /// face holds it inside, none ties): that point and the face's normal
    /// (PointToFace::Tie) if x lies behind the face there (penetrating);
    /// none in front of it.
    std::optional<std::pair<unsigned int, PointToFace::Tie>>
    behind_free_edge(const std::vector<Hit>                     &hits,
                     const std::vector<FaceKernel::SurfaceFace> &faces,
                     const Vector3<double>                      &x)
    {
      const auto nearest = std::min_element(hits.begin(),
                                            hits.end(),
                                            [](const Hit &a, const Hit &b) {
                                              return a.distance < b.distance;
                                            });
      if (nearest == hits.end())
        return {};
      std::vector<double>       N;
      std::vector<Tensor<1, 2>> dN;
      const auto               &nodes = faces[nearest->face].nodes;
      FaceKernel::basis_for(nodes.size()).evaluate(nearest->xi, N, dN);
      const auto      on_edge         = FaceKernel::evaluate(nodes, N, dN).x;
      const auto      n               = unit_normal(nodes, nearest->xi);
      double          signed_distance = 0;
      Vector3<double> normal;
      for (unsigned int d = 0; d < 3; ++d)
        {
          signed_distance += (x[d] - on_edge[d]) * n[d];
          normal[d] = n[d];
        }
      if (!(signed_distance < 0))
        return {};
      return std::make_pair(nearest->face,
                            PointToFace::Tie{normal, nearest->xi});
    }

    PlacedSurface
    place(const std::vector<FaceContact::Face> &faces,
          const std::function<
            std::vector<Vector3<double>>(const FaceContact::Face &)> &geometry)
    {
      std::vector<FaceKernel::SurfaceFace> placed;
      for (const auto &face : faces)
        placed.push_back({{}, geometry(face)});
      FaceKernel::FaceSearch search(placed, 0.);
      return {std::move(placed), std::move(search)};
    }

    /// The centre of a face and its diameter (twice the largest distance
    /// of a node from the centre): the search radius about it.
    std::pair<Point<3>, double>
    centre_and_diameter(const std::vector<Vector3<double>> &x)
    {
      Point<3> centre;
      for (const auto &v : x)
        centre += Point<3>(v[0], v[1], v[2]) / double(x.size());
      double diameter = 0;
      for (const auto &v : x)
        diameter =
          std::max(diameter, 2 * centre.distance(Point<3>(v[0], v[1], v[2])));
      return {centre, diameter};
    }
  } // namespace


  // The candidates of a slave face are the master faces whose boxes meet
  // the cube about its centre of half-width its diameter: the surfaces are
  // paired up to a face's size apart. Segment-based, a candidate whose
  // projection on the slave face's plane does not overlap it adds nothing.
  void
  FaceContact::pair(const Vector<double> &solution)
  {
    // Where the pairs are sought and the normals taken: the reference
    // configuration in small strain (the gaps then linear in the
    // displacement), the current one in finite strain.
    const std::function<std::vector<Vector3<double>>(const Face &)> geometry =
      [&](const Face &face) {
        return geometrically_linear ? face.support_points :
                                      current(face, solution);
      };
    // Everything of the last pair() is found again: the pairs change as
    // the surfaces slide.
    near_pairs.clear();
    overlapping.clear();
    point_pairs.clear();
    std::fill(gaps.begin(), gaps.end(), 0.);
    std::vector<bool> covered(n_nodes(), false);
    if (scheme != Scheme::segment_based)
      pair_points(geometry, solution, covered);
    else
      {
        // Each slave face against the master faces near it: the clip of
        // each gives its share of the face nodes' weighted gaps.
        const PlacedSurface on = place(master, geometry);
        for (unsigned int s = 0; s < slave.size(); ++s)
          {
            const auto xs                 = geometry(slave[s]);
            const auto [centre, diameter] = centre_and_diameter(xs);
            for (const unsigned int m : on.search.near(centre, diameter))
              {
                near_pairs.emplace_back(s, m);
                const auto &xm = on.faces[m].nodes;
                const auto  terms =
                  Mortar3D::pair_terms<double>(xs,
                                               xm,
                                               current(slave[s], solution),
                                               current(master[m], solution),
                                               {},
                                               clip_rule(xs, xm));
                if (!(terms.overlap > 0))
                  continue;
                overlapping.emplace_back(s, m);
                for (unsigned int k = 0; k < 4; ++k)
                  {
                    gaps[slave[s].node[k]] += terms.gaps[k];
                    covered[slave[s].node[k]] = true;
                  }
              }
          }
      }
    is_covered = covered;
  }


  // The point-wise schemes' pairing, the 3D form of the 2D nodal and Gauss
  // schemes' projections.
  //
  // Each point of each slave face is paired with the closest point on the
  // master faces near it (within the slave face's diameter), among those
  // whose closest point lies on the face; of several (a point over a
  // master edge), the nearest, and of equally near ones the first. A point
  // with none stays unpaired.
  void
  FaceContact::pair_points(
    const std::function<std::vector<Vector3<double>>(const Face &)> &geometry,
    const Vector<double>                                            &solution,
    std::vector<bool>                                               &covered)
  {
    const PlacedSurface on = place(master, geometry);
    for (unsigned int s = 0; s < slave.size(); ++s)
      {
        const auto xs       = geometry(slave[s]);
        const auto diameter = centre_and_diameter(xs).second;
        // The master faces met by any point of this face: its candidates
        // (for the sparsity pattern).
        std::set<unsigned int> near;
        for (unsigned int q = 0; q < points.size(); ++q)
          {
            std::vector<double>       N;
            std::vector<Tensor<1, 2>> dN;
            FaceKernel::basis_for(xs.size()).evaluate(points[q].xi, N, dN);
            const auto x = FaceKernel::evaluate(xs, N, dN).x;
            // The faces near the point, each where it comes nearest.
            std::vector<Hit> hits;
            for (const unsigned int m :
                 on.search.near(Point<3>(x[0], x[1], x[2]), diameter))
              {
                near.insert(m);
                hits.push_back(hit_face(on.faces[m].nodes, m, x));
              }
            const auto nearest_inside = std::min_element(
              hits.begin(), hits.end(), [](const Hit &a, const Hit &b) {
                return a.inside > b.inside ||
                       (a.inside == b.inside && a.distance < b.distance);
              });
            const bool inside =
              nearest_inside != hits.end() && nearest_inside->inside;
            // A tie: among every face within the tolerance, inside or not
            // (a point exactly on a master vertex is inside one face there
            // and outside the next by round-off). In finite strain too: the
            // face met first would push the point along its own normal,
            // half a facet's angle off the mean one, and which face that is
            // changed from one iteration to the next by round-off (Newton
            // stalled on SSNP152's rings extruded with matching meshes). The
            // tie's normal is taken again at every iteration's pairing but
            // held in the tangent (a pair holds one master face's unknowns;
            // Newton's iterations there: doc/validation.md).
            const auto tie = find_tie(hits, 1e-5 * diameter, on.faces, x);
            // No face holds the closest point inside and none ties: the
            // point is beyond the master's free edge. Behind the master
            // face there (penetrating), it is pushed out through the edge's
            // nearest point along the face's normal (the 2D nodal scheme
            // pairs it with the segment's end); in front, it adds nothing.
            const auto partner =
              tie || inside ? tie : behind_free_edge(hits, on.faces, x);
            if (!inside && !partner)
              continue;
            PointPair best{s,
                           q,
                           partner ? partner->first : nearest_inside->face};
            if (partner)
              best.tie = partner->second;
            point_pairs.push_back(best);
            overlapping.emplace_back(s, best.master_face);
            const auto terms =
              PointToFace::point_terms<double>(xs,
                                               on.faces[best.master_face].nodes,
                                               current(slave[s], solution),
                                               current(master[best.master_face],
                                                       solution),
                                               {},
                                               points[q],
                                               best.tie ? &*best.tie : nullptr);
            // A Gauss point reaches the face's four nodes, a vertex its own.
            for (unsigned int k = 0; k < 4; ++k)
              {
                gaps[slave[s].node[k]] += terms.gaps[k];
                if (points[q].vertex == numbers::invalid_unsigned_int ||
                    points[q].vertex == k)
                  covered[slave[s].node[k]] = true;
              }
          }
        for (const unsigned int m : near)
          near_pairs.emplace_back(s, m);
      }
  }


  // The couplings are those of the candidates, not only of the pairs that
  // overlap now: a pair that starts to overlap in a later iteration then
  // finds its entries in the pattern. Each pair couples all its unknowns,
  // both faces' displacements and the slave face's pressures, as its
  // local matrix is full.
  std::vector<types::global_dof_index>
  FaceContact::pair_dofs(const Face &s, const Face &m) const
  {
    std::vector<types::global_dof_index> dofs;
    for (const Face *face : {&s, &m})
      for (const auto &node : face->support_dofs)
        dofs.insert(dofs.end(), node.begin(), node.end());
    for (const unsigned int k : s.node)
      dofs.push_back(multiplier_dofs[k]);
    return dofs;
  }

  void
  FaceContact::add_couplings(DynamicSparsityPattern          &pattern,
                             const AffineConstraints<double> &constraints) const
  {
    for (const auto &[s, m] : near_pairs)
      constraints.add_entries_local_to_global(pair_dofs(slave[s], master[m]),
                                              pattern,
                                              false);
    for (const auto dof : multiplier_dofs)
      constraints.add_entries_local_to_global(
        std::vector<types::global_dof_index>{dof}, pattern, false);
  }

  std::vector<std::vector<types::global_dof_index>>
  FaceContact::coupling_blocks() const
  {
    std::vector<std::vector<types::global_dof_index>> blocks;
    for (const auto &[s, m] : near_pairs)
      {
        blocks.push_back(pair_dofs(slave[s], master[m]));
        std::sort(blocks.back().begin(), blocks.back().end());
      }
    return blocks;
  }


  // @sect4{The rows of the Newton system}
  //
  // Each pair (a clipped pair, or a paired slave point) is one local
  // system; the i-th is this process's if i % n_processes == process.
  void
  FaceContact::assemble(const Vector<double>    &solution,
                        const std::vector<bool> &closed,
                        const bool               derivatives,
                        const unsigned int       process,
                        const unsigned int       n_processes,
                        const LocalRows         &add) const
  {
    AssertDimension(closed.size(), n_nodes());
    const bool        segment_based = scheme == Scheme::segment_based;
    const std::size_t n_pairs =
      segment_based ? overlapping.size() : point_pairs.size();
    for (std::size_t i = process; i < n_pairs; i += n_processes)
      {
        const PointPair *point = segment_based ? nullptr : &point_pairs[i];
        const auto [s, m] =
          segment_based ? overlapping[i] :
                          std::make_pair(point->slave_face, point->master_face);
        assemble_pair(
          slave[s], master[m], point, solution, closed, derivatives, add);
      }
  }


  // One pair's rows in AD numbers of its unknowns: the slave face's
  // displacements (12 on a bilinear face, 27 on a biquadratic one), the
  // master face's and the slave face's 4 pressures;
  // the clipped pair's, or with `point` one slave point's. Without
  // derivatives the AD numbers carry none (their values are the same).
  void
  FaceContact::assemble_pair(const Face              &s,
                             const Face              &m,
                             const PointPair         *point,
                             const Vector<double>    &solution,
                             const std::vector<bool> &closed,
                             const bool               derivatives,
                             const LocalRows         &add) const
  {
    const auto         dofs = pair_dofs(s, m);
    const unsigned int n = dofs.size(), first_lambda = n - 4;
    const auto         none = numbers::invalid_unsigned_int;
    std::vector<AD>    lambda;
    for (unsigned int k = 0; k < 4; ++k)
      lambda.push_back(
        derivatives ?
          AD(n, first_lambda + k, solution(dofs[first_lambda + k])) :
          AD(solution(dofs[first_lambda + k])));
    // The positions in AD numbers; in small strain the clip, the points
    // and the normal take the reference positions (constants), the gaps
    // the current ones.
    const auto xs = ad_nodes(current(s, solution), n, derivatives ? 0 : none);
    const auto xm = ad_nodes(current(m, solution),
                             n,
                             derivatives ? 3 * s.support_points.size() : none);
    const auto sg =
      geometrically_linear ? ad_nodes(s.support_points, n, none) : xs;
    const auto mg =
      geometrically_linear ? ad_nodes(m.support_points, n, none) : xm;
    const auto terms =
      point != nullptr ?
        PointToFace::point_terms(sg,
                                 mg,
                                 xs,
                                 xm,
                                 lambda,
                                 points[point->point],
                                 point->tie ? &*point->tie : nullptr) :
        Mortar3D::pair_terms(sg,
                             mg,
                             xs,
                             xm,
                             lambda,
                             clip_rule(FaceKernel::values(sg),
                                       FaceKernel::values(mg)));

    // The pair's residual in the unknowns' order: the forces on the two
    // faces' nodes, then the closed nodes' gap rows c g~_k (the open
    // nodes' rows are the caller's); its derivatives are the local
    // matrix, its values with the sign of a right-hand side -R the local
    // vector.
    std::vector<AD> residual(terms.slave_force);
    residual.insert(residual.end(),
                    terms.master_force.begin(),
                    terms.master_force.end());
    for (unsigned int k = 0; k < 4; ++k)
      residual.push_back(closed[s.node[k]] ? c * terms.gaps[k] : AD(0.));
    FullMatrix<double> local_matrix(derivatives ? n : 0, derivatives ? n : 0);
    Vector<double>     local_rhs(n);
    for (unsigned int i = 0; i < n; ++i)
      {
        local_rhs(i) = -residual[i].val();
        if (derivatives && residual[i].size() > 0)
          for (unsigned int j = 0; j < n; ++j)
            local_matrix(i, j) = residual[i].dx(j);
      }
    add(local_matrix, local_rhs, dofs);
  }
} // namespace RingContact
