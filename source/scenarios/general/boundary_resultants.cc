// @sect3{Resultant forces on boundaries}
//
// A check of Quantity = resultant force x or y (quantities.cc) asks here
// for the force on one boundary: its applied load where it is loaded, its
// part of the support reactions where it is supported. The reactions are
// nodal, and a corner node belongs to two boundaries; summing the nodal
// forces over a boundary's nodes, as was done first, gave wrong resultants for
// blocks loaded by (0.1 p, -p) with one x-support, on the support, the loaded
// edge and a free edge alike (doc/validation.md, "Figures that were in the
// code's comments"). The split of a corner's reaction is set up once per mesh
// (the constructor: which boundaries hold each node, along which directions,
// with which weights) and applied to each state's reactions (resultant()). The
// reactions leave out the contact forces: a support whose end node lies on a
// contact surface once reported that node's contact force as its own.
// general.cc uses the two helpers below too, for its check of a load along a
// held direction.
#include <deal.II/base/quadrature.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/hp/fe_values.h>
#include <deal.II/hp/q_collection.h>

#include <ring_contact/base/components.h>
#include <ring_contact/base/dimension.h>
#include <ring_contact/scenarios/general/boundary_resultants.h>

#include <algorithm>
#include <cmath>
#include <set>

namespace RingContact
{
  // The unit directions a support holds at a point of its boundary: the
  // axes it imposes, e_r and e_theta at the point's angle about the origin,
  // or the outward normal. A support's reaction acts along these and no
  // other: the remaining direction of the node is free, its row balanced.
  template <int dim>
  std::vector<Tensor<1, dim>>
  SupportCondition::directions(const Point<dim>     &X,
                               const Tensor<1, dim> &N) const
  {
    std::vector<Tensor<1, dim>> held;
    switch (kind)
      {
        case Kind::cartesian:
          for (unsigned int c = 0; c < dim; ++c)
            if (components[c])
              held.push_back(Point<dim>::unit_vector(c));
          break;
        case Kind::polar:
          {
            // About the origin; in 3D about the z axis, with z Cartesian.
            const double   theta = std::atan2(X[1], X[0]);
            Tensor<1, dim> e_r, e_theta;
            e_r[0]     = std::cos(theta);
            e_r[1]     = std::sin(theta);
            e_theta[0] = -std::sin(theta);
            e_theta[1] = std::cos(theta);
            if (components[0])
              held.push_back(e_r);
            if (components[1])
              held.push_back(e_theta);
            if (dim == 3 && components[2])
              held.push_back(Point<dim>::unit_vector(dim - 1));
            break;
          }
        case Kind::normal:
          held.push_back(N);
          break;
      }
    return held;
  }

  // The displacement nodes of face f: the face unknowns u_x, u_y (, u_z) at
  // one support point, each with the index of its u_x unknown on the face.
  // The points are compared exactly: all come from one unit point through
  // one mapping. The multiplier's unknowns (on a layer cell) are none of
  // them, and are skipped.
  template <int dim>
  std::vector<std::pair<unsigned int, std::array<types::global_dof_index, dim>>>
  face_nodes(const FiniteElement<dim>                   &fe,
             const unsigned int                          f,
             const FEFaceValues<dim>                    &fv,
             const std::vector<types::global_dof_index> &face_dofs)
  {
    std::vector<
      std::pair<unsigned int, std::array<types::global_dof_index, dim>>>
      nodes;
    for (unsigned int i = 0; i < face_dofs.size(); ++i)
      if (fe.face_system_to_component_index(i, f).first == Components::ux)
        {
          std::array<types::global_dof_index, dim> dofs;
          dofs.fill(numbers::invalid_dof_index);
          dofs[0] = face_dofs[i];
          for (unsigned int j = 0; j < face_dofs.size(); ++j)
            {
              const unsigned int c =
                fe.face_system_to_component_index(j, f).first;
              if (c > 0 && c < dim &&
                  fv.quadrature_point(j) == fv.quadrature_point(i))
                dofs[c] = face_dofs[j];
            }
          if (std::find(dofs.begin(), dofs.end(), numbers::invalid_dof_index) ==
              dofs.end())
            nodes.emplace_back(i, dofs);
        }
    return nodes;
  }

  template std::vector<
    std::pair<unsigned int, std::array<types::global_dof_index, 2>>>
  face_nodes<2>(const FiniteElement<2> &,
                const unsigned int,
                const FEFaceValues<2> &,
                const std::vector<types::global_dof_index> &);
  template std::vector<
    std::pair<unsigned int, std::array<types::global_dof_index, 3>>>
  face_nodes<3>(const FiniteElement<3> &,
                const unsigned int,
                const FEFaceValues<3> &,
                const std::vector<types::global_dof_index> &);

  // Every boundary face with its displacement nodes, in the reference
  // configuration (a support's directions and a check's boundary are
  // those of the undeformed mesh).
  template <int dim>
  void
  for_each_boundary_face(
    const DoFHandler<dim>            &dof_handler,
    const hp::MappingCollection<dim> &mapping,
    const std::function<
      void(const typename DoFHandler<dim>::active_cell_iterator &,
           const unsigned int,
           const std::vector<BoundaryNode<dim>> &)> &visit)
  {
    // The support points of each element's faces as a face quadrature, so
    // that FEFaceValues gives their positions and the normals there; and a
    // Gauss rule for the integral of each node's shape function. p + 1
    // points integrate a shape function of degree p exactly on a straight
    // face. That integral, int phi ds, is the node's share of a uniform
    // traction t (its nodal force is t int phi ds): a reaction over it is
    // the traction density at the node, which resultant() relies on.
    const auto              &fe_collection = dof_handler.get_fe_collection();
    hp::QCollection<dim - 1> support_points, gauss;
    for (unsigned int i = 0; i < fe_collection.size(); ++i)
      {
        support_points.push_back(Quadrature<dim - 1>(
          fe_collection[i].get_unit_face_support_points(0)));
        gauss.push_back(QGauss<dim - 1>(fe_collection[i].degree + 1));
      }
    hp::FEFaceValues<dim>                at_nodes(mapping,
                                   fe_collection,
                                   support_points,
                                   update_quadrature_points |
                                     update_normal_vectors);
    hp::FEFaceValues<dim>                integrals(mapping,
                                    fe_collection,
                                    gauss,
                                    update_values | update_JxW_values);
    std::vector<types::global_dof_index> face_dofs;
    std::vector<BoundaryNode<dim>>       nodes;
    for (const auto &cell : dof_handler.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary())
          {
            at_nodes.reinit(cell, f);
            integrals.reinit(cell, f);
            const FEFaceValues<dim>  &fv = at_nodes.get_present_fe_values();
            const FEFaceValues<dim>  &iv = integrals.get_present_fe_values();
            const FiniteElement<dim> &fe = cell->get_fe();
            face_dofs.resize(fe.n_dofs_per_face(f));
            cell->face(f)->get_dof_indices(face_dofs, cell->active_fe_index());
            nodes.clear();
            for (const auto &[i, dofs] : face_nodes(fe, f, fv, face_dofs))
              {
                // int phi ds of the node's shape function on the face.
                const unsigned int cell_i = fe.face_to_cell_index(i, f);
                double             weight = 0;
                for (unsigned int q = 0; q < iv.n_quadrature_points; ++q)
                  weight += iv.shape_value(cell_i, q) * iv.JxW(q);
                nodes.push_back(
                  {fv.quadrature_point(i), fv.normal_vector(i), dofs, weight});
              }
            visit(cell, f, nodes);
          }
  }

  template <int dim>
  BoundaryResultants<dim>::BoundaryResultants(
    const DoFHandler<dim>               &dof_handler,
    const hp::MappingCollection<dim>    &mapping,
    const std::vector<SupportCondition> &supports)
  {
    // The conditions of one boundary merged into one support: x imposed by
    // one slot and y by another (problem_parameters.cc allows two slots
    // on disjoint components, both Cartesian or both polar, and a normal
    // one only alone) hold both directions. Kept by boundary, the second
    // slot replaced the first, whose direction was then held by no
    // boundary: its reaction reached no resultant (the two blocks held
    // at the bottom by an x and a y slot reported a force y of 0 there).
    std::map<types::boundary_id, SupportCondition> support_of;
    for (const auto &support : supports)
      {
        const auto [merged, first] =
          support_of.emplace(support.boundary_id, support);
        if (first)
          continue;
        Assert(merged->second.kind == support.kind &&
                 support.kind != SupportCondition::Kind::normal,
               ExcMessage("Two supports of one boundary must be both "
                          "Cartesian or both polar."));
        for (unsigned int c = 0; c < dim; ++c)
          merged->second.components[c] =
            merged->second.components[c] || support.components[c];
      }

    // Per node: the boundaries that hold it (Holder), each with the
    // directions it holds there, the node's weight summed over the
    // boundary's faces at the node, and the other nodes of those faces (its
    // neighbours along that boundary, for the estimates of resultant()).
    // Loaded and free boundaries hold nothing and are skipped.
    Holders holders;
    Weights weight_on;
    for_each_boundary_face<dim>(
      dof_handler,
      mapping,
      [&](const auto                           &cell,
          const unsigned int                    f,
          const std::vector<BoundaryNode<dim>> &nodes) {
        const auto id      = cell->face(f)->boundary_id();
        const auto support = support_of.find(id);
        if (support == support_of.end())
          return;
        for (const BoundaryNode<dim> &node : nodes)
          {
            position_of[node.dofs] = node.X;
            auto &list             = holders[node.dofs];
            auto  it =
              std::find_if(list.begin(), list.end(), [&](const auto &h) {
                return h.boundary == id;
              });
            if (it == list.end())
              {
                list.push_back(
                  {id,
                   support->second.template directions<dim>(node.X, node.N),
                   0.0,
                   {}});
                it = list.end() - 1;
              }
            else if (support->second.kind == SupportCondition::Kind::normal)
              {
                // Two faces of one boundary at a node: the mean normal.
                Tensor<1, dim> mean = it->directions[0] + node.N;
                if (mean.norm() > 0)
                  it->directions[0] = mean / mean.norm();
              }
            it->weight += node.weight;
            weight_on[{id, node.dofs}] += node.weight;
            for (const BoundaryNode<dim> &other : nodes)
              if (other.dofs != node.dofs)
                it->neighbours.insert(other.dofs);
          }
      });

    for (const auto &[node, list] : holders)
      split_reaction(node, list, holders, weight_on);
  }


  // Per node: the directions held, grouped where parallel; the reaction s
  // split as s = sum_g c_g d_g with the least c (exactly when two
  // independent directions are held), c_g = d_g . (D D^T)^+ s.
  template <int dim>
  void
  BoundaryResultants<dim>::split_reaction(const Node                &node,
                                          const std::vector<Holder> &list,
                                          const Holders             &holders,
                                          const Weights             &weight_on)
  {
    // Directions of different holders within 1e-9 of parallel are one
    // group: the two x-supports that meet at a corner hold one direction,
    // and the reaction along it must be shared between them, not counted
    // twice.
    struct Group
    {
      Tensor<1, dim>            direction;
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
    // (D D^T)^+ by its eigen decomposition (dim x dim, symmetric). A pseudo-
    // inverse, because a node held along one direction only has a D D^T
    // of rank one; the reaction s is zero at the unknowns no support holds
    // (NodalForces::reactions()), and any part of s along no held direction
    // is left out. Eigenvalues below 1e-12 of the largest count as zero.
    SymmetricTensor<2, dim> DDt;
    for (const auto &g : groups)
      DDt += symmetrize(outer_product(g.direction, g.direction));
    const auto     eigen   = eigenvectors(DDt);
    const double   largest = std::max(eigen[0].first, 1e-300);
    Tensor<2, dim> pseudo_inverse;
    for (const auto &[value, vector] : eigen)
      if (value > 1e-12 * largest)
        pseudo_inverse += outer_product(vector, vector) / value;
    for (const auto &g : groups)
      {
        // c_g = amount . s. A direction one boundary holds alone is that
        // boundary's: its part of the reaction is d_g c_g, a fixed linear
        // map of s, stored as a tensor.
        const Tensor<1, dim> amount = pseudo_inverse * g.direction;
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
            // A neighbour that is a corner itself has its reaction split
            // too: it tells nothing of this boundary's own traction.
            for (const Node &n : list[h].neighbours)
              if (holders.at(n).size() == 1) // not a corner itself
                member.neighbours.emplace_back(
                  n, weight_on.at({member.boundary, n}));
            shared.members.push_back(member);
          }
        shared_directions.push_back(shared);
      }
  }

  template <int dim>
  void
  BoundaryResultants<dim>::for_each_part(
    const types::boundary_id boundary_id,
    const Vector<double>    &reactions,
    const std::function<void(const Node &, const Tensor<1, dim> &)> &visit)
    const
  {
    // A node's reaction as a vector: its displacement rows.
    const auto reaction_at = [&](const Node &node) {
      Tensor<1, dim> s;
      for (unsigned int d = 0; d < dim; ++d)
        s[d] = reactions(node[d]);
      return s;
    };
    // The directions this boundary holds alone, node by node: the
    // reaction's component along each is wholly its own.
    if (const auto list = shares.find(boundary_id); list != shares.end())
      for (const Share &share : list->second)
        visit(share.node, share.part * reaction_at(share.node));

    // A direction held at a node by several boundaries: the node's reaction
    // along it, c = amount . s, is the integral of each boundary's traction
    // times the node's shape function over its faces. Each boundary's part
    // is estimated from its traction density next to the node, the
    // reaction of its neighbouring nodes over their weights (int phi ds):
    // exact where each boundary's traction is uniform near the corner (a
    // split by face lengths alone was off in the frictional patch test, whose
    // sides carry sigma_xx and its bottom sigma_xy: doc/validation.md, "Figures
    // that were in the code's comments"). What the estimates leave of c is
    // shared by weight, so that the parts sum to c.
    for (const SharedDirection &shared : shared_directions)
      {
        const auto member = std::find_if(shared.members.begin(),
                                         shared.members.end(),
                                         [&](const Member &m) {
                                           return m.boundary == boundary_id;
                                         });
        if (member == shared.members.end())
          continue;
        const double total     = shared.amount * reaction_at(shared.node);
        double       estimated = 0, weights = 0, own_estimate = 0;
        for (const Member &m : shared.members)
          {
            double along = 0, w = 0;
            for (const auto &[n, weight] : m.neighbours)
              {
                along += shared.direction * reaction_at(n);
                w += weight;
              }
            // The neighbours' reaction per unit weight is the boundary's
            // traction density; times the corner node's weight on that
            // boundary, its part. A boundary with no neighbour that is not
            // a corner (one face between two corners) estimates nothing
            // and gets its share of the remainder only.
            const double estimate = w > 0 ? along / w * m.weight : 0.0;
            estimated += estimate;
            weights += m.weight;
            if (&m == &*member)
              own_estimate = estimate;
          }
        const double part =
          own_estimate + (total - estimated) * (weights > 0 ?
                                                  member->weight / weights :
                                                  1.0 / shared.members.size());
        visit(shared.node, part * shared.direction);
      }
  }


  template <int dim>
  Tensor<1, dim>
  BoundaryResultants<dim>::resultant(
    const types::boundary_id                            boundary_id,
    const Vector<double>                               &reactions,
    const std::map<types::boundary_id, Tensor<1, dim>> &applied) const
  {
    // The applied load is integrated by the assembly over the boundary's
    // own faces: no corner question arises for it.
    Tensor<1, dim> result;
    if (const auto load = applied.find(boundary_id); load != applied.end())
      result += load->second;
    for_each_part(boundary_id,
                  reactions,
                  [&](const Node &, const Tensor<1, dim> &force) {
                    result += force;
                  });
    return result;
  }


  // The moment of a force f at x about c, (x - c) x f, with three
  // components (in 2D the third alone).
  namespace
  {
    template <int dim>
    Tensor<1, 3>
    moment_of(const Tensor<1, dim> &arm, const Tensor<1, dim> &force)
    {
      Tensor<1, 3> r, f;
      for (unsigned int d = 0; d < dim; ++d)
        {
          r[d] = arm[d];
          f[d] = force[d];
        }
      return cross_product_3d(r, f);
    }
  } // namespace

  // The applied loads' moment is the assembly's integral of x x t about the
  // origin, moved to the centre: M_c = M_0 - c x F. The reactions' parts act
  // at their nodes.
  template <int dim>
  Tensor<1, 3>
  BoundaryResultants<dim>::moment(
    const types::boundary_id                            boundary_id,
    const Vector<double>                               &reactions,
    const std::map<types::boundary_id, Tensor<1, dim>> &applied,
    const std::map<types::boundary_id, Tensor<1, 3>>   &applied_moments,
    const Point<dim>                                   &centre,
    const Vector<double>                               *displacement) const
  {
    Tensor<1, 3> result;
    if (const auto load = applied_moments.find(boundary_id);
        load != applied_moments.end())
      result += load->second - moment_of<dim>(centre, applied.at(boundary_id));
    for_each_part(boundary_id,
                  reactions,
                  [&](const Node &node, const Tensor<1, dim> &force) {
                    Tensor<1, dim> arm = position_of.at(node) - centre;
                    if (displacement != nullptr)
                      for (unsigned int d = 0; d < dim; ++d)
                        arm[d] += (*displacement)(node[d]);
                    result += moment_of<dim>(arm, force);
                  });
    return result;
  }

  // The two dimensions of the program (issue 48).
  template std::vector<Tensor<1, 2>>
  SupportCondition::directions<2>(const Point<2> &, const Tensor<1, 2> &) const;
  template std::vector<Tensor<1, 3>>
  SupportCondition::directions<3>(const Point<3> &, const Tensor<1, 3> &) const;
  template void
  for_each_boundary_face<2>(
    const DoFHandler<2> &,
    const hp::MappingCollection<2> &,
    const std::function<void(const DoFHandler<2>::active_cell_iterator &,
                             const unsigned int,
                             const std::vector<BoundaryNode<2>> &)> &);
  template void
  for_each_boundary_face<3>(
    const DoFHandler<3> &,
    const hp::MappingCollection<3> &,
    const std::function<void(const DoFHandler<3>::active_cell_iterator &,
                             const unsigned int,
                             const std::vector<BoundaryNode<3>> &)> &);
  template class BoundaryResultants<2>;
  template class BoundaryResultants<3>;
} // namespace RingContact
