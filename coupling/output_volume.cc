#include "output_volume.h"

#include <sys/statvfs.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "error.h"
#include "parameters.h"
#include "vtu.h"

namespace pumpd::coupling
{
  namespace
  {
    /// A PD state's file: per node its displacement (3) and damage, stretch ratio, energy density
    /// and boundary layer, as a vertex cell (local/vtu_output.h).
    double pd_file_bytes(double nodes) { return vtu_bytes(nodes, nodes, 1, 7, 0, 0); }

    /// A global solution's file: each cell a quadrilateral of its own corners, with their
    /// displacement (3), and its stress (3), von Mises stress and enrichment kind (global/'s
    /// write_vtu; a cut cell's triangles are few against the mesh).
    double global_file_bytes(double cells) { return vtu_bytes(4. * cells, cells, 4, 3, 4, 1); }

    /// The memory of the edge crack's PD box (pd_edge_crack.h: the tip at its centre).
    local::ModelMemory edge_crack_memory(const Parameters &p)
    {
      const double                half = 0.5 * p.edge_crack.box_size;
      const local::Lattice        grid({-half, -half, half, half}, p.pd.spacing(), p.pd.horizon_over_spacing);
      const local::LiptonMaterial material(p.pd.material(p.scene.material), p.pd.horizon);
      return local::model_memory(grid, local::make_half_stencil(p.pd.horizon_over_spacing, material));
    }

    bool fits(const local::ModelMemory &memory) { return memory.needed <= memory.available; }

    /// Files written every `interval` of `steps` steps, and the last.
    double series_files(double steps, unsigned int interval) { return std::floor(steps / interval) + 1.; }

    std::string entry(const std::string &name, double value) { return name + " = " + to_text(value); }

    std::size_t initial_tips(const Scene &scene)
    {
      std::size_t tips = 0;
      for (const auto &crack : enriched_cracks(scene.cracks, scene))
        tips += crack.tips().size();
      return std::max<std::size_t>(tips, 1);
    }

    /// The exchanges at most: Maximum exchanges, and with Maximum crack length the exchanges that
    /// grow it there by at least the minimum advance each (every exchange that does not stop the
    /// run grows a tip by that much, or grows a tip to where it stops).
    double global_local_exchanges(const Parameters &p, const Scene &scene, std::size_t tips)
    {
      double exchanges = p.cycle.max_exchanges;
      if (p.growth.max_crack_length > 0.)
        {
          double length = 0.;
          for (const auto &crack : scene.cracks)
            length += geometry::length(crack);
          const double growing = std::ceil(std::max(0., p.growth.max_crack_length - length) /
                                           std::max(p.cycle.exchange.min_advance, 1e-300));
          exchanges = std::min(exchanges, growing + double(tips));
        }
      return exchanges;
    }

    /// The free space of the file system of `directory` or of its nearest existing parent [bytes].
    double free_bytes(std::filesystem::path directory)
    {
      std::error_code error;
      while (!directory.empty() && !std::filesystem::exists(directory, error))
        directory = directory.has_parent_path() && directory.parent_path() != directory ? directory.parent_path()
                                                                                        : std::filesystem::path();
      struct statvfs fs;
      if (statvfs(directory.empty() ? "." : directory.c_str(), &fs) != 0)
        return INFINITY;
      return double(fs.f_bavail) * double(fs.f_frsize);
    }

    std::string size_text(double bytes)
    {
      const char *units[] = {"bytes", "kB", "MB", "GB", "TB", "PB", "EB"};
      int         u       = 0;
      for (; bytes >= 1000. && u < 6; ++u)
        bytes /= 1000.;
      return to_text(bytes, 3) + " " + units[u];
    }
  } // namespace

  OutputVolume estimated_output(const Parameters &p, const Scene *scene)
  {
    OutputVolume v;
    if (p.method == "pd-edge-crack")
      {
        const double side = std::floor(p.edge_crack.box_size / p.pd.spacing()) + 1.;
        v.output_interval = p.edge_crack.output_interval;
        v.files           = series_files(p.edge_crack.load_steps, v.output_interval);
        v.bytes_per_file  = pd_file_bytes(side * side);
        v.limits          = entry("Load steps", p.edge_crack.load_steps);
        v.held            = fits(edge_crack_memory(p));
      }
    else if (p.method == "full-pd")
      {
        v.output_interval = p.full_pd.output_interval;
        v.files           = series_files(p.full_pd.max_steps, v.output_interval);
        v.bytes_per_file  = pd_file_bytes(scene->body.area() / (p.pd.spacing() * p.pd.spacing()));
        v.limits          = entry("Maximum steps", p.full_pd.max_steps);
        v.held            = fits(full_pd_memory(*scene, p.pd));
      }
    else if (p.method == "lefm-growth")
      {
        v.output_interval = p.lefm.output_interval;
        v.files           = series_files(p.lefm.max_steps, v.output_interval);
        v.bytes_per_file  = global_file_bytes(estimated_cells(*scene, p.global));
        v.limits          = entry("Maximum steps", p.lefm.max_steps);
      }
    else
      {
        // Per written exchange the global solution and a PD state per box (a box per tip at most).
        const std::size_t tips  = initial_tips(*scene);
        const double      nodes = std::pow(p.cycle.box.size / p.pd.spacing(), 2);
        v.output_interval       = p.cycle.output_interval;
        v.files                 = series_files(global_local_exchanges(p, *scene, tips), v.output_interval);
        v.bytes_per_file =
          global_file_bytes(estimated_cells(*scene, p.global)) + double(tips) * pd_file_bytes(nodes);
        v.limits = entry("Maximum exchanges", p.cycle.max_exchanges) +
                   (p.growth.max_crack_length > 0. ? ", " + entry("Maximum crack length", p.growth.max_crack_length)
                                                   : "");
      }
    return v;
  }

  void check_output_volume(const Parameters &p, const Scene *scene, const std::string &directory)
  {
    if (directory.empty())
      return;
    const OutputVolume v    = estimated_output(p, scene);
    const double       free = free_bytes(directory);
    if (!v.held || v.bytes() <= 0.5 * free)
      return;
    throw InvalidParameter("Output interval", std::to_string(v.output_interval),
                           "with " + v.limits + " the run would write about " + size_text(v.bytes()) +
                             " of VTU files (" + to_text(v.files, 3) + " of about " + size_text(v.bytes_per_file) +
                             "), more than half of the " + size_text(free) + " free in " + directory +
                             ": write less often (a larger Output interval) or fewer steps");
  }
} // namespace pumpd::coupling
