// gmsh's library run in a child process. gmsh 4.8's readers are not safe
// on damaged files (some end the process with a segmentation fault or an
// abort), and its API changes the state of the process that calls it
// (gmsh::initialize sets the locale and lifts the stack limit; a failed
// read leaves gmsh "busy" until gmsh::finalize). So the program never
// calls gmsh itself: a forked child opens the file (and meshes a script),
// and sends the model back through a pipe. A crash, an exit() or a hang of
// gmsh ends the child, and the program reports it in one line.
#ifndef ring_contact_input_gmsh_process_h
#define ring_contact_input_gmsh_process_h

#include <ring_contact/input/gmsh_file.h>

#include <cstddef>
#include <string>
#include <vector>

namespace RingContact
{
  namespace Geometry
  {
    /// What gmsh's library holds after reading a file: every node, and per
    /// entity its physical groups and its elements, grouped by type, as
    /// gmsh::model::mesh::getElements() gives them.
    struct GmshModel
    {
      std::vector<std::size_t> node_tags;
      std::vector<double>      coordinates; ///< x, y, z per node

      struct Entity
      {
        int                                   dim;
        int                                   tag;
        std::vector<int>                      physicals;
        std::vector<int>                      types;
        std::vector<std::vector<std::size_t>> element_tags;
        std::vector<std::vector<std::size_t>> element_nodes;
      };
      std::vector<Entity> entities;
      /// A script's curves (dimension-1 entities) by tag, each as points
      /// x, y, z evenly spaced in the CAD kernel's parameter, ends
      /// included; none for a mesh file.
      std::vector<std::pair<int, std::vector<double>>> curves;
      /// A 3D script's surfaces (dimension-2 entities) by tag, each as
      /// points x, y, z on a grid evenly spaced in the CAD kernel's two
      /// parameters, followed by the unit normals there; none otherwise.
      std::vector<std::pair<int, std::vector<double>>> surfaces;
    };

    /// Open `filename` with gmsh's library in a child process; if
    /// `mesh_script`, mesh it in its dimension, 2 or 3
    /// (gmsh::model::mesh::generate) with
    /// elements of order `element_order`, the `geo_numbers` given as
    /// gmsh's `-setnumber`, and scale the nodes and curves by the script's
    /// Mesh.ScalingFactor. The child is killed after `time_limit_seconds`
    /// (0: no limit). Throws a one-line std::runtime_error that names the
    /// file when gmsh refuses the file (with gmsh's message), crashes,
    /// stops or takes too long.
    GmshModel
    run_gmsh(const std::string &filename,
             bool               mesh_script,
             const GeoNumbers  &geo_numbers,
             unsigned int       element_order,
             double             time_limit_seconds);
  } // namespace Geometry
} // namespace RingContact

#endif
