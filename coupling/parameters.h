// The parameters of a pumpd scene file (deal.II ParameterHandler format): declared once, with
// default, allowed range and documentation, and read into the scenes' parameter structs.
#pragma once

#include <string>

#include "full_pd.h"
#include "global_local.h"
#include "lefm_growth.h"
#include "pd_edge_crack.h"

namespace dealii
{
  class ParameterHandler;
}

namespace pumpd::coupling
{
  void declare_parameters(dealii::ParameterHandler &prm);

  /// The value of "Scene/Type".
  std::string scene_type(dealii::ParameterHandler &prm);
  /// "Scene/Output directory".
  std::string output_directory(dealii::ParameterHandler &prm);

  EdgeCrackParameters  read_edge_crack(dealii::ParameterHandler &prm);
  LefmGrowthParameters read_lefm_growth(dealii::ParameterHandler &prm);
  GlobalLocalParameters read_global_local(dealii::ParameterHandler &prm);
  FullPdParameters      read_full_pd(dealii::ParameterHandler &prm);
} // namespace pumpd::coupling
