// The multipliers on one face of a slave surface, as the Lagrange polynomial
// through their values at the face's support points: read from a solution,
// evaluated and differentiated along the face (face_multipliers.cc).
#ifndef ring_contact_problem_face_multipliers_h
#define ring_contact_problem_face_multipliers_h

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe.h>
#include <deal.II/lac/vector.h>

#include <ring_contact/base/dimension.h>

#include <map>
#include <utility>
#include <vector>

namespace RingContact
{
  using namespace dealii;

  namespace FaceMultipliers
  {
    /// The multiplier values of one face of a slave surface, by component
    /// and by the index of the face's support point in its base element
    /// FE_Q(q) (0 and 1 its ends, then the points between).
    using FaceValues = std::map<std::pair<unsigned int, unsigned int>, double>;

    /// The parameter in [0, 1] along a face (from its vertex 0) of the
    /// support point of a face unknown, and its component and index in the
    /// base element.
    struct FacePoint
    {
      unsigned int component, index;
      double       t;
    };

    /// The support points of the multiplier unknowns of a face of `fe`.
    std::vector<FacePoint>
    multiplier_face_points(const FiniteElement<dim> &fe);

    /// The value at t of the Lagrange polynomial through a face's values of
    /// `component` (at the support points `points` of its element).
    double
    interpolate(const FaceValues             &values,
                const std::vector<FacePoint> &points,
                const unsigned int            component,
                const double                  t);

    /// d/dt of that polynomial.
    double
    derivative(const FaceValues             &values,
               const std::vector<FacePoint> &points,
               const unsigned int            component,
               const double                  t);

    /// The multipliers of `u` on face f of a slave layer's cell.
    FaceValues
    face_multipliers(const DoFHandler<dim>::active_cell_iterator &cell,
                     const unsigned int                           f,
                     const std::vector<FacePoint>                &points,
                     const Vector<double>                        &u);
  } // namespace FaceMultipliers
} // namespace RingContact

#endif
