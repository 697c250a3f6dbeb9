// @sect3{Small-strain linear elasticity}
//
// Small-strain linear elasticity: sigma = lambda tr(eps) I + 2 mu eps with
// eps = (H + H^T) / 2, in plane stress (lambda*) or plane strain.
//
// The law of Material law = linear elasticity, which is geometrically linear
// throughout (design.md): the contact is paired and measured in the
// reference configuration too, so that a run isolates the discretisation
// error (validation.md). Its stress is the one the virtual
// work needs (P = sigma at this order) and the Cauchy stress at once, and
// its tangent is the constant Hooke tensor; the finite-strain laws all
// tend to it at small H (the Hencky and neo-Hookean tests check this at
// strains of 1e-7).
#include <ring_contact/materials/material.h>

namespace RingContact
{
  namespace
  {
    template <int dim>
    class LinearElasticity : public MaterialLaw<dim>
    {
    public:
      explicit LinearElasticity(const ElasticConstants &constants)
          : c(constants)
      {}

      Tensor<2, dim>
      stress(const Tensor<2, dim> &H) const override
      {
        const Tensor<2, dim> I   = unit_symmetric_tensor<dim>();
        const Tensor<2, dim> eps = 0.5 * (H + transpose(H));
        return c.lambda * trace(eps) * I + 2 * c.mu * eps;
      }

      // A_iJkL = lambda d_iJ d_kL + mu (d_ik d_JL + d_iL d_Jk), independent
      // of H: the tangent is the same at every Newton iteration.
      void
      stress_and_tangent(const Tensor<2, dim> &H,
                         Tensor<2, dim>       &P,
                         Tensor<4, dim>       &A) const override
      {
        const Tensor<2, dim> I = unit_symmetric_tensor<dim>();
        P                      = stress(H);
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int J = 0; J < dim; ++J)
            for (unsigned int k = 0; k < dim; ++k)
              for (unsigned int L = 0; L < dim; ++L)
                A[i][J][k][L] = c.lambda * I[i][J] * I[k][L] +
                                c.mu * (I[i][k] * I[J][L] + I[i][L] * I[J][k]);
      }

      // Not P F^T / det F: in a geometrically linear theory the stress is
      // already the Cauchy stress, and applying F to it would add a
      // second-order term that the theory does not have.
      Tensor<2, dim>
      cauchy_stress(const Tensor<2, dim> &H) const override
      {
        return stress(H);
      }

      // Plane strain: eps33 = 0, sigma33 = lambda (eps11 + eps22).
      double
      out_of_plane_stress(const Tensor<2, dim> &H) const override
      {
        // A 3d body: the zz component of its Cauchy stress.
        if constexpr (dim == 3)
          return this->cauchy_stress(H)[2][2];
        if (c.plane == PlaneAssumption::plane_stress)
          return 0;
        return c.lambda_3d * trace(H);
      }

      // A linear theory integrates over the reference configuration and its
      // stress is already the Cauchy stress: the thinning of plane stress,
      // eps33 = -lambda / (lambda + 2 mu) tr(eps), enters no result.
      double
      thickness_stretch(const Tensor<2, dim> &) const override
      {
        return 1.0;
      }

    private:
      const ElasticConstants c;
    };
  } // namespace

  // The registration line: Material law = linear elasticity (the former
  // Kinematics = small strain). Its name is also the one a linearised
  // problem runs every body with.
  const char *const linear_elasticity_law = "linear elasticity";

  namespace
  {
    const MaterialLaws::Add registration{
      MaterialLawRegistration::of<LinearElasticity>(
        linear_elasticity_law,
        {"small strain"},
        "small-strain linear elasticity, sigma = lambda tr(eps) I + 2 mu eps; "
        "geometrically linear: the problem, its contact and its loads are "
        "written on the reference configuration.",
        true)};
  } // namespace
} // namespace RingContact
