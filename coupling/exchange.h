// The scheme of one global-local exchange (preCICE's CouplingScheme::advance): quasi-static PD
// states of one box along the load factor, each judged by the ExchangeController (raise the load,
// repeat a too-long advance with half the increment, accept), the crack increment of each tip in
// the box read off each state's damage (CrackExtractor). The controller judges the tip with the
// largest advance relative to its allowed advance, so the box's tips grow at one load. Each state
// starts from the secant through the last two equilibria of the exchange (first-order
// continuation in the load factor).
// The onset of growth is the lowest load factor at which a tip's trace leaves it (an increment
// longer than zero), the criterion of full PD's first growth: bracketed by the ladder's states
// and refined by bisection to the settings' onset resolution, with states that the ladder does
// not go on from (its path is the same with or without them). It is the load the cycle reports:
// the box's boundary layer holds the global displacement of the crack before its increment, so
// the crack needs more load to run the increment than to start it.
#pragma once

#include <cstddef>
#include <functional>
#include <iosfwd>
#include <limits>
#include <string>
#include <vector>

#include "boundary_transfer.h"
#include "crack_extraction.h"
#include "exchange_controller.h"
#include "pd_settings.h"

namespace pumpd::coupling
{
  struct ExchangeOutcome
  {
    std::vector<CrackIncrement>  increments;        ///< per tip, in the order given
    std::vector<bool>            reaches;           ///< per tip: its increment meets a hole, the outline or another crack's face (none after a branching)
    ExchangeController::Decision decision = ExchangeController::Decision::raise;
    std::string                  branching;         ///< the ridge split there (refused); "" otherwise
    double                       load_factor = 0.;  ///< lambda / lambda_c of the last state
    double                       onset_load_factor = std::numeric_limits<double>::quiet_NaN(); ///< lambda / lambda_c of the onset of growth; NaN without growth
    local::State                 state;             ///< the last PD state
    std::size_t                  states = 0, repeats = 0, iterations = 0;
    std::size_t                  onset_states = 0;  ///< states that refined the onset
    std::size_t                  unrelaxed = 0;     ///< states not relaxed within the settings' max iterations
    double                       node_steps = 0.;   ///< sum of PD nodes x DR iterations
    double                       seconds_pd = 0., seconds_extraction = 0.;
  };

  /// Runs the states of one exchange for the tips in the box, the load factor relative to the
  /// first tip's critical load factor lambda_c; tip k advances at most allowed[k] and its trace
  /// ends on the other cracks faces[k] (crack_extraction.h; none if faces is empty); `arrives(path)`
  /// says whether an increment reaches a hole or the outline (accepted whatever its length within the allowed advance, as
  /// one that reaches another crack's face).
  /// Progress (one line per state, the load factor in units of `unit`: the first tip's lambda_c,
  /// or the lambda_i of a nucleation) to `out`. The controller judges advances in units of
  /// `advance_scale`: its minimum advance is the settings' times this.
  ExchangeOutcome run_exchange(const local::PdModel &model, const BoundaryTransfer &transfer,
                               ExchangeController &controller, const std::vector<TipState> &tips,
                               const std::vector<double> &allowed,
                               const std::vector<std::vector<geometry::Polyline>> &faces,
                               const std::function<bool(const geometry::Polyline &)> &arrives,
                               const PeridynamicsSettings &pd, std::ostream &out,
                               const std::string &unit = "lambda_c", double advance_scale = 1.);

  const char *to_text(ExchangeController::Decision decision);

  /// The PD damage on the lattice (crack extraction's input), NaN where there is no material.
  DamageField damage_field(const local::PdModel &model, const local::State &s);
} // namespace pumpd::coupling
