#include "path_metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "error.h"

namespace pumpd::coupling
{
  using geometry::Point;

  double distance_to_polyline(Point p, const geometry::Polyline &line)
  {
    if (line.empty())
      return std::numeric_limits<double>::infinity();
    double d = geometry::norm(p - line.front());
    for (std::size_t k = 0; k + 1 < line.size(); ++k)
      d = std::min(d, geometry::distance_to_segment(p, line[k], line[k + 1]));
    return d;
  }

  double directed_max_distance(const geometry::Polyline &from, const geometry::Polyline &to)
  {
    double worst = 0.;
    for (const auto &x : from)
      worst = std::max(worst, distance_to_polyline(x, to));
    return worst;
  }

  geometry::Polyline truncate(const geometry::Polyline &line, double length)
  {
    geometry::Polyline out;
    if (line.empty())
      return out;
    out.push_back(line.front());
    double s = 0.;
    for (std::size_t k = 0; k + 1 < line.size(); ++k)
      {
        const double l = geometry::norm(line[k + 1] - line[k]);
        if (s + l >= length)
          {
            if (length > s)
              out.push_back(line[k] + ((length - s) / l) * (line[k + 1] - line[k]));
            return out;
          }
        s += l;
        out.push_back(line[k + 1]);
      }
    return out;
  }

  geometry::Polyline up_to_nearest(const geometry::Polyline &line, Point x)
  {
    if (line.size() < 2)
      return line;
    std::size_t best_k = 0;
    double      best_t = 0., best_d = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k + 1 < line.size(); ++k)
      {
        const Point  e  = line[k + 1] - line[k];
        const double ll = geometry::dot(e, e);
        const double t  = ll > 0. ? std::clamp(geometry::dot(x - line[k], e) / ll, 0., 1.) : 0.;
        const double d  = geometry::norm(x - (line[k] + t * e));
        if (d < best_d)
          best_d = d, best_k = k, best_t = t;
      }
    geometry::Polyline out(line.begin(), line.begin() + best_k + 1);
    if (best_t > 0.)
      out.push_back(line[best_k] + best_t * (line[best_k + 1] - line[best_k]));
    return out;
  }

  namespace
  {
    /// Points every `step` along the polyline (segment ends included), each with the arc length
    /// it stands for (trapezoidal weights).
    void sample(const geometry::Polyline &line, double step, std::vector<Point> &x, std::vector<double> &w)
    {
      for (std::size_t k = 0; k + 1 < line.size(); ++k)
        {
          const double l = geometry::norm(line[k + 1] - line[k]);
          const int    n = std::max(1, int(std::ceil(l / step)));
          for (int j = (k == 0 ? 0 : 1); j <= n; ++j)
            {
              x.push_back(line[k] + (double(j) / n) * (line[k + 1] - line[k]));
              w.push_back(l / n * ((j == 0 || j == n) ? 0.5 : 1.));
            }
        }
    }

    void directed(const geometry::Polyline &a, const geometry::Polyline &b, double step, double &mean, double &max)
    {
      std::vector<Point>  x;
      std::vector<double> w;
      sample(a, step, x, w);
      double sum = 0., weight = 0.;
      max        = 0.;
      for (std::size_t i = 0; i < x.size(); ++i)
        {
          const double d = distance_to_polyline(x[i], b);
          sum += w[i] * d;
          weight += w[i];
          max = std::max(max, d);
        }
      mean = weight > 0. ? sum / weight : 0.;
    }
  } // namespace

  PathDistance path_distance(const geometry::Polyline &a, const geometry::Polyline &b, double step)
  {
    if (!(step > 0.))
      throw InvalidParameter("path sampling step", std::to_string(step), "must be > 0");
    if (a.size() < 2 || b.size() < 2)
      throw InvalidParameter("path", std::to_string(std::min(a.size(), b.size())) + " points",
                             "a path needs at least 2 points");
    double mean_ab, max_ab, mean_ba, max_ba;
    directed(a, b, step, mean_ab, max_ab);
    directed(b, a, step, mean_ba, max_ba);
    return {0.5 * (mean_ab + mean_ba), std::max(max_ab, max_ba)};
  }

  PathDistance published_distance(const geometry::Polyline &path, const geometry::Polyline &published, double step)
  {
    return path_distance(up_to_nearest(path, published.back()), published, step);
  }

  PathDistance trade_distance(const geometry::Polyline &a, const geometry::Polyline &b)
  {
    const bool   a_longer = geometry::length(a) > geometry::length(b);
    const auto  &shorter  = a_longer ? b : a, &longer = a_longer ? a : b;
    const double cut      = geometry::length(up_to_nearest(longer, shorter.back()));
    const double step     = std::max(geometry::length(shorter), cut) / 1000.;
    return published_distance(longer, shorter, std::max(step, 1e-9));
  }
} // namespace pumpd::coupling
