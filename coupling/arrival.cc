#include "arrival.h"

namespace pumpd::coupling
{
  using geometry::Point;

  Arrival arrive(geometry::Polyline path, const geometry::Body &body, double margin, double reach,
                 std::size_t first_new, double hole_reach)
  {
    for (std::size_t k = first_new == 0 ? 0 : first_new - 1; k + 1 < path.size(); ++k)
      {
        const Point  e = path[k + 1] - path[k];
        const double l = geometry::norm(e);
        if (l == 0.)
          continue;
        const Point u   = (1. / l) * e;
        const auto  hit = body.ray_to_holes(path[k], u, margin);
        if (hit.t <= l)
          {
            path.resize(k + 1);
            if (hit.t > 1e-9)
              path.push_back(path[k] + hit.t * u);
            return {path, "reached " + body.hole_name(hit.hole)};
          }
      }
    if (path.size() > first_new && path.size() >= 2)
      {
        const Point  e = path.back() - path[path.size() - 2];
        const Point  u = (1. / geometry::norm(e)) * e;
        const double t = body.ray_to_outline(path.back(), u);
        if (t <= reach)
          {
            path.back() = path.back() + t * u;
            return {path, "reached the outline"};
          }
        const auto hit = body.ray_to_holes(path.back(), u, margin);
        if (hit.t <= hole_reach)
          {
            path.push_back(path.back() + hit.t * u);
            return {path, "reached " + body.hole_name(hit.hole)};
          }
      }
    return {path, ""};
  }
} // namespace pumpd::coupling
