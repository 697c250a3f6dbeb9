// @sect3{Diagnostics: the rigid motions that only the contact holds}
//
// What is checked and said is in rigid_body_modes.h; here is how. A body's
// rigid motions are u = a + w e_z x (X - X_c): two translations and a rotation,
// three numbers (in 3D u = a + w x (X - X_c), three translations and three
// rotations, six). A support fixes one direction e at one point X, the
// linear condition e . u(X) = 0 on them: one row of a matrix M with three
// columns per body, whose null space is the motions that no support
// fixes. A frictionless contact adds, at each slave point, the normal
// relative motion of the two bodies, n . (u_slave - u_master) = 0; what
// is still free then is held by nothing, and the tangent is singular along
// it.
//
// The check exists because the solver does not always say so: a block free
// to slide along a flat interface "converged" to an arbitrary sideways
// position with exit code 0, and two blocks loaded by balanced tractions
// to an arbitrary common translation (both found by probing). It runs once,
// before the first step, in the reference configuration.
//
// The rotation's column is w times the body's size, a length like the
// translations: the columns are then comparable, and one relative
// threshold (1e-10 of the largest eigenvalue or singular value) tells a
// null motion from a held one for bodies of any size.
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/lapack_full_matrix.h>

#include <ring_contact/base/components.h>
#include <ring_contact/diagnostics/rigid_body_modes.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>

namespace RingContact
{
  namespace Diagnostics
  {
    namespace
    {
      /// The number of rigid modes of a body: 3 in 2D, 6 in 3D.
      template <int dim>
      constexpr unsigned int n_modes = dim == 2 ? 3 : 6;

      /// The row of the direction e at r = X - X_c in a body's rigid modes:
      /// e . u(X) = e . a + w . (r x e), so e, then r x e over the body's
      /// size (the rotation's column a length like the translations'); in
      /// 2D w = w e_z and r x e its z component, -e_x r_y + e_y r_x.
      template <int dim>
      std::array<double, n_modes<dim>>
      mode_row(const Tensor<1, dim> &e,
               const Tensor<1, dim> &r,
               const double          size)
      {
        if constexpr (dim == 2)
          return {{e[0], e[1], (-e[0] * r[1] + e[1] * r[0]) / size}};
        else
          {
            const Tensor<1, 3> t = cross_product_3d(r, e) / size;
            return {{e[0], e[1], e[2], t[0], t[1], t[2]}};
          }
      }

      /// A 3D mode in words: a translation, or a rotation about an axis
      /// (the point of the axis nearest to the body's centre, P = X_c +
      /// w x a / |w|^2), its sign chosen so that the first component of
      /// the direction named that is not zero is positive.
      std::string
      describe_mode_3d(const Tensor<1, 6> &mode,
                       const Point<3>     &centre,
                       const double        size)
      {
        Tensor<1, 3> a, w;
        for (unsigned int d = 0; d < 3; ++d)
          {
            a[d] = mode[d];
            w[d] = mode[3 + d] / size;
          }
        const bool          rotation  = w.norm() * size >= 1e-6;
        const Tensor<1, 3> &direction = rotation ? w : a;
        double              sign      = 1;
        for (unsigned int d = 0; d < 3; ++d)
          if (std::abs(direction[d]) > 1e-12)
            {
              sign = direction[d] < 0 ? -1 : 1;
              break;
            }
        const auto shown = [&](const Tensor<1, 3> &v, const double scale) {
          std::ostringstream text;
          text << std::setprecision(3) << "(";
          for (unsigned int d = 0; d < 3; ++d)
            text << (d > 0 ? ", " : "")
                 << (std::abs(v[d]) < 1e-12 ? 0.0 : scale * v[d]);
          return text.str() + ")";
        };
        if (!rotation)
          return "the translation along " + shown(a / a.norm(), sign);
        const Point<3> P = centre + cross_product_3d(w, a) / w.norm_square();
        return "a rotation about the axis along " + shown(w / w.norm(), sign) +
               " through " + shown(Tensor<1, 3>(P), 1);
      }

      // A mode (translation x, y, rotation scaled by the size) in words.
      // An eigenvector's sign is arbitrary: the translation is turned to
      // point along +x (or +y when it has no x part), so that the message
      // does not depend on LAPACK's choice. A mode with a rotation is
      // named by its centre P, where u vanishes: from a = w e_z x (X_c - P)
      // and w = mode[2] / size, P = X_c + (-a_y, a_x) / w.
      std::string
      describe_mode(const Tensor<1, 3> &mode,
                    const Point<2>     &centre,
                    const double        size)
      {
        std::ostringstream what;
        what << std::setprecision(3);
        const double sign =
          mode[0] < -1e-12 || (mode[0] <= 1e-12 && mode[1] < 0) ? -1 : 1;
        if (std::abs(mode[2]) < 1e-6)
          {
            // Whole numbers for the axes, no "-0".
            const auto shown = [&](const double v) {
              return std::abs(v) < 1e-12 ? 0.0 : sign * v;
            };
            what << "the translation along (" << shown(mode[0]) << ", "
                 << shown(mode[1]) << ")";
          }
        else
          what << "a rotation about (" << centre[0] - mode[1] * size / mode[2]
               << ", " << centre[1] + mode[0] * size / mode[2] << ")";
        return what.str();
      }

      // A body's centre and size (the rotation's scale) and the matrix of
      // its supports' constraints on its rigid modes.
      template <int dim>
      struct Frame
      {
        Point<dim>                       centre;
        double                           size;
        SymmetricTensor<2, n_modes<dim>> G;
      };

      /// The eigenvalues of G, from the largest, with their eigenvectors:
      /// deal.II's for 3 x 3 (2D), LAPACK's singular value decomposition
      /// of the symmetric positive semi-definite 6 x 6 (3D).
      template <int dim>
      std::vector<std::pair<double, Tensor<1, n_modes<dim>>>>
      mode_eigenpairs(const SymmetricTensor<2, n_modes<dim>> &G)
      {
        if constexpr (dim == 2)
          {
            const auto pairs = eigenvectors(G);
            return {pairs.begin(), pairs.end()};
          }
        else
          {
            constexpr unsigned int   n = n_modes<dim>;
            LAPACKFullMatrix<double> M(n, n);
            for (unsigned int i = 0; i < n; ++i)
              for (unsigned int j = 0; j < n; ++j)
                M(i, j) = G[i][j];
            M.compute_svd();
            std::vector<std::pair<double, Tensor<1, n>>> pairs(n);
            for (unsigned int m = 0; m < n; ++m)
              {
                pairs[m].first = M.singular_value(m);
                for (unsigned int i = 0; i < n; ++i)
                  pairs[m].second[i] = M.get_svd_vt()(m, i);
              }
            return pairs;
          }
      }

      /// A mode of a body in words, in either dimension.
      template <int dim>
      std::string
      describe(const Tensor<1, n_modes<dim>> &mode,
               const Point<dim>              &centre,
               const double                   size)
      {
        if constexpr (dim == 2)
          return describe_mode(mode, centre, size);
        else
          return describe_mode_3d(mode, centre, size);
      }

      // Per body, G = M^T M, M the rigid modes (translation x, y, rotation
      // scaled by the body's size) along the directions its supports hold:
      // its null space is the free motions, each noted in `log`. The bodies
      // some motion leaves free go into `held_by_contact`.
      template <int dim>
      std::map<types::material_id, Frame<dim>>
      body_frames(const DoFHandler<dim>            &dof_handler,
                  const hp::MappingCollection<dim> &mapping_collection,
                  const std::vector<Body<dim>>     &bodies,
                  const std::vector<types::global_dof_index> &imposed_dofs,
                  const std::vector<NormalDisplacement<dim>> &normal_target,
                  const std::vector<unsigned int>            &normal_component,
                  std::set<types::material_id>               &held_by_contact,
                  std::ostream                               &log)
      {
        // The reference position of each displacement unknown: where its
        // support acts.
        std::map<types::material_id, Frame<dim>>      frames;
        std::map<types::global_dof_index, Point<dim>> support_points;
        const ComponentMask u = Components::displacement_mask<dim>();
        DoFTools::map_dofs_to_support_points(mapping_collection,
                                             dof_handler,
                                             support_points,
                                             u);
        // The unknowns imposed whole, and the nodes (their u_x) of the normal
        // conditions. A normal condition's constrained unknown is in
        // `imposed_dofs` too (constraints.cc), but it fixes N . u only, not
        // its component: it leaves the imposed set, and the node gets one
        // row along N, keyed by its u_x so that the node's two unknowns do
        // not give it twice.
        std::set<types::global_dof_index> imposed(imposed_dofs.begin(),
                                                  imposed_dofs.end());
        std::map<types::global_dof_index, Tensor<1, dim>> normal_at;
        for (unsigned int k = 0; k < normal_target.size(); ++k)
          {
            imposed.erase(normal_target[k].dofs[normal_component[k]]);
            normal_at[normal_target[k].dofs[0]] = normal_target[k].normal;
          }
        for (const Body<dim> &body : bodies)
          {
            // The body's extent and centre, to scale the rotation.
            Point<dim>                                         lower, upper;
            bool                                               first = true;
            std::vector<std::pair<Point<dim>, Tensor<1, dim>>> fixed;
            std::vector<types::global_dof_index>               dofs;
            // One pass over the body's cells: its bounding box from the
            // vertices (`first` stays true until all coordinates of the
            // first vertex are in), and its supported directions from the
            // unknowns. A vertex shared by cells gives the same row twice,
            // which only weighs it more in G and changes no null space.
            for (const auto &cell : dof_handler.active_cell_iterators())
              if (cell->material_id() == body.material_id)
                {
                  for (const unsigned int v : cell->vertex_indices())
                    for (unsigned int d = 0; d < dim; ++d)
                      {
                        const double x = cell->vertex(v)[d];
                        lower[d]       = first ? x : std::min(lower[d], x);
                        upper[d]       = first ? x : std::max(upper[d], x);
                        first          = first && d + 1 < dim;
                      }
                  dofs.resize(cell->get_fe().n_dofs_per_cell());
                  cell->get_dof_indices(dofs);
                  for (unsigned int i = 0; i < dofs.size(); ++i)
                    {
                      const unsigned int c =
                        cell->get_fe().system_to_component_index(i).first;
                      if (!Components::is_displacement<dim>(c))
                        continue;
                      // An imposed component c: e_c . u = 0 for the motion.
                      if (imposed.count(dofs[i]))
                        fixed.emplace_back(support_points.at(dofs[i]),
                                           Point<dim>::unit_vector(c));
                      // A normal condition: N . u = 0.
                      if (normal_at.count(dofs[i]))
                        fixed.emplace_back(support_points.at(dofs[i]),
                                           normal_at.at(dofs[i]));
                    }
                }
            // A body without cells in this mesh has nothing to check.
            if (first)
              continue;
            // The centre of the bounding box, about which the rotation is
            // measured: near the body, so that its column does not mix a
            // large translation into the rotation.
            const Point<dim> centre = 0.5 * (lower + upper);
            double           size   = upper[0] - lower[0];
            for (unsigned int d = 1; d < dim; ++d)
              size = std::max(size, upper[d] - lower[d]);
            // G = M^T M, M the rigid modes (translations, rotations scaled
            // by the body's size) along the imposed directions e: its null
            // space is the free motions (mode_row()).
            SymmetricTensor<2, n_modes<dim>> G;
            for (const auto &[X, e] : fixed)
              {
                const auto row = mode_row<dim>(e, X - centre, size);
                for (unsigned int i = 0; i < n_modes<dim>; ++i)
                  for (unsigned int j = i; j < n_modes<dim>; ++j)
                    G[i][j] += row[i] * row[j];
              }
            frames[body.material_id] = {centre, size, G};
            // G's eigenvalues come sorted from the largest. A body without
            // any support (no row: G = 0) has all its motions free, each
            // said.
            const auto   modes   = mode_eigenpairs<dim>(G);
            const double largest = std::max(modes[0].first, 1e-300);
            for (const auto &[value, mode] : modes)
              if (value <= 1e-10 * largest || fixed.empty())
                {
                  log << "Note: " << body.name << " (material "
                      << body.material_id << "): no imposed displacement fixes "
                      << describe<dim>(mode, centre, size)
                      << "; only the contact holds it there\n";
                  held_by_contact.insert(body.material_id);
                }
          }
        return frames;
      }

      // The rows of the contacts in H: at points of every slave segment,
      // the relative normal motion of the two bodies' rigid modes, which a
      // frictionless contact resists and nothing else.
      void
      add_contact_rows(const std::map<types::material_id, Frame<2>>   &frames,
                       std::map<types::material_id, unsigned int>     &column,
                       const std::vector<const ContactInterface<2> *> &contacts,
                       LAPACKFullMatrix<double>                       &H)
      {
        // n . u(x) of a body's rigid modes, as the row of a support above.
        const auto row_of = [&](const types::material_id id,
                                const Point<2>          &x,
                                const Tensor<1, 2>      &n) {
          const Frame<2> &frame = frames.at(id);
          return mode_row<2>(n, x - frame.centre, frame.size);
        };
        for (const auto &contact : contacts)
          {
            const ContactSurface &slave  = contact->slave_surface();
            const ContactSurface &master = contact->master_surface();
            // The ends and the midpoint of every slave segment. On a
            // straight segment n is constant and the row is affine along
            // it, so its ends give every point's row; the midpoint adds
            // the turn of the normal on a curved one. A cyclic sector's
            // rotated copies are left out: they repeat the original
            // segments' rows.
            for (unsigned int k = 0; k < slave.segments().size(); ++k)
              {
                const auto &segment = slave.segments()[k];
                if (segment.is_copy)
                  continue;
                for (const double t : {0.0, 0.5, 1.0})
                  {
                    const auto   p      = slave.reference_point(k, t);
                    const double length = p.dx.norm();
                    // The partner in the reference configuration says which
                    // body the point faces; a segment of zero length has no
                    // normal.
                    const auto partner = master.project(p.x).segment;
                    if (!(length > 0) || partner >= master.segments().size())
                      continue;
                    const auto s_id = segment.cell->material_id();
                    const auto m_id =
                      master.segments()[partner].cell->material_id();
                    if (s_id == m_id || !frames.count(s_id) ||
                        !frames.count(m_id))
                      continue;
                    // The slave's normal at the point; its sign does not
                    // matter, the row enters H squared. The row is the
                    // relative normal motion: the slave's modes minus the
                    // master's, both evaluated at the same point.
                    const Tensor<1, 2> n({p.dx[1] / length, -p.dx[0] / length});
                    std::vector<std::pair<unsigned int, double>> row;
                    const auto a = row_of(s_id, p.x, n);
                    const auto b = row_of(m_id, p.x, n);
                    for (unsigned int i = 0; i < 3; ++i)
                      {
                        row.emplace_back(column[s_id] + i, a[i]);
                        row.emplace_back(column[m_id] + i, -b[i]);
                      }
                    for (const auto &[i, v] : row)
                      for (const auto &[j, w] : row)
                        H(i, j) += v * w;
                  }
              }
          }
      }

      // The same in 3D: at the vertices and the centre of every slave
      // face (on a bilinear face the normal turns between them), the
      // relative normal motion of the slave face's body and of the body of
      // the master face nearest to the point, both in the reference
      // configuration.
      void
      add_contact_rows(const std::map<types::material_id, Frame<3>>   &frames,
                       std::map<types::material_id, unsigned int>     &column,
                       const std::vector<const ContactInterface<3> *> &contacts,
                       LAPACKFullMatrix<double>                       &H)
      {
        const auto point = [](const FaceContact::Face &face,
                              const unsigned int       v) {
          return Point<3>(face.reference[v][0],
                          face.reference[v][1],
                          face.reference[v][2]);
        };
        for (const auto &contact : contacts)
          {
            const auto           &faces = contact->faces();
            std::vector<Point<3>> centres;
            for (const auto &face : faces.master_faces())
              centres.push_back((point(face, 0) + point(face, 1) +
                                 point(face, 2) + point(face, 3)) /
                                4.);
            for (const auto &face : faces.slave_faces())
              for (const auto &[xi, eta] :
                   std::vector<std::pair<double, double>>{
                     {0, 0}, {1, 0}, {0, 1}, {1, 1}, {0.5, 0.5}})
                {
                  // The bilinear face (lexicographic vertices) and its
                  // tangents at (xi, eta).
                  const Point<3> x0 = point(face, 0), x1 = point(face, 1),
                                 x2 = point(face, 2), x3 = point(face, 3);
                  const Point<3> x =
                    Point<3>((1 - xi) * (1 - eta) * x0 + xi * (1 - eta) * x1 +
                             (1 - xi) * eta * x2 + xi * eta * x3);
                  const Tensor<1, 3> a1 =
                    (1 - eta) * (x1 - x0) + eta * (x3 - x2);
                  const Tensor<1, 3> a2 = (1 - xi) * (x2 - x0) + xi * (x3 - x1);
                  const Tensor<1, 3> normal = cross_product_3d(a1, a2);
                  if (!(normal.norm() > 0) || centres.empty())
                    continue;
                  unsigned int nearest = 0;
                  for (unsigned int m = 1; m < centres.size(); ++m)
                    if (x.distance(centres[m]) < x.distance(centres[nearest]))
                      nearest = m;
                  const auto s_id = face.body;
                  const auto m_id = faces.master_faces()[nearest].body;
                  if (s_id == m_id || !frames.count(s_id) ||
                      !frames.count(m_id))
                    continue;
                  const Tensor<1, 3> n = normal / normal.norm();
                  const auto         a = mode_row<3>(n,
                                             x - frames.at(s_id).centre,
                                             frames.at(s_id).size);
                  const auto         b = mode_row<3>(n,
                                             x - frames.at(m_id).centre,
                                             frames.at(m_id).size);
                  std::vector<std::pair<unsigned int, double>> row;
                  for (unsigned int i = 0; i < n_modes<3>; ++i)
                    {
                      row.emplace_back(column[s_id] + i, a[i]);
                      row.emplace_back(column[m_id] + i, -b[i]);
                    }
                  for (const auto &[i, v] : row)
                    for (const auto &[j, w] : row)
                      H(i, j) += v * w;
                }
          }
      }

      // A frictionless contact pushes along its normals only: a motion of
      // one body, or of several together, that changes no gap (a block
      // sliding along a flat interface, a disc turning in a ring, two blocks
      // held by the contact between them and both free along it) is held by
      // nothing, and the tangent is singular: its solution, if the solver
      // finds one, is arbitrary along that motion. The rigid modes of all
      // bodies, the supports' constraints of each, and per slave point the
      // normal relative motion n . (r_slave - r_master): their null space.
      template <int dim>
      void
      refuse_free_motions(
        const std::map<types::material_id, Frame<dim>>   &frames,
        const std::vector<Body<dim>>                     &bodies,
        const std::vector<const ContactInterface<dim> *> &contacts)
      {
        // The bodies' columns (3 or 6 each) side by side; H = M^T M of the
        // whole matrix M, starting from each body's supports (G,
        // block-diagonal).
        std::map<types::material_id, unsigned int> column;
        std::vector<types::material_id>            ids;
        for (const auto &[id, frame] : frames)
          {
            column[id] = n_modes<dim> * ids.size();
            ids.push_back(id);
          }
        constexpr unsigned int   n   = n_modes<dim>;
        const unsigned int       all = n * ids.size();
        LAPACKFullMatrix<double> H(all, all);
        for (const auto &[id, frame] : frames)
          for (unsigned int i = 0; i < n; ++i)
            for (unsigned int j = 0; j < n; ++j)
              H(column[id] + i, column[id] + j) += frame.G[i][j];
        add_contact_rows(frames, column, contacts, H);
        // H is symmetric and positive semi-definite: its singular values
        // are its eigenvalues, sorted from the largest, and the rows of V^T
        // of the null ones are the free motions, each body's part in its
        // three columns.
        H.compute_svd();
        const double largest = std::max(H.singular_value(0), 1e-300);
        const auto  &vt      = H.get_svd_vt();
        for (unsigned int m = 0; m < all; ++m)
          if (H.singular_value(m) <= 1e-10 * largest)
            {
              std::string  what, alone;
              unsigned int n_moving = 0;
              for (unsigned int b = 0; b < ids.size(); ++b)
                {
                  Tensor<1, n> mode;
                  for (unsigned int i = 0; i < n; ++i)
                    mode[i] = vt(m, n * b + i);
                  if (mode.norm() < 1e-6)
                    continue;
                  const auto body =
                    std::find_if(bodies.begin(),
                                 bodies.end(),
                                 [&](const Body<dim> &x) {
                                   return x.material_id == ids[b];
                                 });
                  const std::string motion =
                    describe<dim>(mode / mode.norm(),
                                  frames.at(ids[b]).centre,
                                  frames.at(ids[b]).size);
                  what +=
                    (what.empty() ? "" : ", ") + body->name + " " + motion;
                  alone = body->name + " (material " +
                          std::to_string(body->material_id) +
                          "): nothing holds " + motion;
                  ++n_moving;
                }
              // A motion of one body keeps the message that names that
              // body alone; a motion of several names each one's part.
              if (n_moving == 1)
                throw std::runtime_error(
                  alone +
                  ": no imposed displacement fixes it, and the frictionless "
                  "contact, which pushes along its normals only, does not "
                  "resist "
                  "it either; the problem has no unique solution (impose a "
                  "displacement on a boundary of the body that fixes this "
                  "motion)");
              throw std::runtime_error(
                "nothing holds the bodies' common motion (" + what +
                "): it changes no gap and no support fixes it, so the "
                "problem has no unique solution (impose a displacement that "
                "fixes it on one of these bodies)");
            }
      }
    } // namespace

    template <int dim>
    std::set<types::material_id>
    rigid_body_modes(const DoFHandler<dim>                      &dof_handler,
                     const hp::MappingCollection<dim>           &mapping,
                     const std::vector<Body<dim>>               &bodies,
                     const std::vector<types::global_dof_index> &imposed_dofs,
                     const std::vector<NormalDisplacement<dim>> &normal,
                     const std::vector<unsigned int> &normal_component,
                     const std::vector<const ContactInterface<dim> *> &contacts,
                     const bool                                        friction,
                     std::ostream                                     &log)
    {
      std::set<types::material_id> held_by_contact;
      const auto                   frames = body_frames<dim>(dof_handler,
                                           mapping,
                                           bodies,
                                           imposed_dofs,
                                           normal,
                                           normal_component,
                                           held_by_contact,
                                           log);
      // With friction, sticking may hold a motion the normals do not. The
      // whole analysis is needed only when some body is held by the
      // contact alone: otherwise the supports fix every body on their own.
      if (!held_by_contact.empty() && !friction && frames.size() >= 2)
        refuse_free_motions(frames, bodies, contacts);
      return held_by_contact;
    }

    template std::set<types::material_id>
    rigid_body_modes(const DoFHandler<2> &,
                     const hp::MappingCollection<2> &,
                     const std::vector<Body<2>> &,
                     const std::vector<types::global_dof_index> &,
                     const std::vector<NormalDisplacement<2>> &,
                     const std::vector<unsigned int> &,
                     const std::vector<const ContactInterface<2> *> &,
                     const bool,
                     std::ostream &);
    template std::set<types::material_id>
    rigid_body_modes(const DoFHandler<3> &,
                     const hp::MappingCollection<3> &,
                     const std::vector<Body<3>> &,
                     const std::vector<types::global_dof_index> &,
                     const std::vector<NormalDisplacement<3>> &,
                     const std::vector<unsigned int> &,
                     const std::vector<const ContactInterface<3> *> &,
                     const bool,
                     std::ostream &);
  } // namespace Diagnostics
} // namespace RingContact
