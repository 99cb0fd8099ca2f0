// The crack of the global problem: tips, level set, (r, theta) and branch functions against closed
// forms and finite differences, growth, and refusal of every invalid input.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "crack.h"
#include "error.h"

using namespace pumpd;
using namespace pumpd::global;
using geometry::Body;
using geometry::Polyline;

namespace
{
  constexpr double tol = 1e-9;

  const Body plate{{0., 0., 2., 1.}, {}};
  const Body holed_plate{{0., 0., 2., 1.}, {{{1.2, 0.5}, 0.1}}};

  Crack edge_crack() { return Crack({{0., 0.5}, {0.6, 0.5}}, plate, tol); }
  Crack interior_crack() { return Crack({{0.5, 0.5}, {1.5, 0.5}}, plate, tol); }
  /// Edge crack from the left edge, kinked by +45 degrees 0.1 sqrt(2) behind its tip at (0.7, 0.6).
  Crack kinked_crack() { return Crack({{0., 0.5}, {0.6, 0.5}, {0.7, 0.6}}, plate, tol); }

  void expect_point(Point actual, Point expected, double eps)
  {
    EXPECT_NEAR(actual.x, expected.x, eps);
    EXPECT_NEAR(actual.y, expected.y, eps);
  }

  /// f must throw InvalidParameter whose what() starts with "Crack" and contains `reason`.
  void expect_invalid(const std::function<void()> &f, const std::string &reason)
  {
    try
      {
        f();
        ADD_FAILURE() << "no exception; expected InvalidParameter: " << reason;
      }
    catch (const InvalidParameter &e)
      {
        const std::string what = e.what();
        EXPECT_EQ(what.rfind("Crack", 0), 0u) << "message does not name the crack: " << what;
        EXPECT_NE(what.find(reason), std::string::npos) << "no \"" << reason << "\" in: " << what;
      }
    catch (const std::exception &e)
      {
        ADD_FAILURE() << "wrong exception type (" << e.what() << "); expected InvalidParameter: " << reason;
      }
  }
} // namespace

TEST(Crack, EdgeCrackHasOneTip)
{
  const Crack c = edge_crack();
  ASSERT_EQ(c.tips().size(), 1u);
  expect_point(c.tips()[0].position, {0.6, 0.5}, 0.);
  expect_point(c.tips()[0].direction, {1., 0.}, 0.);
  EXPECT_EQ(c.tips()[0].vertex, 1u);
  EXPECT_DOUBLE_EQ(c.length(), 0.6);
  EXPECT_EQ(c.nearest_tip({1.9, 0.9}), 0u);
}

TEST(Crack, InteriorCrackHasTwoOppositeTips)
{
  const Crack c = interior_crack();
  ASSERT_EQ(c.tips().size(), 2u);
  expect_point(c.tips()[0].position, {0.5, 0.5}, 0.);
  expect_point(c.tips()[0].direction, {-1., 0.}, 0.);
  EXPECT_EQ(c.tips()[0].vertex, 0u);
  expect_point(c.tips()[1].position, {1.5, 0.5}, 0.);
  expect_point(c.tips()[1].direction, {1., 0.}, 0.);
  EXPECT_EQ(c.tips()[1].vertex, 1u);
  EXPECT_DOUBLE_EQ(c.length(), 1.);
  EXPECT_EQ(c.nearest_tip({0.4, 0.9}), 0u);
  EXPECT_EQ(c.nearest_tip({1.1, 0.1}), 1u);

  const Crack oblique({{0.5, 0.1}, {1.1, 0.9}}, plate, tol);
  ASSERT_EQ(oblique.tips().size(), 2u);
  expect_point(oblique.tips()[0].direction, {-0.6, -0.8}, 1e-15);
  expect_point(oblique.tips()[1].direction, {0.6, 0.8}, 1e-15);
  EXPECT_NEAR(oblique.length(), 1., 1e-15);
}

TEST(Crack, LevelSetIsTheSignedDistanceToTheExtendedCrack)
{
  const Crack c = edge_crack();
  EXPECT_NEAR(c.signed_distance({0.3, 0.7}), 0.2, 1e-15);   // left of the crack walked from the mouth
  EXPECT_NEAR(c.signed_distance({0.3, 0.4}), -0.1, 1e-15);
  EXPECT_NEAR(c.signed_distance({0.6, 0.9}), 0.4, 1e-15);   // above the tip
  EXPECT_NEAR(c.signed_distance({1.2, 0.55}), 0.05, 1e-15); // ahead: distance to the extension line
  EXPECT_NEAR(c.signed_distance({1.5, 0.3}), -0.2, 1e-15);
  EXPECT_EQ(c.side({0.3, 0.5 + 1e-12}), 1);
  EXPECT_EQ(c.side({0.3, 0.5 - 1e-12}), -1);
  EXPECT_EQ(c.side({0.3, 0.5}), 1); // on the crack: phi = 0
  EXPECT_EQ(c.side({1.0, 0.5 + 1e-12}), 1);
  EXPECT_EQ(c.side({1.0, 0.5 - 1e-12}), -1);

  // Interior crack: the extensions at both tips make phi = y - 0.5 everywhere.
  const Crack i = interior_crack();
  EXPECT_NEAR(i.signed_distance({0.1, 0.8}), 0.3, 1e-15);
  EXPECT_NEAR(i.signed_distance({1.9, 0.2}), -0.3, 1e-15);
  EXPECT_NEAR(i.signed_distance({1.0, 0.45}), -0.05, 1e-15);

  // Kinked crack (left turn at (0.6, 0.5)): outside the turn the nearest point is the kink vertex and
  // the pseudo-normal gives the sign; inside it the nearest point is on the first segment; ahead of
  // the tip phi is the signed distance to the line y = x - 0.1.
  const Crack k = kinked_crack();
  EXPECT_NEAR(k.signed_distance({0.65, 0.45}), -std::sqrt(0.005), 1e-15);
  EXPECT_NEAR(k.signed_distance({0.9, 0.2}), -std::sqrt(0.18), 1e-15);
  EXPECT_NEAR(k.signed_distance({0.55, 0.55}), 0.05, 1e-15);
  EXPECT_NEAR(k.signed_distance({1.0, 0.7}), -0.2 / std::sqrt(2.), 1e-15);
  EXPECT_NEAR(k.signed_distance({0.8, 0.9}), 0.2 / std::sqrt(2.), 1e-15);
  EXPECT_NEAR(k.signed_distance({0.45, 0.35}), -0.15, 1e-15); // on the extension behind the kink

  // A kink sharper than 90 degrees: outside it neither segment's own normal gives the side, the
  // pseudo-normal does (x is right of the polyline, 0.1 from the kink at 45 degrees).
  const Crack sharp({{0.2, 0.5}, {1.0, 0.5}, {0.6, 0.7}}, plate, tol);
  const double q = 0.1 / std::sqrt(2.);
  EXPECT_NEAR(sharp.signed_distance({1.0 + q, 0.5 + q}), -0.1, 1e-15);
  EXPECT_NEAR(sharp.signed_distance({1.0 - q, 0.5 - q}), -q, 1e-15);
  EXPECT_NEAR(sharp.signed_distance({0.4, 0.55}), 0.05, 1e-15);
}

TEST(Crack, ThetaIsPlusMinusPiOnTheFacesAndZeroAhead)
{
  const Crack c     = edge_crack();
  const auto  above = c.polar({0.3, 0.5 + 1e-10}, 0);
  EXPECT_NEAR(above[0], 0.3, 1e-12);
  EXPECT_NEAR(above[1], M_PI, 1e-9);
  EXPECT_NEAR(c.polar({0.3, 0.5 - 1e-10}, 0)[1], -M_PI, 1e-9);
  EXPECT_NEAR(c.polar({1.0, 0.5 + 1e-10}, 0)[1], 0., 1e-9);
  EXPECT_NEAR(c.polar({1.0, 0.5 - 1e-10}, 0)[1], 0., 1e-9);
  const auto up = c.polar({0.6, 0.9}, 0), down = c.polar({0.6, 0.1}, 0);
  EXPECT_NEAR(up[0], 0.4, 1e-15);
  EXPECT_NEAR(up[1], M_PI / 2., 1e-15);
  EXPECT_NEAR(down[0], 0.4, 1e-15);
  EXPECT_NEAR(down[1], -M_PI / 2., 1e-15);
  const auto at_tip = c.polar({0.6, 0.5}, 0);
  EXPECT_EQ(at_tip[0], 0.);
  EXPECT_EQ(at_tip[1], 0.);

  // theta carries the sign of side(x) at both tips: at the tip at vertex 0 (direction -x) theta is
  // +pi above the faces too, i.e. measured clockwise from its direction.
  const Crack i = interior_crack();
  for (std::size_t t = 0; t < 2; ++t)
    {
      EXPECT_NEAR(i.polar({1.0, 0.5 + 1e-10}, t)[1], M_PI, 1e-9);
      EXPECT_NEAR(i.polar({1.0, 0.5 - 1e-10}, t)[1], -M_PI, 1e-9);
    }
  EXPECT_NEAR(i.polar({0.2, 0.5 + 1e-10}, 0)[1], 0., 1e-9);
  EXPECT_NEAR(i.polar({1.8, 0.5 - 1e-10}, 1)[1], 0., 1e-9);
  EXPECT_NEAR(i.polar({0.5, 0.8}, 0)[1], M_PI / 2., 1e-15);
}

TEST(Crack, ThetaJumpsOnlyAcrossTheFacesOfAKinkedCrack)
{
  const Crack  k   = kinked_crack();
  const Point  tip = k.tips()[0].position, d = k.tips()[0].direction;
  const double eps = 1e-10;

  // Across the faces theta jumps by 2 acos((x - tip).d / r): from + above (left) to - below.
  for (const Point f : {Point{0.1, 0.5}, Point{0.3, 0.5}, Point{0.55, 0.5}})
    {
      const Point  v     = f - tip;
      const double angle = std::acos(dot(v, d) / norm(v));
      EXPECT_NEAR(k.polar({f.x, f.y + eps}, 0)[1], angle, 1e-8);
      EXPECT_NEAR(k.polar({f.x, f.y - eps}, 0)[1], -angle, 1e-8);
    }
  const Point n{-d.y, d.x};
  for (const Point f : {Point{0.62, 0.52}, Point{0.68, 0.58}})
    {
      EXPECT_NEAR(k.polar(f + eps * n, 0)[1], M_PI, 1e-8);
      EXPECT_NEAR(k.polar(f - eps * n, 0)[1], -M_PI, 1e-8);
    }

  // The straight extension of the last segment behind the tip (y = x - 0.1, x < 0.6) is intact
  // material below the crack: theta is continuous across it (about -pi on both sides).
  for (const Point e : {Point{0.2, 0.1}, Point{0.35, 0.25}, Point{0.5, 0.4}})
    {
      const double t1 = k.polar(e + eps * n, 0)[1], t2 = k.polar(e - eps * n, 0)[1];
      EXPECT_NEAR(t1, t2, 1e-8);
      EXPECT_NEAR(t1, -M_PI, 1e-8);
      const auto f1 = k.branch_functions(e + eps * n, 0), f2 = k.branch_functions(e - eps * n, 0);
      for (std::size_t i = 0; i < 4; ++i)
        EXPECT_NEAR(f1.value[i], f2.value[i], 1e-8);
    }
}

TEST(Crack, BranchFunctionsMatchClosedForms)
{
  const Crack  c  = edge_crack();
  const double sr = std::sqrt(0.4);

  // On the faces (theta = +-pi): F1 = +-sqrt(r), F2 = F3 = F4 = 0.
  const auto above = c.branch_functions({0.2, 0.5 + 1e-12}, 0);
  const auto below = c.branch_functions({0.2, 0.5 - 1e-12}, 0);
  EXPECT_NEAR(above.value[0], sr, 1e-10);
  EXPECT_NEAR(below.value[0], -sr, 1e-10);
  for (std::size_t i = 1; i < 4; ++i)
    {
      EXPECT_NEAR(above.value[i], 0., 1e-10);
      EXPECT_NEAR(below.value[i], 0., 1e-10);
    }

  // theta = pi/2, r = 0.4: sin(t/2) = cos(t/2) = 1/sqrt(2), sin t = 1.
  const auto up = c.branch_functions({0.6, 0.9}, 0);
  for (std::size_t i = 0; i < 4; ++i)
    EXPECT_NEAR(up.value[i], sr / std::sqrt(2.), 1e-15);

  // theta = -2 pi / 3, r = 0.25.
  const double theta = -2. * M_PI / 3.;
  const auto   f     = c.branch_functions({0.6 + 0.25 * std::cos(theta), 0.5 + 0.25 * std::sin(theta)}, 0);
  const double s2 = std::sin(theta / 2.), c2 = std::cos(theta / 2.), s = std::sin(theta);
  EXPECT_NEAR(f.value[0], 0.5 * s2, 1e-15);
  EXPECT_NEAR(f.value[1], 0.5 * c2, 1e-15);
  EXPECT_NEAR(f.value[2], 0.5 * s2 * s, 1e-15);
  EXPECT_NEAR(f.value[3], 0.5 * c2 * s, 1e-15);

  // Straight ahead, r = 0.25 (theta = 0, grad theta = n / r): grad F1 = n / (2 sqrt r),
  // grad F2 = d / (2 sqrt r), grad F3 = 0, grad F4 = n / sqrt r.
  const auto ahead = c.branch_functions({0.85, 0.5}, 0);
  EXPECT_NEAR(ahead.value[1], 0.5, 1e-15);
  expect_point(ahead.gradient[0], {0., 1.}, 1e-14);
  expect_point(ahead.gradient[1], {1., 0.}, 1e-14);
  expect_point(ahead.gradient[2], {0., 0.}, 1e-14);
  expect_point(ahead.gradient[3], {0., 2.}, 1e-14);

  // On the line y' = 0 ahead of the tip at vertex 0 of the interior crack (d = -x, n = -y): side = +1
  // (phi = 0) but the + side is y' < 0, where theta = -alpha: grad theta = -n / r, as its neighbours.
  const auto ahead0 = interior_crack().branch_functions({0.25, 0.5}, 0);
  expect_point(ahead0.gradient[0], {0., 1.}, 1e-14);
  expect_point(ahead0.gradient[1], {-1., 0.}, 1e-14);
  expect_point(ahead0.gradient[2], {0., 0.}, 1e-14);
  expect_point(ahead0.gradient[3], {0., 2.}, 1e-14);

  // At the tip itself: zero values and gradients.
  const auto at_tip = c.branch_functions({0.6, 0.5}, 0);
  for (std::size_t i = 0; i < 4; ++i)
    {
      EXPECT_EQ(at_tip.value[i], 0.);
      EXPECT_EQ(at_tip.gradient[i].x, 0.);
      EXPECT_EQ(at_tip.gradient[i].y, 0.);
    }
}

TEST(Crack, BranchFunctionGradientsMatchFiniteDifferences)
{
  // Edge, interior, kinked edge, and a curved interior crack kinked both ways.
  const std::vector<Crack> cracks = {edge_crack(), interior_crack(), kinked_crack(),
                                     Crack({{0.3, 0.2}, {0.9, 0.4}, {1.2, 0.8}, {1.5, 0.7}}, plate, tol)};
  const double h = 1e-6, margin = 1e-4;
  std::mt19937 rng(20240611);
  std::uniform_real_distribution<double> ux(0., 2.), uy(0., 1.);

  for (std::size_t c = 0; c < cracks.size(); ++c)
    for (std::size_t t = 0; t < cracks[c].tips().size(); ++t)
      {
        const Crack &k   = cracks[c];
        const Tip   &tip = k.tips()[t];
        // Where theta is not smooth: the faces; the straight line behind the tip (a jump on the
        // faces, a kink in theta elsewhere: theta = side |polar angle|); the rays ahead of the other
        // tips (side() changes sign there, theta does not vanish).
        const auto away_from_cuts = [&](Point x) {
          for (std::size_t s = 0; s + 1 < k.vertices().size(); ++s)
            if (geometry::distance_to_segment(x, k.vertices()[s], k.vertices()[s + 1]) < margin)
              return false;
          if (geometry::distance_to_segment(x, tip.position, tip.position - 10. * tip.direction) < margin)
            return false;
          for (std::size_t o = 0; o < k.tips().size(); ++o)
            if (o != t)
              {
                const Tip &other = k.tips()[o];
                if (geometry::distance_to_segment(x, other.position, other.position + 10. * other.direction) <
                    margin)
                  return false;
              }
          return true;
        };

        int tested = 0;
        for (int sample = 0; sample < 2000; ++sample)
          {
            const Point  x{ux(rng), uy(rng)};
            const double r = norm(x - tip.position);
            if (r < 0.05 || !away_from_cuts(x))
              continue;
            ++tested;
            const auto f  = k.branch_functions(x, t);
            const auto xp = k.branch_functions({x.x + h, x.y}, t), xm = k.branch_functions({x.x - h, x.y}, t);
            const auto yp = k.branch_functions({x.x, x.y + h}, t), ym = k.branch_functions({x.x, x.y - h}, t);
            for (std::size_t i = 0; i < 4; ++i)
              {
                const Point fd{(xp.value[i] - xm.value[i]) / (2. * h), (yp.value[i] - ym.value[i]) / (2. * h)};
                // |grad F| scales as 1 / sqrt(r).
                EXPECT_LT(norm(fd - f.gradient[i]), 1e-6 / std::sqrt(r))
                  << "crack " << c << ", tip " << t << ", F" << i + 1 << " at (" << x.x << ", " << x.y << ")";
              }
          }
        EXPECT_GT(tested, 1500) << "crack " << c << ", tip " << t;
      }
}

TEST(Crack, GrowthMovesTheTip)
{
  Crack c = edge_crack();
  c.grow(0, {0.8, 0.6});
  ASSERT_EQ(c.vertices().size(), 3u);
  ASSERT_EQ(c.tips().size(), 1u);
  expect_point(c.tips()[0].position, {0.8, 0.6}, 0.);
  expect_point(c.tips()[0].direction, {2. / std::sqrt(5.), 1. / std::sqrt(5.)}, 1e-15);
  EXPECT_EQ(c.tips()[0].vertex, 2u);
  EXPECT_NEAR(c.length(), 0.6 + std::sqrt(0.05), 1e-15);
  // The level set follows the new segment: ahead of the tip, the line through it along (2, 1).
  EXPECT_NEAR(c.signed_distance({1.0, 0.7}), 0., 1e-15);
  EXPECT_NEAR(c.signed_distance({1.2, 0.9}), 0.2 / std::sqrt(5.), 1e-15);
  EXPECT_NEAR(c.polar({1.0, 0.7}, 0)[1], 0., 1e-7);

  // Growth at the tip at vertex 0 prepends a vertex.
  Crack i = interior_crack();
  i.grow(0, {0.3, 0.6});
  ASSERT_EQ(i.tips().size(), 2u);
  expect_point(i.vertices().front(), {0.3, 0.6}, 0.);
  expect_point(i.tips()[0].position, {0.3, 0.6}, 0.);
  expect_point(i.tips()[0].direction, {-2. / std::sqrt(5.), 1. / std::sqrt(5.)}, 1e-15);
  EXPECT_EQ(i.tips()[0].vertex, 0u);
  EXPECT_EQ(i.tips()[1].vertex, 2u);
  expect_point(i.tips()[1].position, {1.5, 0.5}, 0.);
}

TEST(Crack, GrowthAcrossTheCrackOutOfTheBodyOrIntoAHoleIsRefused)
{
  Crack c = edge_crack();
  c.grow(0, {0.8, 0.6});
  expect_invalid([&] { c.grow(0, {0.3, 0.4}); }, "crosses the crack");
  EXPECT_EQ(c.vertices().size(), 3u); // unchanged
  expect_point(c.tips()[0].position, {0.8, 0.6}, 0.);

  Crack s = edge_crack();
  expect_invalid([&] { s.grow(0, {0.4, 0.5}); }, "folds back");
  expect_invalid([&] { s.grow(0, {2.5, 0.5}); }, "leaves the body outline");
  expect_invalid([&] { s.grow(0, {0.6, 0.5}); }, "must differ from the tip");
  expect_invalid([&] { s.grow(1, {0.8, 0.5}); }, "number of tips");
  EXPECT_EQ(s.vertices().size(), 2u);

  Crack i({{0.5, 0.5}, {1.0, 0.5}, {1.2, 0.7}}, plate, tol);
  expect_invalid([&] { i.grow(1, {0.7, 0.3}); }, "crosses the crack");
  expect_invalid([&] { i.grow(0, {1.1, 0.55}); }, "crosses the crack");

  Crack h({{0., 0.5}, {0.6, 0.5}}, holed_plate, tol);
  expect_invalid([&] { h.grow(0, {1.4, 0.5}); }, "enters a hole");
  expect_invalid([&] { h.grow(0, {1.15, 0.52}); }, "enters a hole");
  h.grow(0, {1.05, 0.5});
  expect_point(h.tips()[0].position, {1.05, 0.5}, 0.);
}

TEST(Crack, ReachingTheOutlineRemovesTheTip)
{
  Crack i = interior_crack();
  i.grow(1, {2.0, 0.6});
  ASSERT_EQ(i.tips().size(), 1u);
  EXPECT_EQ(i.tips()[0].vertex, 0u);
  expect_point(i.tips()[0].position, {0.5, 0.5}, 0.);
  EXPECT_EQ(i.nearest_tip({1.9, 0.6}), 0u);

  // The remaining tip reaches the left edge: the body is cut through, no tip is left.
  i.grow(0, {0., 0.4});
  EXPECT_TRUE(i.tips().empty());
  expect_invalid([&] { i.nearest_tip({1., 0.5}); }, "at least one tip");

  Crack e = edge_crack();
  e.grow(0, {2.0 + 0.5 * tol, 0.5});
  EXPECT_TRUE(e.tips().empty());
}

TEST(Crack, InvalidInputIsRefused)
{
  expect_invalid([] { Crack({}, plate, tol); }, "at least 2 vertices");
  expect_invalid([] { Crack({{1., 0.5}}, plate, tol); }, "at least 2 vertices");
  expect_invalid([] { Crack({{0., 0.5}, {0.5, 0.5}, {0.5, 0.5}, {0.7, 0.6}}, plate, tol); },
                 "repeats the previous vertex");
  expect_invalid([] { Crack({{0.5, 0.2}, {1.0, 0.8}, {1.0, 0.3}, {0.5, 0.7}}, plate, tol); },
                 "must not intersect itself");
  expect_invalid([] { Crack({{0.5, 0.5}, {1.0, 0.5}, {0.8, 0.5}}, plate, tol); }, "folds the crack back");
  expect_invalid([] { Crack({{0.5, 0.5}, {2.5, 0.5}}, plate, tol); }, "outside the body outline");
  expect_invalid([] { Crack({{0.5, 0.5}, {1.2, 0.55}}, holed_plate, tol); }, "inside a hole");
  expect_invalid([] { Crack({{0.9, 0.5}, {1.5, 0.5}}, holed_plate, tol); }, "passes through a hole");
  expect_invalid([] { Crack({{0., 0.5}, {2., 0.5}}, plate, tol); }, "both ends lie on the body outline");
  expect_invalid([] { Crack({{0.5, 0.5}, {1.0, 0.}, {1.5, 0.5}}, plate, tol); }, "only an end");
  expect_invalid([] { Crack({{0.5, 0.5}, {NAN, 0.5}}, plate, tol); }, "must be finite");
  expect_invalid([] { Crack({{0.5, 0.5}, {1.0, 0.5}}, plate, -1.); }, "must be a finite number >= 0");
  expect_invalid([] { edge_crack().polar({1., 0.5}, 1); }, "number of tips");
  expect_invalid([] { edge_crack().branch_functions({1., 0.5}, 1); }, "number of tips");
}

// join: the tip grows onto another crack's face and that end becomes a junction (no tip); the
// other tip keeps growing; a crack without a tip is allowed once growth made it so; a point off
// the other crack's face is refused.
TEST(Crack, JoinTurnsTheTipIntoAJunction)
{
  const Crack face({{0.7, 0.2}, {0.7, 0.8}}, plate, tol);
  Crack       e = edge_crack();
  e.join(0, {0.7, 0.5}, face);
  EXPECT_TRUE(e.tips().empty());
  EXPECT_TRUE(e.junctions()[1]);
  EXPECT_FALSE(e.junctions()[0]);
  expect_point(e.vertices().back(), {0.7, 0.5}, 0.);

  const Crack other({{1.6, 0.2}, {1.6, 0.9}}, plate, tol);
  Crack       i = interior_crack();
  i.join(1, {1.6, 0.55}, other);
  ASSERT_EQ(i.tips().size(), 1u);
  expect_point(i.tips()[0].position, {0.5, 0.5}, 0.);
  i.grow(0, {0.4, 0.5});
  ASSERT_EQ(i.tips().size(), 1u);
  expect_point(i.tips()[0].position, {0.4, 0.5}, 0.);
  expect_point(i.vertices().back(), {1.6, 0.55}, 0.);

  expect_invalid([&] { edge_crack().join(0, {0.7, 0.1}, face); }, "must lie on the face of the crack it joins");
}

// The junction function (Daux et al. 2000): across the crack it joined, the joined crack's H is
// one constant near the junction (its level set's extension there would open a crack that is not
// there), and on its own side H still changes sign across it. An oblique junction: the edge crack
// runs from (0, 0.2) up at 45 degrees into the face of a vertical crack at x = 0.5.
TEST(Crack, JunctionFunctionIsConstantAcrossTheCrackItJoined)
{
  const Crack face({{0.5, 0.1}, {0.5, 0.9}}, plate, tol);
  for (const bool front : {false, true})
    {
      Crack s = front ? Crack({{0.4, 0.6}, {0., 0.2}}, plate, tol) : Crack({{0., 0.2}, {0.4, 0.6}}, plate, tol);
      s.join(0, {0.5, 0.7}, face);
      ASSERT_TRUE(s.tips().empty());
      const Point j{0.5, 0.7};
      std::vector<int> far_side;
      for (const Point o : {Point{0.01, 0.}, Point{0.01, 0.05}, Point{0.01, -0.05}, Point{0.05, 0.2}, Point{0.05, -0.2},
                            Point{0.1, 0.}, Point{1e-6, 1e-3}, Point{1e-6, -1e-3}})
        far_side.push_back(s.side(j + o));
      for (const int h : far_side)
        EXPECT_EQ(h, far_side.front()) << (front ? "front" : "back") << " junction";
      EXPECT_NE(s.side(j + Point{-0.1, -0.05}), s.side(j + Point{-0.1, -0.15}));
      // The same constant where the end's extension does not reach: next to the face on its far
      // side, behind the junction along the face.
      EXPECT_EQ(s.side(j + Point{1e-3, -0.3}), far_side.front());
    }
}

// A junction at a kink of the crack it joined: across that crack is decided by its own level set,
// not by one segment's line, so H is one constant everywhere across it ahead of the junction, on
// both sides of the kink.
TEST(Crack, JunctionAtAKinkFollowsTheKinkedFace)
{
  const Crack face({{0.2, 0.1}, {0.6, 0.5}, {1.2, 0.5}}, plate, tol);
  Crack       s({{0.6, 0.}, {0.6, 0.3}}, plate, tol);
  s.join(0, {0.6, 0.5}, face);
  const int beyond = s.side({0.62, 0.9});
  for (const Point x : {Point{0.65, 0.52}, Point{0.9, 0.51}, Point{0.55, 0.9}, Point{0.61, 0.505}})
    EXPECT_EQ(s.side(x), beyond) << to_text(x);
  EXPECT_NE(s.side({0.59, 0.45}), s.side({0.61, 0.45})) << "below the junction H changes across the joined crack";
}

// distance: to the segments, not to the level set's extension beyond the tips.
TEST(Crack, DistanceIsToTheSegments)
{
  const Crack e = edge_crack();
  EXPECT_NEAR(e.distance({0.3, 0.7}), 0.2, 1e-15);
  EXPECT_NEAR(e.distance({0.9, 0.5}), 0.3, 1e-15);
  EXPECT_NEAR(std::abs(e.signed_distance({0.9, 0.5})), 0., 1e-15);
}

// A crack digitised finely, as a measured path is: 3000 vertices on a circular arc of radius R
// about c, mouth on the plate's left edge. Its level set is R - |x - c| (+ outside the arc, on the
// left of the polyline walked from the mouth) within the arc's sagitta between two vertices,
// ahead of the tip the signed distance to the last segment's line, and its distance the same.
TEST(Crack, LevelSetOfAFinelyDigitisedCrack)
{
  const double      radius = 0.8, sweep = 0.6;
  const Point       centre{0., -0.3};
  const std::size_t n = 3000;
  Polyline          arc;
  for (std::size_t k = 0; k < n; ++k)
    {
      const double a = 0.5 * 3.14159265358979 - sweep * double(k) / double(n - 1);
      arc.push_back(centre + radius * Point{std::cos(a), std::sin(a)});
    }
  const Crack  c(arc, plate, tol);
  const double sagitta = radius * (1. - std::cos(0.5 * sweep / double(n - 1)));
  for (int i = 0; i <= 20; ++i)
    for (int j = 0; j <= 10; ++j)
      {
        const Point  x{0.0 + 0.02 * i, 0.1 * j};
        const double from_centre = norm(x - centre), angle = std::atan2(x.y - centre.y, x.x - centre.x);
        if (angle < 0.5 * 3.14159265358979 - sweep || from_centre == 0.)
          continue; // beyond the tip, where the level set follows the last segment's line
        EXPECT_NEAR(c.signed_distance(x), from_centre - radius, sagitta + 1e-15) << to_text(x);
        EXPECT_NEAR(c.distance(x), std::abs(from_centre - radius), sagitta + 1e-15) << to_text(x);
      }
  const Tip   tip = c.tips().front();
  const Point ahead{tip.position.x + 0.1 * tip.direction.x, tip.position.y + 0.1 * tip.direction.y};
  const Point normal{-tip.direction.y, tip.direction.x};
  EXPECT_NEAR(c.signed_distance(ahead + 0.05 * normal), 0.05, 1e-12);
  EXPECT_NEAR(c.signed_distance(ahead - 0.03 * normal), -0.03, 1e-12);
}
