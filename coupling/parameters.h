// Every parameter of a pumpd scene file (deal.II ParameterHandler format). Each section is
// declared by the settings struct that owns it (ParameterHandler::add_parameter, deal.II
// step-69): the struct's value is the only default, the pattern the only range.
//   Method               Type: which method computes the scene
//   Scene                the specimen: mesh, material, boundary conditions, cracks, report (scene.h)
//   Global               XFEM (global_problem.h)
//   Peridynamics         the PD body (pd_settings.h)
//   Crack growth         where growth stops (growth_settings.h)
//   Initiation           where a crack would start in a scene without one (initiation.h)
//   LEFM growth, Global-local, Full PD, Edge crack   each method's own
//   Study                what pumpd --study runs (study_settings.h)
#pragma once

#include <iosfwd>
#include <string>

#include "full_pd.h"
#include "global_local.h"
#include "initiation.h"
#include "lefm_growth.h"
#include "pd_edge_crack.h"
#include "scene.h"
#include "study_settings.h"

namespace dealii
{
  class ParameterHandler;
}

namespace pumpd::coupling
{
  struct Parameters
  {
    std::string           method = "global-local";
    SceneSettings         scene;
    GlobalSettings        global;
    PeridynamicsSettings  pd;
    GrowthSettings        growth;
    InitiationSettings    initiation;
    LefmSettings          lefm;
    CycleSettings         cycle;
    FullPdControlSettings full_pd;
    EdgeCrackSettings     edge_crack;
    StudySettings         study; ///< read by pumpd --study only (study.h)

    void add_parameters(dealii::ParameterHandler &prm);

    LefmGrowthSettings  lefm_growth_settings() const { return {global, growth, lefm}; }
    GlobalLocalSettings global_local_settings() const { return {global, pd, growth, cycle}; }
    FullPdSettings      full_pd_settings() const { return {pd, growth, full_pd}; }
  };

  /// The parameters of a scene file. Throws deal.II's exceptions for a malformed file, an unknown
  /// entry or a value outside its pattern (each names the entry).
  Parameters read_parameters(const std::string &file);
  /// The same from the text of a scene file (tests).
  Parameters parse_parameters(const std::string &text);

  /// Under Scene/Length defaults = scene, every length entry the scene file did not set
  /// (scene_lengths.h) derived from the scene's lengths; with `out`, a line that gives them and the
  /// lengths they come from. run() and a study's planning call it before check_against_scene.
  void derive_lengths(Parameters &parameters, const Scene &scene, std::ostream *out = nullptr);

  /// The checks of the settings against the built scene that no single section can make (the
  /// hole margin against the body, the tip enrichment radius against the boundary, the refined
  /// mesh against Maximum cells, the output against the free disk: output_volume.h):
  /// InvalidParameter naming the entry. run() and a study's planning call it.
  void check_against_scene(const Parameters &parameters, const Scene &scene);

  /// Runs the method on the scene: builds the scene from the mesh, then calls run_lefm_growth,
  /// run_global_local, run_full_pd or run_edge_crack. Progress and a closing line to `out`. A
  /// scene without a crack: global-local nucleates one at the first initiation site and grows it
  /// (nucleation.h), full PD forms and traces its own; LEFM growth, which has no law for a crack
  /// to start, prints the initiation sites (initiation.h) and stops with InvalidParameter naming
  /// "Initial cracks".
  void run(const Parameters &parameters, std::ostream &out);
} // namespace pumpd::coupling
