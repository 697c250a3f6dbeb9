#include <deal.II/base/quadrature_lib.h>
#include <deal.II/differentiation/ad/sacado_number_types.h>
#include <deal.II/lac/full_matrix.h>

#include <ring_contact/contact_interface.h>

#include <algorithm>
#include <cmath>

namespace RingContact
{
  ContactInterface::ContactInterface(const DoFHandler<2>     &dof_handler,
                                     const ContactParameters &parameters,
                                     const IntegrationScheme &scheme,
                                     const unsigned int       mapping_degree,
                                     const double complementarity_constant)
    : slave(dof_handler, parameters.slave_boundary_id, mapping_degree)
    , master(dof_handler, parameters.master_boundary_id, mapping_degree)
    , quadrature(contact_quadrature(scheme,
                                    slave.displacement_basis().size() - 1))
    , complementarity_constant(complementarity_constant)
  {
    // Basis values at the quadrature points of a slave segment.
    for (const auto &q : quadrature.get_points())
      {
        std::vector<double> N, dN, ddN;
        slave.geometry_basis().evaluate(q[0], N, dN, ddN);
        geometry_values.push_back(N);
        geometry_gradients.push_back(dN);
        slave.displacement_basis().evaluate(q[0], N, dN, ddN);
        displacement_values.push_back(N);
        displacement_gradients.push_back(dN);
        slave.multiplier_basis().evaluate(q[0], N);
        multiplier_values.push_back(N);
      }

    // The multiplier nodes, and w_k = int Phi_k dS with a rule that is exact
    // for the multiplier times the reference length element.
    const QGauss<1> exact(slave.geometry_basis().size() +
                          slave.multiplier_basis().size());
    for (unsigned int s = 0; s < slave.segments().size(); ++s)
      {
        const auto &segment = slave.segments()[s];
        for (const auto dof : segment.multiplier_dofs)
          if (multiplier_index.count(dof) == 0)
            {
              multiplier_index[dof] = multiplier_dof_list.size();
              multiplier_dof_list.push_back(dof);
              reference_weight.push_back(0.0);
            }
        for (unsigned int q = 0; q < exact.size(); ++q)
          {
            std::vector<double> Phi;
            slave.multiplier_basis().evaluate(exact.point(q)[0], Phi);
            const double dS =
              slave.reference_point(s, exact.point(q)[0]).dx.norm() *
              exact.weight(q);
            for (unsigned int k = 0; k < Phi.size(); ++k)
              reference_weight[multiplier_index[segment.multiplier_dofs[k]]] +=
                Phi[k] * dS;
          }
      }
    weighted_gap.assign(multiplier_dof_list.size(), 0.0);
    active.assign(multiplier_dof_list.size(), true);

    // Neighbours on the master surface: segments that share a vertex.
    std::map<unsigned int, std::vector<unsigned int>> segments_at_vertex;
    for (unsigned int m = 0; m < master.segments().size(); ++m)
      for (const unsigned int v : master.segments()[m].vertices)
        segments_at_vertex[v].push_back(m);
    master_neighbours.resize(master.segments().size());
    for (unsigned int m = 0; m < master.segments().size(); ++m)
      for (const unsigned int v : master.segments()[m].vertices)
        for (const unsigned int other : segments_at_vertex[v])
          if (other != m)
            master_neighbours[m].push_back(other);
  }

  unsigned int
  ContactInterface::update(const Vector<double> &solution)
  {
    slave.update(solution);
    master.update(solution);

    // Pair every slave quadrature point; keep the previous partner on ties.
    std::vector<ContactPoint> new_points;
    new_points.reserve(slave.segments().size() * quadrature.size());
    for (unsigned int s = 0; s < slave.segments().size(); ++s)
      for (unsigned int q = 0; q < quadrature.size(); ++q)
        {
          const unsigned int index = new_points.size();
          const unsigned int preferred =
            index < points.size() ? points[index].projection.segment :
                                    numbers::invalid_unsigned_int;
          const CurvePoint x = slave.current_point(s, quadrature.point(q)[0]);
          ContactPoint     point;
          point.slave_segment    = s;
          point.quadrature_point = q;
          point.projection       = master.project(x.x, preferred);
          point.current_length   = x.dx.norm() * quadrature.weight(q);
          new_points.push_back(point);
        }
    points = std::move(new_points);

    // Weighted gaps and the active set from the current multipliers.
    std::fill(weighted_gap.begin(), weighted_gap.end(), 0.0);
    for (const auto &point : points)
      {
        const auto &segment = slave.segments()[point.slave_segment];
        const auto &Phi     = multiplier_values[point.quadrature_point];
        for (unsigned int k = 0; k < Phi.size(); ++k)
          weighted_gap[multiplier_index[segment.multiplier_dofs[k]]] +=
            Phi[k] * point.projection.gap * point.current_length;
      }
    unsigned int n_changed = 0;
    for (unsigned int k = 0; k < multiplier_dof_list.size(); ++k)
      {
        const double lambda = solution(multiplier_dof_list[k]);
        const bool   closed = reference_weight[k] * lambda -
                              complementarity_constant * weighted_gap[k] >=
                            0;
        if (closed != active[k])
          ++n_changed;
        active[k] = closed;
      }
    return n_changed;
  }

  bool
  ContactInterface::sparsity_covers_pairing() const
  {
    for (const auto &point : points)
      if (pattern_pairs.count(
            {point.slave_segment, point.projection.segment}) == 0)
        return false;
    return true;
  }

  void
  ContactInterface::add_couplings(DynamicSparsityPattern &dsp)
  {
    pattern_pairs.clear();
    for (const auto &point : points)
      {
        pattern_pairs.insert({point.slave_segment, point.projection.segment});
        for (const unsigned int m :
             master_neighbours[point.projection.segment])
          pattern_pairs.insert({point.slave_segment, m});
      }
    for (const auto &[s, m] : pattern_pairs)
      {
        const auto &slave_segment  = slave.segments()[s];
        const auto &master_segment = master.segments()[m];
        std::vector<types::global_dof_index> dofs;
        for (const auto *list : {&slave_segment.dofs_x,
                                 &slave_segment.dofs_y,
                                 &master_segment.dofs_x,
                                 &master_segment.dofs_y,
                                 &slave_segment.multiplier_dofs})
          dofs.insert(dofs.end(), list->begin(), list->end());
        std::sort(dofs.begin(), dofs.end());
        for (const auto row : dofs)
          dsp.add_entries(row, dofs.begin(), dofs.end(), true);
      }
  }

  void
  ContactInterface::assemble(const Vector<double>            &solution,
                             const AffineConstraints<double> &constraints,
                             SparseMatrix<double>            &matrix,
                             Vector<double>                  &rhs) const
  {
    using AD = Sacado::Fad::DFad<double>;
    const double c = complementarity_constant;

    std::vector<types::global_dof_index> local_dofs;
    FullMatrix<double>                   local_matrix;
    Vector<double>                       local_rhs;
    std::vector<double> Nm, dNm, ddNm;

    for (const auto &point : points)
      {
        const auto &s_seg = slave.segments()[point.slave_segment];
        const auto &m_seg = master.segments()[point.projection.segment];
        const unsigned int ns = s_seg.dofs_x.size();
        const unsigned int nm = m_seg.dofs_x.size();
        const unsigned int nl = s_seg.multiplier_dofs.size();
        const unsigned int n  = 2 * ns + 2 * nm + nl;

        // Local unknowns: slave u_x, u_y, master u_x, u_y, multipliers.
        local_dofs.clear();
        for (const auto *list : {&s_seg.dofs_x,
                                 &s_seg.dofs_y,
                                 &m_seg.dofs_x,
                                 &m_seg.dofs_y,
                                 &s_seg.multiplier_dofs})
          local_dofs.insert(local_dofs.end(), list->begin(), list->end());
        std::vector<AD> u(n);
        for (unsigned int i = 0; i < n; ++i)
          u[i] = AD(n, i, solution(local_dofs[i]));
        const AD *us_x = &u[0], *us_y = &u[ns], *um_x = &u[2 * ns],
                 *um_y = &u[2 * ns + nm], *lambda_k = &u[2 * ns + 2 * nm];

        // Slave point, its length element and the pressure there.
        const unsigned int q  = point.quadrature_point;
        const auto        &G  = geometry_values[q];
        const auto        &dG = geometry_gradients[q];
        const auto        &N  = displacement_values[q];
        const auto        &dN = displacement_gradients[q];
        const auto        &Phi = multiplier_values[q];
        AD xs[2] = {0, 0}, dxs[2] = {0, 0};
        for (unsigned int j = 0; j < G.size(); ++j)
          for (unsigned int d = 0; d < 2; ++d)
            {
              xs[d] += G[j] * s_seg.reference_nodes[j][d];
              dxs[d] += dG[j] * s_seg.reference_nodes[j][d];
            }
        for (unsigned int i = 0; i < ns; ++i)
          {
            xs[0] += N[i] * us_x[i];
            xs[1] += N[i] * us_y[i];
            dxs[0] += dN[i] * us_x[i];
            dxs[1] += dN[i] * us_y[i];
          }
        const AD ds =
          std::sqrt(dxs[0] * dxs[0] + dxs[1] * dxs[1]) * quadrature.weight(q);
        AD lambda = 0;
        for (unsigned int k = 0; k < nl; ++k)
          lambda += Phi[k] * lambda_k[k];

        // Master point at the converged parameter xi0, and its first-order
        // correction d xi = -r / r' with r = (x_s - x_m) . x_m': its value
        // vanishes, its derivative is that of the projection (implicit
        // function theorem). A clamped projection (corner) keeps xi fixed.
        const double     xi0 = point.projection.t;
        const CurvePoint Xm  = master.reference_point(point.projection.segment, xi0);
        master.displacement_basis().evaluate(xi0, Nm, dNm, ddNm);
        AD xm[2], txm[2], ttxm[2];
        for (unsigned int d = 0; d < 2; ++d)
          {
            xm[d]   = Xm.x[d];
            txm[d]  = Xm.dx[d];
            ttxm[d] = Xm.ddx[d];
          }
        for (unsigned int i = 0; i < nm; ++i)
          {
            xm[0] += Nm[i] * um_x[i];
            xm[1] += Nm[i] * um_y[i];
            txm[0] += dNm[i] * um_x[i];
            txm[1] += dNm[i] * um_y[i];
            ttxm[0] += ddNm[i] * um_x[i];
            ttxm[1] += ddNm[i] * um_y[i];
          }
        AD dxi = 0;
        if (!point.projection.clamped)
          {
            const AD r = (xs[0] - xm[0]) * txm[0] + (xs[1] - xm[1]) * txm[1];
            const AD slope = -(txm[0] * txm[0] + txm[1] * txm[1]) +
                             (xs[0] - xm[0]) * ttxm[0] +
                             (xs[1] - xm[1]) * ttxm[1];
            dxi = -r / slope;
          }
        AD x_m[2], t_m[2];
        for (unsigned int d = 0; d < 2; ++d)
          {
            x_m[d] = xm[d] + txm[d] * dxi;
            t_m[d] = txm[d] + ttxm[d] * dxi;
          }
        const AD t_norm = std::sqrt(t_m[0] * t_m[0] + t_m[1] * t_m[1]);
        const AD normal[2] = {m_seg.orientation * t_m[1] / t_norm,
                              -m_seg.orientation * t_m[0] / t_norm};
        const AD gap =
          (xs[0] - x_m[0]) * normal[0] + (xs[1] - x_m[1]) * normal[1];

        // Residual: contact virtual work and weighted gap rows.
        std::vector<AD> residual(n, AD(0.0));
        for (unsigned int i = 0; i < ns; ++i)
          for (unsigned int d = 0; d < 2; ++d)
            residual[d * ns + i] = -lambda * N[i] * normal[d] * ds;
        for (unsigned int i = 0; i < nm; ++i)
          {
            const AD Nm_xi = Nm[i] + dNm[i] * dxi;
            for (unsigned int d = 0; d < 2; ++d)
              residual[2 * ns + d * nm + i] = lambda * Nm_xi * normal[d] * ds;
          }
        for (unsigned int k = 0; k < nl; ++k)
          if (active[multiplier_index.at(s_seg.multiplier_dofs[k])])
            residual[2 * ns + 2 * nm + k] = c * Phi[k] * gap * ds;

        local_matrix.reinit(n, n);
        local_rhs.reinit(n);
        for (unsigned int i = 0; i < n; ++i)
          {
            local_rhs(i) = -residual[i].val();
            for (unsigned int j = 0; j < n; ++j)
              local_matrix(i, j) = residual[i].dx(j);
          }
        constraints.distribute_local_to_global(
          local_matrix, local_rhs, local_dofs, matrix, rhs);
      }

    // Open nodes: w_k lambda_k = 0.
    for (unsigned int k = 0; k < multiplier_dof_list.size(); ++k)
      if (!active[k])
        {
          const auto dof = multiplier_dof_list[k];
          matrix.add(dof, dof, reference_weight[k]);
          rhs(dof) -= reference_weight[k] * solution(dof);
        }
  }

  unsigned int
  ContactInterface::n_active() const
  {
    return std::count(active.begin(), active.end(), true);
  }

  types::global_dof_index
  ContactInterface::multiplier_dof_nearest_to(const Point<2> &point) const
  {
    double                  best = std::numeric_limits<double>::max();
    types::global_dof_index dof  = numbers::invalid_dof_index;
    for (unsigned int s = 0; s < slave.segments().size(); ++s)
      for (unsigned int k = 0; k < slave.multiplier_nodes().size(); ++k)
        {
          const double distance = point.distance(
            slave.reference_point(s, slave.multiplier_nodes()[k]).x);
          if (distance < best)
            {
              best = distance;
              dof  = slave.segments()[s].multiplier_dofs[k];
            }
        }
    return dof;
  }

  namespace
  {
    // The parameter t of a multiplier dof on a segment, if it is there.
    bool
    node_parameter(const ContactSurface         &surface,
                   const SurfaceSegment         &segment,
                   const types::global_dof_index dof,
                   double                       &t)
    {
      const auto it = std::find(segment.multiplier_dofs.begin(),
                                segment.multiplier_dofs.end(),
                                dof);
      if (it == segment.multiplier_dofs.end())
        return false;
      t = surface.multiplier_nodes()[it - segment.multiplier_dofs.begin()];
      return true;
    }
  } // namespace

  double
  ContactInterface::stretch_at(const types::global_dof_index dof) const
  {
    double       sum = 0;
    unsigned int n   = 0;
    for (unsigned int s = 0; s < slave.segments().size(); ++s)
      {
        double t;
        if (node_parameter(slave, slave.segments()[s], dof, t))
          {
            sum += slave.current_point(s, t).dx.norm() /
                   slave.reference_point(s, t).dx.norm();
            ++n;
          }
      }
    return n > 0 ? sum / n : 1.0;
  }

  double
  ContactInterface::gap_at(const types::global_dof_index dof) const
  {
    for (unsigned int s = 0; s < slave.segments().size(); ++s)
      {
        double t;
        if (node_parameter(slave, slave.segments()[s], dof, t))
          return master.project(slave.current_point(s, t).x).gap;
      }
    return 0.0;
  }

  double
  ContactInterface::l2_relative_error(const Vector<double> &solution,
                                      const double          reference,
                                      const PressureMeasure measure) const
  {
    const QGauss<1>     rule(slave.displacement_basis().size() + 2);
    double              error = 0, norm = 0;
    std::vector<double> Phi;
    for (unsigned int s = 0; s < slave.segments().size(); ++s)
      {
        const auto &segment = slave.segments()[s];
        for (unsigned int q = 0; q < rule.size(); ++q)
          {
            const double t = rule.point(q)[0];
            slave.multiplier_basis().evaluate(t, Phi);
            double lambda = 0;
            for (unsigned int k = 0; k < Phi.size(); ++k)
              lambda += Phi[k] * solution(segment.multiplier_dofs[k]);
            const double ds = slave.current_point(s, t).dx.norm();
            const double dS = slave.reference_point(s, t).dx.norm();
            // Cauchy: lambda over ds; nominal: lambda ds/dS over dS.
            const double pressure =
              measure == PressureMeasure::cauchy ? lambda : lambda * ds / dS;
            const double length =
              (measure == PressureMeasure::cauchy ? ds : dS) * rule.weight(q);
            error += (pressure - reference) * (pressure - reference) * length;
            norm += reference * reference * length;
          }
      }
    return std::sqrt(error / norm);
  }
} // namespace RingContact
