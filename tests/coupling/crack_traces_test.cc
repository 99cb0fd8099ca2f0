// The cracks full PD traces (coupling/crack_traces.h), on synthetic PD damage fields: the damage
// of a node is the fraction of its bonds (lattice offsets of length <= delta = 4 h) that cross a
// true crack. A plate 0.1 m x 0.05 m (h = 1 mm) with an edge crack from the left edge at
// y = 0.02 and one from the right edge at y = 0.03, each 30 mm deep:
// - both grow past each other: two paths, in the scene's order, each within one spacing h of its
//   true crack (the lattice resolution; symmetric Hausdorff distance, sampled every h/10);
// - the left crack turns into the right one's face (once the right one has grown past): its path
//   ends on that face within h of where the true crack meets it, the run stops with the join, and
//   the right crack keeps its path within h;
// - the left crack turns by 60 degrees into the right one's face at a corner past which its damage
//   runs on straight for 5 mm (as PD damage runs on past a corner): the tracer follows the straight
//   ridge to its end, where the turned ridge lies outside its window, and the trace joins the face
//   along the damage that connects them (crack_traces.h), within two spacings of where the true
//   crack meets it; the run stops with the join;
// - an interior crack is traced from both tips: one path, within h of the true crack.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "crack_traces.h"
#include "path_metrics.h"

using namespace pumpd;
using namespace pumpd::coupling;
using geometry::Point;
using geometry::Polyline;

namespace
{
  const double              h = 1e-3;
  const int                 m = 4;
  const double              delta = m * h;
  const geometry::Body      plate(geometry::Box{0., 0., 0.1, 0.05});
  const std::vector<Polyline> initial = {{{0., 0.02}, {0.03, 0.02}}, {{0.1, 0.03}, {0.07, 0.03}}};

  DamageField synthetic_damage(const std::vector<Polyline> &cracks)
  {
    const std::size_t nx = 101, ny = 51;
    DamageField       f{{0., 0.}, h, nx, ny, std::vector<double>(nx * ny, 0.)};
    for (long j = 0; j < long(ny); ++j)
      for (long i = 0; i < long(nx); ++i)
        {
          const Point x{i * h, j * h};
          double      total = 0., broken = 0.;
          for (long b = -m; b <= m; ++b)
            for (long a = -m; a <= m; ++a)
              {
                const long I = i + a, J = j + b;
                if ((a == 0 && b == 0) || a * a + b * b > m * m || I < 0 || J < 0 || I >= long(nx) || J >= long(ny))
                  continue;
                const Point y{I * h, J * h};
                total += 1.;
                for (const auto &c : cracks)
                  if (geometry::segment_crosses_polyline(x, y, c))
                    {
                      broken += 1.;
                      break;
                    }
              }
          f.values[std::size_t(j) * nx + std::size_t(i)] = broken / total;
        }
    return f;
  }

  ExtractionSettings extraction()
  {
    ExtractionSettings s;
    s.horizon = delta;
    return s;
  }

  /// Traces `traces` through the damage of `truth` and accepts: "" or why the run stops.
  std::string trace(CrackTraces &traces, const std::vector<Polyline> &truth)
  {
    const auto increments = traces.extract(synthetic_damage(truth), extraction(), 0.5 * delta);
    return traces.accept(increments, plate, 0., delta);
  }

  double hausdorff(const Polyline &a, const Polyline &b) { return path_distance(a, b, 0.1 * h).hausdorff; }
} // namespace

TEST(CrackTraces, TwoCracksGrowPastEachOther)
{
  CrackTraces               traces(initial, plate, 1e-9);
  const std::vector<Polyline> truth = {{{0., 0.02}, {0.06, 0.02}}, {{0.1, 0.03}, {0.04, 0.03}}};
  EXPECT_EQ(trace(traces, truth), "");
  const auto paths = traces.paths();
  ASSERT_EQ(paths.size(), 2u);
  for (std::size_t c = 0; c < 2; ++c)
    {
      EXPECT_EQ(paths[c].front().x, initial[c].front().x) << "crack " << c + 1 << " keeps its mouth first";
      EXPECT_LE(hausdorff(paths[c], truth[c]), h) << "crack " << c + 1 << ": " << geometry::to_text(paths[c]);
    }
  EXPECT_FALSE(traces.joined());
}

TEST(CrackTraces, ATipThatReachesTheOtherCrackJoinsIt)
{
  CrackTraces        traces(initial, plate, 1e-9);
  const Polyline     right = {{0.1, 0.03}, {0.045, 0.03}};
  const Point        meeting{0.06, 0.03};
  EXPECT_EQ(trace(traces, {initial[0], right}), "");
  const std::vector<Polyline> truth = {{{0., 0.02}, {0.045, 0.02}, meeting}, right};
  const std::string           stop  = trace(traces, truth);
  const auto                  paths = traces.paths();
  ASSERT_EQ(paths.size(), 2u);
  std::cout << "stop: " << stop << "\nleft " << geometry::to_text(paths[0]) << "\nright " << geometry::to_text(paths[1])
            << "\n";
  EXPECT_NE(stop.find("crack 1 joined crack 2"), std::string::npos) << stop;
  EXPECT_TRUE(traces.joined());
  EXPECT_LT(distance_to_polyline(paths[0].back(), paths[1]), 1e-12) << "the left path ends on the right crack";
  EXPECT_LE(geometry::norm(paths[0].back() - meeting), h);
  EXPECT_LE(hausdorff(paths[1], right), h);
}

TEST(CrackTraces, ARidgeThatTurnsIntoTheOtherCrackJoinsIt)
{
  CrackTraces    traces(initial, plate, 1e-9);
  const Polyline right = {{0.1, 0.03}, {0.045, 0.03}};
  const Point    corner{0.05, 0.02};
  const Polyline left    = {initial[0].front(), corner, corner + Point{0.005, 0.}};
  const Point    meeting = corner + 0.01 * Point{1. / std::tan(std::acos(-1.) / 3.), 1.};
  EXPECT_EQ(trace(traces, {left, right}), "");
  const std::string stop  = trace(traces, {left, {corner, meeting}, right});
  const auto        paths = traces.paths();
  ASSERT_EQ(paths.size(), 2u);
  std::cout << "stop: " << stop << "\nleft " << geometry::to_text(paths[0]) << "\n";
  EXPECT_NE(stop.find("crack 1 joined crack 2"), std::string::npos) << stop;
  EXPECT_TRUE(traces.joined());
  EXPECT_LT(distance_to_polyline(paths[0].back(), paths[1]), 1e-12) << "the left path ends on the right crack";
  EXPECT_LE(geometry::norm(paths[0].back() - meeting), 2. * h);
  EXPECT_LE(hausdorff(paths[1], right), h);
}

TEST(CrackTraces, AnInteriorCrackGrowsFromBothTips)
{
  CrackTraces    traces({{{0.04, 0.025}, {0.06, 0.025}}}, plate, 1e-9);
  const Polyline truth = {{0.03, 0.025}, {0.07, 0.025}};
  EXPECT_EQ(traces.initial_tips().size(), 2u);
  EXPECT_EQ(trace(traces, {truth}), "");
  const auto paths = traces.paths();
  ASSERT_EQ(paths.size(), 1u);
  EXPECT_LE(hausdorff(paths[0], truth), h) << geometry::to_text(paths[0]);
}
