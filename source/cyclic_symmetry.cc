#include <deal.II/fe/fe.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/physics/transformations.h>

#include <ring_contact/cyclic_symmetry.h>
#include <ring_contact/parameters.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace RingContact
{
  namespace CyclicSymmetry
  {
    void
    set_master_window(Sector            &sector,
                      const unsigned int sector_elements,
                      const unsigned int elements_around,
                      const double       rotation_elements)
    {
      const unsigned int k = sector_elements, n = elements_around;
      AssertThrow(k >= 1 && k <= n,
                  ExcMessage("cyclic symmetry: the sector must have between "
                             "one element and all the elements around"));
      sector.copies = 1 + static_cast<unsigned int>(
                            std::ceil(std::abs(rotation_elements) / k));
      // Whole elements before and after the sector.
      unsigned int before = sector.copies * k, after = sector.copies * k;
      if (k + before + after >= n)
        {
          // Exactly the circle, with the side the slave slides towards
          // long enough for its nodes never to leave the window (beyond
          // it they would meet the master surface only across the seam).
          const unsigned int lead =
            std::max((n - k + 1) / 2,
                     std::min(n - k,
                              static_cast<unsigned int>(
                                std::ceil(std::abs(rotation_elements))) +
                                1));
          after  = rotation_elements >= 0 ? lead : n - k - lead;
          before = n - k - after;
        }
      const double element_angle = 2 * numbers::PI / n;
      sector.window_before       = before * element_angle;
      sector.window_after        = after * element_angle;
      // Copies that keep no segment at all are not made.
      sector.copies = (std::max(before, after) + k - 1) / k;
    }

    std::vector<NodePair>
    find_node_pairs(const DoFHandler<2>            &dof_handler,
                    const hp::MappingCollection<2> &mapping,
                    const double                    sector_angle)
    {
      // The nodes of each side: position, ring, and dof per component.
      struct Node
      {
        Point<2>                                                      position;
        types::material_id                                            ring;
        std::array<types::global_dof_index, Components::n_components> dofs;
      };
      std::array<std::vector<Node>, 2> side_nodes; // start, end
      const double                     tolerance =
        1e-10 * dof_handler.get_triangulation().get_vertices().front().norm();
      for (const auto &cell : dof_handler.active_cell_iterators())
        for (const unsigned int f : cell->face_indices())
          {
            const auto face = cell->face(f);
            if (!face->at_boundary() ||
                (face->boundary_id() != Ids::sector_start &&
                 face->boundary_id() != Ids::sector_end))
              continue;
            auto &nodes = side_nodes[face->boundary_id() == Ids::sector_end];
            const FiniteElement<2>              &fe = cell->get_fe();
            std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
            cell->get_dof_indices(dofs);
            // Support points of the cell's dofs that lie on the side: on
            // the line through the face's vertices.
            const Point<2>     a = face->vertex(0), b = face->vertex(1);
            const Tensor<1, 2> along = (b - a) / (b - a).norm();
            for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
              {
                const unsigned int component =
                  fe.system_to_component_index(i).first;
                const Point<2> x =
                  mapping[cell->active_fe_index()].transform_unit_to_real_cell(
                    cell, fe.unit_support_point(i));
                const Tensor<1, 2> d = x - a;
                if (std::abs(d[0] * along[1] - d[1] * along[0]) > tolerance)
                  continue;
                Node *node = nullptr;
                for (auto &n : nodes)
                  if (n.ring == cell->material_id() &&
                      n.position.distance(x) < tolerance)
                    node = &n;
                if (node == nullptr)
                  {
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
      const Tensor<2, 2> R =
        Physics::Transformations::Rotations::rotation_matrix_2d(sector_angle);
      std::vector<NodePair> pairs;
      for (const Node &end : side_nodes[1])
        {
          const Node *image = nullptr;
          for (const Node &start : side_nodes[0])
            if (start.ring == end.ring &&
                end.position.distance(Point<2>(R * start.position)) < tolerance)
              image = &start;
          if (image == nullptr)
            throw std::runtime_error(
              "cyclic symmetry: a node of the sector's end side has no image "
              "on its start side");
          pairs.push_back({end.dofs, image->dofs});
        }
      if (pairs.size() != side_nodes[0].size())
        throw std::runtime_error("cyclic symmetry: the two sides of the "
                                 "sector do not carry the same nodes");
      return pairs;
    }

    std::map<types::global_dof_index, types::global_dof_index>
    multiplier_pairs(const std::vector<NodePair> &pairs)
    {
      std::map<types::global_dof_index, types::global_dof_index> twins;
      for (const auto &pair : pairs)
        if (pair.end[Components::multiplier] != numbers::invalid_dof_index)
          twins[pair.end[Components::multiplier]] =
            pair.start[Components::multiplier];
      return twins;
    }

    void
    add_constraints(const std::vector<NodePair> &pairs,
                    const double                 sector_angle,
                    AffineConstraints<double>   &constraints)
    {
      const Tensor<2, 2> R =
        Physics::Transformations::Rotations::rotation_matrix_2d(sector_angle);
      for (const auto &pair : pairs)
        {
          if (!constraints.is_constrained(pair.end[0]) &&
              !constraints.is_constrained(pair.end[1]))
            for (unsigned int i = 0; i < 2; ++i)
              {
                constraints.add_line(pair.end[i]);
                for (unsigned int j = 0; j < 2; ++j)
                  constraints.add_entry(pair.end[i], pair.start[j], R[i][j]);
              }
          if (pair.end[Components::multiplier] != numbers::invalid_dof_index &&
              !constraints.is_constrained(pair.end[Components::multiplier]))
            {
              constraints.add_line(pair.end[Components::multiplier]);
              constraints.add_entry(pair.end[Components::multiplier],
                                    pair.start[Components::multiplier],
                                    1.0);
            }
        }
    }
  } // namespace CyclicSymmetry
} // namespace RingContact
