// pumpd_coupling: scenes, their parameter files and the pumpd executable (DESIGN.md, coupling/).
//
//   parameters.h      every scene parameter: declared (default, range, documentation) and read
//   pd_edge_crack.h   the PD edge-crack scene: a PD box driven by a Williams K-field
//
// The global-local cycle (box policy, boundary transfer, crack extraction, exchange control)
// joins here once the global solver exists.
#pragma once

#include "parameters.h"
#include "pd_edge_crack.h"
