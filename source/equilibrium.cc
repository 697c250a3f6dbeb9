#include <deal.II/base/quadrature.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/hp/fe_values.h>
#include <deal.II/hp/q_collection.h>

#include <ring_contact/components.h>
#include <ring_contact/equilibrium.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

namespace RingContact
{
  std::vector<Tensor<1, 2>>
  SupportCondition::directions(const Point<2> &X, const Tensor<1, 2> &N) const
  {
    std::vector<Tensor<1, 2>> held;
    switch (kind)
      {
        case Kind::cartesian:
          for (unsigned int c = 0; c < 2; ++c)
            if (components[c])
              held.push_back(Point<2>::unit_vector(c));
          break;
        case Kind::polar:
          {
            const double theta = std::atan2(X[1], X[0]);
            const Tensor<1, 2> e_r({std::cos(theta), std::sin(theta)});
            const Tensor<1, 2> e_theta({-std::sin(theta), std::cos(theta)});
            if (components[0])
              held.push_back(e_r);
            if (components[1])
              held.push_back(e_theta);
            break;
          }
        case Kind::normal:
          held.push_back(N);
          break;
      }
    return held;
  }

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

  double
  Balance::worst_body() const
  {
    double worst = 0;
    for (const auto &[name, error] : bodies)
      worst = std::isnan(error) ? error : std::max(worst, error);
    return worst;
  }

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
    // multipliers): the body it belongs to.
    std::vector<types::material_id>
    body_of_unknowns(const DoFHandler<2> &dof_handler)
    {
      std::vector<types::material_id> body(dof_handler.n_dofs(),
                                           numbers::invalid_material_id);
      std::vector<types::global_dof_index> dofs;
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          const auto &fe = cell->get_fe();
          dofs.resize(fe.n_dofs_per_cell());
          cell->get_dof_indices(dofs);
          for (unsigned int i = 0; i < dofs.size(); ++i)
            if (Components::is_displacement(
                  fe.system_to_component_index(i).first))
              body[dofs[i]] = cell->material_id();
        }
      return body;
    }

    // The component (0 or 1) of each displacement unknown.
    std::vector<unsigned int>
    component_of_unknowns(const DoFHandler<2> &dof_handler)
    {
      std::vector<unsigned int>            component(dof_handler.n_dofs(),
                                          Components::n_components);
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
    struct Sum
    {
      Tensor<1, 2> total;
      double       magnitude = 0;
      double       round_off = 0;

      void
      add(const unsigned int component, const double value)
      {
        total[component] += value;
        magnitude += std::abs(value);
      }
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

  Balance
  measure_balance(
    const DoFHandler<2>                                          &dof_handler,
    const NodalForces                                            &forces,
    const std::vector<std::pair<types::material_id, std::string>> &bodies,
    const std::vector<std::pair<types::material_id, types::material_id>>
              &pair_bodies,
    const bool measure_pairs)
  {
    const auto body      = body_of_unknowns(dof_handler);
    const auto component = component_of_unknowns(dof_handler);
    const auto reaction  = forces.reactions();

    // Per body: applied + reaction - contact (what the other bodies exert
    // is minus the contact terms).
    std::map<types::material_id, Sum> per_body;
    for (types::global_dof_index i = 0; i < body.size(); ++i)
      {
        if (body[i] == numbers::invalid_material_id)
          continue;
        Sum &sum = per_body[body[i]];
        if (forces.round_off.size() == body.size())
          sum.round_off += forces.round_off(i);
        sum.add(component[i], forces.applied(i));
        sum.add(component[i], reaction(i));
        for (const auto &pair : forces.contact)
          sum.add(component[i], -pair(i));
      }
    Balance balance;
    for (const auto &[id, name] : bodies)
      {
        balance.bodies.emplace_back(name, per_body[id].relative());
        balance.beyond_round_off.push_back(per_body[id].beyond_round_off());
      }

    // Per pair: the force on the slave body plus that on the master body.
    for (unsigned int k = 0; k < forces.contact.size(); ++k)
      {
        if (!measure_pairs)
          {
            balance.pairs.push_back(std::nan(""));
            continue;
          }
        Sum sum;
        for (types::global_dof_index i = 0; i < body.size(); ++i)
          if (body[i] == pair_bodies[k].first ||
              body[i] == pair_bodies[k].second)
            sum.add(component[i], forces.contact[k](i));
        balance.pairs.push_back(sum.relative());
      }
    return balance;
  }

  void
  for_each_boundary_face(
    const DoFHandler<2>            &dof_handler,
    const hp::MappingCollection<2> &mapping,
    const std::function<void(const DoFHandler<2>::active_cell_iterator &,
                             const unsigned int,
                             const std::vector<BoundaryNode> &)> &visit)
  {
    // The support points of each element's faces as a face quadrature, so
    // that FEFaceValues gives their positions and the normals there; and a
    // Gauss rule for the integral of each node's shape function.
    const auto        &fe_collection = dof_handler.get_fe_collection();
    hp::QCollection<1> support_points, gauss;
    for (unsigned int i = 0; i < fe_collection.size(); ++i)
      {
        support_points.push_back(
          Quadrature<1>(fe_collection[i].get_unit_face_support_points(0)));
        gauss.push_back(QGauss<1>(fe_collection[i].degree + 1));
      }
    hp::FEFaceValues<2> at_nodes(mapping,
                                 fe_collection,
                                 support_points,
                                 update_quadrature_points |
                                   update_normal_vectors);
    hp::FEFaceValues<2> integrals(mapping,
                                  fe_collection,
                                  gauss,
                                  update_values | update_JxW_values);
    std::vector<types::global_dof_index> face_dofs;
    std::vector<BoundaryNode>            nodes;
    for (const auto &cell : dof_handler.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary())
          {
            at_nodes.reinit(cell, f);
            integrals.reinit(cell, f);
            const FEFaceValues<2>  &fv = at_nodes.get_present_fe_values();
            const FEFaceValues<2>  &iv = integrals.get_present_fe_values();
            const FiniteElement<2> &fe = cell->get_fe();
            face_dofs.resize(fe.n_dofs_per_face(f));
            cell->face(f)->get_dof_indices(face_dofs, cell->active_fe_index());
            nodes.clear();
            for (unsigned int i = 0; i < face_dofs.size(); ++i)
              if (fe.face_system_to_component_index(i, f).first ==
                  Components::ux)
                for (unsigned int j = 0; j < face_dofs.size(); ++j)
                  if (fe.face_system_to_component_index(j, f).first ==
                        Components::uy &&
                      fv.quadrature_point(j) == fv.quadrature_point(i))
                    {
                      // int phi ds of the node's shape function on the face.
                      const unsigned int cell_i =
                        fe.face_to_cell_index(i, f);
                      double weight = 0;
                      for (unsigned int q = 0; q < iv.n_quadrature_points; ++q)
                        weight += iv.shape_value(cell_i, q) * iv.JxW(q);
                      nodes.push_back({fv.quadrature_point(i),
                                       fv.normal_vector(i),
                                       {{face_dofs[i], face_dofs[j]}},
                                       weight});
                    }
            visit(cell, f, nodes);
          }
  }

  BoundaryResultants::BoundaryResultants(
    const DoFHandler<2>                 &dof_handler,
    const hp::MappingCollection<2>      &mapping,
    const std::vector<SupportCondition> &supports)
  {
    std::map<types::boundary_id, const SupportCondition *> support_of;
    for (const auto &support : supports)
      support_of[support.boundary_id] = &support;

    // Per node: the boundaries that hold it, each with its directions, the
    // integral of the node's shape function over its faces, and the other
    // nodes of those faces.
    struct Holder
    {
      types::boundary_id                  boundary;
      std::vector<Tensor<1, 2>>           directions;
      double                              weight;
      std::set<Node>                      neighbours;
    };
    std::map<Node, std::vector<Holder>> holders;
    std::map<std::pair<types::boundary_id, Node>, double> weight_on;
    for_each_boundary_face(
      dof_handler,
      mapping,
      [&](const auto                      &cell,
          const unsigned int               f,
          const std::vector<BoundaryNode> &nodes) {
        const auto id      = cell->face(f)->boundary_id();
        const auto support = support_of.find(id);
        if (support == support_of.end())
          return;
        for (const BoundaryNode &node : nodes)
          {
            auto &list = holders[node.dofs];
            auto  it   = std::find_if(list.begin(),
                                   list.end(),
                                   [&](const auto &h) { return h.boundary == id; });
            if (it == list.end())
              {
                list.push_back(
                  {id, support->second->directions(node.X, node.N), 0.0, {}});
                it = list.end() - 1;
              }
            else if (support->second->kind == SupportCondition::Kind::normal)
              {
                // Two faces of one boundary at a node: the mean normal.
                Tensor<1, 2> mean = it->directions[0] + node.N;
                if (mean.norm() > 0)
                  it->directions[0] = mean / mean.norm();
              }
            it->weight += node.weight;
            weight_on[{id, node.dofs}] += node.weight;
            for (const BoundaryNode &other : nodes)
              if (other.dofs != node.dofs)
                it->neighbours.insert(other.dofs);
          }
      });

    // Per node: the directions held, grouped where parallel; the reaction s
    // split as s = sum_g c_g d_g with the least c (exactly when two
    // independent directions are held), c_g = d_g . (D D^T)^+ s.
    for (const auto &[node, list] : holders)
      {
        struct Group
        {
          Tensor<1, 2>              direction;
          std::vector<unsigned int> members; // holders
        };
        std::vector<Group> groups;
        for (unsigned int h = 0; h < list.size(); ++h)
          for (const auto &d : list[h].directions)
            {
              auto group =
                std::find_if(groups.begin(), groups.end(), [&](const Group &g) {
                  return std::abs(g.direction * d) > 1 - 1e-9;
                });
              if (group == groups.end())
                {
                  groups.push_back({d, {}});
                  group = groups.end() - 1;
                }
              group->members.push_back(h);
            }
        // (D D^T)^+ by its eigen decomposition (2 x 2, symmetric).
        SymmetricTensor<2, 2> DDt;
        for (const auto &g : groups)
          DDt += symmetrize(outer_product(g.direction, g.direction));
        const auto   eigen   = eigenvectors(DDt);
        const double largest = std::max(eigen[0].first, 1e-300);
        Tensor<2, 2> pseudo_inverse;
        for (const auto &[value, vector] : eigen)
          if (value > 1e-12 * largest)
            pseudo_inverse += outer_product(vector, vector) / value;
        for (const auto &g : groups)
          {
            const Tensor<1, 2> amount = pseudo_inverse * g.direction;
            if (g.members.size() == 1)
              {
                shares[list[g.members[0]].boundary].push_back(
                  {node, outer_product(g.direction, amount)});
                continue;
              }
            // Held along one direction by several boundaries (a corner of
            // two supports): see resultant().
            SharedDirection shared;
            shared.node      = node;
            shared.direction = g.direction;
            shared.amount    = amount;
            for (const unsigned int h : g.members)
              {
                Member member;
                member.boundary = list[h].boundary;
                member.weight   = list[h].weight;
                for (const Node &n : list[h].neighbours)
                  if (holders.at(n).size() == 1) // not a corner itself
                    member.neighbours.emplace_back(
                      n, weight_on.at({member.boundary, n}));
                shared.members.push_back(member);
              }
            shared_directions.push_back(shared);
          }
      }
  }

  Tensor<1, 2>
  BoundaryResultants::resultant(
    const types::boundary_id                         boundary_id,
    const Vector<double>                            &reactions,
    const std::map<types::boundary_id, Tensor<1, 2>> &applied) const
  {
    const auto reaction_at = [&](const Node &node) {
      return Tensor<1, 2>({reactions(node[0]), reactions(node[1])});
    };
    Tensor<1, 2> result;
    if (const auto load = applied.find(boundary_id); load != applied.end())
      result += load->second;
    if (const auto list = shares.find(boundary_id); list != shares.end())
      for (const Share &share : list->second)
        result += share.part * reaction_at(share.node);

    // A direction held at a node by several boundaries: the node's reaction
    // along it, c = amount . s, is the integral of each boundary's traction
    // times the node's shape function over its faces. Each boundary's part
    // is estimated from its traction density next to the node, the
    // reaction of its neighbouring nodes over their weights (int phi ds):
    // exact where each boundary's traction is uniform near the corner (a
    // split by face lengths alone was off by 9 % in the frictional patch
    // test, whose sides carry sigma_xx and its bottom sigma_xy). What the
    // estimates leave of c is shared by weight, so that the parts sum to c.
    for (const SharedDirection &shared : shared_directions)
      {
        const auto member =
          std::find_if(shared.members.begin(),
                       shared.members.end(),
                       [&](const Member &m) { return m.boundary == boundary_id; });
        if (member == shared.members.end())
          continue;
        const double total = shared.amount * reaction_at(shared.node);
        double       estimated = 0, weights = 0, own_estimate = 0;
        for (const Member &m : shared.members)
          {
            double along = 0, w = 0;
            for (const auto &[n, weight] : m.neighbours)
              {
                along += shared.direction * reaction_at(n);
                w += weight;
              }
            const double estimate = w > 0 ? along / w * m.weight : 0.0;
            estimated += estimate;
            weights += m.weight;
            if (&m == &*member)
              own_estimate = estimate;
          }
        const double part =
          own_estimate + (total - estimated) *
                           (weights > 0 ? member->weight / weights :
                                          1.0 / shared.members.size());
        result += part * shared.direction;
      }
    return result;
  }
} // namespace RingContact
