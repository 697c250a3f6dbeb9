// @sect3{Cyclic symmetry: a sector for the whole rings}
//
// The rings, their meshes (Ne elements around, the first vertex at angle 0) and
// the imposed displacements (the same radial displacement at every angle, a
// rigid turn of r = R3) are invariant under the rotation Q through 2 pi k / Ne
// for every k, and so is the discrete solution, u(Q X) = Q u(X). A sector of k
// elements gives it exactly, with N k / Ne of its N unknowns: the document's
// finest study, 1600 elements around and 120 across each ring, runs as a
// one-element sector of about a thousand unknowns. This file sizes the master
// surface beyond the sector (the window of the rotated copies that
// ContactSurface builds), pairs the nodes of the sector's two sides and ties
// them. deal.II's DoFTools::make_periodicity_constraints() pairs faces by a
// translation; a rotation needs the pairing by support points written here.
#include <deal.II/fe/fe.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/physics/transformations.h>

#include <ring_contact/base/dimension.h>
#include <ring_contact/contact/cyclic_symmetry.h>
#include <ring_contact/input/parameters.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace RingContact
{
  namespace CyclicSymmetry
  {
    // @sect4{The window of the master surface}
    //
    // A slave point of the sector reaches at most |s| + 1 elements beyond a
    // side (s the rotation in elements: the slave's slide along the master), so
    // c = 1 + ceil(|s| / k) copies on each side, c k >= k + |s| elements, hold
    // every master segment it can meet. Where the sector and c copies on each
    // side would go further round than the circle, (2 c + 1) k >= Ne, copies
    // would lie on top of the sector itself and the pairing would meet
    // coincident master segments (Newton failed for k = 21 and 23 to 39 of 40
    // around): the window is then exactly the circle, closed into one curve.
    // For example, k = 1 of 40 with s = 1: c = 2 and the window [-2, 3) in
    // elements; k = 21 of 40 with s = 0: c = 1 would make 63 elements, and the
    // window is 9 elements before the sector and 10 after it.
    void
    set_master_window(Sector            &sector,
                      const unsigned int sector_elements,
                      const unsigned int elements_around,
                      const double       slave_turn)
    {
      const unsigned int k = sector_elements, n = elements_around;
      AssertThrow(k >= 1 && k <= n,
                  ExcMessage("cyclic symmetry: the sector must have between "
                             "one element and all the elements around"));
      sector.copies =
        1 + static_cast<unsigned int>(std::ceil(std::abs(slave_turn) / k));
      // Whole elements before and after the sector.
      unsigned int before = sector.copies * k, after = sector.copies * k;
      if (k + before + after >= n)
        {
          // Exactly the circle, with the side the slave slides towards
          // long enough for its nodes never to leave the window (beyond
          // it they would meet the master surface only across the seam).
          // The side the slave slides towards (the sign of s) leads with
          // max(ceil((Ne - k) / 2), min(Ne - k, ceil(|s|) + 1)) elements: with
          // an even split, sectors of 12 elements turned by s = 3 failed for k
          // = 8 to 10 and converged to another solution for k = 11. Where k +
          // |s| >= Ne even this is not enough, and the parameters refuse it
          // (except k = Ne, the rings cut open, which needs no copy).
          const unsigned int lead =
            std::max((n - k + 1) / 2,
                     std::min(n - k,
                              static_cast<unsigned int>(
                                std::ceil(std::abs(slave_turn))) +
                                1));
          after  = slave_turn >= 0 ? lead : n - k - lead;
          before = n - k - after;
        }
      const double element_angle = 2 * numbers::PI / n;
      sector.window_before       = before * element_angle;
      sector.window_after        = after * element_angle;
      // Copies that keep no segment at all are not made.
      // ceil(max(before, after) / k): as many copies as the window reaches.
      sector.copies = (std::max(before, after) + k - 1) / k;
    }

    // @sect4{The nodes of the two sides}
    //
    // Each node on the end side (at angle Phi) is the image Q X_s of a node on
    // the start side. Both are found by the support points of the cells' dofs,
    // mapped to the real cell, per body: on r = R2 both rings have a node at
    // the same place (the interface nodes are duplicated: the rings are two
    // bodies), so a node is known by its body and its position.
    std::vector<NodePair>
    find_node_pairs(const DoFHandler<dim>            &dof_handler,
                    const hp::MappingCollection<dim> &mapping,
                    const double                      sector_angle,
                    const types::boundary_id          start_side,
                    const types::boundary_id          end_side)
    {
      // The nodes of each side: position, body, and dof per component.
      struct Node
      {
        Point<dim>         position;
        types::material_id body;
        std::array<types::global_dof_index, Components::n_components<dim>> dofs;
      };
      std::array<std::vector<Node>, 2> side_nodes; // start, end
      // 1e-10 of a length of the mesh's size, the distance of its first vertex
      // from the centre.
      const double tolerance =
        1e-10 * dof_handler.get_triangulation().get_vertices().front().norm();
      for (const auto &cell : dof_handler.active_cell_iterators())
        for (const unsigned int f : cell->face_indices())
          {
            const auto face = cell->face(f);
            if (!face->at_boundary() || (face->boundary_id() != start_side &&
                                         face->boundary_id() != end_side))
              continue;
            auto &nodes = side_nodes[face->boundary_id() == end_side];
            const FiniteElement<dim>            &fe = cell->get_fe();
            std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
            cell->get_dof_indices(dofs);
            // Support points of the cell's dofs that lie on the side: on
            // the line through the face's vertices.
            // The sides are straight radial lines: a cell with a face on a side
            // has dofs off it too, and those on the line through the face's
            // vertices are the side's.
            const Point<dim>     a = face->vertex(0), b = face->vertex(1);
            const Tensor<1, dim> along = (b - a) / (b - a).norm();
            for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
              {
                const unsigned int component =
                  fe.system_to_component_index(i).first;
                const Point<dim> x =
                  mapping[cell->active_fe_index()].transform_unit_to_real_cell(
                    cell, fe.unit_support_point(i));
                const Tensor<1, dim> d = x - a;
                if (std::abs(d[0] * along[1] - d[1] * along[0]) > tolerance)
                  continue;
                // A node is met again through its other components and through
                // the neighbouring cell: one node, one entry per component. A
                // linear search is enough, a side has at most a few hundred
                // nodes.
                Node *node = nullptr;
                for (auto &n : nodes)
                  if (n.body == cell->material_id() &&
                      n.position.distance(x) < tolerance)
                    node = &n;
                if (node == nullptr)
                  {
                    // The displacement and multiplier entries start invalid: a
                    // ring without the multiplier (the master, and the slave's
                    // cells off the layer) keeps it so.
                    nodes.push_back({x,
                                     cell->material_id(),
                                     {{numbers::invalid_dof_index,
                                       numbers::invalid_dof_index,
                                       numbers::invalid_dof_index}}});
                    node = &nodes.back();
                  }
                node->dofs[component] = dofs[i];
              }
          }

      // Each end node and the start node it is the image of.
      const Tensor<2, dim> R =
        Physics::Transformations::Rotations::rotation_matrix_2d(sector_angle);
      std::vector<NodePair> pairs;
      // Within the same body, by turning each start node through Phi.
      for (const Node &end : side_nodes[1])
        {
          const Node *image = nullptr;
          for (const Node &start : side_nodes[0])
            if (start.body == end.body && end.position.distance(Point<dim>(
                                            R * start.position)) < tolerance)
              image = &start;
          // Sides that do not match under the rotation cannot be tied: refused
          // with the reason, rather than tied wrongly.
          if (image == nullptr)
            throw std::runtime_error(
              "cyclic symmetry: a node of the sector's end side has no image "
              "on its start side");
          pairs.push_back({end.dofs, image->dofs});
        }
      // And the converse: no node of the start side is left without its image.
      if (pairs.size() != side_nodes[0].size())
        throw std::runtime_error("cyclic symmetry: the two sides of the "
                                 "sector do not carry the same nodes");
      return pairs;
    }

    // The multiplier dofs of the pairs, end to start. The contact interface
    // makes each pair one contact node, its w_k and g~_k summed over its two
    // halves, so that the active set is decided on the whole node rather than
    // on each half.
    std::map<types::global_dof_index, types::global_dof_index>
    multiplier_pairs(const std::vector<NodePair> &pairs)
    {
      std::map<types::global_dof_index, types::global_dof_index> twins;
      for (const auto &pair : pairs)
        if (pair.end[Components::multiplier<dim>] != numbers::invalid_dof_index)
          twins[pair.end[Components::multiplier<dim>]] =
            pair.start[Components::multiplier<dim>];
      return twins;
    }

    // @sect4{The ties}
    //
    // u(X_e) = Q u(X_s), two entries per component, u_e,i = sum_j Q_ij u_s,j,
    // and lambda(X_e) = lambda(X_s), the contact pressure being a scalar: in
    // the AffineConstraints of the Newton update, condensed in the assembly as
    // any other constraint.
    void
    add_constraints(const std::vector<NodePair> &pairs,
                    const double                 sector_angle,
                    AffineConstraints<double>   &constraints)
    {
      const Tensor<2, dim> R =
        Physics::Transformations::Rotations::rotation_matrix_2d(sector_angle);
      for (const auto &pair : pairs)
        {
          // A node whose displacement is constrained already keeps its
          // constraint: the corners on r = R1 and r = R3 have their imposed
          // values, which satisfy the same relation (the imposed data are
          // symmetric themselves). In the rings' case, the only problem with a
          // sector, those corners have both components imposed, so one test
          // serves both.
          if (!constraints.is_constrained(pair.end[0]) &&
              !constraints.is_constrained(pair.end[1]))
            for (unsigned int i = 0; i < dim; ++i)
              {
                constraints.add_line(pair.end[i]);
                for (unsigned int j = 0; j < dim; ++j)
                  constraints.add_entry(pair.end[i], pair.start[j], R[i][j]);
              }
          // The multiplier is tied where it is an unknown; on the layer's nodes
          // off the slave surface it is constrained to zero already, and stays
          // so.
          if (pair.end[Components::multiplier<dim>] !=
                numbers::invalid_dof_index &&
              !constraints.is_constrained(
                pair.end[Components::multiplier<dim>]))
            {
              constraints.add_line(pair.end[Components::multiplier<dim>]);
              constraints.add_entry(pair.end[Components::multiplier<dim>],
                                    pair.start[Components::multiplier<dim>],
                                    1.0);
            }
        }
    }
  } // namespace CyclicSymmetry
} // namespace RingContact
