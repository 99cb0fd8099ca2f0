// The right crack path at the default settings, and what it costs. Label study (not in
// CI): the runs take minutes each. Every run starts from prm/ingraffea-caseN.prm (the default
// settings: the resolution rule of coupling/resolution.h); outputs under
// <build>/tests/bench/study_resolution_output/<run>/.
//
// 1. Cases I-III at the default: where the crack ends (coupling.case3.tip_x_mm, tip_y_mm: the
//    middle hole is centred at (152.4, 120.65) mm; coupling.case1.tip_y_mm: the top edge is at
//    203.2 mm), PD node-steps (coupling.caseN.pd_node_steps), seconds.
// 2. The rule's own convergence: each case again with every horizon the rule chooses halved. The
//    section's horizon is halved, Clearance over horizon doubled (so the rule switches where it
//    did, each box at half its horizon), the box and exchange lengths halved (study::with_pd), one
//    more global refinement level at the tip. coupling.caseN.path_change_half_horizon_mm: the
//    symmetric mean distance of the grown parts (study::path_change), target <= 1 mm.
// What the default costs against the fixed horizon and LEFM growth: bench_cycle_cost.
#include <gtest/gtest.h>

#include <deal.II/base/multithread_info.h>

#include <iostream>
#include <string>

#include "cycle_study.h"

using namespace pumpd;
using namespace pumpd::study;

namespace
{
  const std::string output = "study_resolution_output";

  /// Every horizon the rule chooses halved (header, 2).
  coupling::Parameters half_horizon(coupling::Parameters p)
  {
    p = with_pd(p, 0.5 * p.pd.horizon, p.pd.horizon_over_spacing);
    p.cycle.resolution.clearance_over_horizon *= 2.;
    p.global.refinement_levels += 1;
    return p;
  }

  void case_metrics(int n)
  {
    const std::string prm    = "ingraffea-case" + std::to_string(n) + ".prm";
    const CycleRun    c      = run(output, "case" + std::to_string(n), from_prm(prm));
    const std::string prefix = "coupling.case" + std::to_string(n);
    sanity(c);
    std::cout << "Case " << n << " stop reason: " << (c.r ? c.r->stop_reason : "(the run threw)") << std::endl;
    if (n == 3)
      {
        metric(prefix + ".tip_x_mm", c.r ? 1e3 * c.r->path.back().x : not_a_number);
        metric(prefix + ".tip_y_mm", c.r ? 1e3 * c.r->path.back().y : not_a_number);
      }
    if (n == 1)
      metric(prefix + ".tip_y_mm", c.r ? 1e3 * c.r->path.back().y : not_a_number);
    metric(prefix + ".pd_node_steps", c.r ? c.r->pd_node_steps : not_a_number);
    metric(prefix + ".seconds_total", c.r ? c.r->seconds : not_a_number);

    const CycleRun half = run(output, "case" + std::to_string(n) + "_half_horizon",
                              half_horizon(from_prm(prm)));
    sanity(half);
    metric(prefix + ".path_change_half_horizon_mm", 1e3 * path_change(half, c));
    metric(prefix + ".half_horizon_seconds_total", half.r ? half.r->seconds : not_a_number);
  }
} // namespace

TEST(ResolutionStudy, CaseI)
{
  dealii::MultithreadInfo::set_thread_limit(1);
  case_metrics(1);
}

TEST(ResolutionStudy, CaseII)
{
  dealii::MultithreadInfo::set_thread_limit(1);
  case_metrics(2);
}

TEST(ResolutionStudy, CaseIII)
{
  dealii::MultithreadInfo::set_thread_limit(1);
  case_metrics(3);
}
