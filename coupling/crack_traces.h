// The cracks of a scene as full PD traces them through its damage field: every end of an initial
// crack that is a tip (an edge crack has one, an interior crack two) is traced from that tip
// (coupling::extract_crack), every state anew through the damage of the accepted states.
//
// A tip is traced through the field with the other cracks' faces removed (as if there were no
// material within half a horizon of their paths, where they are nearer than its own crack's
// accepted path: its own band stays where another crack ends on it): the damage band of another crack's face reaches
// about a third of a horizon out, so the ridge ends in front of that face instead of running into
// its band, where the transverse profile would show two branches. The faces removed are those
// traced in the previous pass over the tips (the first pass: the accepted paths), until the paths
// no longer change, at most three passes: a crack that grows towards another one's face in this
// state is then left out of that one's trace too. The traced path ends as in the other methods
// (coupling/arrival.h): at a hole or the outline (arrive), or on another crack's face, where it
// crosses that face (first_crossing), or where its last segment continued meets the face within
// two horizons (ray_to_cracks: the ridge ends about half a horizon in front of the face, farther
// along a slanting approach), else at the nearest point of a face within a horizon ahead of its end
// (face_ahead); the tip joins that crack there. A tip that stopped keeps its path; the others go
// on. Where another crack's new growth comes within the transverse window of a tip's accepted path
// (its ridge would show it as a branch there), that tip is traced on from its accepted end instead.
//
// A ridge that turns into another crack's face by more than the tracer follows ends the trace in
// the material (extract_crack: "the damage ridge ends"): the transverse window, a horizon either
// side of a point two spacings ahead, misses a ridge that turns at a vertex by more than
// atan(delta / 2h) (63 degrees for m = 4), and the trace can run on past that corner where the
// damage does. Such a trace joins the face
// along the shortest straight segment from a point of its increment's last horizon to a point of
// another crack's face within three horizons ahead (along its last segment) on which the damage is
// connected (damage_connects: every sample above the extraction threshold). The path is cut at
// that point and ends the clearance (half a horizon) in front of the face, where a ridge traced
// into a face ends too; accept() joins it along its last segment. A scene with one crack is traced
// without this rule.
//
// Cracks that join end the run, as in the other methods: the ridge of the crack joined would show
// the joining crack's band as a branch at the junction.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "body.h"
#include "crack_extraction.h"

namespace pumpd::coupling
{
  class CrackTraces
  {
  public:
    /// The tips of `cracks`: the ends farther than `tolerance` from the body's boundary. Each
    /// crack is oriented with the end nearer the boundary (its mouth) first.
    CrackTraces(const std::vector<geometry::Polyline> &cracks, const geometry::Body &body, double tolerance);

    /// The increment of every tip, from its initial position along its initial direction through
    /// `field`, the other cracks removed within `clearance` (the passes above); a tip that stopped
    /// has none (path {its end}). Throws CrackBranching where a ridge splits.
    std::vector<CrackIncrement> extract(const DamageField &field, const ExtractionSettings &settings,
                                        double clearance) const;
    /// The length of every crack together if `increments` were accepted as traced.
    double traced_length(const std::vector<CrackIncrement> &increments) const;
    /// Accepts `increments`: each path ends where it reaches a hole (within `margin`), the outline
    /// (within `reach` ahead), or another crack's face (crossed, within twice `reach` along its
    /// last segment, or within `reach` ahead: a join).
    /// Returns "" while the run goes on, else why it stops: every tip stopped, or cracks joined.
    std::string accept(const std::vector<CrackIncrement> &increments, const geometry::Body &body, double margin,
                       double reach);

    /// Every crack, in the scene's order, its mouth (or the end nearer the boundary) first.
    std::vector<geometry::Polyline> paths() const;
    /// The length of every crack together.
    double length() const;
    bool   joined() const { return any_joined; }
    /// The positions the tips start from.
    std::vector<geometry::Point> initial_tips() const;

  private:
    struct Tip
    {
      std::size_t        crack = 0;
      std::size_t        initial_size = 0; ///< path[initial_size - 1] is the initial tip
      geometry::Polyline path;             ///< the crack, this tip last, and what grew from it
      std::string        stop;             ///< "" while the tip goes on
    };

    /// The increment of `tip` through `field`, the cracks `others` but its own removed within
    /// `clearance` where they are nearer than its own crack's accepted path.
    CrackIncrement trace(const Tip &tip, const DamageField &field, const ExtractionSettings &settings,
                         double clearance, const std::vector<geometry::Polyline> &others) const;
    /// `increment` of `tip` where its ridge ends, continued towards another crack's face (of
    /// `others`) along which the damage of `field` is connected, to `clearance` in front of it
    /// (the rule above).
    CrackIncrement turned_into_face(CrackIncrement increment, const Tip &tip, const DamageField &field,
                                    const ExtractionSettings &settings, double clearance,
                                    const std::vector<geometry::Polyline> &others) const;
    /// The crack's path from its tips: the second tip (at the mouth's end) reversed, then the first.
    geometry::Polyline crack_path(std::size_t crack, const std::vector<Tip> &tips) const;
    std::vector<geometry::Polyline> crack_paths(const std::vector<Tip> &tips) const;

    std::vector<geometry::Polyline> initial;
    std::vector<Tip>                tips;
    bool                            any_joined = false;
  };
} // namespace pumpd::coupling
