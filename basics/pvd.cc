#include "pvd.h"

#include <cstdio>
#include <filesystem>
#include <fstream>

namespace pumpd
{
  PvdSeries::PvdSeries(std::string dir, std::string base)
    : directory(std::move(dir))
    , name(std::move(base))
  {
    std::filesystem::create_directories(directory);
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
    std::ofstream pvd(directory + "/" + name + ".pvd");
    pvd << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n<Collection>\n";
    for (const auto &[t, f] : entries)
      pvd << "<DataSet timestep=\"" << t << "\" group=\"\" part=\"0\" file=\"" << f << "\"/>\n";
    pvd << "</Collection>\n</VTKFile>\n";
  }
} // namespace pumpd
