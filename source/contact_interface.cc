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
                                     const double complementarity_constant,
                                     const bool   geometrically_linear)
    : slave(dof_handler, parameters.slave_boundary_id, mapping_degree)
    , master(dof_handler,
             parameters.master_boundary_id,
             mapping_degree,
             parameters.smooth_master_normals)
    , quadrature(contact_quadrature(scheme,
                                    slave.displacement_basis().size() - 1))
    , complementarity_constant(complementarity_constant)
    , geometrically_linear(geometrically_linear)
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
    segment_length = slave.min_segment_length();
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
    // Finite strain: pair and measure in the current configuration. Small
    // strain: pair in the reference configuration, and the gap is the
    // reference gap plus the normal jump of the displacement.
    if (geometrically_linear)
      {
        const Vector<double> zero(solution.size());
        slave.update(zero);
        master.update(zero);
      }
    else
      {
        slave.update(solution);
        master.update(solution);
      }

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
          if (geometrically_linear)
            point.projection.gap += linear_gap_increment(
              solution, s, quadrature.point(q)[0], point.projection);
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
        // Closed when w lambda - c g~ >= 0; a gap of round-off size (at
        // the start the surfaces touch exactly) counts as closed.
        const double round_off = 1e-12 * complementarity_constant *
                                 reference_weight[k] * segment_length;
        const bool closed = reference_weight[k] * lambda -
                              complementarity_constant * weighted_gap[k] >=
                            -round_off;
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
      {
        if (pattern_pairs.count(
              {point.slave_segment, point.projection.segment}) == 0)
          return false;
        if (point.projection.at_vertex &&
            pattern_pairs.count(
              {point.slave_segment, point.projection.neighbour}) == 0)
          return false;
        if (master.smooths_normals())
          for (const unsigned int b :
               master.segments()[point.projection.segment].neighbours)
            if (b != numbers::invalid_unsigned_int &&
                pattern_pairs.count({point.slave_segment, b}) == 0)
              return false;
      }
    return true;
  }

  void
  ContactInterface::add_couplings(DynamicSparsityPattern &dsp)
  {
    // Per slave segment, the master segments its points are paired with and
    // their neighbours (which enter through vertex and smoothed normals, and
    // which a slip may reach next): one block couples all their unknowns.
    pattern_pairs.clear();
    for (const auto &point : points)
      {
        pattern_pairs.insert({point.slave_segment, point.projection.segment});
        for (const unsigned int m :
             master_neighbours[point.projection.segment])
          pattern_pairs.insert({point.slave_segment, m});
      }
    std::map<unsigned int, std::vector<types::global_dof_index>> block;
    for (const auto &[s, m] : pattern_pairs)
      {
        auto &dofs = block[s];
        if (dofs.empty())
          for (const auto *list : {&slave.segments()[s].dofs_x,
                                   &slave.segments()[s].dofs_y,
                                   &slave.segments()[s].multiplier_dofs})
            dofs.insert(dofs.end(), list->begin(), list->end());
        for (const auto *list :
             {&master.segments()[m].dofs_x, &master.segments()[m].dofs_y})
          dofs.insert(dofs.end(), list->begin(), list->end());
      }
    for (auto &[s, dofs] : block)
      {
        std::sort(dofs.begin(), dofs.end());
        dofs.erase(std::unique(dofs.begin(), dofs.end()), dofs.end());
        for (const auto row : dofs)
          dsp.add_entries(row, dofs.begin(), dofs.end(), true);
      }
  }

  namespace
  {
    using AD = Sacado::Fad::DFad<double>;

    // A point of a segment in the current configuration with AD
    // coordinates: reference geometry (double) plus interpolated
    // displacement (AD); `with_displacement` = false keeps the reference
    // tangent (small strain).
    struct ADCurvePoint
    {
      AD x[2], dx[2], ddx[2];
    };

    ADCurvePoint
    ad_curve_point(const CurvePoint                &reference,
                   const std::vector<double>       &N,
                   const std::vector<double>       &dN,
                   const std::vector<double>       &ddN,
                   const AD                        *u_x,
                   const AD                        *u_y,
                   const bool                       with_displacement)
    {
      ADCurvePoint p;
      for (unsigned int d = 0; d < 2; ++d)
        {
          p.x[d]   = reference.x[d];
          p.dx[d]  = reference.dx[d];
          p.ddx[d] = reference.ddx[d];
        }
      for (unsigned int i = 0; i < N.size(); ++i)
        {
          p.x[0] += N[i] * u_x[i];
          p.x[1] += N[i] * u_y[i];
          if (!with_displacement)
            continue;
          p.dx[0] += dN[i] * u_x[i];
          p.dx[1] += dN[i] * u_y[i];
          p.ddx[0] += ddN[i] * u_x[i];
          p.ddx[1] += ddN[i] * u_y[i];
        }
      return p;
    }
  } // namespace

  void
  ContactInterface::assemble(const Vector<double>            &solution,
                             const AffineConstraints<double> &constraints,
                             SparseMatrix<double>            &matrix,
                             Vector<double>                  &rhs) const
  {
    const double c       = complementarity_constant;
    const bool   current = !geometrically_linear;

    std::vector<types::global_dof_index> local_dofs, unique_dofs;
    FullMatrix<double>                   local_matrix;
    Vector<double>                       local_rhs;
    std::vector<double> Nm, dNm, ddNm, Nb, dNb, ddNb;
    const std::vector<double> none;

    const bool smooth = master.smooths_normals();
    for (const auto &point : points)
      {
        const Projection &projection = point.projection;
        const auto &s_seg = slave.segments()[point.slave_segment];
        const auto &m_seg = master.segments()[projection.segment];

        // Master segments whose displacement enters: the partner, and the
        // neighbours that define the normal (at a vertex: the other segment
        // there; smoothed normals: both neighbours of the partner).
        std::vector<unsigned int> master_segments = {projection.segment};
        if (smooth)
          {
            for (const unsigned int b : m_seg.neighbours)
              if (b != numbers::invalid_unsigned_int)
                master_segments.push_back(b);
          }
        else if (projection.at_vertex)
          master_segments.push_back(projection.neighbour);

        // Local unknowns: slave u_x, u_y, then u_x, u_y of each master
        // segment, then the multipliers.
        const unsigned int ns = s_seg.dofs_x.size();
        const unsigned int nl = s_seg.multiplier_dofs.size();
        local_dofs.clear();
        local_dofs.insert(local_dofs.end(),
                          s_seg.dofs_x.begin(),
                          s_seg.dofs_x.end());
        local_dofs.insert(local_dofs.end(),
                          s_seg.dofs_y.begin(),
                          s_seg.dofs_y.end());
        std::map<unsigned int, unsigned int> offset_of; // segment -> u_x
        for (const unsigned int m : master_segments)
          {
            const auto &seg = master.segments()[m];
            offset_of[m]    = local_dofs.size();
            local_dofs.insert(local_dofs.end(),
                              seg.dofs_x.begin(),
                              seg.dofs_x.end());
            local_dofs.insert(local_dofs.end(),
                              seg.dofs_y.begin(),
                              seg.dofs_y.end());
          }
        const unsigned int lambda_offset = local_dofs.size();
        local_dofs.insert(local_dofs.end(),
                          s_seg.multiplier_dofs.begin(),
                          s_seg.multiplier_dofs.end());
        const unsigned int n = local_dofs.size();
        std::vector<AD>    u(n);
        for (unsigned int i = 0; i < n; ++i)
          u[i] = AD(n, i, solution(local_dofs[i]));
        const AD *us_x = &u[0], *us_y = &u[ns];
        const AD *lambda_k = &u[lambda_offset];

        // A point of a master segment in AD numbers.
        const auto master_point = [&](const unsigned int m, const double t) {
          const unsigned int nm = master.segments()[m].dofs_x.size();
          master.displacement_basis().evaluate(t, Nb, dNb, ddNb);
          return ad_curve_point(master.reference_point(m, t),
                                Nb,
                                dNb,
                                ddNb,
                                &u[offset_of[m]],
                                &u[offset_of[m] + nm],
                                current);
        };
        // Outward normal scaled by |x'| of a master segment at t.
        const auto scaled_normal = [&](const unsigned int m, const double t,
                                       AD *normal_out) {
          const ADCurvePoint p = master_point(m, t);
          const double       o = master.segments()[m].orientation;
          normal_out[0]        = o * p.dx[1];
          normal_out[1]        = -o * p.dx[0];
        };
        // Unit vertex normal at the end `end` of the partner segment.
        const auto vertex_normal = [&](const unsigned int end, AD *n_out) {
          scaled_normal(projection.segment, end, n_out);
          const unsigned int b = m_seg.neighbours[end];
          if (b != numbers::invalid_unsigned_int)
            {
              AD other[2];
              scaled_normal(b, m_seg.neighbour_t[end], other);
              n_out[0] += other[0];
              n_out[1] += other[1];
            }
          const AD length = std::sqrt(n_out[0] * n_out[0] + n_out[1] * n_out[1]);
          n_out[0] /= length;
          n_out[1] /= length;
        };

        // Slave point, its length element and the pressure there.
        const unsigned int q = point.quadrature_point;
        CurvePoint         Xs;
        for (unsigned int j = 0; j < s_seg.reference_nodes.size(); ++j)
          {
            Xs.x += geometry_values[q][j] * s_seg.reference_nodes[j];
            Xs.dx += geometry_gradients[q][j] * s_seg.reference_nodes[j];
          }
        const ADCurvePoint xs = ad_curve_point(Xs,
                                               displacement_values[q],
                                               displacement_gradients[q],
                                               displacement_gradients[q],
                                               us_x,
                                               us_y,
                                               current);
        const AD ds = std::sqrt(xs.dx[0] * xs.dx[0] + xs.dx[1] * xs.dx[1]) *
                      quadrature.weight(q);
        const auto &Phi    = multiplier_values[q];
        AD          lambda = 0;
        for (unsigned int k = 0; k < nl; ++k)
          lambda += Phi[k] * lambda_k[k];

        // Master point at the converged parameter xi0, and its first-order
        // correction d xi = -f / f' where f(xi) = 0 defines the projection:
        // its value vanishes, its derivative is that of the projection
        // (implicit function theorem). Closest point: f = (x_s - x_m) . x_m';
        // along the smoothed normal m(xi) = (1 - xi) n0 + xi n1:
        // f = (x_s - x_m) x m. At a vertex or a clamped corner xi is fixed.
        const double xi0 = projection.t;
        master.displacement_basis().evaluate(xi0, Nm, dNm, ddNm);
        const ADCurvePoint xm = master_point(projection.segment, xi0);
        AD                 n0[2], n1[2];
        if (smooth)
          {
            vertex_normal(0, n0);
            vertex_normal(1, n1);
          }
        const AD d[2] = {xs.x[0] - xm.x[0], xs.x[1] - xm.x[1]};
        AD       dxi  = 0;
        if (!projection.clamped && !projection.at_vertex && current)
          {
            if (smooth)
              {
                const AD m[2]  = {(1 - xi0) * n0[0] + xi0 * n1[0],
                                  (1 - xi0) * n0[1] + xi0 * n1[1]};
                const AD f     = d[0] * m[1] - d[1] * m[0];
                const AD slope = -(xm.dx[0] * m[1] - xm.dx[1] * m[0]) +
                                 d[0] * (n1[1] - n0[1]) -
                                 d[1] * (n1[0] - n0[0]);
                dxi = -f / slope;
              }
            else
              {
                const AD r = d[0] * xm.dx[0] + d[1] * xm.dx[1];
                const AD slope =
                  -(xm.dx[0] * xm.dx[0] + xm.dx[1] * xm.dx[1]) +
                  d[0] * xm.ddx[0] + d[1] * xm.ddx[1];
                dxi = -r / slope;
              }
          }
        AD x_m[2], normal[2];
        for (unsigned int dim = 0; dim < 2; ++dim)
          x_m[dim] = xm.x[dim] + xm.dx[dim] * dxi;
        if (smooth)
          {
            const AD xi = xi0 + dxi;
            normal[0]   = (1 - xi) * n0[0] + xi * n1[0];
            normal[1]   = (1 - xi) * n0[1] + xi * n1[1];
          }
        else
          {
            // Outward normal scaled by |x_m'|; at a vertex the sum over the
            // two segments (length-weighted average).
            const double o = m_seg.orientation;
            normal[0]      = o * (xm.dx[1] + xm.ddx[1] * dxi);
            normal[1]      = -o * (xm.dx[0] + xm.ddx[0] * dxi);
            if (projection.at_vertex)
              {
                AD other[2];
                scaled_normal(projection.neighbour,
                              projection.neighbour_t,
                              other);
                normal[0] += other[0];
                normal[1] += other[1];
              }
          }
        {
          const AD length =
            std::sqrt(normal[0] * normal[0] + normal[1] * normal[1]);
          normal[0] /= length;
          normal[1] /= length;
        }
        const AD gap =
          (xs.x[0] - x_m[0]) * normal[0] + (xs.x[1] - x_m[1]) * normal[1];

        // Residual: contact virtual work and weighted gap rows.
        std::vector<AD> residual(n, AD(0.0));
        const auto     &N = displacement_values[q];
        for (unsigned int i = 0; i < ns; ++i)
          for (unsigned int dim = 0; dim < 2; ++dim)
            residual[dim * ns + i] = -lambda * N[i] * normal[dim] * ds;
        const unsigned int nm = m_seg.dofs_x.size();
        const unsigned int mo = offset_of[projection.segment];
        for (unsigned int i = 0; i < nm; ++i)
          {
            const AD Nm_xi = Nm[i] + dNm[i] * dxi;
            for (unsigned int dim = 0; dim < 2; ++dim)
              residual[mo + dim * nm + i] = lambda * Nm_xi * normal[dim] * ds;
          }
        for (unsigned int k = 0; k < nl; ++k)
          if (active[multiplier_index.at(s_seg.multiplier_dofs[k])])
            residual[lambda_offset + k] = c * Phi[k] * gap * ds;

        // A vertex shared by the partner and its neighbour appears twice in
        // the local unknowns: sum the two copies (rows and columns) into one
        // before handing the element to the global system.
        unique_dofs = local_dofs;
        std::sort(unique_dofs.begin(), unique_dofs.end());
        unique_dofs.erase(std::unique(unique_dofs.begin(), unique_dofs.end()),
                          unique_dofs.end());
        std::vector<unsigned int> to_unique(n);
        for (unsigned int i = 0; i < n; ++i)
          to_unique[i] = std::lower_bound(unique_dofs.begin(),
                                          unique_dofs.end(),
                                          local_dofs[i]) -
                         unique_dofs.begin();
        local_matrix.reinit(unique_dofs.size(), unique_dofs.size());
        local_rhs.reinit(unique_dofs.size());
        for (unsigned int i = 0; i < n; ++i)
          {
            local_rhs(to_unique[i]) -= residual[i].val();
            for (unsigned int j = 0; j < n; ++j)
              local_matrix(to_unique[i], to_unique[j]) += residual[i].dx(j);
          }
        constraints.distribute_local_to_global(
          local_matrix, local_rhs, unique_dofs, matrix, rhs);
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

  double
  ContactInterface::linear_gap_increment(const Vector<double> &solution,
                                         const unsigned int    slave_segment,
                                         const double          t,
                                         const Projection     &projection) const
  {
    const auto displacement_at = [&](const ContactSurface &surface,
                                     const unsigned int    segment,
                                     const double          t) {
      std::vector<double> N;
      surface.displacement_basis().evaluate(t, N);
      const auto  &seg = surface.segments()[segment];
      Tensor<1, 2> u;
      for (unsigned int i = 0; i < N.size(); ++i)
        {
          u[0] += N[i] * solution(seg.dofs_x[i]);
          u[1] += N[i] * solution(seg.dofs_y[i]);
        }
      return u;
    };
    const Tensor<1, 2> jump =
      displacement_at(slave, slave_segment, t) -
      displacement_at(master, projection.segment, projection.t);
    // The surfaces hold the reference configuration here.
    return jump * master.normal(projection);
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
  ContactInterface::gap_at(const types::global_dof_index dof,
                          const Vector<double>         &solution) const
  {
    for (unsigned int s = 0; s < slave.segments().size(); ++s)
      {
        double t;
        if (node_parameter(slave, slave.segments()[s], dof, t))
          {
            Projection p = master.project(slave.current_point(s, t).x);
            if (geometrically_linear)
              p.gap += linear_gap_increment(solution, s, t, p);
            return p.gap;
          }
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
