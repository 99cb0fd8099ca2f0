// pumpd_coupling: the scene, the methods that compute it, their parameters and the pumpd
// executable (DESIGN.md, coupling/).
//
//   scene.h               the specimen from the .prm and its mesh: body, conditions, cracks, report
//   parameters.h          every section of a scene file, and run(): the method on the scene
//     parameter_file.h      what deal.II does not check in a scene file: includes, entries set twice
//   global_problem.h      XFEM on the whole body: tip states per unit load, the critical load
//   initiation.h          where a crack starts in a body without one: the PD strength against sigma_1
//   lefm_growth.h         LEFM crack growth (XFEM + maximum hoop stress, no PD)
//   global_local.h        the global-local cycle: XFEM drives a PD box at the tip
//     resolution.h          the horizon of each box, chosen by the clearance and the holes ahead
//     box_policy.h          where the PD box goes: ahead of the tip, grown for holes, clipped
//     boundary_transfer.h   the mapping: the global displacement onto a box's nodes
//     exchange.h            the scheme: PD states along the load, judged by the controller
//     exchange_controller.h the load of each exchange and how far the crack may advance in it
//     crack_extraction.h    the crack increment from a PD damage field (library pumpd_extraction)
//     cycle_checkpoint.h    the cycle's state in HDF5, to resume a run
//   full_pd.h             the whole body as one PD body
//   pd_edge_crack.h       the PD co-solver's check: a box driven by a Williams K-field
//   pd_settings.h, growth_settings.h   sections shared by the methods
//   arrival.h             where a growing crack ends: a hole or the outline
//   recorder.h            the files of a run (CSV, VTU/PVD, body, paths)
//   path_metrics.h        distances between crack paths (mean, Hausdorff)
//   study.h               pumpd --study: the speed/accuracy trade of a scene
//     study_settings.h      the section Study
//     study_plan.h          the runs of a study, checked before any starts
//     ladder.h              the settings tried: rungs of overrides, the scene file of each
//     parameter_table.h     every entry of a scene file with its value
//     study_record.h        runs.csv, the key that makes a run reusable
//     trade_table.h         the table, the distances, the recommended setting
#pragma once

#include "arrival.h"
#include "boundary_transfer.h"
#include "box_policy.h"
#include "crack_extraction.h"
#include "cycle_checkpoint.h"
#include "exchange.h"
#include "exchange_controller.h"
#include "full_pd.h"
#include "global_local.h"
#include "global_problem.h"
#include "initiation.h"
#include "lefm_growth.h"
#include "parameters.h"
#include "path_metrics.h"
#include "pd_edge_crack.h"
#include "recorder.h"
#include "resolution.h"
#include "scene.h"
#include "study.h"
