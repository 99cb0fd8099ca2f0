// The crack network: whether cracks, through their mouths and junctions, cut a piece off the body,
// for every way a piece can come off (two mouths on the outline, two cracks between the outline and
// a hole, also where growth stopped them a margin short of it, a crack joined to one that opens on
// the outline, an interior crack joined at both ends) and the ways it cannot; and the junctions of
// cracks rebuilt from their polylines.
#include <gtest/gtest.h>

#include <vector>

#include "crack.h"
#include "crack_network.h"

using namespace pumpd;
using namespace pumpd::global;
using geometry::Body;

namespace
{
  constexpr double tol = 1e-9;

  const Body plate{{0., 0., 2., 1.}, {}};
  const Body holed_plate{{0., 0., 2., 1.}, {{{1.2, 0.5}, 0.1}}};
} // namespace

TEST(CrackNetwork, AnEdgeCrackThroughTheBodyCutsItAndATipDoesNot)
{
  std::vector<Crack> cracks{Crack({{0., 0.5}, {1.5, 0.5}}, plate, tol)};
  EXPECT_FALSE(cuts_off_a_piece(cracks, plate, tol));
  cracks[0].grow(0, {2., 0.5});
  EXPECT_TRUE(cracks[0].tips().empty());
  EXPECT_TRUE(cuts_off_a_piece(cracks, plate, tol));
}

TEST(CrackNetwork, ACrackToAHoleCutsOnlyWithASecondOne)
{
  std::vector<Crack> cracks{Crack({{0., 0.5}, {1.0, 0.5}}, holed_plate, tol)};
  cracks[0].grow(0, {1.1, 0.5});
  EXPECT_TRUE(cracks[0].tips().empty());
  EXPECT_FALSE(cuts_off_a_piece(cracks, holed_plate, tol)) << "the outline and the hole become one boundary";
  cracks.emplace_back(Crack({{2., 0.5}, {1.4, 0.5}}, holed_plate, tol));
  EXPECT_FALSE(cuts_off_a_piece(cracks, holed_plate, tol));
  cracks[1].grow(0, {1.3, 0.5});
  EXPECT_TRUE(cuts_off_a_piece(cracks, holed_plate, tol)) << "the plate falls in two";

  // Growth stops a tip a margin short of the hole it reached: within the margin it opens on it.
  std::vector<Crack> stopped{Crack({{0., 0.5}, {1.09, 0.5}}, holed_plate, tol),
                             Crack({{2., 0.5}, {1.31, 0.5}}, holed_plate, tol)};
  EXPECT_FALSE(cuts_off_a_piece(stopped, holed_plate, tol));
  EXPECT_TRUE(cuts_off_a_piece(stopped, holed_plate, tol, 0.01 + 1e-12));
}

// A T: an edge crack joined to an interior crack leaves the body whole until the interior crack
// reaches the outline; an interior crack joined to another at both ends cuts out what they enclose.
TEST(CrackNetwork, JunctionsCutOnlyWhenTheyCloseALoop)
{
  std::vector<Crack> cracks{Crack({{0.5, 0.2}, {1.5, 0.2}}, plate, tol), Crack({{1., 1.}, {1., 0.5}}, plate, tol)};
  cracks[1].join(0, {1., 0.2}, cracks[0]);
  EXPECT_FALSE(cuts_off_a_piece(cracks, plate, tol));
  cracks[0].grow(1, {2., 0.2});
  EXPECT_TRUE(cuts_off_a_piece(cracks, plate, tol));

  std::vector<Crack> loop{Crack({{0.5, 0.2}, {1.5, 0.2}}, plate, tol),
                          Crack({{0.7, 0.5}, {0.8, 0.6}, {1.2, 0.6}, {1.3, 0.5}}, plate, tol)};
  loop[1].join(1, {1.3, 0.2}, loop[0]);
  EXPECT_FALSE(cuts_off_a_piece(loop, plate, tol));
  loop[1].join(0, {0.7, 0.2}, loop[0]);
  EXPECT_TRUE(loop[1].tips().empty());
  EXPECT_TRUE(cuts_off_a_piece(loop, plate, tol));
}

// Rebuilt from the polylines (a checkpoint holds no more), a tip on another crack's face is a
// junction again, and one a little off it stays a tip.
TEST(CrackNetwork, JoinTouchingRestoresTheJunctions)
{
  std::vector<Crack> joined{Crack({{0.5, 0.2}, {1.5, 0.2}}, plate, tol), Crack({{1., 1.}, {1., 0.5}}, plate, tol)};
  joined[1].join(0, {1., 0.2}, joined[0]);
  std::vector<Crack> rebuilt{Crack(joined[0].vertices(), plate, tol), Crack(joined[1].vertices(), plate, tol),
                             Crack({{0., 0.7}, {0.5, 0.2 + 1e-6}}, plate, tol)};
  ASSERT_EQ(rebuilt[1].tips().size(), 1u);
  join_touching(rebuilt, tol);
  EXPECT_TRUE(rebuilt[1].tips().empty());
  EXPECT_TRUE(rebuilt[1].junctions()[1]);
  EXPECT_EQ(rebuilt[2].tips().size(), 1u);
  for (const Point x : {Point{0.9, 0.1}, Point{1.1, 0.1}, Point{0.9, 0.3}, Point{1.1, 0.3}})
    EXPECT_EQ(rebuilt[1].side(x), joined[1].side(x));
}
