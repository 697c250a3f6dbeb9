// @sect3{Diagnostics: the balance of forces of a converged state}
//
// The invariants of equilibrium.h, measured after every converged step
// (postprocessing.cc): each body in equilibrium, each contact pair's action
// equal to its reaction. They test what Newton's convergence test cannot:
// that the forces the program reports (reactions, contact forces) are
// those of a state in equilibrium, whatever went into them (constraints,
// corners, several pairs, several processes).
//
// Everything is a sum of nodal forces with the sign of an internal force,
// made relative to the sum of their magnitudes, so that the measures are
// pure numbers whatever the units, the load and the size.
#include <deal.II/base/quadrature.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/hp/fe_values.h>
#include <deal.II/hp/q_collection.h>

#include <ring_contact/base/components.h>
#include <ring_contact/diagnostics/equilibrium.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

namespace RingContact
{
  // At a supported unknown the residual R = f_int - applied + contact is
  // not zero: it is what the support exerts, its reaction. At a free one
  // Newton has driven it to zero, and the reaction is zero by definition.
  // The contact term keeps the other body's force out of the reaction: a
  // boundary's resultant once counted the contact force at its end node,
  // which lay on a contact surface, as its support's reaction (global
  // equilibrium broken, found by probing: doc/validation.md, "Figures that were
  // in the code's comments").
  Vector<double>
  NodalForces::reactions() const
  {
    Vector<double> s(internal.size());
    for (types::global_dof_index i = 0; i < s.size(); ++i)
      if (supported[i])
        {
          s(i) = internal(i) - applied(i);
          for (const auto &pair : contact)
            s(i) += pair(i);
        }
    return s;
  }

  // The worst over the bodies, a NaN being the worst of all:
  // std::max(nan, x) keeps the NaN, so once met it stays.
  double
  Balance::worst_body() const
  {
    double worst = 0;
    for (const auto &[name, error] : bodies)
      worst = std::isnan(error) ? error : std::max(worst, error);
    return worst;
  }

  // As worst_body(); NaN also when there is no pair, or when the pairs are
  // not measured (a cyclic sector).
  double
  Balance::worst_pair() const
  {
    double worst = pairs.empty() ? std::nan("") : 0.0;
    for (const double error : pairs)
      worst = std::isnan(error) ? error : std::max(worst, error);
    return worst;
  }

  namespace
  {
    // The material id of every displacement unknown (invalid for the
    // multipliers): the body it belongs to. A multiplier's row is a
    // weighted gap or a traction condition, not a force, and stays out of
    // every sum. The bodies share no vertex, so each unknown has one
    // body.
    template <int dim>
    std::vector<types::material_id>
    body_of_unknowns(const DoFHandler<dim> &dof_handler)
    {
      std::vector<types::material_id>      body(dof_handler.n_dofs(),
                                           numbers::invalid_material_id);
      std::vector<types::global_dof_index> dofs;
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          const auto &fe = cell->get_fe();
          dofs.resize(fe.n_dofs_per_cell());
          cell->get_dof_indices(dofs);
          for (unsigned int i = 0; i < dofs.size(); ++i)
            if (Components::is_displacement<dim>(
                  fe.system_to_component_index(i).first))
              body[dofs[i]] = cell->material_id();
        }
      return body;
    }

    // The component (0 to dim - 1) of each displacement unknown: the sums are
    // of vectors, one per body.
    template <int dim>
    std::vector<unsigned int>
    component_of_unknowns(const DoFHandler<dim> &dof_handler)
    {
      std::vector<unsigned int>            component(dof_handler.n_dofs(),
                                          Components::n_components<dim>);
      std::vector<types::global_dof_index> dofs;
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          const auto &fe = cell->get_fe();
          dofs.resize(fe.n_dofs_per_cell());
          cell->get_dof_indices(dofs);
          for (unsigned int i = 0; i < dofs.size(); ++i)
            component[dofs[i]] = fe.system_to_component_index(i).first;
        }
      return component;
    }

    // |sum of the vectors| over the sum of their magnitudes, component by
    // component summed, or over the round-off of the forces where that is
    // larger (a body moved rigidly carries forces that are round-off
    // only): 0 when nothing acts.
    template <int dim>
    struct Sum
    {
      Tensor<1, dim> total;
      double         magnitude = 0;
      double         round_off = 0;

      void
      add(const unsigned int component, const double value)
      {
        total[component] += value;
        magnitude += std::abs(value);
      }
      // |total| over the larger of the magnitude and the round-off.
      double
      relative() const
      {
        const double scale = std::max(magnitude, round_off);
        return scale > 0 ? total.norm() / scale : 0.0;
      }
      /// Whether the sum is more than the round-off of the forces.
      bool
      beyond_round_off() const
      {
        return total.norm() > round_off;
      }
    };
  } // namespace

  template <int dim>
  Balance
  measure_balance(
    const DoFHandler<dim>                                         &dof_handler,
    const NodalForces                                             &forces,
    const std::vector<std::pair<types::material_id, std::string>> &bodies,
    const std::vector<std::pair<types::material_id, types::material_id>>
              &pair_bodies,
    const bool measure_pairs)
  {
    const auto body      = body_of_unknowns(dof_handler);
    const auto component = component_of_unknowns(dof_handler);
    const auto reaction  = forces.reactions();

    // Per body: applied + reaction - contact (what the other bodies exert
    // is minus the contact terms). At a supported unknown this is f_int, at
    // a free one f_int - R; and the internal forces of a body sum to zero
    // in each component, since its shape functions sum to one and
    // sum_i f_int,i = int P Grad(sum_i phi_i) dV = 0. So the sum is minus
    // the body's free residual: zero at the solution, and a measure of how
    // far the state is from it. The round-off, when the caller gives it,
    // is summed per body too.
    std::map<types::material_id, Sum<dim>> per_body;
    for (types::global_dof_index i = 0; i < body.size(); ++i)
      {
        if (body[i] == numbers::invalid_material_id)
          continue;
        Sum<dim> &sum = per_body[body[i]];
        if (forces.round_off.size() == body.size())
          sum.round_off += forces.round_off(i);
        sum.add(component[i], forces.applied(i));
        sum.add(component[i], reaction(i));
        for (const auto &pair : forces.contact)
          sum.add(component[i], -pair(i));
      }
    Balance balance;
    // Whether a body's sum exceeds its round-off is kept beside the ratio:
    // a body moved rigidly and not loaded carries round-off only, and its
    // ratio, of order one, means nothing.
    for (const auto &[id, name] : bodies)
      {
        balance.bodies.emplace_back(name, per_body[id].relative());
        balance.beyond_round_off.push_back(per_body[id].beyond_round_off());
      }

    // Per pair: the force on the slave body plus that on the master body.
    // Only the pair's own contact terms, over both bodies' unknowns: with
    // several pairs a body's contact forces are the sum of its pairs', and
    // each pair must balance on its own.
    for (unsigned int k = 0; k < forces.contact.size(); ++k)
      {
        if (!measure_pairs)
          {
            balance.pairs.push_back(std::nan(""));
            continue;
          }
        Sum<dim> sum;
        for (types::global_dof_index i = 0; i < body.size(); ++i)
          if (body[i] == pair_bodies[k].first ||
              body[i] == pair_bodies[k].second)
            sum.add(component[i], forces.contact[k](i));
        balance.pairs.push_back(sum.relative());
      }
    return balance;
  }

  template Balance
  measure_balance(
    const DoFHandler<2> &,
    const NodalForces &,
    const std::vector<std::pair<types::material_id, std::string>> &,
    const std::vector<std::pair<types::material_id, types::material_id>> &,
    const bool);
  template Balance
  measure_balance(
    const DoFHandler<3> &,
    const NodalForces &,
    const std::vector<std::pair<types::material_id, std::string>> &,
    const std::vector<std::pair<types::material_id, types::material_id>> &,
    const bool);
} // namespace RingContact
