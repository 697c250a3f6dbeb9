// @sect3{The multiplier nodes of a slave surface}
//
// A contact node is a multiplier unknown of the slave surface. Its rows are
// one equation per node (the complementarity function C_k, with friction
// the Coulomb law), summed over the slave points whose basis function Phi_k
// reaches it, and scaled by its reference weight w_k. The numbering k, the
// weights and the neighbours along the surface are made here once, from the
// slave surface's segments: the active set, the contact rows and the
// postprocessing all index by k.
#include <deal.II/base/quadrature_lib.h>

#include <ring_contact/contact/multiplier_nodes.h>

#include <algorithm>

namespace RingContact
{
  // @sect4{Numbering and weights}
  //
  // The multiplier nodes, and w_k = int Phi_k dS with a Gauss rule of
  // n_geometry + n_multiplier points: exact on straight segments, where |X'|
  // is constant; on curved ones |X'| is the square root of a polynomial,
  // integrated to the rule's accuracy. A twin (cyclic symmetry) is the node
  // of its image on the start side.
  // w_k is the reference weight, a constant: the open rows w_k lambda_k = 0
  // and the trial tractions stay linear in the unknowns, and the rows keep
  // their scale however the surface stretches.
  MultiplierNodes::MultiplierNodes(
    const ContactSurface                                             &slave,
    const std::map<types::global_dof_index, types::global_dof_index> &twins,
    const bool                                                        friction)
  {
    const QGauss<1> exact(slave.geometry_basis().size() +
                          slave.multiplier_basis().size());
    const auto      node_of = [&](const types::global_dof_index dof) {
      const auto twin = twins.find(dof);
      return twin == twins.end() ? dof : twin->second;
    };
    for (unsigned int s = 0; s < slave.segments().size(); ++s)
      {
        const auto &segment = slave.segments()[s];
        for (unsigned int k = 0; k < segment.multiplier_dofs.size(); ++k)
          {
            const auto dof  = segment.multiplier_dofs[k];
            const auto node = node_of(dof);
            // A node met for the first time gets the next index k; a vertex
            // shared by two segments, or a twin, finds its index there, and
            // its weight is summed over its segments below.
            if (index.count(node) == 0)
              {
                index[node] = dofs.size();
                dofs.push_back(node);
                reference_weight.push_back(0.0);
                // The tangential dof of the same node at the same index: the
                // friction arrays are indexed by k like the normal ones.
                if (friction)
                  {
                    AssertThrow(segment.tangential_dofs.size() ==
                                  segment.multiplier_dofs.size(),
                                ExcInternalError());
                    tangential_dofs.push_back(segment.tangential_dofs[k]);
                  }
              }
            index[dof] = index[node];
            // Where each node sits (segment, t), for the postprocessing: the
            // nearest node, the stretch and the nodal gap look it up instead
            // of searching.
            sites[node].emplace_back(s, slave.multiplier_nodes()[k]);
          }
        for (unsigned int q = 0; q < exact.size(); ++q)
          {
            std::vector<double> Phi;
            slave.multiplier_basis().evaluate(exact.point(q)[0], Phi);
            const double dS =
              slave.reference_point(s, exact.point(q)[0]).dx.norm() *
              exact.weight(q);
            for (unsigned int k = 0; k < Phi.size(); ++k)
              reference_weight[index[segment.multiplier_dofs[k]]] +=
                Phi[k] * dS;
          }
      }
    link_neighbours(slave);
  }

  // @sect4{Neighbours along the surface}
  //
  // The walks of the zones' edge extrapolation (active_set.cc) go from node
  // to node along the surface, and measure how far they went: on each
  // segment the nodes sorted by their parameter, consecutive ones linked
  // with their distance in the reference configuration.
  void
  MultiplierNodes::link_neighbours(const ContactSurface &slave)
  {
    neighbours.assign(dofs.size(), {});
    std::vector<std::vector<std::pair<double, unsigned int>>> on_segment(
      slave.segments().size());
    for (const auto &[dof, node_sites] : sites)
      for (const auto &[s, t] : node_sites)
        on_segment[s].emplace_back(t, index.at(dof));
    for (unsigned int s = 0; s < on_segment.size(); ++s)
      {
        auto &nodes = on_segment[s];
        std::sort(nodes.begin(), nodes.end());
        for (unsigned int i = 1; i < nodes.size(); ++i)
          {
            const unsigned int a = nodes[i - 1].second, b = nodes[i].second;
            const double       length =
              slave.reference_point(s, nodes[i].first)
                .x.distance(slave.reference_point(s, nodes[i - 1].first).x);
            for (const auto &[from, to] :
                 {std::make_pair(a, b), std::make_pair(b, a)})
              if (from != to && std::none_of(neighbours[from].begin(),
                                             neighbours[from].end(),
                                             [to = to](const auto &n) {
                                               return n.first == to;
                                             }))
                neighbours[from].emplace_back(to, length);
          }
      }
  }

  std::vector<types::global_dof_index>
  MultiplierNodes::all_dofs() const
  {
    std::vector<types::global_dof_index> all;
    for (const auto &[dof, k] : index)
      all.push_back(dof);
    return all;
  }

  // The faces' nodes: each dof its own node, the weights the caller's. Two
  // nodes are neighbours where an edge of a face joins them (in the
  // lexicographic order 0-1, 2-3, 0-2, 1-3), once however many faces share
  // the edge; the link's length is the edge's in the reference
  // configuration.
  MultiplierNodes::MultiplierNodes(
    const std::vector<types::global_dof_index>     &dofs,
    const std::vector<double>                      &weights,
    const std::vector<std::array<unsigned int, 4>> &faces,
    const std::vector<Point<3>>                    &positions)
      : dofs(dofs)
      , reference_weight(weights)
      , neighbours(dofs.size())
      , surface_position(positions)
  {
    AssertDimension(positions.size(), dofs.size());
    for (unsigned int k = 0; k < dofs.size(); ++k)
      index[dofs[k]] = k;
    constexpr std::array<std::array<unsigned int, 2>, 4> edges = {
      {{{0, 1}}, {{2, 3}}, {{0, 2}}, {{1, 3}}}};
    for (const auto &face : faces)
      for (const auto &[a, b] : edges)
        {
          const unsigned int i = face[a], j = face[b];
          const auto linked = [&](const auto &link) { return link.first == j; };
          if (std::any_of(neighbours[i].begin(), neighbours[i].end(), linked))
            continue;
          const double length = positions[i].distance(positions[j]);
          neighbours[i].emplace_back(j, length);
          neighbours[j].emplace_back(i, length);
        }
  }

  // Without friction there is no tangential traction (and no list).
  types::global_dof_index
  MultiplierNodes::tangential_dof(
    const types::global_dof_index multiplier_dof) const
  {
    if (tangential_dofs.empty())
      return numbers::invalid_dof_index;
    return tangential_dofs[index.at(multiplier_dof)];
  }
} // namespace RingContact
