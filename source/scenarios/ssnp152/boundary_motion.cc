// @sect3{The imposed motion of the rings' loaded boundaries}
//
// SSNP152 is loaded by displacements only (doc/intro.md, "Loads"). With
// theta = atan2(Y, X), u = f(R1) (cos theta, sin theta) on S1R1 (r = R1); on
// S2R3 (r = R3) the boundary is contracted to R3 + f(R3) and turned rigidly
// through alpha = 2 pi s / Ne,
//   u = (R3 + f(R3))(cos(theta + alpha), sin(theta + alpha)) - (X, Y).
// Both are this one function of the reference point, f from the closed form
// (analytic_solution.cc), alpha = 0 on r = R1. Holding each ring by its own
// boundary also keeps the frictionless inner ring from spinning freely: the
// contact only transmits the pressure.
#include <deal.II/lac/vector.h>

#include <ring_contact/base/dimension.h>
#include <ring_contact/scenarios/ssnp152/boundary_motion.h>

#include <cmath>

namespace RingContact
{
  BoundaryMotion::BoundaryMotion(const double       radial_displacement,
                                 const double       rotation_angle,
                                 const unsigned int n_components)
      : Function<dim>(n_components)
      , radial_displacement(radial_displacement)
      , rotation_angle(rotation_angle)
  {}

  double
  BoundaryMotion::value(const Point<dim> &X, const unsigned int component) const
  {
    // The multipliers are not boundary data: zero, and the interpolation's
    // displacement mask leaves them out anyway.
    if (component >= 2)
      return 0.0;
    // The displacement itself, u = (R - I) X + R u_r X / |X|, not the
    // difference of the moved and the reference positions: a displacement
    // below the round-off of the position (1e-200 m on rings of 1 m) would
    // be lost in it. c - 1 = -2 sin^2(angle / 2), without cancellation. On the
    // circle |X| = R3 this is
    // (R3 + f) (cos(theta + alpha), sin(theta + alpha)) - X of doc/intro.md:
    // the rotation acts on the radial part too, so the contraction turns with
    // the boundary.
    const double         r = X.norm();
    const Tensor<1, dim> radial(X * (radial_displacement / r));
    const double c = std::cos(rotation_angle), s = std::sin(rotation_angle);
    const double half_sine = std::sin(0.5 * rotation_angle);
    const double c_minus_1 = -2 * half_sine * half_sine;
    const double x =
      c_minus_1 * X[0] - s * X[1] + c * radial[0] - s * radial[1];
    const double y =
      s * X[0] + c_minus_1 * X[1] + s * radial[0] + c * radial[1];
    return component == 0 ? x : y;
  }

  void
  BoundaryMotion::vector_value(const Point<dim> &X,
                               Vector<double>   &values) const
  {
    for (unsigned int c = 0; c < values.size(); ++c)
      values[c] = value(X, c);
  }
} // namespace RingContact
