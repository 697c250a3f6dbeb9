// The VTU format itself: an unstructured grid of points, cells and point
// data written as VTK's XML, each array in single precision unless one of
// its values needs double (vtu_format.cc).
#ifndef ring_contact_output_vtu_format_h
#define ring_contact_output_vtu_format_h

#include <cstdint>
#include <string>
#include <vector>

namespace RingContact
{
  /// An array of the grid: the points' coordinates, or a field of point
  /// data, `components` values a point.
  struct VtuArray
  {
    /// An empty array of `components` values a point.
    VtuArray(const std::string &name = "", const unsigned int components = 1)
        : name(name)
        , components(components)
    {}

    std::string         name;
    unsigned int        components;
    std::vector<double> values;
    /// Written as Float64 rather than Float32 (choose_precision()).
    bool double_precision = false;
  };

  /// VTK's cell types this program writes.
  enum class VtuCellType : std::uint8_t
  {
    line                   = 3,
    quadrilateral          = 9,
    hexahedron             = 12,
    lagrange_quadrilateral = 70
  };

  /// One piece of an unstructured grid, built point by point and cell by
  /// cell, its point data in the same order as its points.
  struct VtuGrid
  {
    /// Three coordinates a point (z = 0 in two dimensions); no name.
    VtuArray                  points{"", 3};
    std::vector<std::int64_t> connectivity;
    std::vector<std::int64_t> offsets;
    std::vector<std::uint8_t> cell_types;
    std::vector<VtuArray>     point_data;

    std::size_t
    n_points() const
    {
      return points.values.size() / 3;
    }

    /// A cell of the points `ids`, in VTK's order for `type`.
    void
    add_cell(const VtuCellType type, const std::vector<std::int64_t> &ids);
  };

  /// Whether a value of `values` is lost in single precision: a finite
  /// nonzero value whose magnitude lies outside float's normal range
  /// (below 1.2e-38 it becomes a subnormal, below 1.4e-45 zero; above
  /// 3.4e38 infinite).
  bool
  needs_double_precision(const std::vector<double> &values);

  /// Each array of `grid` (the points too) in double precision where
  /// needs_double_precision() says so. Under MPI the caller makes the
  /// choice the same on every process (the .pvtu names one type).
  void
  choose_precision(VtuGrid &grid);

  /// The grid as a .vtu file: XML, each array binary (zlib-compressed,
  /// base64), the pseudo-time `time` as field data TIME.
  std::string
  vtu_contents(const VtuGrid &grid, const double time);

  /// The .pvtu that lists the pieces `sources` (file names beside it),
  /// each with the arrays of `grid` (names, components and precision: the
  /// same on every process).
  std::string
  pvtu_contents(const VtuGrid &grid, const std::vector<std::string> &sources);
} // namespace RingContact

#endif
