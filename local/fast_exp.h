// exp(-x) for x >= 0, branch-free so that the bond loop vectorises without -ffast-math.
// Range reduction x = k ln2 + f (Cody-Waite, |f| <= ln2/2), degree-12 Taylor polynomial for e^f
// (truncation < 2e-16 relative), 2^k assembled in the exponent bits. Arguments above 700 give
// exp(-700) ~ 1e-304: bonds there have failed long before (their stretch is 10+ S_c).
#pragma once

#include <cstdint>
#include <cstring>

namespace pumpd::local
{
  inline double exp_negative(double x)
  {
    const double t       = -(x < 700. ? x : 700.);
    const double shifter = 0x1.8p52; // adding it rounds to an integer held in the low bits
    const double s       = t * 1.4426950408889634 + shifter;
    const double k       = s - shifter;
    const double f       = (t - k * 6.93147180369123816490e-01) - k * 1.90821492927058770002e-10;
    double       p       = 1. / 479001600.;
    p                    = p * f + 1. / 39916800.;
    p                    = p * f + 1. / 3628800.;
    p                    = p * f + 1. / 362880.;
    p                    = p * f + 1. / 40320.;
    p                    = p * f + 1. / 5040.;
    p                    = p * f + 1. / 720.;
    p                    = p * f + 1. / 120.;
    p                    = p * f + 1. / 24.;
    p                    = p * f + 1. / 6.;
    p                    = p * f + 0.5;
    p                    = p * f + 1.;
    p                    = p * f + 1.;
    std::int64_t bits;
    std::memcpy(&bits, &s, sizeof bits);
    bits = (bits + 1023) << 52; // the integer k sits in the low mantissa bits of s
    double scale;
    std::memcpy(&scale, &bits, sizeof scale);
    return p * scale;
  }
} // namespace pumpd::local
