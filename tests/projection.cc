// Closest-point projection onto the master surface (the outer ring's inner
// circle, r = R2, 40 segments), straight (mapping degree 1: chords) and
// curved (mapping degree 2 and 3: the polar manifold), in the reference
// configuration, against the exact distances: to the chord for straight
// segments, to the circle for curved ones (up to the interpolation error of
// the mapping). Also: the search finds the right segment all around, and a
// point near a vertex is paired with the vertex normal. First, the segments'
// Lagrange basis (values and two derivatives, evaluated as products of
// linear factors) against deal.II's Lagrange polynomials.
#include <deal.II/base/polynomial.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_nothing.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/manifold_lib.h>
#include <deal.II/hp/fe_collection.h>

#include <ring_contact/contact/contact_surface.h>
#include <ring_contact/scenarios/ssnp152/ssnp152.h>

#include "tests.h"

#include <cmath>
#include <iomanip>

using namespace RingContact;
using RingContactTests::check;

int
main()
{
  auto &out = RingContactTests::deallog_file;
  out << std::setprecision(6) << std::fixed;

  // 1 to 5 nodes, equidistant and Gauss-Lobatto-like, at points inside and
  // outside [0, 1] (projections are tried on the segments' extensions).
  for (const std::vector<double> &nodes :
       std::vector<std::vector<double>>{{0.5},
                                        {0, 1},
                                        {0, 0.5, 1},
                                        {0, 0.2763932, 0.7236068, 1},
                                        {0, 0.25, 0.5, 0.75, 1},
                                        {1, 0.3, 0}})
    {
      const LagrangeBasis1D basis(nodes);
      std::vector<Point<1>> points;
      for (const double t : nodes)
        points.emplace_back(t);
      const auto reference =
        Polynomials::generate_complete_Lagrange_basis(points);
      double worst = 0, worst_kronecker = 0;
      for (const double t : {-1.0, -0.3, 0.0, 0.1, 0.37, 0.5, 0.9, 1.0, 2.0})
        {
          double v[LagrangeBasis1D::max_size], d1[LagrangeBasis1D::max_size],
            d2[LagrangeBasis1D::max_size];
          basis.evaluate(t, v, d1, d2);
          std::vector<double> values_only;
          basis.evaluate(t, values_only);
          for (unsigned int i = 0; i < nodes.size(); ++i)
            {
              double r[3];
              reference[i].value(t, 2, r);
              for (const double e : {v[i] - r[0],
                                     d1[i] - r[1],
                                     d2[i] - r[2],
                                     values_only[i] - r[0]})
                worst = std::max(worst, std::abs(e));
            }
        }
      for (unsigned int j = 0; j < nodes.size(); ++j)
        {
          std::vector<double> v;
          basis.evaluate(nodes[j], v);
          for (unsigned int i = 0; i < nodes.size(); ++i)
            worst_kronecker =
              std::max(worst_kronecker, std::abs(v[i] - (i == j ? 1. : 0.)));
        }
      out << "basis of " << nodes.size()
          << " nodes: values and two derivatives as deal.II's to 1e-11: "
          << (worst < 1e-11 ? "yes" : "NO") << ", N_i(t_j) = delta_ij: "
          << (worst_kronecker < 1e-14 ? "yes" : "NO") << std::endl;
      check(worst < 1e-11,
            "basis differs from deal.II's by " + std::to_string(worst));
      check(worst_kronecker < 1e-14, "basis not interpolatory");
    }

  Ssnp152::RingParameters rings;
  rings.elements_around       = 40;
  rings.radial_elements_outer = 3;
  rings.radial_elements_inner = 3;
  rings.outer_radius          = 1.0;
  rings.interface_radius      = 0.6;
  rings.inner_radius          = 0.2;
  Triangulation<2> triangulation;
  Ssnp152::make_rings(triangulation, rings);
  triangulation.set_all_manifold_ids(0);
  triangulation.set_manifold(0, PolarManifold<2>(Point<2>()));

  DoFHandler<2>       dof_handler(triangulation);
  hp::FECollection<2> fe(FESystem<2>(FE_Q<2>(1), 2, FE_Nothing<2>(), 1),
                         FESystem<2>(FE_Q<2>(1), 2, FE_Q<2>(1), 1));
  for (const auto &cell : dof_handler.active_cell_iterators())
    cell->set_active_fe_index(cell->material_id() == Ssnp152::Ids::outer_ring ? 0 : 1);
  dof_handler.distribute_dofs(fe);
  const Vector<double> zero(dof_handler.n_dofs());

  const double R2 = 0.6, h = 2 * numbers::PI / 40;
  for (const unsigned int degree : {1u, 2u, 3u})
    {
      ContactSurface master(dof_handler, Ssnp152::Ids::outer_ring_contact, degree);
      master.update(zero);
      check(master.segments().size() == 40, "40 master segments");
      double       worst_gap = 0, worst_t = 0;
      unsigned int wrong_segment = 0;
      for (unsigned int k = 0; k < 400; ++k)
        {
          // Points between r = 0.45 and 0.6, all around, in the middle
          // 80 % of a segment's angle.
          const unsigned int j  = k / 10;
          const double       a0 = j * h, a1 = (j + 1) * h;
          const double       phi = a0 + (0.1 + 0.8 * (k % 10) / 9.0) * h;
          const double       r   = 0.45 + 0.15 * ((k * 7) % 11) / 10.0;
          const Point<2>     x(r * std::cos(phi), r * std::sin(phi));
          const Projection   p  = master.project(x);
          const Point<2>     xm = master.current_point(p.segment, p.t).x;
          // The foot of the projection lies on the segment between a0, a1.
          const double foot = std::atan2(xm[1], xm[0]) < -1e-12 ?
                                std::atan2(xm[1], xm[0]) + 2 * numbers::PI :
                                std::atan2(xm[1], xm[0]);
          if (p.at_vertex || p.clamped || foot < a0 - 1e-12 ||
              foot > a1 + 1e-12)
            ++wrong_segment;
          // The master's outward normal points to the centre: the gap of a
          // point inside the circle is positive. Straight: distance to the
          // chord; curved: to the circle, along the radius.
          const double mid = 0.5 * (a0 + a1);
          const double exact_gap =
            degree == 1 ? R2 * std::cos(h / 2) - r * std::cos(phi - mid) :
                          R2 - r;
          const double exact_foot = degree == 1 ?
                                      mid + std::atan(r * std::sin(phi - mid) /
                                                      (R2 * std::cos(h / 2))) :
                                      phi;
          worst_gap = std::max(worst_gap, std::abs(p.gap - exact_gap));
          worst_t   = std::max(worst_t, std::abs(foot - exact_foot) / h);
        }
      // Interpolation error of a degree-m curve through Gauss-Lobatto
      // points on the circle: about R (h/2)^(m+1) / (m+1)!.
      const double tolerance = degree == 1 ? 1e-12 : degree == 2 ? 2e-5 : 5e-7;
      out << "mapping degree " << degree
          << ": segments found right: " << (wrong_segment == 0 ? "all" : "NO")
          << ", gap error below " << std::scientific << std::setprecision(0)
          << tolerance << std::fixed << std::setprecision(6) << ": "
          << (worst_gap < tolerance ? "yes" : "NO")
          << ", foot of the projection right: "
          << (worst_t < (degree == 1 ? 1e-12 : 1e-3) ? "yes" : "NO")
          << std::endl;
      check(wrong_segment == 0, "search finds the right segment");
      check(worst_gap < tolerance, "gap error " + std::to_string(worst_gap));
      check(worst_t < (degree == 1 ? 1e-12 : 1e-3),
            "foot of the projection off by " + std::to_string(worst_t) +
              " segments");

      // A point that penetrates the master at a vertex, on its bisector:
      // paired with the vertex, whose normal is radial (the average of the
      // two segments' normals), gap -0.01.
      const Point<2>     near(0.61 * std::cos(3 * h), 0.61 * std::sin(3 * h));
      const Projection   p = master.project(near);
      const Tensor<1, 2> n = master.normal(p);
      out << "  point beyond a vertex on its bisector: gap " << p.gap
          << ", normal . e_r = " << n * near / near.norm() << std::endl;
      // On the faceted surface the point is in the corner's normal cone:
      // only the vertex is closest. On curved surfaces the tangent at the
      // vertex is continuous up to the interpolation error.
      const double curved = degree == 1 ? 1e-12 : 1e-6;
      check(p.at_vertex || degree > 1, "vertex pairing on a faceted surface");
      check(std::abs(p.gap + 0.01) < curved, "gap at the vertex");
      check(std::abs(n * near / near.norm() + 1) < curved, "radial normal");
    }
}
