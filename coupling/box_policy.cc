#include "box_policy.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include "error.h"

namespace pumpd::coupling
{
  using geometry::Box;
  using geometry::Point;

  BoxPolicy::BoxPolicy(const geometry::Body &b, const BoxSettings &settings)
    : body(b)
    , unscaled(settings)
    , s(settings)
  {
    require_positive("Horizon", s.horizon);
    require_positive("PD spacing", s.spacing);
    require_range("Box tip position", s.behind, 0.05, 0.95, "must be in [0.05, 0.95] (fraction of the box side)");
    require_positive("Box margin", s.margin);
    const Box &o = body.bounding_box();
    if (s.margin >= std::min(o.width(), o.height()))
      throw InvalidParameter("Box margin", to_text(s.margin),
                             "must be less than the body's smaller side (" + to_text(std::min(o.width(), o.height())) +
                               " m)");
    const double least = 4. * s.horizon + s.margin;
    if (!(s.size >= least))
      throw InvalidParameter("Box size", to_text(s.size),
                             "must be at least 4 horizons plus the Box margin (" + to_text(least) +
                               " m): a boundary layer on each side, a horizon of free lattice around the tip");
    if (s.size > std::min(o.width(), o.height()))
      throw InvalidParameter("Box size", to_text(s.size),
                             "must not exceed the body's smaller side (" + to_text(std::min(o.width(), o.height())) +
                               " m)");
    if (s.max_size < s.size)
      throw InvalidParameter("Maximum box size", to_text(s.max_size), "must be >= the box size " + to_text(s.size) + " m");
  }

  bool BoxPolicy::keeps(const Box &box, Point tip, Point d) const
  {
    // The tip must be clear of each interior edge by a horizon (layer) plus a horizon, and the
    // box must hold `margin` of free lattice ahead of the tip along d.
    const auto  &o       = body.bounding_box();
    const double tol     = 0.25 * s.spacing;
    const double layer_x0 = box.x_min > o.x_min + tol ? s.horizon : 0., layer_x1 = box.x_max < o.x_max - tol ? s.horizon : 0.;
    const double layer_y0 = box.y_min > o.y_min + tol ? s.horizon : 0., layer_y1 = box.y_max < o.y_max - tol ? s.horizon : 0.;
    const Box    free{box.x_min + layer_x0 + s.horizon, box.y_min + layer_y0 + s.horizon,
                      box.x_max - layer_x1 - s.horizon, box.y_max - layer_y1 - s.horizon};
    const Box    free_ahead{box.x_min + layer_x0, box.y_min + layer_y0, box.x_max - layer_x1, box.y_max - layer_y1};
    return free.contains(tip) && free_ahead.contains(tip + s.margin * d);
  }

  namespace
  {
    /// The hole's bounding box with `reach` around it, if it overlaps the box.
    std::optional<Box> within_reach(const geometry::Loop &hole, const Box &box, double reach)
    {
      const Box b = hole.bounding_box();
      const Box around{b.x_min - reach, b.y_min - reach, b.x_max + reach, b.y_max + reach};
      if (around.x_max > box.x_min && around.x_min < box.x_max && around.y_max > box.y_min && around.y_min < box.y_max)
        return around;
      return std::nullopt;
    }

    Box square_ahead(Point tip, Point d, const BoxSettings &s)
    {
      const Point c = tip + ((0.5 - s.behind) * s.size) * d;
      return {c.x - 0.5 * s.size, c.y - 0.5 * s.size, c.x + 0.5 * s.size, c.y + 0.5 * s.size};
    }

    /// The square ahead of the tip along d, or along the turn where the crack turned by it would
    /// come within two horizons (a layer and a process zone) of the square's edges before it
    /// reaches as far ahead as the front layer.
    Box square_for_turn(Point tip, Point d, Point turn, const BoxSettings &s)
    {
      const Box    ahead = square_ahead(tip, d, s);
      const double inset = 2. * s.horizon;
      const Point  reach = tip + ((1. - s.behind) * s.size - inset) * turn;
      const Box    inner{ahead.x_min + inset, ahead.y_min + inset, ahead.x_max - inset, ahead.y_max - inset};
      return inner.contains(reach) ? ahead : square_ahead(tip, turn, s);
    }
  } // namespace

  double BoxPolicy::smallest_hole_within_reach(Point tip, Point d, double scale) const
  {
    BoxSettings at_scale = unscaled;
    at_scale.size *= scale;
    at_scale.horizon *= scale;
    double smallest = std::numeric_limits<double>::infinity();
    for (const auto &hole : body.holes())
      if (within_reach(hole, square_ahead(tip, d, at_scale), 2. * at_scale.horizon))
        {
          const Box b = hole.bounding_box();
          smallest    = std::min(smallest, 0.5 * std::min(b.width(), b.height()));
        }
    return smallest;
  }

  bool BoxPolicy::fits(double scale) const
  {
    const Box &o = body.bounding_box();
    return scale * unscaled.size <= std::min(o.width(), o.height());
  }

  Box BoxPolicy::fitted(Box box) const
  {
    const auto &o = body.bounding_box();
    // Holes within reach: inside with a horizon to spare, or the box grows (up to max_size).
    for (const auto &hole : body.holes())
      {
        const auto around = within_reach(hole, box, 2. * s.horizon);
        if (!around || box.contains(*around))
          continue;
        Box grown{std::min(box.x_min, around->x_min), std::min(box.y_min, around->y_min),
                  std::max(box.x_max, around->x_max), std::max(box.y_max, around->y_max)};
        if (grown.width() <= s.max_size && grown.height() <= s.max_size)
          box = grown;
      }
    // Shift into the body, then reach out to the outline where a sliver would remain.
    const double snap = 2. * s.horizon;
    const auto   shift_into = [](double &lo, double &hi, double min, double max) {
      if (hi - lo >= max - min)
        lo = min, hi = max;
      else if (lo < min)
        hi += min - lo, lo = min;
      else if (hi > max)
        lo -= hi - max, hi = max;
    };
    shift_into(box.x_min, box.x_max, o.x_min, o.x_max);
    shift_into(box.y_min, box.y_max, o.y_min, o.y_max);
    // Interior edges on lattice lines (outward), outline edges exactly on the outline.
    const double h    = s.spacing;
    const auto   snap_edge = [&](double &lo, double &hi, double min, double max) {
      lo = lo - min < snap ? min : min + std::floor((lo - min) / h + 1e-9) * h;
      hi = max - hi < snap ? max : min + std::ceil((hi - min) / h - 1e-9) * h;
      hi = std::min(hi, max);
    };
    snap_edge(box.x_min, box.x_max, o.x_min, o.x_max);
    snap_edge(box.y_min, box.y_max, o.y_min, o.y_max);
    return box;
  }

  void BoxPolicy::rescale(double scale)
  {
    s          = unscaled;
    s.horizon  = scale * unscaled.horizon;
    s.spacing  = scale * unscaled.spacing;
    s.size     = scale * unscaled.size;
    s.margin   = scale * unscaled.margin;
    s.max_size = scale * unscaled.max_size;
    last_scale = scale;
  }

  Box BoxPolicy::place(Point tip, Point d, double scale)
  {
    return place(std::vector{tip}, std::vector{d}, std::vector{d}, scale);
  }

  Box BoxPolicy::place(const std::vector<Point> &tips, const std::vector<Point> &d, const std::vector<Point> &turns,
                       double scale)
  {
    const bool rescaled = scale != last_scale;
    if (rescaled)
      rescale(scale);
    bool kept = !boxes.empty() && !rescaled;
    for (std::size_t k = 0; k < tips.size(); ++k)
      kept = kept && keeps(boxes.back(), tips[k], d[k]);
    if (kept)
      {
        last_moved = false;
        boxes.push_back(boxes.back());
        return boxes.back();
      }
    last_moved = true;
    Box box = square_for_turn(tips.front(), d.front(), turns.front(), s);
    for (std::size_t k = 1; k < tips.size(); ++k)
      {
        const Box own = square_for_turn(tips[k], d[k], turns[k], s);
        box           = {std::min(box.x_min, own.x_min), std::min(box.y_min, own.y_min), std::max(box.x_max, own.x_max),
                         std::max(box.y_max, own.y_max)};
      }
    boxes.push_back(fitted(box));
    return boxes.back();
  }

  void BoxPolicy::restore(const std::vector<Box> &history, double scale)
  {
    boxes = history;
    rescale(scale);
  }
} // namespace pumpd::coupling
