#include "growth_settings.h"

#include <deal.II/base/parameter_handler.h>

namespace pumpd::coupling
{
  void GrowthSettings::add_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Crack growth");
    prm.add_parameter("Maximum crack length", max_crack_length,
                      "Stop when the crack polyline is this long [m] (several cracks: their total length); 0: no "
                      "limit (the crack grows until it reaches a hole or the outline, or stops).",
                      dealii::Patterns::Double(0.));
    prm.add_parameter("Hole margin", hole_margin,
                      "A tip that would enter a hole stops this far [m] from it.", dealii::Patterns::Double(0., 1.));
    prm.leave_subsection();
  }
} // namespace pumpd::coupling
