// pumpd_coupling: scenes, their parameter files and the pumpd executable (DESIGN.md, coupling/).
//
//   parameters.h          every scene parameter: declared (default, range, documentation) and read
//   pd_edge_crack.h       the PD edge-crack scene: a PD box driven by a Williams K-field
//   lefm_growth.h         LEFM crack growth in the Ingraffea beam (XFEM + maximum hoop stress, no PD)
//   global_local.h        the global-local cycle in the Ingraffea beam (XFEM drives a PD box at the tip)
//   box_policy.h          where the PD box goes: ahead of the tip, grown for holes, clipped to the body
//   exchange_controller.h the load of each exchange and how far the crack may advance in it
//   crack_extraction.h    the crack increment from a PD damage field (library pumpd_extraction)
//   cycle_checkpoint.h    the cycle's state in HDF5, to resume a run
//   path_metrics.h        distances between crack paths (mean, Hausdorff)
//   beam_scene.h          what the beam scenes share: body from the mesh, supports, files for people
#pragma once

#include "beam_scene.h"
#include "box_policy.h"
#include "crack_extraction.h"
#include "cycle_checkpoint.h"
#include "exchange_controller.h"
#include "global_local.h"
#include "lefm_growth.h"
#include "parameters.h"
#include "path_metrics.h"
#include "pd_edge_crack.h"
