#include "study_settings.h"

#include <deal.II/base/parameter_handler.h>

namespace pumpd::coupling
{
  void StudySettings::add_parameters(dealii::ParameterHandler &prm)
  {
    namespace Patterns = dealii::Patterns;
    prm.enter_subsection("Study");
    prm.add_parameter("Ladder", ladder,
                      "The settings of the global-local cycle `pumpd --study` runs besides the scene's own: rungs "
                      "separated by ';', each '<name>: <override>, <override>, ...'. An override changes one entry of "
                      "this file: '<entry> = <value>', '<entry> x <factor>' (a number times the scene's value) or "
                      "'<entry> + <n>' / '<entry> - <n>' (an integer entry). <entry> is the entry's name, or "
                      "'<section>/<entry>' where the sections the rung's method reads have several entries of that "
                      "name. 'Type = full-pd' or 'Type = lefm-growth' makes a rung of another method. The study also "
                      "runs 'lefm' (Type = lefm-growth), 'default' (the scene's global-local settings) and 'fullpd' "
                      "(see Full PD).",
                      Patterns::Anything());
    prm.add_parameter("Tolerance", tolerance,
                      "The recommended setting is the cheapest (wall time) whose crack path lies within this mean "
                      "distance [m] of the finest run's (the global-local run with the smallest PD spacing).",
                      Patterns::Double(1e-300));
    prm.add_parameter("Full PD", full_pd,
                      "Run the scene by full PD too (and the ladder's rungs of Type = full-pd), the reference of the "
                      "trade. yes: stop before anything runs if its estimated memory exceeds this machine's; auto: "
                      "skip it then; either skips it where its estimated time does not fit the time limit; no: never.",
                      Patterns::Selection("auto|yes|no"));
    prm.add_parameter("Full PD settings", full_pd_settings,
                      "Overrides of the full-PD run, as in a rung of the ladder (e.g. 'Horizon over spacing = 4').",
                      Patterns::Anything());
    prm.add_parameter("Time limit", time_limit,
                      "No run starts whose estimated end lies beyond this many seconds after the study started (it is "
                      "named as skipped; run the study again with a larger limit: the runs done are reused); 0: none.",
                      Patterns::Double(0.));
    prm.add_parameter("Output directory", output_directory,
                      "Where the study writes its runs (<run>.prm, <run>.log, <run>/), runs.csv, trade.csv, trade.md "
                      "and trade.png; empty: <the scene's output directory>/study.",
                      Patterns::Anything());
    prm.leave_subsection();
  }
} // namespace pumpd::coupling
