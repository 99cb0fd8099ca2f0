// Material constants against the closed forms, and the vectorisable exp against std::exp.
#include <gtest/gtest.h>

#include <cmath>

#include "error.h"
#include "fast_exp.h"
#include "material.h"

using namespace pumpd;
using namespace pumpd::local;

TEST(Material, LameConstantsAndParameters)
{
  MaterialParameters p; // E = 2.4e9, G_c = 500, plane strain, linear J
  const LiptonMaterial m(p, 0.004);
  EXPECT_DOUBLE_EQ(m.poisson_ratio(), 0.25);
  EXPECT_NEAR(m.lame_lambda(), 0.4 * 2.4e9, 1e-3);       // E nu / ((1+nu)(1-2nu)) at nu = 1/4
  EXPECT_NEAR(m.moment(), 1., 1e-15);                     // int 12 (1-r) r^2 dr
  EXPECT_NEAR(m.C(), M_PI * 500. / 4., 1e-12);
  EXPECT_NEAR(m.beta(), 2. * m.lame_lambda() / (m.C() * m.moment()), 1e-6);
  EXPECT_NEAR(m.critical_sif(), std::sqrt(2.4e9 / (1. - 1. / 16.) * 500.), 1e-6);
  // Bond force C beta 2 r S exp(-beta r S^2) peaks at S_c.
  const double r = 0.001, sc = m.inflection_stretch(r);
  const auto   force = [&](double S) { return S * std::exp(-m.beta() * r * S * S); };
  EXPECT_GT(force(sc), force(0.99 * sc));
  EXPECT_GT(force(sc), force(1.01 * sc));

  p.plane_strain = false;
  p.influence    = Influence::constant;
  const LiptonMaterial s(p, 0.004);
  EXPECT_DOUBLE_EQ(s.poisson_ratio(), 1. / 3.);
  EXPECT_NEAR(s.lame_lambda(), 3. / 8. * 2.4e9, 1e-3);    // E nu / (1 - nu^2) at nu = 1/3
  EXPECT_NEAR(s.moment(), 1. / 3., 1e-15);
  EXPECT_EQ(s.influence(1.0), 0.);
}

TEST(Material, BadInputIsRefused)
{
  MaterialParameters p;
  EXPECT_THROW(LiptonMaterial(p, 0.), InvalidParameter);
  p.youngs_modulus = -1.;
  EXPECT_THROW(LiptonMaterial(p, 0.004), InvalidParameter);
  p.youngs_modulus = 1e9;
  p.break_factor   = 0.5;
  try
    {
      LiptonMaterial(p, 0.004);
      FAIL();
    }
  catch (const InvalidParameter &e)
    {
      EXPECT_NE(std::string(e.what()).find("Bond break factor"), std::string::npos);
    }
}

TEST(FastExp, MatchesStdExp)
{
  double worst = 0.;
  for (double x = 0.; x < 700.; x += 0.0137)
    worst = std::max(worst, std::abs(exp_negative(x) - std::exp(-x)) / std::exp(-x));
  EXPECT_LT(worst, 1e-14);
  EXPECT_EQ(exp_negative(0.), 1.);
}
