// Validation 4: mode-I edge crack in a PD box driven by the Williams field of a slowly rising K
// (dynamic relaxation at each level). LEFM: the crack starts to grow at K_I = K_c = sqrt(E' G_c);
// by symmetry it grows along the crack line. Asserted: onset (first K with growth >= 2 h) within
// 15 % of K_c; the grown crack (nodes with damage above the threshold, ahead of the initial tip)
// within 2 h of the symmetry line; and that it did grow (>= 5 h), so the check has something to check.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>

#include "metric.h"
#include "pd_edge_crack.h"

using namespace pumpd;

TEST(EdgeCrack, OnsetAtKcAndStraightGrowth)
{
  double worst_onset = 0., worst_offset = 0.;
  for (int m : {4, 8})
    {
      coupling::EdgeCrackParameters p; // the decks' PMMA, delta = 4 mm, box 24 delta
      p.pd.tolerance = 1e-6;
      p.pd.horizon_over_spacing = m;
      p.edge.k_start       = 0.8;
      p.edge.k_end         = 1.3;
      p.edge.load_steps    = 21; // K steps of 0.025 K_c
      const auto r    = coupling::run_edge_crack(p, std::cout);

      ASSERT_GT(r.onset_k_over_kc, 0.) << "the crack never grew, m = " << m;
      const double onset_error = std::abs(r.onset_k_over_kc - 1.);
      const double offset      = r.max_offset / r.spacing;
      EXPECT_LT(onset_error, 0.15) << "m = " << m;
      EXPECT_LE(offset, 2.) << "m = " << m;
      EXPECT_GE(r.steps.back().extension, 5. * r.spacing) << "m = " << m;
      const std::string suffix = "_m" + std::to_string(m);
      test::metric("pd.onset_load_rel_err" + suffix, onset_error);
      test::metric("pd.crack_offset_over_h" + suffix, offset);
      test::metric("pd.crack_growth_at_1.3Kc_over_h" + suffix, r.steps.back().extension / r.spacing);
      worst_onset  = std::max(worst_onset, onset_error);
      worst_offset = std::max(worst_offset, offset);
    }
  test::metric("pd.onset_load_rel_err", worst_onset);
  test::metric("pd.crack_offset_over_h", worst_offset);
}
