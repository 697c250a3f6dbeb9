// @sect3{The closest point on a face, averaged normals and the face search}
//
// What the point-wise schemes (nodal, Gauss N x N) need of a 3D contact
// surface, beside the face geometry of face_kernel.h: the closest point of
// a master face to a slave point, its linearisation, the smoothed normals
// of a surface at its nodes, and the search for the faces near a point.
//
// The closest point minimises f(xi) = |x(xi) - p|^2 / 2 over the face's
// parameters. Its gradient and Hessian are
//   r_a  = (x - p) . a_a,
//   H_ab = a_a . a_b + (x - p) . x_,ab,
// and Newton's method with H converges quadratically from the face's
// centre on any face whose curvature radius exceeds the distance (the
// Hessian is then positive definite); where it is not, the step is Gauss-
// Newton's, with a_a . a_b alone, which descends. xi is kept within half a
// face of the face (a projection further out belongs to a neighbour), and a
// step held at that bound is not convergence.
//
// In AD numbers xi is one more Newton step with the exact Hessian taken in
// the numbers of the nodes and the point, xi0 - H^-1 r(xi0): its value is
// xi0 and its first derivatives those of the exact closest point (the
// implicit function theorem), as linearised_xi() does for the plane
// preimage of segment-based integration.
//
// The smoothed normal at a node is the average of its faces' normals at the
// node, each weighted by its area element there (a1 x a2 unnormalised), then
// normalised: on a smooth surface it converges to the surface's normal at
// second order in the face size.
//
// The search puts each face's bounding box (its nodes', grown by a margin)
// in deal.II's R-tree (pack_rtree); the faces near a point are those whose
// box holds the point's box of the search radius.
#ifndef ring_contact_contact_face_projection_h
#define ring_contact_contact_face_projection_h

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/numerics/rtree.h>

#include <ring_contact/contact/face_kernel.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <utility>
#include <vector>

namespace RingContact
{
  namespace FaceKernel
  {
    /// The values, gradients and second derivatives of a face basis at xi.
    struct ShapeDerivatives
    {
      std::vector<double>       N;
      std::vector<Tensor<1, 2>> dN;
      std::vector<Tensor<2, 2>> d2N;

      ShapeDerivatives(const FaceBasis &basis, const Point<2> &xi)
      {
        basis.evaluate(xi, N, dN, &d2N);
      }
    };

    /// The closest point of a face to p: its parameters, whether Newton's
    /// method converged, whether xi lies on the face ([0, 1]^2 to 1e-12),
    /// and the distance |x(xi) - p|.
    struct ClosestPoint
    {
      Point<2> xi;
      bool     converged = false;
      bool     inside    = false;
      double   distance  = 0;
    };

    /// r_a = (x - p) . a_a and the Hessian H_ab = a_a . a_b + (x - p) .
    /// x_,ab at the shape functions' point, in the number type; and, if
    /// asked, the face point there.
    template <typename Number>
    Vector2<Number>
    distance_gradient(const std::vector<Vector3<Number>> &nodes,
                      const Vector3<Number>              &p,
                      const ShapeDerivatives             &s,
                      Tensor<2, 2>                       *hessian = nullptr,
                      FacePoint<Number>                  *point   = nullptr)
    {
      const FacePoint<Number> q = evaluate(nodes, s.N, s.dN);
      if (point != nullptr)
        *point = q;
      Vector3<Number> d;
      for (unsigned int i = 0; i < 3; ++i)
        d[i] = q.x[i] - p[i];
      if (hessian != nullptr)
        {
          const Vector3<Number> *a[2] = {&q.a1, &q.a2};
          // H is symmetric: its upper triangle, mirrored.
          for (unsigned int i = 0; i < 2; ++i)
            for (unsigned int j = i; j < 2; ++j)
              {
                double curvature = 0; // (x - p) . x_,ij
                for (unsigned int k = 0; k < nodes.size(); ++k)
                  for (unsigned int c = 0; c < 3; ++c)
                    curvature += FaceClipping::value(d[c]) * s.d2N[k][i][j] *
                                 FaceClipping::value(nodes[k][c]);
                (*hessian)[i][j] = (*hessian)[j][i] =
                  FaceClipping::value(FaceClipping::dot(*a[i], *a[j])) +
                  curvature;
              }
        }
      return {{FaceClipping::dot(d, q.a1), FaceClipping::dot(d, q.a2)}};
    }

    /// The closest point of a face (nodes in double) to p, to `tolerance`
    /// in xi.
    inline ClosestPoint
    closest_point(const FaceBasis                    &basis,
                  const std::vector<Vector3<double>> &global_nodes,
                  const Vector3<double>              &global_p,
                  const double                        tolerance = 1e-14)
    {
      if (global_nodes.size() != basis.size())
        throw std::invalid_argument(
          "closest_point(): a face's nodes do not match its basis");
      // The nodes about the point: the iteration's round-off is then that
      // of the face's size, not of its distance from the origin (a face far
      // out would never meet the tolerance).
      std::vector<Vector3<double>> nodes = global_nodes;
      for (auto &node : nodes)
        for (unsigned int d = 0; d < 3; ++d)
          node[d] -= global_p[d];
      const Vector3<double> p = {{0, 0, 0}};
      ClosestPoint          result;
      result.xi = Point<2>(0.5, 0.5);
      for (unsigned int step = 0; step < 30 && !result.converged; ++step)
        {
          const ShapeDerivatives s(basis, result.xi);
          Tensor<2, 2>           H;
          FacePoint<double>      q;
          const Vector2<double>  r = distance_gradient(nodes, p, s, &H, &q);
          // Where H is not positive definite (a point beyond the centre of
          // curvature, a start far off), Gauss-Newton's a_a . a_b.
          if (!(H[0][0] > 0 && determinant(H) > 1e-14 * H.norm_square()))
            {
              H[0][0] = FaceClipping::dot(q.a1, q.a1);
              H[0][1] = H[1][0] = FaceClipping::dot(q.a1, q.a2);
              H[1][1]           = FaceClipping::dot(q.a2, q.a2);
              if (!(determinant(H) > 1e-14 * H.norm_square()))
                return result; // a degenerate face
            }
          const Tensor<2, 2> Hinv = invert(H);
          Point<2>           delta(Hinv[0][0] * r[0] + Hinv[0][1] * r[1],
                         Hinv[1][0] * r[0] + Hinv[1][1] * r[1]);
          const Point<2>     previous = result.xi;
          bool               clamped  = false;
          for (unsigned int a = 0; a < 2; ++a)
            {
              result.xi[a] = std::clamp(result.xi[a] - delta[a], -0.5, 1.5);
              clamped      = clamped || result.xi[a] != previous[a] - delta[a];
            }
          // A step held at the bound of the search is no convergence: the
          // closest point lies beyond half a face (a neighbour's).
          result.converged =
            !clamped && result.xi.distance(previous) <= tolerance;
          if (clamped && result.xi.distance(previous) == 0)
            break;
        }
      result.inside = result.xi[0] >= -1e-12 && result.xi[0] <= 1 + 1e-12 &&
                      result.xi[1] >= -1e-12 && result.xi[1] <= 1 + 1e-12;
      const ShapeDerivatives  s(basis, result.xi);
      const FacePoint<double> q  = evaluate(nodes, s.N, s.dN);
      double                  d2 = 0;
      for (unsigned int i = 0; i < 3; ++i)
        d2 += (q.x[i] - p[i]) * (q.x[i] - p[i]);
      result.distance = std::sqrt(d2);
      return result;
    }

    /// The xi of closest_point() in the numbers of the nodes and the point:
    /// xi0 - H^-1 r(xi0) with the exact Hessian at xi0.
    template <typename Number>
    Vector2<Number>
    linearised_closest_xi(const FaceBasis                    &basis,
                          const std::vector<Vector3<Number>> &nodes,
                          const Vector3<Number>              &p,
                          const Point<2>                     &xi0)
    {
      const ShapeDerivatives s(basis, xi0);
      Tensor<2, 2>           H;
      const Vector2<Number>  r    = distance_gradient(nodes, p, s, &H);
      const Tensor<2, 2>     Hinv = invert(H);
      return {{xi0[0] - (Hinv[0][0] * r[0] + Hinv[0][1] * r[1]),
               xi0[1] - (Hinv[1][0] * r[0] + Hinv[1][1] * r[1])}};
    }

    /// A face of a surface: the global numbers of its nodes (in the
    /// basis' lexicographic order) and their positions; its normal a1 x
    /// a2 points out of its body.
    struct SurfaceFace
    {
      std::vector<unsigned int>    node_ids;
      std::vector<Vector3<double>> nodes;
    };

    /// The smoothed normal at every node of a surface: the faces' a1 x a2
    /// at the node (the normal weighted by the area element) summed over
    /// the faces that hold it, then normalised.
    inline std::map<unsigned int, Tensor<1, 3>>
    averaged_normals(const FaceBasis                &basis,
                     const std::vector<SurfaceFace> &faces)
    {
      std::map<unsigned int, Tensor<1, 3>> normals;
      std::vector<double>                  N;
      std::vector<Tensor<1, 2>>            dN;
      for (const SurfaceFace &face : faces)
        {
          if (face.nodes.size() != basis.size() ||
              face.node_ids.size() != basis.size())
            throw std::invalid_argument(
              "averaged_normals(): a face's nodes do not match the basis");
        }
      for (const SurfaceFace &face : faces)
        for (unsigned int k = 0; k < basis.size(); ++k)
          {
            basis.evaluate(basis.nodes[k], N, dN);
            const FacePoint<double> q = evaluate(face.nodes, N, dN);
            const Vector3<double>   n = FaceClipping::cross(q.a1, q.a2);
            for (unsigned int i = 0; i < 3; ++i)
              normals[face.node_ids[k]][i] += n[i];
          }
      for (auto &[node, n] : normals)
        n /= n.norm();
      return normals;
    }

    /// The faces of a surface in an R-tree of their bounding boxes.
    class FaceSearch
    {
    public:
      /// Each face's box is its nodes' grown by `margin` on every side (a
      /// curved face bulges beyond its nodes by a fraction of its size).
      FaceSearch(const std::vector<SurfaceFace> &faces, const double margin)
      {
        std::vector<std::pair<BoundingBox<3>, unsigned int>> boxes;
        for (unsigned int f = 0; f < faces.size(); ++f)
          {
            std::vector<Point<3>> points;
            for (const Vector3<double> &x : faces[f].nodes)
              points.emplace_back(x[0], x[1], x[2]);
            BoundingBox<3> box(points);
            box.extend(margin);
            boxes.emplace_back(box, f);
          }
        tree = pack_rtree(boxes);
      }

      /// The faces whose box meets the cube of half-width `radius` about p.
      std::vector<unsigned int>
      near(const Point<3> &p, const double radius) const
      {
        BoundingBox<3> box(std::make_pair(p, p));
        box.extend(radius);
        std::vector<std::pair<BoundingBox<3>, unsigned int>> found;
        tree.query(boost::geometry::index::intersects(box),
                   std::back_inserter(found));
        std::vector<unsigned int> faces;
        for (const auto &entry : found)
          faces.push_back(entry.second);
        std::sort(faces.begin(), faces.end());
        return faces;
      }

    private:
      RTree<std::pair<BoundingBox<3>, unsigned int>> tree;
    };
  } // namespace FaceKernel
} // namespace RingContact

#endif
