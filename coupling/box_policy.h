// Where the PD box goes (DESIGN.md, coupling/ BoxPolicy). A square of side `size` around the
// crack tip, the tip `behind` x size from its rear along the crack direction, so that most of
// the box lies where the crack will go. The box
//  - stays where it is while the tip keeps `margin` of free lattice (beyond the boundary layer of
//    width delta) ahead of it, and moves ahead of the tip otherwise;
//  - grows to take in a hole that would otherwise cut its boundary layer or come within one
//    horizon of it (up to `max_size` a side), so a hole is either inside the PD model or clear of it;
//  - reaches out to the body outline when an edge would come within `snap` of it (no sliver of
//    material between the boundary layer and a free surface), and is clipped to the body;
//  - has its interior edges on the lattice lines x = x_min(body) + i h, so that consecutive boxes
//    share their nodes.
#pragma once

#include <vector>

#include "body.h"

namespace pumpd::coupling
{
  struct BoxSettings
  {
    double horizon  = 0.004;  ///< delta [m] (the boundary-layer width)
    double spacing  = 0.0005; ///< PD lattice spacing h [m]
    double size     = 0.032;  ///< side of the square box [m]
    double behind   = 0.3;    ///< the tip sits this fraction of the side from the box's rear
    double margin   = 0.008;  ///< free lattice the tip keeps ahead of it before the box moves [m]
    double max_size = 0.064;  ///< a box grown for a hole stays within this side [m]
  };

  class BoxPolicy
  {
  public:
    /// Throws InvalidParameter ("Box size", ...) if the box cannot hold the boundary layer on two
    /// sides plus the margin, or does not fit into the body.
    BoxPolicy(const geometry::Body &body, const BoxSettings &settings);

    /// The box for a tip at `tip` growing along the unit `direction`, every length of the
    /// settings (horizon, spacing, size, margin, maximum size) times `scale`; recorded in history().
    /// A box of another scale is never kept.
    geometry::Box place(geometry::Point tip, geometry::Point direction, double scale = 1.);
    /// The box shared by several tips: the smallest box holding each tip's own square (as placed
    /// for it alone), fitted as one; kept while it keeps every tip. `turns` are the unit directions
    /// the tips are expected to grow in (the maximum hoop stress directions): a new square lies
    /// ahead along the crack's direction if the turned crack, followed to the square's front
    /// layer, stays two horizons inside it; else (a large kink) it lies ahead along the turn.
    geometry::Box place(const std::vector<geometry::Point> &tips, const std::vector<geometry::Point> &directions,
                        const std::vector<geometry::Point> &turns, double scale = 1.);
    /// Half the smaller bounding-box side of the smallest hole the box at this tip (every length
    /// of the settings times `scale`) would take in or grow for; infinity if none.
    double smallest_hole_within_reach(geometry::Point tip, geometry::Point direction, double scale = 1.) const;
    /// True if the box with every length times `scale` fits into the body.
    bool fits(double scale) const;
    /// True if the last place() made a new box.
    bool moved() const { return last_moved; }
    const std::vector<geometry::Box> &history() const { return boxes; }
    /// Continue after a restart with the boxes recorded so far, the last of them placed at `scale`.
    void restore(const std::vector<geometry::Box> &history, double scale = 1.);

  private:
    bool          keeps(const geometry::Box &box, geometry::Point tip, geometry::Point direction) const;
    /// The settings of place() at `scale`: every length of the given ones times it.
    void          rescale(double scale);
    geometry::Box fitted(geometry::Box box) const;

    geometry::Body             body;
    BoxSettings                unscaled;
    BoxSettings                s; ///< of the last place()
    double                     last_scale = 1.;
    std::vector<geometry::Box> boxes;
    bool                       last_moved = true;
  };
} // namespace pumpd::coupling
