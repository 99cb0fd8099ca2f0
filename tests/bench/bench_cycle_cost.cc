// What the default resolution costs, as two ratios of runs made in this one process
// (label bench: timings only; outputs under <build>/tests/bench/bench_cycle_cost_output/<run>/).
// - coupling.case3.default_over_fixed4mm_time: Case III at the default (prm/ingraffea-case3.prm,
//   the resolution rule) over the same scene with the section's fixed 4 mm horizon (Rule = fixed).
// - trade.coupled_over_lefm_time: Case II by the global-local cycle (prm/ingraffea-case2.prm) over
//   Case II by LEFM growth (prm/ingraffea-case2-lefm.prm).
// Each pair runs the cheaper run first, then the default; PD node-steps and global solve seconds are
// printed alongside, so a ratio can be read against the machine's load.
#include <gtest/gtest.h>

#include <deal.II/base/multithread_info.h>

#include <iostream>
#include <sstream>
#include <string>

#include "cycle_study.h"
#include "lefm_growth.h"

using namespace pumpd;
using namespace pumpd::study;

namespace
{
  const std::string output = "bench_cycle_cost_output";

  /// The run's own totals under the name of its case.
  void print_parts(const std::string &prefix, const CycleRun &c)
  {
    if (c.r)
      for (const std::string name : {"seconds_total", "pd_node_steps", "seconds_global", "seconds_pd"})
        metric(prefix + "." + name, c.metrics.at("coupling." + name));
  }
} // namespace

TEST(CycleCost, CaseIIIDefaultAgainstTheFixedHorizon)
{
  dealii::MultithreadInfo::set_thread_limit(1);
  auto fixed                  = from_prm("ingraffea-case3.prm");
  fixed.cycle.resolution.rule = "fixed";
  const CycleRun case3_fixed  = run(output, "case3_fixed_4mm", fixed);
  const CycleRun case3        = run(output, "case3", from_prm("ingraffea-case3.prm"));
  print_parts("coupling.case3_fixed4mm", case3_fixed);
  print_parts("coupling.case3", case3);
  metric("coupling.case3.default_over_fixed4mm_time",
         case3.r && case3_fixed.r ? case3.r->seconds / case3_fixed.r->seconds : not_a_number);
}

TEST(CycleCost, CaseIICoupledAgainstLefm)
{
  dealii::MultithreadInfo::set_thread_limit(1);
  auto lefm                   = from_prm("ingraffea-case2-lefm.prm");
  lefm.scene.output_directory = std::string(PUMPD_BINARY_DIR) + "/" + output + "/case2_lefm";
  std::ostringstream quiet;
  const auto r = coupling::run_lefm_growth(coupling::build_scene(lefm.scene), lefm.lefm_growth_settings(), quiet);
  std::cout << "Case II by LEFM growth: " << r.seconds << " s, tip (" << r.path.back().x << ", " << r.path.back().y
            << ")" << std::endl;
  const CycleRun case2 = run(output, "case2", from_prm("ingraffea-case2.prm"));
  print_parts("coupling.case2", case2);
  metric("coupling.case2.lefm_seconds_total", r.seconds);
  metric("trade.coupled_over_lefm_time", case2.r ? case2.r->seconds / r.seconds : not_a_number);
}
