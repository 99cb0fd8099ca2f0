// How far the load goes in one global-local exchange (DESIGN.md, coupling/ ExchangeController).
//
// The load is a factor lambda of the critical load P_c at which the global solution has G = G_c
// at the tip (LEFM, so P_c is known before the PD run). Within one exchange the PD box is driven
// at lambda = first, first + dlambda, ... (each a quasi-static PD state) until its crack grows:
//  - advance < min(min_advance, allowed / 2): raise lambda by dlambda (stop at max_load_factor:
//    the load is too small to grow the crack, the run says so);
//  - advance > the allowed advance: repeat the sub-step from the state before it with dlambda
//    halved, down to min_load_increment, then accept the first allowed length of the path
//    (truncated);
//  - otherwise, or when the advance reaches a hole or the outline: accept.
// Every exchange starts again at first_load_factor, below P_c: the box is rebuilt undamaged but
// for the crack's broken bonds, and its process zone must form before the crack grows. Started
// above the growth load (one increment below the last accepted lambda, start_below_accepted),
// the crack runs within one relaxation and its direction is biased (docs/ingraffea.md gives the
// cost and the path change on Case II): an option, off by default.
// The allowed advance is max_advance, halved while the tip is within near_distance of a hole or
// the body's outline: near them the crack exchanges more often (what the reference had to do by
// hand for Case III).
#pragma once

namespace pumpd::coupling
{
  struct ExchangeSettings
  {
    double first_load_factor  = 0.9;   ///< lambda of the first sub-step of the first exchange
    double load_increment     = 0.05;  ///< dlambda
    double min_load_increment = 0.0125; ///< dlambda is not halved below this
    double max_load_factor    = 3.;    ///< no growth up to here: the run stops
    double max_advance        = 0.008; ///< da_max per exchange [m]
    double min_advance        = 0.004; ///< an advance below this is no growth [m]
    double near_distance      = 0.008; ///< closer to a hole or the outline: da_max / 2 [m]
    bool   start_below_accepted = false; ///< start an exchange at the last accepted lambda - dlambda
    double onset_resolution   = 0.0125; ///< the onset of growth is bracketed this closely (exchange.h)
  };

  class ExchangeController
  {
  public:
    enum class Decision
    {
      raise,     ///< no growth yet: next sub-step at a higher load
      repeat,    ///< too far: restore the state before the sub-step and redo it at a lower load
      accept,    ///< grew, within the allowed advance
      truncate,  ///< grew too far even at the smallest increment: accept the allowed length
      too_small  ///< no growth up to max_load_factor
    };

    /// Throws InvalidParameter for settings out of range (each named).
    explicit ExchangeController(const ExchangeSettings &settings);

    /// Starts an exchange; returns the first lambda (first_load_factor, or with
    /// start_below_accepted one increment below the last accepted lambda).
    double start();
    /// The allowed advance for a tip `clearance` [m] from the nearest hole or outline.
    double allowed_advance(double clearance) const;
    /// Judges the advance [m] the PD run reached at the current lambda, and sets the next lambda.
    /// An advance that `arrives` at a hole or the outline is accepted whatever its length (the
    /// crack cannot grow further there).
    Decision judge(double advance, double allowed, bool arrives = false);
    double   load_factor() const { return lambda; }
    double   increment() const { return dlambda; }
    const ExchangeSettings &settings() const { return s; }
    /// Continue after a restart from the lambda of the last accepted exchange.
    void restore(double accepted_load_factor) { accepted = accepted_load_factor; }

  private:
    ExchangeSettings s;
    double           lambda   = 0.;
    double           dlambda  = 0.;
    double           accepted = 0.; ///< 0: no exchange accepted yet
  };
} // namespace pumpd::coupling
