#include "study_plan.h"

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <sstream>

#include "error.h"
#include "full_pd.h"
#include "parameter_table.h"
#include "study_record.h"

namespace pumpd::coupling
{
  namespace
  {
    std::string message_of(const dealii::ExceptionBase &e)
    {
      std::ostringstream info;
      e.print_info(info);
      return one_line(info.str());
    }

    /// The rungs of the study: lefm, default, the ladder's, fullpd (unless Full PD = no).
    std::vector<std::pair<Rung, std::string>> rungs_of(const StudySettings &s)
    {
      std::vector<std::pair<Rung, std::string>> rungs = {
        {{"lefm", "Type = lefm-growth", {{"Type", '=', "lefm-growth"}}}, "Ladder"}, {{"default", "", {}}, "Ladder"}};
      for (auto &r : parse_ladder(s.ladder, "Ladder"))
        {
          for (const auto &[earlier, entry] : rungs)
            if (earlier.name == r.name)
              throw InvalidParameter("Ladder", r.name + ": " + r.setting,
                                     "the name " + r.name + " is taken (lefm, default and fullpd are the study's own)");
          rungs.emplace_back(r, "Ladder");
        }
      if (s.full_pd != "no")
        {
          const std::string setting = "Type = full-pd" + (s.full_pd_settings.empty() ? "" : ", " + s.full_pd_settings);
          rungs.push_back({{"fullpd", setting, parse_overrides(setting, "Full PD settings", setting)}, "Full PD settings"});
        }
      return rungs;
    }

    /// The run's parameters read back from its scene file, and the checks of its scene (built again
    /// if the rung changes it) and its PD material: each failure one InvalidParameter naming the rung.
    void check_run(PlannedRun &run, bool own_scene, const Scene &scene)
    {
      const std::string rung = run.name() + ": " + run.rung.setting;
      try
        {
          run.parameters = parse_parameters(run.scene_text);
          if (run.method() == "pd-edge-crack")
            throw InvalidParameter("Type", run.method(), "a study compares methods that grow the scene's crack");
          const Scene  rebuilt = own_scene ? build_scene(run.parameters.scene) : Scene();
          const Scene &s       = own_scene ? rebuilt : scene;
          derive_lengths(run.parameters, s);
          check_against_scene(run.parameters, s);
          if (run.method() != "lefm-growth")
            run.parameters.pd.material(s.material);
        }
      catch (const dealii::ExceptionBase &e)
        {
          throw InvalidParameter(run.entry, rung, message_of(e));
        }
      catch (const std::exception &e)
        {
          throw InvalidParameter(run.entry, rung, e.what());
        }
    }

    /// Full PD: the lattice's estimated memory against this machine's (InvalidParameter under
    /// Full PD = yes, skipped under auto).
    void check_memory(PlannedRun &run, const Scene &scene, const std::string &full_pd)
    {
      const auto &pd                = run.parameters.pd;
      const auto [bytes, available] = full_pd_memory(scene, pd);
      run.full_pd_nodes             = scene.body.area() / (pd.spacing() * pd.spacing());
      if (bytes <= available)
        return;
      std::ostringstream why;
      why << "the full-PD run " << run.name() << " (" << run.full_pd_nodes << " nodes, spacing " << pd.spacing()
          << " m) needs about " << bytes / 1073741824. << " GiB, more than the " << available / 1073741824.
          << " GiB this machine can give it: set Full PD = auto to skip it, or a coarser Full PD settings";
      if (full_pd == "yes")
        throw InvalidParameter("Full PD", full_pd, why.str());
      run.skip = "skipped (memory)";
    }
  } // namespace

  std::vector<PlannedRun> plan_runs(const std::string &scene_file, const Scene &scene, const StudySettings &s,
                                    const std::string &directory, const std::string &program_version)
  {
    const auto              scene_table = ParameterTable::of_file(scene_file);
    std::vector<PlannedRun> plan;
    for (const auto &[rung, entry] : rungs_of(s))
      {
        ParameterTable table     = apply(scene_table, rung, "global-local", entry);
        const bool     own_scene = table.section("Scene") != scene_table.section("Scene");
        table.set("Scene/Output directory", directory + "/" + rung.name);
        PlannedRun run{rung, entry, {}, table.text("Study"), "", "", 0.};
        check_run(run, own_scene, scene);
        if (run.method() == "full-pd" && s.full_pd == "no")
          continue;
        if (run.method() == "full-pd")
          check_memory(run, scene, s.full_pd);
        run.key = run_key(program_version, run.scene_text, run.parameters.scene.mesh_file);
        plan.push_back(std::move(run));
      }
    // Full PD last, the coarse before the fine.
    std::stable_sort(plan.begin(), plan.end(), [](const PlannedRun &a, const PlannedRun &b) {
      const bool fa = a.method() == "full-pd", fb = b.method() == "full-pd";
      return fa != fb ? fb : fa && a.pd_spacing() > b.pd_spacing();
    });
    return plan;
  }
} // namespace pumpd::coupling
