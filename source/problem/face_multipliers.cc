// @sect3{The multipliers of a slave face as a polynomial}
//
// The contact pressure on a face of a slave surface is a Lagrange polynomial
// through its values at the face's support points. Two chapters read it so:
// the refinement carries the multipliers to the new mesh face by face,
// interpolating a parent face's polynomial on its children (refinement.cc),
// and the contact estimator measures the jumps of the pressure's slope
// between neighbouring faces (estimators/kelly_and_contact.cc).
#include <deal.II/base/polynomial.h>
#include <deal.II/dofs/dof_accessor.h>
#include <deal.II/fe/fe.h>

#include <ring_contact/base/components.h>
#include <ring_contact/problem/face_multipliers.h>

#include <array>

namespace RingContact
{
  namespace FaceMultipliers
  {
    std::vector<FacePoint>
    multiplier_face_points(const FiniteElement<dim> &fe)
    {
      std::vector<FacePoint> points;
      for (unsigned int i = 0; i < fe.n_dofs_per_face(); ++i)
        {
          const unsigned int component =
            fe.face_system_to_component_index(i).first;
          if (Components::is_displacement<dim>(component))
            continue;
          const auto base = fe.face_system_to_base_index(i);
          points.push_back({component,
                            base.second,
                            fe.base_element(base.first.first)
                              .get_unit_face_support_points()[base.second][0]});
        }
      return points;
    }

    namespace
    {
      // The value and the slope at t of the Lagrange polynomial through a
      // face's values of `component` (at the support points `points` of its
      // element): deal.II's Lagrange basis through those points, each basis
      // function weighted by its value.
      std::array<double, 2>
      value_and_slope(const FaceValues             &values,
                      const std::vector<FacePoint> &points,
                      const unsigned int            component,
                      const double                  t)
      {
        std::vector<Point<1>>     support;
        std::vector<unsigned int> indices;
        for (const auto &p : points)
          if (p.component == component)
            {
              support.emplace_back(p.t);
              indices.push_back(p.index);
            }
        const std::vector<Polynomials::Polynomial<double>> basis =
          Polynomials::generate_complete_Lagrange_basis(support);
        std::array<double, 2> sum = {{0, 0}};
        std::vector<double>   basis_values(2);
        for (unsigned int k = 0; k < basis.size(); ++k)
          {
            basis[k].value(t, basis_values);
            const double value = values.at({component, indices[k]});
            sum[0] += basis_values[0] * value;
            sum[1] += basis_values[1] * value;
          }
        return sum;
      }
    } // namespace

    double
    interpolate(const FaceValues             &values,
                const std::vector<FacePoint> &points,
                const unsigned int            component,
                const double                  t)
    {
      return value_and_slope(values, points, component, t)[0];
    }

    double
    derivative(const FaceValues             &values,
               const std::vector<FacePoint> &points,
               const unsigned int            component,
               const double                  t)
    {
      return value_and_slope(values, points, component, t)[1];
    }

    // The multipliers of `u` on face f of a slave layer's cell.
    FaceValues
    face_multipliers(const DoFHandler<dim>::active_cell_iterator &cell,
                     const unsigned int                           f,
                     const std::vector<FacePoint>                &points,
                     const Vector<double>                        &u)
    {
      const auto                          &fe = cell->get_fe();
      std::vector<types::global_dof_index> face_dofs(fe.n_dofs_per_face());
      cell->face(f)->get_dof_indices(face_dofs, cell->active_fe_index());
      FaceValues values;
      for (unsigned int i = 0, k = 0; i < fe.n_dofs_per_face(); ++i)
        if (!Components::is_displacement<dim>(
              fe.face_system_to_component_index(i).first))
          {
            values[{points[k].component, points[k].index}] = u(face_dofs[i]);
            ++k;
          }
      return values;
    }
  } // namespace FaceMultipliers
} // namespace RingContact
