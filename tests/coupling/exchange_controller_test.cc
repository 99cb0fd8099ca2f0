// ExchangeController (coupling/exchange_controller.h): the load factor sequence for given
// advances, step by step.
#include <gtest/gtest.h>

#include "error.h"
#include "exchange_controller.h"

using namespace pumpd::coupling;
using D = ExchangeController::Decision;

namespace
{
  ExchangeSettings settings()
  {
    ExchangeSettings s;
    s.first_load_factor  = 0.9;
    s.load_increment     = 0.1;
    s.min_load_increment = 0.025;
    s.max_load_factor    = 1.5;
    s.max_advance        = 0.008;
    s.min_advance        = 0.001;
    s.near_distance      = 0.01;
    return s;
  }
} // namespace

TEST(ExchangeController, RaisesUntilGrowthThenAccepts)
{
  ExchangeController c(settings());
  EXPECT_DOUBLE_EQ(c.start(), 0.9);
  EXPECT_EQ(c.judge(0., 0.008), D::raise);
  EXPECT_DOUBLE_EQ(c.load_factor(), 1.0);
  EXPECT_EQ(c.judge(0.0005, 0.008), D::raise); // below the minimum advance
  EXPECT_DOUBLE_EQ(c.load_factor(), 1.1);
  EXPECT_EQ(c.judge(0.003, 0.008), D::accept);
  EXPECT_DOUBLE_EQ(c.load_factor(), 1.1);
  // The next exchange starts again below P_c: the rebuilt box loads up to growth quasi-statically.
  EXPECT_DOUBLE_EQ(c.start(), 0.9);
}

TEST(ExchangeController, StartsBelowTheAcceptedLoadWhenAsked)
{
  auto s                 = settings();
  s.start_below_accepted = true;
  ExchangeController c(s);
  EXPECT_DOUBLE_EQ(c.start(), 0.9); // nothing accepted yet
  EXPECT_EQ(c.judge(0., 0.008), D::raise);    // 0.9 -> 1.0
  EXPECT_EQ(c.judge(0., 0.008), D::raise);    // 1.0 -> 1.1
  EXPECT_EQ(c.judge(0.003, 0.008), D::accept); // at 1.1
  EXPECT_DOUBLE_EQ(c.start(), 1.0);            // one increment (0.1) below the accepted 1.1
  c.restore(1.5);                              // a resumed run
  EXPECT_DOUBLE_EQ(c.start(), 1.4);
}

TEST(ExchangeController, RepeatsWithSmallerIncrementsThenTruncates)
{
  ExchangeController c(settings());
  c.start();
  EXPECT_EQ(c.judge(0., 0.008), D::raise);     // 0.9 -> 1.0
  EXPECT_EQ(c.judge(0.02, 0.008), D::repeat);  // too far at 1.0: back to 0.95, dlambda 0.05
  EXPECT_DOUBLE_EQ(c.load_factor(), 0.95);
  EXPECT_DOUBLE_EQ(c.increment(), 0.05);
  EXPECT_EQ(c.judge(0.02, 0.008), D::repeat);  // 0.925, dlambda 0.025
  EXPECT_DOUBLE_EQ(c.load_factor(), 0.925);
  EXPECT_EQ(c.judge(0.02, 0.008), D::truncate); // dlambda would drop below the minimum
  EXPECT_DOUBLE_EQ(c.load_factor(), 0.925);
}

TEST(ExchangeController, SaysWhenTheLoadIsTooSmall)
{
  ExchangeController c(settings());
  c.start();
  D d = D::raise;
  int n = 0;
  while (d == D::raise && n < 100)
    d = c.judge(0., 0.008), ++n;
  EXPECT_EQ(d, D::too_small);
  EXPECT_EQ(n, 7); // 0.9, 1.0, ..., 1.5: six raises, then no higher load is allowed
  EXPECT_NEAR(c.load_factor(), 1.5, 1e-12);
}

TEST(ExchangeController, AcceptsAShortAdvanceThatArrivesAtAHole)
{
  ExchangeController c(settings());
  c.start();
  EXPECT_EQ(c.judge(0.0005, 0.008), D::raise);
  EXPECT_EQ(c.judge(0.0005, 0.008, true), D::accept);
  EXPECT_EQ(c.judge(0., 0.008, true), D::raise); // no advance at all: not an arrival
}

TEST(ExchangeController, ExchangesMoreOftenNearAHoleOrTheOutline)
{
  ExchangeController c(settings());
  EXPECT_DOUBLE_EQ(c.allowed_advance(0.05), 0.008);
  EXPECT_DOUBLE_EQ(c.allowed_advance(0.005), 0.004);
}

TEST(ExchangeController, RefusesBadSettings)
{
  auto s = settings();
  s.min_load_increment = 0.2; // > load increment
  EXPECT_THROW(ExchangeController{s}, pumpd::InvalidParameter);
  s = settings();
  s.max_load_factor = 0.5; // < first load factor
  EXPECT_THROW(ExchangeController{s}, pumpd::InvalidParameter);
  s = settings();
  s.min_advance = 0.006; // > max advance / 2
  EXPECT_THROW(ExchangeController{s}, pumpd::InvalidParameter);
}
