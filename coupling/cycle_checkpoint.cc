#include "cycle_checkpoint.h"

#include <hdf5.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <stdexcept>

#include "hash.h"
#include "hdf5_array.h"
#include "output.h"

namespace pumpd::coupling
{
  namespace
  {
    void fail_if(bool bad, const std::string &what)
    {
      if (bad)
        throw std::runtime_error("cycle checkpoint: " + what);
    }

    /// HDF5 prints its error stack to stderr by default; a file that is not a checkpoint, or one
    /// that cannot be written, is reported by the exception alone.
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

    /// The datasets of a checkpoint file, as written.
    struct Datasets
    {
      std::vector<double> crack, boxes, refinements, cycle, scene;
      std::string         entries, outputs; ///< "<path> = <value>" and "<file> <length>" lines

      /// The datasets of doubles and of text, with their names, in the file's order.
      std::vector<std::pair<const char *, std::vector<double> *>> doubles()
      {
        return {{"crack", &crack}, {"boxes", &boxes}, {"refinements", &refinements}, {"cycle", &cycle}, {"scene", &scene}};
      }
      std::vector<std::pair<const char *, std::string *>> texts() { return {{"entries", &entries}, {"outputs", &outputs}}; }
    };

    /// FNV-1a of every dataset's bytes, in the file's order.
    std::uint64_t checksum(Datasets d)
    {
      std::uint64_t h = fnv1a_offset;
      for (const auto &[name, values] : d.doubles())
        h = fnv1a(std::string(reinterpret_cast<const char *>(values->data()), values->size() * sizeof(double)), h);
      for (const auto &[name, text] : d.texts())
        h = fnv1a(*text, h);
      return h;
    }

    Datasets datasets_of(const CycleState &state)
    {
      Datasets d;
      d.cycle = {double(state.exchanges), state.finished ? 1. : 0.};
      for (std::size_t c = 0; c < state.cracks.size(); ++c)
        for (const auto &p : state.cracks[c])
          d.crack.insert(d.crack.end(), {double(c), p.x, p.y});
      for (const auto &r : state.refinements)
        d.refinements.insert(d.refinements.end(), {r.at.x, r.at.y, double(r.levels)});
      for (std::size_t e = 0; e < state.ends.size(); ++e)
        {
          const auto &end = state.ends[e];
          for (const auto &b : end.boxes)
            d.boxes.insert(d.boxes.end(), {double(e), b.x_min, b.y_min, b.x_max, b.y_max});
          d.cycle.insert(d.cycle.end(), {end.load_factor, double(end.halvings), end.stopped ? 1. : 0.});
        }
      // The fingerprint as two 32-bit halves, each exact in a double.
      d.scene = {double(state.scene >> 32), double(state.scene & 0xffffffffull)};
      for (const auto &[path, value] : state.entries)
        d.entries += path + " = " + value + "\n";
      for (const auto &[file, length] : state.outputs)
        d.outputs += file + " " + std::to_string(length) + "\n";
      return d;
    }

    void write_text(hid_t file, const char *name, const std::string &text)
    {
      const hsize_t n     = text.size();
      const hid_t   space = H5Screate_simple(1, &n, nullptr);
      const hid_t   set   = H5Dcreate2(file, name, H5T_NATIVE_UCHAR, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
      const bool    bad   = set < 0 || (n > 0 && H5Dwrite(set, H5T_NATIVE_UCHAR, H5S_ALL, H5S_ALL, H5P_DEFAULT,
                                                        text.data()) < 0);
      if (set >= 0)
        H5Dclose(set);
      H5Sclose(space);
      fail_if(bad, std::string("cannot write ") + name);
    }

    std::string read_text(hid_t file, const char *name, const std::string &path)
    {
      const hid_t set = H5Dopen2(file, name, H5P_DEFAULT);
      fail_if(set < 0, path + ": no dataset " + name);
      const hid_t space = H5Dget_space(set);
      hsize_t     n     = 0;
      H5Sget_simple_extent_dims(space, &n, nullptr);
      H5Sclose(space);
      std::string text(n, '\0');
      const bool  bad = n > 0 && H5Dread(set, H5T_NATIVE_UCHAR, H5S_ALL, H5S_ALL, H5P_DEFAULT, text.data()) < 0;
      H5Dclose(set);
      fail_if(bad, path + ": cannot read " + name);
      return text;
    }

    void write_datasets(hid_t file, Datasets d)
    {
      for (const auto &[name, values] : d.doubles())
        local::hdf5::write_array(file, name, *values, "cycle checkpoint");
      for (const auto &[name, text] : d.texts())
        write_text(file, name, *text);
      local::hdf5::write_array<std::uint64_t>(file, "checksum", {checksum(d)}, "cycle checkpoint");
    }

    /// The datasets of the file, whose checksum they must match.
    Datasets read_datasets(hid_t file, const std::string &path)
    {
      const std::string context = "cycle checkpoint: " + path;
      Datasets          d;
      for (const auto &[name, values] : d.doubles())
        *values = local::hdf5::read_array<double>(file, name, context);
      for (const auto &[name, text] : d.texts())
        *text = read_text(file, name, path);
      const auto sum = local::hdf5::read_array<std::uint64_t>(file, "checksum", context, 1);
      fail_if(sum[0] != checksum(d), path + ": its contents do not match their checksum: the file is damaged");
      return d;
    }

    /// The lines of a text dataset, each split at its first `separator`.
    std::vector<std::pair<std::string, std::string>> split_lines(const std::string &text, const std::string &separator,
                                                                 const std::string &path)
    {
      std::vector<std::pair<std::string, std::string>> pairs;
      std::istringstream                               in(text);
      for (std::string line; std::getline(in, line);)
        {
          const auto at = line.find(separator);
          fail_if(at == std::string::npos, path + " is not a global-local cycle checkpoint");
          pairs.emplace_back(line.substr(0, at), line.substr(at + separator.size()));
        }
      return pairs;
    }
  } // namespace

  void write_cycle_checkpoint(const std::string &path, const CycleState &state)
  {
    const Datasets        d = datasets_of(state);
    const QuietHdf5Errors quiet;
    const std::string     partial = partial_of(path);
    errno                         = 0;
    const hid_t file              = H5Fcreate(partial.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    if (file < 0)
      write_failed(path, errno);
    bool written = true;
    try
      {
        write_datasets(file, d);
      }
    catch (const std::runtime_error &)
      {
        written = false;
      }
    const int error = errno;
    written         = H5Fclose(file) >= 0 && written;
    if (!written)
      {
        std::remove(partial.c_str());
        write_failed(path, error != 0 ? error : errno);
      }
    replace_with_partial(path);
  }

  CycleState read_cycle_checkpoint(const std::string &path)
  {
    fail_if(!std::filesystem::exists(path), path + " does not exist");
    const QuietHdf5Errors quiet;
    const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    fail_if(file < 0, "cannot open " + path);
    Datasets d;
    try
      {
        d = read_datasets(file, path);
      }
    catch (...)
      {
        H5Fclose(file);
        throw;
      }
    H5Fclose(file);
    const auto &crack = d.crack, &boxes = d.boxes, &refined = d.refinements, &cycle = d.cycle, &scene = d.scene;
    fail_if(crack.size() < 6 || crack.size() % 3 != 0 || boxes.size() % 5 != 0 || refined.size() % 3 != 0 ||
              cycle.size() < 2 || (cycle.size() - 2) % 6 != 0 || scene.size() != 2 ||
              !std::all_of(scene.begin(), scene.end(),
                           [](double half) { return half >= 0. && half < 4294967296. && half == std::floor(half); }),
            path + " is not a global-local cycle checkpoint");
    CycleState s;
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
    s.entries = split_lines(d.entries, " = ", path);
    for (const auto &[file, length] : split_lines(d.outputs, " ", path))
      s.outputs[file] = std::stoull(length);
    return s;
  }
} // namespace pumpd::coupling
