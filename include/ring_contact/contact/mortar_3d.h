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
// Bilinear faces (degree 1); a quadratic face is to be split into four
// bilinear sub-faces before the clip (Puso, Laursen & Solberg 2008).
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

    /// The weighted gaps g_i of the slave face's four nodes against one
    /// master face, with deal.II's Gauss rule for triangles of `points`
    /// points per direction (QGaussSimplex; 3 integrates the bilinear
    /// products of two planar faces exactly).
    template <typename Number>
    std::vector<Number>
    weighted_gaps(const std::vector<Vector3<Number>> &slave,
                  const std::vector<Vector3<Number>> &master,
                  const unsigned int                  points = 3)
    {
      // One basis for every call (its polynomials are built once).
      static const FaceBasis basis(1);
      if (slave.size() != basis.size() || master.size() != basis.size())
        throw std::invalid_argument("weighted_gaps() takes bilinear faces");
      std::vector<Number> gaps(4, Number(0));
      const auto          cell =
        FaceClipping::clip_faces(corners(slave), corners(master));
      const QGaussSimplex<2> rule(points);
      for (const auto &t : cell.triangles)
        for (unsigned int q = 0; q < rule.size(); ++q)
          {
            // The point in the plane, in the numbers of the clip vertices.
            const auto     &v = t.vertices;
            const Point<2> &l = rule.point(q);
            Vector2<Number> p;
            for (unsigned int d = 0; d < 2; ++d)
              p[d] = v[0][d] + l[0] * (v[1][d] - v[0][d]) +
                     l[1] * (v[2][d] - v[0][d]);
            // Its preimages on both faces, with their derivatives.
            const FaceKernel::Preimage on_s =
              FaceKernel::find_on_face(basis, slave, cell.plane, p);
            const FaceKernel::Preimage on_m =
              FaceKernel::find_on_face(basis, master, cell.plane, p);
            if (!on_s.converged || !on_m.converged)
              throw std::runtime_error(
                "a clip point was not found on its faces");
            const std::vector<Number> N =
              FaceKernel::linearised_xi(basis, slave, cell.plane, p, on_s.xi).N;
            const std::vector<Number> Phi =
              FaceKernel::linearised_xi(basis, master, cell.plane, p, on_m.xi)
                .N;
            // The gap along the plane's normal.
            Number gap = 0;
            for (unsigned int d = 0; d < 3; ++d)
              {
                Number xs = 0, xm = 0;
                for (unsigned int k = 0; k < 4; ++k)
                  {
                    xs += N[k] * slave[k][d];
                    xm += Phi[k] * master[k][d];
                  }
                gap += (xm - xs) * cell.plane.normal[d];
              }
            // The weight is the clip triangle's area in the auxiliary
            // plane: the slave face's own where the face is planar (a
            // warped face's differs to second order in its warp).
            const Number w = rule.weight(q) * 2. * t.area;
            for (unsigned int i = 0; i < 4; ++i)
              gaps[i] += w * N[i] * gap;
          }
      return gaps;
    }
  } // namespace Mortar3D
} // namespace RingContact

#endif
