// @sect3{The contact element}
//
// The heart of the method: the residual of one slave quadrature point paired
// with its partner on the master surface, and its exact derivative by forward
// automatic differentiation (Sacado). contact_interface.cc decides which points
// exist, where each is paired and which multiplier nodes are closed;
// contact_surface.cc and surface_kernel.h give the geometry of a segment. This
// file turns one such pair into rows of the Newton system: the contact virtual
// work on the displacement rows of both surfaces, the weighted gap on the rows
// of the closed multiplier nodes and, with friction, the slip or the Coulomb
// bound on the tangential rows. See contact_interface.h for the weak form and
// doc/theory.md for its derivation.
//
// Why automatic differentiation: the residual of a point depends on the
// displacement through the slave point itself (and, for segment-based
// integration, through the moving ends of its piece), through the parameter of
// its partner on the master, through the normal (a vertex normal or a smoothed
// normal brings in the neighbouring master segments), through the current
// length element and, with friction, through the master point it was paired
// with at the last converged state. Each of these is written once, in AD
// numbers, and its derivative comes with it; the test `tangent` compares the
// whole Newton matrix with finite differences. The implicit dependences (the
// projection parameter, the ends of a piece) are written as one Newton
// correction in AD numbers around their converged value: its value is zero, its
// derivative that of the implicit function theorem.
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/lac/full_matrix.h>

#include <ring_contact/base/dimension.h>
#include <ring_contact/contact/contact_element.h>

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
  namespace ContactElements
  {
    // A point of a segment in the current configuration with AD
    // coordinates: reference geometry (double) plus interpolated
    // displacement (AD); `with_displacement` = false keeps the reference
    // tangent (small strain).
    // The reference part stays in double: it does not depend on the unknowns,
    // and as AD numbers it would only carry arrays of zero derivatives. The
    // second derivative x'' is needed twice: in the slope of the projection's
    // residual (which contains d . x_m''), and in the tangent expanded to first
    // order around the converged parameter.
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
      for (unsigned int d = 0; d < dim; ++d)
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
                                         Tensor<1, dim, AD> v;
                                         v[0] = u_x[i];
                                         v[1] = u_y[i];
                                         return v;
                                       });
      return p;
    }

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
      // Which master segments the residual depends on beyond the partner. With
      // smoothed normals the normal along the partner interpolates its two
      // vertex normals, each an average with a neighbour; on segment-based
      // pieces the ends of a piece move along the vertex-normal lines at either
      // end of the partner; at a vertex with facet normals the vertex normal
      // brings in the one neighbour there. Inside a segment with facet normals
      // the partner alone defines the normal.
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

      // The order below is the one residual(), slip() and turn_copies() index
      // into. A global unknown may appear twice: at the vertex that the partner
      // shares with a neighbour, or, in a one-element sector, where the
      // partner's neighbours are rotated copies of the partner itself. Each
      // appearance is its own AD variable, and scatter() sums them.
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
      // The tangential tractions only with friction: without it their component
      // is FE_Nothing and the slave segment carries none.
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
      // AD(n, i, value) is the i-th of n independent variables. Without
      // derivatives (add_forces(), the weighted slips) the numbers are
      // constants and no derivative array is filled.
      const unsigned int n = local_dofs.size();
      u.resize(n);
      for (unsigned int i = 0; i < n; ++i)
        u[i] = derivatives ? AD(n, i, solution(local_dofs[i])) :
                             AD(solution(local_dofs[i]));
      turn_copies(u, false);
    }

    // A rotated copy's entries, forward (v = R a, the unknowns) or back (r_a =
    // R^T r_v, the residual rows). The rows turn with the transpose because a
    // copy's nodal forces are conjugate to its displacements: delta v . r_v =
    // delta a . R^T r_v. Writing the copies in the originals' unknowns keeps
    // every derivative a derivative with respect to an unknown of the system,
    // and a point with no copy among its segments does no extra work. The first
    // version turned the rows and columns of the element matrix afterwards,
    // which copied every element's matrix once more.
    template <typename AD>
    void
    ContactElement<AD>::turn_copies(std::vector<AD> &v, const bool back) const
    {
      for (const auto &[m, o] : offset_of)
        {
          const auto &seg = master.segments()[m];
          if (!seg.is_copy)
            continue;
          const Tensor<2, dim> R =
            back ? transpose(seg.rotation) : seg.rotation;
          const unsigned int nm = seg.dofs_x.size();
          for (unsigned int i = 0; i < nm; ++i)
            {
              const AD x = v[o + i], y = v[o + nm + i];
              v[o + i]      = R[0][0] * x + R[0][1] * y;
              v[o + nm + i] = R[1][0] * x + R[1][1] * y;
            }
        }
    }

    // A point of a master segment in AD numbers, at a fixed parameter t: the
    // motion of the partner point along the segment is added by the caller, to
    // first order. In small strain the tangent stays the reference one.
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
    Tensor<1, dim, AD>
    ContactElement<AD>::scaled_normal(const unsigned int m,
                                      const double       t) const
    {
      return SurfaceKernel::scaled_normal(master_point(m, t).dx,
                                          master.segments()[m].orientation);
    }

    // Unit vertex normal at the end `end` of the partner segment: the
    // expression of ContactSurface::vertex_normal() (surface_kernel.h) in AD
    // numbers, so that it moves with the nodes of both segments. The neighbour
    // may run the other way, hence its own parameter neighbour_t[end] for the
    // shared vertex; at the end of an open surface the normal is the partner's
    // own.
    template <typename AD>
    Tensor<1, dim, AD>
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
    // Small strain pairs the surfaces in the reference configuration, where the
    // cuts do not move: the ends stay fixed there, as a slave vertex (-1)
    // always is. eta0 is the crossing that ContactPairing::pair_pieces()
    // found by Newton's method to 1e-15, hence the value; the device is that of
    // the projection's correction in evaluate_partner_and_normal().
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

    namespace
    {
      // Friction: the tangential traction lambda_t = sum_k Psi_k lambda_t,k in
      // the dual basis Psi_k = sum_j a_kj Phi_j, A = D M^-1 with M_jk = int
      // Phi_j Phi_k dS and D_kk = int Phi_k dS over the slave segment
      // (reference length, the rule of the weights w_k). The weighted slip
      // s~_k = int Psi_k s dS is then D_k s_k wherever s lies in the span of
      // the Phi_j: the stick of node k constrains its own slip only, as the
      // nodal scheme's does. Weighted by Phi_k, it tied each node's stick to
      // its neighbours' slips: beside a sliding node the sticking nodes'
      // rows M s = 0 grow the slip and the traction away from it by 2 + sqrt
      // 3 per node (two blocks, 7 nodes, Gauss 3, mu = 0.37: tangential
      // tractions of alternating sign far past the Coulomb bound, no step
      // solved: doc/validation.md, "Curved geometry, ties and touching
      // bodies"), and a node beside the Hertz zone's centre slid at the
      // whole update and stuck at any fraction of it. With multipliers of
      // the displacement's degree the force the traction puts on slave node
      // j is then D_j lambda_t,j, and the Coulomb law per node
      // (ActiveSet::choose_friction_states()) is that of the nodal scheme.
      // The decoupling is exact where the scheme integrates Psi_k Phi_j
      // exactly in the reference configuration; an under-integrating rule,
      // the current length of finite strain and a partly covered
      // segment-based segment leave a coupling of the order of their error.
      // (Psi_k is not positive: a traction field, not a pressure, can be
      // anything.)
      // The coefficients a_kj = D_k (M^-1)_kj of the dual basis on slave
      // segment `segment`, for its nl multiplier nodes.
      FullMatrix<double>
      dual_basis_coefficients(const ContactSurface &slave,
                              const unsigned int    segment,
                              const unsigned int    nl)
      {
        const QGauss<1>     exact(slave.geometry_basis().size() + nl);
        FullMatrix<double>  M(nl, nl);
        std::vector<double> D(nl, 0.0), P;
        for (unsigned int q = 0; q < exact.size(); ++q)
          {
            slave.multiplier_basis().evaluate(exact.point(q)[0], P);
            const double dS =
              slave.reference_point(segment, exact.point(q)[0]).dx.norm() *
              exact.weight(q);
            for (unsigned int j = 0; j < nl; ++j)
              {
                D[j] += P[j] * dS;
                for (unsigned int k = 0; k < nl; ++k)
                  M(j, k) += P[j] * P[k] * dS;
              }
          }
        M.gauss_jordan();
        FullMatrix<double> A(nl, nl);
        for (unsigned int k = 0; k < nl; ++k)
          for (unsigned int j = 0; j < nl; ++j)
            A(k, j) = D[k] * M(k, j);
        return A;
      }
    } // namespace

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
      // For fixed rules the ends are constants: d eta has no derivative, and
      // the point is a material point of its slave segment. On a segment-based
      // piece the quadrature point keeps its place xi in its piece while the
      // piece's ends move along the segment.
      d_eta = eta_of_end[0] + piece_length * point.xi - point.eta; // value 0

      slave.geometry_basis().evaluate(point.eta, G, dG, ddG);
      slave.displacement_basis().evaluate(point.eta, N, dN, ddN);
      slave.multiplier_basis().evaluate(point.eta, Phi, dPhi, ddPhi);
      // The bases expanded around eta0: phi(eta0 + d eta) = phi + phi' d eta.
      // First order is enough: Newton's method needs the residual's value (at d
      // eta = 0) and its first derivative, and a term in d eta^2 contributes to
      // neither.
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
      // The position in two parts, as X + u: the reference part through the
      // mapping's support points with the geometry basis G, then the
      // displacement with N. The displacement us is kept alone as well, for the
      // gap. In small strain the tangent x_s' stays the reference one (dN is
      // not added), and with it the length element.
      xs = ADPoint();
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
      // ds = |x_s'| (eta_b - eta_a) w, a length per unit thickness: the current
      // length element times the point's weight in its piece, moving with the
      // piece's ends.
      ds = std::sqrt(xs.dx[0] * xs.dx[0] + xs.dx[1] * xs.dx[1]) * piece_length *
           point.w;
      // The normal and the tangential traction at the point, interpolated by
      // the multiplier basis Phi_k: Cauchy tractions, force per current length
      // (Pa).
      const AD *lambda_k = &u[lambda_offset];
      Phi_eta.resize(nl);
      lambda   = 0;
      lambda_t = 0;
      for (unsigned int k = 0; k < nl; ++k)
        {
          Phi_eta[k] = Phi[k] + dPhi[k] * d_eta;
          lambda += Phi_eta[k] * lambda_k[k];
        }
      // Friction: the tangential traction in the dual basis Psi_k
      // (dual_basis_coefficients()).
      Psi_eta = Phi_eta;
      if (converged && converged->dual_basis)
        {
          const FullMatrix<double> A =
            dual_basis_coefficients(slave, point.slave_segment, nl);
          for (unsigned int k = 0; k < nl; ++k)
            {
              Psi_eta[k] = 0;
              for (unsigned int j = 0; j < nl; ++j)
                Psi_eta[k] += A(k, j) * Phi_eta[j];
            }
        }
      if (converged)
        for (unsigned int k = 0; k < nl; ++k)
          lambda_t += Psi_eta[k] * u[tangential_offset + k];
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
      // The slave point's own increment u_s - u_s,n, at its parameter in the
      // segment.
      for (unsigned int i = 0; i < ns; ++i)
        {
          relative[0] += N_eta[i] * (u[i] - u_n(s_seg.dofs_x[i]));
          relative[1] += N_eta[i] * (u[ns + i] - u_n(s_seg.dofs_y[i]));
        }
      // The old partner xi_n of the moving point eta0 + d eta (segment-
      // based pieces): xi_n + d xi_n with d xi_n = -(dr/dx . x_s,n') d eta /
      // (dr/dxi), r the projection condition in the old configuration.
      // The old configuration is data (doubles): only eta moves, and only on a
      // segment-based piece; for fixed rules d eta, and with it d xi_n, has no
      // derivative. At a vertex or a clamped corner xi_n is fixed, as the
      // current partner's xi is; in small strain the old pairing is the
      // reference one.
      const Projection &old   = point.old_projection;
      AD                dxi_n = 0;
      // Finite strain: the old separation d_n = x_s,n - x_m,n(xi_n) (along
      // the old normal, the gap the point had) is added to the relative
      // increment, so that the slip is tau . (x_s - x_m(xi_n)), the distance
      // along the current tangent from the old partner's material point: zero
      // for a point that lands on that point, whatever the normal has turned
      // by meanwhile. The increment alone measured -g_n tau . n_n for a point
      // that closes a gap g_n while the master turns: a cylinder pressed
      // from touching (steel on aluminium, mu = 0.2) got slips on nodes that
      // stick, which turned their states from slip one way to slip the other at
      // every iteration, with many iterations and cuts (bench/first-step;
      // doc/validation.md, "Curved geometry, ties and touching bodies"). Small
      // strain keeps the reference tangent, normal to d_n.
      // Only where the old partner is a closest point (d_n along the old
      // normal): at a vertex or a clamped end d_n has a tangential part of its
      // own, which would read as a slip of an unmoved point (two blocks
      // turned against each other: no step could be solved).
      ADVector separation;
      if (current && !old.clamped && !old.at_vertex)
        {
          const CurvePoint xs =
            converged->slave.current_point(point.slave_segment, point.eta);
          const CurvePoint xm =
            converged->master.current_point(old.segment, old.t);
          const Tensor<1, dim> d = xs.x - xm.x;
          separation[0]          = d[0];
          separation[1]          = d[1];
          double slope, along;
          if (smooth)
            {
              const Tensor<1, dim> n0 =
                converged->master.vertex_normal(old.segment, 0);
              const Tensor<1, dim> n1 =
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
          // d_n of the moving point eta0 + d eta, to first order.
          for (unsigned int c = 0; c < dim; ++c)
            separation[c] += xs.dx[c] * d_eta - xm.dx[c] * dxi_n;
        }
      // Minus the old partner's increment u_m(xi_n) - u_m,n(xi_n). The
      // converged solution is read as it is, unturned: the old partner is never
      // a rotated copy, since friction with a sector is refused (by the rings'
      // scenario).
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
      // tau . relative, tau = e_z x n = (-n_y, n_x) along the current master
      // normal: the slip is measured along the tangent on which the tangential
      // traction acts.
      for (unsigned int c = 0; c < dim; ++c)
        relative[c] += separation[c];
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
      // The correction is taken only where xi is free: at a vertex or a clamped
      // corner the partner point is the vertex itself, and in small strain the
      // pairing of the reference configuration does not move with the
      // displacement.
      dxi = 0;
      if (!projection.clamped && !projection.at_vertex && current)
        {
          const auto [r, slope] =
            smooth ?
              SurfaceKernel::smoothed_normal_residual(d, xm, n0, n1, xi0) :
              SurfaceKernel::closest_point_residual(d, xm);
          dxi = -r / slope;
        }
      ADVector x_m;
      for (unsigned int axis = 0; axis < dim; ++axis)
        x_m[axis] = xm.x[axis] + xm.dx[axis] * dxi;
      // The normal, chosen as ContactSurface::normal(projection) chooses it for
      // the search, so that the active set (decided from the search's gaps) and
      // the residual (from the element's) see the same gap: the smoothed field
      // at xi, the vertex normal at a vertex, else the segment's own normal at
      // xi, its tangent expanded to first order like the position.
      if (smooth)
        normal = SurfaceKernel::smoothed_direction(n0, n1, AD(xi0 + dxi));
      else if (projection.at_vertex) // xi0 is the vertex's end, 0 or 1
        normal = vertex_normal(static_cast<unsigned int>(xi0));
      else
        // Outward normal scaled by |x_m'| (normalised below).
        {
          ADVector dx;
          for (unsigned int axis = 0; axis < dim; ++axis)
            dx[axis] = xm.dx[axis] + xm.ddx[axis] * dxi;
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
      // gap of the search (ContactPairing::complete_point()), the jump
      // along the reference normal.
      const unsigned int nm   = m_seg.dofs_x.size();
      const AD          *um   = &u[offset_of.at(projection.segment)];
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
          for (unsigned int axis = 0; axis < dim; ++axis)
            difference[axis] =
              xs_reference[axis] - Xm.x[axis] - Xm.dx[axis] * dxi;
          reference_gap = difference[0] * normal[0] + difference[1] * normal[1];
          if (std::abs(reference_gap.val()) <=
              SurfaceKernel::position_round_off(Xm.x))
            reference_gap -= reference_gap.val();
        }
      // g = (x_s - x_m) . n, in metres: positive when the surfaces are apart,
      // negative where the slave has entered the master.
      gap = reference_gap + jump[0] * normal[0] + jump[1] * normal[1];
    }

    // The residual: the contact virtual work on the slave and the master
    // rows, and the weighted gap on the rows of the active multipliers.
    // Signs: R is the internal minus the external virtual work, R_u = int P :
    // Grad delta u dV - int lambda (delta u_s - delta u_m) . n ds, so the
    // slave's rows get -lambda N_i n ds (the master pushes the slave along its
    // outward normal n; lambda > 0 is a compression) and the master's rows the
    // opposite force at the partner point, action and reaction.
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
        for (unsigned int axis = 0; axis < dim; ++axis)
          {
            r[axis * ns + i] = -lambda * N_eta[i] * normal[axis] * ds;
            if (converged)
              r[axis * ns + i] += lambda_t * N_eta[i] * tau[axis] * ds;
          }
      // The force on the master acts at the partner point, through the
      // partner's shape functions at the moved xi. The neighbours that enter
      // only through the normal get no force: their columns carry derivatives,
      // their rows nothing.
      for (unsigned int i = 0; i < nm; ++i)
        {
          const AD Nm_xi = Nm[i] + dNm[i] * dxi;
          for (unsigned int axis = 0; axis < dim; ++axis)
            {
              r[mo + axis * nm + i] = lambda * Nm_xi * normal[axis] * ds;
              if (converged)
                r[mo + axis * nm + i] -= lambda_t * Nm_xi * tau[axis] * ds;
            }
        }
      // Closed nodes: c Phi_k g ds, which summed over the points is c g~_k, the
      // row C_k of an active node (a force per unit thickness: c in Pa/m, the
      // gap and ds in m). The rows of open nodes, w_k lambda_k = 0, are not
      // sums over points: assemble() writes them per node, and here they stay
      // zero.
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
                r[tangential_offset + k] = c * Psi_eta[k] * s * ds;
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
      // The derivative with respect to such an unknown is the sum of the
      // derivatives with respect to its two appearances (chain rule), and its
      // row gathers both rows. The rows of rotated copies are first turned back
      // into rows of their originals' unknowns, which are the dofs of the
      // layout.
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
      // rhs = -R: Newton's method solves K du = -R.
      for (unsigned int i = 0; i < n; ++i)
        {
          local_rhs(to_unique[i]) -= residual[i].val();
          for (unsigned int j = 0; j < n; ++j)
            local_matrix(to_unique[i], to_unique[j]) += residual[i].dx(j);
        }
      // Condensed with the constraints as a cell's matrix is (the imposed
      // displacements of the update, the sector's ties, the zero multipliers
      // inside the slave layer). Under MPI a row may be another process's:
      // LinearSystem sends it to its owner at compress().
      system.add(constraints, local_matrix, local_rhs, unique_dofs);
    }

    // The residual's values alone, without the constraints: add_forces() wants
    // the contact force at every node, constrained ones included, so that a
    // support's reaction can leave out the contact force at its nodes (a
    // support whose end node was on a contact surface reported 0.34 p instead
    // of 0.3 p on an inclined interface).
    template <typename AD>
    void
    ContactElement<AD>::add_values(std::vector<AD> &residual, Vector<double> &v)
    {
      turn_copies(residual, true);
      for (unsigned int i = 0; i < local_dofs.size(); ++i)
        v(local_dofs[i]) += residual[i].val();
    }

    // The two capacities of AD numbers visit_points() chooses from.
    template class ContactElement<SmallAD>;
    template class ContactElement<LargeAD>;
  } // namespace ContactElements
} // namespace RingContact
