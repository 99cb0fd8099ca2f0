#include "crack_extraction.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>

#include "arrival.h"
#include "error.h"

namespace pumpd::coupling
{
  using geometry::Point;

  namespace
  {
    const double nan = std::numeric_limits<double>::quiet_NaN();

    Point rotated(Point t, double angle)
    {
      const double c = std::cos(angle), s = std::sin(angle);
      return {c * t.x - s * t.y, s * t.x + c * t.y};
    }

    Point normal(Point t) { return {-t.y, t.x}; }

    /// The nodal damage sampled by bilinear interpolation over the material corners of a point's
    /// cell; NaN where the nearest node is absent (a node stands for its cell).
    class DamageSampler
    {
    public:
      explicit DamageSampler(const DamageField &f)
        : f(f)
      {}

      /// Outside the lattice's cells.
      bool outside(Point p) const
      {
        const double u = (p.x - f.origin.x) / f.spacing, v = (p.y - f.origin.y) / f.spacing;
        return !(u >= -0.5 && v >= -0.5 && u < f.nx - 0.5 && v < f.ny - 0.5);
      }

      /// Interpolated damage; NaN where there is no material (the nearest node is absent).
      double operator()(Point p) const
      {
        if (outside(p))
          return nan;
        const double u = (p.x - f.origin.x) / f.spacing, v = (p.y - f.origin.y) / f.spacing;
        if (!std::isfinite(node(long(std::floor(u + 0.5)), long(std::floor(v + 0.5)))))
          return nan;
        const long   i = std::clamp(long(std::floor(u)), 0L, long(f.nx) - 2);
        const long   j = std::clamp(long(std::floor(v)), 0L, long(f.ny) - 2);
        const double a = std::clamp(u - i, 0., 1.), b = std::clamp(v - j, 0., 1.);
        const double w[4] = {(1 - a) * (1 - b), a * (1 - b), (1 - a) * b, a * b};
        const double d[4] = {node(i, j), node(i + 1, j), node(i, j + 1), node(i + 1, j + 1)};
        double       sum = 0., weight = 0.;
        for (int k = 0; k < 4; ++k)
          if (std::isfinite(d[k]))
          {
            sum += w[k] * d[k];
            weight += w[k];
          }
        return sum / weight; // > 0: the nearest corner has material
      }

    private:
      double node(long i, long j) const { return f.values[std::size_t(j) * f.nx + std::size_t(i)]; }

      const DamageField &f;
    };

    /// A stretch of a transverse profile above the threshold, [begin, end], with the first
    /// moment and the mass of its excess damage D - D_c.
    struct Run
    {
      double begin, end, moment = 0., mass = 0.;
      double centroid() const { return moment / mass; }
    };

    /// Runs of D > D_c across the ridge at q: D averaged over a strip |tau| <= h along t (to damp
    /// noise) at offsets eta n, |eta| <= w, every h/8; each side stops where the material ends.
    /// Gaps shorter than a spacing are closed, runs narrower than a spacing dropped.
    std::vector<Run> transverse_runs(const DamageSampler &damage, Point q, Point t, double w, double h,
                                     double threshold)
    {
      const Point  n     = normal(t);
      const double d_eta = h / 8.;
      const int    k_max = int(std::ceil(w / d_eta));
      int          k_min = 0, k_top = 0;
      while (k_min > -k_max && std::isfinite(damage(q + (k_min - 1) * d_eta * n)))
        --k_min;
      while (k_top < k_max && std::isfinite(damage(q + (k_top + 1) * d_eta * n)))
        ++k_top;

      std::vector<Run> runs;
      for (int k = k_min; k <= k_top; ++k)
      {
        const double eta = k * d_eta;
        double       sum = 0.;
        int          count = 0;
        for (int l = -2; l <= 2; ++l)
        {
          const double d = damage(q + eta * n + (0.5 * h * l) * t);
          if (std::isfinite(d))
          {
            sum += d;
            ++count;
          }
        }
        const double excess = sum / count - threshold;
        if (!(excess > 0.))
          continue;
        if (runs.empty() || eta - runs.back().end >= h)
          runs.push_back({eta, eta});
        runs.back().end = eta;
        runs.back().moment += eta * excess;
        runs.back().mass += excess;
      }
      runs.erase(std::remove_if(runs.begin(), runs.end(), [h](const Run &r) { return r.end - r.begin < h; }),
                 runs.end());
      return runs;
    }

    /// Largest damage within a spacing of x across the ridge; NaN where x has no material.
    double ridge_damage(const DamageSampler &damage, Point x, Point n, double h)
    {
      double top = damage(x);
      if (!std::isfinite(top))
        return nan;
      for (int k = -8; k <= 8; ++k)
      {
        const double d = damage(x + (k * h / 8.) * n);
        if (std::isfinite(d))
          top = std::max(top, d);
      }
      return top;
    }

    /// Damage of the crack faces behind the end of `ridge`: the median ridge damage above the
    /// threshold, sampled every h/2 back along the ridge (continued straight behind its first
    /// vertex, against t0) over a length w. The end of `ridge` lies on the crack.
    double face_damage(const DamageSampler &damage, const geometry::Polyline &ridge, Point t0, double w, double h,
                       double threshold)
    {
      geometry::Polyline back(ridge.rbegin(), ridge.rend());
      back.push_back(ridge.front() - w * t0);
      std::vector<double> on_crack;
      double              start = 0.; // arc length of back[k]
      for (std::size_t k = 0; k + 1 < back.size() && start <= w; ++k)
      {
        const double length = geometry::norm(back[k + 1] - back[k]);
        const Point  e      = (1. / length) * (back[k + 1] - back[k]);
        for (double u = std::ceil(start / (0.5 * h)) * 0.5 * h; u < start + length && u <= w; u += 0.5 * h)
        {
          const double d = ridge_damage(damage, back[k] + (u - start) * e, normal(e), h);
          if (d >= threshold)
            on_crack.push_back(d);
        }
        start += length;
      }
      std::nth_element(on_crack.begin(), on_crack.begin() + on_crack.size() / 2, on_crack.end());
      return on_crack[on_crack.size() / 2];
    }

    /// Douglas-Peucker: keeps the ends and every vertex farther than `tolerance` from the chord.
    void douglas_peucker(const geometry::Polyline &line, std::size_t first, std::size_t last, double tolerance,
                         geometry::Polyline &kept)
    {
      double      far = -1.;
      std::size_t at  = first;
      for (std::size_t k = first + 1; k < last; ++k)
      {
        const double d = geometry::distance_to_segment(line[k], line[first], line[last]);
        if (d > far)
        {
          far = d;
          at  = k;
        }
      }
      if (far > tolerance)
      {
        douglas_peucker(line, first, at, tolerance, kept);
        douglas_peucker(line, at, last, tolerance, kept);
      }
      else
        kept.push_back(line[last]);
    }

    /// Where the trace from p along t ends on one of the faces: the first face point along t
    /// within `reach`, else the faces' point nearest to q when it lies within `nearest` and ahead
    /// of p.
    std::optional<Point> face_reached(Point p, Point t, double reach, Point q, double nearest,
                                      const std::vector<geometry::Polyline> &faces)
    {
      if (const double hit = ray_to_cracks(p, t, reach, faces, faces.size()).first; std::isfinite(hit))
        return p + hit * t;
      std::optional<Point> best;
      double               least = nearest;
      for (const auto &face : faces)
        for (std::size_t k = 0; k + 1 < face.size(); ++k)
          if (const Point x = geometry::nearest_on_segment(q, face[k], face[k + 1]);
              geometry::norm(x - q) < least && geometry::dot(x - p, t) > 0.)
            {
              least = geometry::norm(x - q);
              best  = x;
            }
      return best;
    }

    void check_input(const DamageField &f, Point tip, Point direction, const ExtractionSettings &s)
    {
      require_positive("Damage field spacing", f.spacing);
      if (f.nx < 2 || f.ny < 2)
        throw InvalidParameter("Damage field size", std::to_string(f.nx) + " x " + std::to_string(f.ny),
                               "must be at least 2 x 2 nodes");
      if (f.values.size() != f.nx * f.ny)
        throw InvalidParameter("Damage field values", std::to_string(f.values.size()),
                               "must hold nx * ny = " + std::to_string(f.nx * f.ny) + " values");
      if (!(s.threshold > 0. && s.threshold < 1.))
        throw InvalidParameter("Extraction threshold", to_text(s.threshold), "must lie in (0, 1)");
      const double h = f.spacing;
      for (const auto &[name, v] : {std::pair{"Extraction step", s.step}, {"Search half width", s.search_half_width},
                                    {"Horizon", s.horizon}, {"Simplification tolerance", s.simplification}})
        if (!(v >= 0.) || !std::isfinite(v))
          throw InvalidParameter(name, to_text(v), "must be a finite number >= 0 (0: default)");
      if (s.step > 0. && s.step < 0.5 * h)
        throw InvalidParameter("Extraction step", to_text(s.step),
                               "must be 0 (two spacings) or at least half a spacing, " + to_text(0.5 * h));
      const double w = s.search_half_width > 0. ? s.search_half_width : s.horizon;
      if (w < h)
        throw InvalidParameter("Search half width", to_text(w),
                               "must be at least one spacing, " + to_text(h) +
                                 " (0: the horizon, which must then be given)");
      if (!(s.max_turn > 0. && s.max_turn < 0.5 * std::acos(-1.)))
        throw InvalidParameter("Maximum turn", to_text(s.max_turn), "must lie in (0, pi/2) rad");
      if (!(s.max_first_turn > 0. && s.max_first_turn <= 0.5 * std::acos(-1.)))
        throw InvalidParameter("Maximum first turn", to_text(s.max_first_turn), "must lie in (0, pi/2] rad");
      if (!std::isfinite(direction.x) || !std::isfinite(direction.y) || geometry::norm(direction) == 0.)
        throw InvalidParameter("Tip direction", to_text(direction), "must be a finite, non-zero vector");
      if (!std::isfinite(tip.x) || !std::isfinite(tip.y))
        throw InvalidParameter("Crack tip", to_text(tip), "must be a finite point");
    }
  } // namespace

  CrackIncrement extract_crack(const DamageField &field, Point tip, Point direction, const ExtractionSettings &s)
  {
    check_input(field, tip, direction, s);
    const double      h         = field.spacing;
    const double      step      = s.step > 0. ? s.step : 2. * h;
    const double      w         = s.search_half_width > 0. ? s.search_half_width : s.horizon;
    const double      tolerance = s.simplification > 0. ? s.simplification : 0.5 * h;
    const DamageSampler damage(field);
    if (!std::isfinite(damage(tip)))
      throw InvalidParameter("Crack tip", to_text(tip), "must lie in the material of the damage field");

    // Ridge tracing: predictor along t, corrector to the transverse centroid.
    geometry::Polyline traced{tip};
    const Point        t0        = (1. / geometry::norm(direction)) * direction;
    Point              t         = t0;
    const double       perimeter = 2. * (field.nx + field.ny) * h;
    std::string        reason;
    while (reason.empty())
    {
      const Point p = traced.back(), q = p + step * t;
      if (!std::isfinite(damage(q)))
        break;
      const std::vector<Run> runs = transverse_runs(damage, q, t, w, h, s.threshold);
      // Damage across the predictor (the ridge, or the band of a face it is reaching) and a face
      // ahead: the trace ends on it.
      const bool split = runs.size() > 1;
      if (const auto end = runs.empty() ? std::nullopt
                                        : face_reached(p, t, step + (split ? 2. : 1.) * s.horizon, q,
                                                       split ? 2. * s.horizon : 0., s.faces))
      {
        traced.push_back(*end);
        reason = reaches_face;
        break;
      }
      if (runs.size() > 1)
      {
        std::ostringstream m;
        m << ridge_splits << " into " << runs.size() << " branches across " << to_text(q)
          << " (transverse offsets";
        for (const Run &r : runs)
          m << " " << r.centroid();
        m << " m)";
        if (!s.branch_ends_trace)
          throw CrackBranching(m.str() + ": crack branching is not extracted");
        reason = m.str();
        break;
      }
      if (runs.empty())
        break;
      // A crack kinks at its tip by up to 70.5 degrees (maximum hoop stress criterion): the first
      // step has its own bound, by default what the window reaches, atan(w / step).
      const Point  c     = q + runs.front().centroid() * normal(t);
      const double turn  = std::atan2(geometry::cross(t, c - p), geometry::dot(t, c - p));
      const double limit = traced.size() == 1 ? s.max_first_turn : s.max_turn;
      t                  = rotated(t, std::clamp(turn, -limit, limit));
      traced.push_back(p + geometry::norm(c - p) * t);
      if (geometry::length(traced) > perimeter)
        reason = "the traced ridge is longer than the field's perimeter";
    }

    // The new tip: where the ridge damage drops to half the face damage (at most two steps on),
    // or where the material ends. A node at the tip of a straight crack has a quarter of its bonds
    // cut, half the damage of a face node: that level, unlike the threshold, marks the tip itself.
    if (reason.empty())
    {
      const Point p = traced.back();
      double      u = 0., last = ridge_damage(damage, p, normal(t), h);
      reason        = ridge_ends;
      const bool   on_crack = last >= s.threshold;
      const double level    = on_crack ? 0.5 * face_damage(damage, traced, t0, w, h, s.threshold) : 0.;
      for (int k = 1; on_crack && last >= level && k <= int(std::ceil(16. * step / h)); ++k)
      {
        const Point  x    = p + (k * h / 8.) * t;
        const double next = ridge_damage(damage, x, normal(t), h);
        if (!std::isfinite(next))
        {
          reason = damage.outside(x) ? "the ridge reaches the edge of the damage field"
                                     : "the ridge reaches a region without material (a hole, or beyond the outline)";
          break;
        }
        u = k * h / 8.;
        if (next < level)
          u -= h / 8. * (level - next) / (last - next);
        last = next;
      }
      if (u > 0.)
        traced.push_back(p + u * t);
    }

    CrackIncrement increment{{tip}, reason};
    if (geometry::norm(traced.back() - tip) < h)
    {
      increment.stop_reason += "; no growth (increment below one spacing)";
      return increment;
    }
    douglas_peucker(traced, 0, traced.size() - 1, tolerance, increment.path);
    return increment;
  }

  bool damage_connects(const DamageField &field, Point from, Point to, const ExtractionSettings &s)
  {
    const DamageSampler damage(field);
    const double        h = field.spacing, length = geometry::norm(to - from);
    if (!(length > h))
      return false;
    const Point e = (1. / length) * (to - from);
    for (double u = h; u <= length; u += 0.25 * h)
      if (!(ridge_damage(damage, from + u * e, normal(e), h) >= s.threshold))
        return false;
    return true;
  }
} // namespace pumpd::coupling
