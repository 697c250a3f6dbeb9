#include <deal.II/lac/vector.h>

#include <ring_contact/boundary_motion.h>

#include <cmath>

namespace RingContact
{
  BoundaryMotion::BoundaryMotion(const double       radial_displacement,
                                 const double       rotation_angle,
                                 const unsigned int n_components)
      : Function<2>(n_components)
      , radial_displacement(radial_displacement)
      , rotation_angle(rotation_angle)
  {}

  double
  BoundaryMotion::value(const Point<2> &X, const unsigned int component) const
  {
    if (component >= 2)
      return 0.0;
    const double   r = X.norm();
    const Point<2> moved(X * (1 + radial_displacement / r));
    const double   c = std::cos(rotation_angle), s = std::sin(rotation_angle);
    const double   x = c * moved[0] - s * moved[1];
    const double   y = s * moved[0] + c * moved[1];
    return component == 0 ? x - X[0] : y - X[1];
  }

  void
  BoundaryMotion::vector_value(const Point<2> &X, Vector<double> &values) const
  {
    for (unsigned int c = 0; c < values.size(); ++c)
      values[c] = value(X, c);
  }
} // namespace RingContact
