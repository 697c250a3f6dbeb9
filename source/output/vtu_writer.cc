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
// The fields are evaluated here, in double, at the points of each cell's
// patch (`subdivisions` intervals each way), and written by vtu_format.cc:
// deal.II's DataOut, which the program used before, keeps its patches in
// single precision, and a load of 1e-200 came out as zero in every file.
// An array is written in double precision where one of its values needs
// it, in single precision otherwise.
//
// Every file is written whole or not at all (output_folder.cc): a VTU
// under a temporary name, renamed when complete, and the PVD that lists it
// only afterwards, so that a PVD on disk never names a missing or partial
// VTU. Under MPI each process writes its own cells as a piece, and
// process 0 the rest.
#include <deal.II/base/data_out_base.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/fe/fe_values_extractors.h>
#include <deal.II/hp/fe_values.h>

#include <ring_contact/base/components.h>
#include <ring_contact/base/utilities.h>
#include <ring_contact/linear_algebra/linear_system.h>
#include <ring_contact/output/output_folder.h>
#include <ring_contact/output/vtu_format.h>
#include <ring_contact/output/vtu_writer.h>

#include <limits>
#include <memory>
#include <sstream>
#include <stdexcept>

namespace RingContact
{
  namespace
  {
    // @sect4{The points of a patch}
    //
    // A cell is written as (n + 1)^dim points, evenly spaced on the
    // reference cell, x fastest; a face as n + 1 points from its first
    // vertex to its second (3D: (n + 1)^2, as a cell of the face). The
    // mapping places them, curved where the geometry is, in the cell's
    // interior as well (the polar manifold curves every cell of a ring,
    // not only those on its boundary).
    template <int dim>
    Quadrature<dim>
    patch_points(const unsigned int n)
    {
      std::vector<Point<dim>> points;
      for (unsigned int k = 0; k <= (dim == 3 ? n : 0); ++k)
        for (unsigned int j = 0; j <= n; ++j)
          for (unsigned int i = 0; i <= n; ++i)
            {
              Point<dim> x;
              x[0] = double(i) / n;
              x[1] = double(j) / n;
              if constexpr (dim == 3)
                x[2] = double(k) / n;
              points.push_back(x);
            }
      return Quadrature<dim>(points);
    }

    Quadrature<1>
    segment_points(const unsigned int n)
    {
      std::vector<Point<1>> points;
      for (unsigned int k = 0; k <= n; ++k)
        points.emplace_back(double(k) / n);
      return Quadrature<1>(points);
    }

    // VTK's place of the point (i, j) of a Lagrange quadrilateral of degree
    // n (vtkHigherOrderQuadrilateral::PointIndexFromIJK): the four corners
    // counterclockwise, then the edges' inner points (bottom and top
    // left to right, right and left bottom to top, in the order bottom,
    // right, top, left), then the inner points row by row.
    std::int64_t
    lagrange_index(const unsigned int i,
                   const unsigned int j,
                   const unsigned int n)
    {
      const bool i_end = i == 0 || i == n, j_end = j == 0 || j == n;
      if (i_end && j_end)
        return i == 0 ? (j == 0 ? 0 : 3) : (j == 0 ? 1 : 2);
      if (j_end)
        return 4 + (i - 1) + (j == 0 ? 0 : (n - 1) + (n - 1));
      if (i_end)
        return 4 + (j - 1) + (i == n ? (n - 1) : 3 * (n - 1));
      return 4 + 4 * (n - 1) + (i - 1) + (n - 1) * (j - 1);
    }

    // A cell's points as one cell: a Lagrange quadrilateral with n > 1, so
    // that ParaView draws curved edges curved and a Q2 field with its own
    // degree; a plain quadrilateral with n = 1. A hexahedron's as n^3 plain
    // hexahedra (VTK's vertex order: the bottom face counterclockwise, then
    // the top one).
    template <int dim>
    void
    add_patch_cell(VtuGrid           &grid,
                   const std::int64_t first,
                   const unsigned int n)
    {
      if constexpr (dim == 3)
        {
          const auto id = [&](const unsigned int i,
                              const unsigned int j,
                              const unsigned int k) {
            return first + (k * (n + 1) + j) * (n + 1) + i;
          };
          for (unsigned int k = 0; k < n; ++k)
            for (unsigned int j = 0; j < n; ++j)
              for (unsigned int i = 0; i < n; ++i)
                grid.add_cell(VtuCellType::hexahedron,
                              {id(i, j, k),
                               id(i + 1, j, k),
                               id(i + 1, j + 1, k),
                               id(i, j + 1, k),
                               id(i, j, k + 1),
                               id(i + 1, j, k + 1),
                               id(i + 1, j + 1, k + 1),
                               id(i, j + 1, k + 1)});
          return;
        }
      std::vector<std::int64_t> ids((n + 1) * (n + 1));
      for (unsigned int j = 0; j <= n; ++j)
        for (unsigned int i = 0; i <= n; ++i)
          ids[lagrange_index(i, j, n)] = first + j * (n + 1) + i;
      grid.add_cell(n > 1 ? VtuCellType::lagrange_quadrilateral :
                            VtuCellType::quadrilateral,
                    ids);
    }

    // @sect4{The bodies}
    //
    // Displacement, the Cauchy stress as a tensor (ParaView computes its
    // principal values and directions: the 2 x 2 tensor padded with zeros
    // to VTK's 3 x 3, row by row) and the von Mises stress, with sigma_33
    // in plane strain, from the displacement gradient and each body's own
    // material (the laws have no internal state, so the stress is a
    // function of Grad u at the point); and each cell's material id, the
    // physical group of a gmsh model, constant on the cell. Under MPI the
    // cells of the process's subdomain alone.
    template <int dim>
    VtuGrid
    bulk_grid(const DoFHandler<dim>                       &dof_handler,
              const hp::MappingCollection<dim>            &mapping,
              const Vector<double>                        &solution,
              const std::map<unsigned int, Material<dim>> &materials,
              const unsigned int                           n,
              const unsigned int                           piece,
              const unsigned int                           n_pieces)
    {
      VtuGrid grid;
      grid.point_data    = {{"displacement", 3},
                            {"cauchy_stress", 9},
                            {"von_Mises_stress", 1},
                            {"material_id", 1}};
      auto &displacement = grid.point_data[0].values;
      auto &stress       = grid.point_data[1].values;
      auto &von_mises    = grid.point_data[2].values;
      auto &material_id  = grid.point_data[3].values;

      hp::FEValues<dim>                hp_values(mapping,
                                  dof_handler.get_fe_collection(),
                                  hp::QCollection<dim>(patch_points<dim>(n)),
                                  update_values | update_gradients |
                                    update_quadrature_points);
      const FEValuesExtractors::Vector u(Components::ux);
      std::vector<Tensor<1, dim>>      values;
      std::vector<Tensor<2, dim>>      gradients;
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          if (n_pieces > 1 && cell->subdomain_id() != piece)
            continue;
          hp_values.reinit(cell);
          const FEValues<dim> &v = hp_values.get_present_fe_values();
          values.resize(v.n_quadrature_points);
          gradients.resize(v.n_quadrature_points);
          v[u].get_function_values(solution, values);
          v[u].get_function_gradients(solution, gradients);
          const Material<dim> &material = materials.at(cell->material_id());
          const std::int64_t   first    = grid.n_points();
          for (unsigned int q = 0; q < v.n_quadrature_points; ++q)
            {
              const Point<dim> x = v.quadrature_point(q);
              grid.points.values.insert(grid.points.values.end(),
                                        {x[0],
                                         x[1],
                                         dim == 3 ? x[dim - 1] : 0});
              displacement.insert(displacement.end(),
                                  {values[q][0],
                                   values[q][1],
                                   dim == 3 ? values[q][dim - 1] : 0});
              // A law checks its range at the quadrature points of the
              // assembly; at these points (the patch's) a state near the
              // bound may lie past it (Saint Venant-Kirchhoff in plane
              // stress without a thickness): no stress exists there,
              // written as NaN (ParaView's missing value), not thrown
              // mid-file.
              if (!material.in_range(gradients[q]))
                {
                  const double nan = std::numeric_limits<double>::quiet_NaN();
                  stress.insert(stress.end(), 9, nan);
                  von_mises.push_back(nan);
                }
              else
                {
                  const Tensor<2, dim> s = material.cauchy_stress(gradients[q]);
                  if constexpr (dim == 3)
                    for (unsigned int i = 0; i < dim; ++i)
                      for (unsigned int j = 0; j < dim; ++j)
                        stress.push_back(s[i][j]);
                  else
                    stress.insert(
                      stress.end(),
                      {s[0][0], s[0][1], 0, s[1][0], s[1][1], 0, 0, 0, 0});
                  von_mises.push_back(material.von_mises_stress(gradients[q]));
                }
              material_id.push_back(cell->material_id());
            }
          add_patch_cell<dim>(grid, first, n);
        }
      return grid;
    }

    // @sect4{The slave surfaces}
    //
    // A 3D slave surface: each face as n x n quadrilaterals on its own
    // (n + 1)^2 points (no chains: a surface has no order to plot along),
    // with the displacement, the contact pressure, and the nodal fields the
    // problem hands over (the gap) read from the multiplier component.
    template <int dim>
    VtuGrid
    slave_faces_grid(
      const DoFHandler<dim>                                    &dof_handler,
      const hp::MappingCollection<dim>                         &mapping,
      const Vector<double>                                     &solution,
      const std::vector<typename VtuWriter<dim>::SurfaceField> &surface_fields,
      const std::vector<typename VtuWriter<dim>::SlaveFace>    &faces,
      const unsigned int                                        n)
    {
      VtuGrid grid;
      grid.point_data = {{"displacement", 3}, {"contact_pressure", 1}};
      for (const auto &field : surface_fields)
        grid.point_data.push_back({field.name, 1});
      hp::FEFaceValues<dim>            hp_values(mapping,
                                      dof_handler.get_fe_collection(),
                                      hp::QCollection<dim - 1>(
                                        patch_points<dim - 1>(n)),
                                      update_values | update_quadrature_points);
      const FEValuesExtractors::Vector u(Components::ux);
      const FEValuesExtractors::Scalar pressure(Components::multiplier<dim>);
      std::vector<Tensor<1, dim>>      displacement;
      std::vector<double>              scalar;
      for (const auto &face : faces)
        {
          hp_values.reinit(face.cell, face.face_no);
          const FEFaceValues<dim> &v     = hp_values.get_present_fe_values();
          const std::int64_t       first = grid.n_points();
          displacement.resize(v.n_quadrature_points);
          scalar.resize(v.n_quadrature_points);
          v[u].get_function_values(solution, displacement);
          for (unsigned int q = 0; q < v.n_quadrature_points; ++q)
            for (unsigned int d = 0; d < dim; ++d)
              {
                grid.points.values.push_back(v.quadrature_point(q)[d]);
                grid.point_data[0].values.push_back(displacement[q][d]);
              }
          for (unsigned int k = 0; k <= surface_fields.size(); ++k)
            {
              v[pressure].get_function_values(
                k == 0 ? solution : surface_fields[k - 1].values, scalar);
              grid.point_data[1 + k].values.insert(
                grid.point_data[1 + k].values.end(),
                scalar.begin(),
                scalar.end());
            }
          for (unsigned int j = 0; j < n; ++j)
            for (unsigned int i = 0; i < n; ++i)
              {
                const auto id = [&](const unsigned int a,
                                    const unsigned int b) {
                  return first + b * (n + 1) + a;
                };
                grid.add_cell(
                  VtuCellType::quadrilateral,
                  {id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
              }
        }
      return grid;
    }

    // The faces of the slave surfaces in the order the problem gives them:
    // chain after chain, each in the order its arc length runs, so that a
    // plot over the arc length (ParaView's Plot Data, which joins the
    // points in the file's order) draws the curve; the faces used to come
    // in the order of the cells, which on a gmsh mesh is no order along
    // the surface, and the plot was a zigzag. Consecutive faces of a chain
    // share their point; the face that closes a chain on itself ends at a
    // point of its own, where the arc length is the chain's length.
    //
    // Each face is n straight segments (a curved face subdivided). On them
    // the displacement, the contact pressure and the tangential traction
    // (zero without friction), and the nodal fields the problem hands over
    // (the gap, the arc length), stored in the multiplier component of a
    // vector of the unknowns: they belong to the multiplier's nodes and are
    // interpolated like the pressure. The pressure is written here only: in
    // the bulk it would be a field falling to zero across the layer of
    // slave cells.
    template <int dim>
    VtuGrid
    slave_surface_grid(
      const DoFHandler<dim>                                    &dof_handler,
      const hp::MappingCollection<dim>                         &mapping,
      const Vector<double>                                     &solution,
      const std::vector<typename VtuWriter<dim>::SurfaceField> &surface_fields,
      const std::vector<typename VtuWriter<dim>::SlaveFace>    &faces,
      const unsigned int                                        n)
    {
      if constexpr (dim == 3)
        return slave_faces_grid(
          dof_handler, mapping, solution, surface_fields, faces, n);
      else
        {
          VtuGrid grid;
          grid.point_data = {{"displacement", 3},
                             {"contact_pressure", 1},
                             {"tangential_traction", 1}};
          for (const auto &field : surface_fields)
            grid.point_data.push_back({field.name, 1});

          hp::FEFaceValues<dim>            hp_values(mapping,
                                          dof_handler.get_fe_collection(),
                                          hp::QCollection<1>(segment_points(n)),
                                          update_values |
                                            update_quadrature_points);
          const FEValuesExtractors::Vector u(Components::ux);
          const FEValuesExtractors::Scalar pressure(
            Components::multiplier<dim>);
          const FEValuesExtractors::Scalar traction(
            Components::tangential<dim>);
          std::vector<Tensor<1, dim>> displacement(n + 1);
          std::vector<double>         scalar(n + 1);
          for (const auto &face : faces)
            {
              hp_values.reinit(face.cell, face.face_no);
              const FEFaceValues<dim> &v = hp_values.get_present_fe_values();
              v[u].get_function_values(solution, displacement);
              // The face's points in the chain's direction; its first is the
              // last of the face before, but at a chain's start.
              const auto point = [&](const unsigned int k) {
                return face.reversed ? n - k : k;
              };
              const unsigned int first_new = face.starts_chain ? 0 : 1;
              const std::int64_t first =
                static_cast<std::int64_t>(grid.n_points()) - first_new;
              for (unsigned int k = first_new; k <= n; ++k)
                {
                  const Point<dim> x = v.quadrature_point(point(k));
                  grid.points.values.insert(grid.points.values.end(),
                                            {x[0], x[1], 0});
                  const Tensor<1, dim> &d = displacement[point(k)];
                  grid.point_data[0].values.insert(
                    grid.point_data[0].values.end(), {d[0], d[1], 0});
                }
              // The scalars, each read from its vector's multiplier component
              // (the solution's own multiplier and tangential traction first).
              const auto add_scalar = [&](const unsigned int    array,
                                          const Vector<double> &vector,
                                          const FEValuesExtractors::Scalar &c) {
                v[c].get_function_values(vector, scalar);
                for (unsigned int k = first_new; k <= n; ++k)
                  grid.point_data[array].values.push_back(scalar[point(k)]);
              };
              add_scalar(1, solution, pressure);
              add_scalar(2, solution, traction);
              for (unsigned int k = 0; k < surface_fields.size(); ++k)
                {
                  const auto &field = surface_fields[k];
                  add_scalar(3 + k,
                             face.closes_chain &&
                                 field.closing_values.size() > 0 ?
                               field.closing_values :
                               field.values,
                             pressure);
                }
              for (unsigned int k = 0; k < n; ++k)
                grid.add_cell(VtuCellType::line, {first + k, first + k + 1});
            }
          return grid;
        }
    }

    // Every process writes its piece with the same types, which the .pvtu
    // names once: an array is in double precision on all if it is on one.
    void
    choose_precision(VtuGrid &grid, const MPI_Comm communicator)
    {
      choose_precision(grid);
      if (n_processes(communicator) == 1)
        return;
      grid.points.double_precision =
        Utilities::MPI::logical_or(grid.points.double_precision, communicator);
      for (auto &array : grid.point_data)
        array.double_precision =
          Utilities::MPI::logical_or(array.double_precision, communicator);
    }
  } // namespace

  // The writer lives as long as its scheme's run and keeps the records of
  // all its steps: each step's .pvd is written anew with every step so
  // far.
  template <int dim>
  VtuWriter<dim>::VtuWriter(const std::string &directory,
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
  template <int dim>
  void
  VtuWriter<dim>::write(const DoFHandler<dim>            &dof_handler,
                        const hp::MappingCollection<dim> &mapping,
                        const Vector<double>             &solution,
                        const std::vector<SurfaceField>  &surface_fields,
                        const std::map<unsigned int, Material<dim>> &materials,
                        const std::vector<SlaveFace> &slave_faces,
                        const unsigned int            step,
                        const double                  time)
  {
    // Under MPI every process holds the whole mesh and state; each writes
    // the cells it owns (its subdomain), so that the pieces partition the
    // mesh and no cell is written twice.
    const unsigned int n_pieces = n_processes(communicator);
    const unsigned int piece    = this_process(communicator);
    VtuGrid            bulk     = bulk_grid<dim>(
      dof_handler, mapping, solution, materials, subdivisions, piece, n_pieces);
    choose_precision(bulk, communicator);
    // Four digits: ParaView groups the files of a series by name, in the
    // order of their numbers.
    const std::string bulk_stem =
      "solution-" + tag + "-" + Utilities::int_to_string(step, 4);
    const std::string bulk_name = write_bulk(bulk, bulk_stem, time);

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
          write_file_atomically(directory + "/" + bulk_name,
                                pvtu_contents(bulk, pieces));
        }
      record(bulk_records, time, bulk_name);
      write_file_atomically(directory + "/solution-" + tag + ".pvd",
                            pvd_contents(bulk_records));
      write_slave_surface(dof_handler,
                          mapping,
                          solution,
                          surface_fields,
                          slave_faces,
                          step,
                          time);
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
  template <int dim>
  std::string
  VtuWriter<dim>::write_bulk(const VtuGrid     &bulk,
                             const std::string &bulk_stem,
                             const double       time)
  {
    const unsigned int n_pieces  = n_processes(communicator);
    const unsigned int piece     = this_process(communicator);
    std::string        bulk_name = bulk_stem + ".vtu";
    if (n_pieces == 1)
      write_file_atomically(directory + "/" + bulk_name,
                            vtu_contents(bulk, time));
    else
      {
        // Each process its piece; when all are whole, process 0 lists them.
        // The errors are gathered from all: each process throws the first
        // one, so that all leave write() together and the run ends with
        // the message of the process that failed.
        std::string error;
        try
          {
            write_file_atomically(directory + "/" + bulk_stem + "." +
                                    std::to_string(piece) + ".vtu",
                                  vtu_contents(bulk, time));
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

  // The slave surfaces of every contact pair, with the nodal gap and arc
  // length, and the .pvd that lists them.
  template <int dim>
  void
  VtuWriter<dim>::write_slave_surface(
    const DoFHandler<dim>            &dof_handler,
    const hp::MappingCollection<dim> &mapping,
    const Vector<double>             &solution,
    const std::vector<SurfaceField>  &surface_fields,
    const std::vector<SlaveFace>     &slave_faces,
    const unsigned int                step,
    const double                      time)
  {
    VtuGrid surface = slave_surface_grid<dim>(dof_handler,
                                              mapping,
                                              solution,
                                              surface_fields,
                                              slave_faces,
                                              subdivisions);
    choose_precision(surface);
    const std::string surface_name =
      "slave-" + tag + "-" + Utilities::int_to_string(step, 4) + ".vtu";
    write_file_atomically(directory + "/" + surface_name,
                          vtu_contents(surface, time));
    record(surface_records, time, surface_name);
    write_file_atomically(directory + "/slave-" + tag + ".pvd",
                          pvd_contents(surface_records));
  }

  // A rewritten step (the state written again after a failed step)
  // replaces its record instead of listing the file twice.
  template <int dim>
  void
  VtuWriter<dim>::record(std::vector<std::pair<double, std::string>> &records,
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
  template <int dim>
  std::string
  VtuWriter<dim>::pvd_contents(
    const std::vector<std::pair<double, std::string>> &records)
  {
    std::ostringstream out;
    DataOutBase::write_pvd_record(out, records);
    return out.str();
  }

  template class VtuWriter<2>;
  template class VtuWriter<3>;
} // namespace RingContact
