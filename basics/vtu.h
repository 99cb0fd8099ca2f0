// The one VTU writer (VTK XML unstructured grid) of pumpd's ParaView output: points, cells and
// their data, every array inline as base64 binary (a UInt32 byte count, then the values, each
// encoded on its own), which ParaView reads at the full precision of the values.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace pumpd
{
  /// One field on the points or the cells: `components` values per entry, entry by entry.
  struct VtuField
  {
    std::string         name;
    unsigned int        components = 1;
    std::vector<double> values;
    bool                integer = false; ///< written as Int32 (a flag, a kind)
  };

  /// A grid of points in the plane and cells over them (VTK cell types: 1 vertex, 5 triangle,
  /// 9 quadrilateral), with the fields on each.
  struct VtuGrid
  {
    std::vector<double>       points; ///< x, y per point
    std::vector<std::int64_t> connectivity, offsets;
    std::vector<std::uint8_t> types;
    std::vector<VtuField>     point_data, cell_data;
    std::string               active_scalars, active_vectors; ///< of the point data ("": none)

    std::size_t n_points() const { return points.size() / 2; }
    /// Appends a cell on the points `first`, ..., `first + corners - 1`.
    void add_cell(std::int64_t first, unsigned int corners, std::uint8_t type);
  };

  /// Writes the grid to `path` (aside, renamed when complete: output.h). Throws std::logic_error,
  /// before the file is opened, for a field without components, of a length that does not match
  /// its points or cells, or integer with a value that is not an Int32; std::runtime_error naming
  /// the file and the cause if it cannot be written.
  void write_vtu(const std::string &path, const VtuGrid &grid);

  /// The size of the file write_vtu writes for a grid of `points` points and `cells` cells of
  /// `corners` corners each, with `point_values` Float64 values per point and `cell_values`
  /// Float64 and `cell_integers` Int32 values per cell, its XML text aside [bytes].
  double vtu_bytes(double points, double cells, unsigned int corners, unsigned int point_values,
                   unsigned int cell_values, unsigned int cell_integers);
} // namespace pumpd
