// The speed/accuracy trade of a scene, as one command: `pumpd --study <scene.prm>`.
// The scene file is the input as for a single run; its section `Study` (study_settings.h) says
// what to try. The study runs, each as a child process of the same executable on a scene file it
// writes into the study's output directory:
//   lefm      the scene by LEFM growth (Type = lefm-growth)
//   default   the scene by the global-local cycle, its settings as they are
//   <rung>    the cycle at each rung of the ladder (ladder.h)
//   fullpd    the scene by full PD, with the Full PD settings (and rungs of Type = full-pd), where
//             its estimated memory and time fit (Full PD = auto | yes | no)
// and per run measures the wall time and the peak memory (wait4), reads the PD node-steps and the
// global DoFs from its pumpd-metric lines and the crack path and loads from its files, and writes
// trade.csv, trade.md, trade.png (scripts/plot_trade.py) and the recommended setting
// (trade_table.h). Each run's row goes to runs.csv as soon as it ends; a run whose key (the
// program version, its scene file, its mesh: study_record.h) is recorded there is reused, so a
// study interrupted or extended runs only what is new.
// Before any run starts the study checks every run's scene file (each mistake one message naming
// the rung), the full-PD memory, and the study's own entries.
#pragma once

#include <iosfwd>
#include <string>

namespace pumpd::coupling
{
  /// The study of `scene_file`, each run by `executable` (pumpd). Progress, the recommendation and
  /// pumpd-metric lines to `out`, line by line. Throws InvalidParameter or deal.II's exceptions
  /// for bad input, before any run.
  void run_study(const std::string &scene_file, const std::string &executable, std::ostream &out);
} // namespace pumpd::coupling
