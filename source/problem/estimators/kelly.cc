// @sect3{Kelly's estimator}
//
// deal.II's KellyErrorEstimator: the jumps of the displacement's gradient
// across each cell's inner faces. It sees no boundary, and so nothing of the
// contact, whose error sits on one: the contact's estimators start from it
// (kelly_and_contact.cc).
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/numerics/error_estimator.h>

#include <ring_contact/base/components.h>
#include <ring_contact/problem/refinement_estimator.h>

namespace RingContact
{
  namespace
  {
    // Kelly's estimator takes one mapping: the bodies' highest degree (an
    // indicator only; the faces' jumps do not need each body's own).
    void
    kelly_indicator(const EstimatorInput &input, Vector<float> &indicator)
    {
      KellyErrorEstimator<dim>::estimate(MappingQ<dim>(input.mapping_degree),
                                         input.dof_handler,
                                         input.face_quadrature,
                                         {},
                                         input.solution,
                                         indicator,
                                         Components::displacement_mask<dim>());
    }

    // The registration line of the estimator: Mesh refinement/Estimator =
    // Kelly.
    const RefinementEstimators::Add registration{RefinementEstimator{
      "Kelly",
      {},
      "the jumps of the gradient of the displacement across its inner faces "
      "(deal.II's KellyErrorEstimator).",
      "",
      kelly_indicator}};
  } // namespace
} // namespace RingContact
