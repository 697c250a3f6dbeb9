// What the forces of a converged state must satisfy, checked by the program
// itself at every step.
//
// The nodal forces of a state: f_int (the bulk's stresses, int P : Grad
// phi_i), the applied loads, the contact terms (with the sign of an internal
// force: minus what the other body exerts), and at the supported unknowns
// the reaction s = f_int - applied + contact, what the support exerts. Then
// - each body is in equilibrium: the applied loads, the reactions and the
//   forces of the other bodies on it sum to zero (this is the sum of the
//   residual over its free unknowns, since the internal forces of a body sum
//   to zero for any state);
// - each contact pair exerts equal and opposite forces on its two bodies.
// Each is measured relative to the sum of the magnitudes of the nodal
// forces involved (or their round-off, where a body carries no more), so
// that it is a pure number at any scale.
#ifndef ring_contact_diagnostics_equilibrium_h
#define ring_contact_diagnostics_equilibrium_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/hp/mapping_collection.h>
#include <deal.II/lac/vector.h>

#include <ring_contact/base/dimension.h>

#include <array>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace RingContact
{
  using namespace dealii;

  /// The nodal forces of a converged state, each with the sign of an
  /// internal force where it is one: see the file's introduction.
  struct NodalForces
  {
    Vector<double> internal; ///< f_int
    Vector<double> applied;  ///< the applied loads
    /// The contact terms of each pair (the sign of an internal force).
    std::vector<Vector<double>> contact;
    /// The unknowns whose reaction a support (an imposed displacement, a
    /// normal condition, a cyclic constraint) takes.
    std::vector<bool> supported;
    /// Per unknown, the round-off of its forces (a few eps times the
    /// magnitude of the terms they are summed from): the scale of a body
    /// whose forces are round-off only (moved rigidly, not loaded).
    Vector<double> round_off;

    /// The reaction at a supported unknown, zero elsewhere.
    Vector<double>
    reactions() const;
  };

  /// The invariants of one state.
  struct Balance
  {
    /// Per body: |sum of applied, reaction and contact forces| over the
    /// sum of their magnitudes (or over the round-off of its forces, where
    /// that is larger), and the body's name.
    std::vector<std::pair<std::string, double>> bodies;
    /// Per body: whether that sum is more than the round-off of its forces
    /// (only then can it be an error).
    std::vector<bool> beyond_round_off;
    /// Per contact pair: |force on the slave body + force on the master
    /// body| over the sum of the magnitudes of the pair's nodal forces
    /// (NaN where it is not measured: cyclic symmetry, whose copies carry
    /// the master's forces turned).
    std::vector<double> pairs;

    double
    worst_body() const;
    double
    worst_pair() const;
  };

  /// The equilibrium of every body (cells of one material id) and the
  /// action and reaction of every pair (`pair_bodies`: the slave's and the
  /// master's material ids; `measure_pairs` false for cyclic symmetry).
  template <int dim>
  Balance
  measure_balance(
    const DoFHandler<dim>                                         &dof_handler,
    const NodalForces                                             &forces,
    const std::vector<std::pair<types::material_id, std::string>> &bodies,
    const std::vector<std::pair<types::material_id, types::material_id>>
              &pair_bodies,
    const bool measure_pairs = true);

} // namespace RingContact

#endif
