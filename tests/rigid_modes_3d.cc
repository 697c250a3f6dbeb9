// The rigid-body audit in 3D (diagnostics/rigid_body_modes.h): each body's
// six rigid motions (three translations, three rotations) against its
// supports and the frictionless contact's normals.
//
// Two unit cubes, the lower one clamped on its bottom face, the upper one
// resting on it through a frictionless contact pair (the interface z = 1,
// normal along z): the contact holds the upper cube's translation along z
// and its rotations about x and y, nothing else. So:
// - held at the vertex (0, 0, 1) in x and y and at (1, 0, 1) in y: every
//   motion is held, three of them by the contact only (noted, not refused);
// - held at (0, 0, 1) in x and y only: the rotation about the vertical
//   axis through that vertex is free, refused with that axis named (the
//   axis's point nearest the cube's centre, (0, 0, 1.5));
// - held nowhere: three motions free, refused.
// And the lower cube clamped on its bottom alone is held whole: no note.
#include <deal.II/base/function.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_nothing.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/hp/fe_collection.h>
#include <deal.II/hp/mapping_collection.h>
#include <deal.II/numerics/vector_tools.h>

#include <ring_contact/contact/contact_interface.h>
#include <ring_contact/diagnostics/rigid_body_modes.h>

#include "tests.h"

#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

using namespace dealii;
using namespace RingContact;
using RingContactTests::check;

namespace
{
  // The cubes: the lower [0, 1]^3 (material 0) and the upper [0, 1]^2 x
  // [1, 2] (material 1), 2 x 2 x 2 and 3 x 3 x 2 cells; tags 1 the bottom,
  // 2 the lower cube's top (master), 3 the upper cube's bottom (slave).
  void
  make_cubes(Triangulation<3> &cubes)
  {
    Triangulation<3> lower, upper;
    GridGenerator::subdivided_hyper_rectangle(lower,
                                              {2, 2, 2},
                                              Point<3>(0, 0, 0),
                                              Point<3>(1, 1, 1));
    GridGenerator::subdivided_hyper_rectangle(upper,
                                              {3, 3, 2},
                                              Point<3>(0, 0, 1),
                                              Point<3>(1, 1, 2));
    for (const auto &cell : upper.active_cell_iterators())
      cell->set_material_id(1);
    GridGenerator::merge_triangulations(lower, upper, cubes);
    for (const auto &cell : cubes.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary())
          {
            const double z          = face->center()[2];
            const bool   upper_cube = cell->material_id() == 1;
            face->set_boundary_id(std::abs(z) < 1e-12 ? 1 :
                                  std::abs(z - 1) < 1e-12 ?
                                                        (upper_cube ? 3 : 2) :
                                                        0);
          }
  }

  // The audit with the upper cube held at the `held` (vertex, component)
  // pairs: its notes, or the error that refuses the problem.
  std::string
  audit(const std::vector<std::pair<Point<3>, unsigned int>> &held)
  {
    Triangulation<3> cubes;
    make_cubes(cubes);
    // The program's layout: u_x, u_y, u_z, the pressure (on the slave
    // body), the tangential traction (none without friction).
    hp::FECollection<3> fe;
    fe.push_back(
      FESystem<3>(FE_Q<3>(1), 3, FE_Nothing<3>(), 1, FE_Nothing<3>(), 1));
    fe.push_back(FESystem<3>(FE_Q<3>(1), 3, FE_Q<3>(1), 1, FE_Nothing<3>(), 1));
    DoFHandler<3> dofs(cubes);
    for (const auto &cell : dofs.active_cell_iterators())
      cell->set_active_fe_index(cell->material_id());
    dofs.distribute_dofs(fe);
    hp::MappingCollection<3> mapping;
    mapping.push_back(MappingQ<3>(1));
    mapping.push_back(MappingQ<3>(1));

    // The bottom clamped, and the upper cube's held vertices.
    std::map<types::global_dof_index, double> clamped;
    VectorTools::interpolate_boundary_values(
      mapping,
      dofs,
      1,
      Functions::ZeroFunction<3>(5),
      clamped,
      ComponentMask({true, true, true, false, false}));
    std::vector<types::global_dof_index> imposed;
    for (const auto &[dof, value] : clamped)
      imposed.push_back(dof);
    for (const auto &cell : dofs.active_cell_iterators())
      for (const unsigned int v : cell->vertex_indices())
        for (const auto &[x, c] : held)
          if (cell->material_id() == 1 && cell->vertex(v).distance(x) < 1e-12)
            imposed.push_back(
              cell->vertex_dof_index(v, c, cell->active_fe_index()));

    ContactParameters contact;
    contact.slave_boundary_id        = 3;
    contact.master_boundary_id       = 2;
    contact.smooth_master_normals    = false;
    contact.complementarity_constant = 0;
    contact.friction_coefficient     = 0;
    contact.reported_pressure        = PressureMeasure::cauchy;
    const ContactInterface<3> pair(
      dofs, contact, IntegrationScheme::parse("segment-based"), 1., true);
    const std::vector<Body<3>> bodies = {
      {0,
       "lower cube",
       1,
       1,
       Material<3>(
         1., 0.3, PlaneAssumption::plane_strain, "linear elasticity")},
      {1,
       "upper cube",
       1,
       1,
       Material<3>(
         1., 0.3, PlaneAssumption::plane_strain, "linear elasticity")}};
    std::ostringstream log;
    try
      {
        const auto held_by_contact = Diagnostics::rigid_body_modes(
          dofs, mapping, bodies, imposed, {}, {}, {&pair}, false, log);
        std::string        notes = log.str();
        const unsigned int n_notes =
          std::count(notes.begin(), notes.end(), '\n');
        return "accepted, " + std::to_string(n_notes) +
               " motions held by the contact only, bodies held by the "
               "contact: " +
               std::to_string(held_by_contact.size()) +
               (held_by_contact.count(1) ? " (the upper cube)" : "");
      }
    catch (const std::exception &e)
      {
        return std::string("refused: ") + e.what();
      }
  }
} // namespace


int
main()
{
  auto          &out = RingContactTests::deallog_file;
  const Point<3> origin(0, 0, 1), along_x(1, 0, 1);
  out << "held at two vertices: "
      << audit({{origin, 0}, {origin, 1}, {along_x, 1}}) << std::endl;
  const std::string one_vertex = audit({{origin, 0}, {origin, 1}});
  out << "held at one vertex: " << one_vertex << std::endl;
  check(one_vertex.find("a rotation about the axis along (0, 0, 1) through "
                        "(0, 0, 1.5)") != std::string::npos,
        "the free rotation is named with its axis");
  const std::string nowhere = audit({});
  check(nowhere.rfind("refused: ", 0) == 0,
        "a cube held by nothing but the contact is refused");
  out << "held nowhere: refused" << std::endl;
}
