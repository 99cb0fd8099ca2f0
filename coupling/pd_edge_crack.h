// The PD demonstration scene and validation 4: a square PD box around the tip of an edge crack,
// its boundary layer driven by the Williams mode-I field of a stress intensity factor K that
// rises in load steps (dynamic relaxation at each). The box is exactly what the coupling cycle
// drives, with the global solution replaced by the LEFM field it converges to.
//
// Measured: the K at which the crack starts to grow (compared with K_c = sqrt(E' G_c)) and how far
// the grown crack strays from the symmetry line.
#pragma once

#include <cstddef>
#include <iosfwd>
#include <string>
#include <vector>

#include "geometry.h"
#include "material.h"
#include "pd_settings.h"

namespace dealii
{
  class ParameterHandler;
}

namespace pumpd::coupling
{
  /// The section `Edge crack`.
  struct EdgeCrackSettings
  {
    double       box_size        = 0.096; ///< side of the square box [m]; the tip sits at its centre
    double       k_start         = 0.6;   ///< first K / K_c
    double       k_end           = 1.4;   ///< last K / K_c
    unsigned int load_steps      = 17;
    double       growth_to_stop  = 0.;    ///< stop once the crack grew this far [m] (0: run all steps)
    unsigned int output_interval = 1;     ///< VTU every n load steps

    void add_parameters(dealii::ParameterHandler &prm);
  };

  struct EdgeCrackParameters
  {
    local::MaterialParameters material;
    PeridynamicsSettings      pd;
    EdgeCrackSettings         edge;
    std::string               output_directory; ///< "" = no files
  };

  struct EdgeCrackStep
  {
    double      k_over_kc  = 0.;
    double      extension  = 0.; ///< crack growth beyond the initial tip [m]
    double      max_damage = 0.;
    std::size_t iterations = 0;
    double      seconds    = 0.;
  };

  struct EdgeCrackResult
  {
    std::vector<EdgeCrackStep>   steps;
    double                       onset_k_over_kc = 0.; ///< first K with growth >= 2 h (0: none)
    std::vector<geometry::Point> crack_nodes;          ///< nodes on the crack ahead of the initial tip
    double                       max_offset      = 0.; ///< largest |y| of those nodes [m]
    double                       spacing         = 0.;
  };

  /// Throws InvalidParameter for inconsistent parameters (see the .cc for the ranges).
  EdgeCrackResult run_edge_crack(const EdgeCrackParameters &parameters, std::ostream &progress);
} // namespace pumpd::coupling
