// The results for ParaView: VTU files of the bodies (displacement, Cauchy
// and von Mises stress, the body of each cell, the contact pressure) and of
// the slave surfaces (contact pressure and gap), and the PVD records that
// list them step by step.
#ifndef ring_contact_output_vtu_writer_h
#define ring_contact_output_vtu_writer_h

#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/hp/mapping_collection.h>
#include <deal.II/lac/vector.h>

#include <ring_contact/materials/material.h>
#include <ring_contact/output/vtu_format.h>

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace RingContact
{
  using namespace dealii;

  /// VTU of the rings (displacement, Cauchy stress, ring id, contact
  /// pressure) and of the slave surface (contact pressure and gap), and the
  /// PVD records that list them. The fields are evaluated in double, and
  /// an array is written in double precision where one of its values would
  /// be lost in single (vtu_format.h). Every file is written under a
  /// temporary name and renamed, the VTU files first, then the PVD file
  /// that lists them: a PVD on disk lists only whole VTU files. In 3D the
  /// cells are hexahedra (each subdivided into `subdivisions`^3 of them)
  /// and the slave surface's faces quadrilaterals.
  template <int dim>
  class VtuWriter
  {
  public:
    /// With several processes in `communicator`, write() is collective:
    /// each process writes the cells of its subdomain as a piece
    /// (solution-<tag>-<step>.<process>.vtu), process 0 the .pvtu that
    /// lists them, the slave surface and the .pvd files; a file that one
    /// process cannot write is an error of all.
    VtuWriter(const std::string &directory,
              const std::string &tag,
              const unsigned int subdivisions,
              const MPI_Comm     communicator = MPI_COMM_SELF);

    /// A scalar of the slave surface's nodes, by name, stored in the
    /// multiplier component of a vector of the dofs (the gap, the arc
    /// length). `closing_values`, if not empty, are its values on the faces
    /// that close a chain on itself: the arc length there runs to the
    /// chain's length, where `values` hold the start's 0.
    struct SurfaceField
    {
      std::string    name;
      Vector<double> values;
      Vector<double> closing_values = {};
    };

    /// A face of a slave surface, in the order the file lists them (chain
    /// after chain, along each: ContactProblem::output_results()): whether
    /// it is walked from its second vertex to its first, whether it starts
    /// a chain, and whether it closes one on itself (2D: a 3D surface's
    /// faces are written each as its own quadrilaterals).
    struct SlaveFace
    {
      typename DoFHandler<dim>::active_cell_iterator cell;
      unsigned int                                   face_no      = 0;
      bool                                           reversed     = false;
      bool                                           starts_chain = true;
      bool                                           closes_chain = false;
    };

    void
    write(const DoFHandler<dim>                       &dof_handler,
          const hp::MappingCollection<dim>            &mapping,
          const Vector<double>                        &solution,
          const std::vector<SurfaceField>             &surface_fields,
          const std::map<unsigned int, Material<dim>> &materials,
          const std::vector<SlaveFace>                &slave_faces,
          const unsigned int                           step,
          const double                                 time);

  private:
    /// The bodies' .vtu file, or this process's piece of it; the name the
    /// .pvd lists.
    std::string
    write_bulk(const VtuGrid     &bulk,
               const std::string &bulk_stem,
               const double       time);
    void
    write_slave_surface(const DoFHandler<dim>            &dof_handler,
                        const hp::MappingCollection<dim> &mapping,
                        const Vector<double>             &solution,
                        const std::vector<SurfaceField>  &surface_fields,
                        const std::vector<SlaveFace>     &slave_faces,
                        const unsigned int                step,
                        const double                      time);
    static void
    record(std::vector<std::pair<double, std::string>> &records,
           const double                                 time,
           const std::string                           &name);
    static std::string
    pvd_contents(const std::vector<std::pair<double, std::string>> &records);

    const std::string                           directory;
    const std::string                           tag;
    const unsigned int                          subdivisions;
    const MPI_Comm                              communicator;
    std::vector<std::pair<double, std::string>> bulk_records;
    std::vector<std::pair<double, std::string>> surface_records;
  };
} // namespace RingContact

#endif
