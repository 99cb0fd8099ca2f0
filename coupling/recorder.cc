#include "recorder.h"

#include <filesystem>

#include "error.h"
#include "global_problem.h"
#include "output.h"
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

    [[noreturn]] void refuse_resume(const std::string &file, const std::string &what)
    {
      throw InvalidParameter("Resume", "true",
                             file + " " + what +
                               ": the output directory does not hold what the run that wrote its checkpoint wrote; "
                               "set Resume = false to start anew");
    }
  } // namespace

  Recorder::Recorder(const Scene &scene, std::optional<OutputLengths> resumed_lengths)
    : directory(scene.output_directory)
    , resumed(std::move(resumed_lengths))
  {
    if (directory.empty())
      return;
    std::filesystem::create_directories(directory);
    claim_output_directory(directory);
    write_body(path("body.csv"), scene);
    if (!scene.reference_path.empty())
      write_path(path("reference_path.csv"), scene.reference_path);
    loads = table("load_displacement.csv", "step,lambda,load,displacement,crack_length_m,tip_x_m,tip_y_m");
    global_series = std::make_unique<PvdSeries>(directory, "global");
    pd_series     = std::make_unique<PvdSeries>(directory, "pd");
    restore(*global_series);
    restore(*pd_series);
  }

  CsvFile Recorder::table(const std::string &file, const std::string &header)
  {
    if (directory.empty())
      return CsvFile();
    tables.push_back(file);
    cut_back(file);
    return CsvFile(path(file), header, resumed.has_value());
  }

  OutputLengths Recorder::lengths() const
  {
    OutputLengths lengths;
    if (!writes())
      return lengths;
    for (const auto &file : tables)
      lengths[file] = std::filesystem::file_size(path(file));
    for (const auto *series : {global_series.get(), pd_series.get()})
      lengths[std::filesystem::path(series->index()).filename().string()] = series->size();
    return lengths;
  }

  void Recorder::cut_back(const std::string &file) const
  {
    if (!resumed)
      return;
    const auto it = resumed->find(file);
    if (it == resumed->end())
      refuse_resume(path(file), "has no length in the checkpoint");
    std::error_code error;
    const auto      size = std::filesystem::file_size(path(file), error);
    if (error || size < it->second)
      refuse_resume(path(file), "holds " + (error ? std::string("nothing") : std::to_string(size) + " bytes") +
                                  ", less than the " + std::to_string(it->second) +
                                  " bytes when the checkpoint was written");
    std::filesystem::resize_file(path(file), it->second);
  }

  void Recorder::restore(PvdSeries &series) const
  {
    if (!resumed)
      return;
    const std::string name = std::filesystem::path(series.index()).filename().string();
    const auto        it   = resumed->find(name);
    if (it == resumed->end())
      refuse_resume(series.index(), "has no length in the checkpoint");
    if (const auto found = series.restore(it->second); found < it->second)
      refuse_resume(series.index(), "lists " + std::to_string(found) + " files, fewer than the " +
                                      std::to_string(it->second) + " when the checkpoint was written");
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
