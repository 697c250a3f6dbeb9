// The contact element: the residual of one slave quadrature point paired
// with its master partner, and its exact derivative by forward automatic
// differentiation (Sacado). See contact_interface.h for the weak form.
#include <deal.II/differentiation/ad/sacado_number_types.h>
#include <deal.II/lac/full_matrix.h>

#include <ring_contact/contact_interface.h>
#include <ring_contact/surface_kernel.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace RingContact
{
  namespace
  {
    // The most local unknowns of a contact element: a slave segment's
    // displacements, four master segments' (the partner, its two
    // neighbours, and with friction the old partner), the multipliers and
    // the tangential tractions. AD numbers of a static capacity (their
    // derivatives sized to the element's unknowns at run time) need no
    // allocation: with dynamic ones, C's assembly on the seed mesh took
    // 1.1 ms per iteration instead of 0.9 ms (bench/alternate --seed). The
    // capacity of degree 2 (2 x 3 + 4 x 2 x 3 + 3 + 3 = 36) serves the
    // linear and quadratic surfaces; the elements of cubic and quartic ones
    // (up to 2 x 5 + 4 x 2 x 5 + 5 + 5 = 60) take numbers of that capacity:
    // with those for every element, C's assembly took 38 % longer.
    constexpr unsigned int small_capacity = 2 * 3 + 4 * 2 * 3 + 3 + 3;
    constexpr unsigned int large_capacity = 2 * 5 + 4 * 2 * 5 + 5 + 5;
    using SmallAD = Sacado::Fad::SLFad<double, small_capacity>;
    using LargeAD = Sacado::Fad::SLFad<double, large_capacity>;

    // A point of a segment in the current configuration with AD
    // coordinates: reference geometry (double) plus interpolated
    // displacement (AD); `with_displacement` = false keeps the reference
    // tangent (small strain).
    template <typename AD>
    SurfaceKernel::CurvePoint<AD>
    ad_curve_point(const CurvePoint          &reference,
                   const std::vector<double> &N,
                   const std::vector<double> &dN,
                   const std::vector<double> &ddN,
                   const AD                  *u_x,
                   const AD                  *u_y,
                   const bool                 with_displacement)
    {
      SurfaceKernel::CurvePoint<AD> p;
      for (unsigned int d = 0; d < 2; ++d)
        {
          p.x[d]   = reference.x[d];
          p.dx[d]  = reference.dx[d];
          p.ddx[d] = reference.ddx[d];
        }
      SurfaceKernel::add_interpolation(p,
                                       N.size(),
                                       N.data(),
                                       with_displacement ? dN.data() : nullptr,
                                       with_displacement ? ddN.data() : nullptr,
                                       [&](const unsigned int i) {
                                         Tensor<1, 2, AD> v;
                                         v[0] = u_x[i];
                                         v[1] = u_y[i];
                                         return v;
                                       });
      return p;
    }

    // Friction: the last converged solution and the surfaces in that state.
    struct ConvergedState
    {
      const Vector<double> &solution;
      const ContactSurface &slave;
      const ContactSurface &master;
    };

    // The contact element of one slave point and its partner: the local
    // unknowns as AD variables, then the slave point, the partner and the
    // normal, the residual, and its value and exact derivative scattered
    // into the global system. Each step is a member function, in the order
    // ContactInterface::assemble() calls them.
    //
    // ElementLayout is the part that does not depend on the number type:
    // which unknowns enter. Local layout: slave u_x, u_y, then u_x, u_y of
    // each master segment whose displacement enters (the partner, and the
    // neighbours that define the normal: at a vertex the other segment
    // there; smoothed normals and segment-based pieces: both neighbours of
    // the partner; with friction the old partner), then the multipliers,
    // then (friction) the tangential tractions.
    class ElementLayout
    {
    public:
      ElementLayout(const ContactSurface &slave,
                    const ContactSurface &master,
                    const ContactPoint   &point,
                    const bool            current,
                    const bool            segment_based,
                    const ConvergedState *converged);

      unsigned int
      n_unknowns() const
      {
        return local_dofs.size();
      }

    protected:
      const ContactSurface &slave;
      const ContactSurface &master;
      const ContactPoint   &point;
      const Projection     &projection;
      const SurfaceSegment &s_seg;
      const SurfaceSegment &m_seg;
      /// Finite strain: the current configuration (else the reference
      /// tangent, small strain).
      const bool current;
      const bool smooth;
      const bool segment_based;
      /// Friction: the last converged state (nullptr: frictionless).
      const ConvergedState *converged;

      std::vector<types::global_dof_index> local_dofs;
      std::map<unsigned int, unsigned int> offset_of; // segment -> its u_x
      unsigned int ns = 0, nl = 0, lambda_offset = 0, tangential_offset = 0;
    };

    template <typename AD>
    class ContactElement : public ElementLayout
    {
    public:
      using ADPoint  = SurfaceKernel::CurvePoint<AD>;
      using ADVector = Tensor<1, 2, AD>;

      /// The layout's unknowns must fit the AD numbers' capacity.
      explicit ContactElement(const ElementLayout &layout)
          : ElementLayout(layout)
      {}

      void
      gather_unknowns(const Vector<double> &solution,
                      const bool            derivatives = true);
      void
      evaluate_slave_point();
      void
      evaluate_partner_and_normal();
      AD
      slip() const;
      std::vector<AD>
      residual(
        const double                                        c,
        const std::function<bool(types::global_dof_index)> &active,
        const std::function<int(types::global_dof_index)>  &friction_state,
        const double                                        mu) const;
      /// Phi_k at the slave point and the local index of each multiplier.
      AD
      multiplier_basis(const unsigned int k) const
      {
        return Phi_eta[k];
      }
      AD
      length_element() const
      {
        return ds;
      }
      void
      scatter(std::vector<AD>                 &residual,
              const AffineConstraints<double> &constraints,
              LinearSystem                    &system);
      /// The residual's values added to `v`, unconstrained.
      void
      add_values(std::vector<AD> &residual, Vector<double> &v);

    private:
      std::array<AD, 2>
      piece_ends();
      ADPoint
      master_point(const unsigned int m, const double t) const;
      ADVector
      scaled_normal(const unsigned int m, const double t) const;
      ADVector
      vertex_normal(const unsigned int end) const;
      void
      turn_copies(std::vector<AD> &v, const bool back) const;

      std::vector<AD> u;

      // The slave point.
      std::vector<double> N, dN, ddN, Phi, dPhi, ddPhi;
      AD                  d_eta, ds, lambda, lambda_t;
      ADPoint             xs;
      /// Its reference position and its displacement, apart (see the gap).
      ADVector xs_reference, us;
      std::vector<AD>     Phi_eta, N_eta;

      // The partner and the normal.
      std::vector<double> Nm, dNm, ddNm;
      AD                  dxi, gap;
      ADVector            normal;
    };

    ElementLayout::ElementLayout(const ContactSurface &slave,
                                 const ContactSurface &master,
                                 const ContactPoint   &point,
                                 const bool            current,
                                 const bool            segment_based,
                                 const ConvergedState *converged)
        : slave(slave)
        , master(master)
        , point(point)
        , projection(point.projection)
        , s_seg(slave.segments()[point.slave_segment])
        , m_seg(master.segments()[projection.segment])
        , current(current)
        , smooth(master.smooths_normals())
        , segment_based(segment_based)
        , converged(converged)
    {
      std::vector<unsigned int> master_segments = {projection.segment};
      if (smooth || segment_based)
        {
          for (const unsigned int b : m_seg.neighbours)
            if (b != numbers::invalid_unsigned_int)
              master_segments.push_back(b);
        }
      else if (projection.at_vertex)
        master_segments.push_back(
          m_seg.neighbours[static_cast<unsigned int>(projection.t)]);
      // Friction: the old partner, whose motion the slip is measured
      // against.
      if (converged &&
          std::find(master_segments.begin(),
                    master_segments.end(),
                    point.old_projection.segment) == master_segments.end())
        master_segments.push_back(point.old_projection.segment);

      ns = s_seg.dofs_x.size();
      nl = s_seg.multiplier_dofs.size();
      local_dofs.insert(local_dofs.end(),
                        s_seg.dofs_x.begin(),
                        s_seg.dofs_x.end());
      local_dofs.insert(local_dofs.end(),
                        s_seg.dofs_y.begin(),
                        s_seg.dofs_y.end());
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
      lambda_offset = local_dofs.size();
      local_dofs.insert(local_dofs.end(),
                        s_seg.multiplier_dofs.begin(),
                        s_seg.multiplier_dofs.end());
      tangential_offset = local_dofs.size();
      if (converged)
        local_dofs.insert(local_dofs.end(),
                          s_seg.tangential_dofs.begin(),
                          s_seg.tangential_dofs.end());
    }

    // The local unknowns become AD variables (or AD constants, when only
    // values are wanted); a rotated copy of a master segment (cyclic
    // symmetry) moves by v = R a, a the unknowns of the original: its
    // displacements are written in those (so that the derivatives are with
    // respect to a), and its rows are turned back, r_a = R^T r_v, once the
    // residual is known.
    template <typename AD>
    void
    ContactElement<AD>::gather_unknowns(const Vector<double> &solution,
                                        const bool            derivatives)
    {
      const unsigned int n = local_dofs.size();
      u.resize(n);
      for (unsigned int i = 0; i < n; ++i)
        u[i] = derivatives ? AD(n, i, solution(local_dofs[i])) :
                             AD(solution(local_dofs[i]));
      turn_copies(u, false);
    }

    template <typename AD>
    void
    ContactElement<AD>::turn_copies(std::vector<AD> &v, const bool back) const
    {
      for (const auto &[m, o] : offset_of)
        {
          const auto &seg = master.segments()[m];
          if (!seg.is_copy)
            continue;
          const Tensor<2, 2> R  = back ? transpose(seg.rotation) : seg.rotation;
          const unsigned int nm = seg.dofs_x.size();
          for (unsigned int i = 0; i < nm; ++i)
            {
              const AD x = v[o + i], y = v[o + nm + i];
              v[o + i]      = R[0][0] * x + R[0][1] * y;
              v[o + nm + i] = R[1][0] * x + R[1][1] * y;
            }
        }
    }

    // A point of a master segment in AD numbers.
    template <typename AD>
    SurfaceKernel::CurvePoint<AD>
    ContactElement<AD>::master_point(const unsigned int m, const double t) const
    {
      std::vector<double> Nb, dNb, ddNb;
      const unsigned int  nm = master.segments()[m].dofs_x.size();
      master.displacement_basis().evaluate(t, Nb, dNb, ddNb);
      return ad_curve_point(master.reference_point(m, t),
                            Nb,
                            dNb,
                            ddNb,
                            &u[offset_of.at(m)],
                            &u[offset_of.at(m) + nm],
                            current);
    }

    // Outward normal scaled by |x'| of a master segment at t.
    template <typename AD>
    Tensor<1, 2, AD>
    ContactElement<AD>::scaled_normal(const unsigned int m, const double t) const
    {
      return SurfaceKernel::scaled_normal(master_point(m, t).dx,
                                          master.segments()[m].orientation);
    }

    // Unit vertex normal at the end `end` of the partner segment.
    template <typename AD>
    Tensor<1, 2, AD>
    ContactElement<AD>::vertex_normal(const unsigned int end) const
    {
      const unsigned int b             = m_seg.neighbours[end];
      const bool         has_neighbour = b != numbers::invalid_unsigned_int;
      return SurfaceKernel::vertex_normal(
        scaled_normal(projection.segment, end),
        has_neighbour ? scaled_normal(b, m_seg.neighbour_t[end]) : ADVector(),
        has_neighbour);
    }

    // The ends of the slave point's piece: fixed, or (segment-based) moving
    // with the displacement, each the crossing of the slave curve with the
    // line through a vertex of the partner along its normal: eta_end = eta0
    // - h / h' with h = (x_s(eta) - x_v) x n_v, whose value is eta0 and
    // whose derivative is that of the crossing.
    template <typename AD>
    std::array<AD, 2>
    ContactElement<AD>::piece_ends()
    {
      const AD         *us_x = &u[0], *us_y = &u[ns];
      std::array<AD, 2> eta_of_end = {{point.piece[0], point.piece[1]}};
      if (current)
        for (unsigned int side = 0; side < 2; ++side)
          if (point.piece_end[side] >= 0)
            {
              const double   eta0 = point.piece[side];
              const unsigned end  = point.piece_end[side];
              slave.displacement_basis().evaluate(eta0, N, dN, ddN);
              const ADPoint xe =
                ad_curve_point(slave.reference_point(point.slave_segment, eta0),
                               N,
                               dN,
                               ddN,
                               us_x,
                               us_y,
                               true);
              const ADPoint xv      = master_point(projection.segment, end);
              const auto [h, slope] = SurfaceKernel::piece_end_residual(
                SurfaceKernel::difference<AD>(xe.x, xv.x),
                xe.dx,
                vertex_normal(end));
              eta_of_end[side] = eta0 - h / slope;
            }
      return eta_of_end;
    }

    // The slave point: its parameter eta = eta_a + (eta_b - eta_a) xi on its
    // piece, written eta0 + d eta with d eta of value 0 and the derivative
    // of the moving ends; its position, length element and the pressure
    // there, the basis functions expanded to first order around eta0.
    template <typename AD>
    void
    ContactElement<AD>::evaluate_slave_point()
    {
      const AD               *us_x = &u[0], *us_y = &u[ns];
      std::vector<double>     G, dG, ddG;
      const std::array<AD, 2> eta_of_end   = piece_ends();
      const AD                piece_length = eta_of_end[1] - eta_of_end[0];
      d_eta = eta_of_end[0] + piece_length * point.xi - point.eta; // value 0

      slave.geometry_basis().evaluate(point.eta, G, dG, ddG);
      slave.displacement_basis().evaluate(point.eta, N, dN, ddN);
      slave.multiplier_basis().evaluate(point.eta, Phi, dPhi, ddPhi);
      // The bases expanded around eta0: phi(eta0 + d eta) = phi + phi' d eta.
      const auto expanded = [&](const std::vector<double> &phi,
                                const std::vector<double> &dphi) {
        std::vector<AD> values(phi.size());
        for (unsigned int i = 0; i < phi.size(); ++i)
          values[i] = phi[i] + dphi[i] * d_eta;
        return values;
      };
      const std::vector<AD> G_eta = expanded(G, dG), dG_eta = expanded(dG, ddG);
      N_eta                        = expanded(N, dN);
      const std::vector<AD> dN_eta = expanded(dN, ddN);
      xs                           = ADPoint();
      SurfaceKernel::add_interpolation(xs,
                                       G.size(),
                                       G_eta.data(),
                                       dG_eta.data(),
                                       (AD *)nullptr,
                                       [&](const unsigned int j) {
                                         return s_seg.reference_nodes[j];
                                       });
      xs_reference = xs.x;
      us           = ADVector();
      for (unsigned int i = 0; i < ns; ++i)
        {
          us[0] += N_eta[i] * us_x[i];
          us[1] += N_eta[i] * us_y[i];
        }
      SurfaceKernel::add_interpolation(xs,
                                       ns,
                                       N_eta.data(),
                                       current ? dN_eta.data() : nullptr,
                                       (AD *)nullptr,
                                       [&](const unsigned int i) {
                                         ADVector v;
                                         v[0] = us_x[i];
                                         v[1] = us_y[i];
                                         return v;
                                       });
      ds = std::sqrt(xs.dx[0] * xs.dx[0] + xs.dx[1] * xs.dx[1]) * piece_length *
           point.w;
      const AD *lambda_k = &u[lambda_offset];
      Phi_eta.resize(nl);
      lambda   = 0;
      lambda_t = 0;
      for (unsigned int k = 0; k < nl; ++k)
        {
          Phi_eta[k] = Phi[k] + dPhi[k] * d_eta;
          lambda += Phi_eta[k] * lambda_k[k];
          if (converged)
            lambda_t += Phi_eta[k] * u[tangential_offset + k];
        }
    }

    // Friction: the slip of the slave point in the step, the tangential
    // part of its displacement increment relative to that of its old
    // partner's material point, s = tau . [(u_s - u_s,n) - (u_m(xi_n) -
    // u_m,n(xi_n))], tau = e_z x n (see contact_interface.h).
    template <typename AD>
    AD
    ContactElement<AD>::slip() const
    {
      const Vector<double> &u_n = converged->solution;
      ADVector              relative;
      for (unsigned int i = 0; i < ns; ++i)
        {
          relative[0] += N_eta[i] * (u[i] - u_n(s_seg.dofs_x[i]));
          relative[1] += N_eta[i] * (u[ns + i] - u_n(s_seg.dofs_y[i]));
        }
      // The old partner xi_n of the moving point eta0 + d eta (segment-
      // based pieces): xi_n + d xi_n with d xi_n = -(dr/dx . x_s,n') d eta /
      // (dr/dxi), r the projection condition in the old configuration.
      const Projection &old   = point.old_projection;
      AD                dxi_n = 0;
      if (current && !old.clamped && !old.at_vertex)
        {
          const CurvePoint xs =
            converged->slave.current_point(point.slave_segment, point.eta);
          const CurvePoint xm =
            converged->master.current_point(old.segment, old.t);
          const Tensor<1, 2> d = xs.x - xm.x;
          double             slope, along;
          if (smooth)
            {
              const Tensor<1, 2> n0 =
                converged->master.vertex_normal(old.segment, 0);
              const Tensor<1, 2> n1 =
                converged->master.vertex_normal(old.segment, 1);
              slope =
                SurfaceKernel::smoothed_normal_residual(d, xm, n0, n1, old.t)
                  .second;
              along = SurfaceKernel::cross(
                xs.dx, SurfaceKernel::smoothed_direction(n0, n1, old.t));
            }
          else
            {
              slope = SurfaceKernel::closest_point_residual(d, xm).second;
              along = xs.dx * xm.dx;
            }
          dxi_n = -along * d_eta / slope;
        }
      const auto         &seg = master.segments()[old.segment];
      const unsigned int  nm  = seg.dofs_x.size();
      const unsigned int  o   = offset_of.at(old.segment);
      std::vector<double> Nb, dNb, ddNb;
      master.displacement_basis().evaluate(old.t, Nb, dNb, ddNb);
      for (unsigned int i = 0; i < nm; ++i)
        {
          const AD Nb_xi = Nb[i] + dNb[i] * dxi_n;
          relative[0] -= Nb_xi * (u[o + i] - u_n(seg.dofs_x[i]));
          relative[1] -= Nb_xi * (u[o + nm + i] - u_n(seg.dofs_y[i]));
        }
      return -normal[1] * relative[0] + normal[0] * relative[1];
    }

    // The partner and the normal. The master point at the converged
    // parameter xi0, and its first-order correction d xi = -f / f' where
    // f(xi) = 0 defines the projection: its value vanishes, its derivative
    // is that of the projection (implicit function theorem). Closest point:
    // f = (x_s - x_m) . x_m'; along the smoothed normal m(xi) = (1 - xi) n0
    // + xi n1: f = (x_s - x_m) x m. At a vertex or a clamped corner xi is
    // fixed. Then the unit normal there and the gap along it.
    template <typename AD>
    void
    ContactElement<AD>::evaluate_partner_and_normal()
    {
      const double xi0 = projection.t;
      master.displacement_basis().evaluate(xi0, Nm, dNm, ddNm);
      const ADPoint  xm = master_point(projection.segment, xi0);
      const ADVector n0 = smooth ? vertex_normal(0) : ADVector();
      const ADVector n1 = smooth ? vertex_normal(1) : ADVector();
      const ADVector d  = SurfaceKernel::difference<AD>(xs.x, xm.x);
      dxi               = 0;
      if (!projection.clamped && !projection.at_vertex && current)
        {
          const auto [r, slope] =
            smooth ?
              SurfaceKernel::smoothed_normal_residual(d, xm, n0, n1, xi0) :
              SurfaceKernel::closest_point_residual(d, xm);
          dxi = -r / slope;
        }
      ADVector x_m;
      for (unsigned int dim = 0; dim < 2; ++dim)
        x_m[dim] = xm.x[dim] + xm.dx[dim] * dxi;
      if (smooth)
        normal = SurfaceKernel::smoothed_direction(n0, n1, AD(xi0 + dxi));
      else if (projection.at_vertex) // xi0 is the vertex's end, 0 or 1
        normal = vertex_normal(static_cast<unsigned int>(xi0));
      else
        // Outward normal scaled by |x_m'| (normalised below).
        {
          ADVector dx;
          for (unsigned int dim = 0; dim < 2; ++dim)
            dx[dim] = xm.dx[dim] + xm.ddx[dim] * dxi;
          normal = SurfaceKernel::scaled_normal(dx, m_seg.orientation);
        }
      normal = SurfaceKernel::unit(normal);

      // The gap, (x_s - x_m) . n, as the normal distance of the two
      // reference points plus the normal jump of the displacement: the
      // same number, but computed from positions X + u a displacement below
      // their round-off (1e-200 m on a body of 1 m) would be lost, and the
      // round-off of the reference part (a few eps |X| where node-matching
      // surfaces face each other) would be a gap of its own, orders of
      // magnitude above such displacements. So the reference part is zero
      // where it is within that round-off (its value only: its derivatives
      // through the moving parameters stay). Small strain: the reference
      // gap of the search (ContactInterface::complete_point()), the jump
      // along the reference normal.
      const unsigned int nm = m_seg.dofs_x.size();
      const AD          *um = &u[offset_of.at(projection.segment)];
      ADVector           jump = us;
      for (unsigned int i = 0; i < nm; ++i)
        {
          const AD Nm_xi = Nm[i] + dNm[i] * dxi;
          jump[0] -= Nm_xi * um[i];
          jump[1] -= Nm_xi * um[nm + i];
        }
      AD reference_gap = point.reference_gap;
      if (current)
        {
          const CurvePoint Xm = master.reference_point(projection.segment, xi0);
          ADVector         difference;
          for (unsigned int dim = 0; dim < 2; ++dim)
            difference[dim] = xs_reference[dim] - Xm.x[dim] - Xm.dx[dim] * dxi;
          reference_gap =
            difference[0] * normal[0] + difference[1] * normal[1];
          if (std::abs(reference_gap.val()) <=
              SurfaceKernel::position_round_off(Xm.x))
            reference_gap -= reference_gap.val();
        }
      gap = reference_gap + jump[0] * normal[0] + jump[1] * normal[1];
    }

    // The residual: the contact virtual work on the slave and the master
    // rows, and the weighted gap on the rows of the active multipliers.
    template <typename AD>
    std::vector<AD>
    ContactElement<AD>::residual(
      const double                                        c,
      const std::function<bool(types::global_dof_index)> &active,
      const std::function<int(types::global_dof_index)>  &friction_state,
      const double                                        mu) const
    {
      // The traction the master exerts on the slave, per current length:
      // lambda n, and with friction - lambda_t tau, tau = (-n_y, n_x).
      std::vector<AD>    r(local_dofs.size(), AD(0.0));
      const unsigned int nm = m_seg.dofs_x.size();
      const unsigned int mo = offset_of.at(projection.segment);
      ADVector           tau;
      tau[0] = -normal[1];
      tau[1] = normal[0];
      for (unsigned int i = 0; i < ns; ++i)
        for (unsigned int dim = 0; dim < 2; ++dim)
          {
            r[dim * ns + i] = -lambda * N_eta[i] * normal[dim] * ds;
            if (converged)
              r[dim * ns + i] += lambda_t * N_eta[i] * tau[dim] * ds;
          }
      for (unsigned int i = 0; i < nm; ++i)
        {
          const AD Nm_xi = Nm[i] + dNm[i] * dxi;
          for (unsigned int dim = 0; dim < 2; ++dim)
            {
              r[mo + dim * nm + i] = lambda * Nm_xi * normal[dim] * ds;
              if (converged)
                r[mo + dim * nm + i] -= lambda_t * Nm_xi * tau[dim] * ds;
            }
        }
      for (unsigned int k = 0; k < nl; ++k)
        if (active(s_seg.multiplier_dofs[k]))
          r[lambda_offset + k] = c * Phi_eta[k] * gap * ds;
      // Friction: the sticking nodes' rows c s~_k, and the sliding nodes'
      // part of w lambda_t - sign mu (w lambda - c g~_k) that the points
      // carry (the rest is written per node, see
      // ContactInterface::assemble()).
      if (converged)
        {
          const AD s = slip();
          for (unsigned int k = 0; k < nl; ++k)
            {
              const int state = friction_state(s_seg.multiplier_dofs[k]);
              if (state == 0)
                r[tangential_offset + k] = c * Phi_eta[k] * s * ds;
              else if (state == 1 || state == -1)
                r[tangential_offset + k] =
                  state * mu * c * Phi_eta[k] * gap * ds;
            }
        }
      return r;
    }

    // The value and the derivative of the residual into the global system.
    // A vertex shared by the partner and its neighbour appears twice in the
    // local unknowns: the two copies (rows and columns) are summed into one
    // first.
    template <typename AD>
    void
    ContactElement<AD>::scatter(std::vector<AD>                 &residual,
                            const AffineConstraints<double> &constraints,
                            LinearSystem                    &system)
    {
      turn_copies(residual, true);
      const unsigned int                   n           = local_dofs.size();
      std::vector<types::global_dof_index> unique_dofs = local_dofs;
      std::sort(unique_dofs.begin(), unique_dofs.end());
      unique_dofs.erase(std::unique(unique_dofs.begin(), unique_dofs.end()),
                        unique_dofs.end());
      std::vector<unsigned int> to_unique(n);
      for (unsigned int i = 0; i < n; ++i)
        to_unique[i] = std::lower_bound(unique_dofs.begin(),
                                        unique_dofs.end(),
                                        local_dofs[i]) -
                       unique_dofs.begin();
      FullMatrix<double> local_matrix(unique_dofs.size(), unique_dofs.size());
      Vector<double>     local_rhs(unique_dofs.size());
      for (unsigned int i = 0; i < n; ++i)
        {
          local_rhs(to_unique[i]) -= residual[i].val();
          for (unsigned int j = 0; j < n; ++j)
            local_matrix(to_unique[i], to_unique[j]) += residual[i].dx(j);
        }
      system.add(constraints, local_matrix, local_rhs, unique_dofs);
    }

    template <typename AD>
    void
    ContactElement<AD>::add_values(std::vector<AD> &residual, Vector<double> &v)
    {
      turn_copies(residual, true);
      for (unsigned int i = 0; i < local_dofs.size(); ++i)
        v(local_dofs[i]) += residual[i].val();
    }
  } // namespace

  constexpr double stick_regularisation = 1e-12;

  template <typename Visitor>
  void
  ContactInterface::visit_points(const Vector<double> &solution,
                                 const bool            derivatives,
                                 const unsigned int    process,
                                 const Visitor        &visit) const
  {
    const auto is_active = [this](const types::global_dof_index dof) {
      return static_cast<bool>(active[multiplier_index.at(dof)]);
    };
    // 0 sticking, +1 or -1 sliding, 2 open.
    const auto friction_state = [this](const types::global_dof_index dof) {
      const unsigned int k = multiplier_index.at(dof);
      return active[k] ? slip_sign[k] : 2;
    };
    // (Before the first assembly there is no converged state yet: only
    // add_forces() can come that early, and the tangential rows, which
    // need it, are not forces.)
    const std::optional<ConvergedState> converged =
      friction_coefficient > 0 && converged_slave ?
        std::optional<ConvergedState>(ConvergedState{converged_solution,
                                                     *converged_slave,
                                                     *converged_master}) :
        std::nullopt;
    for (const auto &point : points)
      {
        if (process != numbers::invalid_unsigned_int &&
            slave.segments()[point.slave_segment].cell->subdomain_id() !=
              process)
          continue;
        const ElementLayout layout(slave,
                                   master,
                                   point,
                                   !geometrically_linear,
                                   segment_based,
                                   converged ? &*converged : nullptr);
        // The element in AD numbers that hold its unknowns.
        const auto evaluate = [&](auto &&element) {
          element.gather_unknowns(solution, derivatives);
          element.evaluate_slave_point();
          element.evaluate_partner_and_normal();
          auto residual = element.residual(complementarity_constant,
                                           is_active,
                                           friction_state,
                                           friction_coefficient);
          visit(element, residual);
        };
        AssertThrow(layout.n_unknowns() <= large_capacity,
                    ExcMessage("a contact element with " +
                               std::to_string(layout.n_unknowns()) +
                               " unknowns, more than the " +
                               std::to_string(large_capacity) +
                               " its AD numbers hold (displacement degree "
                               "above 4?)"));
        if (layout.n_unknowns() <= small_capacity)
          evaluate(ContactElement<SmallAD>(layout));
        else
          evaluate(ContactElement<LargeAD>(layout));
      }
  }

  void
  ContactInterface::assemble(const Vector<double>            &solution,
                             const AffineConstraints<double> &constraints,
                             LinearSystem                    &system) const
  {
    const bool friction = friction_coefficient > 0;
    visit_points(solution,
                 true,
                 this_process(system.get_communicator()),
                 [&](auto &element, auto &residual) {
                   element.scatter(residual, constraints, system);
                 });

    // Open nodes: w_k lambda_k = 0 (and w_k lambda_t,k = 0).
    for (unsigned int k = 0; k < multiplier_dof_list.size(); ++k)
      if (!active[k] && system.owned_rows().is_element(multiplier_dof_list[k]))
        {
          const auto dof = multiplier_dof_list[k];
          system.add_diagonal(dof,
                              reference_weight[k],
                              -reference_weight[k] * solution(dof));
        }
    if (!friction)
      return;
    for (unsigned int k = 0; k < multiplier_dof_list.size(); ++k)
      {
        const auto   t = tangential_dof_list[k], n = multiplier_dof_list[k];
        const double w = reference_weight[k];
        if (!system.owned_rows().is_element(t))
          continue;
        if (!active[k])
          system.add_diagonal(t, w, -w * solution(t));
        else if (slip_sign[k] == 0)
          // Sticking: c s~_k (the points' rows) + eps w lambda_t = 0. A
          // node whose tangential motion is held on both sides (on a
          // symmetry plane) has s~_k = 0 whatever the unknowns, and its
          // lambda_t no equation; eps = 1e-12 gives it lambda_t = 0 and
          // elsewhere allows a slip of 1e-12 w lambda_t / c (measured:
          // Hertz with mu = 0.2 was singular at its first step).
          system.add_diagonal(t,
                              stick_regularisation * w,
                              -stick_regularisation * w * solution(t));
        else
          {
            // Sliding: w lambda_t - sign mu (w lambda - c g~) = 0, the
            // points' sum of sign mu c Phi_k g ds already in the row.
            const double       b = slip_sign[k] * friction_coefficient * w;
            FullMatrix<double> matrix(2, 2);
            Vector<double>     rhs(2);
            matrix(0, 0) = w;
            matrix(0, 1) = -b;
            rhs(0)       = -(w * solution(t) - b * solution(n));
            system.add(constraints, matrix, rhs, {t, n});
          }
      }
  }

  void
  ContactInterface::add_forces(const Vector<double> &solution,
                               Vector<double>       &forces) const
  {
    visit_points(solution,
                 false,
                 numbers::invalid_unsigned_int,
                 [&](auto &element, auto &residual) {
                   element.add_values(residual, forces);
                 });
  }

  // s~_k = sum Phi_k s ds over the slave points, from the same contact
  // element as the residual (its values only).
  void
  ContactInterface::compute_weighted_slips(const Vector<double> &solution)
  {
    std::fill(weighted_slip.begin(), weighted_slip.end(), 0.0);
    const ConvergedState converged{converged_solution,
                                   *converged_slave,
                                   *converged_master};
    for (const auto &point : points)
      {
        const ElementLayout layout(slave,
                                   master,
                                   point,
                                   !geometrically_linear,
                                   segment_based,
                                   &converged);
        const auto          add_slip = [&](auto &&element) {
          element.gather_unknowns(solution, false); // values only
          element.evaluate_slave_point();
          element.evaluate_partner_and_normal();
          const double s   = element.slip().val();
          const double ds  = element.length_element().val();
          const auto  &seg = slave.segments()[point.slave_segment];
          for (unsigned int k = 0; k < seg.multiplier_dofs.size(); ++k)
            weighted_slip[multiplier_index.at(seg.multiplier_dofs[k])] +=
              element.multiplier_basis(k).val() * s * ds;
        };
        if (layout.n_unknowns() <= small_capacity)
          add_slip(ContactElement<SmallAD>(layout));
        else
          add_slip(ContactElement<LargeAD>(layout));
      }
  }
} // namespace RingContact
