#include "pvd.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "output.h"

namespace pumpd
{
  namespace
  {
    /// The value of `attribute="..."` in an index line, "" without one.
    std::string attribute(const std::string &line, const std::string &attribute)
    {
      const auto start = line.find(attribute + "=\"");
      if (start == std::string::npos)
        return "";
      const auto first = start + attribute.size() + 2;
      return line.substr(first, line.find('"', first) - first);
    }
  } // namespace

  PvdSeries::PvdSeries(std::string dir, std::string base)
    : directory(std::move(dir))
    , name(std::move(base))
  {
    std::filesystem::create_directories(directory);
    claim_output_directory(directory);
  }

  std::string PvdSeries::next_file() const
  {
    char file[64];
    std::snprintf(file, sizeof(file), "_%03zu.vtu", entries.size());
    return name + file;
  }

  void PvdSeries::add(double time, const std::string &file)
  {
    entries.emplace_back(time, file);
    write_aside(index(), [&](std::ostream &pvd) {
      pvd << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n<Collection>\n";
      for (const auto &[t, f] : entries)
        pvd << "<DataSet timestep=\"" << t << "\" group=\"\" part=\"0\" file=\"" << f << "\"/>\n";
      pvd << "</Collection>\n</VTKFile>\n";
    });
  }

  std::size_t PvdSeries::restore(std::size_t n)
  {
    entries.clear();
    std::ifstream in(index());
    for (std::string line; entries.size() < n && std::getline(in, line);)
      if (const std::string file = attribute(line, "file"); !file.empty())
        entries.emplace_back(std::strtod(attribute(line, "timestep").c_str(), nullptr), file);
    return entries.size();
  }
} // namespace pumpd
