// Reduced integration of the 9-node quadrilateral (2 x 2 Gauss points, the
// original's C_PLAN_SI, modelisation H): the zero-energy modes of one
// element's stiffness with full (3 x 3) and reduced integration, and the
// effect on the whole problem: modelisation H with reduced integration
// against full integration, step by step.
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/lac/lapack_full_matrix.h>

#include <ring_contact/config.h>
#include <ring_contact/materials/material.h>
#include <ring_contact/problem/contact_problem.h>

#include "run_problem.h"

#include <iomanip>

using namespace RingContact;
using RingContactTests::check;

namespace
{
  // Number of eigenvalues of the element stiffness below 1e-10 times the
  // largest: the rigid-body modes (3) plus the spurious ones.
  unsigned int
  zero_energy_modes(const unsigned int n_gauss)
  {
    Triangulation<2> triangulation;
    GridGenerator::hyper_cube(triangulation, 0, 0.1);
    const FESystem<2> fe(FE_Q<2>(2), 2);
    DoFHandler<2>     dof_handler(triangulation);
    dof_handler.distribute_dofs(fe);
    const QGauss<2> quadrature(n_gauss);
    FEValues<2> fe_values(fe, quadrature, update_gradients | update_JxW_values);
    fe_values.reinit(dof_handler.begin_active());
    const Material<2> material(1e9,
                               0.2,
                               PlaneAssumption::plane_stress,
                               "small strain");
    Tensor<2, 2>      P;
    Tensor<4, 2>      A;
    material.stress_and_tangent(Tensor<2, 2>(), P, A);
    const FEValuesExtractors::Vector u(0);
    LAPACKFullMatrix<double>         K(fe.n_dofs_per_cell());
    for (unsigned int q = 0; q < quadrature.size(); ++q)
      for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
        for (unsigned int j = 0; j < fe.n_dofs_per_cell(); ++j)
          K(i, j) += scalar_product(fe_values[u].gradient(i, q),
                                    double_contract<2, 0, 3, 1>(
                                      A, fe_values[u].gradient(j, q))) *
                     fe_values.JxW(q);
    Vector<double>     values;
    FullMatrix<double> vectors;
    K.compute_eigenvalues_symmetric(-1e300, 1e300, 0, values, vectors);
    double largest = 0;
    for (unsigned int i = 0; i < values.size(); ++i)
      largest = std::max(largest, std::abs(values(i)));
    unsigned int zeros = 0;
    for (unsigned int i = 0; i < values.size(); ++i)
      zeros += std::abs(values(i)) < 1e-10 * largest;
    return zeros;
  }

  std::vector<double>
  run_h(const bool reduced)
  {
    std::ostringstream prm;
    prm << "include " << RING_CONTACT_SOURCE_DIR << "/prm/ssnp152h.prm\n"
        << "subsection Finite elements\n set Reduced integration = "
        << (reduced ? "true" : "false") << "\nend\n"
        << "subsection Contact\n set Integration schemes = segment-based "
           "3\nend\n";
    const auto          history = RingContactTests::run_problem("h", prm.str());
    std::vector<double> pressures;
    for (const auto &row : history)
      pressures.push_back(row.value("pressure_A"));
    return pressures;
  }
} // namespace

int
main()
{
  auto              &out     = RingContactTests::deallog_file;
  const unsigned int full    = zero_energy_modes(3);
  const unsigned int reduced = zero_energy_modes(2);
  out << "one 9-node element, 3 x 3 Gauss points: " << full
      << " zero-energy modes (3 rigid-body modes)" << std::endl;
  out << "one 9-node element, 2 x 2 Gauss points: " << reduced
      << " zero-energy modes (" << reduced - 3 << " spurious)" << std::endl;
  check(full == 3, "full integration: only the rigid-body modes");

  const auto p_full    = run_h(false);
  const auto p_reduced = run_h(true);
  double     largest   = 0;
  for (unsigned int k = 0; k < p_full.size(); ++k)
    largest = std::max(largest, std::abs(p_reduced[k] - p_full[k]) / p_full[k]);
  out << "modelisation H, pressure at A, reduced against full integration: "
      << "largest relative difference over the 21 steps below 1e-3: "
      << (largest < 1e-3 ? "yes" : "NO") << std::endl;
  check(largest < 1e-3,
        "reduced integration changes the pressure by " +
          std::to_string(largest));
}
