#include "vtu.h"

#include <cmath>
#include <cstring>
#include <filesystem>
#include <ostream>
#include <limits>
#include <stdexcept>

#include "output.h"

namespace pumpd
{
  namespace
  {
    /// RFC 4648 base64 of `n` bytes.
    std::string base64(const unsigned char *bytes, std::size_t n)
    {
      static const char digits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
      std::string       out;
      out.reserve(4 * ((n + 2) / 3));
      std::size_t i = 0;
      for (; i + 2 < n; i += 3)
        {
          const std::uint32_t v = (std::uint32_t(bytes[i]) << 16) | (std::uint32_t(bytes[i + 1]) << 8) | bytes[i + 2];
          out += digits[(v >> 18) & 63];
          out += digits[(v >> 12) & 63];
          out += digits[(v >> 6) & 63];
          out += digits[v & 63];
        }
      if (i < n)
        {
          const bool          two = i + 1 < n;
          const std::uint32_t v   = (std::uint32_t(bytes[i]) << 16) | (two ? std::uint32_t(bytes[i + 1]) << 8 : 0u);
          out += digits[(v >> 18) & 63];
          out += digits[(v >> 12) & 63];
          out += two ? digits[(v >> 6) & 63] : '=';
          out += '=';
        }
      return out;
    }

    /// One DataArray: its byte count and its values, base64-encoded apart (as VTK reads them).
    template <class T>
    void data_array(std::ostream &out, const std::string &attributes, const std::vector<T> &values)
    {
      if (values.size() * sizeof(T) > std::numeric_limits<std::uint32_t>::max())
        throw std::runtime_error("VTU array of " + std::to_string(values.size() * sizeof(T)) +
                                 " bytes: more than its UInt32 byte count can say");
      const std::uint32_t bytes = std::uint32_t(values.size() * sizeof(T));
      out << "<DataArray " << attributes << " format=\"binary\">\n"
          << base64(reinterpret_cast<const unsigned char *>(&bytes), sizeof(bytes))
          << base64(reinterpret_cast<const unsigned char *>(values.data()), bytes) << "\n</DataArray>\n";
    }

    void check(const VtuField &f, std::size_t entries, const std::string &where)
    {
      if (f.components == 0 || f.values.size() != entries * f.components)
        throw std::logic_error("VTU " + where + " field " + f.name + ": " + std::to_string(f.values.size()) +
                               " values in " + std::to_string(f.components) + " components for " +
                               std::to_string(entries) + " entries");
      if (f.integer)
        for (double v : f.values)
          if (!(v == std::round(v) && std::abs(v) <= std::numeric_limits<std::int32_t>::max()))
            throw std::logic_error("VTU " + where + " field " + f.name + ": " + std::to_string(v) +
                                   " is not an Int32");
    }

    void field(std::ostream &out, const VtuField &f)
    {
      const std::string attributes =
        "Name=\"" + f.name + "\" NumberOfComponents=\"" + std::to_string(f.components) + "\"";
      if (f.integer)
        data_array(out, "type=\"Int32\" " + attributes, std::vector<std::int32_t>(f.values.begin(), f.values.end()));
      else
        data_array(out, "type=\"Float64\" " + attributes, f.values);
    }

    bool little_endian()
    {
      const std::uint16_t one = 1;
      unsigned char       first;
      std::memcpy(&first, &one, 1);
      return first == 1;
    }

    /// The file's text: the grid's points, cells and fields.
    void write_grid(std::ostream &out, const VtuGrid &grid)
    {
      const std::size_t n_points = grid.n_points();
      out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\""
          << (little_endian() ? "LittleEndian" : "BigEndian") << "\" header_type=\"UInt32\">\n<UnstructuredGrid>\n"
          << "<Piece NumberOfPoints=\"" << n_points << "\" NumberOfCells=\"" << grid.types.size() << "\">\n<Points>\n";
      std::vector<double> xyz(3 * n_points, 0.);
      for (std::size_t p = 0; p < n_points; ++p)
        {
          xyz[3 * p]     = grid.points[2 * p];
          xyz[3 * p + 1] = grid.points[2 * p + 1];
        }
      data_array(out, "type=\"Float64\" NumberOfComponents=\"3\"", xyz);
      out << "</Points>\n<Cells>\n";
      data_array(out, "type=\"Int64\" Name=\"connectivity\"", grid.connectivity);
      data_array(out, "type=\"Int64\" Name=\"offsets\"", grid.offsets);
      data_array(out, "type=\"UInt8\" Name=\"types\"", grid.types);
      out << "</Cells>\n<PointData";
      if (!grid.active_scalars.empty())
        out << " Scalars=\"" << grid.active_scalars << "\"";
      if (!grid.active_vectors.empty())
        out << " Vectors=\"" << grid.active_vectors << "\"";
      out << ">\n";
      for (const auto &f : grid.point_data)
        field(out, f);
      out << "</PointData>\n<CellData>\n";
      for (const auto &f : grid.cell_data)
        field(out, f);
      out << "</CellData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
    }
  } // namespace

  void VtuGrid::add_cell(std::int64_t first, unsigned int corners, std::uint8_t type)
  {
    for (unsigned int k = 0; k < corners; ++k)
      connectivity.push_back(first + k);
    offsets.push_back(std::int64_t(connectivity.size()));
    types.push_back(type);
  }

  double vtu_bytes(double points, double cells, unsigned int corners, unsigned int point_values,
                   unsigned int cell_values, unsigned int cell_integers)
  {
    // Per point x, y, z and its Float64 values; per cell its connectivity and offset (Int64), its
    // type (UInt8) and its values; base64 writes 4 characters per 3 bytes.
    const double raw = points * 8. * (3. + point_values) + cells * (8. * (corners + 1.) + 1. + 8. * cell_values +
                                                                      4. * cell_integers);
    return 4. / 3. * raw;
  }

  void write_vtu(const std::string &path, const VtuGrid &grid)
  {
    for (const auto &f : grid.point_data)
      check(f, grid.n_points(), "point");
    for (const auto &f : grid.cell_data)
      check(f, grid.types.size(), "cell");
    claim_output_directory(std::filesystem::path(path).parent_path().string());
    // Written aside and renamed when complete: a failed write leaves no truncated file behind.
    write_aside(path, [&](std::ostream &out) { write_grid(out, grid); });
  }
} // namespace pumpd
