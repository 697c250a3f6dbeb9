// @sect3{Kelly's estimator and the contact's residual}
//
// Kelly's indicator on the displacement, and on each slave face
// h/24 int |P N + lambda cof(F) N|^2 / E^2 dS: P N dS is the force the
// body's stress puts on the face, lambda cof(F) N dS the pressure's (the
// multiplier is the Cauchy pressure, per current length), and Kelly's
// scale, the cell's diameter over 24, with the strain's units (over E).
// With friction the tangential traction is a multiplier of its own, and
// only the normal part of the residual is taken. At each slave vertex
// the jump of the pressure's slope, h^3/24 [dp/ds]^2 / E^2 to both
// cells: the edge of a contact, where the pressure falls as a square
// root, is where it is largest (Hertz: the L2 error of the pressure fell
// with it for as many unknowns; doc/validation.md, "Adaptive refinement").
#include <deal.II/base/tensor.h>

#include <ring_contact/base/components.h>
#include <ring_contact/problem/face_multipliers.h>
#include <ring_contact/problem/refinement_estimator.h>

#include <cmath>
#include <map>
#include <vector>

namespace RingContact
{
  namespace
  {
    using namespace FaceMultipliers;

    // The pressure's slope at one end of a slave face, as a vector along
    // the face (orientation-free), with the cell it belongs to, the face's
    // length and the body's Young's modulus.
    struct Slope
    {
      Tensor<1, dim> slope;
      unsigned int   cell;
      double         length, E;
    };

    // The residual of the contact condition on a slave face:
    // int |P N + lambda cof(F) N|^2 dS (its normal part with friction).
    double
    contact_residual(const EstimatorInput    &input,
                     const Material<dim>     &material,
                     const FEFaceValues<dim> &fv)
    {
      const FEValuesExtractors::Vector displacement(0);
      const FEValuesExtractors::Scalar pressure(Components::multiplier<dim>);
      std::vector<Tensor<2, dim>>      grad_u(fv.n_quadrature_points);
      std::vector<double>              lambda(fv.n_quadrature_points);
      fv[displacement].get_function_gradients(input.solution, grad_u);
      fv[pressure].get_function_values(input.solution, lambda);
      const bool linear = material.geometrically_linear;
      double     sum    = 0;
      for (unsigned int q = 0; q < fv.n_quadrature_points; ++q)
        {
          const Tensor<1, dim> N = fv.normal_vector(q);
          Tensor<2, dim>       F = unit_symmetric_tensor<dim>();
          F += grad_u[q];
          // cof(F) = det(F) F^-T; the reference normal in small strain.
          const Tensor<1, dim> area =
            linear ? N : determinant(F) * transpose(invert(F)) * N;
          Tensor<1, dim> residual =
            material.stress(grad_u[q]) * N + lambda[q] * area;
          if (input.friction)
            residual = (residual * area / area.norm()) * area / area.norm();
          sum += residual.norm_square() * fv.JxW(q);
        }
      return sum;
    }

    void
    add_contact_residual(const EstimatorInput &input, Vector<float> &indicator)
    {
      std::map<unsigned int, std::vector<Slope>> slopes;
      for_each_slave_face(
        input,
        [&](const DoFHandler<dim>::active_cell_iterator &cell,
            const unsigned int                           f,
            const FEFaceValues<dim>                     &fv) {
          const Material<dim> &material =
            input.materials.at(cell->material_id());
          const double sum = contact_residual(input, material, fv);
          const double E   = material.youngs_modulus;
          indicator[cell->active_cell_index()] =
            std::sqrt(std::pow(indicator[cell->active_cell_index()], 2) +
                      cell->diameter() / 24 * sum / (E * E));

          // The pressure's slope at the face's two ends, as a vector
          // along the face (orientation-free), for the jumps below.
          const auto       face   = cell->face(f);
          const auto       points = multiplier_face_points(cell->get_fe());
          const FaceValues values =
            face_multipliers(cell, f, points, input.solution);
          const Tensor<1, dim> along  = face->vertex(1) - face->vertex(0);
          const double         length = along.norm();
          for (unsigned int end = 0; end < 2; ++end)
            slopes[face->vertex_index(end)].push_back(
              {derivative(values, points, Components::multiplier<dim>, end) /
                 (length * length) * along,
               cell->active_cell_index(),
               length,
               E});
        });
      // The jump of the pressure's slope at each slave vertex, h^3/24
      // [dp/ds]^2 / E^2 to each of the two cells.
      for (const auto &[vertex, list] : slopes)
        if (list.size() == 2)
          {
            const double jump = (list[0].slope - list[1].slope).norm();
            for (const auto &end : list)
              {
                auto &eta = indicator[end.cell];
                eta       = std::sqrt(eta * eta + std::pow(end.length, 3) / 24 *
                                              jump * jump / (end.E * end.E));
              }
          }
    }

    // The registration line of the estimator: Mesh refinement/Estimator =
    // Kelly and contact.
    const RefinementEstimators::Add registration{RefinementEstimator{
      "Kelly and contact",
      {},
      "plus, on its faces on a slave surface, the residual of the contact "
      "condition (the difference between the body's traction P N and the "
      "contact traction the multipliers give, over Young's modulus) and the "
      "jumps of the pressure's slope.",
      "Kelly",
      add_contact_residual}};
  } // namespace
} // namespace RingContact
