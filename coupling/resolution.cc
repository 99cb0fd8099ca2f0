#include "resolution.h"

#include <deal.II/base/parameter_handler.h>

#include <algorithm>
#include <cmath>

namespace pumpd::coupling
{
  void ResolutionSettings::add_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Resolution");
    prm.add_parameter("Rule", rule,
                      "clearance: each PD box halves the horizon (and spacing, box, advance) until the path ahead of "
                      "the tip keeps Clearance over horizon horizons from every hole and the outline, and every hole "
                      "the box reaches holds as many within its radius, at most Maximum halvings times; fixed: every "
                      "box has the horizon of the section Peridynamics.",
                      dealii::Patterns::Selection("clearance|fixed"));
    prm.add_parameter("Clearance over horizon", clearance_over_horizon,
                      "The clearance of the path ahead, in horizons of the box, at least (3: the tip's family, a free "
                      "horizon of bulk, the surface layer of the hole or edge).",
                      dealii::Patterns::Double(1., 20.));
    prm.add_parameter("Maximum halvings", max_halvings,
                      "The box's horizon is at least the section Peridynamics' horizon / 2^this.",
                      dealii::Patterns::Integer(0, 4));
    prm.leave_subsection();
  }

  double clearance_ahead(const geometry::Body &body, geometry::Point tip, geometry::Point d, double reach, double step)
  {
    const int n = std::max(1, int(std::ceil(reach / step)));
    double    c = body.clearance(tip);
    for (int k = 1; k <= n; ++k)
      c = std::min(c, body.clearance(tip + (reach * k / n) * d));
    return c;
  }

  unsigned int horizon_halvings(const ResolutionSettings &s, double horizon, double clearance)
  {
    unsigned int k = 0;
    if (s.rule == "clearance")
      while (k < s.max_halvings && clearance < s.clearance_over_horizon * std::ldexp(horizon, -int(k)))
        ++k;
    return k;
  }
} // namespace pumpd::coupling
