// @sect3{Normal displacement conditions, node by node}
//
// The resolution of one node's normal conditions (normal_conditions.h): in
// 2D the original's rules, in 3D the same idea with three components, and
// the edge between two rollers written as two lines on two components.
#include <deal.II/base/tensor.h>

#include <ring_contact/scenarios/general/normal_conditions.h>

#include <array>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace RingContact
{
  namespace General
  {
    namespace
    {
      // "0, 0.25, 1": a node in the messages.
      std::string
      position_text(const Point<3> &X)
      {
        std::ostringstream out;
        out << X[0] << ", " << X[1] << ", " << X[2];
        return out.str();
      }

      // Normals more than 60 degrees apart are two directions: at a
      // corner of a rectangle (90 degrees) both are imposed, while the
      // facets of a curve meshed with a few dozen segments around are
      // averaged.
      constexpr double corner = 0.5; // cos 60 degrees

      // One node's normal conditions in 2D (see the header).
      void
      resolve_in_2d(const NodeDofs<2>                         &node,
                    const std::vector<NormalFace<2>>          &list,
                    std::map<types::global_dof_index, double> &values,
                    std::vector<NormalDisplacement<2>>        &normal)
      {
        // Two groups: the normals near the first one, and the others.
        // Within a group the faces' normals are averaged: on a faceted
        // curve the bisector, on a straight boundary the exact normal.
        std::array<Tensor<1, 2>, 2> sum;
        std::array<double, 2>       value = {{0, 0}};
        for (const NormalFace<2> &face : list)
          {
            const unsigned int group = face.N * list[0].N >= corner ? 0 : 1;
            sum[group] += face.N;
            value[group] = face.g; // the later condition decides
          }
        std::array<Tensor<1, 2>, 2> N;
        for (unsigned int k = 0; k < 2; ++k)
          if (sum[k].norm() > 0)
            N[k] = sum[k] / sum[k].norm();
        // A Cartesian or polar condition at the node comes first: with
        // both components imposed, the normal condition adds nothing.
        const bool has_x = values.count(node[0]) > 0,
                   has_y = values.count(node[1]) > 0;
        if (has_x && has_y)
          return;
        if (has_x || has_y)
          {
            // The other component from the group most across the
            // imposed one (none if the normal is along it: the
            // Cartesian condition then decides).
            // u_b = (g - N_a u_a) / N_b; below |N_b| = 0.1 the division
            // would magnify the imposed u_a and g tenfold or more.
            const unsigned int a = has_x ? 0 : 1, b = 1 - a;
            const unsigned int k =
              std::abs(N[1][b]) > std::abs(N[0][b]) ? 1 : 0;
            if (std::abs(N[k][b]) >= 0.1)
              values[node[b]] =
                (value[k] - N[k][a] * values.at(node[a])) / N[k][b];
            return;
          }
        // One direction only: the single linear condition, which the
        // problem class makes a constraint on the component with the
        // larger |N_a|.
        if (N[1].norm() == 0)
          {
            normal.push_back(NormalDisplacement<2>{node, N[0], value[0]});
            return;
          }
        // A corner: N1 . u = g1, N2 . u = g2, solved for u by Cramer's
        // rule.
        const double det = N[0][0] * N[1][1] - N[0][1] * N[1][0];
        values[node[0]]  = (value[0] * N[1][1] - value[1] * N[0][1]) / det;
        values[node[1]]  = (N[0][0] * value[1] - N[1][0] * value[0]) / det;
      }

      // An edge between two rollers in 3D: N1 . u = g1 and N2 . u = g2
      // leave the edge's direction free. Written as two conditions on two
      // different components a and b, u_a + r1 u_c = h1 and u_b + r2 u_c =
      // h2, each of which the problem class constrains on its own
      // component: a and b are the columns of the largest 2 x 2 minor of
      // (N1; N2), so |r1|, |r2| <= 1 (Cramer's rule) and u_a, u_b are each
      // row's largest coefficient. (Two conditions that both named u_c,
      // at a tie |r| = 1, would be one line twice: refused.)
      void
      roller_edge(const NodeDofs<3>                  &node,
                  const Tensor<1, 3>                 &N1,
                  const double                        g1,
                  const Tensor<1, 3>                 &N2,
                  const double                        g2,
                  const NormalFace<3>                &face,
                  std::vector<NormalDisplacement<3>> &normal)
      {
        unsigned int a = 0, b = 1;
        double       det = 0;
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int j = i + 1; j < 3; ++j)
            if (const double d = N1[i] * N2[j] - N1[j] * N2[i];
                std::abs(d) > std::abs(det))
              {
                a   = i;
                b   = j;
                det = d;
              }
        const unsigned int c = 3 - a - b;
        // (h1, h2) and (r1, r2): the 2 x 2 system solved for g and N_c.
        const auto solve = [&](const double v1, const double v2) {
          return std::array<double, 2>{
            {(v1 * N2[b] - v2 * N1[b]) / det, (N1[a] * v2 - N2[a] * v1) / det}};
        };
        const auto                  h = solve(g1, g2), r = solve(N1[c], N2[c]);
        std::array<unsigned int, 2> constrained;
        for (unsigned int k = 0; k < 2; ++k)
          {
            const unsigned int own = k == 0 ? a : b;
            Tensor<1, 3>       row;
            row[own] = 1;
            row[c]   = r[k];
            normal.push_back(
              NormalDisplacement<3>{node, row / row.norm(), h[k] / row.norm()});
            constrained[k] = std::abs(r[k]) >= 1 && c < own ? c : own;
          }
        if (constrained[0] == constrained[1])
          throw std::runtime_error(
            face.condition->name + ": at the node (" + position_text(face.X) +
            ") two normal conditions meet at an edge whose direction is "
            "at 45 degrees to two axes: impose one of them by Cartesian "
            "components there");
      }

      // One node's normal conditions in 3D: the normals grouped as in 2D
      // (within 60 degrees of a group's first face), each group one
      // condition N_k . u = g_k, and each Cartesian component imposed at
      // the node one more, e_c . u = u_c. Where they fix the node (three
      // independent conditions, taken in that order), u is solved for. One
      // normal condition that leaves a direction free keeps its part on the
      // free components, N' . u = g - N . u_imposed (a roller on a
      // cylinder's side where its base holds z); two that leave the edge
      // between them free are refused, as no single condition holds them.
      void
      resolve_in_3d(const NodeDofs<3>                         &node,
                    const std::vector<NormalFace<3>>          &list,
                    std::map<types::global_dof_index, double> &values,
                    std::vector<NormalDisplacement<3>>        &normal)
      {
        std::vector<Tensor<1, 3>> first, sum;
        std::vector<double>       value;
        for (const NormalFace<3> &face : list)
          {
            unsigned int k = 0;
            while (k < first.size() && face.N * first[k] < corner)
              ++k;
            if (k == first.size())
              {
                first.push_back(face.N);
                sum.emplace_back();
                value.push_back(0);
              }
            sum[k] += face.N;
            value[k] = face.g; // the later condition decides
          }
        // The conditions: the imposed components first, then the groups.
        std::vector<Tensor<1, 3>> rows;
        std::vector<double>       rhs;
        for (unsigned int c = 0; c < 3; ++c)
          if (values.count(node[c]) > 0)
            {
              rows.push_back(Point<3>::unit_vector(c));
              rhs.push_back(values.at(node[c]));
            }
        if (rows.size() == 3)
          return;
        const unsigned int n_imposed = rows.size();
        for (unsigned int k = 0; k < sum.size(); ++k)
          {
            rows.push_back(sum[k] / sum[k].norm());
            rhs.push_back(value[k]);
          }
        if (sum.size() == 1)
          {
            // N' on the components not imposed; below |N'| = 0.1 the
            // normal is along the imposed ones, which then decide (as in
            // 2D).
            Tensor<1, 3> free = rows.back();
            double       g    = rhs.back();
            for (unsigned int r = 0; r < n_imposed; ++r)
              {
                const unsigned int c = std::abs(rows[r][0]) > 0.5 ? 0 :
                                       std::abs(rows[r][1]) > 0.5 ? 1 :
                                                                    2;
                g -= free[c] * rhs[r];
                free[c] = 0;
              }
            if (free.norm() >= 0.1)
              normal.push_back(NormalDisplacement<3>{node,
                                                     free / free.norm(),
                                                     g / free.norm()});
            return;
          }
        // Three independent conditions, chosen in order (a row within
        // |r| = 0.1 of the span of those before it adds nothing).
        Tensor<2, 3>              A;
        Tensor<1, 3>              b;
        std::vector<Tensor<1, 3>> basis;
        unsigned int              n = 0;
        for (unsigned int r = 0; r < rows.size() && n < 3; ++r)
          {
            Tensor<1, 3> residual = rows[r];
            for (const auto &e : basis)
              residual -= (residual * e) * e;
            if (residual.norm() < 0.1)
              continue;
            basis.push_back(residual / residual.norm());
            A[n] = rows[r];
            b[n] = rhs[r];
            ++n;
          }
        if (n == 3)
          {
            const Tensor<1, 3> u = invert(A) * b;
            for (unsigned int c = 0; c < 3; ++c)
              values[node[c]] = u[c];
            return;
          }
        if (n_imposed == 0 && n == 2)
          {
            roller_edge(node, A[0], b[0], A[1], b[1], list.front(), normal);
            return;
          }
        std::ostringstream message;
        message << list.front().condition->name << ": at the node ("
                << position_text(list.front().X)
                << ") its normal condition meets another condition at an "
                   "angle, and together they leave a direction free that "
                   "no single condition holds; impose one of them by "
                   "Cartesian components there";
        throw std::runtime_error(message.str());
      }
    } // namespace

    template <>
    void
    resolve_normal_conditions<2>(
      const NodeDofs<2>                         &node,
      const std::vector<NormalFace<2>>          &list,
      std::map<types::global_dof_index, double> &values,
      std::vector<NormalDisplacement<2>>        &normal)
    {
      resolve_in_2d(node, list, values, normal);
    }

    template <>
    void
    resolve_normal_conditions<3>(
      const NodeDofs<3>                         &node,
      const std::vector<NormalFace<3>>          &list,
      std::map<types::global_dof_index, double> &values,
      std::vector<NormalDisplacement<3>>        &normal)
    {
      resolve_in_3d(node, list, values, normal);
    }
  } // namespace General
} // namespace RingContact
