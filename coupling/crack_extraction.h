// Crack extraction: the crack increment of a PD run, read off its nodal damage field D (the
// weighted fraction of a node's bonds that failed; ~0.4 on the crack faces, 0 one horizon away).
// Ridge tracing with a transverse damage-weighted centroid:
// 1. from the last vertex p along the direction t: predictor q = p + s t and the transverse
//    profile D(q + eta n), |eta| <= w, n = t rotated by +90 degrees (bilinear interpolation),
//    averaged over |tau| <= h along t: noise is damped and an isolated damaged node stays below
//    the threshold D_c (the band of a crack face is at least two nodes wide and continues);
// 2. its runs above D_c (gaps shorter than a spacing closed, runs narrower than a spacing ignored):
//    none: the ridge ends near q; two or more: the crack branches (thrown, never guessed; or,
//    with `branch_ends_trace`, the trace ends at p);
//    one: the next vertex is its centroid c = q + eta_c n, eta_c = int eta (D - D_c) / int (D - D_c),
//    and t turns towards c, by at most `max_turn` after the first step and `max_first_turn` on
//    the first (by default no bound but the window's, atan(w / s): from a crack tip the first
//    step takes the kink; CrackTraces' carry-on from an accepted end sets it to `max_turn`);
// 3. the new tip: marching from the last vertex along t by h/8, the first point where the ridge
//    damage R(x) = max_{|eta| <= h} D(x + eta n) drops to half the crack-face damage (the median R
//    over the last horizon of the ridge), interpolated linearly: a node at the tip of a straight
//    crack has a quarter of its bonds cut, half the face damage (the threshold would fall about a
//    spacing behind the tip). The march also stops where the material ends (a hole, the field's edge);
// 4. Douglas-Peucker simplification (tolerance h/2). An increment shorter than one spacing is
//    below the lattice resolution: no growth.
// Other cracks' faces (`faces`): their damage bands would read as branches once the window reaches
// them, so the trace ends on a face that lies within a horizon ahead of the predictor (along t),
// and a split within two horizons of a face ends the trace on it too (on the face along t within
// two horizons of the predictor, else at the face's point nearest to it).
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include "geometry.h"

namespace pumpd::coupling
{
  /// Nodal damage on the PD lattice: node (i, j) at origin + (i h, j h), values[j * nx + i];
  /// NaN where there is no material. A node stands for its cell (side h, centred on it).
  struct DamageField
  {
    geometry::Point     origin;
    double              spacing = 0.;
    std::size_t         nx = 0, ny = 0;
    std::vector<double> values;
  };

  struct ExtractionSettings
  {
    double threshold         = 0.3; ///< damage above which a node lies on the crack (PD crack faces reach ~0.4)
    double step              = 0.;  ///< tracing step [m]; 0: 2 spacings
    double search_half_width = 0.;  ///< half width of the transverse search window [m]; 0: the horizon
    double horizon           = 0.;  ///< delta [m], sets default widths
    double max_turn          = 0.785398163397448; ///< largest turn of the tip direction per step after the first [rad] (45 degrees)
    double max_first_turn    = 1.5707963267948966; ///< largest turn of the first step [rad]; pi/2: no bound but the window's, atan(w / step)
    double simplification    = 0.;  ///< Douglas-Peucker tolerance [m]; 0: half a spacing
    std::vector<geometry::Polyline> faces; ///< other cracks, which the trace ends on
    bool branch_ends_trace = false; ///< a split ends the trace before it (stop reason `ridge_splits`) instead of throwing
  };

  /// The stop reason (its start) of a trace that ends in the material: no run above the threshold
  /// across the predictor, within the turn limit.
  inline constexpr char ridge_ends[] = "the damage ridge ends";
  /// The stop reason (its start) of a trace that ends where the ridge splits (`branch_ends_trace`).
  inline constexpr char ridge_splits[] = "the damage ridge splits";
  /// The stop reason of a trace that ends on one of the `faces`.
  inline constexpr char reaches_face[] = "the damage ridge reaches another crack's face";

  struct CrackIncrement
  {
    geometry::Polyline path;        ///< path[0] == tip; path.size() == 1: no growth
    std::string        stop_reason; ///< why the tracing stopped
    double             length() const { return geometry::length(path); }
  };

  /// Thrown when the damage ridge splits into two branches: refused, never guessed.
  struct CrackBranching : std::runtime_error
  {
    using std::runtime_error::runtime_error;
  };

  /// Traces the damage ridge from the current tip along `direction` (the tip direction of the
  /// crack; normalised here) and returns the crack increment. Throws InvalidParameter for a bad
  /// field, tip, direction or setting, CrackBranching where the ridge splits.
  CrackIncrement extract_crack(const DamageField &damage, geometry::Point tip, geometry::Point direction,
                               const ExtractionSettings &settings);

  /// Whether the damage runs as a crack along the segment from `from` (a point of a trace) to `to`:
  /// every h/4 from a spacing past `from` on, the largest damage within a spacing across the segment
  /// is at least the threshold. The first spacing is not sampled: a trace ends where the ridge
  /// damage has dropped to half the face damage, below the threshold. False for a segment not
  /// longer than a spacing.
  bool damage_connects(const DamageField &damage, geometry::Point from, geometry::Point to,
                       const ExtractionSettings &settings);
} // namespace pumpd::coupling
