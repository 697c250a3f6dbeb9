#include <deal.II/base/data_out_base.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/data_out_faces.h>
#include <deal.II/numerics/data_postprocessor.h>

#include <ring_contact/components.h>
#include <ring_contact/linear_system.h>
#include <ring_contact/output_folder.h>
#include <ring_contact/postprocessing.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <set>
#include <sstream>

namespace RingContact
{
  namespace
  {
    // The rows a check takes: every row, and a failing 'step not reached'
    // after the last one when the run stopped early; or the rows of the
    // listed steps (invalid_unsigned_int: the load program's last), a
    // listed step never reached failing.
    template <typename CheckRow>
    void
    for_checked_rows(const bool                       every_step,
                     const std::vector<unsigned int> &steps,
                     const std::vector<HistoryRow>   &history,
                     const unsigned int               n_steps,
                     const CheckRow                  &check_row,
                     const std::string               &scheme,
                     const double                     tolerance,
                     std::vector<Verdict>            &verdicts)
    {
      const auto not_reached = [&](const unsigned int step) {
        verdicts.push_back(Verdict{scheme,
                                   "step not reached",
                                   step,
                                   std::nan(""),
                                   0,
                                   std::nan(""),
                                   tolerance,
                                   false,
                                   true,
                                   ""});
      };
      if (every_step)
        {
          for (const auto &row : history)
            check_row(row);
          if (history.empty() || history.back().step < n_steps)
            not_reached(history.empty() ? 1 : history.back().step + 1);
          return;
        }
      for (const unsigned int step : steps)
        {
          const unsigned int wanted =
            step == numbers::invalid_unsigned_int ? n_steps : step;
          bool found = false;
          for (const auto &row : history)
            if (row.step == wanted)
              {
                check_row(row);
                found = true;
              }
          if (!found)
            not_reached(wanted);
        }
    }
  } // namespace

  std::vector<Verdict>
  evaluate_checks(const CheckParameters         &checks,
                  const std::string             &scheme,
                  const std::vector<HistoryRow> &history,
                  const unsigned int             n_steps)
  {
    std::vector<Verdict> verdicts;
    const auto           check_row = [&](const HistoryRow &row) {
      Verdict v;
      v.scheme    = row.scheme;
      v.step      = row.step;
      v.tolerance = checks.tolerance;
      // Against the closed form of the rings (Lame's solution): the
      // pressure itself, or the spread and the L2 error relative to it.
      v.source = "closed form";
      if (checks.quantity == CheckedQuantity::pressure_at_A)
        {
          v.quantity  = "pressure at A";
          v.value     = row.pressure_A;
          v.reference = row.analytic;
          v.error     = row.relative_error;
        }
      else if (checks.quantity == CheckedQuantity::pressure_spread)
        {
          v.quantity = "pressure spread";
          v.value = (row.pressure_max - row.pressure_min) / row.analytic;
          v.reference = 0;
          v.error     = v.value;
          v.relative  = false;
        }
      else
        {
          v.quantity  = "L2 error of pressure";
          v.value     = row.l2_relative_error;
          v.reference = 0;
          v.error     = row.l2_relative_error;
          v.relative  = false;
        }
      v.pass = std::isfinite(v.error) && std::abs(v.error) <= v.tolerance;
      verdicts.push_back(v);
    };
    for_checked_rows(checks.every_step,
                     checks.steps,
                     history,
                     n_steps,
                     check_row,
                     scheme,
                     checks.tolerance,
                     verdicts);
    return verdicts;
  }

  std::vector<Verdict>
  evaluate_checks(const ProblemParameters       &problem,
                  const std::string             &scheme,
                  const std::vector<HistoryRow> &history,
                  const unsigned int             n_steps)
  {
    std::vector<Verdict> verdicts;
    for (unsigned int k = 0; k < problem.checks.size(); ++k)
      {
        const ProblemCheckParameters &check = problem.checks[k];
        const auto reference                = make_expression({check.reference},
                                               problem.constants,
                                               check.name + "/Reference");
        const auto check_row                = [&](const HistoryRow &row) {
          Verdict v;
          v.scheme    = row.scheme;
          v.quantity  = check.description();
          v.step      = row.step;
          v.tolerance = check.tolerance;
          v.value     = row.quantities.at(k);
          reference->set_time(row.time);
          v.reference = reference->value(check.point);
          v.error     = v.value - v.reference;
          if (check.relative)
            v.error /= std::abs(v.reference);
          v.relative = check.relative;
          v.source   = check.source;
          v.pass = std::isfinite(v.error) && std::abs(v.error) <= v.tolerance;
          verdicts.push_back(v);
        };
        for_checked_rows(check.every_step,
                         check.steps,
                         history,
                         n_steps,
                         check_row,
                         scheme,
                         check.tolerance,
                         verdicts);
      }
    return verdicts;
  }

  // The verdict table, after Code_Aster's TEST_RESU: each check's value,
  // reference, whether the error is relative or absolute, the error and the
  // tolerance in a form that shows small numbers (1.0e-08, not 0.0000 %),
  // the kind of reference, and the verdict. At most 132 columns.
  bool
  print_verdicts(std::ostream &out, const std::vector<Verdict> &verdicts)
  {
    if (verdicts.empty())
      {
        out << "\nChecks: none\n";
        return true;
      }
    bool all_pass = true;
    out << "\nChecks\n"
        << std::left << std::setw(18) << "scheme" << std::setw(22) << "quantity"
        << std::right << std::setw(5) << "step" << std::setw(15) << "value"
        << std::setw(15) << "reference" << "  " << std::left << std::setw(8)
        << "error is" << std::right << std::setw(11) << "error"
        << std::setw(11) << "tolerance"
        << "  " << std::left << std::setw(13) << "reference is"
        << "verdict\n";
    for (const auto &v : verdicts)
      {
        // A step not reached has no value, reference or error: "-".
        const bool none = std::isnan(v.value) && std::isnan(v.error);
        out << std::left << std::setw(18) << v.scheme << std::setw(22)
            << v.quantity << std::right << std::setw(5) << v.step
            << std::setprecision(7) << std::setw(15);
        if (none)
          out << "-" << std::setw(15) << "-" << "  " << std::left
              << std::setw(8) << "" << std::right << std::setw(11) << "-";
        else
          out << v.value << std::setw(15) << v.reference << "  " << std::left
              << std::setw(8) << (v.relative ? "relative" : "absolute")
              << std::right << std::scientific << std::setprecision(2)
              << std::setw(11) << v.error;
        out << std::scientific << std::setprecision(2) << std::setw(11)
            << v.tolerance << std::defaultfloat << "  " << std::left
            << std::setw(13) << (v.source.empty() ? "-" : v.source)
            << (v.pass ? "PASS" : "FAIL") << std::right << '\n';
        all_pass = all_pass && v.pass;
      }
    unsigned int n_pass = 0;
    for (const auto &v : verdicts)
      n_pass += v.pass;
    out << n_pass << " of " << verdicts.size() << " checks pass\n";
    // A reference expression that gives no number (sqrt(t - 2) at t = 1)
    // fails its check: say so, once per quantity.
    std::set<std::string> said;
    for (const auto &v : verdicts)
      if (!std::isfinite(v.reference) && said.insert(v.quantity).second)
        out << "Note: the reference of '" << v.quantity
            << "' is not a finite number at step " << v.step << " ("
            << (std::isnan(v.reference) ? "nan" :
                v.reference > 0         ? "inf" :
                                          "-inf")
            << "): check its expression\n";
    return all_pass;
  }

  std::string
  verdicts_csv(const std::vector<Verdict> &verdicts)
  {
    // A field with a comma or a quote ("pressure at (0, 0)") in quotes, its
    // quotes doubled (RFC 4180), so that a CSV reader sees one field.
    const auto field = [](const std::string &text) {
      if (text.find_first_of(",\"\n") == std::string::npos)
        return text;
      std::string quoted = "\"";
      for (const char c : text)
        quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
      return quoted + "\"";
    };
    std::ostringstream out;
    out << "scheme,quantity,step,value,reference,error,tolerance,error_is,"
           "reference_is,verdict\n";
    out << std::setprecision(10);
    for (const auto &v : verdicts)
      out << field(v.scheme) << ',' << field(v.quantity) << ',' << v.step << ','
          << v.value << ',' << v.reference << ',' << v.error << ','
          << v.tolerance << ',' << (v.relative ? "relative" : "absolute")
          << ',' << field(v.source) << ',' << (v.pass ? "PASS" : "FAIL")
          << '\n';
    return out.str();
  }

  void
  write_verdicts(const std::string          &filename,
                 const std::vector<Verdict> &verdicts)
  {
    write_file_atomically(filename, verdicts_csv(verdicts));
  }

  std::string
  history_csv_header(const std::vector<std::string> &extra_columns)
  {
    std::string header =
      "scheme,step,time,load_factor,rotation,pressure_A,analytic,"
      "relative_error,l2_relative_error,pressure_min,pressure_max,"
      "newton_iterations,step_cuts,active_nodes,wall_time";
    for (const auto &column : extra_columns)
      header += "," + column;
    return header + ",equilibrium_error,action_reaction_error\n";
  }

  std::string
  history_csv_row(const HistoryRow &r)
  {
    std::ostringstream out;
    out << std::setprecision(10);
    out << r.scheme << ',' << r.step << ',' << r.time << ',' << r.load_factor
        << ',' << r.rotation << ',' << r.pressure_A << ',' << r.analytic << ','
        << r.relative_error << ',' << r.l2_relative_error << ','
        << r.pressure_min << ',' << r.pressure_max << ',' << r.newton_iterations
        << ',' << r.step_cuts << ',' << r.active_nodes << ',' << r.wall_time;
    for (const double q : r.quantities)
      out << ',' << q;
    out << std::setprecision(3) << ',' << r.equilibrium_error << ','
        << r.action_reaction_error << '\n';
    return out.str();
  }

  void
  write_history(const std::string              &filename,
                const std::vector<HistoryRow>  &history,
                const std::vector<std::string> &extra_columns)
  {
    std::string contents = history_csv_header(extra_columns);
    for (const auto &row : history)
      contents += history_csv_row(row);
    write_file_atomically(filename, contents);
  }

  HistoryFile::HistoryFile(const std::string              &filename,
                           const std::vector<std::string> &extra_columns)
      : file(filename, history_csv_header(extra_columns))
  {}

  void
  HistoryFile::append(const HistoryRow &row)
  {
    file.append(history_csv_row(row));
  }

  namespace
  {
    // The Cauchy stress as a tensor (ParaView computes its principal
    // values and directions) and the von Mises stress, with sigma_33 in
    // plane strain, from the displacement gradient and each body's own
    // material.
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
            Tensor<2, 2> H;
            for (unsigned int d = 0; d < 2; ++d)
              H[d] = inputs.solution_gradients[q][d];
            const Tensor<2, 2> s = material.cauchy_stress(H);
            for (unsigned int i = 0; i < 2; ++i)
              for (unsigned int j = 0; j < 2; ++j)
                computed_quantities[q]
                                   [Tensor<2, 2>::component_to_unrolled_index(
                                     TableIndices<2>(i, j))] = s[i][j];
            computed_quantities[q][4] = material.von_mises_stress(H);
          }
      }

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

      UpdateFlags
      get_needed_update_flags() const override
      {
        return update_gradients;
      }

    private:
      const std::map<unsigned int, Material> &materials;
    };

    // Only the faces of the slave surface.
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

    // The gap, stored in the multiplier component of a dof vector.
    class GapPostprocessor : public DataPostprocessorScalar<2>
    {
    public:
      GapPostprocessor()
          : DataPostprocessorScalar<2>("gap", update_values)
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

    std::vector<DataComponentInterpretation::DataComponentInterpretation>
    solution_interpretation()
    {
      return {DataComponentInterpretation::component_is_part_of_vector,
              DataComponentInterpretation::component_is_part_of_vector,
              DataComponentInterpretation::component_is_scalar,
              DataComponentInterpretation::component_is_scalar};
    }
  } // namespace

  VtuWriter::VtuWriter(const std::string &directory,
                       const std::string &tag,
                       const unsigned int subdivisions,
                       const MPI_Comm     communicator)
      : directory(directory)
      , tag(tag)
      , subdivisions(subdivisions)
      , communicator(communicator)
  {}

  void
  VtuWriter::write(const DoFHandler<2>                    &dof_handler,
                   const hp::MappingCollection<2>         &mapping,
                   const Vector<double>                   &solution,
                   const Vector<double>                   &nodal_gap,
                   const std::map<unsigned int, Material> &materials,
                   const std::set<types::boundary_id>     &slave_boundary_ids,
                   const unsigned int                      step,
                   const double                            time)
  {
    DataOutBase::VtkFlags flags;
    flags.time = time;
    // Fast zlib: best compression costs more than the solve here.
    flags.compression_level = DataOutBase::VtkFlags::best_speed;

    // The bodies: curved cells as VTK Lagrange quadrilaterals, which deal.II
    // 9.4 writes correctly for dim = 2; displacement, Cauchy stress tensor,
    // von Mises stress and the material id of each cell.
    Vector<float> ring_id(dof_handler.get_triangulation().n_active_cells());
    for (const auto &cell : dof_handler.active_cell_iterators())
      ring_id(cell->active_cell_index()) = cell->material_id();
    StressPostprocessor       stress(materials);
    DisplacementPostprocessor displacement;
    DataOut<2>                data_out;
    data_out.attach_dof_handler(dof_handler);
    data_out.add_data_vector(solution, displacement);
    data_out.add_data_vector(solution, stress);
    data_out.add_data_vector(ring_id, "ring_id");
    DataOutBase::VtkFlags bulk_flags    = flags;
    bulk_flags.write_higher_order_cells = subdivisions > 1;
    data_out.set_flags(bulk_flags);
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
    const std::string bulk_stem =
      "solution-" + tag + "-" + Utilities::int_to_string(step, 4);
    std::string bulk_name = bulk_stem + ".vtu";
    if (n_pieces == 1)
      write_vtu_file(data_out, directory + "/" + bulk_name);
    else
      {
        // Each process its piece; when all are whole, process 0 lists them.
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

    // The rest on process 0: the .pvtu, the .pvd files and the slave
    // surface (the whole state is on every process).
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
                          nodal_gap,
                          slave_boundary_ids,
                          step,
                          flags);
    };
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

  // The slave surfaces (of every contact pair), with the nodal gap.
  void
  VtuWriter::write_slave_surface(
    const DoFHandler<2>                &dof_handler,
    const hp::MappingCollection<2>     &mapping,
    const Vector<double>               &solution,
    const Vector<double>               &nodal_gap,
    const std::set<types::boundary_id> &slave_boundary_ids,
    const unsigned int                  step,
    const DataOutBase::VtkFlags        &flags)
  {
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
    GapPostprocessor gap;
    faces.add_data_vector(nodal_gap, gap);
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
  template <int patch_dim>
  void
  VtuWriter::write_vtu_file(const DataOutInterface<patch_dim, 2> &data,
                            const std::string &filename) const
  {
    const std::string temporary = temporary_name(filename);
    // Check the stream after the writing and after the flush: a full disk
    // shows there (deal.II may also throw ExcIO on its own).
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
        written = false;
      }
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

  std::string
  VtuWriter::pvd_contents(
    const std::vector<std::pair<double, std::string>> &records)
  {
    std::ostringstream out;
    DataOutBase::write_pvd_record(out, records);
    return out.str();
  }
} // namespace RingContact
