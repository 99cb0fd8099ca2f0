#include "vtu_output.h"

#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace pumpd::local
{
  namespace
  {
    void write_field(std::ofstream &out, const std::string &name, const std::vector<double> &field,
                     const std::vector<std::size_t> &nodes)
    {
      out << "<DataArray type=\"Float64\" Name=\"" << name << "\" format=\"ascii\">\n";
      for (std::size_t i : nodes)
        out << field[i] << '\n';
      out << "</DataArray>\n";
    }
  } // namespace

  void write_vtu(const std::string &path, const PdModel &model, const State &s)
  {
    std::ofstream out(path);
    if (!out)
      throw std::runtime_error("cannot write " + path);
    out.precision(10);
    const auto &nodes = model.nodes();
    const auto  n     = nodes.size();
    out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\">\n"
        << "<UnstructuredGrid>\n<Piece NumberOfPoints=\"" << n << "\" NumberOfCells=\"" << n << "\">\n"
        << "<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
    for (std::size_t i : nodes)
      {
        const auto p = model.lattice().position(i);
        out << p.x << ' ' << p.y << " 0\n";
      }
    out << "</DataArray>\n</Points>\n<Cells>\n"
        << "<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
    for (std::size_t c = 0; c < n; ++c)
      out << c << '\n';
    out << "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
    for (std::size_t c = 0; c < n; ++c)
      out << c + 1 << '\n';
    out << "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
    for (std::size_t c = 0; c < n; ++c)
      out << "1\n";
    out << "</DataArray>\n</Cells>\n<PointData Scalars=\"damage\" Vectors=\"displacement\">\n"
        << "<DataArray type=\"Float64\" Name=\"displacement\" NumberOfComponents=\"3\" format=\"ascii\">\n";
    for (std::size_t i : nodes)
      out << s.ux[i] << ' ' << s.uy[i] << " 0\n";
    out << "</DataArray>\n";
    write_field(out, "damage", model.damage(s), nodes);
    write_field(out, "stretch_ratio_Z", model.stretch_ratio(s), nodes);
    write_field(out, "energy_density", model.energy_density(s), nodes);
    std::vector<double> layer(s.ux.size(), 0.);
    for (std::size_t i : model.boundary_layer())
      layer[i] = 1.;
    write_field(out, "boundary_layer", layer, nodes);
    out << "</PointData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
    if (!out)
      throw std::runtime_error("error while writing " + path);
  }

  void write_vtu(PvdSeries &series, const PdModel &model, const State &s)
  {
    const std::string file = series.next_file();
    write_vtu(series.path_of(file), model, s);
    series.add(s.time, file);
  }
} // namespace pumpd::local
