// @sect3{The results for ParaView: VTU and PVD files}
//
// After each converged step (every `VTU interval` steps) and for the
// undeformed state, step 0, the problem class hands its state to a
// VtuWriter, one per integration scheme (its tag names the files:
// solution-gauss-3-0004.vtu). Two kinds of file: the bodies, with the
// displacement, the Cauchy stress tensor and the von Mises stress; and the
// slave surfaces, with the contact pressure, the tangential traction and
// the gap, where the multiplier lives. A .pvd file for each lists the
// steps with their pseudo-times, so that ParaView animates the run.
//
// Every file is written whole or not at all (output_folder.cc): a VTU
// under a temporary name, renamed when complete, and the PVD that lists it
// only afterwards, so that a PVD on disk never names a missing or partial
// VTU. Under MPI each process writes its own cells as a piece, and
// process 0 the rest.
#include <deal.II/base/data_out_base.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/data_out_faces.h>
#include <deal.II/numerics/data_postprocessor.h>

#include <ring_contact/base/components.h>
#include <ring_contact/base/utilities.h>
#include <ring_contact/linear_algebra/linear_system.h>
#include <ring_contact/output/output_folder.h>
#include <ring_contact/output/vtu_writer.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <memory>
#include <set>
#include <sstream>

namespace RingContact
{
  namespace
  {
    // @sect4{Postprocessors}
    //
    // The Cauchy stress as a tensor (ParaView computes its principal
    // values and directions) and the von Mises stress, with sigma_33 in
    // plane strain, from the displacement gradient and each body's own
    // material. The cell's material id selects the body, so that bodies of
    // different laws and constants are postprocessed in one pass.
    class StressPostprocessor : public DataPostprocessor<2>
    {
    public:
      explicit StressPostprocessor(
        const std::map<unsigned int, Material> &materials)
          : materials(materials)
      {}

      void
      evaluate_vector_field(
        const DataPostprocessorInputs::Vector<2> &inputs,
        std::vector<Vector<double>> &computed_quantities) const override
      {
        const auto      cell     = inputs.template get_cell<2>();
        const Material &material = materials.at(cell->material_id());
        for (unsigned int q = 0; q < inputs.solution_gradients.size(); ++q)
          {
            // The first two components of the solution are u_x and u_y:
            // their gradients are the rows of H = Grad u.
            Tensor<2, 2> H;
            for (unsigned int d = 0; d < 2; ++d)
              H[d] = inputs.solution_gradients[q][d];
            // A law checks its range at the quadrature points of the
            // assembly; at these points (the cell's vertices) a state near
            // the bound may lie past it (Saint Venant-Kirchhoff in plane
            // stress without a thickness): no stress exists there, written
            // as NaN (ParaView's missing value), not thrown mid-file.
            if (!material.in_range(H))
              {
                for (unsigned int c = 0; c < 5; ++c)
                  computed_quantities[q][c] =
                    std::numeric_limits<double>::quiet_NaN();
                continue;
              }
            const Tensor<2, 2> s = material.cauchy_stress(H);
            // Row by row (deal.II's unrolled order), the order in which
            // DataOut reads the components of a tensor field.
            for (unsigned int i = 0; i < 2; ++i)
              for (unsigned int j = 0; j < 2; ++j)
                computed_quantities[q]
                                   [Tensor<2, 2>::component_to_unrolled_index(
                                     TableIndices<2>(i, j))] = s[i][j];
            // After the tensor's four components, as get_names() lists them.
            computed_quantities[q][4] = material.von_mises_stress(H);
          }
      }

      // Four components with one name, marked part of a tensor: VTK then
      // writes one 3 x 3 tensor field (the 2d tensor padded with zeros),
      // not four scalars.
      std::vector<std::string>
      get_names() const override
      {
        return {"cauchy_stress",
                "cauchy_stress",
                "cauchy_stress",
                "cauchy_stress",
                "von_Mises_stress"};
      }

      std::vector<DataComponentInterpretation::DataComponentInterpretation>
      get_data_component_interpretation() const override
      {
        std::vector<DataComponentInterpretation::DataComponentInterpretation>
          interpretation(
            4, DataComponentInterpretation::component_is_part_of_tensor);
        interpretation.push_back(
          DataComponentInterpretation::component_is_scalar);
        return interpretation;
      }

      // The gradients alone: the laws have no internal state, so the stress
      // is a function of Grad u at the point.
      UpdateFlags
      get_needed_update_flags() const override
      {
        return update_gradients;
      }

    private:
      const std::map<unsigned int, Material> &materials;
    };

    // Only the faces of the slave surface. DataOutFaces, built with
    // surface_only = true, would write every boundary face; these two
    // overrides walk the same faces and keep those whose boundary id is a
    // slave surface's. The walk goes over all cells, active or not (a
    // FaceDescriptor holds a cell_iterator), and skips the inactive ones.
    class SlaveFaces : public DataOutFaces<2>
    {
    public:
      explicit SlaveFaces(const std::set<types::boundary_id> &ids)
          : DataOutFaces<2>(true)
          , slave_ids(ids)
      {}

      FaceDescriptor
      first_face() override
      {
        return next_slave_face({this->triangulation->begin_active(), 0}, true);
      }

      FaceDescriptor
      next_face(const FaceDescriptor &face) override
      {
        return next_slave_face(face, false);
      }

    private:
      // The first slave face at or after `face` (include_this), or
      // strictly after it: first_face() asks for the former from face 0
      // of the first cell, next_face() for the latter.
      FaceDescriptor
      next_slave_face(FaceDescriptor face, bool include_this)
      {
        auto         cell = face.first;
        unsigned int f    = face.second;
        if (!include_this)
          ++f;
        for (; cell != this->triangulation->end(); ++cell, f = 0)
          if (cell->is_active())
            for (; f < cell->n_faces(); ++f)
              if (cell->face(f)->at_boundary() &&
                  slave_ids.count(cell->face(f)->boundary_id()) > 0)
                return {cell, f};
        return {this->triangulation->end(), 0};
      }

      const std::set<types::boundary_id> slave_ids;
    };

    // The displacement alone (the multiplier component is written on the
    // slave surface only: in the bulk it would be a field that falls to zero
    // across the first layer of cells).
    class DisplacementPostprocessor : public DataPostprocessorVector<2>
    {
    public:
      DisplacementPostprocessor()
          : DataPostprocessorVector<2>("displacement", update_values)
      {}

      void
      evaluate_vector_field(
        const DataPostprocessorInputs::Vector<2> &inputs,
        std::vector<Vector<double>> &computed_quantities) const override
      {
        for (unsigned int q = 0; q < inputs.solution_values.size(); ++q)
          for (unsigned int d = 0; d < 2; ++d)
            computed_quantities[q][d] = inputs.solution_values[q][d];
      }
    };

    // A nodal field of the slave surface (the gap, the arc length), stored
    // in the multiplier component of a dof vector: it belongs to the
    // multiplier's nodes, so the DoFHandler's own numbering places it and
    // DataOutFaces interpolates it like the pressure.
    class SurfaceFieldPostprocessor : public DataPostprocessorScalar<2>
    {
    public:
      explicit SurfaceFieldPostprocessor(const std::string &name)
          : DataPostprocessorScalar<2>(name, update_values)
      {}

      void
      evaluate_vector_field(
        const DataPostprocessorInputs::Vector<2> &inputs,
        std::vector<Vector<double>> &computed_quantities) const override
      {
        for (unsigned int q = 0; q < inputs.solution_values.size(); ++q)
          computed_quantities[q][0] =
            inputs.solution_values[q][Components::multiplier];
      }
    };

    // u_x and u_y as one vector field, the contact pressure and the
    // tangential traction as scalars (the latter zero without friction).
    std::vector<DataComponentInterpretation::DataComponentInterpretation>
    solution_interpretation()
    {
      return {DataComponentInterpretation::component_is_part_of_vector,
              DataComponentInterpretation::component_is_part_of_vector,
              DataComponentInterpretation::component_is_scalar,
              DataComponentInterpretation::component_is_scalar};
    }
  } // namespace

  // The writer lives as long as its scheme's run and keeps the records of
  // all its steps: each step's .pvd is written anew with every step so
  // far.
  VtuWriter::VtuWriter(const std::string &directory,
                       const std::string &tag,
                       const unsigned int subdivisions,
                       const MPI_Comm     communicator)
      : directory(directory)
      , tag(tag)
      , subdivisions(subdivisions)
      , communicator(communicator)
  {}

  // @sect4{One step's files}
  //
  // The bodies first, each process its piece; then, on process 0, the
  // .pvtu that lists the pieces, the .pvd records and the slave surface.
  // Any process's failure is every process's: write() is collective, and
  // a process that threw alone would leave the others waiting.
  void
  VtuWriter::write(const DoFHandler<2>                    &dof_handler,
                   const hp::MappingCollection<2>         &mapping,
                   const Vector<double>                   &solution,
                   const std::vector<SurfaceField>        &surface_fields,
                   const std::map<unsigned int, Material> &materials,
                   const std::set<types::boundary_id>     &slave_boundary_ids,
                   const unsigned int                      step,
                   const double                            time)
  {
    // The pseudo-time goes into the files as well as into the .pvd.
    DataOutBase::VtkFlags flags;
    flags.time = time;
    // Fast zlib: best compression costs more than the solve here.
    flags.compression_level = DataOutBase::VtkFlags::best_speed;

    // The bodies: curved cells as VTK Lagrange quadrilaterals, which deal.II
    // 9.4 writes correctly for dim = 2; displacement, Cauchy stress tensor,
    // von Mises stress and the material id of each cell.
    // A vector of one value per active cell is cell data for DataOut:
    // each cell shows its body's material id, the physical group of a gmsh
    // model (float suffices for ids).
    Vector<float> material_id(dof_handler.get_triangulation().n_active_cells());
    for (const auto &cell : dof_handler.active_cell_iterators())
      material_id(cell->active_cell_index()) = cell->material_id();
    StressPostprocessor       stress(materials);
    DisplacementPostprocessor displacement;
    DataOut<2>                data_out;
    data_out.attach_dof_handler(dof_handler);
    data_out.add_data_vector(solution, displacement);
    data_out.add_data_vector(solution, stress);
    data_out.add_data_vector(material_id, "material_id");
    // With subdivisions > 1 the cells are written as Lagrange cells of that
    // degree, so that ParaView draws curved edges curved and a Q2 field
    // with its own degree; with one, as plain quadrilaterals.
    // curved_inner_cells (below) applies the mapping to the interior cells
    // too, since the polar manifold curves every cell of a ring, not only
    // those on its boundary.
    DataOutBase::VtkFlags bulk_flags    = flags;
    bulk_flags.write_higher_order_cells = subdivisions > 1;
    data_out.set_flags(bulk_flags);
    // Under MPI every process holds the whole mesh and state; each writes
    // the cells it owns (its subdomain), so that the pieces partition the
    // mesh and no cell is written twice.
    const unsigned int n_pieces = n_processes(communicator);
    const unsigned int piece    = this_process(communicator);
    if (n_pieces > 1)
      data_out.set_cell_selection(
        [piece](const Triangulation<2>::cell_iterator &cell) {
          return cell->is_active() && cell->subdomain_id() == piece;
        });
    data_out.build_patches(mapping,
                           subdivisions,
                           DataOut<2>::curved_inner_cells);
    // Four digits: ParaView groups the files of a series by name, in the
    // order of their numbers.
    const std::string bulk_stem =
      "solution-" + tag + "-" + Utilities::int_to_string(step, 4);
    const std::string bulk_name = write_bulk(data_out, bulk_stem);

    // The rest on process 0: the .pvtu, the .pvd files and the slave
    // surface (the whole state is on every process).
    // In the order that keeps every listed file whole: the .pvtu after all
    // the pieces, the .pvd after the file it adds, each renamed into place.
    const auto write_the_rest = [&]() {
      if (n_pieces > 1)
        {
          std::vector<std::string> pieces;
          for (unsigned int p = 0; p < n_pieces; ++p)
            pieces.push_back(bulk_stem + "." + std::to_string(p) + ".vtu");
          std::ostringstream pvtu;
          data_out.write_pvtu_record(pvtu, pieces);
          write_file_atomically(directory + "/" + bulk_name, pvtu.str());
        }
      record(bulk_records, time, bulk_name);
      write_file_atomically(directory + "/solution-" + tag + ".pvd",
                            pvd_contents(bulk_records));
      write_slave_surface(dof_handler,
                          mapping,
                          solution,
                          surface_fields,
                          slave_boundary_ids,
                          step,
                          flags);
    };
    // Under MPI process 0's failure is broadcast, so that every process
    // throws it and none waits in the next collective call.
    if (n_pieces == 1)
      {
        write_the_rest();
        return;
      }
    std::string error;
    if (piece == 0)
      try
        {
          write_the_rest();
        }
      catch (const std::exception &e)
        {
          error = e.what();
        }
    error = Utilities::MPI::broadcast(communicator, error, 0);
    if (!error.empty())
      throw std::runtime_error(error);
  }


  // The bodies' file: one .vtu, or under MPI one piece per process, whose
  // list (the .pvtu) process 0 writes later, once all are whole. Returns
  // the name the .pvd lists.
  std::string
  VtuWriter::write_bulk(const DataOut<2>  &data_out,
                        const std::string &bulk_stem)
  {
    const unsigned int n_pieces  = n_processes(communicator);
    const unsigned int piece     = this_process(communicator);
    std::string        bulk_name = bulk_stem + ".vtu";
    if (n_pieces == 1)
      write_vtu_file(data_out, directory + "/" + bulk_name);
    else
      {
        // Each process its piece; when all are whole, process 0 lists them.
        // The errors are gathered from all: each process throws the first
        // one, so that all leave write() together and the run ends with
        // the message of the process that failed.
        std::string error;
        try
          {
            write_vtu_file(data_out,
                           directory + "/" + bulk_stem + "." +
                             std::to_string(piece) + ".vtu");
          }
        catch (const std::exception &e)
          {
            error = e.what();
          }
        for (const auto &message :
             Utilities::MPI::all_gather(communicator, error))
          if (!message.empty())
            throw std::runtime_error(message);
        bulk_name = bulk_stem + ".pvtu";
      }
    return bulk_name;
  }

  // @sect4{The slave surfaces}
  //
  // The slave surfaces (of every contact pair), with the nodal gap. The
  // whole solution vector is written on the faces (type_dof_data): the
  // displacement, the contact pressure and the tangential traction of
  // the slave layer. The pressure is written here only: in the bulk it
  // would be a field falling to zero across the layer's cells.
  void
  VtuWriter::write_slave_surface(
    const DoFHandler<2>                &dof_handler,
    const hp::MappingCollection<2>     &mapping,
    const Vector<double>               &solution,
    const std::vector<SurfaceField>    &surface_fields,
    const std::set<types::boundary_id> &slave_boundary_ids,
    const unsigned int                  step,
    const DataOutBase::VtkFlags        &flags)
  {
    // The names of the four components of the FESystem, in order.
    const std::vector<std::string> names = {"displacement",
                                            "displacement",
                                            "contact_pressure",
                                            "tangential_traction"};

    SlaveFaces faces(slave_boundary_ids);
    faces.attach_dof_handler(dof_handler);
    faces.add_data_vector(solution,
                          names,
                          DataOutFaces<2>::type_dof_data,
                          solution_interpretation());
    // Each field's postprocessor lives until the patches are built.
    std::vector<std::unique_ptr<SurfaceFieldPostprocessor>> postprocessors;
    for (const auto &[name, values] : surface_fields)
      {
        postprocessors.push_back(
          std::make_unique<SurfaceFieldPostprocessor>(name));
        faces.add_data_vector(values, *postprocessors.back());
      }
    // Linear segments, `subdivisions` per face: deal.II 9.4 numbers the
    // points of a 1d Lagrange curve wrongly (and a Debug build aborts in
    // write_high_order_cells for dim = 1), so the surface's curved faces
    // are written as subdivided straight segments.
    DataOutBase::VtkFlags surface_flags    = flags;
    surface_flags.write_higher_order_cells = false;
    faces.set_flags(surface_flags);
    // DataOutFaces takes one mapping: that of a slave body (the bodies of a
    // problem of several pairs are straight-sided, their mappings agree).
    unsigned int slave_fe_index = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary() &&
            slave_boundary_ids.count(face->boundary_id()))
          slave_fe_index = cell->active_fe_index();
    faces.build_patches(
      mapping[std::min<unsigned int>(slave_fe_index, mapping.size() - 1)],
      subdivisions);
    const std::string surface_name =
      "slave-" + tag + "-" + Utilities::int_to_string(step, 4) + ".vtu";
    write_vtu_file(faces, directory + "/" + surface_name);
    record(surface_records, flags.time, surface_name);
    write_file_atomically(directory + "/slave-" + tag + ".pvd",
                          pvd_contents(surface_records));
  }

  // Under a temporary name, then renamed: a VTU file is whole or absent.
  // deal.II writes to an std::ostream, so the file is a stream here and
  // commit_file() reopens it to fsync it before the rename.
  template <int patch_dim>
  void
  VtuWriter::write_vtu_file(const DataOutInterface<patch_dim, 2> &data,
                            const std::string &filename) const
  {
    const std::string temporary = temporary_name(filename);
    // Check the stream after the writing and after the flush: a full disk
    // shows there (deal.II may also throw ExcIO on its own).
    // errno is cleared first so that the message names the system's reason
    // only when there was one; a stream can also fail without it.
    bool written = false;
    errno        = 0;
    try
      {
        std::ofstream out(temporary);
        if (out)
          {
            data.write_vtu(out);
            out.flush();
            out.close();
          }
        written = !out.fail();
      }
    catch (const std::exception &)
      {
        // deal.II's own ExcIO: the same error as a failed stream.
        written = false;
      }
    // No partial temporary is left behind: the folder holds whole files
    // and nothing else of ours.
    if (!written)
      {
        const int       error = errno;
        std::error_code ignored;
        std::filesystem::remove(temporary, ignored);
        throw std::runtime_error(
          "cannot write '" + filename + "': " +
          (error != 0 ? std::strerror(error) :
                        "disk full, file size limit or no permission"));
      }
    commit_file(temporary, filename);
  }

  // A rewritten step (the state written again after a failed step)
  // replaces its record instead of listing the file twice.
  void
  VtuWriter::record(std::vector<std::pair<double, std::string>> &records,
                    const double                                 time,
                    const std::string                           &name)
  {
    for (auto &r : records)
      if (r.second == name)
        {
          r.first = time;
          return;
        }
    records.emplace_back(time, name);
  }

  // The whole record list at every step: the .pvd is small, and it is
  // replaced atomically rather than appended to, so that it is always a
  // complete XML file.
  std::string
  VtuWriter::pvd_contents(
    const std::vector<std::pair<double, std::string>> &records)
  {
    std::ostringstream out;
    DataOutBase::write_pvd_record(out, records);
    return out.str();
  }
} // namespace RingContact
