// @sect3{The VTU format, written by hand}
//
// deal.II 9.4 keeps the values of its output patches as float
// (DataOutBase::Patch::data is a Table<2, float>) and writes them as
// Float32, whatever the flags: a run at p = 1e-200 showed zero everywhere
// in ParaView while history.csv held its values. So the program writes its
// VTU files itself (vtu_writer.cc evaluates the fields in double), and this
// file the format: VTK's XML UnstructuredGrid, each array in single
// precision unless one of its values would be lost there, then in double.
// Single precision is kept where it suffices because it halves the files
// of an ordinary run; the choice is made per array and per file, which
// VTK's readers and ParaView take as it comes.
//
// The arrays are "binary" in VTK's sense: zlib-compressed, a header of
// 64-bit sizes (one block), header and data each base64-encoded, as VTK's
// own writer and deal.II's do.
#include <ring_contact/output/vtu_format.h>

#include <zlib.h>

#include <cfloat>
#include <cmath>
#include <cstring>
#include <iomanip>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace RingContact
{
  namespace
  {
    // Standard base64 (RFC 4648), with padding: what VTK's reader decodes.
    // Inline base64 rather than VTK's raw appended data keeps the file
    // plain XML, which check_results.py and a text editor read, at a third
    // more bytes; each three bytes become four characters of the table.
    std::string
    base64(const unsigned char *data, const std::size_t n)
    {
      static const char table[] =
        "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
      std::string text;
      text.reserve(4 * ((n + 2) / 3));
      for (std::size_t i = 0; i < n; i += 3)
        {
          // The last group may be short: its missing bytes are zeros, and
          // the characters that stand for none of the data are '='.
          const unsigned int a = data[i];
          const unsigned int b = i + 1 < n ? data[i + 1] : 0;
          const unsigned int c = i + 2 < n ? data[i + 2] : 0;
          text += table[a >> 2];
          text += table[((a & 3) << 4) | (b >> 4)];
          text += i + 1 < n ? table[((b & 15) << 2) | (c >> 6)] : '=';
          text += i + 2 < n ? table[c & 63] : '=';
        }
      return text;
    }

    // One array's bytes as VTK reads a compressed binary array: the header
    // (one block: 1, its size, the size of the last block, its compressed
    // size) and the compressed block, each in base64. The fastest zlib
    // level: the best compression cost more than a step's solve.
    // The header is encoded apart from the data, as VTK's reader expects
    // of compressed arrays: it decodes the header's length first to learn
    // how much data follows.
    std::string
    encode(const void *bytes, const std::size_t n)
    {
      uLongf                     compressed_size = ::compressBound(n);
      std::vector<unsigned char> compressed(compressed_size);
      if (::compress2(compressed.data(),
                      &compressed_size,
                      static_cast<const Bytef *>(bytes),
                      n,
                      Z_BEST_SPEED) != Z_OK)
        throw std::runtime_error("zlib could not compress a VTU array");
      const std::uint64_t header[4] = {1, n, n, compressed_size};
      return base64(reinterpret_cast<const unsigned char *>(header),
                    sizeof(header)) +
             base64(compressed.data(), compressed_size);
    }

    // The values in the precision chosen for the array: in single
    // precision each is rounded to the nearest float, as deal.II's writer
    // did, so that an ordinary run's files hold the values they held.
    std::string
    encode_values(const VtuArray &array)
    {
      if (array.double_precision)
        return encode(array.values.data(),
                      array.values.size() * sizeof(double));
      const std::vector<float> single(array.values.begin(), array.values.end());
      return encode(single.data(), single.size() * sizeof(float));
    }

    // VTK's names of the two types.
    std::string
    type_name(const VtuArray &array)
    {
      return array.double_precision ? "Float64" : "Float32";
    }

    // The attributes that name an array; the points have no name.
    std::string
    attributes(const VtuArray &array)
    {
      std::ostringstream text;
      text << "type=\"" << type_name(array) << "\"";
      if (!array.name.empty())
        text << " Name=\"" << array.name << "\"";
      text << " NumberOfComponents=\"" << array.components << "\"";
      return text.str();
    }

    // One array, the binary data on a line of its own.
    void
    write_array(std::ostream &out, const VtuArray &array)
    {
      out << "<DataArray " << attributes(array) << " format=\"binary\">\n"
          << encode_values(array) << "\n</DataArray>\n";
    }

    // The cells' arrays: connectivity and offsets as 64-bit integers (no
    // limit at 2^31 entries; VTK reads them natively), the types as bytes.
    template <typename Integer>
    void
    write_integers(std::ostream               &out,
                   const std::string          &name,
                   const std::string          &type,
                   const std::vector<Integer> &values)
    {
      out << "<DataArray type=\"" << type << "\" Name=\"" << name
          << "\" format=\"binary\">\n"
          << encode(values.data(), values.size() * sizeof(Integer))
          << "\n</DataArray>\n";
    }

    // The files start alike: version 1.0 with 64-bit headers, little
    // endian (the machines this runs on), zlib for the .vtu.
    std::string
    head(const std::string &type, const bool compressed)
    {
      return "<?xml version=\"1.0\"?>\n<VTKFile type=\"" + type +
             "\" version=\"1.0\" byte_order=\"LittleEndian\" "
             "header_type=\"UInt64\"" +
             (compressed ? " compressor=\"vtkZLibDataCompressor\"" : "") +
             ">\n";
    }
  } // namespace

  // The offsets are where each cell's point ids end in the connectivity
  // (VTK's convention, with no leading zero).
  void
  VtuGrid::add_cell(const VtuCellType                type,
                    const std::vector<std::int64_t> &ids)
  {
    connectivity.insert(connectivity.end(), ids.begin(), ids.end());
    offsets.push_back(connectivity.size());
    cell_types.push_back(static_cast<std::uint8_t>(type));
  }

  // A zero is exact in single precision, and an infinity or a NaN stays
  // what it is: only finite nonzero values outside float's normal range
  // are lost (a subnormal float keeps too few digits to count as kept).
  bool
  needs_double_precision(const std::vector<double> &values)
  {
    for (const double v : values)
      if (v != 0 && std::isfinite(v) &&
          (std::abs(v) < FLT_MIN || std::abs(v) > FLT_MAX))
        return true;
    return false;
  }

  void
  choose_precision(VtuGrid &grid)
  {
    grid.points.double_precision = needs_double_precision(grid.points.values);
    for (auto &array : grid.point_data)
      array.double_precision = needs_double_precision(array.values);
  }

  // The pseudo-time goes in as field data (TIME), which ParaView shows
  // and its readers of a single file use; the .pvd lists it too.
  std::string
  vtu_contents(const VtuGrid &grid, const double time)
  {
    std::ostringstream out;
    out << head("UnstructuredGrid", true) << "<UnstructuredGrid>\n"
        << "<FieldData>\n<DataArray type=\"Float64\" Name=\"TIME\" "
           "NumberOfTuples=\"1\" format=\"ascii\">"
        << std::setprecision(17) << time << "</DataArray>\n</FieldData>\n"
        << "<Piece NumberOfPoints=\"" << grid.n_points()
        << "\" NumberOfCells=\"" << grid.cell_types.size() << "\">\n"
        << "<PointData>\n";
    for (const auto &array : grid.point_data)
      write_array(out, array);
    out << "</PointData>\n<Points>\n";
    write_array(out, grid.points);
    out << "</Points>\n<Cells>\n";
    write_integers(out, "connectivity", "Int64", grid.connectivity);
    write_integers(out, "offsets", "Int64", grid.offsets);
    write_integers(out, "types", "UInt8", grid.cell_types);
    out << "</Cells>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
    return out.str();
  }

  // The .pvtu repeats each array's name, components and type, which its
  // reader checks against every piece: hence the same precision on every
  // process (vtu_writer.cc). It holds no data of its own.
  std::string
  pvtu_contents(const VtuGrid &grid, const std::vector<std::string> &sources)
  {
    std::ostringstream out;
    out << head("PUnstructuredGrid", false)
        << "<PUnstructuredGrid GhostLevel=\"0\">\n<PPointData>\n";
    for (const auto &array : grid.point_data)
      out << "<PDataArray " << attributes(array) << "/>\n";
    out << "</PPointData>\n<PPoints>\n<PDataArray " << attributes(grid.points)
        << "/>\n</PPoints>\n";
    for (const auto &source : sources)
      out << "<Piece Source=\"" << source << "\"/>\n";
    out << "</PUnstructuredGrid>\n</VTKFile>\n";
    return out.str();
  }
} // namespace RingContact
