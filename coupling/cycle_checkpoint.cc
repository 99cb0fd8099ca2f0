#include "cycle_checkpoint.h"

#include <hdf5.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <stdexcept>

#include "hdf5_array.h"

namespace pumpd::coupling
{
  namespace
  {
    void fail_if(bool bad, const std::string &what)
    {
      if (bad)
        throw std::runtime_error("cycle checkpoint: " + what);
    }

    void write_doubles(hid_t file, const char *name, const std::vector<double> &v)
    {
      local::hdf5::write_array(file, name, v, "cycle checkpoint");
    }

    std::vector<double> read_doubles(hid_t file, const char *name)
    {
      return local::hdf5::read_array<double>(file, name, "cycle checkpoint");
    }

    /// HDF5 prints its error stack to stderr by default; a file that is not a checkpoint is
    /// reported by the exception alone.
    class QuietHdf5Errors
    {
    public:
      QuietHdf5Errors()
      {
        H5Eget_auto2(H5E_DEFAULT, &function, &data);
        H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
      }
      ~QuietHdf5Errors() { H5Eset_auto2(H5E_DEFAULT, function, data); }

    private:
      H5E_auto2_t function = nullptr;
      void       *data     = nullptr;
    };
  } // namespace

  void write_cycle_checkpoint(const std::string &path, const CycleState &state)
  {
    // Written next to the target and renamed: an interruption never leaves half a checkpoint.
    const std::string partial = path + ".partial";
    const hid_t       file    = H5Fcreate(partial.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    fail_if(file < 0, "cannot create " + partial);
    std::vector<double> crack, boxes, refined, cycle{double(state.exchanges), state.finished ? 1. : 0.};
    for (std::size_t c = 0; c < state.cracks.size(); ++c)
      for (const auto &p : state.cracks[c])
        crack.insert(crack.end(), {double(c), p.x, p.y});
    for (const auto &r : state.refinements)
      refined.insert(refined.end(), {r.at.x, r.at.y, double(r.levels)});
    for (std::size_t e = 0; e < state.ends.size(); ++e)
      {
        const auto &end = state.ends[e];
        for (const auto &b : end.boxes)
          boxes.insert(boxes.end(), {double(e), b.x_min, b.y_min, b.x_max, b.y_max});
        cycle.insert(cycle.end(), {end.load_factor, double(end.halvings), end.stopped ? 1. : 0.});
      }
    write_doubles(file, "crack", crack);
    write_doubles(file, "boxes", boxes);
    write_doubles(file, "refinements", refined);
    write_doubles(file, "cycle", cycle);
    // The fingerprint as two 32-bit halves, each exact in a double.
    write_doubles(file, "scene", {double(state.scene >> 32), double(state.scene & 0xffffffffull)});
    H5Fclose(file);
    std::filesystem::rename(partial, path);
  }

  CycleState read_cycle_checkpoint(const std::string &path)
  {
    fail_if(!std::filesystem::exists(path), path + " does not exist");
    const QuietHdf5Errors quiet;
    const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    fail_if(file < 0, "cannot open " + path);
    CycleState          s;
    std::vector<double> crack, boxes, refined, cycle, scene;
    try
      {
        crack   = read_doubles(file, "crack");
        boxes   = read_doubles(file, "boxes");
        refined = read_doubles(file, "refinements");
        cycle   = read_doubles(file, "cycle");
        scene   = read_doubles(file, "scene");
      }
    catch (...)
      {
        H5Fclose(file);
        throw;
      }
    H5Fclose(file);
    fail_if(crack.size() < 6 || crack.size() % 3 != 0 || boxes.size() % 5 != 0 || refined.size() % 3 != 0 ||
              cycle.size() < 2 || (cycle.size() - 2) % 6 != 0 || scene.size() != 2 ||
              !std::all_of(scene.begin(), scene.end(),
                           [](double half) { return half >= 0. && half < 4294967296. && half == std::floor(half); }),
            path + " is not a global-local cycle checkpoint");
    s.ends.resize((cycle.size() - 2) / 3);
    for (std::size_t i = 0; i < crack.size(); i += 3)
      {
        const auto c = std::size_t(crack[i]);
        fail_if(c >= s.ends.size() / 2 || c > s.cracks.size(), path + " is not a global-local cycle checkpoint");
        if (c == s.cracks.size())
          s.cracks.emplace_back();
        s.cracks[c].push_back({crack[i + 1], crack[i + 2]});
      }
    for (std::size_t i = 0; i < boxes.size(); i += 5)
      {
        const auto e = std::size_t(boxes[i]);
        fail_if(e >= s.ends.size(), path + " is not a global-local cycle checkpoint");
        s.ends[e].boxes.push_back({boxes[i + 1], boxes[i + 2], boxes[i + 3], boxes[i + 4]});
      }
    for (std::size_t i = 0; i < refined.size(); i += 3)
      s.refinements.push_back({{refined[i], refined[i + 1]}, (unsigned int)(refined[i + 2])});
    s.scene     = (std::uint64_t(scene[0]) << 32) | std::uint64_t(scene[1]);
    s.exchanges = std::size_t(cycle[0]);
    s.finished  = cycle[1] != 0.;
    for (std::size_t e = 0; e < s.ends.size(); ++e)
      {
        s.ends[e].load_factor = cycle[2 + 3 * e];
        s.ends[e].halvings    = int(cycle[3 + 3 * e]);
        s.ends[e].stopped     = cycle[4 + 3 * e] != 0.;
      }
    return s;
  }
} // namespace pumpd::coupling
