#include "recorder.h"

#include <filesystem>

#include "global_problem.h"
#include "vtu_output.h"

namespace pumpd::coupling
{
  namespace
  {
    void write_path(const std::string &file, const geometry::Polyline &path)
    {
      CsvFile out(file, "x_m,y_m");
      for (const auto &p : path)
        out.row(p.x, p.y);
    }

    /// body.csv: one row per point of each boundary curve (arcs sampled), then the named points
    /// of the conditions: curve,x_m,y_m with curve "outline", "hole<k>" or "point:<name>".
    void write_body(const std::string &file, const Scene &scene)
    {
      CsvFile out(file, "curve,x_m,y_m");
      for (const auto &p : scene.body.outline().sampled(0.05))
        out.row("outline", p.x, p.y);
      for (std::size_t k = 0; k < scene.body.holes().size(); ++k)
        for (const auto &p : scene.body.holes()[k].sampled(0.05))
          out.row("hole" + std::to_string(k), p.x, p.y);
      const auto points = [&](const conditions::Place &place) {
        if (place.kind == conditions::Place::Kind::point)
          for (const auto &p : place.points)
            out.row("point:" + place.name, p.x, p.y);
      };
      for (const auto &d : scene.conditions.displacements)
        points(d.place);
      for (const auto &f : scene.conditions.forces)
        points(f.place);
    }
  } // namespace

  Recorder::Recorder(const Scene &scene, bool resume_run)
    : directory(scene.output_directory)
    , resume(resume_run)
  {
    if (directory.empty())
      return;
    std::filesystem::create_directories(directory);
    write_body(path("body.csv"), scene);
    if (!scene.reference_path.empty())
      write_path(path("reference_path.csv"), scene.reference_path);
    loads = table("load_displacement.csv", "step,lambda,load,displacement,crack_length_m,tip_x_m,tip_y_m");
    global_series = std::make_unique<PvdSeries>(directory, "global");
    pd_series     = std::make_unique<PvdSeries>(directory, "pd");
  }

  CsvFile Recorder::table(const std::string &file, const std::string &header) const
  {
    return directory.empty() ? CsvFile() : CsvFile(path(file), header, resume);
  }

  void Recorder::crack_path(const geometry::Polyline &crack) const
  {
    if (writes())
      write_path(path("crack_path.csv"), crack);
  }

  void Recorder::crack_paths(const std::vector<geometry::Polyline> &cracks) const
  {
    if (!writes())
      return;
    for (std::size_t k = 0; k < cracks.size(); ++k)
      write_path(path(k == 0 ? "crack_path.csv" : "crack_path_" + std::to_string(k + 1) + ".csv"), cracks[k]);
  }

  void Recorder::load_displacement(std::size_t step, double lambda, double load, double displacement,
                                   double crack_length, geometry::Point tip)
  {
    loads.row(step, lambda, load, displacement, crack_length, tip.x, tip.y);
  }

  void Recorder::global_state(const GlobalProblem &global, double time)
  {
    if (!writes())
      return;
    const std::string file = global_series->next_file();
    global.write_vtu(path(file));
    global_series->add(time, file);
  }

  void Recorder::pd_state(const local::PdModel &model, const local::State &s)
  {
    if (writes())
      local::write_vtu(*pd_series, model, s);
  }
} // namespace pumpd::coupling
