// @sect3{The refinement estimators}
//
// The adaptive refinement ranks the cells by an error indicator, and the
// parameter file chooses which (Mesh refinement/Estimator). The estimators
// build on each other: Kelly's sees the jumps of the displacement's gradient
// across the inner faces and no boundary, while the pressure's error sits on
// one; 'Kelly and contact' adds the contact's residual on the slave faces to
// it; 'Contact weighted' weighs that by the distance from the contact zone.
// So each registers the estimator it starts from and the step it adds
// (estimators/*.cc), and the indicator is composed here, down the chain and
// back. The entry's documentation says them in the same order, each after the
// one it builds on.
#include <deal.II/hp/fe_values.h>

#include <ring_contact/problem/refinement_estimator.h>

namespace RingContact
{
  Vector<float>
  estimate_error(const std::string &name, const EstimatorInput &input)
  {
    const RefinementEstimator &estimator = RefinementEstimators::get(name);
    Vector<float>              indicator =
      estimator.starts_from.empty() ?
                     Vector<float>(input.triangulation.n_active_cells()) :
                     estimate_error(estimator.starts_from, input);
    estimator.refine_indicator(input, indicator);
    return indicator;
  }

  namespace
  {
    // The estimators that start from `base` (those that start from nothing
    // for an empty one), each followed by those that start from it: the
    // order in which each is said after what it builds on.
    void
    document_from(const std::string &base, std::string &text)
    {
      for (const auto &estimator : RefinementEstimators::members())
        if (estimator.starts_from == base)
          {
            text += (text.empty() ? "" : " ") + estimator.name + ": " +
                    estimator.documentation;
            document_from(estimator.name, text);
          }
    }
  } // namespace

  std::string
  refinement_estimators_documentation()
  {
    std::string text;
    document_from("", text);
    return text;
  }

  // Every process holds the whole solution and the whole mesh: each visits
  // every slave face, and all compute the same indicators.
  void
  for_each_slave_face(
    const EstimatorInput                                            &input,
    const std::function<void(const DoFHandler<dim>::active_cell_iterator &cell,
                             const unsigned int                           face,
                             const FEFaceValues<dim> &face_values)> &visit)
  {
    hp::FEFaceValues<dim> face_values(input.mapping_collection,
                                      input.fe_collection,
                                      input.face_quadrature,
                                      update_values | update_gradients |
                                        update_normal_vectors |
                                        update_JxW_values);
    for (const auto &cell : input.dof_handler.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary() &&
            input.slave_boundaries.count(cell->face(f)->boundary_id()) > 0)
          {
            face_values.reinit(cell, f);
            visit(cell, f, face_values.get_present_fe_values());
          }
  }
} // namespace RingContact
