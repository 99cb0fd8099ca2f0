#include "resolution.h"

#include <deal.II/base/parameter_handler.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "path_metrics.h"

namespace pumpd::coupling
{
  void ResolutionSettings::add_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Resolution");
    prm.add_parameter("Rule", rule,
                      "clearance: each PD box takes the coarsest horizon (the section Peridynamics' halved at most "
                      "Maximum halvings times, doubled at most Maximum doublings times; spacing, box and advance "
                      "scaled with it) at which the path ahead of the tip keeps Clearance over horizon horizons from "
                      "every hole and the outline, and every hole the box reaches holds as many within its radius; "
                      "fixed: every box has the horizon of the section Peridynamics.",
                      dealii::Patterns::Selection("clearance|fixed"));
    prm.add_parameter("Clearance over horizon", clearance_over_horizon,
                      "The clearance of the path ahead, in horizons of the box, at least (3: the tip's family, a free "
                      "horizon of bulk, the surface layer of the hole or edge).",
                      dealii::Patterns::Double(1., 20.));
    prm.add_parameter("Maximum halvings", max_halvings,
                      "The box's horizon is at least the section Peridynamics' horizon / 2^this.",
                      dealii::Patterns::Integer(0, 4));
    prm.add_parameter("Maximum doublings", max_doublings,
                      "The box's horizon is at most the section Peridynamics' horizon x 2^this. A box doubles its "
                      "horizon (and spacing, side, margin, advance) where its doubled path ahead (twice as long) "
                      "keeps Clearance over horizon doubled horizons from every hole, the outline and the other "
                      "cracks, every hole the doubled box reaches holds as many within its radius, and the doubled "
                      "box fits into the body.",
                      dealii::Patterns::Integer(0, 2));
    prm.add_parameter("Kink tolerance", kink_tolerance,
                      "eps [deg]: a tip that has not grown gets a box whose horizon is at most eps a / |theta_c| "
                      "(eps in radians, theta_c the maximum hoop stress angle, a the crack's length, half of it for "
                      "an interior crack): the first PD increment, a straight segment of 1.5 to 2 horizons, then "
                      "lies within about eps of the kinked path's direction; and halved further until the global "
                      "field's largest hoop stress 1.5 horizons from the tip lies within eps of theta_c. 0: no "
                      "such halving.",
                      dealii::Patterns::Double(0., 30.));
    prm.add_parameter("Maximum kink halvings", max_kink_halvings,
                      "The horizon a kink asks for is at least the section Peridynamics' horizon / 2^this.",
                      dealii::Patterns::Integer(0, 6));
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

  double clearance_ahead(const std::vector<geometry::Polyline> &faces, geometry::Point tip, geometry::Point d,
                         double reach, double step)
  {
    const int n = std::max(1, int(std::ceil(reach / step)));
    double    c = std::numeric_limits<double>::infinity();
    for (const auto &face : faces)
      for (int k = 0; k <= n; ++k)
        c = std::min(c, distance_to_polyline(tip + (reach * k / n) * d, face));
    return c;
  }

  int horizon_halvings(const ResolutionSettings &s, double horizon, const std::function<double(double)> &clearance)
  {
    if (s.rule != "clearance")
      return 0;
    const double finer = clearance(1.);
    for (int k = -int(s.max_doublings); k < int(s.max_halvings); ++k)
      {
        const double scale = std::ldexp(1., -k);
        if ((k < 0 ? clearance(scale) : finer) >= s.clearance_over_horizon * scale * horizon)
          return k;
      }
    return int(s.max_halvings);
  }

  namespace
  {
    /// eps [rad]; 0 under the fixed rule, where no kink halving applies.
    double kink_tolerance_of(const ResolutionSettings &s)
    {
      return s.rule == "clearance" ? s.kink_tolerance * std::acos(-1.) / 180. : 0.;
    }
  } // namespace

  int kink_halvings(const ResolutionSettings &s, double horizon, double kink, double crack_length)
  {
    const double tolerance = kink_tolerance_of(s);
    const double error     = horizon * std::abs(kink) / crack_length;
    if (tolerance <= 0. || !(crack_length > 0.) || error <= tolerance)
      return 0;
    const double needed = std::ceil(std::log2(error / tolerance) - 1e-12);
    return int(std::clamp(needed, 0., double(s.max_kink_halvings)));
  }

  int field_kink_halvings(const ResolutionSettings &s, double horizon, double kink,
                          const std::function<double(double)> &hoop_direction)
  {
    const double tolerance = kink_tolerance_of(s);
    if (tolerance <= 0. || std::abs(kink) <= tolerance)
      return 0;
    for (int k = 0; k < int(s.max_kink_halvings); ++k)
      if (std::abs(hoop_direction(1.5 * std::ldexp(horizon, -k)) - kink) <= tolerance)
        return k;
    return int(s.max_kink_halvings);
  }
} // namespace pumpd::coupling
