// The geometry of the faces of a 3D contact surface
// (contact/face_kernel.h), and the mortar integrals of segment-based
// integration in 3D built on it and on the clip of faces
// (contact/face_clipping.h):
// - the face basis (deal.II's tensor-product Lagrange polynomials) sums to
//   one, its gradients to zero, and it is one at its own node, zero at the
//   others, for degrees 1 to 3;
// - on an affine face (a parallelogram in space) the tangents and the
//   normal are the exact ones;
// - the point of a curved (biquadratic) face that projects onto a given
//   point of a tilted auxiliary plane is found to 1e-12, and its
//   derivatives in AD numbers (with respect to the face's 27 coordinates,
//   the slave face's 12 that make the plane, and the point's 2) equal
//   central differences;
// - the contact patch test in 3D: a slave surface of 3 x 3 faces against a
//   master surface of 8 x 9 faces turned through 0.2 against it (no master
//   edge along a slave edge) and lifted by a gap. The mortar matrices
//   D_ik = int N_i N_k and M_ij = int N_i Phi_j, integrated on the clip
//   triangles, cover the slave area (sum D = 1), transfer every linear
//   field (sum_j M_ij f(X_j) = sum_k D_ik f(X_k)), and give each master
//   node whose faces lie inside the slave surface the force of a uniform
//   pressure on its area, sum_i M_ij = sum of its faces' areas / 4, all to
//   round-off. Integrated instead with n x n Gauss points on each slave
//   face (no clipping), the last fails for every n tried (2, 4, 8): the
//   master basis has kinks inside the slave faces, where master edges
//   cross them. (The linear fields are transferred by either: on affine
//   faces both sides of that identity are one integrand at the same
//   points.)
#include <deal.II/base/quadrature_lib.h>

#include <ring_contact/contact/face_kernel.h>

#include "tests.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <string>
#include <vector>

using namespace RingContact;
using namespace RingContact::FaceKernel;
using RingContactTests::check;

namespace
{
  using AD   = Sacado::Fad::DFad<double>;
  using Face = std::vector<Vector3<double>>;

  // A grid of n1 x n2 bilinear faces on the square [x0, x0 + L]^2 turned
  // through `angle` about its centre, at height z; each face's nodes in
  // the basis' order (lexicographic), or that order mirrored in xi_1 for a
  // master surface (whose normal points down).
  std::vector<Face>
  grid(const unsigned int n1,
       const unsigned int n2,
       const double       x0,
       const double       L,
       const double       angle,
       const double       z,
       const bool         master)
  {
    const double c     = x0 + L / 2;
    const auto   place = [&](const double u, const double v) {
      const double x = x0 + L * u - c, y = x0 + L * v - c;
      return Vector3<double>{{c + std::cos(angle) * x - std::sin(angle) * y,
                              c + std::sin(angle) * x + std::cos(angle) * y,
                              z}};
    };
    std::vector<Face> faces;
    for (unsigned int j = 0; j < n2; ++j)
      for (unsigned int i = 0; i < n1; ++i)
        {
          const double u0 = double(i) / n1, u1 = double(i + 1) / n1;
          const double v0 = double(j) / n2, v1 = double(j + 1) / n2;
          if (master)
            faces.push_back(
              {place(u1, v0), place(u0, v0), place(u1, v1), place(u0, v1)});
          else
            faces.push_back(
              {place(u0, v0), place(u1, v0), place(u0, v1), place(u1, v1)});
        }
    return faces;
  }

  // The face's corners in order around it (the clip takes polygons).
  template <typename Number>
  std::vector<Vector3<Number>>
  corners(const std::vector<Vector3<Number>> &face)
  {
    return {face[0], face[1], face[3], face[2]};
  }

  // A surface's nodes, each once, and each face's node numbers.
  struct Surface
  {
    std::vector<Vector3<double>>           nodes;
    std::vector<std::vector<unsigned int>> faces;
  };

  Surface
  numbered(const std::vector<Face> &faces)
  {
    Surface s;
    for (const auto &face : faces)
      {
        std::vector<unsigned int> numbers;
        for (const auto &x : face)
          {
            unsigned int k = 0;
            while (k < s.nodes.size() &&
                   std::hypot(s.nodes[k][0] - x[0], s.nodes[k][1] - x[1]) >
                     1e-12)
              ++k;
            if (k == s.nodes.size())
              s.nodes.push_back(x);
            numbers.push_back(k);
          }
        s.faces.push_back(numbers);
      }
    return s;
  }

  // The largest error of the transfer of f(x, y) = a + b x + c y by the
  // mortar matrices: |sum_j M_ij f(X_j) - sum_k D_ik f(X_k)| over the slave
  // nodes, for the three basis fields.
  double
  transfer_error(const std::vector<std::vector<double>> &D,
                 const std::vector<std::vector<double>> &M,
                 const Surface                          &slave,
                 const Surface                          &master)
  {
    double worst = 0;
    for (unsigned int field = 0; field < 3; ++field)
      {
        const auto f = [field](const Vector3<double> &x) {
          return field == 0 ? 1.0 : x[field - 1];
        };
        for (unsigned int i = 0; i < slave.nodes.size(); ++i)
          {
            double lhs = 0, rhs = 0;
            for (unsigned int j = 0; j < master.nodes.size(); ++j)
              lhs += M[i][j] * f(master.nodes[j]);
            for (unsigned int k = 0; k < slave.nodes.size(); ++k)
              rhs += D[i][k] * f(slave.nodes[k]);
            worst = std::max(worst, std::abs(lhs - rhs));
          }
      }
    return worst;
  }

  // The force a uniform pressure transmits to each master node whose faces
  // all lie inside the slave surface (the unit square), sum_i M_ij, against
  // its exact value, a quarter of the area of each of its (affine) faces.
  // Returns the largest error relative to that value and counts the nodes.
  double
  master_area_error(const std::vector<std::vector<double>> &M,
                    const Surface                          &master,
                    unsigned int                           &n_inside)
  {
    double worst = 0;
    n_inside     = 0;
    for (unsigned int j = 0; j < master.nodes.size(); ++j)
      {
        bool   inside = true;
        double exact  = 0;
        for (const auto &face : master.faces)
          if (std::count(face.begin(), face.end(), j) > 0)
            {
              for (const unsigned int k : face)
                inside = inside && master.nodes[k][0] >= 0 &&
                         master.nodes[k][0] <= 1 && master.nodes[k][1] >= 0 &&
                         master.nodes[k][1] <= 1;
              const auto &a = master.nodes[face[0]], &b = master.nodes[face[1]],
                         &c = master.nodes[face[2]];
              exact += std::abs((b[0] - a[0]) * (c[1] - a[1]) -
                                (b[1] - a[1]) * (c[0] - a[0])) /
                       4;
            }
        if (!inside)
          continue;
        ++n_inside;
        double sum = 0;
        for (const auto &row : M)
          sum += row[j];
        worst = std::max(worst, std::abs(sum - exact) / exact);
      }
    return worst;
  }

  // One point of the slave surface, at xi_s of slave face fs, with weight
  // w (the area it stands for): found on the master faces by projection
  // along the slave's normal, its products added to D and M.
  void
  add_point(const FaceBasis                  &basis,
            const Surface                    &slave,
            const Surface                    &master,
            const unsigned int                fs,
            const Point<2>                   &xi_s,
            const double                      w,
            std::vector<std::vector<double>> &D,
            std::vector<std::vector<double>> &M,
            const int                         master_face = -1,
            const Point<2>                   &xi_m_given  = Point<2>())
  {
    std::vector<double>       N, Phi;
    std::vector<Tensor<1, 2>> dN, dPhi;
    basis.evaluate(xi_s, N, dN);
    const auto &s = slave.faces[fs];
    for (unsigned int a = 0; a < 4; ++a)
      for (unsigned int b = 0; b < 4; ++b)
        D[s[a]][s[b]] += w * N[a] * N[b];
    int      fm   = master_face;
    Point<2> xi_m = xi_m_given;
    if (fm < 0)
      {
        // Element-based: the master face whose preimage lies in it.
        Face nodes;
        for (const unsigned int k : s)
          nodes.push_back(slave.nodes[k]);
        const auto plane = FaceClipping::auxiliary_plane(corners(nodes));
        const auto x     = evaluate(nodes, N, dN).x;
        const auto p     = FaceClipping::to_plane(plane, x);
        for (unsigned int f = 0; f < master.faces.size() && fm < 0; ++f)
          {
            Face m;
            for (const unsigned int k : master.faces[f])
              m.push_back(master.nodes[k]);
            const Preimage found = find_on_face(basis, m, plane, p);
            if (found.converged && found.xi[0] >= -1e-12 &&
                found.xi[0] <= 1 + 1e-12 && found.xi[1] >= -1e-12 &&
                found.xi[1] <= 1 + 1e-12)
              {
                fm   = f;
                xi_m = found.xi;
              }
          }
        if (fm < 0)
          return;
      }
    basis.evaluate(xi_m, Phi, dPhi);
    for (unsigned int a = 0; a < 4; ++a)
      for (unsigned int b = 0; b < 4; ++b)
        M[s[a]][master.faces[fm][b]] += w * N[a] * Phi[b];
  }

  // The mortar matrices integrated on the clip triangles of every pair of
  // faces, with deal.II's Gauss rule of `n` points per triangle.
  void
  mortar_by_clipping(const FaceBasis                  &basis,
                     const Surface                    &slave,
                     const Surface                    &master,
                     std::vector<std::vector<double>> &D,
                     std::vector<std::vector<double>> &M,
                     double                           &clipped_area)
  {
    const QGaussSimplex<2> rule(3);
    clipped_area = 0;
    for (unsigned int fs = 0; fs < slave.faces.size(); ++fs)
      for (unsigned int fm = 0; fm < master.faces.size(); ++fm)
        {
          Face s, m;
          for (const unsigned int k : slave.faces[fs])
            s.push_back(slave.nodes[k]);
          for (const unsigned int k : master.faces[fm])
            m.push_back(master.nodes[k]);
          const auto cell = FaceClipping::clip_faces(corners(s), corners(m));
          for (const auto &t : cell.triangles)
            for (unsigned int q = 0; q < rule.size(); ++q)
              {
                const auto           &v = t.vertices;
                const Point<2>       &l = rule.point(q);
                const Vector2<double> p = {
                  {v[0][0] + l[0] * (v[1][0] - v[0][0]) +
                     l[1] * (v[2][0] - v[0][0]),
                   v[0][1] + l[0] * (v[1][1] - v[0][1]) +
                     l[1] * (v[2][1] - v[0][1])}};
                const Preimage on_s = find_on_face(basis, s, cell.plane, p);
                const Preimage on_m = find_on_face(basis, m, cell.plane, p);
                check(on_s.converged && on_m.converged,
                      "every clip point found on both faces");
                // The slave face lies in its plane: the area is the plane's.
                const double w = rule.weight(q) * 2 * t.area;
                clipped_area += w;
                add_point(
                  basis, slave, master, fs, on_s.xi, w, D, M, fm, on_m.xi);
              }
        }
  }
} // namespace

int
main()
{
  auto &out = RingContactTests::deallog_file;
  out << std::setprecision(6) << std::scientific;

  // The basis.
  for (unsigned int degree = 1; degree <= 3; ++degree)
    {
      const FaceBasis           basis(degree);
      std::vector<double>       N;
      std::vector<Tensor<1, 2>> dN;
      double                    worst = 0;
      for (const Point<2> &xi :
           {Point<2>(0.1, 0.7), Point<2>(0.5, 0.5), Point<2>(0.93, 0.02)})
        {
          basis.evaluate(xi, N, dN);
          double       sum = 0;
          Tensor<1, 2> gradient_sum;
          for (unsigned int k = 0; k < basis.size(); ++k)
            {
              sum += N[k];
              gradient_sum += dN[k];
            }
          worst = std::max({worst, std::abs(sum - 1), gradient_sum.norm()});
        }
      for (unsigned int k = 0; k < basis.size(); ++k)
        {
          basis.evaluate(basis.nodes[k], N, dN);
          for (unsigned int j = 0; j < basis.size(); ++j)
            worst = std::max(worst, std::abs(N[j] - (j == k ? 1. : 0.)));
        }
      check(worst < 1e-13, "the face basis is a Lagrange basis");
      out << "degree " << degree << ": " << basis.size()
          << " functions, a partition of unity, one at their own node"
          << std::endl;
    }

  // An affine face: the exact tangents and normal.
  {
    const Vector3<double> o = {{0.2, -0.1, 0.4}}, u = {{1, 0.5, 0.2}},
                          v = {{-0.3, 0.8, 0.6}};
    Face face;
    for (const auto &[s, t] :
         std::vector<std::pair<double, double>>{{0, 0}, {1, 0}, {0, 1}, {1, 1}})
      face.push_back({{o[0] + s * u[0] + t * v[0],
                       o[1] + s * u[1] + t * v[1],
                       o[2] + s * u[2] + t * v[2]}});
    const FaceBasis           basis(1);
    std::vector<double>       N;
    std::vector<Tensor<1, 2>> dN;
    basis.evaluate(Point<2>(0.3, 0.6), N, dN);
    const FacePoint<double> p     = evaluate(face, N, dN);
    double                  worst = 0;
    for (unsigned int d = 0; d < 3; ++d)
      worst = std::max({worst,
                        std::abs(p.a1[d] - u[d]),
                        std::abs(p.a2[d] - v[d]),
                        std::abs(p.x[d] - (o[d] + 0.3 * u[d] + 0.6 * v[d]))});
    check(worst < 1e-14, "an affine face's point and tangents are exact");
    out << "affine face: point and tangents exact" << std::endl;
  }

  // A curved face and a tilted plane: the preimage of a point, and its
  // derivatives.
  {
    const FaceBasis basis(2);
    Face            curved;
    for (const auto &xi : basis.nodes)
      {
        const double theta = 0.4 * xi[0], z = xi[1];
        curved.push_back({{2 * std::cos(theta) + 0.05 * z * z,
                           2 * std::sin(theta) - 0.1 * xi[0] * z,
                           z + 0.03 * theta}});
      }
    // The slave face, opposite, a little tilted and warped.
    const Face                slave = {{{2.1, -0.05, -0.02}},
                                       {{2.05, 0.85, 0.03}},
                                       {{2.0, 0.8, 1.02}},
                                       {{2.12, 0.02, 0.98}}};
    const Point<2>            exact(0.3, 0.7);
    std::vector<double>       N;
    std::vector<Tensor<1, 2>> dN;
    basis.evaluate(exact, N, dN);
    const auto     plane = FaceClipping::auxiliary_plane(slave);
    const auto     p = FaceClipping::to_plane(plane, evaluate(curved, N, dN).x);
    const Preimage found = find_on_face(basis, curved, plane, p);
    check(found.converged && found.xi.distance(exact) < 1e-12,
          "the preimage of a point on a curved face");
    out << "curved face: the preimage found to 1e-12" << std::endl;

    // In AD numbers: 27 + 12 + 2 variables.
    const unsigned int       n = 41;
    std::vector<Vector3<AD>> curved_ad(9), slave_ad(4);
    for (unsigned int k = 0; k < 9; ++k)
      for (unsigned int d = 0; d < 3; ++d)
        curved_ad[k][d] = AD(n, 3 * k + d, curved[k][d]);
    for (unsigned int k = 0; k < 4; ++k)
      for (unsigned int d = 0; d < 3; ++d)
        slave_ad[k][d] = AD(n, 27 + 3 * k + d, slave[k][d]);
    const Vector2<AD> p_ad     = {{AD(n, 39, p[0]), AD(n, 40, p[1])}};
    const auto        plane_ad = FaceClipping::auxiliary_plane(slave_ad);
    const Vector2<AD> xi_ad =
      linearised_xi(basis, curved_ad, plane_ad, p_ad, found.xi).xi;
    double       worst = 0, largest = 0;
    const double h = 1e-6;
    for (unsigned int k = 0; k < n; ++k)
      {
        std::array<Point<2>, 2> xi;
        for (unsigned int side = 0; side < 2; ++side)
          {
            Face            c = curved, s = slave;
            Vector2<double> q    = p;
            const double    step = side == 0 ? h : -h;
            if (k < 27)
              c[k / 3][k % 3] += step;
            else if (k < 39)
              s[(k - 27) / 3][(k - 27) % 3] += step;
            else
              q[k - 39] += step;
            xi[side] =
              find_on_face(basis, c, FaceClipping::auxiliary_plane(s), q).xi;
          }
        for (unsigned int d = 0; d < 2; ++d)
          {
            const double fd = (xi[0][d] - xi[1][d]) / (2 * h);
            worst           = std::max(worst, std::abs(xi_ad[d].dx(k) - fd));
            largest         = std::max(largest, std::abs(fd));
          }
      }
    check(std::abs(xi_ad[0].val() - found.xi[0]) < 1e-14 && largest > 0.1 &&
            worst < 1e-7 * largest,
          "the preimage's AD derivatives equal central differences");
    out << "curved face: the preimage's derivatives (41 variables) equal "
           "central differences to 1e-7"
        << std::endl;
  }

  // The contact patch test in 3D.
  {
    const FaceBasis basis(1);
    const Surface   slave  = numbered(grid(3, 3, 0, 1, 0, 0, false));
    const Surface   master = numbered(grid(8, 9, -0.25, 1.5, 0.2, 0.01, true));
    const auto      zero   = [&] {
      return std::vector<std::vector<double>>(
        slave.nodes.size(), std::vector<double>(master.nodes.size(), 0.));
    };
    std::vector<std::vector<double>> D(slave.nodes.size(),
                                       std::vector<double>(slave.nodes.size()));
    auto                             M = zero();
    double                           clipped_area;
    mortar_by_clipping(basis, slave, master, D, M, clipped_area);
    double total = 0;
    for (const auto &row : D)
      for (const double d : row)
        total += d;
    const double error = transfer_error(D, M, slave, master);
    unsigned int n_inside;
    const double area_error = master_area_error(M, master, n_inside);
    check(std::abs(clipped_area - 1) < 1e-13 && std::abs(total - 1) < 1e-13,
          "the clip cells cover the slave surface");
    check(error < 1e-13,
          "segment-based: the linear fields transferred to round-off");
    check(n_inside >= 4 && area_error < 1e-13,
          "segment-based: the master nodes' forces to round-off");
    out << "patch test, 3 x 3 slave faces against 8 x 9 master faces turned "
           "through 0.2: the clip triangles cover the slave area, sum D = 1, "
           "the linear fields are transferred and the "
        << n_inside
        << " master nodes inside receive the uniform pressure's force on "
           "their areas, to round-off"
        << std::endl;

    // Without clipping: n x n Gauss points on each slave face.
    for (const unsigned int n : {2u, 4u, 8u})
      {
        const QGauss<2>                  rule(n);
        std::vector<std::vector<double>> Dg(
          slave.nodes.size(), std::vector<double>(slave.nodes.size()));
        auto Mg = zero();
        for (unsigned int fs = 0; fs < slave.faces.size(); ++fs)
          for (unsigned int q = 0; q < rule.size(); ++q)
            add_point(basis,
                      slave,
                      master,
                      fs,
                      rule.point(q),
                      rule.weight(q) / 9,
                      Dg,
                      Mg);
        unsigned int n_gauss;
        const double gauss_error = master_area_error(Mg, master, n_gauss);
        check(transfer_error(Dg, Mg, slave, master) < 1e-13,
              "element-based: the linear fields transferred");
        check(gauss_error > 1e-6,
              "element-based Gauss is not exact on non-matching faces");
        out << "element-based Gauss " << n << " x " << n
            << " per slave face: the linear fields transferred, the master "
               "nodes' forces wrong by up to "
            << std::defaultfloat << std::setprecision(2) << gauss_error * 100
            << " % (relative)" << std::scientific << std::setprecision(6)
            << std::endl;
      }
  }
  return 0;
}
