#include "scene_lengths.h"

#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "global_problem.h"
#include "path_metrics.h"
#include "scene.h"

namespace pumpd::coupling
{
  SceneLengths measure_lengths(const Scene &scene)
  {
    SceneLengths l;
    const auto  &box = scene.body.bounding_box();
    l.body_side      = std::min(box.width(), box.height());
    for (const auto &hole : scene.body.holes())
      {
        const auto b  = hole.bounding_box();
        l.hole_radius = std::min(l.hole_radius, 0.5 * std::min(b.width(), b.height()));
      }
    const auto cracks = enriched_cracks(scene.cracks, scene);
    for (std::size_t c = 0; c < cracks.size(); ++c)
      for (const auto &tip : cracks[c].tips())
        {
          l.crack_length  = std::min(l.crack_length, cracks[c].length() / double(cracks[c].tips().size()));
          l.tip_clearance = std::min(l.tip_clearance, scene.body.clearance(tip.position));
          if (scene.mesh)
            l.tip_cell = std::max(l.tip_cell, dealii::GridTools::find_active_cell_around_point(
                                                *scene.mesh, dealii::Point<2>(tip.position.x, tip.position.y))
                                                ->diameter());
          for (std::size_t o = 0; o < cracks.size(); ++o)
            if (o != c)
              l.tip_clearance = std::min(l.tip_clearance, distance_to_polyline(tip.position, cracks[o].vertices()));
        }
    return l;
  }

  double preferred_below(double x)
  {
    constexpr std::array<double, 10> preferred = {{1., 1.2, 1.5, 2., 2.5, 3., 4., 5., 6., 8.}};
    const double                     decade    = std::pow(10., std::floor(std::log10(x)));
    double                           value     = decade;
    for (const double p : preferred)
      if (p * decade <= x * (1. + 1e-12))
        value = p * decade;
    return value;
  }

  namespace
  {
    /// The least of the candidates, rounded down to a preferred number.
    RuleLength least(std::initializer_list<RuleLength> candidates)
    {
      RuleLength l = *std::min_element(candidates.begin(), candidates.end(),
                                       [](const RuleLength &a, const RuleLength &b) { return a.value < b.value; });
      l.value = preferred_below(l.value);
      return l;
    }
  } // namespace

  RuleLength scene_horizon(const SceneLengths &l)
  {
    return least({{l.body_side / 32., "L / 32"}, {l.crack_length / 4., "a / 4"}});
  }

  RuleLength scene_growth_increment(const SceneLengths &l)
  {
    return least({{l.body_side / 50., "L / 50"}, {l.crack_length / 10., "a / 10"}, {l.hole_radius / 2., "R / 2"}});
  }

  bool is_scene_length(const std::string &path)
  {
    static const std::array<const char *, 11> entries = {{
      "Peridynamics/Horizon",          "Global-local/Box size",        "Global-local/Box margin",
      "Global-local/Maximum box size", "Global-local/Maximum advance", "Global-local/Minimum advance",
      "Global-local/Near distance",    "LEFM growth/Growth increment", "Global/Tip enrichment radius",
      "Global/Refinement radius",      "Global/Refinement trail"}};
    return std::find(entries.begin(), entries.end(), path) != entries.end();
  }
} // namespace pumpd::coupling
