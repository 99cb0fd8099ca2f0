// pumpd_coupling: scenes, their parameter files and the pumpd executable (DESIGN.md, coupling/).
//
//   parameters.h      every scene parameter: declared (default, range, documentation) and read
//   pd_edge_crack.h   the PD edge-crack scene: a PD box driven by a Williams K-field
//   lefm_growth.h     LEFM crack growth in the Ingraffea beam (XFEM + maximum hoop stress, no PD)
//
// The global-local cycle (box policy, boundary transfer, crack extraction, exchange control)
// joins here once the global solver exists.
#pragma once

#include "lefm_growth.h"
#include "parameters.h"
#include "pd_edge_crack.h"
