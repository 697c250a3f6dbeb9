// The refinement estimators: the error indicator of each cell that the
// adaptive refinement ranks the cells by (subsection Mesh refinement,
// entry Estimator). Each estimator registers itself in a file of its own in
// source/problem/estimators/ (base/registry.h): its name, its documentation,
// the estimator whose indicator it starts from, and what it does to that
// indicator (Kelly's computes it; 'Kelly and contact' adds the contact's
// residual to Kelly's; 'Contact weighted' weighs that by the distance from
// the contact zone).
#ifndef ring_contact_problem_refinement_estimator_h
#define ring_contact_problem_refinement_estimator_h

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/tria.h>
#include <deal.II/hp/fe_collection.h>
#include <deal.II/hp/mapping_collection.h>
#include <deal.II/hp/q_collection.h>
#include <deal.II/lac/vector.h>

#include <ring_contact/base/dimension.h>
#include <ring_contact/base/registry.h>
#include <ring_contact/materials/material.h>

#include <functional>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace RingContact
{
  using namespace dealii;

  /// What an estimator reads of the contact problem: its mesh, elements
  /// and solution, the bodies' materials and the slave surfaces
  /// (ContactProblem::estimate_error() gathers them).
  struct EstimatorInput
  {
    const Triangulation<dim>         &triangulation;
    const DoFHandler<dim>            &dof_handler;
    const hp::FECollection<dim>      &fe_collection;
    const hp::MappingCollection<dim> &mapping_collection;
    /// p + 1 Gauss points on a face of each element of fe_collection.
    const hp::QCollection<1> face_quadrature;
    /// The degree of the one mapping Kelly's estimator takes: the bodies'
    /// highest.
    const unsigned int                           mapping_degree;
    const Vector<double>                        &solution;
    const std::map<unsigned int, Material<dim>> &materials; ///< by material id
    /// The slave surfaces of every contact pair.
    const std::set<types::boundary_id> slave_boundaries;
    /// Whether the tangential traction is a multiplier of its own.
    const bool friction;
  };

  /// One refinement estimator, as it registers itself:
  ///   const RefinementEstimators::Add registration{RefinementEstimator{...}};
  struct RefinementEstimator
  {
    /// Its value of Mesh refinement/Estimator.
    std::string name;
    /// Values still read for it.
    std::vector<std::string> old_names;
    /// What it does, for the entry's documentation (said after the
    /// estimator it starts from).
    std::string documentation;
    /// The estimator whose indicator it starts from; empty: it starts from
    /// nothing, its function computes the indicator.
    std::string starts_from;
    /// What it does to that indicator (one value per active cell).
    std::function<void(const EstimatorInput &input, Vector<float> &indicator)>
      refine_indicator;
  };

  /// The registered estimators, sorted by name.
  using RefinementEstimators = Registry<RefinementEstimator>;

  /// The indicator of the estimator `name` (or an old name of it): that of
  /// the estimator it starts from, and so on down, then its own step.
  Vector<float>
  estimate_error(const std::string &name, const EstimatorInput &input);

  /// "Kelly: ... Kelly and contact: ... Contact weighted: ...": each
  /// estimator after the one it starts from, for the entry's
  /// documentation.
  std::string
  refinement_estimators_documentation();

  /// Call `visit` on every face of a slave surface, with the values,
  /// gradients, normals and JxW of the solution's element there (the
  /// estimators of the contact).
  void
  for_each_slave_face(
    const EstimatorInput                                            &input,
    const std::function<void(const DoFHandler<dim>::active_cell_iterator &cell,
                             const unsigned int                           face,
                             const FEFaceValues<dim> &face_values)> &visit);
} // namespace RingContact

#endif
