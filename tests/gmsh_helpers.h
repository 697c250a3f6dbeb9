// What the gmsh tests share: a model written again by gmsh itself (a mesh
// file converted, or a script meshed), and a triangulation as data that
// two readings of one mesh can be compared by.
#ifndef ring_contact_tests_gmsh_helpers_h
#define ring_contact_tests_gmsh_helpers_h

#include <deal.II/base/point.h>
#include <deal.II/grid/tria.h>

#include <gmsh.h>

#include <string>
#include <vector>

namespace RingContactTests
{
  /// Open `from` with gmsh (a mesh file, or a script, meshed in 3D to
  /// `order` when `order` > 0) and write it to `to` as a .msh of format
  /// `version`, ASCII or binary.
  inline void
  write_with_gmsh(const std::string &from,
                  const std::string &to,
                  const double       version,
                  const bool         binary,
                  const int          order = 0)
  {
    gmsh::initialize(0, nullptr, false);
    gmsh::option::setNumber("General.Terminal", 0);
    gmsh::open(from);
    if (order > 0)
      {
        gmsh::model::mesh::generate(3);
        gmsh::model::mesh::setOrder(order);
      }
    gmsh::option::setNumber("Mesh.MshFileVersion", version);
    gmsh::option::setNumber("Mesh.Binary", binary ? 1 : 0);
    gmsh::write(to);
    gmsh::finalize();
  }

  /// A triangulation as comparable data: per cell its vertices, and its
  /// material id followed by the boundary ids of its faces (9999 inside).
  template <int dim>
  struct Cells
  {
    std::vector<dealii::Point<dim>> vertices;
    std::vector<unsigned int>       ids;
  };

  template <int dim>
  Cells<dim>
  cells_of(const dealii::Triangulation<dim> &triangulation)
  {
    Cells<dim> cells;
    for (const auto &cell : triangulation.active_cell_iterators())
      {
        for (const unsigned int v : cell->vertex_indices())
          cells.vertices.push_back(cell->vertex(v));
        cells.ids.push_back(cell->material_id());
        for (const auto &face : cell->face_iterators())
          cells.ids.push_back(face->at_boundary() ? face->boundary_id() : 9999);
      }
    return cells;
  }
} // namespace RingContactTests

#endif
