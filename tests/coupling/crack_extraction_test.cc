// Crack extraction from a PD damage field (coupling/crack_extraction.h), on synthetic fields that
// mimic PD: the damage of a node is the weighted fraction of its bonds (lattice offsets of length
// <= delta, weight 1 or J = 1 - r/delta) whose segment crosses the true crack; bonds to absent
// nodes or through a hole do not exist. The true crack is a pre-existing part behind the current
// tip plus the true increment. Cases: straight (0, 17, 30, 45, -62 degrees), circular arcs,
// a 40-degree kink, kinks at the tip of -53, 60 and -66 degrees (the first segment's direction
// within 3 degrees: pumpd-metric coupling.extraction_kink_err_deg_<kink>; with the first turn
// bound at 45 degrees, the 60-degree kink's first segment at 45 within half a degree), noise
// (+-0.08 and 1 % speckles of damage 0.5 farther than 2 spacings from the crack; fixed seed), a
// tip 1.5 spacings from a hole, a crack leaving the field, m = 4 and m = 8; a branching ridge must
// throw, damage only behind the tip (also with a cluster of damaged nodes ahead of it) is no
// growth, bad settings throw.
// Tolerance: the distance between the extracted polyline and the true increment, both ways (points
// of either curve to the other, sampled every h/10) and tip to tip, is at most one spacing h (the
// lattice resolution). Printed: pumpd-metric coupling.extraction_max_err_over_h.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <optional>
#include <random>

#include "crack_extraction.h"
#include "error.h"
#include "metric.h"

using namespace pumpd;
using namespace pumpd::coupling;
using geometry::Point;
using geometry::Polyline;

namespace
{
  const double pi = std::acos(-1.);
  const double h  = 1e-3; // lattice spacing [m]

  Point along(double degrees) { return {std::cos(degrees * pi / 180.), std::sin(degrees * pi / 180.)}; }

  Point rotated(Point t, double degrees)
  {
    const Point c = along(degrees);
    return {c.x * t.x - c.y * t.y, c.y * t.x + c.x * t.y};
  }

  /// The angle [degrees] from the tip direction d to the increment's first segment, > 0
  /// counter-clockwise.
  double first_segment_angle(const CrackIncrement &inc, Point d)
  {
    const Point first = inc.path[1] - inc.path[0];
    return std::atan2(geometry::cross(d, first), geometry::dot(d, first)) * 180. / pi;
  }

  /// A synthetic PD damage field and the truth it comes from.
  struct Scene
  {
    std::string           name;
    int                   m           = 4;     // delta / h
    bool                  cone_weight = false; // J = 1 - r/delta instead of 1
    std::size_t           nx = 64, ny = 48;
    Point                 tip, direction; // the current tip and its direction
    Polyline              increment;      // the true increment, from the tip
    std::vector<Polyline> cracks;         // every crack line (pre-existing part included)
    std::optional<geometry::Circle> hole;
    bool                            noise = false;

    double delta() const { return m * h; }
  };

  /// Pre-existing straight crack behind the tip (into the field's edge) followed by `increment`.
  Scene make_scene(std::string name, int m, Point tip, Point d, Polyline increment)
  {
    Scene s;
    s.name      = std::move(name);
    s.m         = m;
    s.tip       = tip;
    s.direction = d;
    s.increment = increment;
    Polyline crack{tip - 0.2 * d};
    crack.insert(crack.end(), increment.begin(), increment.end());
    s.cracks = {crack};
    return s;
  }

  Scene straight(double degrees, int m, double length)
  {
    const Point d = along(degrees), tip{0.0203, 0.0241};
    return make_scene("straight " + std::to_string(int(degrees)) + " deg, m " + std::to_string(m), m, tip, d,
                      {tip, tip + length * d});
  }

  /// Circular arc of radius R leaving the tip tangentially, turning by `turn` degrees (left > 0).
  Scene arc(double R, double turn, int m, Point tip, double start_degrees)
  {
    const Point d = along(start_degrees), n = rotated(d, turn > 0 ? 90. : -90.), centre = tip + R * n;
    Polyline    inc;
    for (int k = 0; k <= 200; ++k)
      inc.push_back(centre + R * rotated(-1. * n, turn * k / 200.));
    return make_scene("arc R " + std::to_string(int(std::lround(R / (m * h)))) + " delta, turn " +
                        std::to_string(int(turn)) + " deg, m " + std::to_string(m),
                      m, tip, d, inc);
  }

  DamageField synthetic_damage(const Scene &s, unsigned seed = 1)
  {
    const double delta = s.delta();
    DamageField  f{{0., 0.}, h, s.nx, s.ny, std::vector<double>(s.nx * s.ny, 0.)};
    auto         node     = [&](long i, long j) { return Point{i * h, j * h}; };
    auto         material = [&](Point p) { return !s.hole || geometry::norm(p - s.hole->centre) >= s.hole->radius; };
    auto         to_crack = [&](Point p) {
      double d = std::numeric_limits<double>::max();
      for (const Polyline &c : s.cracks)
        for (std::size_t k = 0; k + 1 < c.size(); ++k)
          d = std::min(d, geometry::distance_to_segment(p, c[k], c[k + 1]));
      return d;
    };

    std::mt19937                           rng(seed);
    std::uniform_real_distribution<double> uniform(0., 1.);
    for (long j = 0; j < long(s.ny); ++j)
      for (long i = 0; i < long(s.nx); ++i)
      {
        const Point x = node(i, j);
        double     &D = f.values[j * s.nx + i];
        if (!material(x))
        {
          D = std::numeric_limits<double>::quiet_NaN();
          continue;
        }
        const double distance = to_crack(x);
        if (distance < delta)
        {
          double total = 0., broken = 0.;
          for (long b = -s.m; b <= s.m; ++b)
            for (long a = -s.m; a <= s.m; ++a)
            {
              const double r = std::hypot(a, b) * h;
              const long   I = i + a, J = j + b;
              if (r == 0. || r > delta * (1 + 1e-12) || I < 0 || J < 0 || I >= long(s.nx) || J >= long(s.ny))
                continue;
              const Point y = node(I, J);
              if (!material(y) || (s.hole && geometry::segment_meets_disk(x, y, *s.hole)))
                continue;
              const double w = s.cone_weight ? 1. - r / delta : 1.;
              total += w;
              for (const Polyline &c : s.cracks)
                if (geometry::segment_crosses_polyline(x, y, c))
                {
                  broken += w;
                  break;
                }
            }
          D = broken / total;
        }
        if (s.noise)
        {
          D = std::clamp(D + 0.16 * (uniform(rng) - 0.5), 0., 1.);
          if (distance > 2. * h && uniform(rng) < 0.01)
            D = 0.5;
        }
      }
    return f;
  }

  double distance_to(Point p, const Polyline &line)
  {
    if (line.size() == 1)
      return geometry::norm(p - line[0]);
    double d = std::numeric_limits<double>::max();
    for (std::size_t k = 0; k + 1 < line.size(); ++k)
      d = std::min(d, geometry::distance_to_segment(p, line[k], line[k + 1]));
    return d;
  }

  /// Largest distance from points of `from` (vertices and every h/10 along it) to `to`.
  double one_way(const Polyline &from, const Polyline &to)
  {
    double worst = distance_to(from[0], to);
    for (std::size_t k = 0; k + 1 < from.size(); ++k)
    {
      const int n = int(std::ceil(geometry::norm(from[k + 1] - from[k]) / (0.1 * h)));
      for (int q = 1; q <= n; ++q)
        worst = std::max(worst, distance_to(from[k] + (double(q) / n) * (from[k + 1] - from[k]), to));
    }
    return worst;
  }

  ExtractionSettings settings_for(const Scene &s)
  {
    ExtractionSettings e;
    e.horizon = s.delta();
    return e;
  }

  std::vector<Scene> scenes()
  {
    std::vector<Scene> all;
    for (double degrees : {0., 17., 30., 45., -62.})
      all.push_back(straight(degrees, 4, 0.024));
    all.push_back(straight(17., 8, 0.032));
    all.back().nx = all.back().ny = 96;
    all.push_back(straight(30., 8, 0.032));
    all.back().cone_weight = true;
    all.back().nx = all.back().ny = 96;
    all.push_back(straight(-62., 4, 0.020));
    all.back().cone_weight = true;

    all.push_back(arc(12 * 0.004, 30., 4, {0.0102, 0.0153}, 10.));
    all.push_back(arc(8 * 0.004, -45., 4, {0.0153, 0.0402}, 5.));
    all.back().cone_weight = true;
    all.push_back(arc(8 * 0.008, 30., 8, {0.0203, 0.0251}, 0.));
    all.back().nx = all.back().ny = 96;

    {
      const Point d = along(8.), tip{0.0102, 0.0203}, kink = tip + 0.008 * d;
      all.push_back(make_scene("kink 40 deg, m 4", 4, tip, d, {tip, kink, kink + 0.014 * rotated(d, 40.)}));
    }
    {
      Scene s = straight(17., 4, 0.024);
      s.name += ", noisy";
      s.noise = true;
      all.push_back(s);
      Scene a = arc(12 * 0.004, 30., 4, {0.0102, 0.0153}, 10.);
      a.name += ", noisy, J";
      a.noise       = true;
      a.cone_weight = true;
      all.push_back(a);
    }
    {
      // The hole's edge 1.5 spacings ahead of the true tip.
      Scene s = straight(17., 4, 0.016);
      s.name += ", hole ahead";
      s.nx = 80;
      s.hole = geometry::Circle{s.increment.back() + (1.5 * h + 3 * s.delta()) * s.direction, 3 * s.delta()};
      all.push_back(s);
    }
    {
      // The crack leaves the field through its right edge x = (nx - 1/2) h: the truth ends there.
      Scene       s = straight(17., 4, 0.060);
      const Point d = s.direction;
      s.name += ", leaves the field";
      s.increment[1] = s.tip + ((s.nx - 0.5) * h - s.tip.x) / d.x * d;
      all.push_back(s);
    }
    return all;
  }
} // namespace

TEST(CrackExtraction, TracesTheTrueIncrementWithinOneSpacing)
{
  double worst = 0.;
  for (const Scene &s : scenes())
  {
    const DamageField    field = synthetic_damage(s);
    const CrackIncrement inc   = extract_crack(field, s.tip, s.direction, settings_for(s));
    const Polyline      &path  = inc.path;
    ASSERT_GE(path.size(), 2u) << s.name << ": " << inc.stop_reason;
    EXPECT_EQ(path[0].x, s.tip.x);
    EXPECT_EQ(path[0].y, s.tip.y);

    const double extracted_to_true = one_way(path, s.increment);
    const double true_to_extracted = one_way(s.increment, path);
    const double tip_to_tip        = geometry::norm(path.back() - s.increment.back());
    const double error             = std::max({extracted_to_true, true_to_extracted, tip_to_tip}) / h;
    worst                          = std::max(worst, error);
    std::cout << s.name << ": " << path.size() << " vertices, length " << inc.length() / h
              << " h (true " << geometry::length(s.increment) / h << " h), error " << error
              << " h (tip " << tip_to_tip / h << " h); " << inc.stop_reason << "\n";
    EXPECT_LE(error, 1.) << s.name;

    // Few vertices (at most one per horizon plus the ends), no backtracking, turns below 45 degrees.
    EXPECT_LE(path.size(), 2 + std::size_t(inc.length() / s.delta())) << s.name;
    EXPECT_FALSE(geometry::self_intersects(path)) << s.name;
    for (std::size_t k = 1; k + 1 < path.size(); ++k)
    {
      const Point a = path[k] - path[k - 1], b = path[k + 1] - path[k];
      EXPECT_GT(geometry::dot(a, b), std::cos(pi / 4.) * geometry::norm(a) * geometry::norm(b)) << s.name;
    }
  }
  test::metric("coupling.extraction_max_err_over_h", worst);
}

// A crack that kinks at the tip by more than the later steps may turn (45 degrees): the first step
// takes the kink, up to what the transverse window reaches (atan(delta / 2h): 63 degrees for m = 4,
// 76 for m = 8). The first segment's direction is the kink a run reports against the maximum hoop
// stress angle (up to 70.5 degrees). Here the true increment is straight, 16 spacings long, and
// the simplified trace one segment: its direction lies within 3 degrees of the true kink (a
// quarter of a spacing across its length subtends 1 degree, one spacing 3.6), and the path and its
// tip within one spacing of the truth.
TEST(CrackExtraction, TheFirstStepTakesTheKinkAtTheTip)
{
  for (const auto &[kink, m] : {std::pair{-53., 4}, {60., 4}, {-66., 8}})
  {
    const Point d = along(10.), tip{0.0203, 0.0241};
    Scene       s = make_scene("kink " + std::to_string(int(kink)) + " deg at the tip, m " + std::to_string(m), m, tip,
                               d, {tip, tip + 0.016 * rotated(d, kink)});
    s.nx = s.ny = 64;
    const CrackIncrement inc = extract_crack(synthetic_damage(s), s.tip, s.direction, settings_for(s));
    ASSERT_GE(inc.path.size(), 2u) << s.name << ": " << inc.stop_reason;
    const double angle = first_segment_angle(inc, d);
    const double error = std::max({one_way(inc.path, s.increment), one_way(s.increment, inc.path),
                                   geometry::norm(inc.path.back() - s.increment.back())}) /
                         h;
    std::cout << s.name << ": first segment " << angle << " deg, path error " << error << " h\n";
    test::metric("coupling.extraction_kink_err_deg_" + std::to_string(int(std::abs(kink))), std::abs(angle - kink));
    EXPECT_NEAR(angle, kink, 3.) << s.name;
    EXPECT_LE(error, 1.) << s.name;
  }
}

// The bound CrackTraces' carry-on sets (Maximum first turn = Maximum turn, 45 degrees): the
// 60-degree kink at the tip is not taken at once, the first segment turns by the bound, within
// half a degree.
TEST(CrackExtraction, AFirstTurnBoundHoldsTheFirstStep)
{
  const Point d = along(10.), tip{0.0203, 0.0241};
  Scene       s = make_scene("kink 60 deg, first turn bound 45 deg", 4, tip, d, {tip, tip + 0.016 * rotated(d, 60.)});
  s.nx = s.ny          = 64;
  ExtractionSettings e = settings_for(s);
  e.max_first_turn     = e.max_turn;
  const CrackIncrement inc = extract_crack(synthetic_damage(s), s.tip, s.direction, e);
  ASSERT_GE(inc.path.size(), 2u) << inc.stop_reason;
  const double angle = first_segment_angle(inc, d);
  std::cout << s.name << ": first segment " << angle << " deg, " << inc.path.size() << " vertices\n";
  EXPECT_NEAR(angle, 45., 0.5);
}

TEST(CrackExtraction, NoGrowthWhenTheDamageLiesBehindTheTip)
{
  for (int m : {4, 8})
  {
    Scene s = straight(17., m, 0.);
    s.increment = {s.tip};
    s.cracks    = {{s.tip - 0.2 * s.direction, s.tip}};
    s.nx = s.ny = 96;
    DamageField          field = synthetic_damage(s);
    const CrackIncrement inc   = extract_crack(field, s.tip, s.direction, settings_for(s));
    EXPECT_EQ(inc.path.size(), 1u) << "m " << m << ": " << inc.stop_reason;
    EXPECT_EQ(inc.length(), 0.);

    // Isolated damaged nodes ahead of the tip (a cluster of three at damage 0.5, two to three
    // spacings on) do not make a crack.
    const Point       x = s.tip + 2.5 * h * s.direction;
    const std::size_t i = std::size_t(std::lround(x.x / h)), j = std::size_t(std::lround(x.y / h));
    for (std::size_t k : {j * s.nx + i, j * s.nx + i + 1, (j + 1) * s.nx + i})
      field.values[k] = 0.5;
    const CrackIncrement speckled = extract_crack(field, s.tip, s.direction, settings_for(s));
    EXPECT_EQ(speckled.path.size(), 1u) << "m " << m << ", speckles ahead: " << speckled.stop_reason;
  }
}

TEST(CrackExtraction, RefusesABranchingRidge)
{
  for (int m : {4, 8})
  {
    const Point d = along(17.), tip{0.0203, 0.0241}, fork = tip + 1.5 * m * h * d;
    Scene       s = make_scene("branching", m, tip, d, {tip, fork, fork + 4. * m * h * rotated(d, 30.)});
    s.cracks.push_back({fork, fork + 4. * m * h * rotated(d, -30.)});
    s.nx = s.ny = 96;
    try
    {
      extract_crack(synthetic_damage(s), s.tip, s.direction, settings_for(s));
      ADD_FAILURE() << "m " << m << ": a branching ridge was traced";
    }
    catch (const CrackBranching &e)
    {
      std::cout << "m " << m << ": " << e.what() << "\n";
      EXPECT_NE(std::string(e.what()).find("branches"), std::string::npos);
    }

    // Asked to, the trace ends where the split is seen instead: on the stem's line, past the fork
    // by less than the window's reach (a horizon) plus two spacings (the branches first lie within
    // one run across the window).
    ExtractionSettings to_the_fork = settings_for(s);
    to_the_fork.branch_ends_trace  = true;
    const auto stem                = extract_crack(synthetic_damage(s), s.tip, s.direction, to_the_fork);
    std::cout << "m " << m << ", to the fork: " << stem.stop_reason << ", end " << geometry::to_text(stem.path.back())
              << " (fork " << geometry::to_text(fork) << ")\n";
    EXPECT_EQ(stem.stop_reason.rfind(ridge_splits, 0), 0u) << stem.stop_reason;
    EXPECT_LT(distance_to(stem.path.back(), {s.tip, fork + 2. * m * h * d}), 0.5 * h);
    EXPECT_GT(geometry::dot(stem.path.back() - fork, d), 0.);
    EXPECT_LT(geometry::norm(stem.path.back() - fork), m * h + 2. * h);
    EXPECT_GT(stem.length(), h);
  }
}

// A ridge running into another crack's face (a T, the other crack at 75 degrees to it, three
// horizons ahead of the tip): given that face, the trace ends on it within a spacing of the true
// meeting point (reason reaches_face); without it, the face's own damage band reads as a branch
// across the window or carries the trace on, and the trace does not end there.
TEST(CrackExtraction, EndsOnAnotherCracksFace)
{
  for (int m : {4, 8})
  {
    const Point    d = along(17.), tip{0.0203, 0.0241}, meeting = tip + 3. * m * h * d;
    const Point    e = rotated(d, 75.);
    const Polyline face{meeting - 0.015 * e, meeting + 0.015 * e};
    Scene          s = make_scene("T", m, tip, d, {tip, meeting});
    s.cracks.push_back(face);
    s.nx = s.ny = 96;
    const DamageField field = synthetic_damage(s);

    ExtractionSettings with_face = settings_for(s);
    with_face.faces              = {face};
    const auto increment         = extract_crack(field, s.tip, s.direction, with_face);
    std::cout << "m " << m << ": " << increment.stop_reason << ", end " << geometry::to_text(increment.path.back())
              << " (meeting " << geometry::to_text(meeting) << ")\n";
    EXPECT_EQ(increment.stop_reason.rfind(reaches_face, 0), 0u) << increment.stop_reason;
    EXPECT_LT(distance_to(increment.path.back(), face), 1e-12);
    EXPECT_LT(geometry::norm(increment.path.back() - meeting), h);

    bool ends_there = false;
    try
    {
      const auto blind = extract_crack(field, s.tip, s.direction, settings_for(s));
      ends_there       = geometry::norm(blind.path.back() - meeting) < h;
      std::cout << "  without the face: " << blind.stop_reason << ", end " << geometry::to_text(blind.path.back()) << "\n";
    }
    catch (const CrackBranching &b)
    {
      std::cout << "  without the face: " << b.what() << "\n";
    }
    EXPECT_FALSE(ends_there) << "m " << m << ": the face changes nothing";
  }
}

TEST(CrackExtraction, RefusesBadSettings)
{
  const Scene        s     = straight(0., 4, 0.01);
  const DamageField  field = synthetic_damage(s);
  ExtractionSettings good  = settings_for(s);
  auto               bad   = [&](auto change) {
    ExtractionSettings e = good;
    change(e);
    return e;
  };
  EXPECT_THROW(extract_crack(field, s.tip, s.direction, bad([](auto &e) { e.threshold = 0.; })), InvalidParameter);
  EXPECT_THROW(extract_crack(field, s.tip, s.direction, bad([](auto &e) { e.threshold = 1.2; })), InvalidParameter);
  EXPECT_THROW(extract_crack(field, s.tip, s.direction, bad([](auto &e) { e.step = -h; })), InvalidParameter);
  EXPECT_THROW(extract_crack(field, s.tip, s.direction, bad([](auto &e) { e.step = 0.1 * h; })), InvalidParameter);
  EXPECT_THROW(extract_crack(field, s.tip, s.direction, bad([](auto &e) { e.horizon = 0.; })), InvalidParameter);
  EXPECT_THROW(extract_crack(field, s.tip, s.direction, bad([](auto &e) { e.search_half_width = NAN; })),
               InvalidParameter);
  EXPECT_THROW(extract_crack(field, s.tip, s.direction, bad([](auto &e) { e.max_turn = 2.; })), InvalidParameter);
  EXPECT_THROW(extract_crack(field, s.tip, s.direction, bad([](auto &e) { e.max_first_turn = 0.; })),
               InvalidParameter);
  EXPECT_THROW(extract_crack(field, s.tip, s.direction, bad([](auto &e) { e.max_first_turn = 1.6; })),
               InvalidParameter);
  EXPECT_THROW(extract_crack(field, s.tip, {0., 0.}, good), InvalidParameter);
  EXPECT_THROW(extract_crack(field, {-1., 0.}, s.direction, good), InvalidParameter);
  DamageField wrong = field;
  wrong.values.pop_back();
  EXPECT_THROW(extract_crack(wrong, s.tip, s.direction, good), InvalidParameter);
  wrong         = field;
  wrong.spacing = 0.;
  EXPECT_THROW(extract_crack(wrong, s.tip, s.direction, good), InvalidParameter);
  EXPECT_NO_THROW(extract_crack(field, s.tip, s.direction, good));
}
