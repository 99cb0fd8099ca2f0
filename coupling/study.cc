#include "study.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <map>
#include <ostream>
#include <sstream>

#include "error.h"
#include "output.h"
#include "parameters.h"
#include "program.h"
#include "study_plan.h"
#include "study_record.h"
#include "text.h"
#include "trade_table.h"

namespace pumpd::coupling
{
  namespace
  {
    namespace fs = std::filesystem;
    using Clock  = std::chrono::steady_clock;

    constexpr double unknown = std::numeric_limits<double>::quiet_NaN();

    /// Full PD: dynamic-relaxation iterations per node over a run, per lattice spacing of the
    /// body's longer side.
    constexpr double full_pd_iterations_per_spacing = 430.;
    /// Full PD at m = 4 before the default run gives its own: seconds per node-iteration.
    constexpr double full_pd_seconds_per_node_step = 1e-7;

    std::string seconds_text(double s)
    {
      if (!std::isfinite(s))
        return "unknown";
      std::ostringstream t;
      t << std::fixed << std::setprecision(0);
      if (s < 120.)
        t << s << " s";
      else if (s < 7200.)
        t << s / 60. << " min";
      else
        t << std::setprecision(1) << s / 3600. << " h";
      return t.str();
    }

    /// The study's output directory, created before any work: its own, else the scene's with
    /// /study appended.
    std::string study_directory(const Parameters &p)
    {
      if (!p.study.output_directory.empty())
        {
          make_output_directory("Study / Output directory", p.study.output_directory);
          return p.study.output_directory;
        }
      if (p.scene.output_directory.empty())
        throw InvalidParameter("Study / Output directory", "(empty)",
                               "a study writes its table and runs into a folder: give this or the scene's Output "
                               "directory (then <it>/study)");
      make_output_directory("Scene / Output directory", p.scene.output_directory + "/study");
      return p.scene.output_directory + "/study";
    }

    /// What the study knows of the finished runs (runs.csv in its output directory): by key.
    class Runs
    {
    public:
      explicit Runs(const std::string &directory)
        : file(directory + "/runs.csv")
      {
        fs::create_directories(directory);
        for (const auto &r : read_records(file))
          if (r.status != "killed")
            by_key[r.key] = r;
      }
      const RunRecord *find(const std::string &key) const
      {
        const auto it = by_key.find(key);
        return it == by_key.end() ? nullptr : &it->second;
      }
      void add(const RunRecord &r)
      {
        append_record(file, r);
        by_key[r.key] = r;
      }

    private:
      std::string                      file;
      std::map<std::string, RunRecord> by_key;
    };

    /// The estimated wall time of a run, from the runs done (the default's for the cycle, the
    /// LEFM run's for LEFM growth) and, for full PD, its node count; unknown before those ran.
    double estimate(const PlannedRun &run, const std::vector<PlannedRun> &plan, const Runs &runs, const Scene &scene)
    {
      const auto record_of = [&](const std::string &name) -> const RunRecord * {
        for (const auto &p : plan)
          if (p.name() == name)
            {
              const RunRecord *r = runs.find(p.key);
              return r && r->ok() ? r : nullptr;
            }
        return nullptr;
      };
      const auto plan_of = [&](const std::string &name) -> const PlannedRun & {
        return *std::find_if(plan.begin(), plan.end(), [&](const PlannedRun &p) { return p.name() == name; });
      };
      const RunRecord *lefm = record_of("lefm"), *cycle = record_of("default");
      if (run.method() == "lefm-growth")
        return lefm ? lefm->wall_seconds : unknown;
      if (run.method() == "full-pd")
        {
          const auto  &pd         = run.parameters.pd;
          const auto   box        = scene.body.bounding_box();
          const double node_steps = full_pd_iterations_per_spacing * run.full_pd_nodes *
                                    std::max(box.width(), box.height()) / pd.spacing();
          const double m          = pd.horizon_over_spacing;
          if (!cycle || cycle->pd_node_steps <= 0.)
            return node_steps * full_pd_seconds_per_node_step * (m * m / 16.);
          const double m_cycle = plan_of("default").parameters.pd.horizon_over_spacing;
          return node_steps * cycle->pd_seconds / cycle->pd_node_steps * (m * m) / (m_cycle * m_cycle);
        }
      if (!cycle)
        return unknown;
      // The PD work of the cycle: box nodes ((B / h)^2) times exchanges (1 / da_max).
      const auto &d = plan_of("default").parameters, &r = run.parameters;
      const double nodes     = std::pow(r.cycle.box.size / r.pd.spacing() / (d.cycle.box.size / d.pd.spacing()), 2);
      const double exchanges = d.cycle.exchange.max_advance / r.cycle.exchange.max_advance;
      return cycle->wall_seconds - cycle->pd_seconds + cycle->pd_seconds * nodes * exchanges;
    }

    /// Runs one planned run as a child process and records it.
    RunRecord execute(const PlannedRun &run, const std::string &executable, const std::string &directory)
    {
      const std::string prm = directory + "/" + run.name() + ".prm", log = directory + "/" + run.name() + ".log";
      fs::remove_all(directory + "/" + run.name());
      std::ofstream(prm) << "# " << run.name() << ": " << (run.rung.setting.empty() ? "the scene's settings" : run.rung.setting)
                         << " (written by pumpd --study)\n"
                         << run.scene_text;
      const ProgramRun child = run_program({executable, prm}, log);
      if (child.start_error != 0)
        throw std::runtime_error("cannot start " + executable + ": " + std::strerror(child.start_error));
      auto       metrics = read_metrics(log);
      const auto metric  = [&](const char *a, const char *b) { return metrics.count(a) ? metrics[a] : metrics[b]; };
      RunRecord  r;
      r.run           = run.name();
      r.key           = run.key;
      r.method        = run.method();
      r.status        = child.exit_code == 0 ? "ok" : child.exit_code < 0 ? "killed" : "exit " + std::to_string(child.exit_code);
      r.wall_seconds  = child.seconds;
      r.peak_memory   = child.peak_memory;
      r.pd_node_steps = metric("coupling.pd_node_steps", "fullpd.node_steps");
      r.global_dofs   = metric("coupling.global_dofs", "lefm.global_dofs");
      r.pd_seconds    = metric("coupling.seconds_pd", "fullpd.seconds_total");
      return r;
    }

    /// Draws trade.png (scripts/plot_trade.py, python3 with matplotlib); false, with a note, if it
    /// cannot.
    bool plot(const std::string &directory, std::ostream &out)
    {
      const std::string script = std::string(PUMPD_SCRIPTS_DIR) + "/plot_trade.py";
      const ProgramRun run = run_program({"/usr/bin/python3", script, directory}, directory + "/plot.log");
      if (run.start_error != 0)
        out << "study: no trade.png: /usr/bin/python3 could not be started (" << std::strerror(run.start_error) << ")"
            << std::endl;
      else if (run.exit_code != 0)
        out << "study: no trade.png: " << last_line(directory + "/plot.log") << std::endl;
      return run.exit_code == 0;
    }

    /// trade.png of the table, drawn unless it shows this table already: plotted.csv is the table
    /// (without its `reused` flags) of the last plot drawn, as when a study reuses every run.
    void plot_if_changed(TradeTable table, const std::string &directory, std::ostream &out)
    {
      for (auto &r : table.rows)
        r.reused = false;
      const std::string plotted = directory + "/plotted.csv", fresh = plotted + ".new";
      write_csv(table, fresh);
      if (fs::exists(directory + "/trade.png") && file_contents(plotted) == file_contents(fresh))
        {
          fs::remove(fresh);
          return;
        }
      fs::remove(plotted);
      if (plot(directory, out))
        fs::rename(fresh, plotted);
      else
        fs::remove(fresh);
    }

    /// The study's figures; the loads named after the scene file's stem (loads.<stem>.*).
    void print_metrics(const TradeTable &t, const std::string &scene_file, std::ostream &out)
    {
      const auto row = [&](const std::string &name) -> const TradeRow * {
        for (const auto &r : t.rows)
          if (r.record.run == name && r.record.ok() && r.path.size() >= 2)
            return &r;
        return nullptr;
      };
      const TradeRow *lefm = row("lefm"), *cycle = row("default"), *full = t.full_pd ? &t.rows[*t.full_pd] : nullptr;
      if (cycle && full)
        out << "pumpd-metric trade.coupled_over_fullpd_time " << cycle->record.wall_seconds / full->record.wall_seconds
            << "\npumpd-metric trade.coupled_vs_fullpd_mean_dev_mm " << 1e3 * cycle->from_full_pd->mean << "\n";
      if (cycle && lefm)
        out << "pumpd-metric trade.coupled_over_lefm_time " << cycle->record.wall_seconds / lefm->record.wall_seconds
            << "\npumpd-metric trade.lefm_vs_coupled_mean_dev_mm "
            << 1e3 * trade_distance(lefm->path, cycle->path).mean << "\n";
      // The cycle's predicted loads (the onsets of growth in its boxes) against full PD's and LEFM's.
      const std::string loads = "pumpd-metric loads." + fs::path(scene_file).stem().string() + ".";
      const auto        rel   = [](double a, double b) { return a / b - 1.; };
      if (cycle && full && std::isfinite(cycle->first_growth_load) && std::isfinite(full->first_growth_load))
        out << loads << "first_growth_vs_fullpd_rel " << rel(cycle->first_growth_load, full->first_growth_load) << "\n"
            << loads << "peak_vs_fullpd_rel " << rel(cycle->peak_load, full->peak_load) << "\n";
      if (cycle && lefm && std::isfinite(cycle->first_growth_load) && std::isfinite(lefm->first_growth_load))
        out << loads << "first_growth_vs_lefm_rel " << rel(cycle->first_growth_load, lefm->first_growth_load) << "\n";
      if (t.recommended && t.finest)
        out << "pumpd-metric study.recommended_mean_vs_finest_mm " << 1e3 * t.rows[*t.recommended].from_finest->mean
            << "\n";
      out << std::flush;
    }

    /// The scene, its .geo meshed once for the study and its runs: the mesh cache
    /// (PUMPD_MESH_CACHE, global/mesh.h), unless the user set one, is the study's meshes/, and the
    /// runs inherit it.
    Scene build_scene_through_cache(const SceneSettings &settings, const std::string &directory, std::ostream &out)
    {
      ::setenv("PUMPD_MESH_CACHE", (directory + "/meshes").c_str(), 0);
      return build_scene(settings, &out);
    }

    /// A study under way: the scene, the runs planned, those recorded; each planned run taken in
    /// turn (reused, skipped or run), with its progress lines.
    class Study
    {
    public:
      /// Reads the scene file and plans the runs: every check before any run.
      Study(const std::string &scene_file, const std::string &executable, std::ostream &out)
        : parameters(read_parameters(scene_file))
        , directory(study_directory(parameters))
        , scene(build_scene_through_cache(parameters.scene, directory, out))
        , executable(executable)
        , version(program_version(executable))
        , plan(plan_runs(scene_file, scene, parameters.study, directory, version))
        , runs(directory)
        , out(out)
      {
        // Planned and checked: the study writes from here on (its runs lock their own directories).
        claim_output_directory(directory);
        out << "study: " << scene_file << ", " << plan.size() << " runs into " << directory << " (program "
            << version << ")" << std::endl;
      }

      std::size_t size() const { return plan.size(); }
      std::size_t reused() const { return n_reused; }
      double      seconds() const { return std::chrono::duration<double>(Clock::now() - t0).count(); }
      const std::string &output_directory() const { return directory; }
      double             tolerance() const { return parameters.study.tolerance; }

      /// The planned run i: reused if recorded, skipped if it may not run, else run now.
      TradeRow take(std::size_t i)
      {
        const PlannedRun &run = plan[i];
        TradeRow          row;
        row.setting    = run.rung.setting;
        row.pd_spacing = run.pd_spacing();
        const double eta = estimate(run, plan, runs, scene);
        out << "study: run " << i + 1 << "/" << plan.size() << " " << run.name() << " ("
            << (run.rung.setting.empty() ? "the scene's settings" : run.rung.setting) << ")";
        if (const RunRecord *done = runs.find(run.key))
          {
            row.record = *done;
            row.reused = true;
            ++n_reused;
            out << ": reused (" << done->status << ", " << seconds_text(done->wall_seconds) << " when it ran)"
                << std::endl;
          }
        else if (const std::string why = skip_reason(run, eta); !why.empty())
          {
            row.record = {run.name(), run.key, run.method(), why};
            out << ": " << why << ", estimated " << seconds_text(eta) << std::endl;
            return row;
          }
        else
          row.record = execute_with_progress(i, eta);
        read_run_output(directory + "/" + run.name(), row);
        return row;
      }

    private:
      /// "" if the run may start: not skipped by the plan, and its estimated end within the time limit.
      std::string skip_reason(const PlannedRun &run, double eta) const
      {
        const double limit = parameters.study.time_limit;
        if (run.skip.empty() && limit > 0. && std::isfinite(eta) && seconds() + eta > limit)
          return "skipped (time limit)";
        return run.skip;
      }

      /// The estimated time of the runs from i on that are neither recorded nor skipped.
      double eta_from(std::size_t i) const
      {
        double eta = 0.;
        for (std::size_t j = i; j < plan.size(); ++j)
          if (!runs.find(plan[j].key) && plan[j].skip.empty())
            eta += estimate(plan[j], plan, runs, scene);
        return eta;
      }

      RunRecord execute_with_progress(std::size_t i, double eta)
      {
        const PlannedRun &run = plan[i];
        out << ": started, ETA " << seconds_text(eta) << ", study ETA " << seconds_text(eta_from(i));
        if (run.method() == "full-pd")
          out << " (full PD: about " << std::setprecision(3) << run.full_pd_nodes << " nodes)" << std::setprecision(6);
        out << std::endl;
        const RunRecord record = execute(run, executable, directory);
        runs.add(record);
        out << "study: " << run.name() << ": " << record.status << ", " << seconds_text(record.wall_seconds) << ", "
            << std::fixed << std::setprecision(0) << record.peak_memory << " MiB" << std::defaultfloat
            << std::setprecision(6);
        if (!record.ok())
          out << ": " << last_line(directory + "/" + run.name() + ".log");
        out << std::endl;
        return record;
      }

      const Clock::time_point       t0 = Clock::now();
      const Parameters              parameters;
      const std::string             directory;
      const Scene                   scene;
      const std::string             executable, version;
      const std::vector<PlannedRun> plan;
      Runs                          runs;
      std::ostream                 &out;
      std::size_t                   n_reused = 0;
    };
  } // namespace

  void run_study(const std::string &scene_file, const std::string &executable, std::ostream &out)
  {
    Study                 study(scene_file, executable, out);
    std::vector<TradeRow> rows;
    for (std::size_t i = 0; i < study.size(); ++i)
      rows.push_back(study.take(i));

    const std::string directory = study.output_directory();
    const TradeTable  table     = judge(std::move(rows), study.tolerance());
    write_csv(table, directory + "/trade.csv");
    write_markdown(table, scene_file, directory + "/trade.md");
    plot_if_changed(table, directory, out);
    out << "study: trade.csv, trade.md, trade.png in " << directory << "\n"
        << "pumpd-metric study.runs " << study.size() << "\n"
        << "pumpd-metric study.reused " << study.reused() << "\n"
        << "pumpd-metric study.seconds " << study.seconds() << "\n";
    print_metrics(table, scene_file, out);
    out << "study: recommended: " << recommendation(table) << std::endl;
  }
} // namespace pumpd::coupling
