// @sect3{Assembly: the bulk, the boundary loads and the contact terms}
//
// The residual R of the virtual work and its tangent at the current
// solution, into the linear system (rhs = -R): the bulk's total Lagrangian
// virtual work with each body's material law (materials/), the loads of the
// scenario's boundaries, and the contact terms of each pair (contact/,
// exactly linearised by automatic differentiation). Each row also gets the
// magnitude of the terms it is summed from, machine epsilon times which is
// the round-off of the residual (the floors of nonlinear_problem.cc).
//
// Signs: the system receives -R, as deal.II's tutorials assemble it; the
// vectors internal_force and external_force receive their parts of R, the
// bulk's f_int and the loads' -f_applied (nodal_forces() turns the latter
// back for equilibrium.h).
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/hp/fe_values.h>

#include <ring_contact/base/components.h>
#include <ring_contact/base/dimension.h>
#include <ring_contact/base/utilities.h>
#include <ring_contact/problem/contact_problem.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace RingContact
{
  // @sect4{The reference geometry, once}
  //
  // What the total Lagrangian assembly needs of the reference
  // configuration, which does not move: per cell of this process and
  // quadrature point, JxW and the gradients of the displacement's scalar
  // shape functions (both components share them). Evaluated once, by
  // FEValues through the mapping, instead of at every assembly, of which it was
  // a noticeable part. 288 bytes per Q1 cell, 1.4 kB per Q2 cell: small beside
  // the memory of the factorization (doc/validation.md, "Time and memory behind
  // the code's choices").
  //
  // The layout per finite element of the collection says where each
  // unknown's gradient is found: both displacement components of FE_Q(p)^2
  // share one scalar shape function, so the gradients are stored per
  // scalar function (n_bases per point), not per unknown, which halves
  // them.
  template <int dim>
  void
  ContactProblem<dim>::store_reference_geometry()
  {
    auto &geometry = reference_geometry;
    geometry.layout.resize(fe_collection.size());
    for (unsigned int k = 0; k < fe_collection.size(); ++k)
      {
        const FiniteElement<dim> &fe     = fe_collection[k];
        auto                     &layout = geometry.layout[k];
        layout.n_q_points                = q_collection[k].size();
        layout.component.resize(fe.n_dofs_per_cell());
        layout.u_dofs.clear();
        layout.base.clear();
        layout.n_bases = 0;
        for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
          {
            layout.component[i] = fe.system_to_component_index(i).first;
            if (!Components::is_displacement<dim>(layout.component[i]))
              continue;
            // The index of the scalar shape function in its base element.
            layout.u_dofs.push_back(i);
            layout.base.push_back(fe.system_to_base_index(i).second);
            layout.n_bases = std::max(layout.n_bases, layout.base.back() + 1);
          }
      }
    // Through each body's mapping: on curved rings (mapping degree 2 and
    // more) the reference geometry is the polar manifold's, not the
    // straight cells'.
    hp::FEValues<dim> hp_fe_values(mapping_collection,
                                   fe_collection,
                                   q_collection,
                                   update_gradients | update_JxW_values);
    geometry.start.assign(triangulation.n_active_cells(), {0, 0});
    geometry.JxW.clear();
    geometry.gradients.clear();
    // Only this process's cells: under MPI each stores what it assembles,
    // and the others keep an empty start.
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        if (cell->subdomain_id() != this_process)
          continue;
        hp_fe_values.reinit(cell);
        const FEValues<dim> &fe_values = hp_fe_values.get_present_fe_values();
        const auto          &layout = geometry.layout[cell->active_fe_index()];
        geometry.start[cell->active_cell_index()] = {geometry.JxW.size(),
                                                     geometry.gradients.size()};
        for (unsigned int q = 0; q < layout.n_q_points; ++q)
          {
            geometry.JxW.push_back(fe_values.JxW(q));
            const std::size_t first = geometry.gradients.size();
            geometry.gradients.resize(first + layout.n_bases);
            for (unsigned int a = 0; a < layout.u_dofs.size(); ++a)
              geometry.gradients[first + layout.base[a]] =
                fe_values.shape_grad(layout.u_dofs[a], q);
          }
      }
    geometry.JxW.shrink_to_fit();
    geometry.gradients.shrink_to_fit();
  }

  // @sect4{Pairing, then assembly}
  //
  // Pair, choose the active set, and assemble the Newton system at the
  // current solution; a new sparsity pattern when the pairs left the old.
  //
  // The pairing is redone at every assembly (large sliding: the partners at
  // the end of a step are not those of its start), unless the Newton solver
  // holds it because it cycles (`pairing`). The count of nodes whose
  // status changed goes back to the Newton solver, which accepts no iterate
  // whose active set is still changing.
  template <int dim>
  unsigned int
  ContactProblem<dim>::assemble_newton_system(const Pairing  pairing,
                                              const Assembly what)
  {
    // Only finite numbers in the state: an update that overflowed (a body
    // as soft as E = 1e-200, a diverging iterate) fails the iteration here,
    // with its reason, before the contact search computes with it.
    for (const double value : solution)
      if (!std::isfinite(value))
        throw NonFiniteState("the displacement or contact pressure is not a "
                             "finite number after the Newton update");
    unsigned int n_changed;
    {
      TimerOutput::Scope t(timer, "contact search");
      n_changed = 0;
      for (const auto &contact : contacts)
        n_changed += contact->update(solution, pairing);
    }
    // A point that slid onto a master segment beyond its old partner's
    // neighbours couples unknowns the pattern has no room for: the pattern
    // is made again before anything is added to it.
    if (!std::all_of(contacts.begin(),
                     contacts.end(),
                     [](const std::unique_ptr<ContactInterface<dim>> &contact) {
                       return contact->sparsity_covers_pairing();
                     }))
      make_sparsity_pattern();
    assemble_system(what);
    return n_changed;
  }

  // @sect4{The Newton system}
  //
  // Bulk: total Lagrangian virtual work int P : Grad(delta u) dV and its
  // tangent int Grad(delta u) : A : Grad(du) dV; then the contact terms and
  // the boundary loads. Without the tangent (Assembly::residual) the bulk's
  // cells give their residual alone, from the stress alone: a third of the
  // work (the contact terms are whole either way). The constraints of the
  // lifting update are not homogeneous and act on the right-hand side
  // through the matrix: that assembly always has its tangent.
  //
  // The order is that of the magnitudes: the contact terms first, alone in
  // the system, so that their rows' magnitudes can be read off it; then the
  // bulk and the loads, which add theirs cell by cell.
  template <int dim>
  void
  ContactProblem<dim>::assemble_system(Assembly what)
  {
    if (update_constraints().has_inhomogeneities())
      what = Assembly::residual_and_tangent;
    TimerOutput::Scope t(timer, "assembly");
    const bool         tangent = what == Assembly::residual_and_tangent;
    tangent_assembled          = tangent;
    system->set_zero();
    internal_force     = 0;
    external_force     = 0;
    residual_magnitude = 0;
    // Counted afresh: the Newton loop and the line search judge the state
    // just assembled, and reject it if any point is inverted.
    n_inverted        = 0;
    n_undefined_det_F = 0;
    min_det_F         = std::numeric_limits<double>::max();
    n_outside_law     = 0;
    outside_law_body  = numbers::invalid_material_id;

    assemble_contact_terms();
    // At the first assembly: the partition and the mappings are known, and
    // the reference configuration does not change after it.
    if (reference_geometry.start.empty())
      store_reference_geometry();
    assemble_bulk(tangent);

    // A load that is not a finite number at a face of one process fails the
    // load step on every process. The error is held until after compress()
    // and the sums below, which every process must reach: thrown on one
    // process alone, it would leave the others waiting in them.
    std::string boundary_data_error;
    try
      {
        assemble_boundary_loads();
      }
    catch (const BoundaryDataError &e)
      {
        boundary_data_error = e.what();
      }
    system->compress();
    if (n_processes > 1)
      {
        // The sums over the processes' cells: every process then holds the
        // whole force vectors, so that the convergence measures and the
        // invariants are the same on all of them.
        for (Vector<double> *v :
             {&internal_force, &external_force, &residual_magnitude})
          sum_over_processes(*v, communicator);
        n_inverted = Utilities::MPI::sum(n_inverted, communicator);
        n_undefined_det_F =
          Utilities::MPI::sum(n_undefined_det_F, communicator);
        min_det_F     = Utilities::MPI::min(min_det_F, communicator);
        n_outside_law = Utilities::MPI::sum(n_outside_law, communicator);
        outside_law_body =
          Utilities::MPI::min(static_cast<unsigned int>(outside_law_body),
                              communicator);
        for (const BoundaryLoad<dim> &load : boundary_loads)
          {
            for (unsigned int d = 0; d < dim; ++d)
              applied_resultant[load.boundary_id][d] =
                Utilities::MPI::sum(applied_resultant[load.boundary_id][d],
                                    communicator);
            for (unsigned int d = 0; d < 3; ++d)
              applied_moment[load.boundary_id][d] =
                Utilities::MPI::sum(applied_moment[load.boundary_id][d],
                                    communicator);
          }
        for (const auto &message :
             Utilities::MPI::all_gather(communicator, boundary_data_error))
          if (!message.empty())
            {
              boundary_data_error = message;
              break;
            }
      }
    if (!boundary_data_error.empty())
      throw BoundaryDataError(boundary_data_error);
    // The magnitude of the terms of each row at the last assembly with the
    // tangent (the others have the contact's only): the round-off scale of
    // the forces for the invariants of the converged state, whose own
    // assembly may have skipped the tangent.
    if (tangent)
      tangent_magnitude = residual_magnitude;
  }

  // @sect4{The contact terms and their round-off}
  //
  // The contact terms first, on their own, to measure their magnitudes: a
  // contact row is computed from positions X + u (the gap, the normal), so
  // its round-off is eps |K_ij| (|X| + |u_j|), not eps |K_ij| |u_j|. At
  // p = 1e4 on steel this is a thousand times the bulk's.
  template <int dim>
  void
  ContactProblem<dim>::assemble_contact_terms()
  {
    for (const auto &contact : contacts)
      contact->assemble(solution, update_constraints(), *system);
    // The contact points of other processes add to this process's rows too:
    // the rows are whole only after compress(), and only the owner of a row
    // has its entries.
    system->compress();
    {
      // The largest |X| of the mesh bounds the position of every node: the
      // scale of the round-off of a position, whatever its displacement.
      double largest_position = 0;
      for (const auto &vertex : triangulation.get_vertices())
        largest_position = std::max(largest_position, vertex.norm());
      for (const auto i : locally_owned_dofs)
        {
          double magnitude = std::abs(system->rhs()(i));
          // A multiplier column enters with its value alone: lambda is no
          // position, and its terms' round-off is relative to it.
          system->for_each_entry(i, [&](const auto j, const double value) {
            magnitude +=
              std::abs(value) * (std::abs(solution(j)) +
                                 (is_multiplier[j] ? 0 : largest_position));
          });
          residual_magnitude(i) = magnitude;
        }
    }
  }

  // @sect4{The bulk}
  //
  // The bulk, cell by cell with the reference geometry stored once: the
  // displacement shape functions each have one nonzero component c, Grad
  // phi = e_c (x) grad(phi_c), so that Grad u = sum_i u_i e_c (x)
  // grad(phi_i), P : Grad(phi_i) = P_cJ d_J phi_i and the tangent is d_J
  // phi_i A_cJdL d_L phi_j.
  template <int dim>
  void
  ContactProblem<dim>::assemble_bulk(const bool tangent)
  {
    FullMatrix<double>                   cell_matrix;
    Vector<double>                       cell_rhs;
    std::vector<types::global_dof_index> dofs;
    std::vector<Tensor<2, dim>>          grad_u;
    std::vector<Tensor<1, dim>>          grad_phi;

    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        if (cell->subdomain_id() != this_process)
          continue;
        const FiniteElement<dim> &fe       = cell->get_fe();
        const unsigned int        n        = fe.n_dofs_per_cell();
        const Material<dim>      &material = materials.at(cell->material_id());
        const auto &layout = reference_geometry.layout[cell->active_fe_index()];
        const auto &u_dofs = layout.u_dofs;
        const auto &component         = layout.component;
        const unsigned int n_q_points = layout.n_q_points;
        // This cell's stored values: JxW per point, and the gradient of
        // scalar function k at point q at gradients[q * n_bases + k].
        const auto start = reference_geometry.start[cell->active_cell_index()];
        const double         *JxW_values = &reference_geometry.JxW[start.first];
        const Tensor<1, dim> *gradients =
          &reference_geometry.gradients[start.second];
        cell_matrix.reinit(n, n);
        cell_rhs.reinit(n);
        dofs.resize(n);
        cell->get_dof_indices(dofs);

        // Grad u at every quadrature point, row c of it summed from the
        // unknowns of component c times their stored scalar gradients:
        // what FEValues' get_function_gradients() gave after a reinit(),
        // without either.
        grad_phi.resize(u_dofs.size());
        grad_u.assign(n_q_points, Tensor<2, dim>());
        for (unsigned int q = 0; q < n_q_points; ++q)
          for (unsigned int a = 0; a < u_dofs.size(); ++a)
            grad_u[q][component[u_dofs[a]]] +=
              solution(dofs[u_dofs[a]]) *
              gradients[q * layout.n_bases + layout.base[a]];

        for (unsigned int q = 0; q < n_q_points; ++q)
          {
            // An inverted state (det F <= 0) has no physical meaning, in
            // either kinematics: it is counted, the material law is not
            // evaluated there (the neo-Hookean and logarithmic laws take
            // ln J), and the Newton loop rejects the state; a line search
            // trial halves its step instead. The negated test also counts a
            // NaN det F (a gradient whose products overflow), apart:
            // std::min() skips a NaN, and min_det_F, still its initial
            // max(), would have been reported as "det F = 1.79769e+308 <= 0".
            const double det_F =
              determinant(unit_symmetric_tensor<dim>() + grad_u[q]);
            min_det_F = std::min(min_det_F, det_F);
            if (!(det_F > 0))
              {
                ++n_inverted;
                n_undefined_det_F += std::isnan(det_F) ? 1 : 0;
                continue;
              }
            // A state the law does not have is rejected alike.
            if (outside_law(material, grad_u[q], cell->material_id()))
              continue;
            // Without the tangent the law gives the stress alone, and no
            // cell matrix is formed.
            Tensor<2, dim> P;
            Tensor<4, dim> A;
            if (tangent)
              material.stress_and_tangent(grad_u[q], P, A);
            else
              P = material.stress(grad_u[q]);
            const double JxW = JxW_values[q];
            for (unsigned int a = 0; a < u_dofs.size(); ++a)
              grad_phi[a] = gradients[q * layout.n_bases + layout.base[a]];
            for (unsigned int a = 0; a < u_dofs.size(); ++a)
              {
                // -R: the internal virtual work enters with a minus.
                const unsigned int i = u_dofs[a], c = component[i];
                cell_rhs(i) -= (P[c] * grad_phi[a]) * JxW;
                if (!tangent)
                  continue;
                // A_cJdL grad_phi_a[J], for each d and L: contracted once
                // per a, it leaves a 2 x 2 product per entry (a, b).
                Tensor<2, dim> Ag;
                for (unsigned int J = 0; J < dim; ++J)
                  for (unsigned int d = 0; d < dim; ++d)
                    for (unsigned int L = 0; L < dim; ++L)
                      Ag[d][L] += grad_phi[a][J] * A[c][J][d][L];
                // The upper triangle: the laws are hyperelastic, A_cJdL =
                // A_dLcJ, and the bulk's tangent is symmetric.
                for (unsigned int b = a; b < u_dofs.size(); ++b)
                  {
                    const unsigned int j = u_dofs[b];
                    cell_matrix(i, j) += (Ag[component[j]] * grad_phi[b]) * JxW;
                  }
              }
          }
        // The lower triangle mirrored; the multiplier rows and columns of
        // a layer cell stay zero (the bulk has no multiplier terms).
        if (tangent)
          for (unsigned int a = 0; a < u_dofs.size(); ++a)
            for (unsigned int b = 0; b < a; ++b)
              cell_matrix(u_dofs[a], u_dofs[b]) =
                cell_matrix(u_dofs[b], u_dofs[a]);
        // With the cell's index: a cell without constrained unknowns, all
        // its rows this process's, goes straight to the places of its
        // entries in the matrix's storage, found once per sparsity pattern
        // (LinearSystem::add_cell()). Inserting by global index was a large
        // part of an assembly on the Trilinos path (doc/validation.md, "Time
        // and memory behind the code's choices").
        add_local_system(cell_matrix,
                         cell_rhs,
                         dofs,
                         internal_force,
                         cell->active_cell_index());
      }
  }

  // Whether the law has no state at a point (Saint Venant-Kirchhoff in
  // plane stress past its thickness stretch's zero, whose stress would be
  // that of an imaginary thickness), counted with the inverted points; the
  // body of the smallest material id is named.
  template <int dim>
  bool
  ContactProblem<dim>::outside_law(const Material<dim>     &material,
                                   const Tensor<2, dim>    &grad_u,
                                   const types::material_id body)
  {
    if (material.in_range(grad_u))
      return false;
    ++n_inverted;
    ++n_outside_law;
    outside_law_body = std::min(outside_law_body, body);
    return true;
  }

  // The reason a state with points of det F <= 0 is rejected, for the
  // Newton log and the step's failure: the inverted points with the
  // smallest det F, and apart those where det F is not a number, whose
  // det F has no value to give (the displacement is finite, which the
  // assembly checked first, but its gradient's products overflow: inf -
  // inf), and those outside the material law's range with the law's
  // condition.
  template <int dim>
  std::string
  ContactProblem<dim>::inverted_state_reason() const
  {
    std::ostringstream reason;
    const unsigned int n_negative =
      n_inverted - n_undefined_det_F - n_outside_law;
    const auto separator = [&reason]() {
      return reason.tellp() > 0 ? "; " : "";
    };
    if (n_negative > 0)
      reason << "inverted elements: det F = " << min_det_F << " <= 0 at "
             << n_negative << " quadrature points";
    if (n_undefined_det_F > 0)
      reason << separator() << "det F is not a number at " << n_undefined_det_F
             << " quadrature points (the displacement "
             << "gradient overflows in it: an iterate far beyond any "
             << "physical state)";
    if (n_outside_law > 0)
      for (const Body<dim> &body : bodies)
        if (body.material_id == outside_law_body)
          reason << separator() << "outside the material law at "
                 << n_outside_law << " quadrature points (" << body.name
                 << " and maybe others): " << body.material.range_condition();
    return reason.str();
  }

  // Add a cell's (or face's) matrix and right-hand side -R to the system,
  // its force R to `force` (internal or external), and to each row the
  // magnitude of its terms: computed from the displacement alone, their
  // round-off is eps sum_j |K_ij| |u_j| (see residual_measure()). Without
  // the tangent, the right-hand side and the force alone.
  template <int dim>
  void
  ContactProblem<dim>::add_local_system(
    const FullMatrix<double>                   &matrix,
    const Vector<double>                       &rhs,
    const std::vector<types::global_dof_index> &dofs,
    Vector<double>                             &force,
    const unsigned int                          cell)
  {
    // Without the tangent the constraints are homogeneous (assemble_system()
    // makes sure of it), and condensing the right-hand side needs no matrix.
    if (!tangent_assembled)
      {
        for (unsigned int i = 0; i < dofs.size(); ++i)
          force(dofs[i]) -= rhs(i);
        system->add_rhs(update_constraints(), rhs, dofs);
        return;
      }
    for (unsigned int i = 0; i < dofs.size(); ++i)
      {
        force(dofs[i]) -= rhs(i);
        double magnitude = std::abs(rhs(i));
        for (unsigned int j = 0; j < dofs.size(); ++j)
          magnitude += std::abs(matrix(i, j)) * std::abs(solution(dofs[j]));
        residual_magnitude(dofs[i]) += magnitude;
      }
    // The faces of the boundary loads (no cell index) take the general
    // path through AffineConstraints.
    if (cell == numbers::invalid_unsigned_int)
      system->add(update_constraints(), matrix, rhs, dofs);
    else
      system->add_cell(cell, update_constraints(), matrix, rhs, dofs);
  }

  namespace
  {
    // cof(G) = det(G) G^-T, in two dimensions [[G11, -G10], [-G01, G00]]:
    // linear in G, so that cof(I + Grad u) = I + cof(Grad u) and its
    // derivative along phi_j is cof(Grad phi_j), exactly. In three it is
    // quadratic, cof(F + G) = cof(F) + cof'(F)[G] + cof(G), which gives the
    // derivative exactly from three cofactors (deal.II's).
    template <int dim>
    Tensor<2, dim>
    cof(const Tensor<2, dim> &G)
    {
      if constexpr (dim == 2)
        {
          Tensor<2, dim> C;
          C[0][0] = G[1][1];
          C[0][1] = -G[1][0];
          C[1][0] = -G[0][1];
          C[1][1] = G[0][0];
          return C;
        }
      else
        return cofactor(G);
    }

    /// The derivative of cof at F along G.
    template <int dim>
    Tensor<2, dim>
    cof_derivative(const Tensor<2, dim> &F, const Tensor<2, dim> &G)
    {
      if constexpr (dim == 2)
        return cof(G);
      else
        return Tensor<2, dim>(cof(F + G) - cof(F) - cof(G));
    }
  } // namespace

  // @sect4{The boundary loads}
  //
  // The scenario's boundary loads.
  // A pressure p on the current configuration: the load -p n da, with
  // n da = cof(F) N dA (Nanson; in two dimensions the cofactor det(F) F^-T
  // is linear in F), adds int p phi_i . cof(F) N dA to the residual and,
  // F = I + Grad u, the tangent int p phi_i . cof(Grad phi_j) N dA (not
  // symmetric). A body in small strain: the dead load, cof(F) = I. p is
  // evaluated at the reference position of the quadrature point.
  // A traction t per reference length: the dead load, - int phi_i . t dA
  // in the residual, no tangent.
  template <int dim>
  void
  ContactProblem<dim>::assemble_boundary_loads()
  {
    // The resultants of this assembly's state only (a follower pressure's
    // changes with the surface).
    applied_resultant.clear();
    applied_moment.clear();
    if (boundary_loads.empty())
      return;
    // p + 1 Gauss points on the faces of an element of degree p (the
    // FESystem's degree is its displacement's, which the multiplier's does
    // not exceed).
    hp::QCollection<dim - 1> face_q;
    for (unsigned int i = 0; i < q_collection.size(); ++i)
      face_q.push_back(QGauss<dim - 1>(fe_collection[i].degree + 1));
    hp::FEFaceValues<dim>                hp_face_values(mapping_collection,
                                         fe_collection,
                                         face_q,
                                         update_values | update_gradients |
                                           update_normal_vectors |
                                           update_quadrature_points |
                                           update_JxW_values);
    std::vector<types::global_dof_index> dofs;
    std::vector<Tensor<2, dim>>          grad_u;
    std::vector<Tensor<1, dim>>          u_at;
    FullMatrix<double>                   face_matrix;
    Vector<double>                       face_rhs;
    for (const BoundaryLoad<dim> &load : boundary_loads)
      for (const auto &cell : dof_handler.active_cell_iterators())
        for (const unsigned int f : cell->face_indices())
          if (cell->subdomain_id() == this_process &&
              cell->face(f)->at_boundary() &&
              cell->face(f)->boundary_id() == load.boundary_id)
            {
              hp_face_values.reinit(cell, f);
              const FEFaceValues<dim> &fv =
                hp_face_values.get_present_fe_values();
              const FiniteElement<dim> &fe = cell->get_fe();
              const unsigned int        n  = fe.n_dofs_per_cell();
              const bool                pressure =
                load.type == BoundaryLoad<dim>::Type::pressure;
              // Each body's kinematics: a body in finite (or logarithmic)
              // strain carries the pressure on its current surface.
              const bool follower =
                !materials.at(cell->material_id()).geometrically_linear;
              dofs.resize(n);
              cell->get_dof_indices(dofs);
              face_matrix.reinit(n, n);
              face_rhs.reinit(n);
              // Grad u on the face, for cof(F); the face values are those of
              // the reference configuration, and N is its outward normal.
              grad_u.resize(fv.n_quadrature_points);
              fv[displacement].get_function_gradients(solution, grad_u);
              u_at.resize(fv.n_quadrature_points);
              fv[displacement].get_function_values(solution, u_at);
              for (unsigned int q = 0; q < fv.n_quadrature_points; ++q)
                {
                  const Tensor<1, dim> value =
                    load.value(fv.quadrature_point(q), current_load);
                  // A pressure load's value is p in its first component; a
                  // traction's is the vector t itself.
                  const double         p  = value[0];
                  const Tensor<1, dim> N  = fv.normal_vector(q);
                  const double         dA = fv.JxW(q);
                  // The force per unit of the face's measure, times dA.
                  const Tensor<1, dim> force =
                    pressure ?
                      Tensor<1, dim>(
                        -p *
                        ((follower ?
                            cof(unit_symmetric_tensor<dim>() + grad_u[q]) :
                            Tensor<2, dim>(unit_symmetric_tensor<dim>())) *
                         N) *
                        dA) :
                      Tensor<1, dim>(value * dA);
                  // The integral of the load over its boundary, for the
                  // scenario's resultant checks.
                  applied_resultant[load.boundary_id] += force;
                  // Its moment about the origin, x x t dA, at the point's
                  // current position where the body is in finite strain.
                  Tensor<1, 3> x, t;
                  for (unsigned int d = 0; d < dim; ++d)
                    {
                      x[d] = fv.quadrature_point(q)[d] +
                             (follower ? u_at[q][d] : 0.);
                      t[d] = force[d];
                    }
                  applied_moment[load.boundary_id] += cross_product_3d(x, t);
                  for (unsigned int i = 0; i < n; ++i)
                    {
                      const unsigned int c =
                        fe.system_to_component_index(i).first;
                      if (!Components::is_displacement<dim>(c))
                        continue;
                      face_rhs(i) += fv.shape_value(i, q) * force[c];
                      // A dead load does not depend on u: no tangent.
                      if (!pressure || !follower)
                        continue;
                      for (unsigned int j = 0; j < n; ++j)
                        {
                          const unsigned int d =
                            fe.system_to_component_index(j).first;
                          if (!Components::is_displacement<dim>(d))
                            continue;
                          // Grad phi_j = e_d (x) grad(phi_j): its row d.
                          Tensor<2, dim> G;
                          G[d] = fv.shape_grad(j, q);
                          face_matrix(i, j) +=
                            p * fv.shape_value(i, q) *
                            (cof_derivative(unit_symmetric_tensor<dim>() +
                                              grad_u[q],
                                            G) *
                             N)[c] *
                            dA;
                        }
                    }
                }
              add_local_system(face_matrix, face_rhs, dofs, external_force);
            }
  }


  // This chapter's members for the dimensions the program runs in: the
  // explicit instantiation of the class in a chapter instantiates the
  // members defined here (see contact_problem.cc).
  template class ContactProblem<2>;
  template class ContactProblem<3>;
} // namespace RingContact
