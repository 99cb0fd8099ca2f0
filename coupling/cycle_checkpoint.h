// The state of the global-local cycle between two exchanges, in HDF5 (checkpoint.h5), so that an
// interrupted run resumes where it stopped. The PD boxes are rebuilt at every exchange from the
// crack polylines, so the cracks, the counters, the refinements of the global mesh (tip positions
// and levels: the same mesh on resume) and, per end of each crack, its tip's boxes, accepted load,
// last box's horizon and whether it stopped are the whole state, with what makes the scene that
// wrote it (the fingerprint of its geometry, the entries of its scene file that change results),
// the length of every file the run appends to when the state was written (a resumed run cuts them
// back to it: recorder.h), and a checksum (FNV-1a) of all of it: a damaged file is refused.
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "geometry.h"
#include "global_problem.h"

namespace pumpd::coupling
{
  /// What the cycle keeps for the tip at one end of the crack polyline.
  struct TipEndState
  {
    std::vector<geometry::Box> boxes;
    double                     load_factor = 0.; ///< lambda / lambda_c of its last accepted exchange
    int                        halvings    = 0;  ///< of its last box's horizon, < 0: doublings (coupling/resolution.h)
    bool                       stopped     = false;
  };

  struct CycleState
  {
    std::uint64_t              scene     = 0; ///< geometry_fingerprint of the scene (coupling/scene.h)
    std::size_t                exchanges = 0; ///< exchanges done so far
    bool                       finished  = false;
    std::vector<geometry::Polyline> cracks;
    std::vector<Refinement>         refinements; ///< of every global solve so far
    std::vector<TipEndState>        ends; ///< 2 c + e: crack c's tip at its first (e = 0) or last vertex
    /// The scene file's entries that change results: path ("Scene/Material/Young's modulus") and value.
    std::vector<std::pair<std::string, std::string>> entries;
    std::map<std::string, std::uint64_t>             outputs; ///< Recorder::lengths() (recorder.h)
  };

  /// Writes aside and renames (an interruption never leaves half a checkpoint). Throws
  /// std::runtime_error naming the file and the cause if it cannot be written.
  void write_cycle_checkpoint(const std::string &path, const CycleState &state);
  /// Throws std::runtime_error naming the file if it is missing, not a cycle checkpoint, or its
  /// contents do not match their checksum.
  CycleState read_cycle_checkpoint(const std::string &path);
} // namespace pumpd::coupling
