// @sect3{The weighted gaps of a pair of 3D faces (segment-based)}
//
// The normal contact of a slave face against a master face in the mortar
// form the 2D program uses: for each node i of the slave face the weighted
// gap
//   g_i = int N_i(xi_s) (x_m(xi_m) - x_s(xi_s)) . n dA
// over the part of the slave face that the master face covers, n the
// slave face's normal (its auxiliary plane's), positive where the surfaces
// are apart. The integral is taken on the clip triangles of the two faces
// (face_clipping.h) with a triangle rule, each point found on both faces
// (face_kernel.h). Written in any number type: in AD numbers of the two
// faces' coordinates it gives the exact linearisation the Newton iteration
// needs (the clip vertices, the points and their preimages all move with
// the unknowns).
//
// Bilinear (4 nodes) and biquadratic (9 nodes) faces. A biquadratic face
// is clipped as its four bilinear quarters (the polygons of its nodes;
// Puso, Laursen & Solberg 2008), each point then found on the whole
// curved face: the quarters only cut the integration into cells where the
// integrands are smooth, the geometry and the shape functions are the
// face's own. The contact pressure is bilinear on the face's vertices
// whatever its degree (the multiplier one degree below a quadratic
// displacement, as in 2D: the inf-sup condition).
#ifndef ring_contact_contact_mortar_3d_h
#define ring_contact_contact_mortar_3d_h

#include <deal.II/base/quadrature_lib.h>

#include <ring_contact/contact/face_clipping.h>
#include <ring_contact/contact/face_kernel.h>

#include <stdexcept>
#include <vector>

namespace RingContact
{
  namespace Mortar3D
  {
    using namespace dealii;
    using FaceClipping::Vector2;
    using FaceClipping::Vector3;
    using FaceKernel::FaceBasis;

    /// The corners of a bilinear face whose nodes are in the basis' order
    /// (lexicographic), in order around it, as the clip takes them.
    template <typename Number>
    std::vector<Vector3<Number>>
    corners(const std::vector<Vector3<Number>> &nodes)
    {
      return {nodes[0], nodes[1], nodes[3], nodes[2]};
    }

    /// The polygons a face is clipped as: a bilinear face's corners, or
    /// the corners of the four quarters of a biquadratic face (its nine
    /// nodes lexicographic, k = i + 3 j), each in order around it.
    template <typename Number>
    std::vector<std::vector<Vector3<Number>>>
    clip_polygons(const std::vector<Vector3<Number>> &nodes)
    {
      if (nodes.size() == 4)
        return {corners(nodes)};
      std::vector<std::vector<Vector3<Number>>> quarters;
      for (unsigned int j = 0; j < 2; ++j)
        for (unsigned int i = 0; i < 2; ++i)
          {
            const unsigned int k = i + 3 * j;
            quarters.push_back(
              {nodes[k], nodes[k + 1], nodes[k + 4], nodes[k + 3]});
          }
      return quarters;
    }

    /// What a slave face and a master face contribute to the contact rows:
    /// the weighted gaps g_k = int M_k g dA of the slave face's four
    /// vertices (M_k the bilinear functions of the pressure), and the nodal
    /// forces of the contact pressure lambda = sum_k M_k lambda_k on the
    /// two faces' nodes (4 or 9 each, N_a and Phi_b their shape
    /// functions), as residual terms (three components per node):
    ///   slave node a:   + int lambda N_a n dA,
    ///   master node b:  - int lambda Phi_b n dA,
    /// the derivatives of -sum_k lambda_k g_k with the normal and the
    /// weights held (the mortar form of Popp et al.; the pressure pushes
    /// the slave back along -n and the master along n, and the two forces
    /// balance: sum_a N_a = sum_b Phi_b = 1). On bilinear faces M = N.
    template <typename Number>
    struct PairTerms
    {
      std::vector<Number> gaps;
      std::vector<Number> slave_force, master_force;
      /// The area of the clip polygon (zero where the faces do not
      /// overlap).
      double overlap = 0;
    };

    /// The forces of a pressure f (a weight times the pressure) along n at
    /// a point: + f N_a n on the slave face's nodes, - f Phi_b n on the
    /// master's.
    template <typename Number>
    void
    add_forces(const Number              &f,
               const Vector3<Number>     &n,
               const std::vector<Number> &N,
               const std::vector<Number> &Phi,
               PairTerms<Number>         &terms)
    {
      for (unsigned int d = 0; d < 3; ++d)
        {
          const Number fn = f * n[d];
          for (unsigned int a = 0; a < N.size(); ++a)
            terms.slave_force[3 * a + d] += fn * N[a];
          for (unsigned int b = 0; b < Phi.size(); ++b)
            terms.master_force[3 * b + d] -= fn * Phi[b];
        }
    }

    /// The terms of PairTerms for faces whose clip, points and normal are
    /// those of `slave_geometry` and `master_geometry` and whose gaps are
    /// those of the positions `slave` and `master`: the same nodes in
    /// finite strain (the current configuration), the reference nodes and
    /// the displaced ones in small strain (gaps linear in the
    /// displacement). `lambda`: the slave nodes' pressures (may be empty
    /// for the gaps alone). `rule` is the quadrature on each clip triangle
    /// (on the reference triangle): where both faces are parallelograms,
    /// the integrands are polynomials of the plane's coordinates, and
    /// QGaussSimplex<2>(3) integrates the products of two bilinear
    /// functions exactly; on other faces the preimages, and so the
    /// integrands, are not polynomials and a rule of a higher degree
    /// leaves a smaller error; on biquadratic faces the integrands are of
    /// a degree above 5 and the higher rule is needed.
    template <typename Number>
    PairTerms<Number>
    pair_terms(const std::vector<Vector3<Number>> &slave_geometry,
               const std::vector<Vector3<Number>> &master_geometry,
               const std::vector<Vector3<Number>> &slave,
               const std::vector<Vector3<Number>> &master,
               const std::vector<Number>          &lambda,
               const Quadrature<2>                &rule)
    {
      // The bases by the faces' numbers of nodes (built once each).
      const FaceBasis &s_basis = FaceKernel::basis_for(slave_geometry.size());
      const FaceBasis &m_basis = FaceKernel::basis_for(master_geometry.size());
      if (slave.size() != slave_geometry.size() ||
          master.size() != master_geometry.size())
        throw std::invalid_argument(
          "pair_terms(): a face's positions and geometry differ in size");
      const unsigned int ns = slave.size(), nm = master.size();
      PairTerms<Number>  terms;
      terms.gaps.assign(4, Number(0));
      terms.slave_force.assign(lambda.empty() ? 0 : 3 * ns, Number(0));
      terms.master_force.assign(lambda.empty() ? 0 : 3 * nm, Number(0));
      for (const auto &slave_part : clip_polygons(slave_geometry))
        for (const auto &master_part : clip_polygons(master_geometry))
          {
            const auto cell = FaceClipping::clip_faces(slave_part, master_part);
            for (const auto &t : cell.triangles)
              for (unsigned int q = 0; q < rule.size(); ++q)
                {
                  // The point in the plane, in the numbers of the clip
                  // vertices.
                  const auto     &v = t.vertices;
                  const Point<2> &l = rule.point(q);
                  Vector2<Number> p;
                  for (unsigned int d = 0; d < 2; ++d)
                    p[d] = v[0][d] + l[0] * (v[1][d] - v[0][d]) +
                           l[1] * (v[2][d] - v[0][d]);
                  // Its preimages on both faces, with their derivatives.
                  const FaceKernel::Preimage on_s = FaceKernel::find_on_face(
                    s_basis, slave_geometry, cell.plane, p);
                  const FaceKernel::Preimage on_m = FaceKernel::find_on_face(
                    m_basis, master_geometry, cell.plane, p);
                  if (!on_s.converged || !on_m.converged)
                    throw std::runtime_error(
                      "a clip point was not found on its faces");
                  const auto at_s = FaceKernel::linearised_xi(
                    s_basis, slave_geometry, cell.plane, p, on_s.xi);
                  const std::vector<Number> &N = at_s.N;
                  const std::vector<Number>  Phi =
                    FaceKernel::linearised_xi(
                      m_basis, master_geometry, cell.plane, p, on_m.xi)
                      .N;
                  // The pressure's functions: the face's own on a bilinear
                  // face, the bilinear ones of the vertices on a quadratic.
                  const std::vector<Number> M =
                    ns == 4 ? N : FaceKernel::bilinear_values(at_s.xi);
                  // The gap along the plane's normal.
                  Number gap = 0;
                  for (unsigned int d = 0; d < 3; ++d)
                    {
                      Number xs = 0, xm = 0;
                      for (unsigned int k = 0; k < ns; ++k)
                        xs += N[k] * slave[k][d];
                      for (unsigned int k = 0; k < nm; ++k)
                        xm += Phi[k] * master[k][d];
                      gap += (xm - xs) * cell.plane.normal[d];
                    }
                  // The weight is the clip triangle's area in the auxiliary
                  // plane: the slave face's own where the face is planar (a
                  // warped face's differs to second order in its warp).
                  const Number w = rule.weight(q) * 2. * t.area;
                  terms.overlap += FaceClipping::value(w);
                  for (unsigned int i = 0; i < 4; ++i)
                    terms.gaps[i] += w * M[i] * gap;
                  if (lambda.empty())
                    continue;
                  Number pressure = 0;
                  for (unsigned int k = 0; k < 4; ++k)
                    pressure += M[k] * lambda[k];
                  add_forces(
                    Number(w * pressure), cell.plane.normal, N, Phi, terms);
                }
          }
      return terms;
    }

    /// The weighted gaps g_i of the slave face's four nodes against one
    /// master face, in the current configuration (pair_terms()), with
    /// QGaussSimplex<2>(points).
    template <typename Number>
    std::vector<Number>
    weighted_gaps(const std::vector<Vector3<Number>> &slave,
                  const std::vector<Vector3<Number>> &master,
                  const unsigned int                  points = 3)
    {
      return pair_terms(
               slave, master, slave, master, {}, QGaussSimplex<2>(points))
        .gaps;
    }
  } // namespace Mortar3D
} // namespace RingContact

#endif
