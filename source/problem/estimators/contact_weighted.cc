// @sect3{The contact-weighted estimator}
//
// Contact weighted: the error that matters is the contact's. A cell's error
// reaches the contact pressure through the dual solution of a functional on
// the contact zone, whose second derivatives (which weigh the cell's
// residual) fall like 1 / r^2 away from a zone of length l: each indicator of
// 'Kelly and contact' is weighed by (l / (l + d))^2, d the distance from the
// cell to the nearest active slave face. Hertz (a = R / 30, 11 cycles of
// 5 %): a smaller L2 error of the pressure than unweighted for as many
// unknowns (doc/validation.md, "Adaptive refinement").
#include <deal.II/base/utilities.h>
#include <deal.II/numerics/rtree.h>

#include <ring_contact/base/components.h>
#include <ring_contact/problem/refinement_estimator.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace RingContact
{
  namespace
  {
    // The slave faces in contact: a multiplier above 1e-8 of the largest (an
    // open node's multiplier is zero up to the linear solver's round-off,
    // which differs between one process and several), each face's largest
    // |multiplier| at the points of its rule. Their centres, and the length
    // they cover.
    std::pair<std::vector<Point<dim>>, double>
    faces_in_contact(const EstimatorInput &input)
    {
      const FEValuesExtractors::Scalar pressure(Components::multiplier<dim>);
      // (centre, length, largest |multiplier|) of each slave face.
      std::vector<std::tuple<Point<dim>, double, double>> slave_faces;
      std::vector<double>                                 lambda;
      for_each_slave_face(input,
                          [&](const DoFHandler<dim>::active_cell_iterator &cell,
                              const unsigned int                           f,
                              const FEFaceValues<dim>                     &fv) {
                            lambda.resize(fv.n_quadrature_points);
                            fv[pressure].get_function_values(input.solution,
                                                             lambda);
                            double largest = 0;
                            for (const double l : lambda)
                              largest = std::max(largest, std::abs(l));
                            slave_faces.emplace_back(cell->face(f)->center(),
                                                     cell->face(f)->measure(),
                                                     largest);
                          });
      double largest = 0;
      for (const auto &face : slave_faces)
        largest = std::max(largest, std::get<2>(face));
      std::vector<Point<dim>> active_points;
      double                  active_length = 0;
      for (const auto &[center, length, multiplier] : slave_faces)
        if (multiplier > 1e-8 * largest)
          {
            active_points.push_back(center);
            active_length += length;
          }
      return {active_points, active_length};
    }

    // Without contact, the indicator is left as 'Kelly and contact' made it.
    void
    weigh_by_distance_from_contact(const EstimatorInput &input,
                                   Vector<float>        &indicator)
    {
      const auto [active_points, active_length] = faces_in_contact(input);
      if (active_points.empty())
        return;
      const auto tree = pack_rtree(active_points);
      for (const auto &cell : input.triangulation.active_cell_iterators())
        {
          std::vector<Point<dim>> nearest;
          tree.query(boost::geometry::index::nearest(cell->center(), 1),
                     std::back_inserter(nearest));
          const double d = std::max(0.0,
                                    nearest[0].distance(cell->center()) -
                                      cell->diameter() / 2);
          indicator[cell->active_cell_index()] *=
            Utilities::fixed_power<2>(active_length / (active_length + d));
        }
    }

    // The registration line of the estimator: Mesh refinement/Estimator =
    // Contact weighted, the default.
    const RefinementEstimators::Add registration{RefinementEstimator{
      "Contact weighted",
      {},
      "Kelly and contact, each cell's indicator multiplied by (l / (l + "
      "d))^2, d its distance from the nearest slave face in contact and l "
      "the length in contact: the mesh refined for the contact's accuracy "
      "rather than the energy's everywhere (without contact, as Kelly and "
      "contact).",
      "Kelly and contact",
      weigh_by_distance_from_contact}};
  } // namespace
} // namespace RingContact
