// What a run will write, estimated before it starts, against the free space where it writes. The
// files that grow with a run are its VTU series (a table row is a few hundred bytes, a VTU file
// megabytes): the number of files its settings imply (one per output interval up to the limit of
// steps or exchanges, and the last) times the size of one (basics/vtu.h: from its points and
// cells: the global mesh refined at the tips, the PD box's or the body's lattice). A run whose
// estimate exceeds half the free space of its output directory's file system is refused: the
// estimate is of the order of what the run writes, and a run that fills the disk stops on its
// first failed write (basics/output.h).
#pragma once

#include <string>

namespace pumpd::coupling
{
  struct Parameters;
  struct Scene;

  /// The VTU output a method's settings imply.
  struct OutputVolume
  {
    double       files = 0., bytes_per_file = 0.;
    unsigned int output_interval = 1; ///< the method's Output interval
    std::string  limits;              ///< the entries that bound its steps, "<name> = <value>, ..."
    /// false: its PD lattice needs more memory than this machine has, and the PD model refuses it
    /// before anything is written, naming its entry (local/model.h): no estimate is made.
    bool   held = true;
    double bytes() const { return files * bytes_per_file; }
  };

  /// Of the scene's method (pd-edge-crack needs no scene: `scene` may be null for it).
  OutputVolume estimated_output(const Parameters &parameters, const Scene *scene);

  /// Refuses (InvalidParameter naming Output interval and the limits) a run whose estimated
  /// output exceeds half the free space of the file system of `directory` (or of its nearest
  /// existing parent); nothing without an output directory or for a lattice not `held`.
  void check_output_volume(const Parameters &parameters, const Scene *scene, const std::string &directory);
} // namespace pumpd::coupling
