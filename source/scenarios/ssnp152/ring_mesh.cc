// @sect3{The rings' mesh}
//
// The rings' mesh: generated in code (the original's structured layout for any
// number of elements, or a sector of it for cyclic symmetry), and the checks of
// any mesh of the rings, generated or read. The scenario (ssnp152.cc) calls
// these before it puts every cell on the polar manifold and refines.
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria_description.h>

#include <ring_contact/base/dimension.h>
#include <ring_contact/scenarios/ssnp152/ssnp152.h>

#include <cmath>
#include <map>
#include <set>
#include <stdexcept>
#include <string>

namespace RingContact
{
  namespace Ssnp152
  {
    // @sect4{The rings generated in code}
    //
    // The original's structured layout for any number of elements
    // (doc/intro.md, "Geometry and mesh"): Ne cells around every circle with
    // the first vertex at angle 0, so that node A, (R2, 0), is a vertex, and
    // uniformly spaced radii, 3 cells across each ring in the seed mesh. Each
    // ring has its own vertices, those on r = R2 included: the two copies of
    // the interface coincide but belong to two bodies, and merging them would
    // glue the rings and leave no contact to compute. create_triangulation()
    // does not merge coincident vertices, so nothing more keeps them apart. The
    // vertices lie exactly on the circles; the polar manifold attached
    // afterwards puts the refined vertices, and with a mapping of degree 2 or
    // more the element edges, on them as well.
    void
    make_rings(Triangulation<dim> &triangulation, const RingParameters &rings)
    {
      // The whole rings, or (cyclic symmetry) a sector of `sector_elements`
      // columns from angle 0, whose two radial sides are boundaries.
      const unsigned int n_around  = rings.elements_around;
      const bool         sector    = rings.sector_elements > 0;
      const unsigned int n_columns = sector ? rings.sector_elements : n_around;
      const unsigned int n_vertices_around = sector ? n_columns + 1 : n_around;
      std::vector<Point<dim>>    vertices;
      std::vector<CellData<dim>> cells;

      // One ring between radii r_in and r_out with n_radial cells across.
      // Cell (i, j): angular index i, radial index j. The local x axis runs
      // radially and y along the circle, so that every cell has a positive
      // Jacobian.
      const auto add_ring = [&](const double       r_in,
                                const double       r_out,
                                const unsigned int n_radial,
                                const unsigned int material_id) {
        const unsigned int offset = vertices.size();
        for (unsigned int j = 0; j <= n_radial; ++j)
          for (unsigned int i = 0; i < n_vertices_around; ++i)
            {
              const double r   = r_in + (r_out - r_in) * j / n_radial;
              const double phi = 2 * numbers::PI * i / n_around;
              vertices.emplace_back(r * std::cos(phi), r * std::sin(phi));
            }
        // The modulo closes a whole ring: the last column of cells ends on the
        // vertices of column 0. A sector has one vertex column more than cells,
        // and its index never wraps.
        const auto v = [&](const unsigned int i, const unsigned int j) {
          return offset + j * n_vertices_around + (i % n_vertices_around);
        };
        for (unsigned int j = 0; j < n_radial; ++j)
          for (unsigned int i = 0; i < n_columns; ++i)
            {
              CellData<dim> cell;
              cell.vertices    = {v(i, j),
                                  v(i, j + 1),
                                  v(i + 1, j),
                                  v(i + 1, j + 1)};
              cell.material_id = material_id;
              cells.push_back(cell);
            }
      };
      add_ring(rings.interface_radius,
               rings.outer_radius,
               rings.radial_elements_outer,
               Ids::outer_ring);
      add_ring(rings.inner_radius,
               rings.interface_radius,
               rings.radial_elements_inner,
               Ids::inner_ring);

      triangulation.create_triangulation(vertices, cells, SubCellData());

      // Boundary ids from the circle a face lies on and the ring it bounds;
      // the radial sides of a sector from their angle and the side of the
      // cell (with k = Ne both sides lie on the ray at angle 0).
      // The other faces are told apart by their radius: r = R1 and r = R3 are
      // the loaded boundaries (200, 500), and a face on neither lies on r = R2
      // and is the contact surface of the ring it bounds, S1R2 (300) on the
      // outer ring, S2R2 (400) on the inner. 1e-8 R1 cannot confuse two
      // circles, since each ring is at least 1e-4 R1 thick
      // (RingParameters::finish()).
      const double         tol          = 1e-8 * rings.outer_radius;
      const double         sector_angle = rings.sector_angle();
      const Tensor<1, dim> end_normal(
        {-std::sin(sector_angle), std::cos(sector_angle)});
      for (const auto &cell : triangulation.active_cell_iterators())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary())
            {
              const bool       outer  = cell->material_id() == Ids::outer_ring;
              const Point<dim> center = face->center();
              if (sector && std::abs(center[1]) < tol && center[0] > 0 &&
                  cell->center()[1] > 0)
                face->set_boundary_id(Ids::sector_start);
              else if (sector && std::abs(center * end_normal) < tol &&
                       cell->center() * end_normal < 0)
                face->set_boundary_id(Ids::sector_end);
              else
                {
                  // The mean radius of the end points (the center of a
                  // straight face lies inside the circle).
                  const double r_face =
                    0.5 * (face->vertex(0).norm() + face->vertex(1).norm());
                  if (std::abs(r_face - rings.outer_radius) < tol)
                    face->set_boundary_id(Ids::outer_boundary);
                  else if (std::abs(r_face - rings.inner_radius) < tol)
                    face->set_boundary_id(Ids::inner_boundary);
                  else
                    face->set_boundary_id(outer ? Ids::outer_ring_contact :
                                                  Ids::inner_ring_contact);
                }
            }
    }

    // Each circle is covered once: its faces span the whole turn (the
    // sector angle for a sector), no gap, no overlap. Each face adds the
    // angle its chord subtends, |atan2(a x b, a . b)|: a missing face leaves
    // the sum short and a face listed twice makes it long, neither of which
    // the radius check sees.
    void
    check_circles_covered(const Triangulation<dim> &triangulation,
                          const Parameters         &parameters,
                          const std::string        &name)
    {
      const auto &rings = parameters.scenario_entries<RingParameters>();
      std::map<types::boundary_id, double> angle_covered;
      for (const auto &cell : triangulation.active_cell_iterators())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary())
            {
              const Point<dim> a = face->vertex(0), b = face->vertex(1);
              angle_covered[face->boundary_id()] +=
                std::abs(std::atan2(a[0] * b[1] - a[1] * b[0], a * b));
            }
      const double full_turn =
        rings.sector_elements > 0 ? rings.sector_angle() : 2 * numbers::PI;
      for (const auto id : {Ids::outer_boundary,
                            Ids::inner_boundary,
                            static_cast<types::boundary_id>(
                              parameters.contact.slave_boundary_id),
                            static_cast<types::boundary_id>(
                              parameters.contact.master_boundary_id)})
        if (angle_covered.count(id) != 0 &&
            std::abs(angle_covered[id] - full_turn) > 1e-6 * full_turn)
          throw std::runtime_error(
            name + ": boundary " + std::to_string(id) + " covers " +
            std::to_string(angle_covered[id] * 180 / numbers::PI) +
            " degrees of its circle instead of " +
            std::to_string(full_turn * 180 / numbers::PI) +
            " (a gap or an overlap)");
    }

    // @sect4{The checks of any mesh of the rings}
    //
    // A generated mesh is right by construction, but a mesh file is whatever
    // its author wrote, and a wrong one runs: a boundary without its tag keeps
    // its displacement free, an interface tagged on both rings makes a contact
    // surface of two bodies, a circle off its radius changes the problem the
    // closed form solves. Each would show as a wrong pressure at A with no hint
    // of the cause, so each is refused here with what is wrong and where.
    void
    check_rings(const Triangulation<dim> &triangulation,
                const Parameters         &parameters)
    {
      const auto       &rings = parameters.scenario_entries<RingParameters>();
      const std::string name = parameters.mesh.source == MeshSource::generated ?
                                 std::string("the generated mesh") :
                                 "mesh '" + parameters.mesh.mesh_file + "'";

      // The cells' material ids, the rings of each boundary id, and how far
      // each boundary's vertices lie from its circle: R1 and R3 for the loaded
      // boundaries, R2 for any other id (the contact surfaces; an id that is
      // none of the rings' boundaries is refused below anyway).
      std::set<types::material_id>                               materials;
      std::map<types::boundary_id, std::set<types::material_id>> rings_of;
      std::map<types::boundary_id, double> worst_radius_error;
      for (const auto &cell : triangulation.active_cell_iterators())
        {
          materials.insert(cell->material_id());
          for (const auto &face : cell->face_iterators())
            if (face->at_boundary())
              {
                const auto id = face->boundary_id();
                rings_of[id].insert(cell->material_id());
                double expected = rings.interface_radius;
                if (id == Ids::outer_boundary)
                  expected = rings.outer_radius;
                else if (id == Ids::inner_boundary)
                  expected = rings.inner_radius;
                for (unsigned int v = 0; v < 2; ++v)
                  worst_radius_error[id] =
                    std::max(worst_radius_error[id],
                             std::abs(face->vertex(v).norm() - expected));
              }
        }
      for (const unsigned int m : {Ids::outer_ring, Ids::inner_ring})
        if (materials.count(m) == 0)
          throw std::runtime_error(name + " has no cells with material id " +
                                   std::to_string(m) +
                                   " (100: outer ring, 101: inner ring)");

      // A boundary must exist, belong to one ring, and lie on its circle to
      // 1e-6 R1. A circle off its radius may be a mesh made for other
      // radii than those of subsection Mesh, which the message points to.
      const auto require_boundary = [&](const unsigned int id,
                                        const std::string &role) {
        if (rings_of.count(id) == 0)
          throw std::runtime_error(name + " has no boundary with id " +
                                   std::to_string(id) + " (the " + role + ")");
        if (rings_of.at(id).size() != 1)
          throw std::runtime_error(name + ": boundary " + std::to_string(id) +
                                   " (the " + role +
                                   ") touches both rings; it must belong to "
                                   "one");
        if (worst_radius_error.at(id) > 1e-6 * rings.outer_radius)
          throw std::runtime_error(
            name + ": boundary " + std::to_string(id) + " (the " + role +
            ") is not on its circle; its vertices are up to " +
            std::to_string(worst_radius_error.at(id)) +
            " m off (check the radii in subsection 'Mesh')");
      };
      check_circles_covered(triangulation, parameters, name);

      require_boundary(Ids::outer_boundary, "outer boundary r = R1");
      require_boundary(Ids::inner_boundary, "inner boundary r = R3");
      require_boundary(parameters.contact.slave_boundary_id, "slave surface");
      require_boundary(parameters.contact.master_boundary_id, "master surface");
      // Every boundary face belongs to one of the known boundaries.
      std::set<types::boundary_id> known = {
        Ids::outer_boundary,
        Ids::inner_boundary,
        static_cast<types::boundary_id>(parameters.contact.slave_boundary_id),
        static_cast<types::boundary_id>(parameters.contact.master_boundary_id)};
      if (rings.sector_elements > 0)
        known.insert({Ids::sector_start, Ids::sector_end});
      for (const auto &[id, rings] : rings_of)
        if (known.count(id) == 0)
          throw std::runtime_error(
            name + " has boundary faces with id " + std::to_string(id) +
            ", which is none of the ring boundaries (200, 500) nor the "
            "slave or master surface (a boundary line missing from a mesh "
            "file leaves id 0)");


      // Slave and master on one ring would be the contact of a body with
      // itself, which the program does not compute.
      if (*rings_of.at(parameters.contact.slave_boundary_id).begin() ==
          *rings_of.at(parameters.contact.master_boundary_id).begin())
        throw std::runtime_error(name +
                                 ": the slave and master surfaces belong to "
                                 "the same ring");
    }
  } // namespace Ssnp152
} // namespace RingContact
