// @sect3{Constraints: the imposed displacements of the Newton updates}
//
// The scenario imposes displacements on boundaries (values, or a normal
// component N . u = g). A Newton update either keeps them (homogeneous
// constraints) or, as the first update of a load step, moves the boundary
// to the new load state: its increment is imposed on the linearised
// problem (inhomogeneous constraints, as step-44 does), so that it spreads
// over the bodies instead of concentrating in the first layer of cells.
// The multiplier lives on the slave surfaces only, and a cyclic sector's
// end side follows its start side.
#include <deal.II/dofs/dof_tools.h>

#include <ring_contact/base/components.h>
#include <ring_contact/problem/contact_problem.h>

#include <cmath>
#include <limits>
#include <set>

namespace RingContact
{
  // @sect4{The imposed displacements as constraints}
  //
  // The unknowns the scenario imposes (at any load state: they define the
  // constraints; their values change), the normal conditions N . u = g,
  // each on the component with the larger |N_a|, and the multipliers off
  // the slave surfaces, held at zero.
  //
  // The motion is asked for at the unloaded state only for its keys: which
  // unknowns are imposed and which nodes carry a normal condition is the
  // same at every load state (the scenario promises it), so that the
  // constraints, the sparsity pattern and the direct solver's analysis
  // outlive the load steps; each step changes the values alone.
  template <int dim>
  void
  ContactProblem<dim>::make_constraints()
  {
    hanging_node_constraints.clear();
    DoFTools::make_hanging_node_constraints(dof_handler,
                                            hanging_node_constraints);
    hanging_node_constraints.close();
    imposed_dofs.clear();
    const ImposedMotion<dim> motion =
      scenario->boundary_motion(dof_handler, mapping_collection, LoadState{});
    for (const auto &[dof, value] : motion.values)
      imposed_dofs.push_back(dof);
    normal_target = motion.normal;
    normal_component.clear();
    // The constrained component is the one with the larger |N_a|, so that
    // the coefficient N_b / N_a of the other is at most 1 in magnitude and
    // no division by a small component amplifies the round-off. The normal
    // is that of the reference boundary, fixed for the whole run.
    for (const auto &line : normal_target)
      {
        unsigned int a = 0;
        for (unsigned int d = 1; d < dim; ++d)
          if (std::abs(line.normal[d]) > std::abs(line.normal[a]))
            a = d;
        normal_component.push_back(a);
        imposed_dofs.push_back(line.dofs[a]);
      }
    // The homogeneous constraints of the corrector updates. is_dirichlet is
    // taken before the multipliers and the cyclic ties are added (see
    // add_constraints()): the supports only, whose internal forces are the
    // reactions that scale the force residual (residual_measure()).
    add_constraints(constraints, {}, {}, &is_dirichlet);
    // Every multiplier unknown, on the slave surfaces or not: the rows
    // whose residual is a gap or a traction rather than a force.
    const IndexSet all_multipliers =
      DoFTools::extract_dofs(dof_handler, Components::contact_mask<dim>());
    is_multiplier.assign(dof_handler.n_dofs(), false);
    for (const auto i : all_multipliers)
      is_multiplier[i] = true;

    // The unknowns whose reaction a support takes (equilibrium.h): the
    // imposed ones, both of a node with a normal condition (its reaction is
    // along the normal), and the two sides of a cyclic sector (the rest of
    // the rings acts there).
    supported.assign(dof_handler.n_dofs(), false);
    for (const auto dof : imposed_dofs)
      supported[dof] = true;
    for (const auto &line : normal_target)
      for (const auto dof : line.dofs)
        supported[dof] = true;
    for (const auto &pair : cyclic_pairs)
      for (const unsigned int c : {Components::ux, Components::uy})
        supported[pair.end[c]] = supported[pair.start[c]] = true;
  }

  // The constraints of a Newton update. The fixed displacements get the
  // values of `boundary_increment` (zero where it has none): homogeneous for
  // the iterations that correct a state, inhomogeneous for the update that
  // moves the boundary to a new load state.
  // A normal displacement N . u = g constrains the component a with the
  // larger |N_a|: du_a = -(N_b / N_a) du_b + (its increment).
  template <int dim>
  void
  ContactProblem<dim>::add_constraints(
    AffineConstraints<double>                       &target,
    const std::map<types::global_dof_index, double> &boundary_increment,
    const std::vector<double>                       &normal_increment,
    std::vector<bool>                               *fixed_dofs)
  {
    target.clear();
    // The hanging nodes of an adaptively refined mesh (refinement.cc), on
    // inner faces only: never an imposed unknown or a slave surface's node.
    target.merge(hanging_node_constraints);
    // The imposed unknowns, then their increments: an unknown the increment
    // leaves out keeps its value (a homogeneous line).
    for (const auto dof : imposed_dofs)
      target.add_line(dof);
    for (const auto &[dof, increment] : boundary_increment)
      target.set_inhomogeneity(dof, increment);
    // The line of u_a is already in `imposed_dofs`; its entry makes the
    // update keep N . u: N_a du_a + N_b du_b = (N_a times the increment).
    for (unsigned int k = 0; k < normal_target.size(); ++k)
      {
        const auto        &line = normal_target[k];
        const unsigned int a    = normal_component[k];
        for (unsigned int b = 0; b < dim; ++b)
          if (b != a)
            target.add_entry(line.dofs[a],
                             line.dofs[b],
                             -line.normal[b] / line.normal[a]);
        if (!normal_increment.empty())
          target.set_inhomogeneity(line.dofs[a], normal_increment[k]);
      }
    if (fixed_dofs)
      {
        fixed_dofs->assign(dof_handler.n_dofs(), false);
        for (types::global_dof_index i = 0; i < dof_handler.n_dofs(); ++i)
          (*fixed_dofs)[i] = target.is_constrained(i) &&
                             !hanging_node_constraints.is_constrained(i);
      }

    // The multiplier lives on the slave surface only. The layer's nodes off
    // the surface (on its inner faces) are held at zero, which leaves the
    // trace of FE_Q(q) on the slave surface as the multiplier's space.
    const IndexSet all_multipliers =
      DoFTools::extract_dofs(dof_handler, Components::contact_mask<dim>());
    std::set<types::global_dof_index> slave_multipliers;
    for (const auto &[node, pair] : pair_of_node)
      slave_multipliers.insert(node);
    for (const auto i : all_multipliers)
      if (slave_multipliers.count(i) == 0 && !target.is_constrained(i))
        target.add_line(i);

    // Cyclic symmetry: the end side of the sector follows the start side,
    // u(X_e) = Q u(X_s) and the same multiplier. An end-side node imposed
    // already (a corner on the rings' loaded circles) keeps its line: its
    // imposed value satisfies the same relation.
    if (!cyclic_pairs.empty())
      CyclicSymmetry::add_constraints(cyclic_pairs, sector.angle, target);
    target.close();
  }

  // The first update of a load step carries the boundary increment, the
  // difference between the displacements of the new load state and those
  // of the current solution (the last converged state, or the predictor's
  // extrapolation of it). Writing that increment into the solution instead
  // would concentrate it in the first layer of elements along r = R1 and
  // r = R3: at finite strain that state can be far from the one sought (27 %
  // strain in the first layer with 12 layers per ring at p = 1e7), and
  // Newton then converges to another solution, the rings apart. Imposed on
  // the linearised problem, the increment spreads over the rings (step-44).
  // Returns whether there is an increment to impose.
  template <int dim>
  bool
  ContactProblem<dim>::impose_boundary_increment()
  {
    // The increments, and the sizes that decide whether there is one at
    // all: the largest increment against the largest imposed value.
    std::map<types::global_dof_index, double> increment;
    double largest_target = 0, largest_increment = 0;
    for (const auto &[dof, value] : boundary_target)
      {
        increment[dof] = value - solution(dof);
        largest_target = std::max(largest_target, std::abs(value));
        largest_increment =
          std::max(largest_increment, std::abs(increment[dof]));
      }
    // A normal condition's increment is on its constrained component u_a:
    // the value N . u = g gives it with the current u_b, less its current
    // value.
    std::vector<double> normal_increment;
    for (unsigned int k = 0; k < normal_target.size(); ++k)
      {
        const auto dof = normal_target[k].dofs[normal_component[k]];
        normal_increment.push_back(normal_constrained_value(k, solution) -
                                   solution(dof));
        largest_target =
          std::max(largest_target, std::abs(normal_target[k].value));
        largest_increment =
          std::max(largest_increment, std::abs(normal_increment.back()));
      }
    // The predictor hits the target up to round-off when the motion is
    // linear in the load: then there is nothing to lift. The boundary is
    // set exactly and the first update is an ordinary one, so that the
    // extrapolated state may be accepted at once (the lifting update is
    // never a converged one): the two-blocks patch test in four steps takes
    // 1 0 0 0 Newton iterations. The bound, 1e3 eps of the largest imposed
    // value, leaves room for the round-off of the extrapolation.
    if (largest_increment <=
        1e3 * std::numeric_limits<double>::epsilon() * largest_target)
      {
        set_boundary_at_target();
        return false;
      }
    add_constraints(lifting_constraints, increment, normal_increment);
    return true;
  }

  // The value of the constrained component u_a that satisfies the k-th
  // normal condition N . u = g with the other components of `u`:
  // u_a = (g - sum over b != a of N_b u_b) / N_a.
  template <int dim>
  double
  ContactProblem<dim>::normal_constrained_value(const unsigned int    k,
                                                const Vector<double> &u) const
  {
    const auto        &line = normal_target[k];
    const unsigned int a    = normal_component[k];
    double             rest = line.value;
    for (unsigned int b = 0; b < dim; ++b)
      if (b != a)
        rest -= line.normal[b] * u(line.dofs[b]);
    return rest / line.normal[a];
  }

  // The boundary exactly at its target, not up to round-off: the imposed
  // values, then the normal conditions (a normal condition's other unknown
  // may be an imposed one). The updates from here keep it: their
  // constraints are the homogeneous ones (update_constraints()).
  template <int dim>
  void
  ContactProblem<dim>::set_boundary_at_target()
  {
    for (const auto &[dof, value] : boundary_target)
      solution(dof) = value;
    for (unsigned int k = 0; k < normal_target.size(); ++k)
      solution(normal_target[k].dofs[normal_component[k]]) =
        normal_constrained_value(k, solution);
    lifting_constraints.clear();
  }

  // The scenario's displacements at the load state become the target.
  // Nothing is moved here: the first update of the step imposes the target
  // (impose_boundary_increment()), and a step that is cut asks again for
  // the state at its shorter increment.
  template <int dim>
  void
  ContactProblem<dim>::apply_boundary_motion(const LoadState &load)
  {
    ImposedMotion<dim> motion =
      scenario->boundary_motion(dof_handler, mapping_collection, load);
    boundary_target = std::move(motion.values);
    normal_target   = std::move(motion.normal);
    current_load    = load;
  }

  // Whether the extrapolated state has the boundary near its target at the
  // load state tried: its imposed values (and normal conditions) within a
  // tenth of their increment from the converged state. On a path linear in the
  // extrapolated parameter they agree to round-off (or to second order, turning
  // a boundary in small steps).
  template <int dim>
  bool
  ContactProblem<dim>::boundary_near_target(
    const Vector<double> &converged) const
  {
    double miss = 0, increment = 0, largest = 0;
    for (const auto &[dof, value] : boundary_target)
      {
        miss      = std::max(miss, std::abs(solution(dof) - value));
        increment = std::max(increment, std::abs(value - converged(dof)));
        largest   = std::max(largest, std::abs(value));
      }
    // The normal conditions N . u = g on their constrained component.
    for (unsigned int k = 0; k < normal_target.size(); ++k)
      {
        const auto dof = normal_target[k].dofs[normal_component[k]];
        miss           = std::max(miss,
                        std::abs(normal_constrained_value(k, solution) -
                                 solution(dof)));
        increment      = std::max(increment,
                             std::abs(normal_constrained_value(k, converged) -
                                      converged(dof)));
        largest        = std::max(largest, std::abs(normal_target[k].value));
      }
    // The same decision on every process.
    if (n_processes > 1)
      {
        miss      = Utilities::MPI::max(miss, communicator);
        increment = Utilities::MPI::max(increment, communicator);
        largest   = Utilities::MPI::max(largest, communicator);
      }
    // The extrapolation's round-off (x + a x - a x) is no miss: the bound of
    // impose_boundary_increment().
    return miss <= 0.1 * increment +
                     1e3 * std::numeric_limits<double>::epsilon() * largest;
  }


  // This chapter's members for the dimensions the program runs in: the
  // explicit instantiation of the class in a chapter instantiates the
  // members defined here (see contact_problem.cc).
  template class ContactProblem<2>;
  template class ContactProblem<3>;
} // namespace RingContact
