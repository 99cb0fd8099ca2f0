// pumpd_local: bond-based peridynamics in a box, no deal.II (DESIGN.md, local/). Built on
// pumpd_basics (basics.h: geometry, the body, errors, Williams fields).
//
//   material.h        Lipton's softening bond potential: C, beta, S_c from E, G_c, nu, J
//   lattice.h         the node lattice with ghost padding, the half stencil and its weights
//   model.h           PdModel: nodes, bonds (holes, pre-cracks), boundary layer, force kernel,
//                     energies, damage, stretch ratio Z, stable time step
//   strength.h        the model's peak stress under homogeneous strain (tensile strength)
//   boundary_layer.h  prescribed, ramped displacement of the boundary layer
//   integrators.h     velocity Verlet (stability bound enforced), dynamic relaxation (with an
//                     optional servo for indirect displacement control)
//   explicit_run.h    a dynamic run that stops on NaN and saves the last good state
//   checkpoint.h      HDF5 checkpoint / restart (bit for bit)
//   hdf5_array.h      one-dimensional HDF5 datasets (the checkpoints' arrays; not included here:
//                     it needs the HDF5 headers)
//   vtu_output.h      VTU / PVD for ParaView
#pragma once

#include "basics.h"
#include "boundary_layer.h"
#include "checkpoint.h"
#include "explicit_run.h"
#include "integrators.h"
#include "lattice.h"
#include "material.h"
#include "model.h"
#include "strength.h"
#include "vtu_output.h"
