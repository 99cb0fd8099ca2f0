// pumpd_basics: what global/ and local/ share, knowing neither PD nor deal.II (DESIGN.md).
//
//   geometry.h  points, boxes, circles, polylines, segment tests
//   segment_tree.h  a bounding-box hierarchy over a polyline's segments: the nearest segment
//   body.h      the body of a specimen: outline and holes as curves of segments and arcs, built
//               from a mesh's boundary edges; containment, clearance, bond and ray tests
//   error.h     InvalidParameter (names the parameter and its allowed range), NonFiniteState
//   conditions.h  a scene's boundary conditions on named places of the mesh, per unit load factor;
//               whether a place lies near a point
//   lefm.h      Williams near-tip fields (PD driving data, interaction integral, exact solutions)
//   csv.h       the CSV writer (flushed row by row) and reader
//   pvd.h       the ParaView series index (.pvd)
//   vtu.h       the VTU writer (unstructured grids, arrays as base64 binary)
//   text.h      a file's bytes, trim
//   hash.h      content hashes (FNV-1a) and their hex text
//   memory.h    the memory this machine can give a new allocation
//   program.h   another program run as a child process: exit status, wall time, peak memory
#pragma once

#include "body.h"
#include "conditions.h"
#include "csv.h"
#include "error.h"
#include "geometry.h"
#include "hash.h"
#include "lefm.h"
#include "memory.h"
#include "program.h"
#include "segment_tree.h"
#include "pvd.h"
#include "text.h"
#include "vtu.h"
