#include "exchange_controller.h"

#include <algorithm>
#include <string>

#include "error.h"

namespace pumpd::coupling
{
  ExchangeController::ExchangeController(const ExchangeSettings &settings)
    : s(settings)
  {
    require_range("First load factor", s.first_load_factor, 0.05, 10., "must be in [0.05, 10]");
    require_range("Load increment", s.load_increment, 1e-4, 1., "must be in [1e-4, 1]");
    require_range("Minimum load increment", s.min_load_increment, 1e-6, s.load_increment,
                  "must be in [1e-6, Load increment]");
    require_range("Maximum load factor", s.max_load_factor, s.first_load_factor, 100.,
                  "must be in [First load factor, 100]");
    require_range("Onset resolution", s.onset_resolution, 1e-4, s.load_increment, "must be in [1e-4, Load increment]");
    require_positive("Maximum advance", s.max_advance);
    require_range("Minimum advance", s.min_advance, 0., 0.5 * s.max_advance, "must be in [0, Maximum advance / 2]");
    require_range("Near distance", s.near_distance, 0., 1., "must be in [0, 1] m");
  }

  double ExchangeController::start()
  {
    dlambda = s.load_increment;
    lambda  = s.start_below_accepted && accepted > 0. ? std::max(0.05, accepted - s.load_increment)
                                                       : s.first_load_factor;
    return lambda;
  }

  double ExchangeController::allowed_advance(double clearance) const
  {
    return clearance < s.near_distance ? 0.5 * s.max_advance : s.max_advance;
  }

  ExchangeController::Decision ExchangeController::judge(double advance, double allowed, bool arrives)
  {
    if (arrives && advance > 0. && advance <= allowed)
      {
        accepted = lambda;
        return Decision::accept;
      }
    if (advance > allowed)
      {
        if (0.5 * dlambda >= s.min_load_increment)
          {
            lambda -= 0.5 * dlambda;
            dlambda *= 0.5;
            return Decision::repeat;
          }
        accepted = lambda;
        return Decision::truncate;
      }
    if (advance >= std::min(s.min_advance, 0.5 * allowed))
      {
        accepted = lambda;
        return Decision::accept;
      }
    if (lambda + dlambda > s.max_load_factor * (1. + 1e-12))
      return Decision::too_small;
    lambda += dlambda;
    return Decision::raise;
  }
} // namespace pumpd::coupling
