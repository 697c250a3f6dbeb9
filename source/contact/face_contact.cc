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
// unknowns the residual and its exact tangent. Nothing here is
// linearised by hand: the clip vertices, the preimages, the closest points
// and the normals all move with the unknowns through the AD numbers.
#include <deal.II/base/geometry_info.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/lac/full_matrix.h>

#include <ring_contact/contact/face_contact.h>
#include <ring_contact/contact/face_projection.h>
#include <ring_contact/contact/mortar_3d.h>

#include <Sacado.hpp>

#include <algorithm>
#include <limits>
#include <map>
#include <set>
#include <stdexcept>
#include <string>

namespace RingContact
{
  namespace
  {
    using FaceClipping::Vector3;
    using AD = Sacado::Fad::DFad<double>;

    /// The bilinear basis of every face (its polynomials built once).
    const FaceKernel::FaceBasis &
    bilinear()
    {
      static const FaceKernel::FaceBasis basis(1);
      return basis;
    }

    /// The faces of boundary tag `tag`, oriented out of their cells. On
    /// the slave surface (`multipliers` given) each vertex's multiplier
    /// unknown is numbered as a node, in the order first met.
    std::vector<FaceContact::Face>
    surface_faces(const DoFHandler<3>                  &dof_handler,
                  const types::boundary_id              tag,
                  std::vector<types::global_dof_index> *multipliers)
    {
      // Each boundary face of the tag is one face of the surface; a face
      // holds its cell's unknowns at its four vertices, found through the
      // cell's vertex numbers (face_to_cell_vertices() gives them in the
      // face's lexicographic order, the order of the face basis).
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
            if (fe.n_components() < 3 || fe.degree != 1)
              throw std::runtime_error(
                "the 3D " + surface + " surface (boundary tag " +
                std::to_string(tag) +
                ") lies on cells that are not first-order (Q1) hexahedra: "
                "the 3D contact takes bilinear faces");
            if (multipliers != nullptr &&
                (fe.n_components() < 4 ||
                 fe.base_element(fe.component_to_base_index(3).first)
                     .n_dofs_per_vertex() != 1))
              throw std::runtime_error(
                "the cells of the 3D slave surface (boundary tag " +
                std::to_string(tag) + ") carry no contact pressure");
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
            // a1 x a2 at the centre, against the direction out of the cell:
            // a face seen from inside is turned over by exchanging its
            // nodes 1 and 2 (the basis' xi_1 and xi_2).
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
              {
                std::swap(face.u_dofs[1], face.u_dofs[2]);
                std::swap(face.reference[1], face.reference[2]);
                std::swap(face.node[1], face.node[2]);
              }
            faces.push_back(face);
          }
      if (faces.empty())
        throw std::runtime_error("the 3D " + surface +
                                 " surface (boundary tag " +
                                 std::to_string(tag) + ") has no faces");
      return faces;
    }

    /// Whether a face is a parallelogram (x0 - x1 - x2 + x3 = 0 relative to
    /// its size): its map from the plane is then affine. x0 - x1 - x2 + x3
    /// is the bilinear map's twist, the coefficient of xi_1 xi_2; it is
    /// compared with the square of the face's diagonal, so that the test
    /// does not depend on the units.
    bool
    parallelogram(const std::vector<Vector3<double>> &x)
    {
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
    /// distorted faces (doc/validation.md).
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


  FaceContact::FaceContact(const DoFHandler<3>     &dof_handler,
                           const types::boundary_id slave_tag,
                           const types::boundary_id master_tag,
                           const double             c,
                           const bool               geometrically_linear,
                           const Scheme             scheme,
                           const unsigned int       gauss_points)
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
    slave  = surface_faces(dof_handler, slave_tag, &multiplier_dofs);
    master = surface_faces(dof_handler, master_tag, nullptr);
    // w_k by the 2 x 2 Gauss rule on each reference slave face (exact for
    // a parallelogram's bilinear N_k |a1 x a2|). The weights are the
    // reference configuration's in finite strain too: they scale the open
    // nodes' rows w_k lambda_k and the active-set choice, where a fixed
    // scale keeps the complementarity function's switch where it was.
    node_weights.assign(n_nodes(), 0.);
    const QGauss<2>           rule(2);
    std::vector<double>       N;
    std::vector<Tensor<1, 2>> dN;
    for (const Face &face : slave)
      for (unsigned int q = 0; q < rule.size(); ++q)
        {
          bilinear().evaluate(rule.point(q), N, dN);
          const auto   p  = FaceKernel::evaluate(face.reference, N, dN);
          const auto   n  = FaceClipping::cross(p.a1, p.a2);
          const double dA = std::sqrt(FaceClipping::dot(n, n)) * rule.weight(q);
          for (unsigned int k = 0; k < 4; ++k)
            node_weights[face.node[k]] += N[k] * dA;
        }
    gaps.assign(n_nodes(), 0.);
    is_covered.assign(n_nodes(), false);
  }


  // The positions of a face's nodes at a solution: the reference
  // positions moved by the displacement unknowns.
  std::vector<Vector3<double>>
  FaceContact::current(const Face &face, const Vector<double> &solution) const
  {
    std::vector<Vector3<double>> x = face.reference;
    for (unsigned int k = 0; k < 4; ++k)
      for (unsigned int d = 0; d < 3; ++d)
        x[k][d] += solution(face.u_dofs[k][d]);
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
        centre += Point<3>(v[0], v[1], v[2]) / 4.;
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
        return geometrically_linear ? face.reference : current(face, solution);
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
            bilinear().evaluate(points[q].xi, N, dN);
            const auto x = FaceKernel::evaluate(xs, N, dN).x;
            PointPair  best{s, q, numbers::invalid_unsigned_int};
            double     nearest = std::numeric_limits<double>::max();
            for (const unsigned int m :
                 on.search.near(Point<3>(x[0], x[1], x[2]), diameter))
              {
                near.insert(m);
                const auto found =
                  FaceKernel::closest_point(bilinear(), on.faces[m].nodes, x);
                if (found.converged && found.inside &&
                    found.distance < nearest &&
                    PointToFace::is_minimum(
                      bilinear(), on.faces[m].nodes, x, found.xi))
                  {
                    nearest = found.distance;
                    best    = {s, q, m};
                  }
              }
            // No master face under the point (beyond the master's edge):
            // it adds nothing, as a slave segment past the master does in 2D.
            if (best.master_face == numbers::invalid_unsigned_int)
              continue;
            point_pairs.push_back(best);
            overlapping.emplace_back(s, best.master_face);
            const auto terms =
              PointToFace::point_terms<double>(xs,
                                               on.faces[best.master_face].nodes,
                                               current(slave[s], solution),
                                               current(master[best.master_face],
                                                       solution),
                                               {},
                                               points[q]);
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
      for (const auto &node : face->u_dofs)
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


  // One pair's rows in AD numbers of its 28 unknowns: the slave face's 12
  // displacements, the master face's 12 and the slave face's 4 pressures;
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
    constexpr unsigned int n    = 28;
    const auto             dofs = pair_dofs(s, m);
    const auto             none = numbers::invalid_unsigned_int;
    std::vector<AD>        lambda;
    for (unsigned int k = 0; k < 4; ++k)
      lambda.push_back(derivatives ? AD(n, 24 + k, solution(dofs[24 + k])) :
                                     AD(solution(dofs[24 + k])));
    // The positions in AD numbers; in small strain the clip, the points
    // and the normal take the reference positions (constants), the gaps
    // the current ones.
    const auto xs = ad_nodes(current(s, solution), n, derivatives ? 0 : none);
    const auto xm = ad_nodes(current(m, solution), n, derivatives ? 12 : none);
    const auto sg = geometrically_linear ? ad_nodes(s.reference, n, none) : xs;
    const auto mg = geometrically_linear ? ad_nodes(m.reference, n, none) : xm;
    const auto terms =
      point != nullptr ?
        PointToFace::point_terms(sg, mg, xs, xm, lambda, points[point->point]) :
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
