// The section `Study` of a scene file: what `pumpd --study <scene.prm>` runs and how it judges the
// runs (study.h). A single run (`pumpd <scene.prm>`) reads the section and ignores it, so one file
// describes the scene and its study.
#pragma once

#include <string>

namespace dealii
{
  class ParameterHandler;
}

namespace pumpd::coupling
{
  struct StudySettings
  {
    /// The global-local settings the study tries besides the scene's own (ladder.h): rungs
    /// "<name>: <override>, <override>, ..." separated by ";", an override "<entry> = <value>",
    /// "<entry> x <factor>" or "<entry> + <n>" / "<entry> - <n>".
    std::string ladder =
      "horizon-half: Horizon x 0.5, Minimum advance x 0.5; "
      "horizon-double: Horizon x 2, Box size x 2, Maximum box size x 2, Box margin x 2, Maximum advance x 2, "
      "Minimum advance x 2, Near distance x 2; "
      "m4: Horizon over spacing = 4; "
      "box-large: Box size x 1.5, Maximum box size x 1.5; "
      "advance-half: Maximum advance x 0.5, Minimum advance x 0.5; "
      "refinement-plus-1: Refinement levels near the tip + 1; "
      "refinement-minus-1: Refinement levels near the tip - 1";
    double      tolerance        = 0.001; ///< a setting within this mean path distance of the finest run qualifies [m]
    std::string full_pd          = "auto"; ///< auto | yes | no
    std::string full_pd_settings = "";     ///< overrides of the full-PD run, as in a rung
    double      time_limit       = 3600.;  ///< [s]; 0: none
    std::string output_directory = "";     ///< "": <the scene's output directory>/study

    void add_parameters(dealii::ParameterHandler &prm);
  };
} // namespace pumpd::coupling
