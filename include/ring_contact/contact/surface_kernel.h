// The geometry of a contact surface written once for any number type:
// double for the search and the closest-point projection (ContactSurface),
// Sacado's AD numbers for the exact linearisation of the contact element
// (contact_assembly.cc). A segment of a surface is the curve
//   x(t) = sum_j G_j(t) X_j + sum_i N_i(t) u_i,   0 <= t <= 1,
// with X_j the reference support points of the mapping, u_i the nodal
// displacements, G and N their 1d Lagrange bases; its outward normal is
// n = o (x'_y, -x'_x) / |x'| with o = +-1 the segment's orientation, and the
// normal at a vertex is the length-weighted average of the normals of the
// two segments that meet there. A point x_s is projected onto a segment by
// solving r(t) = 0 with
//   closest point:          r = (x_s - x(t)) . x'(t),
//   along smoothed normals: r = (x_s - x(t)) x m(t),  m = (1 - t) n0 + t n1
// (n0, n1 the vertex normals), and a segment-based piece ends where the
// slave curve crosses the line through a master vertex along its normal.
// Every function here is a template on the
// number type, so that the two paths cannot drift apart.
#ifndef ring_contact_contact_surface_kernel_h
#define ring_contact_contact_surface_kernel_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <ring_contact/base/dimension.h>

#include <cmath>
#include <limits>
#include <type_traits>
#include <utility>

namespace RingContact
{
  using namespace dealii;

  namespace SurfaceKernel
  {
    /// Position and derivatives of a point of a segment.
    template <typename Number>
    struct CurvePoint
    {
      Point<dim, Number>     x;   ///< position
      Tensor<1, dim, Number> dx;  ///< dx/dt
      Tensor<1, dim, Number> ddx; ///< d2x/dt2
    };

    /// The round-off of a distance computed from positions of the size of
    /// x: a gap below it is a gap of zero (see ContactInterface).
    inline double
    position_round_off(const Point<dim> &x)
    {
      return 64 * std::numeric_limits<double>::epsilon() * x.norm();
    }

    /// Add sum_i phi_i v_i to p.x, and the same with the derivatives dphi
    /// and ddphi to p.dx and p.ddx where they are given (not nullptr). The
    /// basis values may be of another number type than the point (a basis
    /// expanded around a moving parameter); `nodal(i)` is the nodal vector
    /// v_i (a Point, a Tensor, of double or of Number).
    template <typename Number, typename BasisNumber, typename Nodal>
    void
    add_interpolation(CurvePoint<Number> &p,
                      const unsigned int  n,
                      const BasisNumber  *phi,
                      const BasisNumber  *dphi,
                      const BasisNumber  *ddphi,
                      const Nodal        &nodal)
    {
      for (unsigned int i = 0; i < n; ++i)
        {
          const auto v = nodal(i);
          for (unsigned int d = 0; d < dim; ++d)
            {
              p.x[d] += phi[i] * v[d];
              if (dphi != nullptr)
                p.dx[d] += dphi[i] * v[d];
              if (ddphi != nullptr)
                p.ddx[d] += ddphi[i] * v[d];
            }
        }
    }

    /// The outward normal scaled by |x'|: o (x'_y, -x'_x).
    template <typename Number>
    Tensor<1, dim, Number>
    scaled_normal(const Tensor<1, dim, Number> &dx, const double orientation)
    {
      Tensor<1, dim, Number> n;
      n[0] = orientation * dx[1];
      n[1] = -orientation * dx[0];
      return n;
    }

    // A note on the order of the operations below: the double and the AD
    // paths were written separately before this kernel, with the same
    // expressions grouped differently (a double Tensor divides by
    // multiplying with the inverse, the AD code divided; sums were grouped
    // differently). `exact_as_before` keeps each path's own order, so that
    // the kernel changed no result in its last bit; both orders are the
    // same expression.
    template <typename Number>
    constexpr bool exact_as_before = std::is_floating_point<Number>::value;

    /// v / |v|.
    template <typename Number>
    Tensor<1, dim, Number>
    unit(const Tensor<1, dim, Number> &v)
    {
      using std::sqrt;
      const Number           length = sqrt(v[0] * v[0] + v[1] * v[1]);
      Tensor<1, dim, Number> u;
      if constexpr (exact_as_before<Number>)
        {
          const Number inverse = Number(1.) / length;
          u[0]                 = v[0] * inverse;
          u[1]                 = v[1] * inverse;
        }
      else
        {
          u[0] = v[0] / length;
          u[1] = v[1] / length;
        }
      return u;
    }

    /// The unit normal at a vertex from the scaled normals of the segments
    /// that meet there (`has_second` = false at the end of an open
    /// surface).
    template <typename Number>
    Tensor<1, dim, Number>
    vertex_normal(const Tensor<1, dim, Number> &first,
                  const Tensor<1, dim, Number> &second,
                  const bool                    has_second)
    {
      Tensor<1, dim, Number> n = first;
      if (has_second)
        {
          n[0] += second[0];
          n[1] += second[1];
        }
      return unit(n);
    }

    /// a - b, component by component (deal.II's Tensor arithmetic does not
    /// take Sacado's expression templates).
    template <typename Number, typename A, typename B>
    Tensor<1, dim, Number>
    difference(const A &a, const B &b)
    {
      Tensor<1, dim, Number> d;
      for (unsigned int i = 0; i < dim; ++i)
        d[i] = a[i] - b[i];
      return d;
    }

    /// a x b in the plane.
    template <typename Number, typename OtherNumber>
    Number
    cross(const Tensor<1, dim, Number> &a, const Tensor<1, dim, OtherNumber> &b)
    {
      return a[0] * b[1] - a[1] * b[0];
    }

    /// The smoothed normal direction m(t) = (1 - t) n0 + t n1.
    template <typename Number, typename T>
    Tensor<1, dim, Number>
    smoothed_direction(const Tensor<1, dim, Number> &n0,
                       const Tensor<1, dim, Number> &n1,
                       const T                      &t)
    {
      Tensor<1, dim, Number> m;
      for (unsigned int d = 0; d < dim; ++d)
        m[d] = (1 - t) * n0[d] + t * n1[d];
      return m;
    }

    /// The closest-point condition r(t) = d . x'(t) with d = x_s - x(t),
    /// and dr/dt (x_s fixed).
    template <typename Number>
    std::pair<Number, Number>
    closest_point_residual(const Tensor<1, dim, Number> &d,
                           const CurvePoint<Number>     &p)
    {
      const Number r       = d[0] * p.dx[0] + d[1] * p.dx[1];
      const Number tangent = -(p.dx[0] * p.dx[0] + p.dx[1] * p.dx[1]);
      if constexpr (exact_as_before<Number>)
        return {r, tangent + (d[0] * p.ddx[0] + d[1] * p.ddx[1])};
      else
        return {r, tangent + d[0] * p.ddx[0] + d[1] * p.ddx[1]};
    }

    /// The smoothed-normal condition r(t) = d x m(t) with d = x_s - x(t),
    /// and dr/dt.
    template <typename Number>
    std::pair<Number, Number>
    smoothed_normal_residual(const Tensor<1, dim, Number> &d,
                             const CurvePoint<Number>     &p,
                             const Tensor<1, dim, Number> &n0,
                             const Tensor<1, dim, Number> &n1,
                             const double                  t)
    {
      const Tensor<1, dim, Number> m = smoothed_direction(n0, n1, t);
      if constexpr (exact_as_before<Number>)
        return {cross(d, m),
                -cross(p.dx, m) + cross(d, difference<Number>(n1, n0))};
      else
        return {cross(d, m),
                -cross(p.dx, m) + d[0] * (n1[1] - n0[1]) -
                  d[1] * (n1[0] - n0[0])};
    }
    /// Segment-based integration: the crossing of a slave curve x_s(eta)
    /// with the line through a master vertex x_v along its normal n_v is
    /// h(eta) = (x_s - x_v) x n_v = 0; returns h and dh/deta from d = x_s -
    /// x_v and x_s'.
    template <typename Number, typename NormalNumber>
    std::pair<Number, Number>
    piece_end_residual(const Tensor<1, dim, Number>       &d,
                       const Tensor<1, dim, Number>       &dx,
                       const Tensor<1, dim, NormalNumber> &normal)
    {
      return {cross(d, normal), cross(dx, normal)};
    }
  } // namespace SurfaceKernel
} // namespace RingContact

#endif
