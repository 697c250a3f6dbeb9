// The consistent tangent against central finite differences of the
// residual: first the material law (dP/dH for Saint Venant-Kirchhoff in
// plane stress and plane strain, and linear elasticity), then the whole
// Newton system of the two rings (bulk and contact, with the projection of
// the slave points onto a master surface that has slid by a third of an
// element, or with the slave nodes on the master vertices; nodal and Gauss
// integration, faceted and curved), and with Coulomb friction (every node
// sticking, or every node sliding, against the reference configuration as
// the last converged state).
#include <deal.II/base/function.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/numerics/vector_tools.h>

#include <ring_contact/base/components.h>
#include <ring_contact/materials/material.h>
#include <ring_contact/problem/inspector.h>
#include <ring_contact/scenarios/ssnp152/analytic_solution.h>
#include <ring_contact/scenarios/ssnp152/ssnp152.h>

#include "tests.h"

#include <cmath>
#include <iomanip>
#include <set>

using namespace RingContact;
using RingContactTests::check;

namespace
{
  std::string
  kinematics_name(const std::string &kinematics)
  {
    return kinematics == "finite strain" ? "finite strain" :
           kinematics == "small strain"  ? "small strain" :
                                           "logarithmic strain";
  }

  void
  check_material(const PlaneAssumption plane,
                 const std::string    &kinematics,
                 const std::string    &name)
  {
    const Material<2> material(1e9, 0.3, plane, kinematics);
    Tensor<2, 2>      H;
    H[0][0] = 0.03;
    H[0][1] = -0.2;
    H[1][0] = 0.15;
    H[1][1] = -0.05;
    Tensor<2, 2> P;
    Tensor<4, 2> A;
    material.stress_and_tangent(H, P, A);
    check((P - material.stress(H)).norm() < 1e-12 * P.norm(),
          name + ": stress() and stress_and_tangent() agree");
    // The major symmetry, on which the assembly relies.
    double asymmetry = 0;
    for (unsigned int i = 0; i < 2; ++i)
      for (unsigned int J = 0; J < 2; ++J)
        for (unsigned int k = 0; k < 2; ++k)
          for (unsigned int L = 0; L < 2; ++L)
            asymmetry =
              std::max(asymmetry, std::abs(A[i][J][k][L] - A[k][L][i][J]));
    check(asymmetry <= 1e-12 * A.norm(),
          name + ": the tangent has the major symmetry A_iJkL = A_kLiJ");
    double       worst = 0;
    const double h     = 1e-6;
    for (unsigned int k = 0; k < 2; ++k)
      for (unsigned int L = 0; L < 2; ++L)
        {
          Tensor<2, 2> Hp = H, Hm = H;
          Hp[k][L] += h;
          Hm[k][L] -= h;
          const Tensor<2, 2> fd =
            (material.stress(Hp) - material.stress(Hm)) / (2 * h);
          for (unsigned int i = 0; i < 2; ++i)
            for (unsigned int J = 0; J < 2; ++J)
              worst = std::max(worst, std::abs(fd[i][J] - A[i][J][k][L]));
        }
    const double relative = worst / A.norm();
    RingContactTests::deallog_file
      << name << ": tangent matches finite differences: "
      << (relative < 1e-7 ? "yes" : "NO") << std::endl;
    check(relative < 1e-7, name + " material tangent");
  }

  // The analytic displacement, turned through an angle on the inner ring,
  // plus a smooth perturbation; the analytic pressure as multiplier, and a
  // tenth of it as tangential traction.
  class State : public Function<2>
  {
  public:
    State(const AnalyticSolution &analytic, const double p, const double angle)
        : Function<2>(Components::n_components<dim>)
        , analytic(analytic)
        , p(p)
        , angle(angle)
    {}

    double
    value(const Point<2> &X, const unsigned int component) const override
    {
      if (component == Components::multiplier<dim>)
        return analytic.contact_pressure(p);
      if (component == Components::tangential<dim>)
        return -0.1 * analytic.contact_pressure(p);
      const double r     = X.norm();
      const double theta = std::atan2(X[1], X[0]);
      // Turn the inner ring rigidly (more near R3, less at R2).
      const double turn =
        r < 0.6 - 1e-9 ? angle * (0.6 - r) / 0.4 + 0.3 * angle : 0.0;
      const double radius =
        r + analytic.radial_displacement(r, p) + 1e-4 * std::sin(3 * theta) * r;
      const Point<2> x(radius * std::cos(theta + turn),
                       radius * std::sin(theta + turn));
      return x[component] - X[component];
    }

  private:
    const AnalyticSolution &analytic;
    const double            p, angle;
  };

  void
  check_system(const std::string &scheme,
               const unsigned int mapping_degree,
               const std::string &kinematics,
               const bool         vertex          = false,
               const bool         smooth          = false,
               const bool         pressure_loaded = false,
               const double       friction        = 0)
  {
    Parameters parameters;
    {
      std::ofstream prm("tangent.prm");
      prm << "subsection Contact\n set Integration schemes = " << scheme
          << "\nend\nsubsection Finite elements\n set Mapping degree = "
          << mapping_degree << "\nend\nsubsection Contact\n"
          << " set Smooth master normals = " << (smooth ? "true" : "false")
          << "\n set Friction coefficient = " << friction
          << "\nend\nsubsection Materials\n"
          << " set Material law = " << kinematics_name(kinematics)
          << "\nend\nsubsection Output\n set Print timing = false\n"
          << " set VTU interval = 0\nend\nsubsection Mesh\n"
          << " set Elements around = 12\n set Radial elements outer ring = 2\n"
          << " set Radial elements inner ring = 2\nend\n";
      if (pressure_loaded)
        prm << "subsection Load program\n set Loading = pressure\nend\n";
    }
    parameters.read("tangent.prm");
    std::ostringstream      log;
    ContactProblem<dim>     contact_problem(parameters,
                                        parameters.contact.schemes.front(),
                                        log);
    ContactProblemInspector problem(contact_problem);
    problem.setup();
    problem.set_load_state({0, {{"pressure", 1e7}, {"rotation", 0}}});

    // A third of an element of sliding: slave points project inside master
    // segments, away from vertices (where the pairing is not smooth).
    const AnalyticSolution analytic(
      parameters.scenario_entries<Ssnp152::RingParameters>(),
      parameters.materials.plane);
    const double    angle = 2 * numbers::PI / 12 / 3;
    const double    slide = vertex ? 0.0 : angle;
    Vector<double> &u     = problem.current_solution();
    VectorTools::interpolate(problem.get_mapping(),
                             problem.get_dof_handler(),
                             State(analytic, 1e7, angle),
                             u);
    problem.newton_constraints().distribute(u);
    // Turn the slave surface nodes by a third of an element, so that the
    // meshes no longer match.
    {
      const auto &slave = problem.contact_interface().slave_surface();
      std::set<types::global_dof_index> moved;
      for (unsigned int s = 0; s < slave.segments().size(); ++s)
        {
          const auto &segment = slave.segments()[s];
          for (unsigned int i = 0; i < segment.dofs_x.size(); ++i)
            {
              if (!moved.insert(segment.dofs_x[i]).second)
                continue;
              const double   t = i == 0 ? 0.0 : i == 1 ? 1.0 : 0.5;
              const Point<2> X = slave.reference_point(s, t).x;
              const Point<2> x(X[0] + u(segment.dofs_x[i]),
                               X[1] + u(segment.dofs_y[i]));
              const double   c = std::cos(slide), sn = std::sin(slide);
              u(segment.dofs_x[i]) += c * x[0] - sn * x[1] - x[0];
              u(segment.dofs_y[i]) += sn * x[0] + c * x[1] - x[1];
            }
        }
    }
    // The states settle first: at finite strain a sliding node whose trial
    // turns past the opposite bound sticks for one update before it slides
    // the other way (ActiveSet::choose_friction_states()), so that a second
    // update at the same iterate may change them; the checks below assemble
    // at this iterate again and expect its states.
    bool settled = false;
    for (unsigned int i = 0; i < 3 && !settled; ++i)
      settled = problem.assemble_newton_system() == 0;
    check(settled, "the contact states settle at the iterate");
    const auto           &Kref        = problem.tangent_matrix();
    const Vector<double>  rhs0        = problem.residual_rhs();
    const auto           &constraints = problem.newton_constraints();
    const ResidualMeasure measure0    = problem.residual_measure();

    // The residual alone (what a convergence test assembles): the same
    // right-hand side on the free rows, up to round-off, and the same
    // measures but the force floor, which needs the tangent.
    {
      problem.assemble_newton_system(Pairing::search,
                                     ContactProblem<dim>::Assembly::residual);
      const ResidualMeasure measure = problem.residual_measure();
      double                largest = 0, difference = 0;
      for (types::global_dof_index i = 0; i < u.size(); ++i)
        if (!constraints.is_constrained(i))
          {
            largest = std::max(largest, std::abs(rhs0(i)));
            difference =
              std::max(difference,
                       std::abs(problem.residual_rhs()(i) - rhs0(i)));
          }
      const auto close = [](const double a, const double b) {
        return std::abs(a - b) <= 1e-12 * std::abs(b);
      };
      check(difference <= 1e-13 * largest && !measure.force_floor_known &&
              measure0.force_floor_known && measure.force_floor == 0 &&
              close(measure.force, measure0.force) &&
              close(measure.merit, measure0.merit) &&
              close(measure.gap, measure0.gap) &&
              measure.gap_floor == measure0.gap_floor,
            "the residual assembled without the tangent is the same (largest "
            "difference " +
              std::to_string(difference / largest) + " of the largest entry)");
      if (std::getenv("TANGENT_DEBUG"))
        std::cerr << "residual alone: " << difference / largest << std::endl;
      problem.assemble_newton_system();
    }

    // Columns: every unconstrained dof of the contact surfaces and a few
    // bulk ones.
    std::vector<types::global_dof_index> columns;
    const auto                          &contact = problem.contact_interface();
    for (const auto *surface :
         {&contact.slave_surface(), &contact.master_surface()})
      for (const auto &segment : surface->segments())
        for (const auto *list : {&segment.dofs_x,
                                 &segment.dofs_y,
                                 &segment.multiplier_dofs,
                                 &segment.tangential_dofs})
          columns.insert(columns.end(), list->begin(), list->end());
    for (types::global_dof_index i = 0; i < u.size(); i += 37)
      columns.push_back(i);
    // Those of r = R1, where the pressure acts.
    if (pressure_loaded)
      for (const auto i : DoFTools::extract_boundary_dofs(
             problem.get_dof_handler(),
             Components::displacement_mask<dim>(),
             {static_cast<types::boundary_id>(Ssnp152::Ids::outer_boundary)}))
        columns.push_back(i);
    std::sort(columns.begin(), columns.end());
    columns.erase(std::unique(columns.begin(), columns.end()), columns.end());

    double worst = 0;
    for (const auto j : columns)
      {
        if (constraints.is_constrained(j))
          continue;
        const auto &tangential = contact.nodes().tangential_dofs;
        const auto &normal     = contact.nodes().dofs;
        const bool  traction =
          std::find(normal.begin(), normal.end(), j) != normal.end() ||
          std::find(tangential.begin(), tangential.end(), j) !=
            tangential.end();
        const double h =
          traction ? 1e-2 * analytic.contact_pressure(1e7) * 1e-6 : 1e-8;
        const double u0 = u(j);
        u(j)            = u0 + h;
        problem.assemble_newton_system();
        Vector<double> plus = problem.residual_rhs();
        u(j)                = u0 - h;
        problem.assemble_newton_system();
        Vector<double> minus = problem.residual_rhs();
        u(j)                 = u0;
        // rhs = -R, so dR/du_j = -(plus - minus) / 2h.
        double column_norm = 0, difference = 0;
        for (types::global_dof_index i = 0; i < u.size(); ++i)
          {
            if (constraints.is_constrained(i))
              continue;
            const double fd = -(plus(i) - minus(i)) / (2 * h);
            const double k  = Kref.el(i, j);
            column_norm += k * k;
            difference += (fd - k) * (fd - k);
          }
        if (column_norm > 0 && std::sqrt(difference / column_norm) > worst)
          {
            worst = std::sqrt(difference / column_norm);
            if (getenv("TANGENT_DEBUG"))
              for (types::global_dof_index i = 0; i < u.size(); ++i)
                if (!constraints.is_constrained(i))
                  {
                    const double fd = -(plus(i) - minus(i)) / (2 * h);
                    if (std::abs(fd - Kref.el(i, j)) >
                        1e-4 * std::sqrt(column_norm))
                      std::cerr << "col " << j << " row " << i << " K "
                                << Kref.el(i, j) << " fd " << fd << std::endl;
                  }
          }
      }
    problem.assemble_newton_system();
    if (friction > 0)
      {
        const auto &states = contact.active_set();
        check(states.n_active() > 0 &&
                states.n_slipping() == (friction > 1 ? 0 : states.n_active()),
              "friction: every closed node sticks (mu = 1e3) or slides (" +
                std::to_string(states.n_slipping()) + " of " +
                std::to_string(states.n_active()) + " closed nodes slide)");
      }
    const std::string name =
      scheme + (pressure_loaded ? ", pressure on r = R1" : "") +
      (vertex ? ", at master vertices" : "") +
      (smooth ? ", smoothed normals" : "") +
      (friction > 0 ?
         friction > 1 ? ", friction (sticking)" : ", friction (sliding)" :
         "") +
      ", mapping degree " + std::to_string(mapping_degree) + ", " +
      kinematics_name(kinematics);
    RingContactTests::deallog_file
      << name << ": " << columns.size()
      << " columns of the Newton matrix match finite differences: "
      << (worst < 1e-5 ? "yes" : "NO") << std::endl;
    check(worst < 1e-5,
          name + ": tangent differs from finite differences by " +
            std::to_string(worst));
  }
} // namespace

int
main()
{
  check_material(PlaneAssumption::plane_stress,
                 "logarithmic strain",
                 "Hencky plane stress");
  check_material(PlaneAssumption::plane_strain,
                 "logarithmic strain",
                 "Hencky plane strain");
  check_material(PlaneAssumption::plane_stress,
                 "finite strain",
                 "SVK plane stress");
  check_material(PlaneAssumption::plane_strain,
                 "finite strain",
                 "SVK plane strain");
  check_material(PlaneAssumption::plane_stress,
                 "small strain",
                 "linear plane stress");
  check_material(PlaneAssumption::plane_stress,
                 "neo-Hookean",
                 "neo-Hookean plane stress");
  check_material(PlaneAssumption::plane_strain,
                 "neo-Hookean",
                 "neo-Hookean plane strain");
  check_system("nodal", 1, "finite strain");
  check_system("nodal", 1, "finite strain", true);
  check_system("Gauss 3", 1, "finite strain");
  check_system("Gauss 3", 2, "finite strain");
  check_system("Gauss 2", 1, "small strain");
  check_system("nodal", 1, "finite strain", false, true);
  check_system("Gauss 3", 1, "finite strain", false, true);
  check_system("Gauss 3", 2, "finite strain", false, true);
  check_system("segment-based 2", 1, "finite strain");
  check_system("segment-based 3", 2, "finite strain");
  check_system("segment-based 2", 1, "finite strain", false, true);
  // The follower pressure on r = R1 (Loading = pressure): its tangent is
  // not symmetric; with small strain it is a dead load.
  check_system("Gauss 3", 1, "finite strain", false, false, true);
  check_system("Gauss 3", 2, "finite strain", false, true, true);
  check_system("nodal", 1, "small strain", false, false, true);
  // Logarithmic strain (Hencky), and its follower pressure.
  check_system("Gauss 3", 1, "logarithmic strain");
  check_system("segment-based 2", 2, "logarithmic strain", false, true);
  check_system("Gauss 3", 1, "logarithmic strain", false, false, true);
  // Coulomb friction: mu = 1e3 keeps every closed node sticking (the slip
  // rows, through the old partner's motion), mu = 0.2 makes it slide.
  for (const double mu : {1e3, 0.2})
    {
      check_system("nodal", 1, "finite strain", false, true, false, mu);
      check_system("Gauss 3", 2, "finite strain", false, false, false, mu);
      check_system(
        "segment-based 2", 1, "finite strain", false, false, false, mu);
      check_system("Gauss 2", 1, "logarithmic strain", false, false, false, mu);
    }
}
