// @sect3{The geometry of a face of a 3D contact surface}
//
// The 3D counterpart of the segment kernel (surface_kernel.h): a face of a
// hexahedron's boundary is the surface
//   x(xi) = sum_k N_k(xi) x_k,   xi in [0, 1]^2,
// with N_k the tensor-product Lagrange basis of degree p at the face's
// (p + 1)^2 nodes, in lexicographic order (k = i + (p + 1) j for the node
// at (i / p, j / p)), and x_k the nodes' current positions. Its tangents
// are a_1 = dx/dxi_1, a_2 = dx/dxi_2, its normal a_1 x a_2 / |a_1 x a_2|
// and its area element |a_1 x a_2|.
//
// Segment-based integration (face_clipping.h) puts its points on the clip
// triangles of the auxiliary plane; each point is then found on the slave
// face and on the master face: the xi whose face point projects onto it
// along the plane's normal. That xi is found by Newton's method on values
// (find_on_face()); in AD numbers it is one more Newton step taken in the
// numbers of the nodes, the plane and the point (linearised_xi()), which
// gives its first derivatives exactly (the implicit function theorem), as
// the 2D kernel does for the pieces' ends.
#ifndef ring_contact_contact_face_kernel_h
#define ring_contact_contact_face_kernel_h

#include <deal.II/base/point.h>
#include <deal.II/base/polynomial.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/tensor_product_polynomials.h>

#include <ring_contact/contact/face_clipping.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace RingContact
{
  namespace FaceKernel
  {
    using namespace dealii;
    using FaceClipping::Plane;
    using FaceClipping::Vector2;
    using FaceClipping::Vector3;

    /// The Lagrange basis of a face of degree p: deal.II's tensor product
    /// of the 1D Lagrange polynomials through p + 1 equidistant points.
    class FaceBasis
    {
    public:
      explicit FaceBasis(const unsigned int degree)
          : polynomials(Polynomials::generate_complete_Lagrange_basis(
              equidistant(degree)))
      {
        const std::vector<Point<1>> points = equidistant(degree);
        for (const auto &y : points)
          for (const auto &x : points)
            nodes.emplace_back(x[0], y[0]);
      }

      unsigned int
      size() const
      {
        return nodes.size();
      }

      /// The values and gradients of every basis function at xi, and
      /// their second derivatives if `hessians` is given.
      void
      evaluate(const Point<2>            &xi,
               std::vector<double>       &values,
               std::vector<Tensor<1, 2>> &gradients,
               std::vector<Tensor<2, 2>> *hessians = nullptr) const
      {
        values.resize(size());
        gradients.resize(size());
        std::vector<Tensor<2, 2>> none2;
        std::vector<Tensor<3, 2>> none3;
        std::vector<Tensor<4, 2>> none4;
        if (hessians != nullptr)
          hessians->resize(size());
        polynomials.evaluate(xi,
                             values,
                             gradients,
                             hessians != nullptr ? *hessians : none2,
                             none3,
                             none4);
      }

      /// The nodes' reference positions, in the basis' order.
      std::vector<Point<2>> nodes;

    private:
      static std::vector<Point<1>>
      equidistant(const unsigned int degree)
      {
        std::vector<Point<1>> points;
        for (unsigned int i = 0; i <= degree; ++i)
          points.emplace_back(static_cast<double>(i) / degree);
        return points;
      }

      TensorProductPolynomials<2> polynomials;
    };

    /// A point of a face and its tangents.
    /// The basis of a face of `n_nodes` nodes: bilinear (4) or
    /// biquadratic (9), each built once.
    inline const FaceBasis &
    basis_for(const std::size_t n_nodes)
    {
      static const FaceBasis bilinear(1), biquadratic(2);
      if (n_nodes == bilinear.size())
        return bilinear;
      if (n_nodes == biquadratic.size())
        return biquadratic;
      throw std::invalid_argument("a face has 4 (bilinear) or 9 "
                                  "(biquadratic) nodes, not " +
                                  std::to_string(n_nodes));
    }

    /// The bilinear functions at the vertices (lexicographic) at xi, in
    /// the numbers of xi: the contact pressure's basis on a face of any
    /// degree (its multiplier is bilinear on the face's vertices).
    template <typename Number>
    std::vector<Number>
    bilinear_values(const Vector2<Number> &xi)
    {
      return {(1. - xi[0]) * (1. - xi[1]),
              xi[0] * (1. - xi[1]),
              (1. - xi[0]) * xi[1],
              xi[0] * xi[1]};
    }

    template <typename Number>
    struct FacePoint
    {
      Vector3<Number> x, a1, a2;
    };

    /// The face point of shape values N and gradients dN (at some xi).
    template <typename Number>
    FacePoint<Number>
    evaluate(const std::vector<Vector3<Number>> &nodes,
             const std::vector<double>          &values,
             const std::vector<Tensor<1, 2>>    &gradients)
    {
      FacePoint<Number> p;
      for (unsigned int d = 0; d < 3; ++d)
        {
          p.x[d]  = 0;
          p.a1[d] = 0;
          p.a2[d] = 0;
          for (unsigned int k = 0; k < nodes.size(); ++k)
            {
              p.x[d] += values[k] * nodes[k][d];
              p.a1[d] += gradients[k][0] * nodes[k][d];
              p.a2[d] += gradients[k][1] * nodes[k][d];
            }
        }
      return p;
    }

    /// The values of a face's numbers (its nodes, a plane, a point).
    template <typename Number>
    std::vector<Vector3<double>>
    values(const std::vector<Vector3<Number>> &nodes)
    {
      std::vector<Vector3<double>> v(nodes.size());
      for (unsigned int k = 0; k < nodes.size(); ++k)
        for (unsigned int d = 0; d < 3; ++d)
          v[k][d] = FaceClipping::value(nodes[k][d]);
      return v;
    }

    template <typename Number>
    Plane<double>
    values(const Plane<Number> &plane)
    {
      Plane<double> v;
      for (unsigned int d = 0; d < 3; ++d)
        {
          v.centre[d] = FaceClipping::value(plane.centre[d]);
          v.normal[d] = FaceClipping::value(plane.normal[d]);
          v.e1[d]     = FaceClipping::value(plane.e1[d]);
          v.e2[d]     = FaceClipping::value(plane.e2[d]);
        }
      return v;
    }

    /// The residual r(xi) = to_plane(x(xi)) - p of a face point against a
    /// point p of the plane, and its Jacobian J_ab = e_a . a_b.
    template <typename Number>
    Vector2<Number>
    plane_residual(const FacePoint<Number> &q,
                   const Plane<Number>     &plane,
                   const Vector2<Number>   &p,
                   Tensor<2, 2>            *jacobian = nullptr)
    {
      const Vector2<Number> at = FaceClipping::to_plane(plane, q.x);
      if (jacobian != nullptr)
        {
          const Vector3<Number> *a[2] = {&q.a1, &q.a2};
          const Vector3<Number> *e[2] = {&plane.e1, &plane.e2};
          for (unsigned int i = 0; i < 2; ++i)
            for (unsigned int j = 0; j < 2; ++j)
              (*jacobian)[i][j] =
                FaceClipping::value(FaceClipping::dot(*e[i], *a[j]));
        }
      return {{at[0] - p[0], at[1] - p[1]}};
    }

    /// Where on a face the point p of the plane lies: xi with
    /// to_plane(x(xi)) = p, by Newton's method on values from the face's
    /// centre, to `tolerance` in xi. `converged` is false if the face is
    /// too distorted to be seen from the plane (a singular Jacobian) or
    /// the iteration does not settle in 20 steps.
    struct Preimage
    {
      Point<2> xi;
      bool     converged;
    };

    template <typename Number>
    Preimage
    find_on_face(const FaceBasis                    &basis,
                 const std::vector<Vector3<Number>> &nodes,
                 const Plane<Number>                &plane,
                 const Vector2<Number>              &p,
                 const double                        tolerance = 1e-14)
    {
      // The nodes and the plane about the plane's centre: the iteration's
      // round-off is then that of the face's size, not of its distance
      // from the origin (a face far out would never meet the tolerance).
      std::vector<Vector3<double>> x      = values(nodes);
      Plane<double>                plane0 = values(plane);
      for (auto &node : x)
        for (unsigned int d = 0; d < 3; ++d)
          node[d] -= plane0.centre[d];
      plane0.centre            = {{0, 0, 0}};
      const Vector2<double> p0 = {
        {FaceClipping::value(p[0]), FaceClipping::value(p[1])}};
      std::vector<double>       N;
      std::vector<Tensor<1, 2>> dN;
      Point<2>                  xi(0.5, 0.5);
      for (unsigned int step = 0; step < 20; ++step)
        {
          basis.evaluate(xi, N, dN);
          Tensor<2, 2>          J;
          const Vector2<double> r =
            plane_residual(evaluate(x, N, dN), plane0, p0, &J);
          if (std::abs(determinant(J)) < 1e-14 * J.norm_square())
            return {xi, false};
          const Tensor<2, 2> Jinv = invert(J);
          const Point<2>     delta(Jinv[0][0] * r[0] + Jinv[0][1] * r[1],
                               Jinv[1][0] * r[0] + Jinv[1][1] * r[1]);
          xi -= delta;
          if (delta.norm() <= tolerance)
            return {xi, true};
        }
      return {xi, false};
    }

    /// The xi of find_on_face() in the numbers of the nodes, the plane and
    /// the point, xi0 - J^-1 r(xi0), whose value is xi0 and whose
    /// derivatives are those of the exact preimage; and the shape values
    /// there, N(xi0) + dN(xi0) (xi - xi0), exact to first order in xi - xi0,
    /// which is all the derivatives need. One evaluation of the basis.
    template <typename Number>
    struct LinearisedPreimage
    {
      Vector2<Number>     xi;
      std::vector<Number> N;
    };

    template <typename Number>
    LinearisedPreimage<Number>
    linearised_xi(const FaceBasis                    &basis,
                  const std::vector<Vector3<Number>> &nodes,
                  const Plane<Number>                &plane,
                  const Vector2<Number>              &p,
                  const Point<2>                     &xi0)
    {
      std::vector<double>       N;
      std::vector<Tensor<1, 2>> dN;
      basis.evaluate(xi0, N, dN);
      Tensor<2, 2>          J;
      const Vector2<Number> r =
        plane_residual(evaluate(nodes, N, dN), plane, p, &J);
      const Tensor<2, 2>         Jinv = invert(J);
      LinearisedPreimage<Number> result;
      result.xi = {{xi0[0] - (Jinv[0][0] * r[0] + Jinv[0][1] * r[1]),
                    xi0[1] - (Jinv[1][0] * r[0] + Jinv[1][1] * r[1])}};
      result.N.resize(N.size());
      for (unsigned int k = 0; k < N.size(); ++k)
        result.N[k] = N[k] + dN[k][0] * (result.xi[0] - xi0[0]) +
                      dN[k][1] * (result.xi[1] - xi0[1]);
      return result;
    }
  } // namespace FaceKernel
} // namespace RingContact

#endif
