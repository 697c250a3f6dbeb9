// The contact interface of a pair of surfaces in 3D (face_contact_interface.h):
// FaceContact's pairs and rows, the 2D ActiveSet's choice between them.
#include <deal.II/base/geometry_info.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/lac/full_matrix.h>

#include <ring_contact/contact/face_contact_interface.h>

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>

namespace RingContact
{
  namespace
  {
    /// The shortest edge of the faces of boundary tag `tag`: the length
    /// that scales the complementarity constant and the active set's
    /// round-off (2D: the shortest slave segment).
    double
    shortest_edge(const DoFHandler<3>     &dof_handler,
                  const types::boundary_id tag)
    {
      double shortest = std::numeric_limits<double>::max();
      for (const auto &cell : dof_handler.active_cell_iterators())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary() && face->boundary_id() == tag)
            for (unsigned int l = 0; l < GeometryInfo<2>::lines_per_cell; ++l)
              shortest = std::min(shortest, face->line(l)->diameter());
      if (shortest == std::numeric_limits<double>::max())
        throw std::runtime_error("the slave surface (boundary tag " +
                                 std::to_string(tag) + ") has no faces");
      return shortest;
    }

    /// The 3D form of a contact integration scheme of the .prm file:
    /// segment-based, nodal, and Gauss n (n x n points per face); the
    /// Newton-Cotes rules of the 2D segments have none.
    FaceContact::Scheme
    face_scheme(const IntegrationScheme &scheme)
    {
      if (scheme.cuts_at_master_kinks())
        return FaceContact::Scheme::segment_based;
      if (scheme.family->name == "nodal")
        return FaceContact::Scheme::nodal;
      if (scheme.family->name == "Gauss")
        return FaceContact::Scheme::gauss;
      throw std::runtime_error(
        "the contact integration scheme '" + scheme.name() +
        "' is 2D only: in 3D the schemes are segment-based, nodal and Gauss "
        "n (n x n points per slave face)");
    }
  } // namespace


  ContactInterface<3>::ContactInterface(const DoFHandler<3>     &dof_handler,
                                        const ContactParameters &parameters,
                                        const IntegrationScheme &scheme,
                                        const double largest_youngs_modulus,
                                        const bool   geometrically_linear,
                                        const hp::MappingCollection<3> *mapping)
      : edge_length(shortest_edge(dof_handler, parameters.slave_boundary_id))
      , complementarity_constant(parameters.complementarity_constant > 0 ?
                                   parameters.complementarity_constant :
                                   largest_youngs_modulus / edge_length)
      , small_strain_model(geometrically_linear)
      , geometrically_linear(geometrically_linear)
      , face_contact(dof_handler,
                     parameters.slave_boundary_id,
                     parameters.master_boundary_id,
                     complementarity_constant,
                     geometrically_linear,
                     face_scheme(scheme),
                     scheme.n_points,
                     mapping)
  {
    if (parameters.frictional())
      throw std::runtime_error("friction is 2D only: a 3D contact pair is "
                               "frictionless (set Friction coefficient = 0)");
    multiplier_nodes =
      std::make_unique<MultiplierNodes>(face_contact.multiplier_nodes());
    states = std::make_unique<ActiveSet>(*multiplier_nodes,
                                         complementarity_constant,
                                         0.,
                                         edge_length);
  }


  // @sect4{An iterate}
  unsigned int
  ContactInterface<3>::update(const Vector<double> &solution, const Pairing)
  {
    face_contact.pair(solution);
    measure_stretches(solution);
    return states->choose_closed_nodes(solution,
                                       face_contact.weighted_gaps(),
                                       face_contact.covered(),
                                       piecewise_linear());
  }

  void
  ContactInterface<3>::linearise(const bool on)
  {
    geometrically_linear = small_strain_model || on;
    face_contact.set_geometrically_linear(geometrically_linear);
  }

  std::vector<bool>
  ContactInterface<3>::closed_nodes() const
  {
    std::vector<bool> closed(multiplier_nodes->size());
    for (unsigned int k = 0; k < closed.size(); ++k)
      closed[k] = states->is_closed(k);
    return closed;
  }


  // @sect4{The Newton system}
  //
  // The pattern holds the candidates of the last update(); it covers the
  // pairing while every pair that makes rows is among them.
  bool
  ContactInterface<3>::sparsity_covers_pairing() const
  {
    return std::all_of(face_contact.pairs().begin(),
                       face_contact.pairs().end(),
                       [&](const auto &pair) {
                         return pattern_pairs.count(pair) > 0;
                       });
  }

  std::vector<std::vector<types::global_dof_index>>
  ContactInterface<3>::coupling_blocks()
  {
    pattern_pairs.clear();
    pattern_pairs.insert(face_contact.candidates().begin(),
                         face_contact.candidates().end());
    return face_contact.coupling_blocks();
  }

  // The pairs' rows, shared among the processes by FaceContact; the open
  // nodes' rows w_k lambda_k = 0 by the process that stores the row (a
  // force scale, as in 2D).
  void
  ContactInterface<3>::assemble(const Vector<double>            &solution,
                                const AffineConstraints<double> &constraints,
                                LinearSystem                    &system) const
  {
    const std::vector<bool> closed = closed_nodes();
    face_contact.assemble(
      solution,
      closed,
      true,
      this_process(system.get_communicator()),
      n_processes(system.get_communicator()),
      [&](const FullMatrix<double>                   &matrix,
          const Vector<double>                       &rhs,
          const std::vector<types::global_dof_index> &dofs) {
        system.add(constraints, matrix, rhs, dofs);
      });
    const auto &nodes = *multiplier_nodes;
    for (unsigned int k = 0; k < nodes.size(); ++k)
      if (!closed[k] && system.owned_rows().is_element(nodes.dofs[k]))
        system.add_diagonal(nodes.dofs[k],
                            nodes.reference_weight[k],
                            -nodes.reference_weight[k] *
                              solution(nodes.dofs[k]));
  }

  // The contact forces with the sign of an internal force: the residual's
  // values, every pair on every process.
  void
  ContactInterface<3>::add_forces(const Vector<double> &solution,
                                  Vector<double>       &forces) const
  {
    face_contact.assemble(
      solution,
      closed_nodes(),
      false,
      0,
      1,
      [&](const FullMatrix<double> &,
          const Vector<double>                       &rhs,
          const std::vector<types::global_dof_index> &dofs) {
        for (unsigned int i = 0; i < dofs.size(); ++i)
          forces(dofs[i]) -= rhs(i);
      });
  }


  // @sect4{What the postprocessing asks}
  types::global_dof_index
  ContactInterface<3>::multiplier_dof_nearest_to(const Point<3> &point,
                                                 double         *distance) const
  {
    const auto  &positions = multiplier_nodes->surface_position;
    unsigned int nearest   = 0;
    for (unsigned int k = 1; k < positions.size(); ++k)
      if (positions[k].distance(point) < positions[nearest].distance(point))
        nearest = k;
    if (distance != nullptr)
      *distance = positions[nearest].distance(point);
    return multiplier_nodes->dofs[nearest];
  }

  // The area element |a1 x a2| at a face's vertex, current over reference,
  // averaged over the faces around the node.
  double
  ContactInterface<3>::stretch_at(
    const types::global_dof_index multiplier_dof) const
  {
    const unsigned int k = multiplier_nodes->index.at(multiplier_dof);
    return k < stretches.size() ? stretches[k] : 1.;
  }

  // Per node, the mean over the faces at it of the ratio of the current to
  // the reference area spanned by the face's two edges from the node (the
  // lexicographic order: v ^ 1 along xi_1, v ^ 2 along xi_2): one pass over
  // the faces, at each update.
  void
  ContactInterface<3>::measure_stretches(const Vector<double> &solution)
  {
    std::vector<double>       sum(face_contact.n_nodes(), 0.);
    std::vector<unsigned int> faces(face_contact.n_nodes(), 0);
    for (const auto &face : face_contact.slave_faces())
      for (unsigned int v = 0; v < 4; ++v)
        {
          const auto area = [&](const bool moved) {
            Tensor<1, 3> a1, a2;
            for (unsigned int d = 0; d < 3; ++d)
              {
                const auto x = [&](const unsigned int w) {
                  return face.reference[w][d] +
                         (moved ? solution(face.u_dofs[w][d]) : 0.);
                };
                a1[d] = x(v ^ 1) - x(v);
                a2[d] = x(v ^ 2) - x(v);
              }
            return cross_product_3d(a1, a2).norm();
          };
          sum[face.node[v]] += area(true) / area(false);
          ++faces[face.node[v]];
        }
    stretches.resize(sum.size());
    for (unsigned int k = 0; k < sum.size(); ++k)
      stretches[k] = faces[k] > 0 ? sum[k] / faces[k] : 1.;
  }

  // Over each slave face with the 3 x 3 Gauss rule, at the reference and
  // the current positions of its nodes.
  double
  ContactInterface<3>::l2_relative_error(const Vector<double> &solution,
                                         const double          reference,
                                         const PressureMeasure measure) const
  {
    const QGauss<2> rule(3);
    const FE_Q<2>   bilinear(1);
    double          error = 0, norm = 0;
    for (const auto &face : face_contact.slave_faces())
      for (unsigned int q = 0; q < rule.size(); ++q)
        {
          // The area elements |a1 x a2| of the reference and current face.
          Tensor<1, 3> a1, a2, A1, A2;
          double       lambda = 0;
          for (unsigned int v = 0; v < 4; ++v)
            {
              const auto dN = bilinear.shape_grad(v, rule.point(q));
              lambda += bilinear.shape_value(v, rule.point(q)) *
                        solution(face_contact.multiplier_dof(face.node[v]));
              for (unsigned int d = 0; d < 3; ++d)
                {
                  const double X = face.reference[v][d];
                  const double x = X + solution(face.u_dofs[v][d]);
                  A1[d] += dN[0] * X;
                  A2[d] += dN[1] * X;
                  a1[d] += dN[0] * x;
                  a2[d] += dN[1] * x;
                }
            }
          const double dA0 = cross_product_3d(A1, A2).norm() * rule.weight(q);
          const double dA  = cross_product_3d(a1, a2).norm() * rule.weight(q);
          const bool   cauchy = measure == PressureMeasure::cauchy;
          const double p      = cauchy ? lambda : lambda * dA / dA0;
          const double area   = cauchy ? dA : dA0;
          error += (p - reference) * (p - reference) * area;
          norm += reference * reference * area;
        }
    return std::sqrt(error) / std::sqrt(norm);
  }

  std::vector<ContactInterface<3>::SlaveFace>
  ContactInterface<3>::slave_faces() const
  {
    std::vector<SlaveFace> faces;
    for (const auto &face : face_contact.slave_faces())
      {
        SlaveFace f;
        for (unsigned int v = 0; v < 4; ++v)
          {
            f.multipliers[v] = face_contact.multiplier_dof(face.node[v]);
            for (unsigned int d = 0; d < 3; ++d)
              f.X[v][d] = face.reference[v][d];
          }
        faces.push_back(f);
      }
    return faces;
  }

  double
  ContactInterface<3>::gap_at(
    const types::global_dof_index multiplier_dof) const
  {
    const unsigned int k = multiplier_nodes->index.at(multiplier_dof);
    const double       w = multiplier_nodes->reference_weight[k];
    return w > 0 ? face_contact.weighted_gaps()[k] / w : 0.;
  }

  std::pair<double, Point<3>>
  ContactInterface<3>::deepest_interpenetration() const
  {
    std::pair<double, Point<3>> deepest{0., Point<3>()};
    const auto                  mean_gaps = states->mean_gaps();
    for (unsigned int k = 0; k < mean_gaps.size(); ++k)
      if (face_contact.covered()[k] && -mean_gaps[k] > deepest.first)
        deepest = {-mean_gaps[k], node_position(k)};
    return deepest;
  }
} // namespace RingContact
