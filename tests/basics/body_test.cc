// The body of a specimen (basics/body.h) against exact answers: containment, clearance, bonds
// across holes and re-entrant corners, rays to the outline and to the holes' margins, and the
// curves fitted to a mesh's boundary edges (segments merged, arcs and circles recovered).
#include <gtest/gtest.h>

#include <cmath>

#include "body.h"

using namespace pumpd::geometry;

namespace
{
  const double pi = std::acos(-1.);

  /// The boundary of a polygon split into edges of at most `step`, appended to v and e.
  void add_polygon(const std::vector<Point> &corners, double step, std::vector<Point> &v,
                   std::vector<std::array<std::size_t, 2>> &e)
  {
    const std::size_t first = v.size();
    for (std::size_t k = 0; k < corners.size(); ++k)
      {
        const Point a = corners[k], b = corners[(k + 1) % corners.size()];
        const int   n = std::max(1, int(std::ceil(norm(b - a) / step)));
        for (int j = 0; j < n; ++j)
          v.push_back(a + (double(j) / n) * (b - a));
      }
    for (std::size_t k = first; k < v.size(); ++k)
      e.push_back({k, k + 1 < v.size() ? k + 1 : first});
  }

  /// A circle as n vertices and edges.
  void add_circle(Point c, double r, int n, std::vector<Point> &v, std::vector<std::array<std::size_t, 2>> &e)
  {
    std::vector<Point> ring;
    for (int k = 0; k < n; ++k)
      ring.push_back(c + r * Point{std::cos(2. * pi * k / n), std::sin(2. * pi * k / n)});
    add_polygon(ring, 1e9, v, e);
  }
} // namespace

TEST(Body, RectangleWithAHole)
{
  const Body body{{0, 0, 4, 2}, {{{1, 1}, 0.5}}};
  EXPECT_TRUE(body.contains({3, 1}));
  EXPECT_TRUE(body.contains({4, 1})); // on the outline
  EXPECT_TRUE(body.contains({1.5, 1})); // on the hole's circle
  EXPECT_FALSE(body.contains({1.2, 1.1}));
  EXPECT_FALSE(body.contains({5, 1}));
  EXPECT_NEAR(body.clearance({3, 1.2}), 0.8, 1e-15);
  EXPECT_NEAR(body.clearance({2, 1}), 0.5, 1e-15);
  EXPECT_NEAR(body.area(), 8. - pi * 0.25, 1e-14);
  // Bonds: through the hole, tangent to it, clear of it.
  EXPECT_TRUE(body.crosses_boundary({0.2, 1.1}, {1.8, 1.1}));
  EXPECT_FALSE(body.crosses_boundary({0.2, 1.5}, {1.8, 1.5}));
  EXPECT_FALSE(body.crosses_boundary({0.2, 0.2}, {3.8, 0.4})); // 0.75 from the centre
  // A crack segment that touches the hole within the allowed depth does not cross it.
  EXPECT_FALSE(body.crosses_boundary({0.2, 1.499}, {1.8, 1.499}, 0.002));
  EXPECT_TRUE(body.crosses_boundary({0.2, 1.49}, {1.8, 1.49}, 0.002));
  // Rays: to the outline, to the hole's margin (the circle of radius 0.5 + margin).
  EXPECT_NEAR(body.ray_to_outline({3, 1}, {1, 0}), 1., 1e-15);
  EXPECT_NEAR(body.ray_to_outline({3, 1}, {0, -1}), 1., 1e-15);
  EXPECT_NEAR(body.ray_to_outline({3, 1}, {std::sqrt(0.5), std::sqrt(0.5)}), std::sqrt(2.), 1e-15);
  const auto hit = body.ray_to_holes({3, 1}, {-1, 0}, 0.1);
  EXPECT_NEAR(hit.t, 3 - 1 - 0.6, 1e-14);
  EXPECT_EQ(hit.hole, 0u);
  EXPECT_EQ(body.ray_to_holes({3, 1}, {1, 0}, 0.1).t, std::numeric_limits<double>::infinity());
  EXPECT_EQ(body.ray_to_holes({1.55, 1}, {1, 0}, 0.1).t, 0.);
  EXPECT_EQ(body.hole_name(0), "the hole at (1, 1)");
}

TEST(Body, MeshBoundaryBecomesSegmentsAndCircles)
{
  std::vector<Point>                      v;
  std::vector<std::array<std::size_t, 2>> e;
  add_polygon({{0, 0}, {0.508, 0}, {0.508, 0.2032}, {0, 0.2032}}, 0.008, v, e);
  add_circle({0.1524, 0.12065}, 0.00635, 32, v, e);
  const Body body = body_from_edges(v, e);
  ASSERT_EQ(body.outline().pieces.size(), 4u);
  for (const auto &p : body.outline().pieces)
    EXPECT_FALSE(p.arc);
  ASSERT_EQ(body.holes().size(), 1u);
  Circle c;
  ASSERT_TRUE(body.holes()[0].circle(c));
  EXPECT_NEAR(c.centre.x, 0.1524, 1e-15);
  EXPECT_NEAR(c.centre.y, 0.12065, 1e-15);
  EXPECT_NEAR(c.radius, 0.00635, 1e-15);
  EXPECT_NEAR(body.area(), 0.508 * 0.2032 - pi * 0.00635 * 0.00635, 1e-15);
  EXPECT_EQ(body.hole_name(0), "the hole at (0.1524, 0.12065)");
}

TEST(Body, ReEntrantCornerOfAnLPanel)
{
  // L-shaped panel [0, 2] x [0, 2] without (1, 2] x (1, 2].
  std::vector<Point>                      v;
  std::vector<std::array<std::size_t, 2>> e;
  add_polygon({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}, 0.1, v, e);
  const Body body = body_from_edges(v, e);
  EXPECT_EQ(body.outline().pieces.size(), 6u);
  EXPECT_TRUE(body.contains({0.5, 1.5}));
  EXPECT_FALSE(body.contains({1.5, 1.5}));
  EXPECT_NEAR(body.area(), 3., 1e-14);
  // A bond across the cut-out leaves the body; one below the corner does not.
  EXPECT_TRUE(body.crosses_boundary({0.9, 1.2}, {1.2, 0.9}));
  EXPECT_FALSE(body.crosses_boundary({0.9, 0.95}, {1.2, 0.9}));
  // From below the corner, rays into the cut-out and along the leg.
  EXPECT_NEAR(body.ray_to_outline({1.5, 0.5}, {0, 1}), 0.5, 1e-14);
  EXPECT_NEAR(body.ray_to_outline({0.5, 0.5}, {0, 1}), 1.5, 1e-14);
  // Below the cut-out its lower side is nearest; diagonally off the corner, the corner.
  EXPECT_NEAR(body.clearance({1.1, 0.9}), 0.1, 1e-14);
  EXPECT_NEAR(body.clearance({0.9, 0.9}), std::hypot(0.1, 0.1), 1e-14);
}

TEST(Body, SemicircularDiscHasAnArcAndADiameter)
{
  std::vector<Point>                      v;
  std::vector<std::array<std::size_t, 2>> e;
  const int                               n = 24;
  for (int k = 0; k <= n; ++k)
    v.push_back({0.05 * std::cos(pi * k / n), 0.05 * std::sin(pi * k / n)});
  for (int k = 1; k < 10; ++k)
    v.push_back({-0.05 + 0.01 * k, 0.});
  for (std::size_t k = 0; k < v.size(); ++k)
    e.push_back({k, (k + 1) % v.size()});
  const Body body = body_from_edges(v, e);
  ASSERT_EQ(body.outline().pieces.size(), 2u);
  const auto &arc = body.outline().pieces[0].arc ? body.outline().pieces[0] : body.outline().pieces[1];
  ASSERT_TRUE(arc.arc);
  EXPECT_NEAR(std::abs(arc.sweep), pi, 1e-12);
  EXPECT_NEAR(arc.radius, 0.05, 1e-15);
  EXPECT_NEAR(body.area(), 0.5 * pi * 0.05 * 0.05, 1e-15);
  EXPECT_TRUE(body.contains({0., 0.049}));
  EXPECT_FALSE(body.contains({0.04, 0.04}));
  EXPECT_NEAR(body.ray_to_outline({0., 0.01}, {0, 1}), 0.04, 1e-14);
  EXPECT_NEAR(body.clearance({0., 0.04}), 0.01, 1e-14);
  const Box b = body.bounding_box();
  EXPECT_NEAR(b.y_max, 0.05, 1e-15);
  EXPECT_NEAR(b.y_min, 0., 1e-15);
}

TEST(Body, ClosedBoundaryRequired)
{
  std::vector<Point>                      v = {{0, 0}, {1, 0}, {1, 1}};
  std::vector<std::array<std::size_t, 2>> e = {{0, 1}, {1, 2}};
  EXPECT_THROW(body_from_edges(v, e), std::invalid_argument);
}
