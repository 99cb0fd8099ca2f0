#include "global_local.h"

#include <deal.II/base/parameter_handler.h>

namespace pumpd::coupling
{
  void CycleSettings::add_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Global-local");
    prm.add_parameter("Box size", box.size,
                      "Side of the square PD box [m]: at least 4 horizons plus the box margin, at most the body's "
                      "smaller side.",
                      dealii::Patterns::Double(1e-300));
    prm.add_parameter("Box tip position", box.behind,
                      "The tip sits this fraction of the box side from the box's rear (along the crack; along the "
                      "maximum hoop stress direction for a kink too large for that box).",
                      dealii::Patterns::Double(0.05, 0.95));
    prm.add_parameter("Box margin", box.margin,
                      "The box moves ahead once the tip has less than this much free lattice ahead [m].",
                      dealii::Patterns::Double(1e-300));
    prm.add_parameter("Maximum box size", box.max_size,
                      "A box grows to take in a nearby hole up to this side [m], at least the box size.",
                      dealii::Patterns::Double(1e-300));
    prm.add_parameter("First load factor", exchange.first_load_factor,
                      "lambda / lambda_c of the first PD state of an exchange (lambda_c: G = G_c at the tip).",
                      dealii::Patterns::Double(0.05, 10.));
    prm.add_parameter("Load increment", exchange.load_increment, "dlambda / lambda_c between PD states.",
                      dealii::Patterns::Double(1e-4, 1.));
    prm.add_parameter("Minimum load increment", exchange.min_load_increment,
                      "A too-long advance halves the load increment down to this, then the advance is truncated; at "
                      "most the load increment.",
                      dealii::Patterns::Double(1e-6, 1.));
    prm.add_parameter("Maximum load factor", exchange.max_load_factor,
                      "No growth up to lambda = this lambda_c: the run stops (the load is too small); at least the "
                      "first load factor.",
                      dealii::Patterns::Double(0.05, 100.));
    prm.add_parameter("Onset resolution", exchange.onset_resolution,
                      "The load the cycle reports at an exchange is the onset of growth in the box (the lowest "
                      "lambda / lambda_c at which its crack leaves the tip), bracketed this closely by bisection "
                      "between the box's states; at most the load increment.",
                      dealii::Patterns::Double(1e-4, 1.));
    prm.add_parameter("Maximum advance", exchange.max_advance, "da_max: the longest crack advance per exchange [m].",
                      dealii::Patterns::Double(1e-300));
    prm.add_parameter("Minimum advance", exchange.min_advance,
                      "An advance below this is no growth [m], at least two PD spacings and at most da_max / 2. A "
                      "short advance is mostly straight ahead: the increment must be long enough for the PD crack to "
                      "turn.",
                      dealii::Patterns::Double(0.));
    prm.add_parameter("Near distance", exchange.near_distance,
                      "Within this of a hole or the outline the advance per exchange is da_max / 2 [m].",
                      dealii::Patterns::Double(0., 1.));
    prm.add_parameter("Start below the last load", exchange.start_below_accepted,
                      "false: every exchange's PD states start at the first load factor (below lambda_c), so the "
                      "rebuilt box forms its process zone before the crack grows; true: one load increment below "
                      "the last accepted load (fewer PD states, but the crack then runs within one relaxation and "
                      "turns less).",
                      dealii::Patterns::Bool());
    prm.add_parameter("Box threshold", box_threshold,
                      "A tip gets a PD box when its G / G_c is at least this at the load where the first tip reaches "
                      "G = G_c (G grows with the load squared); a tip below it waits, modelled by the enrichment "
                      "alone.",
                      dealii::Patterns::Double(1e-3, 1.));
    prm.add_parameter("Maximum exchanges", max_exchanges, "Global-local exchanges at most.", dealii::Patterns::Integer(1));
    prm.add_parameter("Reference box area", reference_box_area,
                      "Area of the fixed PD box the moving box is compared with [m^2] (a metric); default: Ni et al. "
                      "(2019), 0.127 m x 0.1778 m.",
                      dealii::Patterns::Double(1e-300));
    prm.add_parameter("Output interval", output_interval,
                      "Write global and PD VTU every n exchanges (and the last).", dealii::Patterns::Integer(1));
    prm.add_parameter("Resume", resume,
                      "true: continue from checkpoint.h5 in the output directory (written after every exchange).",
                      dealii::Patterns::Bool());
    resolution.add_parameters(prm);
    prm.leave_subsection();
  }
} // namespace pumpd::coupling
