// @sect3{A slave point against a master face in 3D (the point-wise schemes)}
//
// The nodal and Gauss N x N schemes of the 2D program, on faces: each
// point of a slave face is paired with its closest point on the master
// surface (face_projection.h), and contributes at its weight omega
//   to the weighted gap of slave node k:   omega N_k g,
//     g = (x_s - x_m(xi_m)) . n_m, positive where the surfaces are apart,
//   to the forces, with lambda = sum_k N_k lambda_k:
//     slave node k:   - omega lambda N_k n_m,
//     master node b:  + omega lambda Phi_b(xi_m) n_m,
// n_m the master face's unit normal at xi_m (out of the master body), the
// derivatives of -sum_k lambda_k g~_k with the normal and the weights held,
// as the mortar terms are (mortar_3d.h: there n is the slave's, towards the
// master, and the signs are the other way round).
//
// The points: nodal, the face's four vertices, each of weight
// int_face N_k dA (the lumped rule; summed over the faces at a node, the
// node's w_k), with N = delta; Gauss N x N, deal.II's Gauss points with
// weight w_q |a1 x a2|. In finite strain the point, its projection and the
// normal follow the current configuration, and in AD numbers the closest
// point's xi is one Newton step of its exact Hessian (its derivatives
// exact); in small strain they are the reference configuration's.
//
// On a biquadratic face (9 nodes) N_k are its own nine functions for the
// positions and forces and the pressure is bilinear on its vertices (M_k,
// as in mortar_3d.h); the nodal scheme takes bilinear faces only (on a
// quadratic one its points would leave the mid-side nodes without load).
//
// Point-wise schemes do not pass the contact patch test where the
// surfaces' vertices do not meet (the node-to-segment limit): the
// multipliers then swing about the uniform pressure.
#ifndef ring_contact_contact_point_to_face_h
#define ring_contact_contact_point_to_face_h

#include <deal.II/base/quadrature_lib.h>

#include <ring_contact/contact/face_projection.h>
#include <ring_contact/contact/mortar_3d.h>

#include <stdexcept>
#include <vector>

namespace RingContact
{
  namespace PointToFace
  {
    using namespace dealii;
    using FaceClipping::Vector3;
    using FaceKernel::FaceBasis;

    /// A point of a slave face: its parameters, and the vertex it is
    /// (nodal) or its rule weight (Gauss, `vertex` invalid).
    struct SlavePoint
    {
      Point<2>     xi;
      unsigned int vertex;
      double       weight;
    };

    /// The points of a slave face: its four vertices (nodal, `n` = 0) or
    /// the n x n Gauss points.
    inline std::vector<SlavePoint>
    slave_points(const unsigned int n)
    {
      std::vector<SlavePoint> points;
      if (n == 0)
        {
          const FaceBasis basis(1);
          for (unsigned int k = 0; k < 4; ++k)
            points.push_back({basis.nodes[k], k, 0.});
          return points;
        }
      const QGauss<2> rule(n);
      for (unsigned int q = 0; q < rule.size(); ++q)
        points.push_back(
          {rule.point(q), numbers::invalid_unsigned_int, rule.weight(q)});
      return points;
    }

    /// A slave point whose closest points on two or more master faces are
    /// as near (a tie: the point faces a master vertex or edge, as where
    /// the meshes match): its partner is where the line through it along
    /// `normal`, the mean of those faces' normals, meets the master face,
    /// at `xi`; the gap and the forces are along `normal`. The 2D nodal
    /// scheme takes the vertex and its normal at a tie. In small strain
    /// both are constants of the reference configuration; in finite strain
    /// the current configuration's at each pairing, held in the tangent.
    struct Tie
    {
      Vector3<double> normal;
      Point<2>        xi;
    };

    /// The values of a point's numbers.
    template <typename Number>
    Vector3<double>
    values(const Vector3<Number> &x)
    {
      return {{FaceClipping::value(x[0]),
               FaceClipping::value(x[1]),
               FaceClipping::value(x[2])}};
    }

    /// Whether the closest point xi of a face to p is a minimum of the
    /// distance (its exact Hessian positive definite): where it is not (a
    /// saddle that Gauss-Newton's steps settled on), its linearisation
    /// would divide by a Hessian that is singular or indefinite.
    inline bool
    is_minimum(const FaceBasis                    &basis,
               const std::vector<Vector3<double>> &nodes,
               const Vector3<double>              &p,
               const Point<2>                     &xi)
    {
      Tensor<2, 2> H;
      FaceKernel::distance_gradient(nodes,
                                    p,
                                    FaceKernel::ShapeDerivatives(basis, xi),
                                    &H);
      return H[0][0] > 0 && determinant(H) > 1e-14 * H.norm_square();
    }

    /// |a1 x a2| at shape gradients dN on a face.
    template <typename Number>
    Number
    area_element(const std::vector<Vector3<Number>> &nodes,
                 const std::vector<double>          &N,
                 const std::vector<Tensor<1, 2>>    &dN)
    {
      const auto q = FaceKernel::evaluate(nodes, N, dN);
      const auto n = FaceClipping::cross(q.a1, q.a2);
      return sqrt(FaceClipping::dot(n, n));
    }

    /// The terms of one slave point of the face `slave_geometry` against
    /// the master face `master_geometry`, whose closest point to it is
    /// found again here (closest_point(), in the values), so that the terms
    /// are a function of the positions alone; the gaps with the positions
    /// `slave` and `master` (PairTerms, as mortar_3d.h's pair_terms()).
    /// `tie`, if given, is the point's partner instead of its closest
    /// point (Tie).
    template <typename Number>
    Mortar3D::PairTerms<Number>
    point_terms(const std::vector<Vector3<Number>> &slave_geometry,
                const std::vector<Vector3<Number>> &master_geometry,
                const std::vector<Vector3<Number>> &slave,
                const std::vector<Vector3<Number>> &master,
                const std::vector<Number>          &lambda,
                const SlavePoint                   &point,
                const Tie                          *tie = nullptr)
    {
      const FaceBasis &s_basis = FaceKernel::basis_for(slave_geometry.size());
      const FaceBasis &m_basis = FaceKernel::basis_for(master_geometry.size());
      const unsigned int        ns = slave.size(), nm = master.size();
      std::vector<double>       N, M;
      std::vector<Tensor<1, 2>> dN;
      // The point's shape values (N of the face's nodes, M of the
      // pressure's bilinear functions, the same on a bilinear face) and
      // weight omega.
      Number omega = 0;
      if (point.vertex == numbers::invalid_unsigned_int)
        {
          s_basis.evaluate(point.xi, N, dN);
          omega = point.weight * area_element(slave_geometry, N, dN);
          M     = ns == 4 ?
                    N :
                    FaceKernel::bilinear_values(
                  FaceClipping::Vector2<double>{{point.xi[0], point.xi[1]}});
        }
      else
        {
          if (ns != 4)
            throw std::invalid_argument(
              "point_terms(): the nodal scheme takes bilinear faces");
          const QGauss<2> rule(2);
          for (unsigned int q = 0; q < rule.size(); ++q)
            {
              s_basis.evaluate(rule.point(q), N, dN);
              omega += rule.weight(q) * N[point.vertex] *
                       area_element(slave_geometry, N, dN);
            }
          N.assign(4, 0.);
          N[point.vertex] = 1;
          M               = N;
        }
      // Its place, its closest point on the master face and the normal
      // there, in the numbers (first order in xi - xi_m0 is all the
      // derivatives need).
      Vector3<Number> x_g = {{0, 0, 0}};
      for (unsigned int k = 0; k < ns; ++k)
        for (unsigned int d = 0; d < 3; ++d)
          x_g[d] += N[k] * slave_geometry[k][d];
      // (At a tie the partner and the normal are the Tie's constants.)
      const auto found =
        tie != nullptr ?
          FaceKernel::ClosestPoint{tie->xi, true, true, 0.} :
          FaceKernel::closest_point(m_basis,
                                    FaceKernel::values(master_geometry),
                                    values(x_g));
      if (!found.converged)
        throw std::runtime_error(
          "a slave point's closest point on its master face was lost");
      const Point<2>                    &xi_m0 = found.xi;
      const auto                         xi    = tie != nullptr ?
                                                   FaceClipping::Vector2<Number>{{xi_m0[0], xi_m0[1]}} :
                                                   FaceKernel::linearised_closest_xi(m_basis,
                                                          master_geometry,
                                                          x_g,
                                                          xi_m0);
      const FaceKernel::ShapeDerivatives s(m_basis, xi_m0);
      const Number        dxi[2] = {xi[0] - xi_m0[0], xi[1] - xi_m0[1]};
      std::vector<Number> Phi(nm);
      Vector3<Number>     a[2];
      for (unsigned int b = 0; b < nm; ++b)
        Phi[b] = s.N[b] + s.dN[b][0] * dxi[0] + s.dN[b][1] * dxi[1];
      for (unsigned int i = 0; i < 2; ++i)
        for (unsigned int d = 0; d < 3; ++d)
          {
            a[i][d] = 0;
            for (unsigned int b = 0; b < nm; ++b)
              a[i][d] += (s.dN[b][i] + s.d2N[b][i][0] * dxi[0] +
                          s.d2N[b][i][1] * dxi[1]) *
                         master_geometry[b][d];
          }
      Vector3<Number> n = FaceClipping::unit(FaceClipping::cross(a[0], a[1]));
      if (tie != nullptr)
        for (unsigned int d = 0; d < 3; ++d)
          n[d] = tie->normal[d];
      // The gap and the terms.
      Number gap = 0, pressure = 0;
      for (unsigned int d = 0; d < 3; ++d)
        {
          Number xs = 0, xm = 0;
          for (unsigned int k = 0; k < ns; ++k)
            xs += N[k] * slave[k][d];
          for (unsigned int k = 0; k < nm; ++k)
            xm += Phi[k] * master[k][d];
          gap += (xs - xm) * n[d];
        }
      Mortar3D::PairTerms<Number> terms;
      terms.gaps.assign(4, Number(0));
      for (unsigned int k = 0; k < 4; ++k)
        terms.gaps[k] = omega * M[k] * gap;
      terms.overlap = FaceClipping::value(omega);
      if (lambda.empty())
        return terms;
      for (unsigned int k = 0; k < 4; ++k)
        pressure += M[k] * lambda[k];
      terms.slave_force.assign(3 * ns, Number(0));
      terms.master_force.assign(3 * nm, Number(0));
      // The slave is pushed along -n here (n is the master's normal):
      // the mortar terms' signs the other way round.
      const std::vector<Number> slave_N(N.begin(), N.end());
      Mortar3D::add_forces(Number(-omega * pressure), n, slave_N, Phi, terms);
      return terms;
    }
  } // namespace PointToFace
} // namespace RingContact

#endif
