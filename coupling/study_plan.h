// The runs of a study (study.h), planned and checked before any starts: lefm, default, the
// ladder's rungs, fullpd (unless Full PD = no), each with the scene file it runs and its key.
// Checked: every run's scene file (each value against its range; the scene built again where a
// rung changes it; the PD material), and full PD's memory (the lattice's estimate against this
// machine's: refused under Full PD = yes, skipped under auto). Full-PD runs come last, the coarse
// before the fine.
#pragma once

#include <string>
#include <vector>

#include "ladder.h"
#include "parameters.h"
#include "scene.h"

namespace pumpd::coupling
{
  /// One run of the study, planned: its rung, the Study entry it comes from, its scene file.
  struct PlannedRun
  {
    Rung        rung;
    std::string entry;
    Parameters  parameters;
    std::string scene_text;
    std::string key;
    std::string skip; ///< why it does not run ("": it runs)
    double      full_pd_nodes = 0.;

    const std::string &name() const { return rung.name; }
    const std::string &method() const { return parameters.method; }
    double pd_spacing() const { return method() == "lefm-growth" ? 0. : parameters.pd.spacing(); }
  };

  /// The runs of the study of `scene_file` (whose scene is `scene`), their outputs under
  /// `directory`, their keys with `program_version`. Throws InvalidParameter naming the Study
  /// entry and the rung for each failed check.
  std::vector<PlannedRun> plan_runs(const std::string &scene_file, const Scene &scene, const StudySettings &s,
                                    const std::string &directory, const std::string &program_version);
} // namespace pumpd::coupling
