// The displacements imposed on the two outer boundaries of SSNP152, taken
// from the analytic solution: radial on r = R1, radial and turned through
// the angle alpha on r = R3.
#ifndef ring_contact_scenarios_ssnp152_boundary_motion_h
#define ring_contact_scenarios_ssnp152_boundary_motion_h

#include <deal.II/base/function.h>

#include <ring_contact/base/dimension.h>

namespace RingContact
{
  using namespace dealii;

  /**
   * u(X) = Q(alpha) (X + f X/|X|) - X: the point moves radially by f and the
   * result is turned through alpha about the origin. For alpha = 0 this is
   * f (cos theta, sin theta); for |X| = R it is (R + f)(cos(theta + alpha),
   * sin(theta + alpha)) - X, exactly as SSNP152 writes it. Components beyond
   * the first two (the multiplier) are zero.
   */
  class BoundaryMotion : public Function<dim>
  {
  public:
    BoundaryMotion(const double       radial_displacement,
                   const double       rotation_angle,
                   const unsigned int n_components);

    double
    value(const Point<dim> &X, const unsigned int component) const override;

    void
    vector_value(const Point<dim> &X, Vector<double> &values) const override;

  private:
    const double radial_displacement;
    const double rotation_angle;
  };
} // namespace RingContact

#endif
