#include "crack_traces.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <tuple>

#include "arrival.h"
#include "path_metrics.h"

namespace pumpd::coupling
{
  using geometry::Point;
  using geometry::Polyline;

  namespace
  {
    /// `field` without material where a crack other than `own` lies within `clearance` and nearer
    /// than `own_path`.
    DamageField without_other_cracks(const DamageField &field, const std::vector<Polyline> &cracks, std::size_t own,
                                     const Polyline &own_path, double clearance)
    {
      DamageField f = field;
      for (std::size_t j = 0; j < f.ny; ++j)
        for (std::size_t i = 0; i < f.nx; ++i)
          {
            const Point x = f.origin + Point{double(i) * f.spacing, double(j) * f.spacing};
            for (std::size_t c = 0; c < cracks.size(); ++c)
              if (const double d = c == own ? clearance : distance_to_polyline(x, cracks[c]);
                  d < clearance && d < distance_to_polyline(x, own_path))
                {
                  f.values[j * f.nx + i] = std::numeric_limits<double>::quiet_NaN();
                  break;
                }
          }
      return f;
    }

    /// A point `at` of crack `crack`'s face, `distance` from a point of a trace.
    struct FacePoint
    {
      double      distance;
      Point       at;
      std::size_t crack;
    };

    /// The points of the cracks but `own` within `reach` of `end` and ahead of it (along `ahead`),
    /// nearest first: on every segment its point nearest to `end` and points every `spacing` / 2.
    std::vector<FacePoint> face_points_ahead(Point end, Point ahead, const std::vector<Polyline> &cracks,
                                             std::size_t own, double reach, double spacing)
    {
      std::vector<FacePoint> found;
      const auto             consider = [&](Point q, std::size_t c) {
        if (const double r = geometry::norm(q - end); r < reach && geometry::dot(q - end, ahead) > 0.)
          found.push_back({r, q, c});
      };
      for (std::size_t c = 0; c < cracks.size(); ++c)
        for (std::size_t j = 0; c != own && j + 1 < cracks[c].size(); ++j)
          {
            const Point  a = cracks[c][j], w = cracks[c][j + 1] - a;
            const double l = geometry::norm(w);
            consider(geometry::nearest_on_segment(end, a, cracks[c][j + 1]), c);
            for (double u = 0.; u <= l; u += 0.5 * spacing)
              consider(a + (u / l) * w, c);
          }
      std::sort(found.begin(), found.end(),
                [](const FacePoint &p, const FacePoint &q) { return p.distance < q.distance; });
      return found;
    }

    /// The points of `line` within `length` of its end along it, every `step` from the end back,
    /// each with the index of the segment it lies on (a single point: itself, segment 0).
    std::vector<std::pair<Point, std::size_t>> last_stretch(const Polyline &line, double length, double step)
    {
      std::vector<std::pair<Point, std::size_t>> points;
      if (line.size() == 1)
        points.push_back({line[0], 0});
      double back = 0.; // arc length from the end to line[k + 1]
      for (std::size_t k = line.size() - 1; k-- > 0 && back <= length;)
        {
          const double l = geometry::norm(line[k + 1] - line[k]);
          for (double u = std::ceil(back / step) * step; u <= std::min(back + l, length); u += step)
            points.push_back({line[k + 1] + ((u - back) / l) * (line[k] - line[k + 1]), k});
          back += l;
        }
      return points;
    }
  } // namespace

  CrackTraces::CrackTraces(const std::vector<Polyline> &cracks, const geometry::Body &body, double tolerance)
  {
    for (std::size_t c = 0; c < cracks.size(); ++c)
      {
        Polyline crack = cracks[c];
        if (body.clearance(crack.back()) < body.clearance(crack.front()))
          std::reverse(crack.begin(), crack.end());
        initial.push_back(crack);
        if (body.clearance(crack.back()) > tolerance)
          tips.push_back({c, crack.size(), crack, ""});
        if (body.clearance(crack.front()) > tolerance)
          tips.push_back({c, crack.size(), Polyline(crack.rbegin(), crack.rend()), ""});
      }
  }

  CrackIncrement CrackTraces::trace(const Tip &tip, const DamageField &field, const ExtractionSettings &settings,
                                    double clearance, const std::vector<Polyline> &others) const
  {
    const Point at = tip.path[tip.initial_size - 1], behind = tip.path[tip.initial_size - 2];
    const Point direction = (1. / geometry::norm(at - behind)) * (at - behind);
    if (initial.size() == 1)
      return extract_crack(field, at, direction, settings);
    const DamageField own = without_other_cracks(field, others, tip.crack, crack_path(tip.crack, tips), clearance);
    CrackIncrement    increment;
    try
      {
        increment = extract_crack(own, at, direction, settings);
      }
    catch (const CrackBranching &)
      {
        // Another crack's new growth crosses the band of this tip's accepted path: traced on from
        // the accepted end instead: a point on the crack, not a fresh tip, so its first turn is
        // bound like any step's.
        const Point        end = tip.path.back(), last = tip.path[tip.path.size() - 2];
        ExtractionSettings on_settings = settings;
        on_settings.max_first_turn     = settings.max_turn;
        const auto         on = extract_crack(own, end, (1. / geometry::norm(end - last)) * (end - last), on_settings);
        increment = {Polyline(tip.path.begin() + long(tip.initial_size) - 1, tip.path.end()), on.stop_reason};
        increment.path.insert(increment.path.end(), on.path.begin() + 1, on.path.end());
      }
    return turned_into_face(increment, tip, field, settings, clearance, others);
  }

  CrackIncrement CrackTraces::turned_into_face(CrackIncrement increment, const Tip &tip, const DamageField &field,
                                               const ExtractionSettings &settings, double clearance,
                                               const std::vector<Polyline> &others) const
  {
    if (increment.stop_reason.rfind(ridge_ends, 0) != 0)
      return increment;
    Polyline path(tip.path.begin(), tip.path.begin() + long(tip.initial_size));
    path.insert(path.end(), increment.path.begin() + 1, increment.path.end());
    const Point  ahead = path.back() - path[path.size() - 2];
    const double h     = field.spacing;

    // The shortest connected segment to a face ahead, from a point of the increment's last
    // horizon: the end of a trace can lie past the corner where its ridge turns.
    std::optional<FacePoint> face;
    Point                    start;
    std::size_t              cut = 0;
    for (const auto &[s, k] : last_stretch(increment.path, settings.horizon, 0.5 * h))
      for (const auto &f :
           face_points_ahead(s, ahead, others, tip.crack, face ? face->distance : 3. * settings.horizon, h))
        if (damage_connects(field, s, f.at, settings))
          {
            std::tie(face, start, cut) = std::tuple{f, s, k};
            break;
          }
    if (!face)
      return increment;
    increment.path.resize(cut + 1);
    if (geometry::norm(start - increment.path.back()) > 0.)
      increment.path.push_back(start);
    // It ends `clearance` in front of the face, as a ridge traced into a face does; accept() joins
    // it to the face along its last segment.
    if (const double length = geometry::norm(face->at - start); length > clearance)
      increment.path.push_back(start + ((length - clearance) / length) * (face->at - start));
    increment.stop_reason += "; the damage runs on into crack " + std::to_string(face->crack + 1) + "'s face";
    return increment;
  }

  std::vector<CrackIncrement> CrackTraces::extract(const DamageField &field, const ExtractionSettings &settings,
                                                   double clearance) const
  {
    std::vector<Tip>            traced = tips;
    std::vector<CrackIncrement> increments;
    for (int pass = 0; pass < 3; ++pass)
      {
        const auto others = crack_paths(traced);
        increments.clear();
        bool moved = false;
        for (std::size_t k = 0; k < tips.size(); ++k)
          {
            auto &tip = traced[k];
            if (!tip.stop.empty())
              {
                increments.push_back({{tip.path.back()}, tip.stop});
                continue;
              }
            increments.push_back(trace(tips[k], field, settings, clearance, others));
            Polyline path(tip.path.begin(), tip.path.begin() + long(tip.initial_size));
            path.insert(path.end(), increments.back().path.begin() + 1, increments.back().path.end());
            moved = moved || path.size() != tip.path.size() ||
                    !std::equal(path.begin(), path.end(), tip.path.begin(),
                                [](Point a, Point b) { return a.x == b.x && a.y == b.y; });
            tip.path = path;
          }
        if (!moved || initial.size() == 1)
          break;
      }
    return increments;
  }

  double CrackTraces::traced_length(const std::vector<CrackIncrement> &increments) const
  {
    double total = 0.;
    for (const auto &crack : initial)
      total += geometry::length(crack);
    for (std::size_t k = 0; k < tips.size(); ++k)
      if (tips[k].stop.empty())
        total += increments[k].length();
      else
        total += geometry::length(Polyline(tips[k].path.begin() + long(tips[k].initial_size) - 1, tips[k].path.end()));
    return total;
  }

  std::string CrackTraces::accept(const std::vector<CrackIncrement> &increments, const geometry::Body &body,
                                  double margin, double reach)
  {
    std::vector<Tip> next = tips;
    for (std::size_t k = 0; k < next.size(); ++k)
      {
        auto &tip = next[k];
        if (!tip.stop.empty())
          continue;
        Polyline path(tip.path.begin(), tip.path.begin() + long(tip.initial_size));
        for (std::size_t j = 1; j < increments[k].path.size(); ++j)
          path.push_back(increments[k].path[j]);
        auto arrival = arrive(path, body, margin, reach, tip.initial_size);
        tip.path     = arrival.path;
        tip.stop     = arrival.reason;
        if (!tip.stop.empty() && next.size() > 1)
          tip.stop = "crack " + std::to_string(tip.crack + 1) + " " + tip.stop;
      }
    // Joins, against the other cracks as traced in this state.
    const auto others = crack_paths(next);
    for (std::size_t k = 0; k < next.size(); ++k)
      {
        auto &tip = next[k];
        if (!tips[k].stop.empty())
          continue;
        auto face = first_crossing(tip.path, others, tip.crack);
        if (!face && tip.stop.empty())
          {
            // The last segment continued (within twice the reach: the ridge ends about half a
            // horizon in front of the face, farther along a slanting approach), else the nearest
            // face ahead.
            const Point end = tip.path.back(), e = end - tip.path[tip.path.size() - 2];
            const Point u = (1. / geometry::norm(e)) * e;
            if (const auto [t, c] = ray_to_cracks(end, u, 2. * reach, others, tip.crack); t <= 2. * reach)
              face = CrackMeeting{c, tip.path.size() - 1, end + t * u};
            else
              face = face_ahead(tip.path, others, tip.crack, reach);
          }
        if (!face)
          continue;
        tip.path.resize(face->segment + 1);
        if (geometry::norm(face->at - tip.path.back()) > 0.)
          tip.path.push_back(face->at);
        tip.stop   = "crack " + std::to_string(tip.crack + 1) + " joined crack " + std::to_string(face->crack + 1) +
                   " at " + to_text(face->at);
        any_joined = true;
      }
    tips = next;

    std::string stop;
    bool        all_stopped = true;
    for (const auto &tip : tips)
      {
        all_stopped = all_stopped && !tip.stop.empty();
        if (!tip.stop.empty())
          stop += (stop.empty() ? "" : "; ") + tip.stop;
      }
    return any_joined || all_stopped ? stop : "";
  }

  Polyline CrackTraces::crack_path(std::size_t crack, const std::vector<Tip> &from) const
  {
    const Tip *first = nullptr, *second = nullptr;
    for (const auto &tip : from)
      if (tip.crack == crack)
        (first ? second : first) = &tip;
    if (!first)
      return initial[crack];
    if (!second)
      return first->path;
    Polyline path(second->path.rbegin(), second->path.rend());
    path.insert(path.end(), first->path.begin() + long(first->initial_size), first->path.end());
    return path;
  }

  std::vector<Polyline> CrackTraces::crack_paths(const std::vector<Tip> &from) const
  {
    std::vector<Polyline> paths;
    for (std::size_t c = 0; c < initial.size(); ++c)
      paths.push_back(crack_path(c, from));
    return paths;
  }

  std::vector<Polyline> CrackTraces::paths() const { return crack_paths(tips); }

  double CrackTraces::length() const
  {
    double total = 0.;
    for (const auto &path : paths())
      total += geometry::length(path);
    return total;
  }

  std::vector<Point> CrackTraces::initial_tips() const
  {
    std::vector<Point> at;
    for (const auto &tip : tips)
      at.push_back(tip.path[tip.initial_size - 1]);
    return at;
  }
} // namespace pumpd::coupling
