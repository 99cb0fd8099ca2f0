#include "arrival.h"

#include <algorithm>

#include "error.h"

namespace pumpd::coupling
{
  using geometry::Point;

  std::string tip_stop(Point tip, const std::string &what) { return "the tip at " + geometry::to_text(tip) + " " + what; }

  namespace
  {
    /// The ends of `crack` that lie at neither end of `initial` (the same crack before the run, in
    /// either order; none: a crack the run formed, all of whose ends grew).
    std::vector<Point> grown_ends(const geometry::Polyline *initial, const geometry::Polyline &crack, double tolerance)
    {
      std::vector<Point> grown;
      for (const Point end : {crack.front(), crack.back()})
        if (!initial || std::min(geometry::norm(end - initial->front()), geometry::norm(end - initial->back())) > tolerance)
          grown.push_back(end);
      return grown;
    }

    /// The ends of `crack` off the boundary.
    std::vector<Point> tips_of(const geometry::Polyline &crack, const geometry::Body &body, double tolerance)
    {
      std::vector<Point> tips;
      for (const Point end : {crack.front(), crack.back()})
        if (body.clearance(end) > tolerance)
          tips.push_back(end);
      return tips;
    }

    std::string crack_text(const geometry::Polyline &crack, const std::vector<Point> &ends)
    {
      std::string s = to_text(geometry::length(crack)) + " m";
      for (std::size_t k = 0; k < ends.size(); ++k)
        s += (k == 0 ? (ends.size() == 1 ? ", tip at " : ", tips at ") : " and ") + geometry::to_text(ends[k]);
      return s;
    }
  } // namespace

  std::string grown_cracks_text(const std::vector<geometry::Polyline> &initial,
                                const std::vector<geometry::Polyline> &cracks, const geometry::Body &body,
                                double tolerance)
  {
    std::vector<std::pair<std::size_t, std::vector<Point>>> named; // (crack, its ends to name)
    for (std::size_t c = 0; c < cracks.size(); ++c)
      if (cracks[c].size() >= 2)
        if (auto grown = grown_ends(c < initial.size() ? &initial[c] : nullptr, cracks[c], tolerance); !grown.empty())
          named.emplace_back(c, std::move(grown));
    if (named.empty())
      for (std::size_t c = 0; c < cracks.size(); ++c)
        if (cracks[c].size() >= 2)
          named.emplace_back(c, tips_of(cracks[c], body, tolerance));
    if (named.empty())
      return "no crack";
    std::string s;
    for (const auto &[c, ends] : named)
      s += (s.empty() ? "" : "; ") +
           (cracks.size() > 1 ? "crack " + std::to_string(c + 1) + ": " : std::string("crack ")) +
           crack_text(cracks[c], ends);
    return s;
  }

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
            return {path, tip_stop(path.back(), "reached " + body.hole_name(hit.hole))};
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
            return {path, tip_stop(path.back(), "reached the outline")};
          }
        const auto hit = body.ray_to_holes(path.back(), u, margin);
        if (hit.t <= hole_reach)
          {
            path.push_back(path.back() + hit.t * u);
            return {path, tip_stop(path.back(), "reached " + body.hole_name(hit.hole))};
          }
      }
    return {path, ""};
  }

  std::pair<double, std::size_t> ray_to_cracks(geometry::Point from, geometry::Point e, double t_max,
                                               const std::vector<geometry::Polyline> &cracks, std::size_t skip)
  {
    std::pair<double, std::size_t> best{std::numeric_limits<double>::infinity(), skip};
    for (std::size_t c = 0; c < cracks.size(); ++c)
      {
        if (c == skip)
          continue;
        const auto &v = cracks[c];
        for (std::size_t k = 0; k + 1 < v.size(); ++k)
          {
            // from + t e = v_k + u f,  t in [0, t_max], u in [0, 1]. The segment meets the ray's
            // line where its ends lie on opposite sides (or on it), at u = side_0 / (side_0 -
            // side_1), which rounds into [0, 1]. The side of a vertex two segments share is the
            // same number for both, so a ray through it meets one of them however it rounds (a
            // test of u computed from the lines' intersection can miss both).
            const double side_0 = geometry::cross(e, v[k] - from), side_1 = geometry::cross(e, v[k + 1] - from);
            if ((side_0 > 0. && side_1 > 0.) || (side_0 < 0. && side_1 < 0.) || side_0 == side_1)
              continue;
            const double          u  = side_0 / (side_0 - side_1);
            const geometry::Point at = v[k] + u * (v[k + 1] - v[k]);
            const double          t  = geometry::dot(at - from, e) / geometry::dot(e, e);
            if (t >= 0. && t <= t_max && t < best.first)
              best = {t, c};
          }
      }
    return best;
  }

  std::optional<CrackMeeting> first_crossing(const geometry::Polyline &path,
                                             const std::vector<geometry::Polyline> &cracks, std::size_t own)
  {
    for (std::size_t k = 0; k + 1 < path.size(); ++k)
      {
        const geometry::Point e = path[k + 1] - path[k];
        // A path that ends on a face (a trace that reached it) meets it: its end may lie a
        // rounding error short of the face.
        if (const auto [t, c] = ray_to_cracks(path[k], e, 1. + 1e-9, cracks, own); t <= 1. + 1e-9)
          return CrackMeeting{c, k, path[k] + t * e};
      }
    return std::nullopt;
  }

  std::optional<CrackMeeting> face_ahead(const geometry::Polyline &path, const std::vector<geometry::Polyline> &cracks,
                                         std::size_t own, double reach)
  {
    const geometry::Point       tip = path.back(), d = tip - path[path.size() - 2];
    std::optional<CrackMeeting> nearest;
    double                      least = reach;
    for (std::size_t c = 0; c < cracks.size(); ++c)
      for (std::size_t j = 0; j + 1 < cracks[c].size(); ++j)
        {
          if (c == own)
            break;
          const geometry::Point q = geometry::nearest_on_segment(tip, cracks[c][j], cracks[c][j + 1]);
          if (const double r = geometry::norm(q - tip); r < least && geometry::dot(q - tip, d) > 0.)
            {
              least   = r;
              nearest = CrackMeeting{c, path.size() - 1, q};
            }
        }
    return nearest;
  }
} // namespace pumpd::coupling
