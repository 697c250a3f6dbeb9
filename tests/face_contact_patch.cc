// The contact patch test in 3D (contact/face_contact.h) under its three
// schemes, and the exactness of their tangents:
// - two blocks of different materials, [0,1]^2 x [-1,0] (E1, nu1, 3 x 3 x 2
//   hexahedra, the master) under [0,1]^2 x [g0, 1 + g0] (E2, nu2, 5 x 4 x 2,
//   the slave), each mesh's inner columns moved in the plane by a
//   different smooth field so that no slave face matches a master face;
//   the bottom held in z, the symmetry planes x = 0 and y = 0, the top
//   moved down by d. The gap g0 closes and the blocks are in uniaxial
//   stress with the pressure p = (d - g0) / (h1 / E1 + h2 / E2), the
//   displacement linear in each block. Q1 represents it exactly, and the
//   clipped integration transfers the uniform pressure whole between
//   non-matching faces (exactly between parallelograms, to its rule's
//   round-off on these distorted faces), so every multiplier is p, the
//   support's reaction p A, every displacement the closed form's, to 1e-8
//   of p and of d; again with the blocks 100 out from the origin;
// - the nodal and Gauss 2 x 2 schemes on matching meshes (the upper block
//   meshed and moved as the lower one), exact as well; on the non-matching
//   ones their multipliers swing about p, by the measure the output says;
// - in finite strain (clip, points and normal of the current
//   configuration), the assembled contact rows' derivatives at a generic
//   state (displaced, with open and closed nodes) equal central
//   differences of the assembled residual;
// - the same with quadratic hexahedra (Q2, biquadratic faces of nine nodes
//   clipped as four bilinear quarters, the pressure bilinear on the
//   vertices): the segment-based patch test on the non-matching meshes and
//   Gauss 2 x 2 on the matching ones exact, every node's displacement the
//   closed form's; the tangents exact in finite strain (on coarser
//   blocks, 2 x 2 under 3 x 2 hexahedra);
// - a third-order surface, a quadratic pressure, the nodal scheme on
//   quadratic faces and a slave body without the pressure field are
//   refused with their messages.
#include <deal.II/base/function.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_nothing.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>
#include <deal.II/hp/fe_collection.h>
#include <deal.II/hp/fe_values.h>
#include <deal.II/hp/q_collection.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/numerics/vector_tools.h>

#include <ring_contact/contact/active_set.h>
#include <ring_contact/contact/face_contact.h>
#include <ring_contact/contact/multiplier_nodes.h>

#include "tests.h"

#include <cmath>
#include <iomanip>
#include <map>
#include <string>
#include <vector>

using namespace dealii;
using RingContact::ActiveSet;
using RingContact::FaceContact;
using RingContact::MultiplierNodes;
using RingContactTests::check;

namespace
{
  constexpr double g0 = 1e-3, d = 0.01;
  // The bodies by material id: 0 the master (lower), 1 the slave.
  constexpr double E[2] = {200., 70.}, nu[2] = {0.3, 0.2};
  const double     p = (d - g0) / (1. / E[0] + 1. / E[1]);

  // The two blocks, their inner columns moved in the plane, and their
  // boundary tags: 1 bottom, 2 master, 3 slave, 4 top, 5 x = 0, 6 y = 0.
  // `matching`: the upper block meshed and moved as the lower one, so that
  // the faces of the two surfaces coincide.
  // `coarse`: 2 x 2 x 2 under 3 x 2 x 2 hexahedra (the quadratic
  // tangent's test, whose differences take every unknown).
  void
  make_blocks(Triangulation<3> &blocks,
              const bool        matching = false,
              const double      offset   = 0,
              const bool        coarse   = false)
  {
    Triangulation<3> lower, upper;
    GridGenerator::subdivided_hyper_rectangle(
      lower,
      coarse ? std::vector<unsigned int>{2, 2, 2} :
               std::vector<unsigned int>{3, 3, 2},
      Point<3>(0, 0, -1),
      Point<3>(1, 1, 0));
    GridGenerator::subdivided_hyper_rectangle(
      upper,
      matching ? std::vector<unsigned int>{3, 3, 2} :
      coarse   ? std::vector<unsigned int>{3, 2, 2} :
                 std::vector<unsigned int>{5, 4, 2},
      Point<3>(0, 0, g0),
      Point<3>(1, 1, 1 + g0));
    const auto inner = [](const Point<3> &x) {
      return x[0] > 1e-12 && x[0] < 1 - 1e-12 && x[1] > 1e-12 &&
             x[1] < 1 - 1e-12;
    };
    const auto lower_field = [&](const Point<3> &x) {
      return inner(x) ? Point<3>(x[0] + 0.08 * std::sin(7 * x[1] + 1),
                                 x[1] + 0.07 * std::cos(5 * x[0]),
                                 x[2]) :
                        x;
    };
    const auto upper_field = [&](const Point<3> &x) {
      return inner(x) ? Point<3>(x[0] + 0.05 * std::cos(6 * x[1]),
                                 x[1] + 0.06 * std::sin(4 * x[0] + 2),
                                 x[2]) :
                        x;
    };
    GridTools::transform(lower_field, lower);
    if (matching)
      GridTools::transform(lower_field, upper);
    else
      GridTools::transform(upper_field, upper);
    for (const auto &cell : upper.active_cell_iterators())
      cell->set_material_id(1);
    GridGenerator::merge_triangulations(lower, upper, blocks);
    GridTools::shift(Tensor<1, 3>({offset, offset, 0.}), blocks);
    for (const auto &cell : blocks.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary())
          {
            const Point<3> c = face->center();
            if (std::abs(c[2] + 1) < 1e-12)
              face->set_boundary_id(1);
            else if (std::abs(c[2]) < 1e-12)
              face->set_boundary_id(2);
            else if (std::abs(c[2] - g0) < 1e-12)
              face->set_boundary_id(3);
            else if (std::abs(c[2] - 1 - g0) < 1e-12)
              face->set_boundary_id(4);
            else if (std::abs(c[0] - offset) < 1e-12)
              face->set_boundary_id(5);
            else if (std::abs(c[1] - offset) < 1e-12)
              face->set_boundary_id(6);
            else
              face->set_boundary_id(0);
          }
  }

  // Displacement (Q1, three components) on both blocks, the pressure on
  // the slave block (FE_Nothing on the master).
  hp::FECollection<3>
  elements(const unsigned int degree)
  {
    hp::FECollection<3> fe;
    fe.push_back(FESystem<3>(FE_Q<3>(degree), 3, FE_Nothing<3>(), 1));
    fe.push_back(FESystem<3>(FE_Q<3>(degree), 3, FE_Q<3>(1), 1));
    return fe;
  }

  void
  distribute(DoFHandler<3> &dofs, const hp::FECollection<3> &fe)
  {
    for (const auto &cell : dofs.active_cell_iterators())
      cell->set_active_fe_index(cell->material_id());
    dofs.distribute_dofs(fe);
  }

  // The homogeneous constraints of a Newton update: the held components,
  // and the pressure zero off the slave surface.
  void
  make_constraints(const DoFHandler<3>       &dofs,
                   const FaceContact         &contact,
                   AffineConstraints<double> &constraints)
  {
    constraints.clear();
    const Functions::ZeroFunction<3>             zero(4);
    const std::map<types::boundary_id, unsigned> held = {{1, 2},
                                                         {4, 2},
                                                         {5, 0},
                                                         {6, 1}};
    for (const auto &[tag, component] : held)
      {
        ComponentMask mask(4, false);
        mask.set(component, true);
        VectorTools::interpolate_boundary_values(
          dofs, tag, zero, constraints, mask);
      }
    std::set<types::global_dof_index> on_slave;
    for (unsigned int k = 0; k < contact.n_nodes(); ++k)
      on_slave.insert(contact.multiplier_dof(k));
    ComponentMask pressure(4, false);
    pressure.set(3, true);
    for (const auto dof : DoFTools::extract_dofs(dofs, pressure))
      if (on_slave.count(dof) == 0)
        constraints.add_line(dof);
    constraints.close();
  }

  // The linear elastic bulk: K u into the matrix (if given), -K u into
  // the rhs.
  void
  assemble_bulk(const DoFHandler<3>             &dofs,
                const AffineConstraints<double> &constraints,
                const Vector<double>            &u,
                SparseMatrix<double>            *matrix,
                Vector<double>                  &rhs)
  {
    const unsigned int               p_u = dofs.get_fe(0).degree;
    const hp::QCollection<3>         q(QGauss<3>(p_u + 1), QGauss<3>(p_u + 1));
    hp::FEValues<3>                  hp_values(dofs.get_fe_collection(),
                              q,
                              update_gradients | update_JxW_values);
    const FEValuesExtractors::Vector displacement(0);
    std::vector<types::global_dof_index> local;
    for (const auto &cell : dofs.active_cell_iterators())
      {
        hp_values.reinit(cell);
        const FEValues<3> &v  = hp_values.get_present_fe_values();
        const unsigned int n  = cell->get_fe().n_dofs_per_cell();
        const unsigned int b  = cell->material_id();
        const double       mu = E[b] / (2 * (1 + nu[b]));
        const double lambda   = E[b] * nu[b] / ((1 + nu[b]) * (1 - 2 * nu[b]));
        FullMatrix<double> k(n, n);
        for (unsigned int q = 0; q < v.n_quadrature_points; ++q)
          for (unsigned int i = 0; i < n; ++i)
            for (unsigned int j = 0; j < n; ++j)
              k(i, j) +=
                (lambda * v[displacement].divergence(i, q) *
                   v[displacement].divergence(j, q) +
                 2 * mu *
                   scalar_product(v[displacement].symmetric_gradient(i, q),
                                  v[displacement].symmetric_gradient(j, q))) *
                v.JxW(q);
        local.resize(n);
        cell->get_dof_indices(local);
        Vector<double> ue(n), r(n);
        for (unsigned int i = 0; i < n; ++i)
          ue(i) = u(local[i]);
        k.vmult(r, ue);
        r *= -1.;
        if (matrix != nullptr)
          constraints.distribute_local_to_global(k, r, local, *matrix, rhs);
        else
          constraints.distribute_local_to_global(r, local, rhs);
      }
  }
} // namespace


// The larger of two errors, NaN if either is (std::max would drop a NaN
// that comes second).
double
worse(const double a, const double b)
{
  return std::isnan(a) || std::isnan(b) ? std::nan("") : std::max(a, b);
}


// The patch test: the semi-smooth Newton iteration from the top's motion,
// then the multipliers and the displacements against the closed form.
using Scheme = FaceContact::Scheme;

// The faces of a pair with the program's active set (ActiveSet, chosen
// from the faces' weighted gaps) and the open nodes' rows w_k lambda_k:
// what ContactInterface<3> adds to FaceContact, here on a SparseMatrix.
struct Pair
{
  Pair(const DoFHandler<3> &dofs, const bool linear, const Scheme scheme)
      : faces(dofs, 3, 2, c, linear, scheme)
      , nodes(faces.multiplier_nodes())
      , states(nodes, c, 0., 0.2)
  {}

  unsigned int
  update(const Vector<double> &u)
  {
    faces.pair(u);
    return states.choose_closed_nodes(u,
                                      faces.weighted_gaps(),
                                      faces.covered(),
                                      true);
  }

  /// The rows at u; without `derivatives` the matrix gets the open nodes'
  /// entries alone (what a residual needs is the right-hand side).
  void
  assemble(const Vector<double>            &u,
           const AffineConstraints<double> &constraints,
           SparseMatrix<double>            &matrix,
           Vector<double>                  &rhs,
           const bool                       derivatives = true) const
  {
    std::vector<bool> closed(nodes.size());
    for (unsigned int k = 0; k < nodes.size(); ++k)
      closed[k] = states.is_closed(k);
    faces.assemble(u,
                   closed,
                   derivatives,
                   0,
                   1,
                   [&](const FullMatrix<double>                   &m,
                       const Vector<double>                       &r,
                       const std::vector<types::global_dof_index> &d) {
                     if (derivatives)
                       constraints.distribute_local_to_global(
                         m, r, d, matrix, rhs);
                     else
                       constraints.distribute_local_to_global(r, d, rhs);
                   });
    for (unsigned int k = 0; k < nodes.size(); ++k)
      if (!closed[k])
        {
          FullMatrix<double> w(1, 1);
          Vector<double>     r(1);
          w(0, 0) = nodes.reference_weight[k];
          r(0)    = -nodes.reference_weight[k] * u(nodes.dofs[k]);
          constraints.distribute_local_to_global(
            w,
            r,
            std::vector<types::global_dof_index>{nodes.dofs[k]},
            matrix,
            rhs);
        }
  }

  /// c = E / h with the slave faces' size.
  static constexpr double c = E[1] / 0.2;
  FaceContact             faces;
  const MultiplierNodes   nodes;
  ActiveSet               states;
};

std::string
name(const Scheme scheme)
{
  return scheme == Scheme::segment_based ? "segment-based" :
         scheme == Scheme::nodal         ? "nodal" :
                                           "Gauss 2 x 2";
}


// The patch test under `scheme`: exact where the scheme passes it (the
// segment-based on any meshes, the point-wise on matching ones); elsewhere
// the point-wise schemes' multipliers swing about p, by the measure said.
void
patch_test(std::ostream      &out,
           const Scheme       scheme,
           const bool         matching,
           const double       offset = 0,
           const unsigned int degree = 1)
{
  Triangulation<3> blocks;
  make_blocks(blocks, matching, offset);
  const hp::FECollection<3> fe = elements(degree);
  DoFHandler<3>             dofs(blocks);
  distribute(dofs, fe);
  Pair                      contact(dofs, true, scheme);
  AffineConstraints<double> constraints;
  make_constraints(dofs, contact.faces, constraints);

  Vector<double>                            u(dofs.n_dofs());
  std::map<types::global_dof_index, double> top;
  ComponentMask                             z(4, false);
  z.set(2, true);
  VectorTools::interpolate_boundary_values(
    dofs, 4, Functions::ConstantFunction<3>(-d, 4), top, z);
  for (const auto &[dof, value] : top)
    u(dof) = value;

  contact.update(u);
  DynamicSparsityPattern pattern(dofs.n_dofs());
  DoFTools::make_sparsity_pattern(dofs, pattern, constraints, false);
  contact.faces.add_couplings(pattern, constraints);
  SparsityPattern sparsity;
  sparsity.copy_from(pattern);
  SparseMatrix<double> matrix(sparsity);
  unsigned int         iterations = 0, changes = 1;
  while (changes > 0 && iterations < 20)
    {
      matrix = 0;
      Vector<double> rhs(dofs.n_dofs());
      assemble_bulk(dofs, constraints, u, &matrix, rhs);
      contact.assemble(u, constraints, matrix, rhs);
      SparseDirectUMFPACK solver;
      solver.initialize(matrix);
      solver.solve(rhs);
      constraints.distribute(rhs);
      u += rhs;
      ++iterations;
      changes = contact.update(u);
    }
  check(changes == 0, "the active set settles");

  double       worst_pressure = 0;
  unsigned int n_active       = 0;
  for (unsigned int k = 0; k < contact.nodes.size(); ++k)
    {
      const double lambda = u(contact.nodes.dofs[k]);
      worst_pressure      = worse(worst_pressure, std::abs(lambda - p));
      n_active += contact.states.is_closed(k);
    }
  check(n_active == contact.nodes.size(), "every slave node is closed");
  const std::string case_name =
    name(scheme) + ", " + (matching ? "matching" : "non-matching") + " meshes" +
    (offset != 0 ? ", 100 out from the origin" : "") +
    (degree == 2 ? ", Q2 (biquadratic faces)" : "");
  if (scheme != Scheme::segment_based && !matching)
    {
      // The node-to-segment limit, measured: the swing is real.
      check(worst_pressure > 1e-3 * p, "the point-wise swing is seen");
      out << "patch test, " << case_name
          << ": the multipliers depart from p by up to " << std::setprecision(2)
          << 100 * worst_pressure / p << std::setprecision(10)
          << " % (the point-wise schemes do not pass the patch test there)"
          << std::endl;
      return;
    }
  check(worst_pressure < 1e-8 * p, "every multiplier is p");
  // The support's reaction, from the bulk alone: the bottom's nodal forces
  // K u in z sum to the force p A the contact carries.
  Vector<double> bulk(dofs.n_dofs());
  {
    AffineConstraints<double> none;
    none.close();
    assemble_bulk(dofs, none, u, nullptr, bulk);
  }
  std::map<types::global_dof_index, double> bottom;
  VectorTools::interpolate_boundary_values(
    dofs, 1, Functions::ZeroFunction<3>(4), bottom, z);
  double reaction = 0;
  for (const auto &entry : bottom)
    reaction -= bulk(entry.first); // the support's force, -K u
  check(std::abs(reaction - p) < 1e-8 * p, "the support carries p A");

  // Every node's displacement against the closed form (the support
  // points of the displacement's base element, on the cells' trilinear
  // geometry).
  double                               worst_u = 0;
  const Mapping<3>                    &linear  = StaticMappingQ1<3>::mapping;
  std::vector<types::global_dof_index> local;
  for (const auto &cell : dofs.active_cell_iterators())
    {
      const FiniteElement<3> &cell_fe = cell->get_fe();
      local.resize(cell_fe.n_dofs_per_cell());
      cell->get_dof_indices(local);
      for (unsigned int i = 0; i < cell_fe.n_dofs_per_cell(); ++i)
        {
          const auto [c, base_index] = cell_fe.system_to_component_index(i);
          if (c > 2)
            continue;
          const Point<3> x =
            linear.transform_unit_to_real_cell(cell,
                                               cell_fe.unit_support_point(i));
          const unsigned int b        = cell->material_id();
          const double       lateral  = nu[b] * p / E[b];
          const double       exact[3] = {lateral * (x[0] - offset),
                                         lateral * (x[1] - offset),
                                   b == 0 ? -p * (x[2] + 1) / E[0] :
                                                  -d + p * (1 + g0 - x[2]) / E[1]};
          worst_u = worse(worst_u, std::abs(u(local[i]) - exact[c]));
        }
    }
  check(worst_u < 1e-8 * d, "the displacement is the closed form's");
  out << "patch test, " << case_name << ", "
      << contact.faces.slave_faces().size() << " slave faces against "
      << contact.faces.master_faces().size() << " master faces, "
      << contact.faces.pairs().size() << " pairs, " << contact.faces.n_nodes()
      << " contact nodes, " << dofs.n_dofs()
      << " unknowns: the active set settled after " << iterations << " solves"
      << std::endl
      << "every multiplier is p = (d - g0) / (h1/E1 + h2/E2) = " << p
      << " to 1e-8, the support's reaction p A to 1e-8, every displacement the "
         "closed form's to 1e-8 d"
      << std::endl;
}


// A smooth, deterministic scatter in [-1, 1].
double
scatter(const unsigned int i)
{
  return std::sin(12.9898 * i + 78.233 * std::sin(0.5 * i));
}


// Finite strain: the assembled rows' derivatives against central
// differences of the assembled residual, the pairs and the active set
// held (those of the state).
void
tangent_test(std::ostream      &out,
             const Scheme       scheme,
             const unsigned int degree = 1)
{
  // Quadratic faces on the coarse blocks: the differences take every
  // unknown, and a pair of biquadratic faces is 16 clips.
  Triangulation<3> blocks;
  make_blocks(blocks, false, 0, degree == 2);
  const hp::FECollection<3> fe = elements(degree);
  DoFHandler<3>             dofs(blocks);
  distribute(dofs, fe);
  Pair contact(dofs, false, scheme);

  std::set<types::global_dof_index> unknowns;
  for (const auto *faces :
       {&contact.faces.slave_faces(), &contact.faces.master_faces()})
    for (const auto &face : *faces)
      for (const auto &node : face.support_dofs)
        unknowns.insert(node.begin(), node.end());
  Vector<double> state(dofs.n_dofs());
  for (const auto i : unknowns)
    state(i) = 4e-3 * scatter(i);
  for (unsigned int k = 0; k < contact.nodes.size(); ++k)
    {
      unknowns.insert(contact.nodes.dofs[k]);
      state(contact.nodes.dofs[k]) = p * (0.5 + scatter(1000 + k));
    }
  contact.update(state);
  unsigned int n_active = 0;
  for (unsigned int k = 0; k < contact.nodes.size(); ++k)
    n_active += contact.states.is_closed(k);
  check(n_active > 0 && n_active < contact.nodes.size(),
        "the state has open and closed nodes");

  AffineConstraints<double> none;
  none.close();
  DynamicSparsityPattern pattern(dofs.n_dofs());
  contact.faces.add_couplings(pattern, none);
  SparsityPattern sparsity;
  sparsity.copy_from(pattern);
  SparseMatrix<double> matrix(sparsity), scratch(sparsity);
  Vector<double>       rhs(dofs.n_dofs());
  contact.assemble(state, none, matrix, rhs);
  const double scale = matrix.linfty_norm();

  const double h     = 1e-6;
  double       worst = 0;
  for (const auto j : unknowns)
    {
      Vector<double> plus(dofs.n_dofs()), minus(dofs.n_dofs());
      Vector<double> shifted(state);
      shifted(j) += h;
      contact.assemble(shifted, none, scratch, plus, false);
      shifted(j) -= 2 * h;
      contact.assemble(shifted, none, scratch, minus, false);
      for (const auto i : unknowns)
        worst =
          worse(worst,
                std::abs((minus(i) - plus(i)) / (2 * h) - matrix.el(i, j)));
    }
  check(worst < 1e-8 * scale, "the contact tangent is exact");
  out << "finite strain, " << name(scheme)
      << (degree == 2 ? ", Q2 (biquadratic faces)" : "")
      << ", a displaced state with " << n_active << " of "
      << contact.nodes.size()
      << " nodes closed: the derivatives of the contact rows in "
      << unknowns.size()
      << " unknowns equal central differences to 1e-8 of the largest entry"
      << std::endl;
}


// What the surfaces refuse.
void
refusals(std::ostream &out)
{
  Triangulation<3> blocks;
  make_blocks(blocks);
  const auto refused = [&](const hp::FECollection<3> &fe,
                           const types::boundary_id   slave,
                           const Scheme scheme = Scheme::segment_based) {
    DoFHandler<3> dofs(blocks);
    distribute(dofs, fe);
    try
      {
        FaceContact(dofs, slave, 2, 1., true, scheme);
      }
    catch (const std::exception &e)
      {
        out << "refused: " << e.what() << std::endl;
        return;
      }
    check(false, "the surface is refused");
  };
  refused(elements(3), 3);
  hp::FECollection<3> quadratic_pressure;
  quadratic_pressure.push_back(FESystem<3>(FE_Q<3>(2), 3, FE_Nothing<3>(), 1));
  quadratic_pressure.push_back(FESystem<3>(FE_Q<3>(2), 3, FE_Q<3>(2), 1));
  refused(quadratic_pressure, 3);
  refused(elements(2), 3, Scheme::nodal);
  hp::FECollection<3> bare;
  for (unsigned int b = 0; b < 2; ++b)
    bare.push_back(FESystem<3>(FE_Q<3>(1), 3, FE_Nothing<3>(), 1));
  refused(bare, 3);
  refused(elements(1), 9);
}


int
main()
{
  auto &out = RingContactTests::deallog_file;
  out << std::setprecision(10);
  for (const auto scheme :
       {Scheme::segment_based, Scheme::nodal, Scheme::gauss})
    patch_test(out, scheme, scheme != Scheme::segment_based);
  for (const auto scheme : {Scheme::nodal, Scheme::gauss})
    patch_test(out, scheme, false);
  // Far from the origin (faces 400 of their sizes out), where the
  // projections' round-off is that of the coordinates.
  patch_test(out, Scheme::segment_based, false, 100);
  patch_test(out, Scheme::nodal, true, 100);
  for (const auto scheme :
       {Scheme::segment_based, Scheme::nodal, Scheme::gauss})
    tangent_test(out, scheme);
  // Quadratic hexahedra.
  patch_test(out, Scheme::segment_based, false, 0, 2);
  patch_test(out, Scheme::gauss, true, 0, 2);
  patch_test(out, Scheme::gauss, false, 0, 2);
  patch_test(out, Scheme::segment_based, false, 100, 2);
  for (const auto scheme : {Scheme::segment_based, Scheme::gauss})
    tangent_test(out, scheme, 2);
  refusals(out);
}
