// The closest point on a 3D face, its linearisation, smoothed normals and
// the face search (contact/face_projection.h), against closed forms:
// - a parallelogram face: the closest point is the orthogonal projection,
//   xi from the 2 x 2 normal equations, for points above, below and beside
//   the face (xi outside [0, 1]^2 flagged), and one 1.5 faces beyond it
//   left unconverged at the search's bound;
// - a curved biquadratic face, the paraboloid z = (x^2 + y^2) / 2 which it
//   holds exactly, turned and moved into space: a point at a distance g
//   along the normal at a known foot x0 (g from -0.3 to 0.3, within the
//   radius of curvature 1) has its closest point at x0 and its distance
//   |g|;
// - the AD derivatives of xi (27 node coordinates and the point, through
//   linearised_closest_xi()) against central differences on a warped face;
// - the averaged normals of a sphere of bilinear faces (a cube's faces
//   projected onto the unit sphere, n x n per side) against the radial
//   direction, at n = 4, 8, 16, 32, with the order of convergence;
// - the search: for points near that sphere, every face within the search
//   radius (its closest point or a node) is among the R-tree's candidates.
#include <ring_contact/contact/face_projection.h>

#include "tests.h"

#include <Sacado.hpp>

#include <array>
#include <cmath>
#include <iomanip>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

using namespace RingContact;
using namespace RingContact::FaceKernel;
using RingContactTests::check;

namespace
{
  using AD = Sacado::Fad::DFad<double>;

  Vector3<double>
  v3(const double x, const double y, const double z)
  {
    return {{x, y, z}};
  }

  // A rotation (Rodrigues) about the unit axis of (1, 2, 2) / 3 and a
  // shift, to move the faces into general position.
  Vector3<double>
  placed(const Vector3<double> &x)
  {
    const Vector3<double> k     = v3(1. / 3, 2. / 3, 2. / 3);
    const double          angle = 0.7, c = std::cos(angle), s = std::sin(angle);
    const Vector3<double> kx    = FaceClipping::cross(k, x);
    const double          kdotx = FaceClipping::dot(k, x);
    Vector3<double>       y;
    for (unsigned int i = 0; i < 3; ++i)
      y[i] = x[i] * c + kx[i] * s + k[i] * kdotx * (1 - c) + 0.3 * (i + 1);
    return y;
  }

  // The paraboloid z = (x^2 + y^2) / 2 over [-0.5, 0.5]^2, x = xi1 - 0.5,
  // y = xi2 - 0.5: its point and unit normal.
  Vector3<double>
  paraboloid(const double x, const double y)
  {
    return v3(x, y, 0.5 * (x * x + y * y));
  }

  Vector3<double>
  paraboloid_normal(const double x, const double y)
  {
    return FaceClipping::unit(v3(-x, -y, 1));
  }

  // The max over the components of |a - b|.
  double
  difference(const Vector3<double> &a, const Vector3<double> &b)
  {
    return std::max(
      {std::abs(a[0] - b[0]), std::abs(a[1] - b[1]), std::abs(a[2] - b[2])});
  }

  // The surface of the unit sphere as a cube's faces projected onto it,
  // n x n bilinear faces per side, a1 x a2 outward, nodes numbered once.
  std::vector<SurfaceFace>
  sphere(const unsigned int n)
  {
    std::map<std::array<long, 3>, unsigned int> ids;
    const auto id = [&](const Vector3<double> &x) {
      const std::array<long, 3> key = {{std::lround(x[0] * 1e9),
                                        std::lround(x[1] * 1e9),
                                        std::lround(x[2] * 1e9)}};
      return ids.emplace(key, ids.size()).first->second;
    };
    std::vector<SurfaceFace> faces;
    for (unsigned int axis = 0; axis < 3; ++axis)
      for (const double side : {-1.0, 1.0})
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = 0; j < n; ++j)
            {
              SurfaceFace face;
              for (unsigned int b = 0; b < 2; ++b)
                for (unsigned int a = 0; a < 2; ++a)
                  {
                    Vector3<double> x;
                    x[axis]           = side;
                    x[(axis + 1) % 3] = -1 + 2. * (i + a) / n;
                    x[(axis + 2) % 3] = -1 + 2. * (j + b) / n;
                    x                 = FaceClipping::unit(x);
                    face.nodes.push_back(x);
                    face.node_ids.push_back(id(x));
                  }
              // Outward: a1 x a2 along the face's centre.
              const Vector3<double> n1 =
                FaceClipping::cross(v3(face.nodes[1][0] - face.nodes[0][0],
                                       face.nodes[1][1] - face.nodes[0][1],
                                       face.nodes[1][2] - face.nodes[0][2]),
                                    v3(face.nodes[2][0] - face.nodes[0][0],
                                       face.nodes[2][1] - face.nodes[0][1],
                                       face.nodes[2][2] - face.nodes[0][2]));
              if (FaceClipping::dot(n1, face.nodes[0]) < 0)
                {
                  std::swap(face.nodes[1], face.nodes[2]);
                  std::swap(face.node_ids[1], face.node_ids[2]);
                }
              faces.push_back(face);
            }
    return faces;
  }
} // namespace

int
main()
{
  auto &out = RingContactTests::deallog_file;
  out << std::scientific << std::setprecision(2);

  // A parallelogram: O + xi1 u + xi2 v.
  {
    const FaceBasis       basis(1);
    const Vector3<double> O = placed(v3(0, 0, 0)), U = placed(v3(1.5, 0, 0)),
                          V = placed(v3(0.4, 0.8, 0.1));
    Vector3<double> u, v;
    for (unsigned int i = 0; i < 3; ++i)
      {
        u[i] = U[i] - O[i];
        v[i] = V[i] - O[i];
      }
    std::vector<Vector3<double>> nodes;
    for (unsigned int j = 0; j < 2; ++j)
      for (unsigned int i = 0; i < 2; ++i)
        nodes.push_back(v3(O[0] + i * u[0] + j * v[0],
                           O[1] + i * u[1] + j * v[1],
                           O[2] + i * u[2] + j * v[2]));
    const Vector3<double> normal =
      FaceClipping::unit(FaceClipping::cross(u, v));
    double       worst  = 0;
    unsigned int inside = 0, outside = 0;
    for (const double a : {-0.3, 0.2, 0.7, 1.2})
      for (const double b : {-0.2, 0.5, 1.1})
        for (const double h : {-0.4, 0.0, 0.3})
          {
            Vector3<double> p;
            for (unsigned int i = 0; i < 3; ++i)
              p[i] = O[i] + a * u[i] + b * v[i] + h * normal[i];
            const ClosestPoint q = closest_point(basis, nodes, p);
            // The normal equations in closed form.
            const double uu = FaceClipping::dot(u, u),
                         uv = FaceClipping::dot(u, v),
                         vv = FaceClipping::dot(v, v);
            Vector3<double> d;
            for (unsigned int i = 0; i < 3; ++i)
              d[i] = p[i] - O[i];
            const double du = FaceClipping::dot(d, u),
                         dv = FaceClipping::dot(d, v), det = uu * vv - uv * uv;
            const double xi1 = (vv * du - uv * dv) / det,
                         xi2 = (uu * dv - uv * du) / det;
            worst            = std::max({worst,
                                         std::abs(q.xi[0] - xi1),
                                         std::abs(q.xi[1] - xi2),
                                         std::abs(q.distance - std::abs(h))});
            const bool expected_inside =
              xi1 >= 0 && xi1 <= 1 && xi2 >= 0 && xi2 <= 1;
            check(q.converged && q.inside == expected_inside,
                  "the parallelogram's projection converges and says inside");
            (q.inside ? inside : outside) += 1;
          }
    out << "parallelogram, " << inside << " points over it and " << outside
        << " beside: xi and distance against the normal equations "
        << (worst < 1e-14 ? "< 1e-14" : "FAILS") << std::endl;
    std::cout << "parallelogram " << worst << std::endl;
    check(worst < 1e-14, "the parallelogram's closest points");
    // Beyond half a face the search stops at its bound, unconverged (the
    // point is a neighbour's); a face whose nodes do not fit the basis is
    // refused.
    Vector3<double> beyond;
    for (unsigned int i = 0; i < 3; ++i)
      beyond[i] = O[i] + 2.5 * u[i] + 0.5 * v[i] + 0.1 * normal[i];
    const ClosestPoint far     = closest_point(basis, nodes, beyond);
    bool               refused = false;
    try
      {
        closest_point(FaceBasis(2), nodes, beyond);
      }
    catch (const std::invalid_argument &)
      {
        refused = true;
      }
    out << "a point 1.5 faces beyond the face: not converged "
        << (!far.converged ? "yes" : "NO")
        << "; nodes that do not fit the basis refused "
        << (refused ? "yes" : "NO") << std::endl;
    check(!far.converged && refused, "the projection's bounds");
  }

  // The paraboloid, biquadratic and exact, turned and moved.
  const FaceBasis              quadratic(2);
  std::vector<Vector3<double>> paraboloid_nodes;
  for (const Point<2> &xi : quadratic.nodes)
    paraboloid_nodes.push_back(placed(paraboloid(xi[0] - 0.5, xi[1] - 0.5)));
  {
    double       worst_xi = 0, worst_distance = 0;
    unsigned int n = 0;
    for (const double x : {-0.4, -0.1, 0.0, 0.25, 0.45})
      for (const double y : {-0.35, 0.0, 0.3})
        for (const double g : {-0.3, -0.01, 0.0, 0.05, 0.3})
          {
            const Vector3<double> foot = paraboloid(x, y),
                                  nrm  = paraboloid_normal(x, y);
            Vector3<double> p;
            for (unsigned int i = 0; i < 3; ++i)
              p[i] = foot[i] + g * nrm[i];
            p = placed(p);
            const ClosestPoint q =
              closest_point(quadratic, paraboloid_nodes, p);
            check(q.converged && q.inside, "the paraboloid's projection");
            worst_xi = std::max({worst_xi,
                                 std::abs(q.xi[0] - (x + 0.5)),
                                 std::abs(q.xi[1] - (y + 0.5))});
            worst_distance =
              std::max(worst_distance, std::abs(q.distance - std::abs(g)));
            ++n;
          }
    out << "paraboloid (biquadratic, exact), " << n
        << " points at -0.3 to 0.3 along the normal: xi "
        << (worst_xi < 1e-13 ? "< 1e-13" : "FAILS") << ", distance "
        << (worst_distance < 1e-13 ? "< 1e-13" : "FAILS") << std::endl;
    std::cout << "paraboloid " << worst_xi << " " << worst_distance
              << std::endl;
    check(worst_xi < 1e-13 && worst_distance < 1e-13,
          "the paraboloid's closest points");
  }

  // The AD derivatives of xi on a warped face against central differences.
  {
    std::vector<Vector3<double>> nodes = paraboloid_nodes;
    for (unsigned int k = 0; k < nodes.size(); ++k)
      for (unsigned int i = 0; i < 3; ++i)
        nodes[k][i] += 0.03 * std::sin(1.0 + 3 * k + i);
    Vector3<double>    p           = placed(v3(0.13, -0.21, 0.25));
    const unsigned int n_variables = 3 * nodes.size() + 3;
    const auto         xi_of       = [&](const std::vector<double> &z) {
      std::vector<Vector3<double>> x(nodes.size());
      Vector3<double>              q;
      for (unsigned int k = 0; k < nodes.size(); ++k)
        for (unsigned int i = 0; i < 3; ++i)
          x[k][i] = z[3 * k + i];
      for (unsigned int i = 0; i < 3; ++i)
        q[i] = z[3 * nodes.size() + i];
      return closest_point(quadratic, x, q).xi;
    };
    std::vector<double> z(n_variables);
    for (unsigned int k = 0; k < nodes.size(); ++k)
      for (unsigned int i = 0; i < 3; ++i)
        z[3 * k + i] = nodes[k][i];
    for (unsigned int i = 0; i < 3; ++i)
      z[3 * nodes.size() + i] = p[i];
    const Point<2>           xi0 = xi_of(z);
    std::vector<Vector3<AD>> x_ad(nodes.size());
    Vector3<AD>              p_ad;
    for (unsigned int k = 0; k < nodes.size(); ++k)
      for (unsigned int i = 0; i < 3; ++i)
        x_ad[k][i] = AD(n_variables, 3 * k + i, nodes[k][i]);
    for (unsigned int i = 0; i < 3; ++i)
      p_ad[i] = AD(n_variables, 3 * nodes.size() + i, p[i]);
    const Vector2<AD> xi    = linearised_closest_xi(quadratic, x_ad, p_ad, xi0);
    double            worst = 0, size = 0, value = 0;
    for (unsigned int a = 0; a < 2; ++a)
      {
        value = std::max(value, std::abs(xi[a].val() - xi0[a]));
        for (unsigned int j = 0; j < n_variables; ++j)
          {
            const double        h  = 1e-6;
            std::vector<double> zp = z, zm = z;
            zp[j] += h;
            zm[j] -= h;
            const double fd = (xi_of(zp)[a] - xi_of(zm)[a]) / (2 * h);
            worst           = std::max(worst, std::abs(fd - xi[a].dx(j)));
            size            = std::max(size, std::abs(fd));
          }
      }
    out << "a warped biquadratic face: the AD derivatives of xi ("
        << n_variables << " variables) against central differences "
        << (worst < 1e-7 * size ? "< 1e-7" : "FAILS")
        << " of the largest, its value xi0 "
        << (value < 1e-14 ? "to 1e-14" : "NOT") << std::endl;
    std::cout << "AD " << worst / size << std::endl;
    check(worst < 1e-7 * size && value < 1e-14, "the AD derivatives of xi");
  }

  // The averaged normals of the sphere against its radial direction.
  {
    const FaceBasis bilinear(1);
    double          previous = 0;
    for (const unsigned int n : {4u, 8u, 16u, 32u})
      {
        const std::vector<SurfaceFace>          faces = sphere(n);
        std::map<unsigned int, Vector3<double>> position;
        for (const SurfaceFace &face : faces)
          for (unsigned int k = 0; k < 4; ++k)
            position[face.node_ids[k]] = face.nodes[k];
        double worst = 0;
        for (const auto &[node, normal] : averaged_normals(bilinear, faces))
          {
            const Vector3<double> x = position.at(node);
            worst =
              std::max(worst,
                       difference(v3(normal[0], normal[1], normal[2]), x));
          }
        out << "sphere of 6 x " << n << " x " << n
            << " bilinear faces: the averaged normals off the radial "
               "direction by "
            << std::setprecision(2) << worst;
        if (previous > 0)
          out << ", order " << std::fixed << std::setprecision(1)
              << std::log2(previous / worst) << std::scientific;
        out << std::endl;
        if (previous > 0)
          check(std::log2(previous / worst) > 1.8,
                "the averaged normals converge at second order");
        previous = worst;
      }
  }

  // The search: every face within the radius among the candidates.
  {
    const FaceBasis                bilinear(1);
    const std::vector<SurfaceFace> faces = sphere(16);
    const FaceSearch               search(faces, 0.0);
    unsigned int                   n = 0, candidates = 0, most = 0;
    for (unsigned int i = 0; i < 200; ++i)
      {
        // Points spread over the sphere at radii 0.95 to 1.05.
        const double    t = 0.1 + i * 0.618034, s = -1 + (2.0 * i + 1) / 200;
        const double    r = 1 + 0.05 * std::sin(7.0 * i);
        const double    c = std::sqrt(1 - s * s);
        Vector3<double> p = v3(r * c * std::cos(2 * M_PI * t),
                               r * c * std::sin(2 * M_PI * t),
                               r * s);
        // Every face within the search radius of p (its closest point over
        // it, or one of its nodes) is among the candidates.
        const std::vector<unsigned int> near =
          search.near(Point<3>(p[0], p[1], p[2]), 0.1);
        unsigned int within = 0;
        for (unsigned int f = 0; f < faces.size(); ++f)
          {
            const ClosestPoint q = closest_point(bilinear, faces[f].nodes, p);
            bool               close = q.inside && q.distance < 0.1;
            for (const Vector3<double> &x : faces[f].nodes)
              close = close || difference(x, p) < 0.1 / std::sqrt(3.);
            if (close)
              {
                ++within;
                check(std::binary_search(near.begin(), near.end(), f),
                      "the search holds every face within its radius");
              }
          }
        check(within > 0, "a face within the radius of every point");
        candidates += near.size();
        most = std::max<unsigned int>(most, near.size());
        ++n;
      }
    out << "search on the sphere of " << faces.size() << " faces, " << n
        << " points at radii 0.95 to 1.05: every face within 0.1 among the "
           "R-tree's candidates ("
        << candidates / n << " candidates on average, at most " << most << ")"
        << std::endl;
  }
}
