// BoxPolicy (coupling/box_policy.h): placement ahead of the tip, staying put while the tip has
// room, moving when it nears the front, growing for a hole, reaching out to the outline, lattice
// alignment, and the refusals.
#include <gtest/gtest.h>

#include <cmath>

#include "box_policy.h"
#include "error.h"

using namespace pumpd;
using geometry::Body;
using geometry::Box;
using geometry::Point;

namespace
{
  const Body beam{{0., 0., 0.508, 0.2032}, {{{0.1524, 0.12065}, 0.00635}}};

  coupling::BoxSettings settings()
  {
    coupling::BoxSettings s;
    s.horizon  = 0.004;
    s.spacing  = 0.0005;
    s.size     = 0.032;
    s.behind   = 0.3;
    s.margin   = 0.008;
    s.max_size = 0.064;
    return s;
  }

  /// x is on a lattice line x_min(body) + i h (to a relative 1e-9).
  bool on_lattice(double x, double h) { return std::abs(x / h - std::round(x / h)) < 1e-6; }
} // namespace

TEST(BoxPolicy, PlacesTheBoxAheadOfTheTip)
{
  coupling::BoxPolicy policy(beam, settings());
  const Point         tip{0.1016, 0.04}, up{0., 1.};
  const Box           b = policy.place(tip, up);
  EXPECT_TRUE(policy.moved());
  // Tip 0.3 of the side from the rear, centred across (to the lattice snap, one spacing).
  EXPECT_NEAR(tip.y - b.y_min, 0.3 * 0.032, 0.0005 + 1e-12);
  EXPECT_NEAR(0.5 * (b.x_min + b.x_max), tip.x, 0.0005 + 1e-12);
  EXPECT_GE(b.width(), 0.032 - 1e-12);
  for (double e : {b.x_min, b.x_max, b.y_min, b.y_max})
    EXPECT_TRUE(on_lattice(e, 0.0005)) << e;
}

// Box 32 mm, tip 0.3 of it from the rear, delta 4 mm: a crack turned by theta reaches the front
// layer's depth (0.7 * 32 - 8 = 14.4 mm on) 14.4 sin(theta) off the axis, within two horizons of
// a side (16 - 8 = 8 mm) for theta above 33.7 degrees: then the box lies ahead along the turn.
TEST(BoxPolicy, PlacesTheBoxAlongALargeTurn)
{
  const double pi = std::acos(-1.);
  const Point  tip{0.1016, 0.04}, up{0., 1.};
  const auto   turned = [&](double degrees) {
    return Point{std::sin(degrees * pi / 180.), std::cos(degrees * pi / 180.)};
  };
  coupling::BoxPolicy straight(beam, settings()), small(beam, settings()), large(beam, settings());
  const Box           ahead = straight.place(tip, up);
  const Box           kept  = small.place(std::vector{tip}, std::vector{up}, std::vector{turned(30.)});
  EXPECT_EQ(kept.x_min, ahead.x_min);
  EXPECT_EQ(kept.y_min, ahead.y_min);
  const Box along = large.place(std::vector{tip}, std::vector{up}, std::vector{turned(40.)});
  const Point centre{0.5 * (along.x_min + along.x_max), 0.5 * (along.y_min + along.y_max)};
  const Point expected = tip + (0.2 * 0.032) * turned(40.);
  EXPECT_NEAR(centre.x, expected.x, 0.0005 + 1e-12);
  EXPECT_NEAR(centre.y, expected.y, 0.0005 + 1e-12);
}

TEST(BoxPolicy, StaysWhileTheTipHasRoomAndMovesAheadOtherwise)
{
  coupling::BoxPolicy policy(beam, settings());
  const Point         up{0., 1.};
  const Box           first = policy.place({0.1016, 0.04}, up);
  // The box is [0.030, 0.0625] along y (lattice-snapped). 3 mm on: 19.5 mm to the front edge,
  // room for the layer (4 mm) and the margin (8 mm).
  const Box same = policy.place({0.1016, 0.043}, up);
  EXPECT_FALSE(policy.moved());
  EXPECT_EQ(same.y_min, first.y_min);
  // 12 mm on: 10.5 mm to the front edge, less than layer + margin: a new box ahead.
  const Box next = policy.place({0.1016, 0.052}, up);
  EXPECT_TRUE(policy.moved());
  EXPECT_GT(next.y_min, first.y_min);
  EXPECT_EQ(policy.history().size(), 3u);
}

TEST(BoxPolicy, ReachesOutToTheOutlineAndStaysInsideTheBody)
{
  coupling::BoxPolicy policy(beam, settings());
  // Near the top edge, growing upwards: the box would stick out; it is shifted in and its top
  // edge lies on the outline (a free surface, no boundary layer there).
  const Box b = policy.place({0.2, 0.19}, {0., 1.});
  EXPECT_DOUBLE_EQ(b.y_max, beam.bounding_box().y_max);
  EXPECT_TRUE(beam.bounding_box().contains(b, 1e-12));
  // Near the bottom edge at the mouth: the rear edge reaches the bottom (closer than two
  // horizons would leave a sliver).
  const Box c = policy.place({0.3, 0.006}, {0., 1.});
  EXPECT_DOUBLE_EQ(c.y_min, 0.);
}

TEST(BoxPolicy, GrowsToTakeInAHoleWithinReach)
{
  coupling::BoxPolicy policy(beam, settings());
  // Tip 17 mm below the hole's centre: the plain box's front edge would cut the hole.
  const Box b = policy.place({0.1524, 0.1036}, {0., 1.});
  geometry::Circle h;
  ASSERT_TRUE(beam.holes()[0].circle(h));
  EXPECT_LE(b.y_min, h.centre.y - h.radius - 2. * 0.004);
  EXPECT_GE(b.y_max, h.centre.y + h.radius + 2. * 0.004 - 1e-12);
  EXPECT_LE(b.height(), 0.064 + 1e-12);
}

TEST(BoxPolicy, RefusesABoxThatCannotWork)
{
  auto s = settings();
  s.size = 0.02; // < 4 delta + margin = 0.024
  EXPECT_THROW(coupling::BoxPolicy(beam, s), InvalidParameter);
  s.size = 0.3; // larger than the beam's height
  s.max_size = 0.3;
  try
    {
      coupling::BoxPolicy policy(beam, s);
      FAIL() << "a box larger than the body was accepted";
    }
  catch (const InvalidParameter &e)
    {
      EXPECT_NE(std::string(e.what()).find("Box size"), std::string::npos) << e.what();
    }
  s          = settings();
  s.max_size = 0.01;
  EXPECT_THROW(coupling::BoxPolicy(beam, s), InvalidParameter);
}
